#include "candidates.hpp"

#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "contact/harness/candidate.hpp"
#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "error_map.hpp"
#include "methods.hpp"

namespace report {

namespace {

using double_solver = double (*)(double, double, double, int*);

struct entry {
  std::string name;
  contact::harness::candidate_spec spec;
  std::unique_ptr<contact::harness::candidate> runner;  // isolated: survives a crash or a hang
  double_solver in_process = nullptr;                   // loaded once the runner has shown it safe
};

// Whether the isolated runner answers every input: only then may the candidate
// run in this process, where a crash or a hang would end the report.
bool answers_all(entry& e, const std::vector<contact::harness::input<double>>& inputs) {
  const auto answers = e.runner->solve(inputs);
  return std::all_of(answers.begin(), answers.end(), [](const auto& a) { return a.answered(); });
}

double_solver load(const entry& e) {
  std::string path = e.spec.path;
  if (path.find('/') == std::string::npos) path = "./" + path;  // a file, not a search
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open for the report's lifetime
  return library ? reinterpret_cast<double_solver>(::dlsym(library, e.spec.symbol.c_str())) : nullptr;
}

double cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// CPU ns per solve of one repetition: passes over the lanes for at least
// min_time seconds, as the built-in algorithms' benchmarks loop over theirs.
double ns_per_solve(double_solver solve, const std::vector<double>& u, const std::vector<double>& dy,
                    const std::vector<double>& phi, double min_time) {
  long passes = 0;
  const double start = cpu_seconds();
  double elapsed = 0;
  do {
    for (std::size_t i = 0; i < u.size(); ++i) {
      int which = 0;
      double s = solve(u[i], dy[i], phi[i], &which);
      benchmark::DoNotOptimize(s);
      benchmark::DoNotOptimize(which);
    }
    ++passes;
    elapsed = cpu_seconds() - start;
  } while (elapsed < min_time);
  return elapsed * 1e9 / (double(passes) * double(u.size()));
}

std::vector<entry>& entries() {
  static std::vector<entry> list;
  return list;
}

std::vector<contact::harness::input<double>> triples(const std::vector<input>& inputs) {
  std::vector<contact::harness::input<double>> out;
  for (const auto& x : inputs) out.push_back({x.u, x.dy, x.phi});
  return out;
}

}  // namespace

void add_candidate(const std::string& name_equals_spec) {
  const auto equals = name_equals_spec.find('=');
  if (equals == std::string::npos || equals == 0)
    throw contact::harness::candidate_error("'" + name_equals_spec + "': expected NAME=SPEC");
  const std::string name = name_equals_spec.substr(0, equals);
  if (method_named(name)) throw contact::harness::candidate_error("'" + name + "' is the name of a built-in algorithm");
  for (const auto& e : entries())
    if (e.name == name) throw contact::harness::candidate_error("candidate '" + name + "' is given twice");
  const std::string spec = name_equals_spec.substr(equals + 1);
  entries().push_back({name, contact::harness::parse_candidate_spec(spec, false), contact::harness::open_candidate(spec, false)});
}

bool has_candidates() { return !entries().empty(); }

void measure_candidates(const std::vector<input>& inputs, const reference_list& references, std::size_t families,
                        std::vector<accuracy_result>& out) {
  for (auto& e : entries()) {
    accuracy_result a;
    a.type = "double";
    a.algorithm = e.name;
    a.samples = static_cast<long>(inputs.size());
    a.family_max.assign(families, -1.0);
    a.reference_bits = static_cast<int>(mpfr_get_prec(references.front().s.get()));
    const auto answers = e.runner->solve(triples(inputs));
    std::vector<double> errors(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      // a crash or a hang is an answer of NaN: infinitely wrong
      const double s = answers[i].answered() ? answers[i].s : std::nan("");
      const double error = contact::reference::ulp_error<double>(s, references[i]);
      errors[i] = error;
      a.histogram[static_cast<std::size_t>(histogram_bin(error))]++;
      if (std::isnan(s)) ++a.nan;
      if (std::isinf(s)) {
        ++a.inf;
        if (error == 0) ++a.inf_overflow;
      }
      const auto which = static_cast<contact::contact_case>(answers[i].which);
      if (which != references[i].which) ++a.wrong_case;
      if (!contact::lies_on_its_side(which, s, inputs[i].dy)) ++a.complementarity;
      double& worst = a.family_max[static_cast<std::size_t>(inputs[i].family)];
      worst = std::isnan(error) ? INFINITY : std::max(worst, error);
    }
    a.ulps = summarize(errors);
    out.push_back(std::move(a));
  }
}

// A library is timed in this process, on the timing lanes that its isolated
// run has answered without a crash or a hang. A command is not timed: its
// time would be its protocol's.
void time_candidates(const run& r, const std::vector<input>& lanes, std::vector<timing_result>& out) {
  const auto batch = triples(lanes);
  std::vector<double> u, dy, phi;
  for (const auto& x : lanes) u.push_back(x.u), dy.push_back(x.dy), phi.push_back(x.phi);
  for (auto& e : entries()) {
    if (e.spec.form != contact::harness::candidate_spec::kind::library || !answers_all(e, batch)) continue;
    if (!e.in_process && !(e.in_process = load(e))) continue;
    timing_result t;
    t.type = "double";
    t.algorithm = e.name;
    t.inputs = static_cast<long>(lanes.size());
    ns_per_solve(e.in_process, u, dy, phi, r.min_time / 2);  // warm-up
    for (int round = 0; round < r.repetitions; ++round) t.ns.push_back(ns_per_solve(e.in_process, u, dy, phi, r.min_time));
    std::vector<double> sorted = t.ns;
    std::sort(sorted.begin(), sorted.end());
    t.median = sorted[sorted.size() / 2];
    t.min = sorted.front();
    t.max = sorted.back();
    out.push_back(std::move(t));
  }
}

// The maps of contact-check --map, of each candidate and of the stable path,
// on the physical scene's domain (or the first scene's), appended to report.md.
bool write_candidate_maps(const std::string& out_dir, const std::vector<scene>& scenes) {
  if (entries().empty()) return true;
  const scene* on = nullptr;
  for (const auto& s : scenes)
    if (!s.families.empty() && (!on || s.name == "physical")) on = &s;
  if (!on) return true;
  const auto d = ::check::domain<double>::of_scene(on->file);
  const ::check::map_grid grid = ::check::grid_of(d);
  const std::string plots = (std::filesystem::path(out_dir) / "plots").string();
  bool drawn = true;
  auto draw = [&](const ::check::batch_solver& solve, const std::string& name) {
    const auto written = ::check::write_map_files(::check::map_errors<double>(solve, grid), grid, 4, plots, "map_" + name,
                                                name + " on " + d.name());
    if (!written.ok) std::fprintf(stderr, "contact-report: %s\n", written.message.c_str());
    drawn = drawn && written.ok;
  };
  draw([](const std::vector<contact::harness::input<double>>& inputs) {
         std::vector<double> out;
         for (const auto& x : inputs) out.push_back(contact::solve(x.u, x.dy, x.phi).s);
         return out;
       },
       "stable");
  std::ofstream md((std::filesystem::path(out_dir) / "report.md").string(), std::ios::app);
  md << "\n## Error maps of the candidates\n\nOn scene " << on->name
     << ": the largest error in ulps over log10|u| by log10|dy|, a panel per sign of u and dy and per phi, the case "
        "boundaries drawn (`contact-check --map` draws the same). Green is within 4 ulps.\n\n";
  for (auto& e : entries()) {
    draw(::check::solver_of(*e.runner), e.name);
    md << "| " << e.name << " | stable |\n|---|---|\n| ![" << e.name << "](plots/map_" << e.name
       << ".png) | ![stable](plots/map_stable.png) |\n\n";
  }
  return drawn && static_cast<bool>(md);
}

}  // namespace report
