// Shared pieces of the test suite: the types under test (the registry of
// contact/types.hpp), the claimed error bounds and the input families (of
// contact/harness/), drawn through RapidCheck, and reference-based measurements.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "contact/types.hpp"
#include "contact/harness/claimed_bounds.hpp"
#include "contact/harness/families.hpp"

namespace contact::harness {

// An input as the tests print it: exact (C99 hex) for float and double, all
// significant digits for the wider types. In the families' namespace, where
// GoogleTest's and RapidCheck's printers look for it.
template <class T>
std::ostream& operator<<(std::ostream& out, const input<T>& x) {
  if constexpr (contact::detail::hardware_binary<T>) {
    char text[160];
    std::snprintf(text, sizeof text, "u=%a dy=%a phi=%a", double(x.u), double(x.dy), double(x.phi));
    return out << text;
  } else {
    const int digits = static_cast<int>(detail::precision_of<T>() * 0.30103) + 2;
    return out << std::setprecision(digits) << "u=" << x.u << " dy=" << x.dy << " phi=" << x.phi;
  }
}

}  // namespace contact::harness

namespace contact::testing {

// ---- the claimed bounds --------------------------------------------------

// The stable algorithm's bound for the case (and sign of u) an input falls in,
// from proofs/claimed_bounds.txt (contact/harness/claimed_bounds.hpp).
inline double stable_bound(contact_case which, bool u_positive) {
  return harness::project_bounds().for_case(which, u_positive);
}

// The largest bound over all branches: what cross-case properties use.
inline double stable_bound_any() { return harness::project_bounds().largest(); }

// Boost's cpp_bin_float has no fused fma (its fma rounds twice); the stable
// path replaces it by an exact product and sum whose final rounding is within
// an ulp rather than half: one ulp more is claimed.
template <class T>
constexpr double unfused_fma_allowance = detail::has_fused_fma<T>::value ? 0 : 1;

template <class T>
double stable_bound_for(contact_case which, const T& u) {
  return stable_bound(which, u > 0) + unfused_fma_allowance<T>;
}

// ---- inputs: the families of contact/harness/families.hpp, drawn by RapidCheck

using harness::input;

// The families' randomness source, drawn from RapidCheck inside rc::gen::exec,
// so that a failing input shrinks (integers towards the low end of their
// range). The draws ignore RapidCheck's growing size: the families choose
// their own magnitudes, uniformly from the first case on.
struct rapidcheck_source {
  static constexpr int full_size = rc::kNominalSize;
  std::uint64_t bits() { return *rc::gen::resize(full_size, rc::gen::arbitrary<std::uint64_t>()); }
  long integer(long low, long high) { return *rc::gen::resize(full_size, rc::gen::inRange<long>(low, high + 1)); }
};

// A RapidCheck generator of whatever `family(source)` draws.
template <class Family>
auto generator(Family family) {
  return rc::gen::exec([family] {
    rapidcheck_source source;
    return family(source);
  });
}

template <class T>
rc::Gen<input<T>> any_input() {
  return generator([](auto& source) { return harness::any_input<T>(source); });
}
template <class T>
rc::Gen<input<T>> whole_range_input() {
  return generator([](auto& source) { return harness::whole_range<T>(source); });
}
template <class T>
rc::Gen<input<T>> boundary_input() {
  return generator([](auto& source) { return harness::any_boundary<T>(source); });
}
template <class T>
rc::Gen<input<T>> cancellation_input() {
  return generator([](auto& source) { return harness::any_cancellation<T>(source); });
}
template <class T>
rc::Gen<input<T>> physical_input() {
  return generator([](auto& source) { return harness::physical<T>(source, harness::audio_rate()); });
}
template <class T>
rc::Gen<T> any_finite() {
  return generator([](auto& source) { return harness::any_finite<T>(source); });
}
template <class T>
rc::Gen<T> log_uniform(long low, long high) {
  return generator([low, high](auto& source) { return harness::log_uniform<T>(source, low, high); });
}

// ---- measurement -----------------------------------------------------------

template <class T>
reference::certified reference_for(const input<T>& x) {
  return reference::solve(x.u, x.dy, x.phi);
}

// Whether the exact root is a finite T (the bound is claimed only then).
template <class T>
bool root_is_finite_in(const reference::certified& exact) {
  const reference::real largest = reference::exactly((std::numeric_limits<T>::max)(), mpfr_get_prec(exact.s.get()));
  return mpfr_cmpabs(exact.s.get(), largest.get()) <= 0;
}

// x exactly, as an MPFR number with room to spare.
template <class T>
reference::real as_real(const T& x) {
  return reference::exactly(x, std::max(512, 4 * detail::precision_of<T>()));
}

// |value| in ulps of T at `at`.
template <class T>
double in_ulps(const reference::real& value, const reference::real& at) {
  reference::real ratio(64);
  mpfr_div(ratio.get(), value.get(), reference::ulp_of<T>(at).get(), MPFR_RNDN);
  return std::fabs(mpfr_get_d(ratio.get(), MPFR_RNDN));
}

// |a - b| in ulps of T at the larger of the two.
template <class T>
double ulps_apart(const T& a, const T& b) {
  const reference::real ra = as_real(a), rb = as_real(b);
  reference::real difference(std::max(1024, 8 * detail::precision_of<T>()));
  mpfr_sub(difference.get(), ra.get(), rb.get(), MPFR_RNDN);
  return in_ulps<T>(difference, mpfr_cmpabs(ra.get(), rb.get()) >= 0 ? ra : rb);
}

template <class T>
void set_up_type() {
  if constexpr (std::is_same_v<T, mpfr_float>) mpfr_float::default_precision(60);
}

// The number of RapidCheck cases for a type: fewer for the slow software types.
template <class T>
int cases_for() {
  if constexpr (std::is_same_v<T, double>) return 20000;
  if constexpr (std::is_floating_point_v<T>) return 5000;
  return 1000;
}

// rc::check with the type's case count; the seed comes from RC_PARAMS if set.
template <class T, class Property>
bool check_property(const std::string& description, Property&& property) {
  set_up_type<T>();
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = cases_for<T>();
  rc::detail::TestMetadata metadata;
  metadata.id = metadata.description = description + " [" + std::string(type_name<T>) + "]";
  const auto result = rc::detail::checkTestable(std::forward<Property>(property), metadata, params);
  std::ostringstream report;
  rc::detail::printResultMessage(result, report);
  const bool passed = result.template is<rc::detail::SuccessResult>();
  if (!passed) ADD_FAILURE() << description << " [" << type_name<T> << "]\n" << report.str();
  return passed;
}

// Homogeneity of (A.2): s(2^k u, 2^k dy, phi) = 2^k s(u, dy, phi) in the same
// case, so a solver keeps it exactly wherever s and 2^k s are normal. One
// RapidCheck case: draws an input and k, and asserts it of `solve`. With
// `normal_inputs_only`, u and dy before and after scaling must be normal or
// zero as well (a subnormal input has fewer significant bits, and a path that
// rounds each operation need not treat it as its scaled copy).
template <class T, class Solver>
void assert_scaling_by_power_of_two_scales_step(Solver solve, bool normal_inputs_only) {
  using std::fabs;
  using std::isfinite;
  using std::ldexp;
  const auto x = *any_input<T>();
  const int reach = int(std::min<long>(300, harness::highest_exponent<T>() / 4));
  const int k = *rc::gen::inRange(-reach, reach + 1);
  const T u2 = ldexp(x.u, k), dy2 = ldexp(x.dy, k);
  const T smallest_normal = (std::numeric_limits<T>::min)();
  auto normal_or_zero = [&](const T& v) { return v == 0 || (isfinite(v) && fabs(v) >= smallest_normal); };
  auto normal = [&](const T& v) { return v != 0 && normal_or_zero(v); };
  if (normal_inputs_only)
    RC_PRE(normal_or_zero(x.u) && normal_or_zero(x.dy) && normal_or_zero(u2) && normal_or_zero(dy2));
  RC_PRE(ldexp(u2, -k) == x.u && ldexp(dy2, -k) == x.dy);  // no input lost bits
  const auto base = solve(x.u, x.dy, x.phi), scaled = solve(u2, dy2, x.phi);
  RC_PRE(normal(base.s) && normal(ldexp(base.s, k)));
  RC_LOG() << x << " k=" << k << " s=" << base.s << " s(2^k)=" << scaled.s << "\n";
  RC_ASSERT(scaled.which == base.which);
  RC_ASSERT(scaled.s == ldexp(base.s, k));
}

template <class... Ts>
::testing::Types<Ts...> as_gtest_types(type_list<Ts...>);
using all_types = decltype(as_gtest_types(scalar_types{}));

struct type_names_for_gtest {
  template <class T>
  static std::string GetName(int) {
    return std::string(type_name<T>);
  }
};

}  // namespace contact::testing
