#include "measure.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <map>
#include <memory>

#include "contact/batch.hpp"
#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "contact/types.hpp"
#include "candidates.hpp"
#include "targets.hpp"
#include "type_ops.hpp"

namespace report {

namespace {

// Collects Google Benchmark's per-repetition runs as ns per item (CPU time).
class collector : public benchmark::BenchmarkReporter {
 public:
  std::map<std::string, long> items_per_iteration;
  std::map<std::string, std::vector<double>> ns;

  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration) continue;
      std::string name = run.run_name.function_name;
      name = name.substr(0, name.rfind('#'));  // the round
      if (run.error_occurred) {
        std::fprintf(stderr, "contact-report: benchmark %s failed: %s\n", name.c_str(), run.error_message.c_str());
        continue;
      }
      const double items = double(run.iterations) * double(items_per_iteration.at(name));
      ns[name].push_back(run.cpu_accumulated_time * 1e9 / items);
    }
    if (!runs.empty() && runs.back().run_type == Run::RT_Iteration) {
      const std::string full = runs.back().run_name.function_name;
      const auto& v = ns[full.substr(0, full.rfind('#'))];
      if (!v.empty())
        std::fprintf(stderr, "contact-report: timed %-52s %10.3f ns\n", full.c_str(), v.back());
    }
  }
};

void run_benchmarks(collector& c) {
  static bool initialised = false;
  if (!initialised) {
    int argc = 1;
    char name[] = "contact-report";
    char* argv[] = {name, nullptr};
    benchmark::Initialize(&argc, argv);
    initialised = true;
  }
  benchmark::RunSpecifiedBenchmarks(&c);
  benchmark::ClearRegisteredBenchmarks();
}

void spread(const std::vector<double>& values, double& median, double& low, double& high) {
  if (values.empty()) {
    median = low = high = std::nan("");
    return;
  }
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
  low = sorted.front();
  high = sorted.back();
}

// Eigen arrays, as the batch API takes them (aligned to the vector width).
struct stream_arrays {
  contact::batch_array<double> u, dy, phi, s;
  contact::batch_array<int> which;
  std::size_t root_lanes = 0, contact_lanes = 0;  // impacts and releases, contacts (by the exact criteria)
};

using lane_path = std::function<void(stream_arrays&, std::size_t)>;

// The memory floor: the same bytes in and out, and no solving.
void memory_floor(stream_arrays& a, std::size_t n) {
  const double* __restrict u = a.u.data();
  const double* __restrict dy = a.dy.data();
  const double* __restrict phi = a.phi.data();
  double* __restrict s = a.s.data();
  int* __restrict which = a.which.data();
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = u[i] + dy[i] + phi[i];
    which[i] = static_cast<int>(dy[i] > 0);
  }
}

// The divisions and square roots alone: one square root and one division
// for each impact and release lane, one division for each contact lane, on
// arrays packed by that cost, vectorised by the compiler (the report's
// vector flags). Every exact kernel runs these correctly rounded operations
// at least, so none runs below this floor; on a CPU whose vector divider is
// slow it bounds the speed-up over textbook.
void division_floor(stream_arrays& a, std::size_t) {
  const double* __restrict u = a.u.data();
  const double* __restrict dy = a.dy.data();
  const double* __restrict phi = a.phi.data();
  double* __restrict s = a.s.data();
  const std::size_t roots = a.root_lanes, lanes = a.root_lanes + a.contact_lanes;
  for (std::size_t i = 0; i < roots; ++i) s[i] = std::sqrt(phi[i]) / dy[i];
  for (std::size_t i = roots; i < lanes; ++i) s[i] = u[i] / phi[i];
}

// The batch kernel over the arrays.
void batch_kernel(stream_arrays& a, std::size_t) { contact::solve_batch(a.u, a.dy, a.phi, a.s, a.which); }

// One target's batch kernel alone over the arrays.
lane_path target_kernel(const contact::batch_target& t) {
  return [&t](stream_arrays& a, std::size_t n) {
    solve_on(t, a.u.data(), a.dy.data(), a.phi.data(), a.s.data(), a.which.data(), static_cast<std::ptrdiff_t>(n));
  };
}

