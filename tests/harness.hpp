// Shared pieces of the test suite: the types under test, the claimed error
// bounds (read from proofs/claimed_bounds.txt, the file the Gappa check holds
// to the proofs), the input generators, and reference-based measurements.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

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

namespace contact::testing {

// ---- the claimed bounds --------------------------------------------------

// Per branch of the stable path, in ulps of T at the exact root. Branch names as
// in the Gappa files proofs/gappa/stable_<branch>.g: free, impact, contact,
// release_u_positive, release_u_nonpositive.
inline const std::map<std::string, double>& claimed_bounds() {
  static const std::map<std::string, double> bounds = [] {
    std::map<std::string, double> result;
    std::ifstream in(CONTACT_CLAIMED_BOUNDS);
    if (!in) throw std::runtime_error("cannot read " CONTACT_CLAIMED_BOUNDS);
    std::string line;
    while (std::getline(in, line)) {
      line = line.substr(0, line.find('#'));
      std::istringstream fields(line);
      std::string branch, last, token;
      if (!(fields >> branch)) continue;
      while (fields >> token) last = token;
      result[branch] = std::stod(last);
    }
    if (result.empty()) throw std::runtime_error(CONTACT_CLAIMED_BOUNDS " has no bounds");
    return result;
  }();
  return bounds;
}

inline double claimed_bound(const std::string& branch) {
  const auto& bounds = claimed_bounds();
  auto it = bounds.find(branch);
  if (it == bounds.end()) throw std::runtime_error("no claimed bound for " + branch);
  return it->second;
}

// The stable algorithm's bound for the case (and sign of u) an input falls in.
inline double stable_bound(contact_case which, bool u_positive) {
  switch (which) {
    case contact_case::free: return claimed_bound("free");
    case contact_case::impact: return claimed_bound("impact");
    case contact_case::contact: return claimed_bound("contact");
    default: return claimed_bound(u_positive ? "release_u_positive" : "release_u_nonpositive");
  }
}

// The largest bound over all branches: what cross-case properties use.
inline double stable_bound_any() {
  double largest = 0;
  for (const auto& [branch, bound] : claimed_bounds()) largest = std::max(largest, bound);
  return largest;
}

// Boost's cpp_bin_float has no fused fma (its fma rounds twice); the stable
// path replaces it by an exact product and sum whose final rounding is within
// an ulp rather than half: one ulp more is claimed.
template <class T>
constexpr double unfused_fma_allowance = 0;
template <>
inline constexpr double unfused_fma_allowance<bin_float_50> = 1;
template <>
inline constexpr double unfused_fma_allowance<bin_float_100> = 1;

template <class T>
double stable_bound_for(contact_case which, const T& u) {
  return stable_bound(which, u > 0) + unfused_fma_allowance<T>;
}

// ---- inputs -------------------------------------------------------------

template <class T>
struct input {
  T u, dy, phi;
};

template <class T>
std::ostream& operator<<(std::ostream& out, const input<T>& x) {
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
    char text[160];
    std::snprintf(text, sizeof text, "u=%a dy=%a phi=%a", double(x.u), double(x.dy), double(x.phi));
    return out << text;
  } else {
    const int digits = static_cast<int>(detail::precision_of<T>() * 0.30103) + 2;
    return out << std::setprecision(digits) << "u=" << x.u << " dy=" << x.dy << " phi=" << x.phi;
  }
}

// The exponent range the generators draw from: T's whole normal and subnormal
// range for the hardware types; double's range, widened, for the software types
// (whose own range is astronomically large).
template <class T>
struct exponent_range {
  static int lowest() {
    if constexpr (std::is_floating_point_v<T> || std::is_same_v<T, float128>)
      return std::numeric_limits<T>::min_exponent - detail::precision_of<T>();
    else
      return -1200;
  }
  static int highest() {
    if constexpr (std::is_floating_point_v<T> || std::is_same_v<T, float128>)
      return std::numeric_limits<T>::max_exponent - 1;
    else
      return 1200;
  }
};

// A random significand with T's full precision, in [1, 2).
template <class T>
rc::Gen<T> significand() {
  return rc::gen::map(rc::gen::container<std::vector<std::uint32_t>>(
                          std::size_t((detail::precision_of<T>() + 31) / 32), rc::gen::arbitrary<std::uint32_t>()),
                      [](const std::vector<std::uint32_t>& words) {
                        using std::ldexp;
                        T m = 0;
                        for (auto w : words) m = ldexp(m + T(w), -32);  // exact while it fits; T rounds once at the end
                        return T(1) + m;
                      });
}

// |x| log-uniform over [2^lo, 2^hi], with T's full precision; the smallest
// exponents land in the subnormal range and lose bits as they should.
template <class T>
rc::Gen<T> log_uniform(int lo, int hi) {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(lo, hi + 1), significand<T>()), [](const auto& pair) {
    using std::ldexp;
    return T(ldexp(pair.second, pair.first));
  });
}

