// Exact facts about the root s* of (A.2) for inputs of a mini_float format,
// without computing s*: R increases, so every question about where s* lies is
// a question about the sign of R at a dyadic point, and there s R(s) is a
// polynomial in integers.
//
//   - the exact case: the sign of R(dy) (docs/equations.md, section 2);
//   - the binade of s*, from the signs of R at +-2^j;
//   - whether s is within B ulps of s*: R(s - B ulp(s*)) <= 0 <= R(s + B ulp(s*));
//   - whether s is s* rounded to nearest, ties to even, as the format rounds:
//     s* lies between the midpoints to the neighbours of s.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "contact/cases.hpp"
#include "contact/detail/float_tools.hpp"

namespace contact::testing::exact {

namespace mp = boost::multiprecision;

// Integers that throw std::overflow_error rather than wrap. A triple is
// checked in 128 bits, which suffice for the formats here, and again in 256
// should they not (a root very many binades from the inputs).
using narrow = mp::number<mp::cpp_int_backend<128, 128, mp::signed_magnitude, mp::checked, void>, mp::et_off>;
using wide = mp::number<mp::cpp_int_backend<256, 256, mp::signed_magnitude, mp::checked, void>, mp::et_off>;

template <class Integer>
struct dyadic {
  Integer m = 0;  // the value m 2^e
  int e = 0;

  friend int sign(const dyadic& a) { return a.m.sign(); }
  friend dyadic operator-(const dyadic& a) { return {-a.m, a.e}; }
  friend dyadic operator*(const dyadic& a, const dyadic& b) { return {a.m * b.m, a.e + b.e}; }
  friend dyadic operator+(const dyadic& a, const dyadic& b) {
    if (a.m == 0) return b;
    if (b.m == 0) return a;
    if (a.e >= b.e) return {shifted(a.m, a.e - b.e) + b.m, b.e};
    return {a.m + shifted(b.m, b.e - a.e), a.e};
  }
  friend dyadic operator-(const dyadic& a, const dyadic& b) { return a + (-b); }
  // (a + b) / 2, exactly
  friend dyadic midpoint(const dyadic& a, const dyadic& b) {
    const dyadic sum = a + b;
    return {sum.m, sum.e - 1};
  }

 private:
  // cpp_int shifts magnitudes only
  static Integer shifted(const Integer& m, int k) { return m.sign() < 0 ? Integer(-(Integer(-m) << k)) : Integer(m << k); }
};

template <class Integer>
dyadic<Integer> power_of_two(int sign, int k) {
  return {Integer(sign), k};
}

template <class Integer>
dyadic<Integer> positive_part(const dyadic<Integer>& a) {
  return sign(a) > 0 ? a : dyadic<Integer>{};
}

// A finite double (every value of a mini_float is one), exactly.
template <class Integer>
dyadic<Integer> exactly(double x) {
  if (x == 0) return {};
  int e = 0;
  const auto m = static_cast<std::int64_t>(std::ldexp(std::frexp(x, &e), 53));
  const int zeros = std::countr_zero(static_cast<std::uint64_t>(m < 0 ? -m : m));
  return {Integer(m >> zeros), e - 53 + zeros};
}

template <class Integer>
struct input {
  dyadic<Integer> u, dy, phi, compression, compression_squared;  // max(dy, 0), its square

  input(double u_, double dy_, double phi_) : u(exactly<Integer>(u_)), dy(exactly<Integer>(dy_)), phi(exactly<Integer>(phi_)) {
    compression = positive_part(dy);
    compression_squared = compression * compression;
  }

  // The sign of R(s). R(0) = u - 2 phi max(dy, 0) (the limit); elsewhere
  // s R(s) is the polynomial s^2 + u s + phi (max(dy - s, 0)^2 - max(dy, 0)^2).
  int residual_sign(const dyadic<Integer>& s) const {
    if (sign(s) == 0) return sign(u - power_of_two<Integer>(1, 1) * phi * compression);
    const dyadic<Integer> gap = positive_part(dy - s);
    return sign(s * s + u * s + phi * (gap * gap - compression_squared)) * sign(s);
  }

  // The sign of s*: R(0) > 0 puts the root below 0.
  int root_sign() const { return -residual_sign({}); }

  contact_case exact_case() const {
    if (sign(dy) <= 0) return sign(u + dy) <= 0 ? contact_case::free : contact_case::impact;
    return sign(u + dy - phi * dy) >= 0 ? contact_case::contact : contact_case::release;
  }
};

// Where the values of a mini_float format T lie, exactly.
template <class T>
struct format_of {
  static constexpr int precision = T::precision, least_exponent = T::least_exponent;
  static constexpr bool subnormals = T::subnormals;

