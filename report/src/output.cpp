#include "output.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "contact/cases.hpp"
#include "contact/types.hpp"
#include "inputs.hpp"
#include "targets.hpp"

namespace report {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

std::string format_ulp(double ulps) {
  if (std::isnan(ulps)) return "nan";
  if (std::isinf(ulps)) return "inf";
  if (ulps < 0) return "—";
  if (ulps > 0 && ulps < 1e-3) return "<0.001";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", ulps);
  return buffer;
}

std::string format_ns(double ns) {
  if (!std::isfinite(ns)) return "—";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, ns < 100 ? "%.3g" : "%.0f", ns);
  return buffer;
}

std::string format_ratio(double ratio) {
  if (!std::isfinite(ratio)) return "—";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", ratio);
  return buffer;
}

std::string format_energy(double relative) {
  if (std::isnan(relative)) return "nan";
  if (std::isinf(relative)) return "inf (blew up)";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2e", relative);
  return buffer;
}

namespace {

json number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// The headline's tables compare algorithms in double.
const std::string double_type(contact::type_name<double>);

template <class Names>
std::string join(const Names& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

const timing_result* timing_of(const scene_result& r, const std::string& type, const std::string& algorithm) {
  for (const auto& t : r.timing)
    if (t.type == type && t.algorithm == algorithm) return &t;
  return nullptr;
}

const accuracy_result* accuracy_of(const scene_result& r, const std::string& type, const std::string& algorithm) {
  for (const auto& a : r.accuracy)
    if (a.type == type && a.algorithm == algorithm) return &a;
  return nullptr;
}

const throughput_result* throughput_of(const std::vector<throughput_result>& rows, const std::string& what) {
  for (const auto& t : rows)
    if (t.what == what) return &t;
  return nullptr;
}

// The (type, algorithm) rows of a scene's table, in the order of its runs.
std::vector<std::pair<std::string, std::string>> rows_of(const scene_result& r) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const run& x : r.s.runs) {
    if (asks_for(x, check::energy) && x.checks.size() == 1) continue;
    for (const auto& type : x.types)
      for (method m : x.methods) {
        std::pair<std::string, std::string> row{type, name_of(m)};
        if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
        if (m != method::batch && m != method::rounded_batch) continue;
        for (const auto& t : r.timing)  // each target's kernel alone, after batch and rounded_batch
          if (t.type == type && is_target_row_of(name_of(m), t.algorithm) &&
              std::find(rows.begin(), rows.end(), std::pair{t.type, t.algorithm}) == rows.end())
            rows.emplace_back(t.type, t.algorithm);
      }
  }
  // then whatever else was measured: the candidates (contact-report --candidate)
  for (const auto& a : r.accuracy)
    if (std::find(rows.begin(), rows.end(), std::pair{a.type, a.algorithm}) == rows.end()) rows.emplace_back(a.type, a.algorithm);
  return rows;
}

}  // namespace

// "N", or "N (k overflow)" when k of the N infinite results are right.
std::string format_inf(const accuracy_result& a) {
  if (a.inf_overflow == 0) return std::to_string(a.inf);
  return std::to_string(a.inf) + " (" + (a.inf_overflow == a.inf ? std::string("all") : std::to_string(a.inf_overflow)) +
         " overflow)";
}

std::string format_slow_path(const accuracy_result& a) {
  if (a.slow_path_share < 0) return "—";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g%%", 100 * a.slow_path_share);
  return buffer;
}

std::string format_iterations(const accuracy_result& a) {
  if (a.iterations_max < 0) return "—";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.2f / %ld", a.iterations_mean, a.iterations_max);
  return buffer;
}

