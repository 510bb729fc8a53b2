// report.md, results.csv, results.json, the raw measurements and the plots.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "results.hpp"

namespace report {

struct run_info {
  std::string command;     // the command line
  std::string started;     // UTC, ISO 8601
  double seconds = 0;      // wall time of all scenes
  std::string cpu;         // the model name of /proc/cpuinfo, or "unknown"
  std::string compiler, flags;
  // the batch targets the library holds (contact::batch_targets()), whether
  // this CPU runs each, and the one solve_batch dispatches to
  std::vector<std::pair<std::string, bool>> batch_targets;
  std::string batch_chosen;
};

// The number formats of report.md (the tests use them to compare figures).
std::string format_ulp(double ulps);
std::string format_ns(double ns);
std::string format_ratio(double ratio);
std::string format_energy(double relative);
std::string format_inf(const accuracy_result& a);
std::string format_iterations(const accuracy_result& a);  // "mean / max", or "—" for a method that does not iterate
std::string format_slow_path(const accuracy_result& a);  // "12.3%" of samples on the exact decision, or "—" for a method other than rounded

// Writes everything into `directory` (created if need be). Returns false if
// gnuplot failed (the rest is written anyway).
bool write_report(const std::string& directory, const std::vector<scene_result>& scenes, const run_info& info,
                  bool raw);

// Writes plots/*.gp and *.dat and runs gnuplot on them; false if it failed.
bool write_plots(const std::string& directory, const std::vector<scene_result>& scenes, std::vector<std::string>& made);

}  // namespace report