template <class T>
rc::Gen<T> signed_(rc::Gen<T> magnitude) {
  return rc::gen::map(rc::gen::pair(magnitude, rc::gen::arbitrary<bool>()),
                      [](const auto& p) { return p.second ? T(-p.first) : p.first; });
}

// Magnitudes over the whole range, signed zeros, and values near 0.
template <class T>
rc::Gen<T> any_finite() {
  const int lo = exponent_range<T>::lowest(), hi = exponent_range<T>::highest();
  return rc::gen::weightedOneOf<T>({{12, signed_(log_uniform<T>(lo, hi))},
                                    {2, signed_(log_uniform<T>(lo, lo + 60))},
                                    {1, rc::gen::element(T(0), T(-0.0))}});
}

// phi: stiff (up to 1e300 and beyond), physical, soft, tiny and subnormal, zero.
template <class T>
rc::Gen<T> any_phi() {
  const int lo = exponent_range<T>::lowest(), hi = exponent_range<T>::highest();
  return rc::gen::weightedOneOf<T>({{6, log_uniform<T>(lo, hi)},
                                    {3, log_uniform<T>(-10, 20)},
                                    {2, log_uniform<T>(700, std::min(hi, 1000))},
                                    {1, log_uniform<T>(lo, lo + 40)},
                                    {1, rc::gen::just(T(0))}});
}

// The audio-rate ranges of context.md: |u|, |dy| in 1e-7..1e-3, phi in 1e-3..1e6.
template <class T>
rc::Gen<input<T>> physical_input() {
  auto displacement = signed_(log_uniform<T>(-24, -10));
  return rc::gen::construct<input<T>>(displacement, displacement, log_uniform<T>(-10, 20));
}

// The software types' own least values (2^-2^31) are beyond what a rational
// reference can hold; for them the harness stays above 2^-1300 (or at zero).
template <class T>
bool in_reference_range(const T& x) {
  using std::fabs;
  using std::ldexp;
  if constexpr (std::is_floating_point_v<T> || std::is_same_v<T, float128>) return true;
  else return x != 0 && fabs(x) >= ldexp(T(1), -1300);
}

// u placed within a few ulps of a case boundary: u = -dy, or u = dy (phi - 1) rounded.
template <class T>
rc::Gen<input<T>> boundary_input() {
  return rc::gen::map(rc::gen::tuple(any_finite<T>(), any_phi<T>(), rc::gen::inRange(-4, 5)),
                      [](const auto& t) {
                        const auto& [dy, phi, steps] = t;
                        T u = dy <= 0 ? T(-dy) : T(dy * (phi - 1));
                        using std::isfinite;
                        if (!isfinite(u)) u = 0;
                        for (int k = 0; k < steps; ++k) u = detail::next_up(u);
                        for (int k = 0; k > steps; --k) u = detail::next_down(u);
                        if (!isfinite(u)) u = dy <= 0 ? T(-dy) : T(0);
                        // the software types' own least values (2^-2^31) are beyond what a
                        // rational reference can hold; their inputs stay within 2^-1300
                        if (!in_reference_range(u)) u = 0;
                        return input<T>{u, dy, phi};
                      });
}

// The cancellation regions: (A.31) near s = 0 (u within a few ulps of 2 phi dy)
// and (A.32) with u >> sqrt(phi) dy (the printed root subtracts nearly equal terms).
template <class T>
rc::Gen<input<T>> cancellation_input() {
  auto near_zero_step = rc::gen::map(
      rc::gen::tuple(log_uniform<T>(-60, 60), log_uniform<T>(-30, 30), rc::gen::inRange(-6, 7)), [](const auto& t) {
        const auto& [dy, phi, steps] = t;
        T u = 2 * phi * dy;
        for (int k = 0; k < steps; ++k) u = detail::next_up(u);
        for (int k = 0; k > steps; --k) u = detail::next_down(u);
        return input<T>{u, dy, phi};
      });
  auto small_release = rc::gen::map(
      rc::gen::tuple(log_uniform<T>(-40, 0), rc::gen::inRange(10, 40), log_uniform<T>(0, 1)), [](const auto& t) {
        const auto& [u, gap, factor] = t;
        using std::ldexp;
        const T dy = ldexp(u, -gap);            // dy << u
        const T phi = (u / dy) * 4 * factor;    // phi > u / dy + 1, so (A.32) applies, with phi dy^2 << u^2
        return input<T>{u, dy, phi};
      });
  return rc::gen::oneOf(near_zero_step, small_release);
}

// Every family together, for properties that must hold everywhere.
template <class T>
rc::Gen<input<T>> any_input() {
  return rc::gen::weightedOneOf<input<T>>({{6, rc::gen::construct<input<T>>(any_finite<T>(), any_finite<T>(), any_phi<T>())},
                                           {3, boundary_input<T>()},
                                           {2, cancellation_input<T>()},
                                           {2, physical_input<T>()}});
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

using all_types = ::testing::Types<float, double, long double, float128, bin_float_50, bin_float_100, mpfr_float>;

struct type_names_for_gtest {
  template <class T>
  static std::string GetName(int) {
    return std::string(type_name<T>);
  }
};

}  // namespace contact::testing
