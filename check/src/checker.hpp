// The engine of contact-check: runs properties on a candidate, fuzzes it
// against the reference, shrinks what fails and records it per property.
#pragma once

#include <algorithm>
#include <chrono>
#include <deque>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contact/harness/candidate.hpp"
#include "contact/reference.hpp"
#include "domain.hpp"
#include "properties.hpp"
#include "shrink.hpp"

namespace check {

struct options {
  double max_ulp = 4;
  double seconds = 10;   // of the fuzzing campaign
  long trials = 1000;    // per property of the suite
  long sweep_trials = 24;  // per magnitude of the sweep (0: no sweep)
  std::uint64_t seed = 1;
};

// One shrunk failure, as printed.
struct failure {
  std::string reason;
  std::vector<std::string> lines;  // input, answer, certified root of each probe
};

struct record {
  std::string name, claim;
  long tried = 0, failed = 0;
  // the first failure in each exact case (0 for invalid input), shrunk within
  // that case: one misprint in one case's formula does not hide another's
  std::map<int, failure> first;
  double seconds = 0;
  std::vector<std::string> where;  // where it breaks, per swept variable (sweep)
};

// The verdict of one family in one exact case: the single inputs judged there.
struct tally {
  long tried = 0;
  long failed = 0;  // inputs on which the property judging them failed
  double max_ulp = 0, max_relative = 0;
};

template <class T>
std::string hex(const T& x) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", double(x));
  return text;
}

template <class T>
std::string decimal(const T& x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", double(x));
  return text;
}

template <class T>
class checker {
 public:
  checker(contact::harness::candidate& c, const options& o, const domain<T>& d)
      : candidate_(c), options_(o), domain_(d), all_(properties<T>(o.max_ulp, d)) {
    returns_record();
  }

  // The property suite: `trials` trials of each property.
  void run_suite() {
    seeded_source source(options_.seed);
    for (const property<T>& p : all_) {
      const auto start = std::chrono::steady_clock::now();
      record& r = record_of(p);
      constexpr long batch = 256;
      for (long done = 0; done < options_.trials; done += batch) {
        std::vector<trial<T>> trials;
        for (long i = done; i < std::min(options_.trials, done + batch); ++i) trials.push_back(p.draw(source));
        judge(p, trials);
      }
      r.seconds += seconds_since(start);
    }
  }