namespace {

json iterations_json(const accuracy_result& a) {
  if (a.iterations_max < 0) return nullptr;
  return {{"mean", number(a.iterations_mean)}, {"max", a.iterations_max}};
}

std::string parameters_of(const family& f) {
  std::string out;
  for (const auto& [name, d] : f.parameters) out += (out.empty() ? "" : ", ") + name + " " + describe(d);
  if (f.ulps) out += ", ulps " + std::to_string(f.ulps);
  return out;
}

std::string plot_link(const std::string& name, const std::vector<std::string>& made, const std::string& caption) {
  if (std::find(made.begin(), made.end(), name) == made.end()) return "";
  return "![" + caption + "](plots/" + name + ".png)\n\n[" + caption + " (SVG)](plots/" + name + ".svg)\n\n";
}

// `algorithms` with, after batch and rounded_batch, their [NAME] rows timed in double in some scene.
std::vector<std::string> with_batch_targets(const std::vector<std::string>& algorithms,
                                            const std::vector<const scene_result*>& scenes) {
  std::vector<std::string> out;
  for (const auto& algorithm : algorithms) {
    out.push_back(algorithm);
    if (algorithm != name_of(method::batch) && algorithm != name_of(method::rounded_batch)) continue;
    for (const auto* r : scenes)
      for (const auto& t : r->timing)
        if (t.type == double_type && is_target_row_of(algorithm, t.algorithm) &&
            std::find(out.begin(), out.end(), t.algorithm) == out.end())
          out.push_back(t.algorithm);
  }
  return out;
}

// The algorithms that ran in double in some scene, in the order of all_methods.
std::vector<std::string> algorithms_in_double(const std::vector<scene_result>& scenes) {
  std::vector<std::string> out;
  for (method m : all_methods)
    for (const auto& r : scenes)
      if (accuracy_of(r, double_type, name_of(m)) || timing_of(r, double_type, name_of(m))) {
        out.push_back(name_of(m));
        break;
      }
  for (const auto& r : scenes)  // the candidates, after the built-in algorithms
    for (const auto& a : r.accuracy)
      if (a.type == double_type && std::find(out.begin(), out.end(), a.algorithm) == out.end()) out.push_back(a.algorithm);
  return out;
}

// "| algorithm |", one column per scene and the optional last column "| worst |".
void scene_columns(std::ostream& md, const std::vector<const scene_result*>& scenes, bool worst_column) {
  md << "| algorithm |";
  for (const auto* r : scenes) md << " " << r->s.name << " |";
  md << (worst_column ? " worst |" : "") << "\n|---|";
  for (std::size_t i = 0; i < scenes.size() + (worst_column ? 1 : 0); ++i) md << "---:|";
  md << "\n";
}

void write_double_accuracy(std::ostream& md, const std::vector<std::string>& algorithms,
                           const std::vector<const scene_result*>& scenes, json& headline) {
  md << "### Accuracy in double: maximum ulp error against the certified reference\n\n";
  scene_columns(md, scenes, true);
  for (const auto& algorithm : algorithms) {
    md << "| " << algorithm << " |";
    double worst = -1;
    json per_scene = json::object();
    for (const auto* r : scenes) {
      const auto* a = accuracy_of(*r, double_type, algorithm);
      md << " " << (a ? format_ulp(a->ulps.max) : "—") << " |";
      if (a) {
        worst = std::max(worst, a->ulps.max);
        per_scene[r->s.name] = number(a->ulps.max);
      }
    }
    md << " **" << format_ulp(worst) << "** |\n";
    headline["double_max_ulp"][algorithm] = {{"worst", number(worst)}, {"per_scene", per_scene}};
  }
  md << "\n";
}

void write_double_speed(std::ostream& md, const std::vector<std::string>& algorithms,
                        const std::vector<const scene_result*>& scenes, json& headline) {
  md << "### Speed in double: ns per solve (median over repetitions, CPU time)\n\n";
  scene_columns(md, scenes, false);
  for (const auto& algorithm : algorithms) {
    md << "| " << algorithm << " |";
    json per_scene = json::object();
    for (const auto* r : scenes) {
      const auto* t = timing_of(*r, double_type, algorithm);
      md << " " << (t ? format_ns(t->median) : "—") << " |";
      if (t) per_scene[r->s.name] = number(t->median);
    }
    md << "\n";
    headline["double_ns_per_solve"][algorithm] = per_scene;
  }
  md << "\n";
}

// The iterative methods' iteration counts over the accuracy samples.
void write_double_iterations(std::ostream& md, const std::vector<std::string>& algorithms,
                             const std::vector<const scene_result*>& scenes, json& headline) {
  std::vector<std::string> iterating;
  for (const auto& algorithm : algorithms)
    if (const auto m = method_named(algorithm); m && iterative(*m)) iterating.push_back(algorithm);
  if (iterating.empty()) return;
  md << "### Iterations in double: mean / max over the accuracy samples\n\n";
  scene_columns(md, scenes, false);
  for (const auto& algorithm : iterating) {
    md << "| " << algorithm << " |";
    json per_scene = json::object();
    for (const auto* r : scenes) {
      const auto* a = accuracy_of(*r, double_type, algorithm);
      md << " " << (a ? format_iterations(*a) : "—") << " |";
      if (a && a->iterations_max >= 0) per_scene[r->s.name] = iterations_json(*a);
    }
    md << "\n";
    headline["double_iterations"][algorithm] = per_scene;
  }
  md << "\nWhat each counts is in the Method section.\n\n";
}

// The stable form in every other registered type that some scene ran it in.
void write_stable_by_type(std::ostream& md, const std::vector<const scene_result*>& scenes, json& headline) {
  const std::string stable = name_of(method::stable);
  std::vector<std::string> types;
  for (std::string_view name : contact::type_names) {
    const std::string type(name);
    if (type == double_type) continue;
    for (const auto* r : scenes)
      if (accuracy_of(*r, type, stable) || timing_of(*r, type, stable)) {
        types.push_back(type);
        break;
      }
  }
  if (types.empty()) return;
  md << "### What each precision costs: the stable form\n\n"
        "Worst maximum error over the scenes, in ulps of the type itself and after rounding the result to "
        "double; ns per solve in each scene.\n\n| type | max ulp (own) | max ulp as double |";
  for (const auto* r : scenes) md << " ns " << r->s.name << " |";
  md << "\n|---|---:|---:|";
  for (std::size_t i = 0; i < scenes.size(); ++i) md << "---:|";
  md << "\n";
  for (const auto& type : types) {
    double worst = -1, worst_double = -1;
    json ns = json::object();
    std::string cells;
    for (const auto* r : scenes) {
      if (const auto* a = accuracy_of(*r, type, stable)) {
        worst = std::max(worst, a->ulps.max);
        worst_double = std::max(worst_double, a->max_ulp_as_double);
      }
      const auto* t = timing_of(*r, type, stable);
      cells += " " + (t ? format_ns(t->median) : std::string("—")) + " |";
      if (t) ns[r->s.name] = number(t->median);
    }
    md << "| " << type << " | " << format_ulp(worst) << " | " << format_ulp(worst_double) << " |" << cells << "\n";
    headline["stable_by_type"][type] = {
        {"max_ulp", number(worst)}, {"max_ulp_as_double", number(worst_double)}, {"ns_per_solve", ns}};
  }
  md << "\n";
}

// For each scene that times textbook and stable in a type wider than double:
// each type's stable path against its own textbook, with rounded and newton.
// A type's rows are timed in the same rounds, so each ratio divides two
// medians measured side by side.
void write_cost_by_type(std::ostream& md, const std::vector<const scene_result*>& scenes, json& headline) {
  const std::string textbook = name_of(method::textbook), stable = name_of(method::stable),
                    rounded = name_of(method::rounded), newton = name_of(method::newton);
  for (const auto* r : scenes) {
    std::vector<std::string> types;
    bool wider = false;
    for (std::string_view name : contact::type_names) {
      const std::string type(name);
      if (!timing_of(*r, type, textbook) || !timing_of(*r, type, stable)) continue;
      types.push_back(type);
      wider = wider || (type != double_type && name != contact::type_name<float>);
    }
    if (!wider) continue;
    md << "### What each precision costs against its own textbook (scene " << r->s.name << ")\n\n"
       << "ns per solve (medians); each ratio divides two medians of one type, timed in the same rounds.\n\n"
       << "| type | textbook | stable | stable / textbook | rounded | rounded / stable | newton |\n"
       << "|---|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& type : types) {
      const auto *t = timing_of(*r, type, textbook), *s = timing_of(*r, type, stable);
      const auto *ro = timing_of(*r, type, rounded), *n = timing_of(*r, type, newton);
      json entry = {{"textbook", number(t->median)}, {"stable", number(s->median)},
                    {"stable_over_textbook", number(s->median / t->median)}};
      md << "| " << type << " | " << format_ns(t->median) << " | " << format_ns(s->median) << " | **"
         << format_ratio(s->median / t->median) << "** | ";
      if (ro) {
        md << format_ns(ro->median) << " | " << format_ratio(ro->median / s->median) << " | ";
        entry["rounded"] = number(ro->median);
        entry["rounded_over_stable"] = number(ro->median / s->median);
      } else {
        md << "— | — | ";
      }
      md << (n ? format_ns(n->median) : std::string("—")) << " |\n";
      if (n) entry["newton"] = number(n->median);
      headline["cost_by_type"][r->s.name][type] = entry;
    }
    md << "\n";
  }
}

