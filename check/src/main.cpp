// contact-check: checks any implementation of (A.2) against the certified
// reference: a property suite on the harness's input families, then a
// differential fuzzing campaign; every failure is printed shrunk.
//
// Exit status: 0 every property holds, 1 some property fails, 2 bad usage
// (bad option, bad spec, missing library or symbol).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "checker.hpp"
#include "junit.hpp"

namespace {

template <class T>
int run(contact::harness::candidate& candidate, const check::options& o, const std::string& spec,
        const std::string& type, const std::string& junit_file) {
  std::printf("contact-check: %s as %s, max %g ulps, %ld trials per property, then %g s of fuzzing (seed %llu)\n",
              spec.c_str(), type.c_str(), o.max_ulp, o.trials, o.seconds, static_cast<unsigned long long>(o.seed));
  std::fflush(stdout);
  check::checker<T> c(candidate, o);
  const auto start = std::chrono::steady_clock::now();
  c.run_suite();
  const double suite_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.run_campaign();

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
  std::printf("\ncontact-check: %ld of %zu properties fail; suite %.1f s, fuzzing %.1f s (%ld inputs)\n", failing,
              c.records().size(), suite_seconds, c.campaign_seconds(), c.campaign_inputs());
  if (!junit_file.empty() && !check::write_junit(junit_file, spec, c.records())) {
    std::fprintf(stderr, "contact-check: cannot write %s\n", junit_file.c_str());
    return 2;
  }
  return failing ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"contact-check: checks an implementation of the contact step (A.2) against the certified reference"};
  std::string spec, type = "double", junit_file;
  check::options o;
  double call_timeout = 1;
  app.add_option("--candidate", spec, "lib:PATH[:SYMBOL] (a shared library) or cmd:COMMAND (contact-solve's protocol)")
      ->required();
  app.add_option("--type", type, "the candidate's floating-point type")
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
  app.add_option("--junit", junit_file, "also write a JUnit XML file, one testcase per property");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  const bool single = type == "float";
  try {
    auto candidate = contact::harness::open_candidate(spec, single, call_timeout);
    return single ? run<float>(*candidate, o, spec, type, junit_file) : run<double>(*candidate, o, spec, type, junit_file);
  } catch (const contact::harness::candidate_error& e) {
    std::fprintf(stderr, "contact-check: %s\n", e.what());
    return 2;
  }
}