  // Differential fuzzing against the reference until `seconds` have passed:
  // fresh draws from every family, and mutations of the inputs with the
  // largest errors so far (the campaign's feedback).
  void run_campaign() {
    seeded_source source(options_.seed ^ 0x9e3779b97f4a7c15ULL);
    const auto start = std::chrono::steady_clock::now();
    const auto singles = single_input_properties();
    std::vector<std::pair<double, tagged<T>>> pool;  // (ulp error, input), the worst first
    while (seconds_since(start) < options_.seconds) {
      std::vector<trial<T>> trials;
      for (int i = 0; i < 512; ++i) {
        const tagged<T> x = pool.empty() || coin(source) ? fresh(source) : mutate(source, pool);
        trials.push_back({x.x, 0, x.family});
      }
      std::vector<probe_result<T>> results;
      if (!solve(trials, results)) continue;
      campaign_inputs_ += static_cast<long>(trials.size());
      returns_record().tried += static_cast<long>(trials.size());
      for (std::size_t i = 0; i < trials.size(); ++i) {
        if (results[i].exact) {
          const double error = contact::reference::ulp_error<T>(results[i].s, *results[i].exact);
          pool.emplace_back(std::isnan(error) ? std::numeric_limits<double>::infinity() : error,
                            tagged<T>{results[i].x, trials[i].family});
        }
        std::vector<probe_result<T>> one;
        one.push_back(std::move(results[i]));
        bool failed = false;
        for (const property<T>* p : singles) {
          record& rec = record_of(*p);
          ++rec.tried;
          if (const auto why = p->verdict(trials[i], one)) {
            ++rec.failed;
            failed = true;
            keep(rec, *p, trials[i], one, *why);
          }
        }
        count(trials[i].family, one[0], failed);
      }
      std::sort(pool.begin(), pool.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      if (pool.size() > 64) pool.resize(64);
    }
    campaign_seconds_ = seconds_since(start);
  }

  // For each failing property, where it breaks: the property's trials at
  // magnitudes of |u|, |dy| and phi a fixed step of decades apart over the
  // domain, one variable at a time (the others as the domain draws them), and
  // |u| and |dy| together: (A.2) is homogeneous in them, so their common
  // scale is the size of the input.
  void run_sweep() {
    const long trials_per_point = options_.sweep_trials;
    if (trials_per_point <= 0) return;
    const auto start = std::chrono::steady_clock::now();
    seeded_source source(options_.seed ^ 0x5bd1e995ULL);
    for (const property<T>& p : all_) {
      record& r = record_of(p);
      if (!r.failed || p.name == "invalid_input" || p.name == "phi_zero") continue;
      const bool boundary = p.name.rfind("continuity", 0) == 0;  // u is the boundary's, not drawn
      for (int variable = boundary ? 1 : 0; variable < (boundary ? 3 : 4); ++variable)
        r.where.push_back(sweep_variable(p, variable, trials_per_point, source));
    }
    sweep_seconds_ = seconds_since(start);
  }

  const std::deque<record>& records() const { return records_; }
  const std::map<std::pair<int, int>, tally>& table() const { return table_; }
  double sweep_seconds() const { return sweep_seconds_; }
  long campaign_inputs() const { return campaign_inputs_; }
  double campaign_seconds() const { return campaign_seconds_; }

 private:
  static double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  record& record_of(const std::string& name, const std::string& claim) {
    for (auto& r : records_)
      if (r.name == name) return r;
    records_.push_back({name, claim});
    return records_.back();
  }
  record& record_of(const property<T>& p) { return record_of(p.name, p.claim); }
  record& returns_record() { return record_of(returns_name, returns_claim); }

  std::vector<const property<T>*> single_input_properties() {
    std::vector<const property<T>*> out;
    for (const auto& p : all_)
      if (p.name == "forward_error" || p.name == "residual" || p.name == "case" || p.name == "complementarity" ||
          p.name == "invalid_input")
        out.push_back(&p);
    return out;
  }

  // Solves the probes of every trial (one call for all); false when the
  // candidate faulted, which is recorded (shrunk the first time) under `returns`.
  bool solve(const std::vector<trial<T>>& trials, std::vector<probe_result<T>>& results) {
    std::vector<input<T>> inputs;
    for (const auto& t : trials) inputs.push_back(t.x);
    const auto outcomes = candidate_.solve(as_double(inputs));
    results.clear();
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (outcomes[i].faulted()) {
        record& r = returns_record();
        ++r.failed;
        if (r.first.empty()) r.first[0] = shrink_fault(inputs[i], outcomes[i]);
        return false;
      }
      results.push_back(answer_of(inputs[i], outcomes[i]));
    }
    return true;
  }

  static std::vector<input<double>> as_double(const std::vector<input<T>>& inputs) {
    std::vector<input<double>> out;
    for (const auto& x : inputs) out.push_back({double(x.u), double(x.dy), double(x.phi)});
    return out;
  }

  static probe_result<T> answer_of(const input<T>& x, const outcome& o) {
    probe_result<T> r{x, T(o.s), o.which, std::nullopt};
    if (valid(x)) r.exact.emplace(contact::reference::solve<T>(x.u, x.dy, x.phi));
    return r;
  }

  // The probes of the trials as one batch for the candidate: trial k's are
  // inputs[first[k]] up to inputs[first[k + 1]].
  struct probe_batch {
    std::vector<input<T>> inputs;
    std::vector<std::size_t> first;
  };
  static probe_batch probes_of(const property<T>& p, const std::vector<trial<T>>& trials) {
    probe_batch batch;
    for (const auto& t : trials) {
      batch.first.push_back(batch.inputs.size());
      for (const auto& x : p.probes(t)) batch.inputs.push_back(x);
    }
    batch.first.push_back(batch.inputs.size());
    return batch;
  }

  // Judges a batch of trials of p; the first failure is shrunk and kept.
  void judge(const property<T>& p, const std::vector<trial<T>>& trials) {
    record& r = record_of(p);
    const auto [inputs, first] = probes_of(p, trials);
    const auto outcomes = candidate_.solve(as_double(inputs));
    for (std::size_t t = 0; t < trials.size(); ++t) {
      std::vector<probe_result<T>> results;
      bool complete = true;
      for (std::size_t i = first[t]; i < first[t + 1]; ++i) {
        if (outcomes[i].faulted()) {
          record& returns = returns_record();
          ++returns.failed;
          if (returns.first.empty()) returns.first[0] = shrink_fault(inputs[i], outcomes[i]);
        }
        if (!outcomes[i].answered()) complete = false;
        else results.push_back(answer_of(inputs[i], outcomes[i]));
      }
      if (!complete) break;  // the rest was not run
      ++r.tried;
      ++returns_record().tried;
      const auto why = p.verdict(trials[t], results);
      if (results.size() == 1) count(trials[t].family, results[0], why.has_value());
      if (why) {
        ++r.failed;
        keep(r, p, trials[t], results, *why);
      }
    }
  }