// A path over the arrays, under the name of its rows.
struct named_path {
  std::string what;
  lane_path body;
};

// The batch kernels: "batch" (the target dispatch chose), then each target the CPU runs alone.
std::vector<named_path> batch_kernels() {
  std::vector<named_path> kernels{{name_of(method::batch), batch_kernel}};
  for (const contact::batch_target* t : supported_batch_targets()) kernels.push_back({batch_row_name(*t), target_kernel(*t)});
  return kernels;
}

// One round of `body` over the arrays, as a Google Benchmark of min_time seconds.
void register_round(const std::string& name, const std::shared_ptr<stream_arrays>& d, const lane_path& body,
                    double min_time) {
  benchmark::RegisterBenchmark(name.c_str(), [d, n = d->u.size(), body](benchmark::State& state) {
    for (auto _ : state) {
      body(*d, n);
      benchmark::ClobberMemory();
    }
  })->Repetitions(1)->MinTime(min_time)->MinWarmUpTime(min_time / 2)->Unit(benchmark::kNanosecond);
}

// A scalar solver over the arrays, one call per lane.
template <class Solve>
lane_path each_lane(Solve solve) {
  return [solve](stream_arrays& a, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto r = solve(a.u[i], a.dy[i], a.phi[i]);
      a.s[i] = r.s;
      a.which[i] = static_cast<int>(r.which);
    }
  };
}

// The paths the throughput compares, in the order of its tables: the floor,
// the batch kernels, the scalar paths.
std::vector<named_path> throughput_paths() {
  std::vector<named_path> paths{{"floor", memory_floor}, {"division floor", division_floor}};
  for (auto& kernel : batch_kernels()) paths.push_back(std::move(kernel));
  paths.push_back({"stable", each_lane([](double u, double dy, double phi) { return contact::solve_stable(u, dy, phi); })});
  paths.push_back(
      {"textbook", each_lane([](double u, double dy, double phi) { return contact::solve_textbook(u, dy, phi); })});
  return paths;
}

void register_throughput(const std::shared_ptr<stream_arrays>& d, const std::vector<named_path>& paths,
                         const throughput& t, const std::string& prefix, collector& c) {
  const std::size_t n = d->u.size();
  for (const auto& path : paths) c.items_per_iteration[prefix + path.what] = static_cast<long>(n);
  // Repetition-major, as in typed.hpp: each round times every path once.
  for (int round = 0; round < t.repetitions; ++round)
    for (const auto& path : paths)
      register_round(prefix + path.what + "#" + std::to_string(round), d, path.body, t.min_time);
}

std::shared_ptr<stream_arrays> stream_data(const std::vector<input>& lanes) {
  auto d = std::make_shared<stream_arrays>();
  const auto n = static_cast<Eigen::Index>(lanes.size());
  d->u.resize(n);
  d->dy.resize(n);
  d->phi.resize(n);
  d->s.setZero(n);
  d->which.setZero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    d->u[i] = lanes[static_cast<std::size_t>(i)].u;
    d->dy[i] = lanes[static_cast<std::size_t>(i)].dy;
    d->phi[i] = lanes[static_cast<std::size_t>(i)].phi;
    switch (contact::solve_stable(d->u[i], d->dy[i], d->phi[i]).which) {
      case contact::contact_case::impact:
      case contact::contact_case::release: ++d->root_lanes; break;
      case contact::contact_case::contact: ++d->contact_lanes; break;
      case contact::contact_case::free:
      case contact::contact_case::invalid: break;
    }
  }
  return d;
}


// How many inputs of each family fall into each case, by the exact criteria
// (stable decides them exactly).
std::vector<family_mix> case_mix(const scene& s, const std::vector<input>& inputs) {
  std::vector<family_mix> mix(s.families.size());
  for (const auto& in : inputs)
    mix[static_cast<std::size_t>(in.family)].cases[static_cast<int>(contact::solve_stable(in.u, in.dy, in.phi).which)]++;
  return mix;
}

// The first r.samples inputs of each family (all of them if r.samples < 0).
std::vector<input> samples_of(const run& r, const scene& s, const std::vector<input>& inputs) {
  std::vector<input> subset;
  std::vector<long> taken(s.families.size(), 0);
  for (const auto& in : inputs)
    if (r.samples < 0 || taken[static_cast<std::size_t>(in.family)]++ < r.samples) subset.push_back(in);
  return subset;
}

