// The plain window: the exponent range inside which plain T arithmetic cannot
// overflow or underflow in any stable formula. stable.hpp takes its plain path
// inside it and scaled<T> outside; batch.hpp's vector window lies inside it; the
// fuzzers fold inputs into it; docs/equations.md states the bound.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "float_tools.hpp"
#include "scaled.hpp"

namespace contact::detail {

// Half-width E of the window |x| in [2^-E, 2^E] (or x = 0): the formulas'
// intermediates are of degree three at most in u, dy and phi, and the least
// significant bit of a difference lies at most `digits` binades lower, so
// 4 E + digits + 8 binades must fit below T's largest exponent, and as many
// above its least normal value. An IEEE format has as many of the one as of the
// other (min_exponent = 3 - max_exponent); a cpp_bin_float may have fewer below.
template <class T>
constexpr long window_half_width(long digits) {
  using limits = std::numeric_limits<T>;
  const long room = std::min(long(limits::max_exponent), 3 - long(limits::min_exponent));
  return (room - digits) / 4 - 2;
}

// For the hardware types a compile-time constant: 240 for double, 24 for float.
template <class T>
  requires std::is_floating_point_v<T>
inline constexpr long plain_window = window_half_width<T>(std::numeric_limits<T>::digits);

template <class T>
struct safe_window {
  static long half_width() {
    if constexpr (std::is_floating_point_v<T>) return plain_window<T>;
    else return window_half_width<T>(precision_of<T>());
  }
  static bool holds(const T& x) {
    using std::fabs;
    const T magnitude = fabs(x);
    if (magnitude == 0) return true;
    if constexpr (std::numeric_limits<T>::is_bounded && std::numeric_limits<T>::max_exponent < 20000) {
      static const T lowest = scaled<T>::shifted(T(1), -half_width());
      static const T highest = scaled<T>::shifted(T(1), half_width());
      return lowest <= magnitude && magnitude <= highest;
    } else {
      const long bound = half_width();
      return scaled<T>::shifted(T(1), -bound) <= magnitude && magnitude <= scaled<T>::shifted(T(1), bound);
    }
  }
  static bool holds(const T& u, const T& dy, const T& phi) { return holds(u) && holds(dy) && holds(phi); }
};
static_assert(plain_window<double> == 240 && plain_window<float> == 24);

// The plain window on bit patterns, for binary32 and binary64: |x| in
// [2^-E, 2^E] with x normal. Bit patterns of non-negative numbers order as
// their values, so the test is one unsigned comparison; zero, subnormals, NaN
// and infinity all fail it.
template <class T>
  requires(std::is_same_v<T, float> || std::is_same_v<T, double>)
bool magnitude_inside_plain_window(const T& x) {
  using bits = typename binary_layout<T>::bits;
  constexpr bits magnitude = ~binary_layout<T>::sign;
  constexpr T highest = [] {
    T power = 1;
    for (long k = 0; k < plain_window<T>; ++k) power *= 2;
    return power;
  }();
  constexpr bits lowest = std::bit_cast<bits>(T(1) / highest);
  constexpr bits span = std::bit_cast<bits>(highest) - lowest;
  return bits((std::bit_cast<bits>(x) & magnitude) - lowest) <= span;
}

// floor(log2 |x|) for a finite non-zero binary32 or binary64 x, subnormals included.
template <class T>
  requires(std::is_same_v<T, float> || std::is_same_v<T, double>)
int binade_of(const T& x) {
  using layout = binary_layout<T>;
  using bits = typename layout::bits;
  constexpr int significand_bits = layout::significand_bits, bias = layout::bias;
  const bits magnitude = std::bit_cast<bits>(x) & ~layout::sign;
  const int field = int(magnitude >> significand_bits);
  if (field != 0) return field - bias;
  return int(sizeof(bits) * 8 - 1) - std::countl_zero(magnitude) - (bias - 1 + significand_bits);
}

// 2^k for k in T's normal exponent range, from its bits.
template <class T>
  requires(std::is_same_v<T, float> || std::is_same_v<T, double>)
T power_of_two(int k) {
  using layout = binary_layout<T>;
  return std::bit_cast<T>(typename layout::bits(k + layout::bias) << layout::significand_bits);
}

// x 2^k, exact when x and x 2^k are both normal or zero, or x 2^k lies further
// from the subnormals than x: the two factors have the sign of k, so the
// intermediate lies between x and x 2^k. Two steps because a shift from the
// subnormals to the top of the window exceeds T's exponent range.
template <class T>
  requires(std::is_same_v<T, float> || std::is_same_v<T, double>)
T scale_by_power_of_two(const T& x, int k) {
  const int first = k / 2;
  return (x * power_of_two<T>(first)) * power_of_two<T>(k - first);
}

// The common input: valid, u, dy and phi non-zero and inside the plain window,
// phi > 0, as a test of bits. Other types than binary32 and binary64 have no
// such shortcut and take safe_window's general test.
template <class T>
  requires(std::is_same_v<T, float> || std::is_same_v<T, double>)
bool inside_plain_window(const T& u, const T& dy, const T& phi) {
  return magnitude_inside_plain_window(u) && magnitude_inside_plain_window(dy) && magnitude_inside_plain_window(phi) &&
         !std::signbit(phi);
}

}  // namespace contact::detail