  // The trials a shrink may move to: inside a scene's domain, those it holds
  // (a boundary property's u is the boundary's, not the trial's).
  std::vector<trial<T>> within_domain(std::vector<trial<T>> trials, bool boundary) const {
    if (domain_.is_whole_range()) return trials;
    std::erase_if(trials, [&](const trial<T>& t) {
      const input<T> x{boundary ? domain_.draw_free_u() : t.x.u, t.x.dy, t.x.phi};
      return !domain_.contains(x);
    });
    return trials;
  }

  // Seconds one more shrink may take: a few each, and at most half a minute in
  // all, so that a slow candidate (a command started per batch) still finishes.
  double shrink_seconds() const { return std::clamp(30.0 - shrinking_, 0.0, 3.0); }

  static int case_of(const std::vector<probe_result<T>>& results) {
    return results[0].exact ? static_cast<int>(results[0].exact->which) : 0;
  }

  // Keeps the failure, shrunk, if it is the first in its case.
  void keep(record& r, const property<T>& p, const trial<T>& t, const std::vector<probe_result<T>>& results,
            const std::string& why) {
    const int which = case_of(results);
    if (!r.first.count(which)) r.first[which] = shrink(p, t, why, which);
  }

  // Replaces the failing trial by its simplest failing neighbour in the same case while there is one.
  failure shrink(const property<T>& p, trial<T> t, std::string why, int which) {
    const auto start = std::chrono::steady_clock::now();
    for (int round = 0; round < 200 && seconds_since(start) < shrink_seconds(); ++round) {
      const auto neighbours = within_domain(simpler_trials(t), p.name.rfind("continuity", 0) == 0);
      if (neighbours.empty()) break;
      const auto [inputs, first] = probes_of(p, neighbours);
      const auto outcomes = candidate_.solve(as_double(inputs));
      bool simpler = false;
      for (std::size_t k = 0; k < neighbours.size() && !simpler; ++k) {
        std::vector<probe_result<T>> results;
        bool complete = true;
        for (std::size_t i = first[k]; i < first[k + 1]; ++i) {
          if (!outcomes[i].answered()) complete = false;
          else results.push_back(answer_of(inputs[i], outcomes[i]));
        }
        if (!complete) break;  // a fault: the shrink stays with what it has
        if (case_of(results) != which) continue;
        if (auto reason = p.verdict(neighbours[k], results)) {
          t = neighbours[k];
          why = *reason;
          simpler = true;
        }
      }
      if (!simpler) break;
    }
    shrinking_ += seconds_since(start);
    return describe(p.probes(t), why);
  }

  // The simplest neighbour that still makes the candidate crash or hang.
  failure shrink_fault(input<T> x, outcome fault) {
    const auto start = std::chrono::steady_clock::now();
    for (int round = 0; round < 100 && seconds_since(start) < shrink_seconds(); ++round) {
      bool simpler = false;
      for (const auto& n : within_domain(simpler_trials(trial<T>{x, 0}), false)) {
        const auto o = candidate_.solve(as_double({n.x}));
        if (o[0].faulted()) {
          x = n.x;
          fault = o[0];
          simpler = true;
          break;
        }
        // a neighbour that answers is cheap; one that hangs costs a timeout, so few are tried
        if (seconds_since(start) > shrink_seconds()) break;
      }
      if (!simpler) break;
    }
    shrinking_ += seconds_since(start);
    failure f;
    f.reason = fault.detail.empty() ? "no answer" : fault.detail;
    f.lines.push_back(input_line(x));
    return f;
  }

  static std::string input_line(const input<T>& x) {
    return "input      u = " + hex(x.u) + "  dy = " + hex(x.dy) + "  phi = " + hex(x.phi) + "   (" + decimal(x.u) +
           ", " + decimal(x.dy) + ", " + decimal(x.phi) + ")";
  }

