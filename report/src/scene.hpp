// Scenes: the declarative TOML files of scenes/ that say which inputs to
// generate, which types and algorithms to run on them and which checks to make.
// The grammar is documented in scenes/README.md; every key is checked, unknown
// keys are errors, and every error names the file and line.
#pragma once

#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "contact/harness/random.hpp"
#include "methods.hpp"

namespace report {

// "FILE:LINE: reason" (LINE is 0 when the file itself cannot be read).
class scene_error : public std::runtime_error {
 public:
  scene_error(const std::string& file, long line, const std::string& reason)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " + reason), file_(file), line_(line), reason_(reason) {}
  const std::string& file() const { return file_; }
  long line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  long line_;
  std::string reason_;
};

// How one number of a family is drawn: the input families' own distribution.
using contact::harness::distribution;

struct family {
  std::string name;
  std::string generator;                            // see inputs.hpp
  std::map<std::string, distribution> parameters;  // named by the generator
  long samples = 0;
  long ulps = 0;  // boundary generators: the half-width of the neighbourhood in ulps
  long line = 0;
};

enum class check { accuracy, timing, energy };

// The pictures a scene asks for ([scene] plots, scenes/README.md): the
// headline figure (its run times in double are the figure's times; at most one
// scene asks for it), the scene's Pareto panels, its share of the error
// histograms and its energy plots.
enum class plot { headline, pareto, histograms, energy };
inline constexpr plot all_plots[] = {plot::headline, plot::pareto, plot::histograms, plot::energy};
std::string name_of(plot p);
// What a scene without the key asks for: every per-scene picture, no headline.
inline constexpr plot default_plots[] = {plot::pareto, plot::histograms, plot::energy};

// Which types and algorithms to run, and what to measure of them: accuracy and
// timing on the scene's families, energy on the scene's [oscillator].
struct run {
  std::vector<std::string> types;
  std::vector<method> methods;
  std::vector<check> checks;
  long samples = -1;         // at most this many samples of each family (-1: all)
  long timing_inputs = 4096;  // length of the input array that the timings loop over
  // rounds of every method of the run, each timed once per round: the
  // medians of eleven survive five rounds disturbed by the machine's load
  // (on the shared 2-core machine a slow phase of seconds, measured to move
  // the physical scene's stable/textbook from 1.05-1.09 to 1.21 with five)
  int repetitions = 11;
  double min_time = 0.05;  // seconds per repetition
  long line = 0;
};

struct throughput {
  long lanes = 1 << 21;       // the streamed arrays (larger than the caches)
  long cache_lanes = 4096;    // an in-cache size, for the compute-bound figure
  int repetitions = 5;
  double min_time = 0.1;
  long line = 0;
};

struct oscillator {
  double mass = 1e-3, spring = 1e3, barrier_height = -5e-4, barrier_stiffness = 1e13;
  double sample_rate = 44100, duration = 1.0;
  double initial_displacement = 0, initial_velocity = 1.0;
  long plot_points = 400;
  long line = 0;
};

struct scene {
  std::string file;
  std::string name, title, description;
  std::uint64_t seed = 1;
  int mpfr_digits10 = 50;
  // The scene whose batch ns per lane every scene's is compared against,
  // timed in the same rounds (measure_batch_across_scenes); at most one.
  bool batch_reference = false;
  long batch_reference_line = 0;
  std::vector<plot> plots{std::begin(default_plots), std::end(default_plots)};
  long plots_line = 0;  // of the key, 0 when absent
  std::vector<family> families;
  std::vector<run> runs;
  std::optional<throughput> batch_throughput;
  std::optional<oscillator> energy;
};

// Whether the run asks for the check.
bool asks_for(const run& r, check c);
// Whether the scene asks for the picture.
bool asks_for(const scene& s, plot p);

// The first run that times batch in double, or null.
const run* batch_timing_run(const scene& s);

// Reads and checks a scene file; throws scene_error.
scene parse_scene(const std::string& path);
// Same, from text (`path` only names it in errors).
scene parse_scene_text(const std::string& text, const std::string& path);

}  // namespace report
