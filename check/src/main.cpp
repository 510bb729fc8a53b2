// contact-check: checks any implementation of (A.2) against the certified
// reference: a property suite on the harness's input families, then a
// differential fuzzing campaign; every failure is printed shrunk.
//
// Exit status: 0 every property holds, 1 some property fails, 2 bad usage
// (bad option, bad spec, missing library or symbol, bad scene file).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "checker.hpp"
#include "error_map.hpp"
#include "junit.hpp"

namespace {

struct settings {
  std::string spec, type = "double", junit_file, scene, map_dir;
};

template <class T>
int run(contact::harness::candidate& candidate, const check::options& o, const settings& a) {
  const check::domain<T> d = a.scene.empty() ? check::domain<T>::whole_range() : check::domain<T>::of_scene(a.scene);
  std::printf("contact-check: %s as %s, max %g ulps, %ld trials per property, then %g s of fuzzing (seed %llu)\n",
              a.spec.c_str(), a.type.c_str(), o.max_ulp, o.trials, o.seconds, static_cast<unsigned long long>(o.seed));
  std::printf("domain: %s; families: %s\n", d.name().c_str(), check::joined(d.families()).c_str());
  if (!d.is_whole_range())
    std::printf("        |u| 10^[%.3g, %.3g], |dy| 10^[%.3g, %.3g], phi 10^[%.3g, %.3g]; phi_zero and invalid_input "
                "are the whole range's, not judged here\n",
                std::log10(d.u().least), std::log10(d.u().most), std::log10(d.dy().least), std::log10(d.dy().most),
                std::log10(d.phi().least), std::log10(d.phi().most));
  std::fflush(stdout);
  check::checker<T> c(candidate, o, d);
  const auto start = std::chrono::steady_clock::now();
  c.run_suite();
  const double suite_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.run_campaign();
  c.run_sweep();

  long failing = 0;
  for (const auto& r : c.records()) {
    if (r.failed) ++failing;
    std::printf("%-5s %-28s %ld of %ld trials fail   (%s)\n", r.failed ? "FAIL" : "ok", r.name.c_str(), r.failed,
                r.tried, r.claim.c_str());
  }
  for (const auto& r : c.records()) {
    for (const auto& [which, f] : r.first) {
      std::printf("\nFAIL %s: %s\n", r.name.c_str(), f.reason.c_str());
      for (const auto& line : f.lines) std::printf("  %s\n", line.c_str());
    }
  }
  const std::string table = check::table_text(c.table(), d.families());
  std::printf("\nper family and case (%s):\n%s", d.name().c_str(), table.c_str());
  bool swept = false;
  for (const auto& r : c.records()) swept = swept || !r.where.empty();
  if (swept) std::printf("\nwhere each failing property breaks, sweeping one magnitude at a time over the domain:\n");
  for (const auto& r : c.records())
    for (const auto& line : r.where) std::printf("  %s\n", line.c_str());
  std::printf("\ncontact-check: %ld of %zu properties fail on %s; suite %.1f s, fuzzing %.1f s (%ld inputs), sweep %.1f s\n",
              failing, c.records().size(), d.name().c_str(), suite_seconds, c.campaign_seconds(), c.campaign_inputs(),
              c.sweep_seconds());
  if (!a.junit_file.empty() && !check::write_junit(a.junit_file, a.spec, d.name(), table, c.records())) {
    std::fprintf(stderr, "contact-check: cannot write %s\n", a.junit_file.c_str());
    return 2;
  }
  if (!a.map_dir.empty()) {
    const auto written = check::write_error_map<T>(candidate, d, o.max_ulp, a.map_dir, "candidate", a.spec);
    if (!written.ok) {
      std::fprintf(stderr, "contact-check: --map: %s\n", written.message.c_str());
      return 2;
    }
    std::printf("error map: %s\n", written.message.c_str());
  }
  return failing ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"contact-check: checks an implementation of the contact step (A.2) against the certified reference"};
  settings a;
  check::options o;
  double call_timeout = 1;
  app.add_option("--candidate", a.spec, "lib:PATH[:SYMBOL] (a shared library) or cmd:COMMAND (contact-solve's protocol)")
      ->required();
  app.add_option("--type", a.type, "the candidate's floating-point type")
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  app.add_option("--max-ulp", o.max_ulp, "allowed error in ulps of the exact root (at least 0.5)")
      ->check(CLI::Range(0.5, 1e15))
      ->capture_default_str();
  app.add_option("--time", o.seconds, "seconds of differential fuzzing after the suite")
      ->check(CLI::Range(0.0, 1e7))
      ->capture_default_str();
  app.add_option("--trials", o.trials, "trials per property of the suite")->check(CLI::Range(1L, 100000000L))->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the draws")->capture_default_str();
  app.add_option("--call-timeout", call_timeout, "seconds one call may take before the candidate counts as hung")
      ->check(CLI::Range(0.001, 3600.0))
      ->capture_default_str();
  app.add_option("--junit", a.junit_file, "also write a JUnit XML file, one testcase per property");
  app.add_option("--scene", a.scene,
                 "judge on a scene file's families (a path, or the name of a scene of scenes/, e.g. physical) "
                 "instead of the whole range");
  app.add_option("--sweep-trials", o.sweep_trials,
                 "trials at each magnitude of the sweep that finds where a failing property breaks (0: no sweep)")
      ->check(CLI::Range(0L, 100000L))
      ->capture_default_str();
  app.add_option("--map", a.map_dir, "also write DIR/error_map.png and .svg: the largest ulp error over |u| and |dy|");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  const bool single = a.type == "float";
  try {
    auto candidate = contact::harness::open_candidate(a.spec, single, call_timeout);
    return single ? run<float>(*candidate, o, a) : run<double>(*candidate, o, a);
  } catch (const contact::harness::candidate_error& e) {
    std::fprintf(stderr, "contact-check: %s\n", e.what());
    return 2;
  } catch (const report::scene_error& e) {
    std::fprintf(stderr, "contact-check: --scene: %s\n", e.what());
    return 2;
  }
}
