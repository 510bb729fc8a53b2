// mini_float: a binary floating-point format small enough to enumerate.
//
// Precision significand bits (the leading one included), normal numbers
// 2^MinExponent <= |x| <= (2 - 2^(1 - Precision)) 2^MaxExponent, round to
// nearest with ties to even. A result that rounds to 2^(MaxExponent + 1) or
// beyond becomes infinity of its sign. Below 2^MinExponent, without
// Subnormals, a result that rounds (at Precision bits) to below 2^MinExponent
// in magnitude is flushed to zero of its sign; with Subnormals it is rounded
// to a multiple of 2^(MinExponent - Precision + 1), the least subnormal, as
// IEEE 754 does (gradual underflow), and numeric_limits calls the format
// IEEE: with MinExponent = 1 - MaxExponent it is a binary interchange format
// in miniature, which the correctly rounded mode asks for. (Without
// Subnormals these are cpp_bin_float's rules; Boost 1.74's cpp_bin_float itself cannot serve for a
// few bits: its sum of opposite signs misrounds when the smaller term lies just
// beyond the significand, and its conversion to double returns 0 for a narrow
// exponent range.)
//
// A value is held in a double, which holds every value of the format exactly.
// Each operation is done in double and rounded once more to Precision bits.
// That second rounding gives the correctly rounded result of +, -, *, / and
// sqrt because double carries at least 2 Precision + 2 bits (a subnormal
// result has fewer significant bits, which only widens the margin) (Figueroa, "When
// is double rounding innocuous?", 1995) and the double operation can neither
// overflow nor underflow for exponents this small. fma is rounded from the
// exact sum as a double pair.
//
// FusedFma tells the solver which fma to use: true, this one, rounded once;
// false, the solver's own exact product and sum (Dekker), as for cpp_bin_float.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>
#include <ostream>
#include <type_traits>

#include "contact/detail/float_tools.hpp"

namespace contact::testing {

template <int Precision, int MinExponent, int MaxExponent, bool FusedFma, bool Subnormals = false>
class mini_float {
  static_assert(2 <= Precision && 2 * Precision + 2 <= std::numeric_limits<double>::digits);
  static_assert(-500 <= MinExponent && MinExponent < 0 && 0 < MaxExponent && MaxExponent <= 500);

 public:
  static constexpr int precision = Precision, least_exponent = MinExponent, greatest_exponent = MaxExponent;
  static constexpr bool subnormals = Subnormals;

  // constexpr where generic code needs constants of T (the rounded mode's eps<T>)
  constexpr mini_float() = default;
  template <std::integral I>
  constexpr mini_float(I n) : value_(rounded(static_cast<double>(n))) {}  // NOLINT: implicit, as for the literals of generic code
  constexpr explicit mini_float(double x) : value_(rounded(x)) {}
  constexpr explicit operator double() const { return value_; }

  friend constexpr mini_float operator-(mini_float a) { return exactly(-a.value_); }
  friend constexpr mini_float operator+(mini_float a, mini_float b) { return mini_float(a.value_ + b.value_); }
  friend constexpr mini_float operator-(mini_float a, mini_float b) { return mini_float(a.value_ - b.value_); }
  friend constexpr mini_float operator*(mini_float a, mini_float b) { return mini_float(a.value_ * b.value_); }
  friend constexpr mini_float operator/(mini_float a, mini_float b) { return mini_float(a.value_ / b.value_); }
  mini_float& operator+=(mini_float b) { return *this = *this + b; }
  mini_float& operator-=(mini_float b) { return *this = *this - b; }
  mini_float& operator*=(mini_float b) { return *this = *this * b; }
  mini_float& operator/=(mini_float b) { return *this = *this / b; }
  friend bool operator==(mini_float a, mini_float b) { return a.value_ == b.value_; }
  friend std::partial_ordering operator<=>(mini_float a, mini_float b) { return a.value_ <=> b.value_; }