  failure describe(const std::vector<input<T>>& probes, const std::string& why) {
    failure f;
    f.reason = why;
    const auto outcomes = candidate_.solve(as_double(probes));
    for (std::size_t i = 0; i < probes.size(); ++i) {
      f.lines.push_back(input_line(probes[i]));
      if (!outcomes[i].answered()) {
        f.lines.push_back("candidate  no answer: " + outcomes[i].detail);
        continue;
      }
      const auto r = answer_of(probes[i], outcomes[i]);
      f.lines.push_back("candidate  s  = " + hex(r.s) + " (" + decimal(r.s) + "), case " + std::to_string(r.which) +
                        " " + std::string(contact::name_of(static_cast<contact::contact_case>(r.which))));
      if (r.exact)
        f.lines.push_back("certified  s* = " + root_text<T>(*r.exact) + ", case " +
                          std::to_string(static_cast<int>(r.exact->which)) + " " +
                          std::string(contact::name_of(r.exact->which)) + " " +
                          std::string(contact::equation_of(r.exact->which)));
      else
        f.lines.push_back("certified  invalid input: s* = NaN, case 0");
    }
    return f;
  }

  // A draw of the domain; in the whole range, also the special values.
  tagged<T> fresh(seeded_source& source) {
    using namespace contact::harness;
    using s = distribution::shape;
    if (!domain_.is_whole_range()) return domain_.draw(source);
    switch (source.integer(0, 9)) {
      case 0: return {impact_grazing<T>(source, {s::log2, -60, 60, 1}, {s::log2, -30, 60, 1}, {s::log2, -50, 0, 1}), 1};
      case 1: return {{any_finite<T>(source), any_finite<T>(source), T(0)}, 0};
      case 2:
        for (const auto& p : all_)
          if (p.name == "invalid_input") return {p.draw(source).x, -1};
        [[fallthrough]];
      default: return domain_.draw(source);
    }
  }

  // A neighbour of one of the worst inputs so far; inside a scene's domain,
  // one the domain holds (else a fresh draw).
  tagged<T> mutate(seeded_source& source, const std::vector<std::pair<double, tagged<T>>>& pool) {
    const tagged<T>& parent = pool[static_cast<std::size_t>(source.integer(0, long(pool.size()) - 1))].second;
    if (domain_.is_whole_range()) return {mutate_anywhere(source, parent.x), parent.family};
    const input<T> x = mutate_within(source, parent.x);
    if (domain_.contains(x)) return {x, parent.family};
    return domain_.draw(source);
  }

  input<T> mutate_within(seeded_source& source, input<T> x) {
    using std::ldexp;
    T* fields[] = {&x.u, &x.dy, &x.phi};
    T& f = *fields[source.integer(0, 2)];
    switch (source.integer(0, 4)) {
      case 0: f = contact::detail::ulp_steps(f, source.integer(-8, 8)); break;
      case 1: f = -f; break;
      case 2: {
        const int k = static_cast<int>(source.integer(-3, 3));
        x.u = ldexp(x.u, k);
        x.dy = ldexp(x.dy, k);
        break;
      }
      case 3: f = with_bits(f, static_cast<int>(source.integer(1, 8))); break;
      default: x.u = contact::detail::ulp_steps(T(x.dy > 0 ? x.dy * (x.phi - 1) : -x.dy), source.integer(-3, 3)); break;
    }
    return x;
  }

  input<T> mutate_anywhere(seeded_source& source, input<T> x) {
    using std::ldexp;
    T* fields[] = {&x.u, &x.dy, &x.phi};
    T& f = *fields[source.integer(0, 2)];
    switch (source.integer(0, 6)) {
      case 0: f = contact::detail::ulp_steps(f, source.integer(-8, 8)); break;
      case 1: f = -f; break;
      case 2: {  // both lengths by a power of two: a homogeneous copy
        const int k = static_cast<int>(source.integer(-40, 40));
        x.u = ldexp(x.u, k);
        x.dy = ldexp(x.dy, k);
        break;
      }
      case 3: f = with_bits(f, static_cast<int>(source.integer(1, 8))); break;
      case 4: x.u = contact::detail::ulp_steps(T(x.dy > 0 ? x.dy * (x.phi - 1) : -x.dy), source.integer(-3, 3)); break;
      case 5: f = contact::harness::any_finite<T>(source); break;
      default: x.phi = contact::harness::any_phi<T>(source); break;
    }
    if (x.phi < 0 && source.integer(0, 7) != 0) x.phi = -x.phi;  // mostly valid
    return x;
  }