// The throughput of each batch kernel: batch (the target dispatch chose), then
// each target's kernel alone, streamed and in cache.
void write_batch_headline(std::ostream& md, const scene_result& r, const run_info& info, json& headline) {
  md << "### Batch throughput (scene " << r.s.name << ", double, mixed cases)\n\n"
     << "| lanes | kernel | floor ns/lane | kernel ns/lane | stable | textbook | kernel speed-up over textbook | "
        "over stable | kernel / floor | division floor | its speed-up over textbook |\n"
     << "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto* rows : {&r.throughput, &r.throughput_cache}) {
    const auto *floor = throughput_of(*rows, "floor"), *stable = throughput_of(*rows, "stable"),
               *textbook = throughput_of(*rows, "textbook"), *divisions = throughput_of(*rows, "division floor");
    if (!floor || !stable || !textbook || !divisions) continue;
    const bool streamed = rows == &r.throughput;
    const char* pass = streamed ? "streamed" : "in_cache";
    for (const auto& kernel : *rows) {
      const bool dispatched = kernel.what == name_of(method::batch);
      if (!dispatched && !is_batch_target_row(kernel.what)) continue;
      md << "| " << floor->lanes << (streamed ? " (streamed)" : " (in cache)") << " | " << kernel.what << " | "
         << format_ns(floor->median) << " | " << format_ns(kernel.median) << " | " << format_ns(stable->median) << " | "
         << format_ns(textbook->median) << " | **" << format_ratio(textbook->median / kernel.median) << "** | "
         << format_ratio(stable->median / kernel.median) << " | **" << format_ratio(kernel.median / floor->median)
         << "** | " << format_ns(divisions->median) << " | " << format_ratio(textbook->median / divisions->median) << " |\n";
      const json figures = {{"scene", r.s.name},
                            {"lanes", floor->lanes},
                            {"floor_ns", number(floor->median)},
                            {"batch_ns", number(kernel.median)},
                            {"stable_ns", number(stable->median)},
                            {"textbook_ns", number(textbook->median)},
                            {"speedup_over_textbook", number(textbook->median / kernel.median)},
                            {"speedup_over_stable", number(stable->median / kernel.median)},
                            {"batch_to_floor", number(kernel.median / floor->median)},
                            {"division_floor_ns", number(divisions->median)},
                            {"division_floor_speedup_over_textbook", number(textbook->median / divisions->median)}};
      if (dispatched)
        headline["batch"][pass] = figures;
      else
        headline["batch_per_target"][kernel.what][pass] = figures;
    }
  }
  md << "\n`batch` is `solve_batch`, which runs the target dispatch chose (" << info.batch_chosen
     << "); `batch[NAME]` runs target NAME's kernel alone. The goals: streamed, within 1.5 times the floor "
        "for the target dispatch chose; in cache, at least 2.5 times faster than scalar textbook on every vector "
        "target (docs/performance.md says what bounds both). The in-cache rows repeat a "
        "short array, whose branches a branch predictor partly learns by heart: it flatters the scalar paths. The "
        "division floor runs only the correctly rounded divisions and square roots the lanes' cases need, in vectors: "
        "no exact kernel runs below it, and textbook over it bounds any kernel's speed-up.\n\n";
}

// The batch kernel on every scene's timing inputs, timed in the same rounds
// (measure_batch_across_scenes): a ratio of two scenes that no change of the
// machine's load between them moves.
void write_batch_across_scenes(std::ostream& md, const std::vector<scene_result>& scenes, json& headline) {
  std::vector<const scene_result*> timed;
  for (const auto& r : scenes)
    if (r.batch_across) timed.push_back(&r);
  if (timed.empty()) return;
  const std::string& reference = timed.front()->batch_across->reference;
  md << "### Batch across scenes (double): ns per lane, every scene timed in the same rounds\n\n"
     << "| scene | ns per lane (median) | over " << reference << " (median of the rounds' ratios) | range of the ratios |\n"
     << "|---|---:|---:|---:|\n";
  for (const auto* r : timed) {
    const auto& b = *r->batch_across;
    md << "| " << r->s.name << " | " << format_ns(b.median) << " | **" << format_ratio(b.ratio_median) << "** | "
       << format_ratio(b.ratio_min) << "-" << format_ratio(b.ratio_max) << " |\n";
    headline["batch_across_scenes"][r->s.name] = {{"ns_per_lane", number(b.median)},
                                                  {"over_reference", number(b.ratio_median)}};
  }
  headline["batch_across_scenes_reference"] = reference;
  md << "\nEach round times the batch kernel (`batch`, the target dispatch chose, and each target alone) once on "
        "each scene's timing inputs (the arrays of the scene's own timing), one scene after the other; the ratio of "
        "a round divides a scene's time by the reference scene's with the same kernel in the same round. The scenes' own timing tables time each scene a minute or more apart.\n\n";
  if (timed.front()->batch_across_targets.empty()) return;
  md << "Per target, in the same rounds: each target's kernel alone on every scene, over its own time on "
     << reference << ".\n\n"
     << "| scene | kernel | ns per lane (median) | over " << reference << " (median of the rounds' ratios) | "
     << "range of the ratios |\n|---|---|---:|---:|---:|\n";
  for (const auto& kernel : timed.front()->batch_across_targets)
    for (const auto* r : timed)
      for (const auto& b : r->batch_across_targets) {
        if (b.kernel != kernel.kernel) continue;
        md << "| " << r->s.name << " | " << b.kernel << " | " << format_ns(b.median) << " | **"
           << format_ratio(b.ratio_median) << "** | " << format_ratio(b.ratio_min) << "-" << format_ratio(b.ratio_max)
           << " |\n";
        headline["batch_across_scenes_per_target"][b.kernel][r->s.name] = {{"ns_per_lane", number(b.median)},
                                                                           {"over_reference", number(b.ratio_median)}};
      }
  md << "\n";
}