  friend mini_float sqrt(mini_float a) { return mini_float(std::sqrt(a.value_)); }
  friend mini_float fabs(mini_float a) { return exactly(std::fabs(a.value_)); }
  friend bool isfinite(mini_float a) { return std::isfinite(a.value_); }
  friend bool isinf(mini_float a) { return std::isinf(a.value_); }
  friend bool isnan(mini_float a) { return std::isnan(a.value_); }
  friend bool signbit(mini_float a) { return std::signbit(a.value_); }
  // exact, as IEEE's remainder operations are
  friend mini_float fmod(mini_float a, mini_float b) { return exactly(std::fmod(a.value_, b.value_)); }
  friend mini_float frexp(mini_float a, int* exponent) { return exactly(split(a.value_, exponent)); }
  friend mini_float ldexp(mini_float a, int exponent) {
    // two exact multiplications by powers of two; one that leaves double's
    // range takes the result far outside the format's, where it flushes anyway
    const int n = std::clamp(exponent, -2000, 2000);
    return mini_float(a.value_ * power_of_two(n / 2) * power_of_two(n - n / 2));
  }

  // a b + c rounded once. a b is exact in double; the sum is hi + lo exactly
  // (TwoSum). Rounding hi again is right unless hi is a midpoint of the
  // format and lo != 0: then lo breaks the tie, as the next double towards it
  // does.
  friend mini_float fma(mini_float a, mini_float b, mini_float c) {
    const double product = a.value_ * b.value_;
    const double hi = product + c.value_;
    const double product_virtual = hi - c.value_;
    const double lo = (product - product_virtual) + (c.value_ - (hi - product_virtual));
    if (lo == 0 || !is_midpoint(hi)) return mini_float(hi);
    return mini_float(std::nextafter(hi, lo > 0 ? INFINITY : -INFINITY));
  }

  friend std::ostream& operator<<(std::ostream& out, mini_float a) { return out << a.value_; }

 private:
  double value_ = 0;

  static constexpr mini_float exactly(double x) {
    mini_float r;
    r.value_ = x;
    return r;
  }
  static constexpr std::uint64_t exponent_field = 0x7ff0000000000000, fraction_field = 0x000fffffffffffff;

  // 2^n for a normal double 2^n
  static constexpr double power_of_two(int n) { return std::bit_cast<double>(std::uint64_t(1023 + n) << 52); }
  static constexpr double least = power_of_two(MinExponent), beyond = power_of_two(MaxExponent + 1);
  // The exponent of the spacing of the format's values at binade k
  // (2^k <= |x| < 2^(k + 1)), with an unbounded exponent but for subnormals.
  static constexpr int quantum_exponent(int k) {
    return (Subnormals ? std::max(k, MinExponent) : k) - Precision + 1;
  }
  // the binade of a normal double, by its bits
  static constexpr int binade_of(double x) {
    return int((std::bit_cast<std::uint64_t>(x) & exponent_field) >> 52) - 1023;
  }
  // frexp of a double, by its bits: x = m 2^e, 0.5 <= |m| < 1 (0, inf, NaN: m = x, e = 0)
  static double split(double x, int* exponent) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    if (x == 0 || !std::isfinite(x)) {
      *exponent = 0;
      return x;
    }
    *exponent = binade_of(x) + 1;  // x is a normal double: the format's range is far inside
    return std::bit_cast<double>((bits & ~exponent_field) | (std::uint64_t(1022) << 52));
  }
  // x lies halfway between two neighbouring values of the format (as they
  // are before the range's ends flush or overflow)
  static bool is_midpoint(double x) {
    if (x == 0 || !std::isfinite(x)) return false;
    const int k = binade_of(x);
    if (!Subnormals && k < MinExponent - 1) return false;  // far below the range, flushed either way
    const double units = std::fabs(x) * power_of_two(-quantum_exponent(k));  // exact
    return units - std::floor(units) == 0.5;
  }
  // x rounded to a multiple of 2^quantum_exponent, ties to even, on the bits
  // of the significand (so that it is constexpr), then flushed to zero
  // (without subnormals) or to infinity outside the range.
  static constexpr double rounded(double x) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    const bool negative = (bits >> 63) != 0;
    const double zero = negative ? -0.0 : 0.0, infinity = negative ? -std::numeric_limits<double>::infinity()
                                                                    : std::numeric_limits<double>::infinity();
    if ((bits & exponent_field) == exponent_field) return x;  // inf, NaN
    if ((bits & exponent_field) == 0) return zero;  // 0, or a subnormal double, far below the range
    const int k = binade_of(x);
    if (k > MaxExponent) return infinity;
    if (k < MinExponent - Precision - 1) return zero;  // below half the least subnormal and least normal value
    const int quantum = quantum_exponent(k);
    const int dropped = quantum - (k - 52);  // of the 53 significand bits: >= 53 - Precision, <= 53 + 1
    std::uint64_t m = (bits & fraction_field) | (std::uint64_t(1) << 52);
    if (dropped > 53) {
      m = 0;  // below half the quantum
    } else {
      const std::uint64_t half = std::uint64_t(1) << (dropped - 1), rest = m & (2 * half - 1);
      m >>= dropped;
      if (rest > half || (rest == half && (m & 1) != 0)) ++m;
    }
    const double r = double(m) * power_of_two(quantum);  // exact
    if (!Subnormals && r < least) return zero;
    if (r >= beyond) return infinity;
    return negative ? -r : r;
  }
};

}  // namespace contact::testing