// The certified root of every input, at 256 bits or four times the widest type's precision.
reference_list references_for(const run& r, const scene& s, const std::vector<input>& subset) {
  int digits = 53;
  for (const auto& type : r.types) digits = std::max(digits, ops_for(type).digits());
  const mpfr_prec_t bits = std::max(256, 4 * digits);
  reference_list references;
  references.reserve(subset.size());
  progress bar("scene " + s.name + ": certified references (" + std::to_string(bits) + " bits)",
               static_cast<long>(subset.size()));
  long uncertified = 0;
  for (std::size_t i = 0; i < subset.size(); ++i) {
    references.push_back(contact::reference::solve<double>(subset[i].u, subset[i].dy, subset[i].phi, bits));
    if (!references.back().is_certified) ++uncertified;
    if ((i & 1023) == 0) bar.update(static_cast<long>(i));
  }
  if (uncertified)
    std::fprintf(stderr, "contact-report: warning: %ld references of scene %s are not certified\n", uncertified,
                 s.name.c_str());
  return references;
}

void measure_accuracy(const scene& s, const std::vector<input>& inputs, const measure_options& options,
                      scene_result& result) {
  for (const run& r : s.runs) {
    if (!asks_for(r, check::accuracy)) continue;
    // every type of the run solves, and the reference certifies, the same
    // numbers: the drawn doubles as the run's narrowest type holds them
    std::vector<input> subset = samples_of(r, s, inputs);
    for (const auto& type : r.types) subset = ops_for(type).as_held(subset);
    const reference_list references = references_for(r, s, subset);
    for (const auto& type : r.types) {
      progress bar("scene " + s.name + ": accuracy " + type, static_cast<long>(subset.size()));
      ops_for(type).accuracy(r, subset, references, s.families.size(), options.raw, bar, result.accuracy);
    }
    if (std::find(r.types.begin(), r.types.end(), "double") != r.types.end())
      measure_candidates(subset, references, s.families.size(), result.accuracy);
  }
}

// One Google Benchmark per (run, type, row: a method or a batch target), over a shuffled array of the scene's inputs.
void measure_timings(const scene& s, const std::vector<input>& inputs, scene_result& result) {
  collector c;
  std::vector<std::pair<std::string, timing_result>> registered;
  const run* batch_run = batch_timing_run(s);
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const run& r = s.runs[k];
    if (!asks_for(r, check::timing)) continue;
    const std::vector<input> lanes = mixed(inputs, r.timing_inputs, s.seed + k);
    const std::string prefix = s.name + "|" + std::to_string(k) + "|";
    if (&r == batch_run) result.batch_lanes = lanes;
    if (std::find(r.types.begin(), r.types.end(), "double") != r.types.end())
      time_candidates(r, lanes, result.timing);
    for (const auto& type : r.types) {
      for (const std::string& row : ops_for(type).register_timings(r, lanes, prefix)) {
        const std::string name = prefix + type + "|" + row;
        c.items_per_iteration[name] = static_cast<long>(lanes.size());
        timing_result t;
        t.type = type;
        t.algorithm = row;
        t.inputs = static_cast<long>(lanes.size());
        registered.emplace_back(name, t);
      }
    }
  }
  if (registered.empty()) return;
  run_benchmarks(c);
  for (auto& [name, t] : registered) {
    t.ns = c.ns[name];
    spread(t.ns, t.median, t.min, t.max);
    result.timing.push_back(t);
  }
}

// Batch throughput against the scalar paths and the memory floor, streamed and in cache.
void measure_throughput(const scene& s, const std::vector<input>& inputs, scene_result& result) {
  const throughput& t = *s.batch_throughput;
  const std::vector<named_path> paths = throughput_paths();
  for (int pass = 0; pass < 2; ++pass) {
    const long lanes = pass == 0 ? t.lanes : t.cache_lanes;
    collector c;
    const std::string prefix = s.name + "|throughput|" + std::to_string(lanes) + "|";
    auto data = stream_data(mixed(inputs, lanes, s.seed + 1000 + static_cast<std::uint64_t>(pass)));
    register_throughput(data, paths, t, prefix, c);
    run_benchmarks(c);
    for (const auto& path : paths) {
      throughput_result row;
      row.what = path.what;
      row.lanes = lanes;
      row.ns = c.ns[prefix + path.what];
      spread(row.ns, row.median, row.min, row.max);
      row.gigabytes_per_second = bytes_per_lane / row.median;
      (pass == 0 ? result.throughput : result.throughput_cache).push_back(row);
    }
  }
}