void write_energy_headline(std::ostream& md, const scene_result& r, json& headline) {
  md << "### Energy conservation (scene " << r.s.name << "): maximum relative energy error\n\n"
     << "| type | algorithm | max abs(H[n] - H[0]) / H[0] |\n|---|---|---:|\n";
  for (const auto& e : r.energy) {
    md << "| " << e.type << " | " << e.algorithm << " | " << format_energy(e.max_exact) << " |\n";
    headline["energy"][e.type][e.algorithm] = number(e.max_exact);
  }
  md << "\n";
}

void write_headline(std::ostream& md, const std::vector<scene_result>& scenes, const run_info& info, json& headline) {
  std::vector<const scene_result*> with_runs;
  for (const auto& r : scenes)
    if (!r.accuracy.empty() || !r.timing.empty()) with_runs.push_back(&r);
  const std::vector<std::string> algorithms = algorithms_in_double(scenes);
  if (!algorithms.empty() && !with_runs.empty()) {
    write_double_accuracy(md, algorithms, with_runs, headline);
    write_double_speed(md, with_batch_targets(algorithms, with_runs), with_runs, headline);
    write_double_iterations(md, algorithms, with_runs, headline);
  }
  write_stable_by_type(md, with_runs, headline);
  write_cost_by_type(md, with_runs, headline);
  write_batch_across_scenes(md, scenes, headline);
  for (const auto& r : scenes)
    if (!r.throughput.empty()) write_batch_headline(md, r, info, headline);
  for (const auto& r : scenes)
    if (!r.energy.empty()) write_energy_headline(md, r, headline);
}

void write_method(std::ostream& md, const run_info& info) {
  md << "## Method\n\n"
        "- **Reference.** Every input is solved by `contact::reference::solve` (MPFR and GMP): the case is decided "
        "in exact rational arithmetic, the root computed at 256 bits or more (four times the widest type's precision "
        "in the run) and certified by the sign change of the exact residual of (A.2) around it. An error is "
        "|computed - exact| in units in the last place of the type at the exact root (`reference::ulp_error`); a "
        "correctly rounded result is at most 0.5 ulp off. The inputs are drawn in double and, in a run with a type "
        "narrower than double (float), rounded to it first (saturating at its largest finite value), so that every "
        "type of a run solves, and the reference certifies, exactly the same numbers.\n"
        "- **Statistics.** Maximum, 99th percentile and median (nearest rank) of the ulp errors of all samples of a "
        "run; a NaN result counts as an infinite error and is counted under NaN. *inf* counts infinite results; "
        "\"(k overflow)\" says how many of them are right, because the exact root rounds to infinity in the type. *compl.* counts complementarity violations: a "
        "result that does not lie on the side of dy that its own case claims (`lies_on_its_side`; for `rounded`, "
        "which promises it only weakly, s = dy is on both sides). *wrong case* "
        "counts results whose case differs from the exact one. *slow path* (for `rounded` only) is the share of "
        "samples for which the fast approximation's rounding test failed and the exact decision ran.\n"
        "- **Timing.** Google Benchmark, in process, single-threaded: one benchmark per (type, algorithm) loops over "
        "an array of the scene's inputs, shuffled so that the cases mix (its length is in the table). Each is warmed "
        "(Google Benchmark's warm-up and iteration calibration), then repeated; the table gives the median over the "
        "repetitions of CPU nanoseconds per solve and its spread (minimum to maximum).\n"
        "- **Peers.** `boost_quadratic` is Boost.Math `tools::quadratic_roots` (present in Boost 1.74, "
        "`boost/math/tools/roots.hpp`; it uses an fma-corrected discriminant for built-in types and the naive one for "
        "multiprecision types) and `eigen_companion` is Eigen 3.4's `PolynomialSolver` (eigenvalues of the balanced "
        "companion matrix), each applied to the quadratic of the case: (A.9) (1+phi) s^2 + (u - 2 phi dy) s + phi "
        "dy^2 = 0 for impact (smaller root), (A.23) s^2 + u s - phi dy^2 = 0 for release (larger root) and the linear "
        "(A.18) for contact; the case is decided by the printed criteria, as the textbook path does.\n"
        "- **Iterative peers**, what a user without the closed form runs on the residual R(s) of (A.2), each as its "
        "users call it. All start at the kink s = dy, where the sign of R decides the side of the root and so the "
        "case (the library newton's rule); none moves its answer onto that side, so *compl.* shows what that costs. "
        "`boost_newton` and `boost_halley` are Boost.Math `tools::newton_raphson_iterate` and `halley_iterate` "
        "(Boost 1.74) with the digits of Boost's examples, 0.6 and 0.4 of the type's (each Newton step doubles the "
        "correct digits, each Halley step triples them) and max_iter 50, on R and its derivatives on the root's "
        "side; `boost_toms748` is `tools::toms748_solve` with `eps_tolerance<T>` of the type's digits and max_iter "
        "50, answering the midpoint of the bracket it returns. The Boost peers search the bracket the kink gives: "
        "[-u, dy] below it (R(-u) <= 0 there), [dy, |dy| + 2 b] above it, b a bound of the root: max(0, -u) on the "
        "free side, max(0, -u) + sqrt(phi) dy on the release side and, for u > 0, phi dy^2 / u if smaller "
        "(`bracket_from_kink` in `report/src/iterative_peers.hpp`). A failure Boost reports by throwing (no sign "
        "change within the type's range) gives NaN, and so do toms748_solve's and halley_iterate's steps once "
        "products of residuals overflow (|R| beyond about 1e154 in double). `practitioner_newton` is plain Newton "
        "as physical-modelling code runs it: from the kink, with the slope of the side the iterate is on, stopping "
        "when a step is at most 1e-12 of |s| or after 20 steps, without a bracket (the same 1e-12 in every type: "
        "in float only a zero step meets it).\n"
        "- **Iterations** (mean / max over the accuracy samples): for `newton` the residuals it evaluates after the "
        "one at the kink (`contact::newton_iterate`'s count); for the Boost peers the evaluations of R (with its "
        "derivatives) inside Boost, counted by the function Boost calls: newton_raphson_iterate and halley_iterate "
        "evaluate again at their start s = dy, toms748_solve at both ends of the bracket; the evaluation at the kink "
        "that chose the bracket is not counted, and when it found the root (R(dy) = 0) Boost is not called (0). "
        "This is the count Boost writes back into max_iter, except where halley_iterate searches beyond its "
        "bracket: there Boost's count wraps below zero and it writes back more than it evaluated, and the search "
        "can run past max_iter. For `practitioner_newton` its Newton steps, one evaluation each, the first at the "
        "kink.\n"
        "- **newton** is the library's safeguarded Newton iteration on the residual (the baseline the closed form "
        "replaces); **textbook** is the appendix's summary with its misprints corrected and nothing else; **stable** "
        "is `contact::solve_stable`; **rounded** is `contact::solve_rounded`, the exact root rounded to nearest "
        "(ties to even) in the type (float, double, long double and float128 only); **batch** is `contact::solve_batch` (`contact/batch.hpp`), whose results equal "
        "stable's bit for bit (tested), on the target dispatch chose; **batch[NAME]** is the batch kernel of target "
        "NAME alone (`contact::batch_targets()`), timed for every target this CPU supports, in float and double. "
        "Every target gives batch's results bit for bit (tested), so the batch[NAME] rows have timings and no "
        "accuracy figures of their own. **rounded_batch** is `contact::solve_rounded_batch`, whose results equal "
        "rounded's bit for bit (tested): the vectors take the inputs inside the common window (float's widened "
        "to double, where they run float's own test) and solve_rounded the rest; **rounded_batch[NAME]** is its "
        "kernel of target NAME alone, in float and double.\n"
        "- **Types.** The registered scalar types of `contact/types.hpp` ("
     << join(contact::type_names)
     << "); each scene says which algorithms run in which of them, "
     << contact::type_name<contact::mpfr_float>
     << " at the scene's `mpfr_digits10` decimal digits.\n"
        "- **Energy.** The oscillator of docs/equations.md, section 1 (mass, spring, one-sided barrier, "
        "discrete-gradient midpoint "
        "scheme, dt = 1/sample rate) is stepped in each type with each algorithm; H is evaluated exactly (MPFR) from "
        "the parameters and state as the type holds them, so the figure is the drift of the simulation, not the "
        "rounding of H. The energy error with H evaluated in the type itself is in results.csv/json.\n"
        "- **Build.** " << info.compiler << ", flags `" << info.flags << "` for every algorithm alike.\n\n";
}