  // Adds one input, judged by a single-input property, to its family's and case's tally.
  void count(int family, const probe_result<T>& r, bool failed) {
    if (family < 0 || !r.exact) return;
    tally& c = table_[{family, static_cast<int>(r.exact->which)}];
    ++c.tried;
    if (failed) ++c.failed;
    double error = contact::reference::accepted_ulp_error<T>(r.s, *r.exact, r.x.dy);
    if (std::isnan(error)) error = std::numeric_limits<double>::infinity();
    c.max_ulp = std::max(c.max_ulp, error);
    c.max_relative = std::max(c.max_relative, error == 0 ? 0.0 : relative_error(r));
  }

  static double relative_error(const probe_result<T>& r) {
    const double root = contact::reference::rounded_to_double(r.exact->s), s = double(r.s);
    if (std::isnan(s)) return std::numeric_limits<double>::infinity();
    if (root == 0) return s == 0 ? 0 : std::numeric_limits<double>::infinity();
    return std::fabs((s - root) / root);
  }

  // The exponents of ten the sweep visits over [least, most]: half-decades, or
  // wider steps where the span is wide, at most about 64 points.
  static std::vector<double> sweep_points(const span& v) {
    std::vector<double> out;
    if (!(v.least > 0) || !(v.most > v.least)) return out;
    const double low = std::log10(v.least), high = std::log10(v.most);
    double step = 0.5;
    for (double wider : {1.0, 2.0, 5.0, 10.0, 20.0})
      if ((high - low) / step > 64) step = wider;
    for (double e = std::ceil(low / step) * step; e <= high + 1e-9; e += step) out.push_back(e);
    if (out.size() < 2) out = {low, high};
    return out;
  }

  static std::string power_text(double exponent) {
    char text[32];
    std::snprintf(text, sizeof text, "10^%g", std::round(exponent * 100) / 100);
    return text;
  }

  // One line: where property p holds and fails as one variable (0 |u|, 1 |dy|,
  // 2 phi, 3 |u| and |dy| at once, the larger of them set) sweeps the domain.
  std::string sweep_variable(const property<T>& p, int variable, long trials_per_point, seeded_source& source) {
    static const char* names[] = {"|u|", "|dy|", "phi", "|u| and |dy| together (the larger)"};
    span both = domain_.u();
    both.least = std::max(domain_.u().least, domain_.dy().least);
    both.most = std::max(domain_.u().most, domain_.dy().most);
    const span& v = variable == 0 ? domain_.u() : variable == 1 ? domain_.dy() : variable == 2 ? domain_.phi() : both;
    const auto points = sweep_points(v);
    std::string head = p.name + " over " + names[variable] + ": ";
    if (points.empty()) return head + "one magnitude only in the domain, not swept";
    const double step = points.size() > 1 ? points[1] - points[0] : 0;
    std::vector<trial<T>> trials;
    for (double e : points)
      for (long i = 0; i < trials_per_point; ++i) {
        trial<T> t = p.draw(source);
        const double jitter = step * 0.1 * (unit(source) - 0.5);
        const double magnitude = std::clamp(std::pow(10.0, e + jitter), v.least, v.most);
        if (variable == 3) {
          using std::fabs;
          const double larger = std::max(fabs(double(t.x.u)), fabs(double(t.x.dy)));
          if (larger > 0) {
            t.x.u = T(double(t.x.u) / larger * magnitude);
            t.x.dy = T(double(t.x.dy) / larger * magnitude);
          }
          trials.push_back(t);
          continue;
        }
        T& f = variable == 0 ? t.x.u : variable == 1 ? t.x.dy : t.x.phi;
        const bool negative = variable < 2 && (f < 0 || (f == 0 && v.negative && (!v.positive || coin(source))));
        f = T(negative ? -magnitude : magnitude);
        trials.push_back(t);
      }
    const auto [inputs, first] = probes_of(p, trials);
    const auto outcomes = solve_past_faults(as_double(inputs));
    std::vector<long> fails(points.size(), 0);
    for (std::size_t t = 0; t < trials.size(); ++t) {
      std::vector<probe_result<T>> results;
      bool complete = true;
      for (std::size_t i = first[t]; i < first[t + 1]; ++i) {
        if (!outcomes[i].answered()) complete = false;
        else results.push_back(answer_of(inputs[i], outcomes[i]));
      }
      // no answer counts as a failure where it happened
      if (!complete || p.verdict(trials[t], results)) ++fails[t / static_cast<std::size_t>(trials_per_point)];
    }
    return head + describe_sweep(points, fails, trials_per_point);
  }

