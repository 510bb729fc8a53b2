// The yardstick of contact-report's in-process timing of a library candidate:
// the same candidate linked in and called directly, in the same loop over the
// same lanes (a scene's first [[run]], shuffled as the report shuffles them),
// CPU ns per solve, median over the run's repetitions.
//   direct-loop SCENE.toml
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "inputs.hpp"
#include "scene.hpp"

extern "C" double contact_candidate(double u, double dy, double phi, int* which);

namespace {

double cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

volatile double sink;

double ns_per_solve(const std::vector<report::input>& lanes, double min_time) {
  long passes = 0;
  const double start = cpu_seconds();
  double elapsed = 0;
  do {
    for (const auto& x : lanes) {
      int which = 0;
      sink = contact_candidate(x.u, x.dy, x.phi, &which);
    }
    ++passes;
    elapsed = cpu_seconds() - start;
  } while (elapsed < min_time);
  return elapsed * 1e9 / (double(passes) * double(lanes.size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: direct-loop SCENE.toml\n");
    return 2;
  }
  try {
    const report::scene s = report::parse_scene(argv[1]);
    const report::run& r = s.runs.front();
    const auto lanes = report::mixed(report::generate(s), r.timing_inputs, s.seed);
    ns_per_solve(lanes, r.min_time / 2);
    std::vector<double> ns;
    for (int round = 0; round < r.repetitions; ++round) ns.push_back(ns_per_solve(lanes, r.min_time));
    std::sort(ns.begin(), ns.end());
    std::printf("direct call: %.2f ns per solve (median of %d, %.2f to %.2f), %zu lanes\n", ns[ns.size() / 2],
                r.repetitions, ns.front(), ns.back(), lanes.size());
  } catch (const report::scene_error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
