// The plain window: the exponent range inside which plain T arithmetic cannot
// overflow or underflow in any stable formula. stable.hpp takes its plain stage
// inside it (and the moved stage, by the phi bands, outside it) and scaled<T> where
// neither serves; the common window (below), the first test of the stable path
// and of the batch kernels, lies inside it; the fuzzers fold inputs into it;
// docs/equations.md states the bound.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
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
  requires hardware_binary<T>
bool magnitude_inside_plain_window(const T& x);

template <class T>
struct safe_window {
  static long half_width() {
    if constexpr (std::is_floating_point_v<T>) return plain_window<T>;
    else return window_half_width<T>(precision_of<T>());
  }
  static bool holds(const T& x) {
    if constexpr (hardware_binary<T>) {
      return (x == 0) | magnitude_inside_plain_window(x);  // on the bits, without a branch
    } else if constexpr (emulated_format<T>::available) {
      // x87 long double and binary128 on their bits, as float and double
      // (magnitude_inside_plain_window): zero is inside; subnormals,
      // infinities and NaN are not (& and |, not && and ||: no branch that
      // only inputs beyond 2^E would take the other way)
      using format = emulated_format<T>;
      unpacked_binary parts;
      if (!format::unpack(x, parts)) return x == 0;
      const long E = half_width(), binade = parts.exponent + format::digits - 1;
      return (-E <= binade) & ((binade < E) | ((binade == E) & (parts.significand == uint128(1) << (format::digits - 1))));
    } else if constexpr (mpfr_number<T>) {
      // MPFR: |x| in [2^(e-1), 2^e) for a regular x, e its exponent field;
      // zero, infinities, NaN (special values of the field) and |x| in
      // [2^E, 2^(E+1)) take the general test below
      const long e = x.backend().data()->_mpfr_exp, E = half_width();
      if ((e > std::numeric_limits<long>::min() + 3) & (e != E + 1)) return (-E < e) & (e <= E);
    }
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
// The window's ends as bits: |x| lies inside iff bits(|x|) - lowest <= span
// (also the batch kernels' lane test).
template <class T>
  requires hardware_binary<T>
struct plain_window_bits {
  using bits = typename binary_layout<T>::bits;
  static constexpr T highest = [] {
    T power = 1;
    for (long k = 0; k < plain_window<T>; ++k) power *= 2;
    return power;
  }();
  static constexpr bits lowest = std::bit_cast<bits>(T(1) / highest);
  static constexpr bits span = std::bit_cast<bits>(highest) - lowest;
};

template <class T>
  requires hardware_binary<T>
bool magnitude_inside_plain_window(const T& x) {
  using window = plain_window_bits<T>;
  using bits = typename window::bits;
  constexpr bits magnitude = ~binary_layout<T>::sign;
  return bits((std::bit_cast<bits>(x) & magnitude) - window::lowest) <= window::span;
}

// floor(log2 |x|) for a finite non-zero binary32 or binary64 x, subnormals included.
template <class T>
  requires hardware_binary<T>
int binade_of(const T& x) {
  using layout = binary_layout<T>;
  using bits = typename layout::bits;
  constexpr int significand_bits = layout::significand_bits, bias = layout::bias;
  const bits magnitude = std::bit_cast<bits>(x) & ~layout::sign;
  const int field = int(magnitude >> significand_bits);
  if (field != 0) return field - bias;
  return int(sizeof(bits) * 8 - 1) - std::countl_zero(magnitude) - (bias - 1 + significand_bits);
}

// floor(log2 |x|) for a finite non-zero x of the other types.
template <class T>
  requires(!hardware_binary<T>)
int binade_of(const T& x) {
  return int(scaled<T>(x).exponent - 1);
}

// The phi bands: outside the plain window, (A.2)'s homogeneity in (u, dy)
// lets u and dy move by a power of two to wherever phi leaves room for them.
// phi's binades are cut into bands of 2^band_bits; for each band, `top` is
// where the larger of |u|, |dy| is moved (into [2^(top-1), 2^top)) and
// `lowest` the least binade a non-zero u or dy may then have. With them no
// intermediate of the stable formulas, of the fma pre-test and of two_prod
// over- or underflows (docs/equations.md, section 6, lists each bound;
// proofs/gappa/window/ proves them per band). A band leaves u and dy 406 to
// 904 binades of spread in double, 16 to 93 in float (the plain window: 480
// and 48 with phi inside it); an impact, 458 to 1428 and 39 to 166. The last
// band ends early, at `end`, 2^1021 (double) or 2^125 (float): from there up
// 2 (1 + phi) could overflow, and phi is in no band.
template <class T>
  requires hardware_binary<T>
struct phi_bands {
  struct band {
    int top, lowest;
    // the least binade of gap = -dy when u, the larger, lies at top - 1: the
    // impact formula's own room (impact's u > gap puts u at top - 1 in the moved
    // stage), far below `lowest` where phi is small
    int impact_lowest;
  };
  static constexpr int digits = std::numeric_limits<T>::digits;
  static constexpr int least_normal_binade = std::numeric_limits<T>::min_exponent - 1;  // -1022
  static constexpr int overflow_binade = std::numeric_limits<T>::max_exponent;         // 2^1024 overflows
  static constexpr int least_binade = least_normal_binade - (digits - 1);               // -1074, the least subnormal
  static constexpr int band_bits = std::is_same_v<T, double> ? 7 : 4;
  // the largest binade of phi in a band: 2 (1 + phi) < 2^(Q + 3) must stay finite
  static constexpr int last_phi_binade = overflow_binade - 4;
  static constexpr int count = ((last_phi_binade - least_binade) >> band_bits) + 1;
  // band j holds phi in [2^first_of(j), 2^(last_of(j) + 1))
  static constexpr int first_of(int j) { return least_binade + (j << band_bits); }
  static constexpr int last_of(int j) { return std::min(first_of(j) + (1 << band_bits) - 1, last_phi_binade); }
  // 2^(last_phi_binade + 1): phi from here up is in no band
  static constexpr T end = [] {
    T power = 1;
    for (int k = 0; k <= last_phi_binade; ++k) power *= 2;
    return power;
  }();

  static constexpr int ceil_half(int x) { return x >= 0 ? (x + 1) / 2 : -(-x / 2); }

  // phi in [2^P, 2^(Q+1)), |u|, |dy| < 2^top; the bounds of docs/equations.md, section 6.
  static constexpr band of(int P, int Q) {
    const int p = digits, emin = least_normal_binade;
    // the largest intermediates, below 2^(2 top + max(Q + 3, 0) + 1): the discriminants
    // (non-negative: Q <= last_phi_binade, so / 2 is the floor)
    const int top = (overflow_binade - 1 - std::max(Q + 3, 0)) / 2;
    // a non-zero phi is a multiple of 2^(Pe - p + 1), a non-zero u or dy of 2^(b - p + 1)
    const int Pe = std::max(P, emin);
    const int lowest = std::max({ceil_half(emin - P),    // phi dy^2
                                 emin - Pe + 2 * p - 2,  // two_prod's low part, the fmas' exact values
                                 // phi dy^2's low part (stable_form::stiffness_of), a multiple of
                                 // 2^(Pe + 2b - 3p + 3), and phi dy^2 >= 2^(emin + 2p - 2), so that
                                 // the compensated release's corrections stay far above the subnormals
                                 ceil_half(emin - Pe + 2 * p - 2),
                                 ceil_half(emin),        // u^2, the discriminants
                                 emin - P,               // phi dy
                                 emin + p - 1});         // u + dy, a multiple of 2^emin
    // with u in [2^(top-1), 2^top): push = phi gap and, where gap is near u,
    // push (u - gap) >= 2^(P + 2 (top - 2) - p + 1); push's error a multiple of
    // the least subnormal; gap normal, so that it moves on its bits
    const int impact_lowest = std::max({emin - P, emin - Pe + p - 1, emin});
    return {top, lowest, impact_lowest};
  }
  static constexpr std::array<band, count> table = [] {
    std::array<band, count> bands{};
    for (int j = 0; j < count; ++j) bands[j] = of(first_of(j), last_of(j));
    return bands;
  }();
  // Whether every input of safe_window (u, dy, phi in binades -E .. E, E =
  // plain_window) fits its phi's band: the larger of u, dy moved to top - 1,
  // the smaller, at most 2 E binades below, still at lowest or above. The moved
  // stage then sends to the exact stage only inputs outside safe_window.
  static constexpr bool holds_safe_window = [] {
    constexpr int E = int(plain_window<T>);
    for (int j = 0; j < count; ++j)
      if (last_of(j) >= -E && first_of(j) <= E && table[j].top - 1 - table[j].lowest < 2 * E) return false;
    return true;
  }();
  // the band of phi in (0, end), subnormals included
  static band of_phi(const T& phi) { return table[(binade_of(phi) - least_binade) >> band_bits]; }
};

// The common input: valid, u, dy and phi non-zero and inside the plain window,
// phi > 0, as a test of bits. Other types than binary32 and binary64 have no
// such shortcut and take safe_window's general test.
template <class T>
  requires hardware_binary<T>
bool inside_plain_window(const T& u, const T& dy, const T& phi) {
  return magnitude_inside_plain_window(u) && magnitude_inside_plain_window(dy) && magnitude_inside_plain_window(phi) &&
         !std::signbit(phi);
}

// The common window, for binary32 and binary64: |u| and |dy| normal in
// [2^L, 2^(L + 2C)), phi normal in [2^M, 2^(M + 2C)), inside the plain window.
// The stable path's first test and the batch kernels' lane test. Bit patterns
// of non-negative numbers order as their values and 2C binades is a power of
// two, so the three offsets from the lower ends lie below 2^(2C) binades of bit
// patterns iff their bitwise OR does: one comparison; phi's sign bit makes a
// negative phi fail. Physical inputs lie inside; the rest of the plain window
// takes the moved stage, which gives the same s.
// double: C = 128, L = M = -128. float: C = 16 (the plain window, 24 binades
// either side of 1, holds no 64), placed where audio-rate inputs lie: u and dy
// from 2^-24 (displacements of 1e-7 to 1e-3 m: binades -24 to -11), phi from
// 2^-9 (binades -10 to 23): 99.5% of the physical scene's float inputs, against
// 16.7% for [2^-16, 2^16) for all three.
template <class T>
  requires hardware_binary<T>
inline constexpr int common_window = std::is_same_v<T, double> ? 128 : 16;  // C
template <class T>
  requires hardware_binary<T>
inline constexpr int common_window_least_uv = std::is_same_v<T, double> ? -128 : -24;  // L
template <class T>
  requires hardware_binary<T>
inline constexpr int common_window_least_phi = std::is_same_v<T, double> ? -128 : -9;  // M
static_assert(std::has_single_bit(unsigned(2 * common_window<double>)) &&
                  std::has_single_bit(unsigned(2 * common_window<float>)),
              "one comparison of the OR");

// both ranges inside the plain window [2^-E, 2^E]
template <class T>
consteval bool common_window_inside_plain_window() {
  constexpr long E = plain_window<T>, width = 2 * common_window<T>;
  for (const long least : {common_window_least_uv<T>, common_window_least_phi<T>})
    if (least < -E || least + width > E) return false;
  return true;
}
static_assert(common_window_inside_plain_window<double>() && common_window_inside_plain_window<float>());

// bits(2^binade) for a normal power of two
template <class T>
consteval typename binary_layout<T>::bits bits_of_power_of_two(int binade) {
  return typename binary_layout<T>::bits(binary_layout<T>::bias + binade) << binary_layout<T>::significand_bits;
}

template <class T>
inline constexpr typename binary_layout<T>::bits common_window_lowest_uv = bits_of_power_of_two<T>(common_window_least_uv<T>);  // 2^L

template <class T>
inline constexpr typename binary_layout<T>::bits common_window_lowest_phi = bits_of_power_of_two<T>(common_window_least_phi<T>);  // 2^M

template <class T>
inline constexpr typename binary_layout<T>::bits common_window_width =  // 2C binades of bit patterns
    typename binary_layout<T>::bits(2 * common_window<T>) << binary_layout<T>::significand_bits;

// The OR of the three offsets; the input lies in the window iff it is below common_window_width.
template <class T>
  requires hardware_binary<T>
inline typename binary_layout<T>::bits common_window_offsets(const T& abs_u, const T& abs_dy, const T& phi) {
  using bits = typename binary_layout<T>::bits;
  constexpr bits lowest_uv = common_window_lowest_uv<T>, lowest_phi = common_window_lowest_phi<T>;
  return bits(std::bit_cast<bits>(abs_u) - lowest_uv) | bits(std::bit_cast<bits>(abs_dy) - lowest_uv) |
         bits(std::bit_cast<bits>(phi) - lowest_phi);
}

template <class T>
  requires hardware_binary<T>
bool inside_common_window(const T& u, const T& dy, const T& phi) {
  using std::fabs;
  return common_window_offsets(fabs(u), fabs(dy), phi) < common_window_width<T>;
}

}  // namespace contact::detail