  // Every input's outcome: after a crash or a hang the rest are asked again,
  // up to a few faults (each may cost a timeout); after those they stay not_run.
  std::vector<outcome> solve_past_faults(const std::vector<input<double>>& inputs) {
    std::vector<outcome> out;
    for (int faults = 0; out.size() < inputs.size() && faults < 3; ++faults) {
      const auto o = candidate_.solve({inputs.begin() + long(out.size()), inputs.end()});
      std::size_t i = 0;
      while (i < o.size() && (i == 0 || o[i].kind != outcome::status::not_run)) out.push_back(o[i++]);
    }
    out.resize(inputs.size());
    return out;
  }

  static std::string describe_sweep(const std::vector<double>& points, const std::vector<long>& fails, long per_point) {
    const std::size_t n = points.size();
    std::vector<bool> bad(n);
    std::size_t failing = 0;
    for (std::size_t i = 0; i < n; ++i) failing += (bad[i] = fails[i] > 0);
    const std::string range = power_text(points.front()) + " to " + power_text(points.back());
    const std::string counts = " (" + std::to_string(failing) + " of " + std::to_string(n) + " magnitudes fail, " +
                              std::to_string(per_point) + " trials each)";
    if (failing == 0) return "no failure found from " + range + counts;
    if (failing == n) return "fails at every magnitude from " + range + counts;
    std::size_t first_bad = 0, last_bad = n - 1;
    while (!bad[first_bad]) ++first_bad;
    while (!bad[last_bad]) --last_bad;
    const bool suffix = last_bad == n - 1 && std::all_of(bad.begin() + long(first_bad), bad.end(), [](bool b) { return b; });
    const bool prefix = first_bad == 0 && std::all_of(bad.begin(), bad.begin() + long(last_bad) + 1, [](bool b) { return b; });
    if (suffix)
      return "holds up to " + power_text(points[first_bad - 1]) + ", fails from " + power_text(points[first_bad]) + counts;
    if (prefix)
      return "fails up to " + power_text(points[last_bad]) + ", holds from " + power_text(points[last_bad + 1]) + counts;
    std::string at;
    for (std::size_t i = 0; i < n; ++i)
      if (bad[i] && (i == 0 || !bad[i - 1])) {
        std::size_t j = i;
        while (j + 1 < n && bad[j + 1]) ++j;
        at += std::string(at.empty() ? "" : ", ") + power_text(points[i]) +
              (j > i ? " to " + power_text(points[j]) : std::string());
      }
    if (first_bad == 0) return "fails at " + at + "; holds at the other magnitudes from " + range + counts;
    return "holds up to " + power_text(points[first_bad - 1]) + ", fails from " + power_text(points[first_bad]) +
           ", not at every magnitude above: fails at " + at + counts;
  }

  contact::harness::candidate& candidate_;
  options options_;
  const domain<T>& domain_;
  std::deque<record> records_;  // a deque: references to records stay valid as records are added
  std::vector<property<T>> all_;
  std::map<std::pair<int, int>, tally> table_;  // (family, exact case)
  double sweep_seconds_ = 0;
  long campaign_inputs_ = 0;
  double shrinking_ = 0;  // seconds spent shrinking so far
  double campaign_seconds_ = 0;
};

inline std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The per-family-and-case table, as printed and as the JUnit file carries it.
inline std::string table_text(const std::map<std::pair<int, int>, tally>& table, const std::vector<std::string>& families) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "  %-22s %-12s %10s %10s %12s %14s\n", "family", "case", "tried", "failures",
                "max ulps", "max rel. error");
  out += line;
  for (const auto& [key, c] : table) {
    const std::string which =
        std::to_string(key.second) + " " + std::string(contact::name_of(static_cast<contact::contact_case>(key.second)));
    std::snprintf(line, sizeof line, "  %-22s %-12s %10ld %10ld %12.4g %14.3g\n",
                  families[static_cast<std::size_t>(key.first)].c_str(), which.c_str(), c.tried, c.failed, c.max_ulp,
                  c.max_relative);
    out += line;
  }
  return out;
}

}  // namespace check
