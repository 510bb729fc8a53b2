// The measurements that depend on the number type, as templates; each
// type_*.cpp instantiates them for one type (so that the heavy ones compile in
// parallel) and hands out a type_ops table of function pointers.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "contact/batch.hpp"
#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "contact/types.hpp"
#include "peers.hpp"
#include "results.hpp"

namespace report {

using reference_list = std::vector<contact::reference::certified>;

struct type_ops {
  std::string name;
  int (*digits)();  // significand bits (MPFR: at the current default precision)
  // Solves run.samples of `inputs` with each of the run's methods; `references`
  // are the certified roots of the same inputs.
  void (*accuracy)(const run& r, const std::vector<input>& inputs, const reference_list& references,
                   std::size_t families, bool keep_raw, progress& bar, std::vector<accuracy_result>& out);
  // Registers one Google Benchmark per method, named "<prefix><type>|<method>".
  void (*register_timings)(const run& r, const std::vector<input>& lanes, const std::string& prefix);
  energy_result (*simulate)(const oscillator& o, method m);
};

const type_ops& ops_for(const std::string& type);  // in measure.cpp

namespace typed {

template <class T>
contact::solution<T> solve_one(method m, const T& u, const T& dy, const T& phi) {
  switch (m) {
    case method::textbook: return contact::solve_textbook(u, dy, phi);
    case method::newton: return contact::solve_newton(u, dy, phi);
    case method::boost_quadratic: return peers::solve_boost(u, dy, phi);
    case method::eigen_companion:
      if constexpr (std::is_floating_point_v<T>) return peers::solve_eigen(u, dy, phi);
      else return {std::numeric_limits<T>::quiet_NaN(), contact::contact_case::invalid};  // refused by the scene parser
    case method::batch: {
      T s;
      int which;
      contact::solve_batch(&u, &dy, &phi, &s, &which, 1);
      return {s, static_cast<contact::contact_case>(which)};
    }
    default: return contact::solve_stable(u, dy, phi);
  }
}

template <class T>
double to_double(const T& x) {
  return static_cast<double>(x);
}

template <class T>
void accuracy(const run& r, const std::vector<input>& inputs, const reference_list& references, std::size_t families,
              bool keep_raw, progress& bar, std::vector<accuracy_result>& out) {
  const std::size_t n = inputs.size();
  std::vector<T> u(n), dy(n), phi(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = T(inputs[i].u), dy[i] = T(inputs[i].dy), phi[i] = T(inputs[i].phi);
  constexpr bool wider_than_double = std::numeric_limits<T>::digits > 53 || !std::numeric_limits<T>::is_specialized ||
                                     !std::is_floating_point_v<T>;
  for (method m : r.methods) {
    accuracy_result a;
    a.type = std::string(contact::type_name<T>);
    a.algorithm = name_of(m);
    a.samples = static_cast<long>(n);
    a.family_max.assign(families, -1.0);
    a.reference_bits = static_cast<int>(mpfr_get_prec(references.front().s.get()));
    std::vector<T> s(n);
    std::vector<int> which(n);
    if (m == method::batch) {
      contact::solve_batch(u.data(), dy.data(), phi.data(), s.data(), which.data(), static_cast<std::ptrdiff_t>(n));
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        const auto result = solve_one(m, u[i], dy[i], phi[i]);
        s[i] = result.s;
        which[i] = static_cast<int>(result.which);
      }
    }
    std::vector<double> errors(n);
    double worst_as_double = 0;
    for (std::size_t i = 0; i < n; ++i) {
      using std::isinf;
      using std::isnan;
      const double e = contact::reference::ulp_error<T>(s[i], references[i]);
      errors[i] = e;
      a.histogram[static_cast<std::size_t>(histogram_bin(e))]++;
      if (isnan(s[i])) ++a.nan;
      if (isinf(s[i])) {
        ++a.inf;
        if (e == 0) ++a.inf_overflow;
      }
      const auto c = static_cast<contact::contact_case>(which[i]);
      if (c != references[i].which) ++a.wrong_case;
      if (!contact::lies_on_its_side(c, s[i], dy[i])) ++a.complementarity;
      double& family_worst = a.family_max[static_cast<std::size_t>(inputs[i].family)];
      family_worst = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::max(family_worst, e);
      if constexpr (wider_than_double) {
        const double as_double = contact::reference::ulp_error<double>(to_double(s[i]), references[i]);
        worst_as_double = std::isnan(as_double) ? std::numeric_limits<double>::infinity() : std::max(worst_as_double, as_double);
      }
      if ((i & 1023) == 0) bar.update(static_cast<long>(i));
    }
    if constexpr (wider_than_double) a.max_ulp_as_double = worst_as_double;
    a.ulps = summarize(errors);
    if (keep_raw) {
      a.errors = std::move(errors);
      a.which = std::move(which);
      a.inputs = inputs;
      for (std::size_t i = 0; i < n; ++i) a.s_text.push_back(contact::round_trip_text(s[i]));
    }
    out.push_back(std::move(a));
    bar.finish();
  }
}

template <class T>
void register_timings(const run& r, const std::vector<input>& lanes, const std::string& prefix) {
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
  // Repetition-major: round k times every method once, so that a change of the
  // machine's load during the run hits all methods alike. "#k" ends the name.
  for (int round = 0; round < r.repetitions; ++round)
    for (method m : r.methods) {
      const std::string name =
          prefix + std::string(contact::type_name<T>) + "|" + name_of(m) + "#" + std::to_string(round);
      benchmark::internal::Benchmark* b;
      if (m == method::batch) {
        b = benchmark::RegisterBenchmark(name.c_str(), [data, n](benchmark::State& state) {
          for (auto _ : state) {
            contact::solve_batch(data->u.data(), data->dy.data(), data->phi.data(), data->s.data(), data->which.data(),
                                 static_cast<std::ptrdiff_t>(n));
            benchmark::ClobberMemory();
          }
        });
      } else {
        b = benchmark::RegisterBenchmark(name.c_str(), [data, n, m](benchmark::State& state) {
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
}

// The energy-conserving oscillator of context.md in T, stepped with method m.
template <class T>
energy_result simulate(const oscillator& o, method m) {
  using contact::reference::exactly;
  using contact::reference::real;
  energy_result e;
  e.type = std::string(contact::type_name<T>);
  e.algorithm = name_of(m);
  e.steps = static_cast<long>(std::llround(o.duration * o.sample_rate));
  const T mass(o.mass), spring(o.spring), height(o.barrier_height), stiffness(o.barrier_stiffness);
  const T dt = T(1) / T(o.sample_rate);
  const T a = T(2) * mass / (dt * dt) + spring / T(2);
  const T phi = stiffness / (T(2) * a);
  T y(o.initial_displacement), p = mass * T(o.initial_velocity);

  // H exactly, in MPFR, from the parameters and the state as T holds them.
  const mpfr_prec_t bits = std::max<mpfr_prec_t>(256, 4 * contact::detail::precision_of<T>());
  const real m_x = exactly(mass, bits), k_x = exactly(spring, bits), h_x = exactly(height, bits),
             kb_x = exactly(stiffness, bits);
  real term(bits), total(bits), gap(bits);
  auto exact_energy = [&](const T& y_now, const T& p_now) {
    const real y_x = exactly(y_now, bits), p_x = exactly(p_now, bits);
    mpfr_sqr(total.get(), p_x.get(), MPFR_RNDN);
    mpfr_div(total.get(), total.get(), m_x.get(), MPFR_RNDN);
    mpfr_sqr(term.get(), y_x.get(), MPFR_RNDN);
    mpfr_mul(term.get(), term.get(), k_x.get(), MPFR_RNDN);
    mpfr_add(total.get(), total.get(), term.get(), MPFR_RNDN);
    mpfr_sub(gap.get(), h_x.get(), y_x.get(), MPFR_RNDN);
    if (mpfr_sgn(gap.get()) > 0) {
      mpfr_sqr(term.get(), gap.get(), MPFR_RNDN);
      mpfr_mul(term.get(), term.get(), kb_x.get(), MPFR_RNDN);
      mpfr_add(total.get(), total.get(), term.get(), MPFR_RNDN);
    }
    real energy(bits);
    mpfr_div_2ui(energy.get(), total.get(), 1, MPFR_RNDN);
    return energy;
  };
  auto energy_in_type = [&](const T& y_now, const T& p_now) {
    const T g = height - y_now;
    const T barrier = g > 0 ? T(stiffness * g * g / T(2)) : T(0);
    return T(p_now * p_now / (T(2) * mass) + spring * y_now * y_now / T(2) + barrier);
  };
  const real h0 = exact_energy(y, p);
  const T h0_in_type = energy_in_type(y, p);
  real difference(bits);
  const long buckets = std::min(o.plot_points, e.steps);
  e.time.assign(static_cast<std::size_t>(buckets), 0.0);
  e.envelope.assign(static_cast<std::size_t>(buckets), 0.0);
  for (long n = 1; n <= e.steps; ++n) {
    const T u = (spring * y - T(2) * p / dt) / a;
    const T dy = height - y;
    const auto step = solve_one(m, u, dy, phi);
    if (dy > 0 || step.s < dy) ++e.contact_steps;
    const T y_next = y + step.s;
    p = T(2) * mass * step.s / dt - p;
    y = y_next;
    using std::isfinite;
    if (!isfinite(y) || !isfinite(p)) {
      e.finite = false;
      e.max_exact = e.max_in_type = e.final_exact = std::numeric_limits<double>::infinity();
      for (long k = (n - 1) * buckets / e.steps; k < buckets; ++k) e.envelope[static_cast<std::size_t>(k)] = e.max_exact;
      break;
    }
    mpfr_sub(difference.get(), exact_energy(y, p).get(), h0.get(), MPFR_RNDN);
    mpfr_div(difference.get(), difference.get(), h0.get(), MPFR_RNDN);
    const double relative = std::fabs(mpfr_get_d(difference.get(), MPFR_RNDN));
    using std::fabs;
    const double relative_in_type = to_double(T(fabs(T(energy_in_type(y, p) - h0_in_type)) / h0_in_type));
    e.max_exact = std::max(e.max_exact, relative);
    e.max_in_type = std::max(e.max_in_type, relative_in_type);
    e.final_exact = relative;
    const auto k = static_cast<std::size_t>((n - 1) * buckets / e.steps);
    e.envelope[k] = std::max(e.envelope[k], relative);
  }
  for (long k = 0; k < buckets; ++k)
    e.time[static_cast<std::size_t>(k)] = (double(k + 1) * double(e.steps) / double(buckets)) / o.sample_rate;
  return e;
}

template <class T>
int digits() {
  return contact::detail::precision_of<T>();
}

template <class T>
type_ops make_ops() {
  return {std::string(contact::type_name<T>), &digits<T>, &accuracy<T>, &register_timings<T>, &simulate<T>};
}

}  // namespace typed
}  // namespace report