// Without a fused fma the solver takes Dekker's product and its own exact sum.
template <int P, int MinE, int MaxE, bool Sub>
struct contact::detail::has_fused_fma<contact::testing::mini_float<P, MinE, MaxE, false, Sub>> : std::false_type {};

template <int P, int MinE, int MaxE, bool Fused, bool Sub>
struct std::numeric_limits<contact::testing::mini_float<P, MinE, MaxE, Fused, Sub>> {
  using T = contact::testing::mini_float<P, MinE, MaxE, Fused, Sub>;

 public:
  static constexpr bool is_specialized = true, is_signed = true, is_integer = false, is_exact = false;
  static constexpr bool has_infinity = true, has_quiet_NaN = true, has_signaling_NaN = false;
  static constexpr std::float_denorm_style has_denorm = Sub ? std::denorm_present : std::denorm_absent;
  // IEEE-like: with subnormals, and as many binades below 1 as above
  static constexpr bool has_denorm_loss = false, is_iec559 = Sub && MinE == 1 - MaxE, is_bounded = true, is_modulo = false;
  static constexpr bool traps = false, tinyness_before = false;
  static constexpr std::float_round_style round_style = std::round_to_nearest;
  static constexpr int radix = 2, digits = P, digits10 = 0, max_digits10 = 4;
  // the IEEE convention: min() = 2^(min_exponent - 1), max() < 2^max_exponent
  static constexpr int min_exponent = MinE + 1, max_exponent = MaxE + 1, min_exponent10 = 0, max_exponent10 = 0;
  static constexpr T min() { return T(power_of_two(MinE)); }
  static constexpr T max() { return T((2.0 - power_of_two(1 - P)) * power_of_two(MaxE)); }
  static constexpr T lowest() { return -max(); }
  static constexpr T epsilon() { return T(power_of_two(1 - P)); }
  static constexpr T round_error() { return T(0.5); }
  static constexpr T infinity() { return T(std::numeric_limits<double>::infinity()); }
  static constexpr T quiet_NaN() { return T(std::numeric_limits<double>::quiet_NaN()); }
  static constexpr T signaling_NaN() { return quiet_NaN(); }
  static constexpr T denorm_min() { return Sub ? T(power_of_two(MinE - P + 1)) : min(); }

 private:
  static constexpr double power_of_two(int n) { return std::bit_cast<double>(std::uint64_t(1023 + n) << 52); }
};