void simulate_oscillator(const scene& s, scene_result& result) {
  for (const run& r : s.runs) {
    if (!asks_for(r, check::energy)) continue;
    for (const auto& type : r.types)
      for (method m : r.methods) {
        const auto start = std::chrono::steady_clock::now();
        result.energy.push_back(ops_for(type).simulate(*s.energy, m));
        std::fprintf(stderr, "contact-report: scene %s: oscillator %s %s: max energy error %.3g (%.1f s)\n",
                     s.name.c_str(), type.c_str(), name_of(m).c_str(), result.energy.back().max_exact,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
  }
}

}  // namespace

void measure_batch_across_scenes(std::vector<scene_result>& results) {
  const scene_result* reference = nullptr;
  std::vector<scene_result*> timed;
  for (auto& r : results)
    if (!r.batch_lanes.empty()) {
      timed.push_back(&r);
      if (r.s.batch_reference) reference = &r;
    }
  if (!reference) return;
  const run& rounds = *batch_timing_run(reference->s);  // its repetitions and min_time
  const std::vector<named_path> kernels = batch_kernels();
  collector c;
  auto name_of_timing = [](const named_path& kernel, const scene_result& r) {
    return "batch across scenes|" + kernel.what + "|" + r.s.name;
  };
  std::vector<std::shared_ptr<stream_arrays>> data;
  for (const auto* r : timed) {
    data.push_back(stream_data(r->batch_lanes));
    for (const auto& kernel : kernels)
      c.items_per_iteration[name_of_timing(kernel, *r)] = static_cast<long>(r->batch_lanes.size());
  }
  std::fprintf(stderr, "contact-report: batch across scenes, against scene %s\n", reference->s.name.c_str());
  // each round times every kernel on every scene once
  for (int round = 0; round < rounds.repetitions; ++round)
    for (const auto& kernel : kernels)
      for (std::size_t k = 0; k < timed.size(); ++k)
        register_round(name_of_timing(kernel, *timed[k]) + "#" + std::to_string(round), data[k], kernel.body,
                       rounds.min_time);
  run_benchmarks(c);
  for (const auto& kernel : kernels) {
    const std::vector<double>& reference_ns = c.ns[name_of_timing(kernel, *reference)];
    for (auto* r : timed) {
      batch_across_result b;
      b.kernel = kernel.what;
      b.reference = reference->s.name;
      b.ns = c.ns[name_of_timing(kernel, *r)];
      spread(b.ns, b.median, b.min, b.max);
      for (std::size_t round = 0; round < std::min(b.ns.size(), reference_ns.size()); ++round)
        b.ratios.push_back(b.ns[round] / reference_ns[round]);
      spread(b.ratios, b.ratio_median, b.ratio_min, b.ratio_max);
      if (kernel.what == name_of(method::batch))
        r->batch_across = std::move(b);
      else
        r->batch_across_targets.push_back(std::move(b));
    }
  }
}

scene_result measure(const scene& s, const measure_options& options) {
  const auto start = std::chrono::steady_clock::now();
  scene_result result;
  result.s = s;
  contact::mpfr_float::default_precision(static_cast<unsigned>(s.mpfr_digits10));
  std::fprintf(stderr, "contact-report: scene %s (%s)\n", s.name.c_str(), s.file.c_str());
  const std::vector<input> inputs = generate(s);
  result.mix = case_mix(s, inputs);
  measure_accuracy(s, inputs, options, result);
  measure_timings(s, inputs, result);
  if (s.batch_throughput) measure_throughput(s, inputs, result);
  simulate_oscillator(s, result);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "contact-report: scene %s done in %.1f s\n", s.name.c_str(), result.seconds);
  return result;
}

}  // namespace report
