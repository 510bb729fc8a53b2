// What a scene's measurements produce; output.cpp writes them out.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "inputs.hpp"
#include "scene.hpp"

namespace report {

// Error histogram bins: [0] exactly 0, [1] (0, 0.5], [2] (0.5, 1], then
// (2^(k-3), 2^(k-2)] for k = 3 .. 62, [63] above 2^60 (including infinity),
// [64] NaN.
inline constexpr int histogram_bins = 65;
int histogram_bin(double ulps);
std::string histogram_label(int bin);

struct summary {  // of a set of ulp errors; NaN counts as infinitely wrong
  long count = 0;
  double max = 0, p99 = 0, median = 0;
};
// Nearest-rank percentiles (the value at rank ceil(q n)).
summary summarize(std::vector<double> errors);

struct accuracy_result {
  std::string type, algorithm;
  long samples = 0;
  summary ulps;
  double max_ulp_as_double = -1;  // the result rounded to double, in ulps of double (-1: not measured)
  long nan = 0, inf = 0, complementarity = 0, wrong_case = 0;
  long inf_overflow = 0;  // infinite results that are right: the exact root rounds to infinity in the type
  std::vector<double> family_max;  // max ulp per family of the scene (-1: family not in this run)
  std::vector<long> histogram = std::vector<long>(histogram_bins, 0);
  int reference_bits = 0;
  // iterations of an iterative method (methods.hpp) over the samples (-1: the method does not iterate)
  double iterations_mean = -1;
  long iterations_max = -1;
  // the share of samples that took the exact decision (the slow path) of the
  // correctly rounded mode (-1: not the rounded method)
  double slow_path_share = -1;
  // the raw measurements (kept only with --raw)
  std::vector<double> errors;
  std::vector<int> which;
  std::vector<int> iterations;  // empty for a method that does not iterate
  std::vector<std::string> s_text;
  std::vector<input> inputs;
};

// Sets the mean and maximum iteration count of `a` from one count per sample.
void count_iterations(const std::vector<int>& counts, accuracy_result& a);

struct timing_result {
  std::string type, algorithm;  // algorithm: a method's name, or "batch[NAME]": one target's kernel alone
  long inputs = 0;  // length of the array one iteration solves
  std::vector<double> ns;  // ns per solve, one per repetition (CPU time)
  double median = 0, min = 0, max = 0;
};

// What one lane of the batch throughput streams: u, dy and phi in, s and the case out.
inline constexpr long bytes_per_lane = 4 * sizeof(double) + sizeof(int);

struct throughput_result {
  std::string what;  // floor, batch, batch[NAME] (one per target the CPU runs), stable, textbook
  long lanes = 0;
  std::vector<double> ns;  // ns per lane, one per repetition (CPU time)
  double median = 0, min = 0, max = 0;
  double gigabytes_per_second = 0;  // bytes_per_lane / ns per lane
};

// The batch kernel on one scene's timing inputs, timed in the same rounds as
// on every other scene's (measure_batch_across_scenes): a scene timed a
// minute after another can meet another load of the shared machine, a round
// meets the same load on every scene.
struct batch_across_result {
  std::string kernel;          // "batch" (the target dispatch chose) or "batch[NAME]" (targets.hpp)
  std::string reference;       // the scene that sets batch_reference
  std::vector<double> ns;      // ns per lane, one per round (CPU time)
  double median = 0, min = 0, max = 0;
  std::vector<double> ratios;  // ns over the reference's ns in the same round
  double ratio_median = 0, ratio_min = 0, ratio_max = 0;
};

struct energy_result {
  std::string type, algorithm;
  long steps = 0;
  double max_exact = 0;    // max |H[n] - H[0]| / H[0], H evaluated exactly (MPFR) from the state in T
  double max_in_type = 0;  // the same with H evaluated in T
  double final_exact = 0;
  long contact_steps = 0;  // steps with dy > 0 or s < dy, i.e. barrier force acting
  bool finite = true;      // the state stayed finite
  std::vector<double> time, envelope;  // max error within each plot interval, exact H
};

struct family_mix {
  long cases[5] = {0, 0, 0, 0, 0};  // invalid, free, impact, contact, release (exact criteria)
};

struct scene_result {
  scene s;
  std::vector<family_mix> mix;  // per family
  std::vector<accuracy_result> accuracy;
  std::vector<timing_result> timing;
  std::vector<throughput_result> throughput;
  std::vector<throughput_result> throughput_cache;  // the same at cache_lanes
  std::vector<input> batch_lanes;  // the inputs its batch timing in double loops over (none: no such timing)
  std::optional<batch_across_result> batch_across;
  std::vector<batch_across_result> batch_across_targets;  // the same per target the CPU runs, timed in the same rounds
  std::vector<energy_result> energy;
  double seconds = 0;
};

// Progress lines on stderr, at most one every two seconds per task.
class progress {
 public:
  progress(std::string label, long total);
  void update(long done);
  void finish();

 private:
  std::string label_;
  long total_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace report