// The families and how their inputs fall into the cases.
void write_families(std::ostream& md, const scene_result& r) {
  md << "| family | generator | samples | parameters |";
  for (contact::contact_case c : contact::valid_cases) md << " " << contact::name_of(c) << " |";
  md << "\n|---|---|---:|---|";
  for (std::size_t c = 0; c < std::size(contact::valid_cases); ++c) md << "---:|";
  md << "\n";
  for (std::size_t i = 0; i < r.s.families.size(); ++i) {
    const auto& f = r.s.families[i];
    md << "| " << f.name << " | " << f.generator << " | " << f.samples << " | " << parameters_of(f) << " |";
    for (contact::contact_case c : contact::valid_cases) md << " " << r.mix[i].cases[static_cast<int>(c)] << " |";
    md << "\n";
  }
  md << "\nCases by the exact criteria.\n\n";
}

// One row per (type, algorithm): accuracy and timing side by side.
void write_results(std::ostream& md, const scene_result& r,
                   const std::vector<std::pair<std::string, std::string>>& rows) {
  bool as_double = false;
  for (const auto& a : r.accuracy) as_double = as_double || a.max_ulp_as_double >= 0;
  md << "| type | algorithm | samples | max ulp | p99 ulp | median ulp |" << (as_double ? " max ulp as double |" : "")
     << " NaN | inf | compl. | wrong case | iterations mean / max | slow path | ns/solve | spread | inputs × reps |\n"
     << "|---|---|---:|---:|---:|---:|" << (as_double ? "---:|" : "") << "---:|---:|---:|---:|---:|---:|---:|---|---:|\n";
  for (const auto& [type, algorithm] : rows) {
    const auto* a = accuracy_of(r, type, algorithm);
    const auto* t = timing_of(r, type, algorithm);
    md << "| " << type << " | " << algorithm << " | ";
    if (a) {
      md << a->samples << " | " << format_ulp(a->ulps.max) << " | " << format_ulp(a->ulps.p99) << " | "
         << format_ulp(a->ulps.median) << " | ";
      if (as_double) md << format_ulp(a->max_ulp_as_double) << " | ";
      md << a->nan << " | " << format_inf(*a) << " | " << a->complementarity << " | " << a->wrong_case << " | "
         << format_iterations(*a) << " | " << format_slow_path(*a) << " | ";
    } else {
      md << "— | — | — | — | " << (as_double ? "— | " : "") << "— | — | — | — | — | — | ";
    }
    if (t && !t->ns.empty())
      md << format_ns(t->median) << " | " << format_ns(t->min) << "–" << format_ns(t->max) << " | " << t->inputs << " × "
         << t->ns.size() << " |\n";
    else
      md << "— | — | — |\n";
  }
  md << "\n";
}

void write_family_max(std::ostream& md, const scene_result& r) {
  md << "Maximum ulp error by family:\n\n| type | algorithm |";
  for (const auto& f : r.s.families) md << " " << f.name << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < r.s.families.size(); ++i) md << "---:|";
  md << "\n";
  for (const auto& a : r.accuracy) {
    md << "| " << a.type << " | " << a.algorithm << " |";
    for (double v : a.family_max) md << " " << format_ulp(v) << " |";
    md << "\n";
  }
  md << "\n";
}

