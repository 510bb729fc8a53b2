// contact-avx512-baseline: today's batch kernels against the AVX-512 kernel
// they replaced (extract.sh), on the report's batch timing inputs, timed in
// one process: each round runs every kernel once over the same array, in
// turn, and a ratio is the median of the rounds' ratios.
//   contact-avx512-baseline [SCENE.toml ...]   (default: every scene of scenes/ that times batch)
// A bad scene file, or a named one that times no batch kernel, stops it with
// FILE:LINE: reason (exit status 1).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <contact/batch.hpp>

#include "inputs.hpp"
#include "scene.hpp"

void baseline_patched(const double* u, const double* dy, const double* phi, double* s, int* which, long n);
void baseline_as_was(const double* u, const double* dy, const double* phi, double* s, int* which, long n);

namespace {

struct kernel {
  std::string name;
  std::function<void(const double*, const double*, const double*, double*, int*, long)> solve;
};

struct lanes_of {
  std::string name;
  std::vector<double> u, dy, phi;
};

lanes_of lanes_from(const std::string& name, const std::vector<report::input>& inputs) {
  lanes_of l{name, {}, {}, {}};
  for (const auto& x : inputs) {
    l.u.push_back(x.u);
    l.dy.push_back(x.dy);
    l.phi.push_back(x.phi);
  }
  return l;
}

// The arrays the report times batch on: a scene's batch timing run, or the
// throughput scene's in-cache and streamed arrays (measure.cpp draws them so);
// none for a scene that times no batch kernel.
std::vector<lanes_of> arrays_of(const report::scene& s) {
  if (s.batch_throughput) {
    const std::vector<report::input> inputs = report::generate(s);
    const auto& t = *s.batch_throughput;
    return {lanes_from(s.name + " in cache", report::mixed(inputs, t.cache_lanes, s.seed + 1001)),
            lanes_from(s.name + " streamed", report::mixed(inputs, t.lanes, s.seed + 1000))};
  }
  const report::run* r = report::batch_timing_run(s);
  if (!r) return {};
  const auto k = static_cast<std::uint64_t>(r - s.runs.data());
  return {lanes_from(s.name, report::mixed(report::generate(s), r->timing_inputs, s.seed + k))};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  // the baseline is built for x86-64-v4, as the library's avx3 kernel is
  const auto targets = contact::batch_targets();
  if (std::none_of(targets.begin(), targets.end(), [](const auto& t) { return std::strcmp(t.name, "avx3") == 0 && t.supported; })) {
    std::printf("This CPU has no AVX-512: the baseline kernel does not run here.\n");
    return 0;
  }
  std::vector<std::string> scenes;
  for (int k = 1; k < argc; ++k) scenes.push_back(argv[k]);
  const bool named = !scenes.empty();
  if (!named) {
    for (const auto& entry : std::filesystem::directory_iterator(CONTACT_SCENES_DIR))
      if (entry.is_regular_file() && entry.path().extension() == ".toml") scenes.push_back(entry.path().string());
    std::sort(scenes.begin(), scenes.end());
  }

  std::vector<kernel> kernels{{"baseline", baseline_patched}, {"baseline as it was", baseline_as_was}};
  for (const auto& t : targets)
    if (t.supported)
      kernels.push_back({std::string("batch[") + t.name + "]", [solve = t.solve_double](const double* u, const double* dy, const double* phi,
                                                                                       double* s, int* which, long n) { solve(u, dy, phi, s, which, n); }});
  auto run = [&](std::size_t k, const lanes_of& l, double* s, int* which) {
    kernels[k].solve(l.u.data(), l.dy.data(), l.phi.data(), s, which, static_cast<long>(l.u.size()));
  };

  std::vector<lanes_of> arrays;
  for (const auto& path : scenes) {
    try {
      const report::scene s = report::parse_scene(path);
      auto of_scene = arrays_of(s);
      if (of_scene.empty() && named) throw report::scene_error(path, 0, "no run of the scene times batch in double");
      for (auto& l : of_scene) arrays.push_back(std::move(l));
    } catch (const report::scene_error& e) {  // FILE:LINE: reason
      std::fprintf(stderr, "contact-avx512-baseline: %s\n", e.what());
      return 1;
    }
  }
  constexpr int rounds = 11;
  std::printf("ns per lane, median of %d rounds; new / baseline: median of the rounds' ratios (their range);\n"
              "differ: lanes whose s (bits) or case differs from the baseline's\n\n", rounds);
  std::printf("| inputs | lanes | kernel | ns per lane | / baseline | range | differ |\n|---|---:|---|---:|---:|---|---:|\n");
  for (const lanes_of& l : arrays) {
    const long n = static_cast<long>(l.u.size());
    const std::size_t count = kernels.size();
    std::vector<std::vector<double>> s(count, std::vector<double>(n));
    std::vector<std::vector<int>> which(count, std::vector<int>(n));
    for (std::size_t k = 0; k < count; ++k) run(k, l, s[k].data(), which[k].data());
    const long repeats = std::max(1L, 20'000'000L / n);
    std::vector<std::vector<double>> ns(count), ratio(count);
    for (int round = 0; round < rounds; ++round) {
      std::vector<double> this_round(count);
      for (std::size_t j = 0; j < count; ++j) {
        const std::size_t k = (j + static_cast<std::size_t>(round)) % count;  // each kernel first in turn
        const auto start = std::chrono::steady_clock::now();
        for (long r = 0; r < repeats; ++r) run(k, l, s[k].data(), which[k].data());
        this_round[k] = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                        (static_cast<double>(n) * static_cast<double>(repeats));
      }
      for (std::size_t k = 0; k < count; ++k) {
        ns[k].push_back(this_round[k]);
        ratio[k].push_back(this_round[k] / this_round[0]);
      }
    }
    for (std::size_t k = 0; k < count; ++k) {
      long differ = 0;
      for (long i = 0; i < n; ++i)
        differ += std::memcmp(&s[k][i], &s[0][i], sizeof(double)) != 0 || which[k][i] != which[0][i];
      const auto [low, high] = std::minmax_element(ratio[k].begin(), ratio[k].end());
      std::printf("| %s | %ld | %s | %.3f | %.3f | %.3f-%.3f | %ld |\n", l.name.c_str(), n, kernels[k].name.c_str(), median(ns[k]),
                  median(ratio[k]), *low, *high, differ);
    }
    std::fflush(stdout);
  }
}
