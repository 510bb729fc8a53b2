// mini_float: a binary floating-point format small enough to enumerate.
//
// Precision significand bits (the leading one included), normal numbers
// 2^MinExponent <= |x| <= (2 - 2^(1 - Precision)) 2^MaxExponent, round to
// nearest with ties to even, and no subnormals: a result that rounds to below
// 2^MinExponent in magnitude is flushed to zero of its sign, one that rounds to
// 2^(MaxExponent + 1) or beyond becomes infinity of its sign. (These are
// cpp_bin_float's rules; Boost 1.74's cpp_bin_float itself cannot serve for a
// few bits: its sum of opposite signs misrounds when the smaller term lies just
// beyond the significand, and its conversion to double returns 0 for a narrow
// exponent range.)
//
// A value is held in a double, which holds every value of the format exactly.
// Each operation is done in double and rounded once more to Precision bits.
// That second rounding gives the correctly rounded result of +, -, *, / and
// sqrt because double carries at least 2 Precision + 2 bits (Figueroa, "When
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

template <int Precision, int MinExponent, int MaxExponent, bool FusedFma>
class mini_float {
  static_assert(2 <= Precision && 2 * Precision + 2 <= std::numeric_limits<double>::digits);
  static_assert(-500 <= MinExponent && MinExponent < 0 && 0 < MaxExponent && MaxExponent <= 500);

 public:
  static constexpr int precision = Precision, least_exponent = MinExponent, greatest_exponent = MaxExponent;

  mini_float() = default;
  template <std::integral I>
  mini_float(I n) : value_(rounded(static_cast<double>(n))) {}  // NOLINT: implicit, as for the literals of generic code
  explicit mini_float(double x) : value_(rounded(x)) {}
  explicit operator double() const { return value_; }

  friend mini_float operator-(mini_float a) { return exactly(-a.value_); }
  friend mini_float operator+(mini_float a, mini_float b) { return mini_float(a.value_ + b.value_); }
  friend mini_float operator-(mini_float a, mini_float b) { return mini_float(a.value_ - b.value_); }
  friend mini_float operator*(mini_float a, mini_float b) { return mini_float(a.value_ * b.value_); }
  friend mini_float operator/(mini_float a, mini_float b) { return mini_float(a.value_ / b.value_); }
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

  static mini_float exactly(double x) {
    mini_float r;
    r.value_ = x;
    return r;
  }
  static constexpr int dropped_bits = std::numeric_limits<double>::digits - Precision;
  static constexpr std::uint64_t exponent_field = 0x7ff0000000000000;

  // 2^n for a normal double 2^n
  static constexpr double power_of_two(int n) { return std::bit_cast<double>(std::uint64_t(1023 + n) << 52); }
  static constexpr double least = power_of_two(MinExponent), beyond = power_of_two(MaxExponent + 1);
  // frexp of a double, by its bits: x = m 2^e, 0.5 <= |m| < 1 (0, inf, NaN: m = x, e = 0)
  static double split(double x, int* exponent) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    if (x == 0 || !std::isfinite(x)) {
      *exponent = 0;
      return x;
    }
    *exponent = int((bits & exponent_field) >> 52) - 1022;  // x is a normal double: the format's range is far inside
    return std::bit_cast<double>((bits & ~exponent_field) | (std::uint64_t(1022) << 52));
  }
  static bool is_midpoint(double x) {
    if (x == 0 || !std::isfinite(x)) return false;
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    // the highest dropped bit set, the ones below it clear
    return (bits & ((std::uint64_t(1) << dropped_bits) - 1)) == std::uint64_t(1) << (dropped_bits - 1);
  }
  // x rounded to Precision bits, ties to even, then flushed to zero or
  // infinity outside the range. The rounding adds half a unit of the last
  // kept bit, less one unless that bit is odd, to the bit pattern and clears
  // the dropped bits: a carry out of the significand steps the exponent, and
  // out of the largest exponent gives infinity. A subnormal double rounds
  // wrongly here, but lies far below the format's range and flushes to zero.
  static double rounded(double x) {
    if (!std::isfinite(x)) return x;
    std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    const std::uint64_t last_kept = (bits >> dropped_bits) & 1;
    bits += (std::uint64_t(1) << (dropped_bits - 1)) - 1 + last_kept;
    bits &= ~((std::uint64_t(1) << dropped_bits) - 1);
    const double r = std::bit_cast<double>(bits);
    if (std::fabs(r) < least) return std::copysign(0.0, x);
    if (std::fabs(r) >= beyond) return std::copysign(INFINITY, x);
    return r;
  }
};

}  // namespace contact::testing

// Without a fused fma the solver takes Dekker's product and its own exact sum.
template <int P, int MinE, int MaxE>
struct contact::detail::has_fused_fma<contact::testing::mini_float<P, MinE, MaxE, false>> : std::false_type {};

template <int P, int MinE, int MaxE, bool Fused>
struct std::numeric_limits<contact::testing::mini_float<P, MinE, MaxE, Fused>> {
  using T = contact::testing::mini_float<P, MinE, MaxE, Fused>;

 public:
  static constexpr bool is_specialized = true, is_signed = true, is_integer = false, is_exact = false;
  static constexpr bool has_infinity = true, has_quiet_NaN = true, has_signaling_NaN = false;
  static constexpr std::float_denorm_style has_denorm = std::denorm_absent;
  static constexpr bool has_denorm_loss = false, is_iec559 = false, is_bounded = true, is_modulo = false;
  static constexpr bool traps = false, tinyness_before = false;
  static constexpr std::float_round_style round_style = std::round_to_nearest;
  static constexpr int radix = 2, digits = P, digits10 = 0, max_digits10 = 4;
  // the IEEE convention: min() = 2^(min_exponent - 1), max() < 2^max_exponent
  static constexpr int min_exponent = MinE + 1, max_exponent = MaxE + 1, min_exponent10 = 0, max_exponent10 = 0;
  static T min() { return T(std::ldexp(1.0, MinE)); }
  static T max() { return T(std::ldexp(2.0 - std::ldexp(1.0, 1 - P), MaxE)); }
  static T lowest() { return -max(); }
  static T epsilon() { return T(std::ldexp(1.0, 1 - P)); }
  static T round_error() { return T(0.5); }
  static T infinity() { return T(INFINITY); }
  static T quiet_NaN() { return T(NAN); }
  static T signaling_NaN() { return T(NAN); }
  static T denorm_min() { return min(); }
};