void write_throughput(std::ostream& md, const scene_result& r) {
  md << "Batch throughput (double, mixed cases; ns per lane, median of " << r.s.batch_throughput->repetitions
     << " repetitions, spread min–max; " << bytes_per_lane << " bytes per lane):\n\n"
     << "| lanes | path | ns/lane | spread | GB/s |\n|---:|---|---:|---|---:|\n";
  for (const auto* rows : {&r.throughput, &r.throughput_cache})
    for (const auto& t : *rows)
      md << "| " << t.lanes << " | " << t.what << " | " << format_ns(t.median) << " | " << format_ns(t.min) << "–"
         << format_ns(t.max) << " | " << format_ratio(t.gigabytes_per_second) << " |\n";
  md << "\nThe floor streams the same bytes (reads u, dy, phi; writes s and the case) and solves nothing.\n\n";
}

void write_energy(std::ostream& md, const scene_result& r, const std::vector<std::string>& plots) {
  const scene& s = r.s;
  const oscillator& o = *s.energy;
  md << "Oscillator: m = " << o.mass << " kg, K = " << o.spring << " N/m, barrier at h_b = " << o.barrier_height
     << " m with k_b = " << o.barrier_stiffness << " N/m, sample rate " << o.sample_rate << " Hz, " << o.duration
     << " s (" << r.energy.front().steps << " steps), y0 = " << o.initial_displacement << " m, v0 = "
     << o.initial_velocity << " m/s.\n\n"
     << "| type | algorithm | steps in contact | max rel. energy error (exact H) | final | max with H in the type |\n"
        "|---|---|---:|---:|---:|---:|\n";
  for (const auto& e : r.energy)
    md << "| " << e.type << " | " << e.algorithm << " | " << e.contact_steps << " | " << format_energy(e.max_exact)
       << " | " << format_energy(e.final_exact) << " | " << format_energy(e.max_in_type) << " |\n";
  md << "\n";
  std::set<std::string> types;
  for (const auto& e : r.energy) types.insert(e.type);
  for (const auto& type : types)
    md << plot_link("energy_" + s.name + "_" + type, plots, "Relative energy error, " + type + ", scene " + s.name);
  md << plot_link("energy_" + s.name + "_types", plots, "Relative energy error of the stable form by type, scene " + s.name);
}

void write_scene(std::ostream& md, const scene_result& r, const std::vector<std::string>& plots) {
  const scene& s = r.s;
  md << "## Scene " << s.name << ": " << s.title << "\n\n";
  md << "File `" << fs::path(s.file).filename().string() << "`, seed " << s.seed << ", measured in "
     << format_ratio(r.seconds) << " s.";
  if (!s.description.empty()) md << " " << s.description;
  md << "\n\n";
  if (!s.families.empty()) write_families(md, r);
  if (const auto rows = rows_of(r); !rows.empty()) {
    write_results(md, r, rows);
    if (!r.accuracy.empty() && s.families.size() > 1) write_family_max(md, r);
    if (std::find(plots.begin(), plots.end(), "pareto_" + s.name) != plots.end())
      md << "Maximum ulp error against ns per solve: double and float in one panel, the wider types in another; "
            "colour for the algorithm, shape for the type, a line per type through the points no other of its type "
            "beats on both (the Pareto front); the strip on top holds the infinite and NaN errors.\n\n"
         << plot_link("pareto_" + s.name, plots, "Error against run time, scene " + s.name);
  }
  if (!r.throughput.empty()) write_throughput(md, r);
  if (!r.energy.empty()) write_energy(md, r, plots);
}

json scene_json(const scene_result& r) {
  const scene& s = r.s;
  json j;
  j["name"] = s.name;
  j["title"] = s.title;
  j["file"] = s.file;
  j["description"] = s.description;
  j["seed"] = s.seed;
  j["seconds"] = r.seconds;
  j["families"] = json::array();
  for (std::size_t i = 0; i < s.families.size(); ++i) {
    const auto& f = s.families[i];
    json cases;
    cases[std::string(contact::name_of(contact::contact_case::invalid))] =
        r.mix[i].cases[static_cast<int>(contact::contact_case::invalid)];
    for (contact::contact_case c : contact::valid_cases)
      cases[std::string(contact::name_of(c))] = r.mix[i].cases[static_cast<int>(c)];
    j["families"].push_back(
        {{"name", f.name}, {"generator", f.generator}, {"samples", f.samples}, {"parameters", parameters_of(f)}, {"cases", cases}});
  }
  j["accuracy"] = json::array();
  for (const auto& a : r.accuracy) {
    json family_max;
    for (std::size_t i = 0; i < a.family_max.size(); ++i) family_max[s.families[i].name] = number(a.family_max[i]);
    json histogram;
    for (int b = 0; b < histogram_bins; ++b)
      if (a.histogram[static_cast<std::size_t>(b)]) histogram[histogram_label(b)] = a.histogram[static_cast<std::size_t>(b)];
    j["accuracy"].push_back({{"type", a.type},
                             {"algorithm", a.algorithm},
                             {"samples", a.samples},
                             {"max_ulp", number(a.ulps.max)},
                             {"p99_ulp", number(a.ulps.p99)},
                             {"median_ulp", number(a.ulps.median)},
                             {"max_ulp_as_double", a.max_ulp_as_double < 0 ? json(nullptr) : number(a.max_ulp_as_double)},
                             {"nan", a.nan},
                             {"inf", a.inf},
                             {"inf_overflow", a.inf_overflow},
                             {"complementarity_violations", a.complementarity},
                             {"wrong_case", a.wrong_case},
                             {"iterations", iterations_json(a)},
                             {"slow_path_share", a.slow_path_share < 0 ? json(nullptr) : number(a.slow_path_share)},
                             {"reference_bits", a.reference_bits},
                             {"family_max_ulp", family_max},
                             {"histogram", histogram}});
  }
  j["timing"] = json::array();
  for (const auto& t : r.timing) {
    json reps = json::array();
    for (double x : t.ns) reps.push_back(number(x));
    j["timing"].push_back({{"type", t.type},
                           {"algorithm", t.algorithm},
                           {"inputs", t.inputs},
                           {"ns_median", number(t.median)},
                           {"ns_min", number(t.min)},
                           {"ns_max", number(t.max)},
                           {"ns_repetitions", reps}});
  }
  j["throughput"] = json::array();
  for (const auto* rows : {&r.throughput, &r.throughput_cache})
    for (const auto& t : *rows) {
      json reps = json::array();
      for (double x : t.ns) reps.push_back(number(x));
      j["throughput"].push_back({{"lanes", t.lanes},
                                 {"path", t.what},
                                 {"ns_median", number(t.median)},
                                 {"ns_min", number(t.min)},
                                 {"ns_max", number(t.max)},
                                 {"gigabytes_per_second", number(t.gigabytes_per_second)},
                                 {"ns_repetitions", reps}});
    }
  const auto across_json = [&r](const batch_across_result& b) {
    json reps = json::array(), ratios = json::array();
    for (double x : b.ns) reps.push_back(number(x));
    for (double x : b.ratios) ratios.push_back(number(x));
    return json{{"reference", b.reference},       {"inputs", r.batch_lanes.size()},
                {"ns_median", number(b.median)},  {"ns_min", number(b.min)},
                {"ns_max", number(b.max)},        {"ns_repetitions", reps},
                {"over_reference_median", number(b.ratio_median)},
                {"over_reference_min", number(b.ratio_min)},
                {"over_reference_max", number(b.ratio_max)},
                {"over_reference_repetitions", ratios}};
  };
  if (r.batch_across) j["batch_across_scenes"] = across_json(*r.batch_across);
  for (const auto& b : r.batch_across_targets) j["batch_across_scenes_per_target"][b.kernel] = across_json(b);
  j["energy"] = json::array();
  for (const auto& e : r.energy) {
    json time = json::array(), envelope = json::array();
    for (std::size_t k = 0; k < e.time.size(); ++k) {
      time.push_back(e.time[k]);
      envelope.push_back(number(e.envelope[k]));
    }
    j["energy"].push_back({{"type", e.type},
                           {"algorithm", e.algorithm},
                           {"steps", e.steps},
                           {"contact_steps", e.contact_steps},
                           {"max_relative_error", number(e.max_exact)},
                           {"final_relative_error", number(e.final_exact)},
                           {"max_relative_error_in_type", number(e.max_in_type)},
                           {"finite", e.finite},
                           {"plot_time", time},
                           {"plot_max_relative_error", envelope}});
  }
  return j;
}

