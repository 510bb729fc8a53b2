// The measurements that depend on the scalar type, as templates over T.
// typed_instance.cpp instantiates them once per registered type (so that the
// heavy types compile in parallel) and hands out their type_ops table.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "contact/batch.hpp"
#include "contact/harness/oscillator.hpp"
#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "contact/types.hpp"
#include "iterative_peers.hpp"
#include "peers.hpp"
#include "results.hpp"
#include "targets.hpp"
#include "type_ops.hpp"

namespace report::typed {

// The type at `index` of the registry.
template <std::size_t index, class... Ts>
auto registered_at(contact::type_list<Ts...>) {
  return std::tuple_element_t<index, std::tuple<Ts...>>{};
}
template <std::size_t index>
using registered = decltype(registered_at<index>(contact::scalar_types{}));

// The library's algorithms through contact::solve; the batch API and the
// peers are the report's own.
template <class T>
contact::solution<T> solve_one(method m, const T& u, const T& dy, const T& phi) {
  if (const auto algorithm = library_algorithm(m)) return contact::solve(u, dy, phi, *algorithm);
  switch (m) {
    case method::batch: {
      T s;
      int which;
      contact::solve_batch(&u, &dy, &phi, &s, &which, 1);
      return {s, static_cast<contact::contact_case>(which)};
    }
    case method::rounded_batch:
      if constexpr (runs_in<T>(method::rounded_batch)) {
        T s;
        int which;
        contact::solve_rounded_batch(&u, &dy, &phi, &s, &which, 1);
        return {s, static_cast<contact::contact_case>(which)};
      }
      break;
    case method::boost_quadratic: return peers::solve_boost(u, dy, phi);
    case method::eigen_companion:
      if constexpr (runs_in<T>(method::eigen_companion)) return peers::solve_eigen(u, dy, phi);
      break;  // unsupported() keeps it out of the scenes
    case method::boost_newton: return peers::solve_boost_newton(u, dy, phi).answer;
    case method::boost_halley: return peers::solve_boost_halley(u, dy, phi).answer;
    case method::boost_toms748: return peers::solve_boost_toms748(u, dy, phi).answer;
    case method::practitioner_newton: return peers::solve_practitioner_newton(u, dy, phi).answer;
    default: break;
  }
  return {std::numeric_limits<T>::quiet_NaN(), contact::contact_case::invalid};
}

// The same answer as solve_one, with the iteration count of an iterative
// method (-1 for the others). The timings call solve_one, which does not
// keep the count.
template <class T>
peers::iterated<T> solve_counted(method m, const T& u, const T& dy, const T& phi) {
  switch (m) {
    case method::newton: {
      const auto result = contact::newton_iterate(u, dy, phi);  // what contact::solve's newton returns
      return {result.answer, result.iterations};
    }
    case method::boost_newton: return peers::solve_boost_newton(u, dy, phi);
    case method::boost_halley: return peers::solve_boost_halley(u, dy, phi);
    case method::boost_toms748: return peers::solve_boost_toms748(u, dy, phi);
    case method::practitioner_newton: return peers::solve_practitioner_newton(u, dy, phi);
    default: return {solve_one(m, u, dy, phi), -1};
  }
}

template <class T>
double to_double(const T& x) {
  return static_cast<double>(x);
}

// Types that hold more than double: their results are also scored after rounding to double.
template <class T>
inline constexpr bool wider_than_double =
    !std::is_floating_point_v<T> || std::numeric_limits<T>::digits > std::numeric_limits<double>::digits;

// ---- accuracy ----------------------------------------------------------------------

// x as T holds it: rounded, and saturated at T's largest finite value, since
// an infinite input is invalid (and the reference takes finite input only).
template <class T>
double held_in(double x) {
  using std::isinf;
  const T rounded(x);
  if (!isinf(rounded)) return to_double(rounded);
  const T largest = (std::numeric_limits<T>::max)();
  return to_double(x > 0 ? largest : T(-largest));
}

template <class T>
std::vector<input> as_held(const std::vector<input>& inputs) {
  std::vector<input> held = inputs;
  for (auto& in : held) {
    in.u = held_in<T>(in.u);
    in.dy = held_in<T>(in.dy);
    in.phi = held_in<T>(in.phi);
  }
  return held;
}

// The inputs as T (exactly: measure.cpp has rounded them to the run's narrowest type).
template <class T>
struct columns {
  std::vector<T> u, dy, phi;
  explicit columns(const std::vector<input>& inputs) {
    for (const auto& in : inputs) {
      u.emplace_back(in.u);
      dy.emplace_back(in.dy);
      phi.emplace_back(in.phi);
    }
  }
  std::size_t size() const { return u.size(); }
};

template <class T>
struct solved {
  std::vector<T> s;
  std::vector<int> which;
  std::vector<int> iterations;  // -1 for a method that does not iterate
  long slow_path = 0;           // rounded: how many took the exact decision
};

// Every input solved by `m`; batch and rounded_batch in one call, as their users call them.
template <class T>
solved<T> solve_all(method m, const columns<T>& in) {
  const std::size_t n = in.size();
  solved<T> out{std::vector<T>(n), std::vector<int>(n), std::vector<int>(n, -1)};
  if (m == method::batch) {
    contact::solve_batch(in.u.data(), in.dy.data(), in.phi.data(), out.s.data(), out.which.data(),
                         static_cast<std::ptrdiff_t>(n));
    return out;
  }
  if constexpr (runs_in<T>(method::rounded_batch)) {
    if (m == method::rounded_batch) {
      contact::solve_rounded_batch(in.u.data(), in.dy.data(), in.phi.data(), out.s.data(), out.which.data(),
                                   static_cast<std::ptrdiff_t>(n));
      return out;
    }
  }
  if constexpr (contact::rounded_available<T>) {
    if (m == method::rounded) {  // the same answers as solve_one gives, with the path each took
      for (std::size_t i = 0; i < n; ++i) {
        const auto traced = contact::detail::solve_rounded_traced(in.u[i], in.dy[i], in.phi[i]);
        out.s[i] = traced.result.s;
        out.which[i] = static_cast<int>(traced.result.which);
        out.slow_path += traced.exact_decision;
      }
      return out;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto result = solve_counted(m, in.u[i], in.dy[i], in.phi[i]);
    out.s[i] = result.answer.s;
    out.which[i] = static_cast<int>(result.answer.which);
    out.iterations[i] = result.iterations;
  }
  return out;
}

// One result's ulp error, added into the counts of `a`; `worst_as_double`
// gathers the error of the result rounded to double (wider types only).
template <class T>
double score(accuracy_result& a, method m, const T& s, int which, const T& dy, int family,
             const contact::reference::certified& exact, double& worst_as_double) {
  using std::isinf;
  using std::isnan;
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const double error = contact::reference::ulp_error<T>(s, exact);
  a.histogram[static_cast<std::size_t>(histogram_bin(error))]++;
  if (isnan(s)) ++a.nan;
  if (isinf(s)) {
    ++a.inf;
    if (error == 0) ++a.inf_overflow;
  }
  const auto c = static_cast<contact::contact_case>(which);
  if (c != exact.which) ++a.wrong_case;
  const bool on_its_side = contact::lies_on_its_side(c, s, dy) || (weakly_complementary(m) && s == dy);
  if (!on_its_side) ++a.complementarity;
  double& family_worst = a.family_max[static_cast<std::size_t>(family)];
  family_worst = std::isnan(error) ? infinity : std::max(family_worst, error);
  if constexpr (wider_than_double<T>) {
    const double as_double = contact::reference::ulp_error<double>(to_double(s), exact);
    worst_as_double = std::isnan(as_double) ? infinity : std::max(worst_as_double, as_double);
  }
  return error;
}

template <class T>
void accuracy(const run& r, const std::vector<input>& inputs, const reference_list& references, std::size_t families,
              bool keep_raw, progress& bar, std::vector<accuracy_result>& out) {
  const columns<T> in(inputs);
  const std::size_t n = in.size();
  for (method m : r.methods) {
    accuracy_result a;
    a.type = std::string(contact::type_name<T>);
    a.algorithm = name_of(m);
    a.samples = static_cast<long>(n);
    a.family_max.assign(families, -1.0);
    a.reference_bits = static_cast<int>(mpfr_get_prec(references.front().s.get()));
    solved<T> results = solve_all(m, in);
    std::vector<double> errors(n);
    double worst_as_double = 0;
    for (std::size_t i = 0; i < n; ++i) {
      errors[i] = score(a, m, results.s[i], results.which[i], in.dy[i], inputs[i].family, references[i], worst_as_double);
      if ((i & 1023) == 0) bar.update(static_cast<long>(i));
    }
    if constexpr (wider_than_double<T>) a.max_ulp_as_double = worst_as_double;
    a.ulps = summarize(errors);
    if (iterative(m)) count_iterations(results.iterations, a);  // the others keep -1
    if (m == method::rounded) a.slow_path_share = double(results.slow_path) / double(std::max<std::size_t>(n, 1));
    if (keep_raw) {
      a.errors = std::move(errors);
      a.which = std::move(results.which);
      if (iterative(m)) a.iterations = std::move(results.iterations);
      a.inputs = inputs;
      for (const T& s : results.s) a.s_text.push_back(contact::round_trip_text(s));
    }
    out.push_back(std::move(a));
    bar.finish();
  }
}

// ---- timing ------------------------------------------------------------------------

// A row of a scene's timings: a method, or one target's batch kernel alone.
struct timed_row {
  std::string name;  // name_of(m), or target_row_name(name_of(m), *target)
  method m;
  const contact::batch_target* target = nullptr;
};

// The rows a run times in T: each method of the run and, after batch and
// rounded_batch in float and double, each target's kernel that this CPU runs
// (targets.hpp).
template <class T>
std::vector<timed_row> timed_rows(const run& r) {
  std::vector<timed_row> rows;
  for (method m : r.methods) {
    rows.push_back({name_of(m), m});
    if constexpr (has_batch_kernels<T>)
      if (m == method::batch || m == method::rounded_batch)
        for (const contact::batch_target* t : supported_batch_targets())
          rows.push_back({target_row_name(name_of(m), *t), m, t});
  }
  return rows;
}

template <class T>
std::vector<std::string> register_timings(const run& r, const std::vector<input>& lanes, const std::string& prefix) {
  struct arrays {  // aligned to the vector width, as Eigen arrays are
    std::vector<T, Eigen::aligned_allocator<T>> u, dy, phi, s;
    std::vector<int, Eigen::aligned_allocator<int>> which;
  };
  auto data = std::make_shared<arrays>();
  const std::size_t n = lanes.size();
  for (const auto& in : lanes) {
    data->u.push_back(T(in.u));
    data->dy.push_back(T(in.dy));
    data->phi.push_back(T(in.phi));
  }
  data->s.resize(n);
  data->which.resize(n);
  // the batch API: the whole array in one call of `solve`
  const auto whole_array = [data, n](const std::string& name, auto solve) {
    return benchmark::RegisterBenchmark(name.c_str(), [data, n, solve](benchmark::State& state) {
      for (auto _ : state) {
        solve(data->u.data(), data->dy.data(), data->phi.data(), data->s.data(), data->which.data(),
              static_cast<std::ptrdiff_t>(n));
        benchmark::ClobberMemory();
      }
    });
  };
  const std::vector<timed_row> rows = timed_rows<T>(r);
  // Repetition-major: round k times every row once, so that a change of the
  // machine's load during the run hits all rows alike. "#k" ends the name.
  for (int round = 0; round < r.repetitions; ++round)
    for (const timed_row& row : rows) {
      const std::string name = prefix + std::string(contact::type_name<T>) + "|" + row.name + "#" + std::to_string(round);
      benchmark::internal::Benchmark* b = nullptr;
      if (row.target) {
        if constexpr (has_batch_kernels<T>)
          b = whole_array(name, [t = row.target, rounded = row.m == method::rounded_batch](
                                    const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t count) {
            solve_on(*t, u, dy, phi, s, which, count, rounded);
          });
      } else if (row.m == method::batch) {
        b = whole_array(name, [](const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t count) {
          contact::solve_batch(u, dy, phi, s, which, count);
        });
      } else if (row.m == method::rounded_batch) {
        if constexpr (runs_in<T>(method::rounded_batch))
          b = whole_array(name, [](const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t count) {
            contact::solve_rounded_batch(u, dy, phi, s, which, count);
          });
      } else {
        b = benchmark::RegisterBenchmark(name.c_str(), [data, n, m = row.m](benchmark::State& state) {
          for (auto _ : state) {
            for (std::size_t i = 0; i < n; ++i) {
              auto result = solve_one(m, data->u[i], data->dy[i], data->phi[i]);
              benchmark::DoNotOptimize(result);
            }
          }
        });
      }
      b->Repetitions(1)->MinTime(r.min_time)->MinWarmUpTime(r.min_time / 2)->Unit(benchmark::kNanosecond);
    }
  std::vector<std::string> names;
  for (const timed_row& row : rows) names.push_back(row.name);
  return names;
}

// ---- energy ------------------------------------------------------------------------

// |H - H[0]| / H[0] for H of (S.2) evaluated exactly (MPFR) from the parameters
// and the state as T holds them: what it shows is the simulation's drift, not
// the rounding of H.
template <class T>
class exact_energy_drift {
 public:
  exact_energy_drift(const contact::harness::oscillator<T>& scheme, const contact::harness::oscillator_state<T>& start)
      : bits_(std::max<mpfr_prec_t>(256, 4 * contact::detail::precision_of<T>())),
        mass_(contact::reference::exactly(scheme.mass, bits_)),
        spring_(contact::reference::exactly(scheme.spring, bits_)),
        height_(contact::reference::exactly(scheme.barrier_height, bits_)),
        stiffness_(contact::reference::exactly(scheme.barrier_stiffness, bits_)),
        start_(energy(start)) {}

  double operator()(const contact::harness::oscillator_state<T>& x) {
    contact::reference::real difference(bits_);
    mpfr_sub(difference.get(), energy(x).get(), start_.get(), MPFR_RNDN);
    mpfr_div(difference.get(), difference.get(), start_.get(), MPFR_RNDN);
    return std::fabs(mpfr_get_d(difference.get(), MPFR_RNDN));
  }

 private:
  // (S.2) H = (p^2 / m + K y^2 + k_b floor(h_b - y)^2) / 2
  contact::reference::real energy(const contact::harness::oscillator_state<T>& x) {
    using contact::reference::exactly;
    const contact::reference::real y = exactly(x.y, bits_), p = exactly(x.p, bits_);
    contact::reference::real total(bits_), term(bits_), gap(bits_);
    mpfr_sqr(total.get(), p.get(), MPFR_RNDN);
    mpfr_div(total.get(), total.get(), mass_.get(), MPFR_RNDN);
    mpfr_sqr(term.get(), y.get(), MPFR_RNDN);
    mpfr_mul(term.get(), term.get(), spring_.get(), MPFR_RNDN);
    mpfr_add(total.get(), total.get(), term.get(), MPFR_RNDN);
    mpfr_sub(gap.get(), height_.get(), y.get(), MPFR_RNDN);
    if (mpfr_sgn(gap.get()) > 0) {
      mpfr_sqr(term.get(), gap.get(), MPFR_RNDN);
      mpfr_mul(term.get(), term.get(), stiffness_.get(), MPFR_RNDN);
      mpfr_add(total.get(), total.get(), term.get(), MPFR_RNDN);
    }
    mpfr_div_2ui(total.get(), total.get(), 1, MPFR_RNDN);
    return total;
  }

  mpfr_prec_t bits_;
  contact::reference::real mass_, spring_, height_, stiffness_, start_;
};

// The plotted series: the largest exact drift within each of `buckets` equal
// runs of steps (step n, from 1, falls into bucket (n - 1) buckets / steps).
class drift_envelope {
 public:
  drift_envelope(energy_result& e, long buckets) : e_(e), buckets_(buckets) {
    e_.envelope.assign(static_cast<std::size_t>(buckets), 0.0);
  }

  void record(long n, double exact, double in_type) {
    e_.max_exact = std::max(e_.max_exact, exact);
    e_.max_in_type = std::max(e_.max_in_type, in_type);
    e_.final_exact = exact;
    double& bucket = e_.envelope[bucket_of(n)];
    bucket = std::max(bucket, exact);
  }

  // The state stopped being finite at step n: every figure from there on is infinite.
  void blew_up(long n) {
    e_.finite = false;
    e_.max_exact = e_.max_in_type = e_.final_exact = std::numeric_limits<double>::infinity();
    for (std::size_t k = bucket_of(n); k < e_.envelope.size(); ++k) e_.envelope[k] = e_.max_exact;
  }

  // Each bucket is plotted at the time of its last step.
  void set_times(double sample_rate) {
    e_.time.resize(static_cast<std::size_t>(buckets_));
    for (long k = 0; k < buckets_; ++k)
      e_.time[static_cast<std::size_t>(k)] = (double(k + 1) * double(e_.steps) / double(buckets_)) / sample_rate;
  }

 private:
  std::size_t bucket_of(long n) const { return static_cast<std::size_t>((n - 1) * buckets_ / e_.steps); }
  energy_result& e_;
  long buckets_;
};

// The oscillator of docs/equations.md, section 1, in T, stepped with method m.
template <class T>
energy_result simulate(const oscillator& o, method m) {
  using std::fabs;
  using std::isfinite;
  energy_result e;
  e.type = std::string(contact::type_name<T>);
  e.algorithm = name_of(m);
  e.steps = static_cast<long>(std::llround(o.duration * o.sample_rate));
  const T mass(o.mass);
  const contact::harness::oscillator<T> scheme(mass, T(o.spring), T(o.barrier_height), T(o.barrier_stiffness),
                                               T(T(1) / T(o.sample_rate)));
  contact::harness::oscillator_state<T> x{T(o.initial_displacement), T(mass * T(o.initial_velocity))};
  exact_energy_drift<T> drift(scheme, x);
  const T start_in_type = scheme.energy(x);
  drift_envelope envelope(e, std::min(o.plot_points, e.steps));
  for (long n = 1; n <= e.steps; ++n) {
    const T dy = scheme.compression(x.y);
    const auto step = solve_one(m, scheme.u(x.y, x.p), dy, scheme.phi);
    if (dy > 0 || step.s < dy) ++e.contact_steps;  // the barrier pushes during this step
    x = scheme.next(x, step.s);
    if (!isfinite(x.y) || !isfinite(x.p)) {
      envelope.blew_up(n);
      break;
    }
    envelope.record(n, drift(x), to_double(T(fabs(T(scheme.energy(x) - start_in_type)) / start_in_type)));
  }
  envelope.set_times(o.sample_rate);
  return e;
}

// ---- the table ---------------------------------------------------------------------

template <class T>
int digits() {
  return contact::detail::precision_of<T>();
}

template <class T>
type_ops make_ops() {
  return {std::string(contact::type_name<T>), &digits<T>, &as_held<T>, &accuracy<T>, &register_timings<T>,
          &simulate<T>};
}

}  // namespace report::typed