  // ulp(x) for x in binade j (2^j <= |x| < 2^(j + 1)) is 2^(j - p + 1), as
  // proofs/claimed_bounds.txt defines it. Below the least normal value it is
  // the spacing there, as 2^-1074 is double's below 2^-1022: that of the
  // subnormals, or without them 2^least_exponent, the format holding only 0
  // and +-2^least_exponent there.
  static int ulp_exponent(int binade) {
    if (binade >= least_exponent) return binade - precision + 1;
    return subnormals ? least_exponent - precision + 1 : least_exponent;
  }

  // The binade j of s* != 0, least_exponent - 1 below the least normal value,
  // searched from guess: |s*| < 2^j exactly when sign(s*) R(sign(s*) 2^j) > 0.
  template <class Integer>
  static int binade_of_root(const input<Integer>& x, int guess) {
    const int root_sign = x.root_sign();
    auto below = [&](int j) { return root_sign * x.residual_sign(power_of_two<Integer>(root_sign, j)) > 0; };
    int j = std::max(guess, int(least_exponent));
    while (j > least_exponent && below(j)) --j;
    if (j == least_exponent && below(j)) return least_exponent - 1;
    while (!below(j + 1)) ++j;
    return j;
  }

  // The exponent of ulp(s*); s, the solver's answer, only speeds the search.
  template <class Integer>
  static int ulp_exponent_of_root(const input<Integer>& x, const T& s) {
    if (x.root_sign() == 0) return ulp_exponent(least_exponent - 1);
    int guess = least_exponent;
    if (s != 0 && (s > 0) == (x.root_sign() > 0)) {
      frexp(s, &guess);
      --guess;
    }
    return ulp_exponent(binade_of_root(x, guess));
  }

  // |s - s*| <= units 2^-fraction_bits ulp(s*), for a finite s.
  template <class Integer>
  static bool within(const input<Integer>& x, const T& s, long units, int fraction_bits) {
    const dyadic<Integer> reach{Integer(units), ulp_exponent_of_root(x, s) - fraction_bits};
    const auto exact_s = exactly<Integer>(double(s));
    return x.residual_sign(exact_s - reach) <= 0 && x.residual_sign(exact_s + reach) >= 0;
  }

  // The largest finite value plus half its ulp: the rounding limit, from
  // which on s* rounds to infinity (the largest value is odd, so the tie does).
  template <class Integer>
  static dyadic<Integer> rounding_limit() {
    const T largest = (std::numeric_limits<T>::max)();
    int e = 0;
    frexp(largest, &e);
    return exactly<Integer>(double(largest)) + power_of_two<Integer>(1, e - precision - 1);
  }

  // Whether s is s* rounded as the format rounds its own operations (as
  // mini_float_test checks them): to nearest in Precision bits with an
  // unbounded exponent, ties to even, then flushed to zero below the least
  // normal value and to infinity from the rounding limit on. s* lies between
  // the midpoints to the neighbours of s, the neighbours below the least
  // normal value being those of the unbounded exponent; so 0 takes the roots
  // below the midpoint under the least normal value, which takes the tie.
  // With subnormals the neighbours are the format's own down to 0, which
  // takes the roots within half the least subnormal, ties included (0 is even).
  template <class Integer>
  static bool is_rounded_root(const input<Integer>& x, const T& s) {
    using std::isinf;
    using std::isnan;
    if (isnan(s)) return false;
    const auto limit = rounding_limit<Integer>();
    if (isinf(s)) return s > 0 ? x.residual_sign(limit) <= 0 : x.residual_sign(-limit) >= 0;
    const auto least = power_of_two<Integer>(1, least_exponent);
    const auto least_midpoint = least - power_of_two<Integer>(1, least_exponent - precision - 1);
    if (s == 0 && subnormals) {
      const auto half_least_subnormal = power_of_two<Integer>(1, least_exponent - precision);
      return x.residual_sign(-half_least_subnormal) <= 0 && x.residual_sign(half_least_subnormal) >= 0;
    }
    if (s == 0) return x.residual_sign(-least_midpoint) < 0 && x.residual_sign(least_midpoint) > 0;
    const auto exact_s = exactly<Integer>(double(s));
    auto midpoint_towards = [&](const T& neighbour) {
      if (isinf(neighbour)) return s > 0 ? limit : -limit;
      if (neighbour == 0 && !subnormals) return s > 0 ? least_midpoint : -least_midpoint;
      return midpoint(exact_s, exactly<Integer>(double(neighbour)));
    };
    const auto low = midpoint_towards(detail::next_down(s)), high = midpoint_towards(detail::next_up(s));
    const int at_low = x.residual_sign(low), at_high = x.residual_sign(high);
    if (at_low > 0 || at_high < 0) return false;  // s* outside [low, high]
    return (at_low != 0 && at_high != 0) || is_even(s);
  }

  // The last bit of the significand is 0 (0 included): s is an even multiple
  // of its ulp.
  static bool is_even(const T& s) {
    if (s == 0) return true;
    int e = 0;
    frexp(s, &e);
    return std::fmod(std::ldexp(double(s), -ulp_exponent(e - 1)), 2.0) == 0;
  }
};

}  // namespace contact::testing::exact