void write_csv(std::ostream& csv, const std::vector<scene_result>& scenes) {
  csv << "scene,check,type,algorithm,metric,value\n";
  for (const auto& r : scenes) {
    const std::string& sn = r.s.name;
    auto row = [&](const char* check, const std::string& type, const std::string& algorithm, const std::string& metric,
                   const std::string& value) {
      csv << sn << "," << check << "," << type << "," << algorithm << "," << metric << "," << value << "\n";
    };
    for (const auto& a : r.accuracy) {
      row("accuracy", a.type, a.algorithm, "samples", std::to_string(a.samples));
      row("accuracy", a.type, a.algorithm, "max_ulp", csv_number(a.ulps.max));
      row("accuracy", a.type, a.algorithm, "p99_ulp", csv_number(a.ulps.p99));
      row("accuracy", a.type, a.algorithm, "median_ulp", csv_number(a.ulps.median));
      if (a.max_ulp_as_double >= 0) row("accuracy", a.type, a.algorithm, "max_ulp_as_double", csv_number(a.max_ulp_as_double));
      row("accuracy", a.type, a.algorithm, "nan", std::to_string(a.nan));
      row("accuracy", a.type, a.algorithm, "inf", std::to_string(a.inf));
      row("accuracy", a.type, a.algorithm, "inf_overflow", std::to_string(a.inf_overflow));
      row("accuracy", a.type, a.algorithm, "complementarity_violations", std::to_string(a.complementarity));
      row("accuracy", a.type, a.algorithm, "wrong_case", std::to_string(a.wrong_case));
      if (a.iterations_max >= 0) {
        row("accuracy", a.type, a.algorithm, "iterations_mean", csv_number(a.iterations_mean));
        row("accuracy", a.type, a.algorithm, "iterations_max", std::to_string(a.iterations_max));
      }
      if (a.slow_path_share >= 0) row("accuracy", a.type, a.algorithm, "slow_path_share", csv_number(a.slow_path_share));
      for (std::size_t i = 0; i < a.family_max.size(); ++i)
        if (a.family_max[i] >= 0)
          row("accuracy", a.type, a.algorithm, "max_ulp[" + r.s.families[i].name + "]", csv_number(a.family_max[i]));
    }
    for (const auto& t : r.timing) {
      row("timing", t.type, t.algorithm, "inputs", std::to_string(t.inputs));
      row("timing", t.type, t.algorithm, "repetitions", std::to_string(t.ns.size()));
      row("timing", t.type, t.algorithm, "ns_median", csv_number(t.median));
      row("timing", t.type, t.algorithm, "ns_min", csv_number(t.min));
      row("timing", t.type, t.algorithm, "ns_max", csv_number(t.max));
    }
    for (const auto* rows : {&r.throughput, &r.throughput_cache})
      for (const auto& t : *rows) {
        const std::string check = "throughput@" + std::to_string(t.lanes);
        row(check.c_str(), double_type, t.what, "ns_median", csv_number(t.median));
        row(check.c_str(), double_type, t.what, "ns_min", csv_number(t.min));
        row(check.c_str(), double_type, t.what, "ns_max", csv_number(t.max));
        row(check.c_str(), double_type, t.what, "gigabytes_per_second", csv_number(t.gigabytes_per_second));
      }
    std::vector<const batch_across_result*> across;
    if (r.batch_across) across.push_back(&*r.batch_across);
    for (const auto& b : r.batch_across_targets) across.push_back(&b);
    for (const auto* b : across) {
      const char* check = "batch_across_scenes";
      row(check, double_type, b->kernel, "inputs", std::to_string(r.batch_lanes.size()));
      row(check, double_type, b->kernel, "repetitions", std::to_string(b->ns.size()));
      row(check, double_type, b->kernel, "ns_median", csv_number(b->median));
      row(check, double_type, b->kernel, "ns_min", csv_number(b->min));
      row(check, double_type, b->kernel, "ns_max", csv_number(b->max));
      row(check, double_type, b->kernel, "over_" + b->reference + "_median", csv_number(b->ratio_median));
      row(check, double_type, b->kernel, "over_" + b->reference + "_min", csv_number(b->ratio_min));
      row(check, double_type, b->kernel, "over_" + b->reference + "_max", csv_number(b->ratio_max));
    }
    for (const auto& e : r.energy) {
      row("energy", e.type, e.algorithm, "steps", std::to_string(e.steps));
      row("energy", e.type, e.algorithm, "contact_steps", std::to_string(e.contact_steps));
      row("energy", e.type, e.algorithm, "max_relative_error", csv_number(e.max_exact));
      row("energy", e.type, e.algorithm, "final_relative_error", csv_number(e.final_exact));
      row("energy", e.type, e.algorithm, "max_relative_error_in_type", csv_number(e.max_in_type));
    }
  }
}

