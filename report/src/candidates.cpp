#include "candidates.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "contact/harness/candidate.hpp"
#include "contact/reference.hpp"
#include "methods.hpp"

namespace report {

namespace {

struct entry {
  std::string name;
  std::unique_ptr<contact::harness::candidate> runner;
};

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
  entries().push_back({name, contact::harness::open_candidate(name_equals_spec.substr(equals + 1), false)});
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

void time_candidates(const run& r, const std::vector<input>& lanes, std::vector<timing_result>& out) {
  const auto batch = triples(lanes);
  for (auto& e : entries()) {
    timing_result t;
    t.type = "double";
    t.algorithm = e.name;
    t.inputs = static_cast<long>(lanes.size());
    for (int round = 0; round < r.repetitions; ++round) {
      const auto start = std::chrono::steady_clock::now();
      e.runner->solve(batch);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      t.ns.push_back(seconds * 1e9 / double(lanes.size()));
    }
    std::vector<double> sorted = t.ns;
    std::sort(sorted.begin(), sorted.end());
    t.median = sorted[sorted.size() / 2];
    t.min = sorted.front();
    t.max = sorted.back();
    out.push_back(std::move(t));
  }
}

}  // namespace report