void write_raw(const fs::path& directory, const std::vector<scene_result>& scenes) {
  for (const auto& r : scenes) {
    const fs::path dir = directory / "raw" / r.s.name;
    fs::create_directories(dir);
    for (const auto& a : r.accuracy) {
      std::ofstream out(dir / ("accuracy_" + a.type + "_" + a.algorithm + ".csv"));
      out << "index,family,u,dy,phi,s,case,ulp_error,iterations\n";  // iterations empty: the method does not iterate
      char buffer[200];
      for (std::size_t i = 0; i < a.errors.size(); ++i) {
        const auto& in = a.inputs[i];
        std::snprintf(buffer, sizeof buffer, "%zu,%s,%a,%a,%a,", i, r.s.families[static_cast<std::size_t>(in.family)].name.c_str(),
                      in.u, in.dy, in.phi);
        out << buffer << a.s_text[i] << "," << a.which[i] << "," << csv_number(a.errors[i]) << ","
            << (a.iterations.empty() ? std::string() : std::to_string(a.iterations[i])) << "\n";
      }
    }
    for (const auto& t : r.timing) {
      std::ofstream out(dir / ("timing_" + t.type + "_" + t.algorithm + ".csv"));
      out << "repetition,ns_per_solve\n";
      for (std::size_t i = 0; i < t.ns.size(); ++i) out << i << "," << csv_number(t.ns[i]) << "\n";
    }
  }
}

}  // namespace

bool write_report(const std::string& directory, const std::vector<scene_result>& scenes, const run_info& info, bool raw) {
  const fs::path dir(directory);
  fs::create_directories(dir);
  std::vector<std::string> plots;
  const bool plotted = write_plots(directory, scenes, plots);

  std::ostringstream md;
  json headline = json::object();
  std::vector<std::string> held, supported;
  for (const auto& [name, runs] : info.batch_targets) {
    held.push_back(name);
    if (runs) supported.push_back(name);
  }
  md << "# Precision and speed of the closed-form contact step (A.2)\n\n"
     << "Generated by `" << info.command << "` at " << info.started << " in " << format_ratio(info.seconds)
     << " s.\n\n"
     << "- **CPU:** " << info.cpu << "\n"
     << "- **Batch targets** the library holds: " << join(held) << "; this CPU supports: " << join(supported)
     << "; dispatch chose: **" << info.batch_chosen << "** (the `batch` rows).\n"
     << "- **Ratios measured side by side:** within a scene, each type's algorithms are timed in turn in every "
        "round, so a ratio of two algorithms in one type (stable / textbook, rounded / stable) divides medians of "
        "the same rounds; batch across scenes has rounds of its own (below). Figures of different scenes or types "
        "are timed apart.\n\n"
     << "Every figure below is measured in this run; `results.csv` and `results.json` hold the same figures "
        "with full precision.\n\n";
  if (std::find(plots.begin(), plots.end(), "headline") != plots.end()) {
    std::string timed;
    for (const auto& r : scenes)
      if (asks_for(r.s, plot::headline)) timed = r.s.name;
    md << "Which algorithm to use, in double: each point is an algorithm, its worst maximum ulp error over every "
          "scene against its median ns per solve on scene " << timed
       << "; lower is better on both axes. The line joins the algorithms that no other beats on both (the Pareto "
          "front); the strip on top holds those whose error is infinite or NaN in some scene.\n\n"
       << plot_link("headline", plots, "Worst error over all scenes against run time, double");
  }
  md << "## Headline figures\n\n";
  std::ostringstream head;
  write_headline(head, scenes, info, headline);
  md << head.str();
  if (!plotted) md << "_gnuplot failed or is missing: no plots._\n\n";
  write_method(md, info);
  for (const auto& r : scenes) write_scene(md, r, plots);
  {
    std::string hist;
    for (const auto& name : plots)
      if (name.rfind("hist_", 0) == 0) hist += plot_link(name, plots, "Error histograms, " + name.substr(5));
    if (!hist.empty())
      md << "## Error histograms\n\nFraction of samples per ulp-error bin: a figure per type, a panel per algorithm "
            "on shared axes, a line per scene. The data of each panel is in `plots/hist_TYPE_ALGORITHM.dat`.\n\n"
         << hist;
  }
  std::ofstream(dir / "report.md") << md.str();

  json j;
  j["generator"] = "contact-report";
  j["command"] = info.command;
  j["started"] = info.started;
  j["seconds"] = info.seconds;
  j["machine"] = {{"cpu", info.cpu},
                  {"compiler", info.compiler},
                  {"flags", info.flags},
                  {"batch_targets", json::array()},
                  {"batch_supported", json::array()},
                  {"batch_chosen", info.batch_chosen}};
  for (const auto& [name, runs] : info.batch_targets) {
    j["machine"]["batch_targets"].push_back(name);
    if (runs) j["machine"]["batch_supported"].push_back(name);
  }
  j["headline"] = headline;
  j["scenes"] = json::array();
  for (const auto& r : scenes) j["scenes"].push_back(scene_json(r));
  j["plots"] = plots;
  std::ofstream(dir / "results.json") << j.dump(1) << "\n";

  std::ofstream csv(dir / "results.csv");
  write_csv(csv, scenes);
  if (raw) write_raw(dir, scenes);
  return plotted;
}

}  // namespace report
