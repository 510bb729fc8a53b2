// a * b + c rounded once (to nearest, ties to even), for the formats whose
// library fma is a software emulation that saves, changes and restores the
// floating-point environment on every call (glibc's fmal for x87 long double,
// libquadmath's fmaq for binary128), and costs far more than the whole closed
// form around it: in integer arithmetic (fma_in_integers), and for x87 long
// double inside a wide range from error-free sums and products in x87
// arithmetic (fma_by_exact_parts). The result is the library's, bit for bit: an fma
// rounded once has one correct answer (tests/emulated_fma_test.cpp holds both
// to MPFR). Every other type keeps its own fma.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include <boost/multiprecision/number.hpp>

#include "error_free.hpp"

// Declared, not included: the core solver needs no quadmath header.
namespace boost::multiprecision::backends {
struct float128_backend;
}

namespace contact::detail {

using uint128 = unsigned __int128;

// A normal number as sign, integer significand (digits bits, the leading one
// included) and the exponent of the significand's last bit.
struct unpacked_binary {
  uint128 significand;
  int exponent;
  bool negative;
};

// The formats emulated_fma knows, by their bits; `available` is false for every
// other type. Both have 15 exponent bits: normal binades -16382 .. 16383.
template <class T>
struct emulated_format {
  static constexpr bool available = false;
};

inline constexpr int wide_bias = 16383;

// x87 extended precision: a 64-bit significand with an explicit leading bit,
// then sign and exponent in the next 16 bits (the rest of long double's 16
// bytes is padding).
template <>
struct emulated_format<long double> {
  static constexpr bool available =
      std::numeric_limits<long double>::digits == 64 && std::numeric_limits<long double>::max_exponent == 16384;
  static constexpr int digits = 64;
  // x's parts, read where x lies rather than through a copy of x (a load of
  // part of an x87 store that has just been made waits for the store)
  static std::uint64_t significand_of(const long double& x) {
    std::uint64_t significand;
    std::memcpy(&significand, &x, sizeof significand);
    return significand;
  }
  static unsigned sign_exponent_of(const long double& x) {
    std::uint16_t sign_exponent;
    std::memcpy(&sign_exponent, reinterpret_cast<const unsigned char*>(&x) + 8, sizeof sign_exponent);
    return sign_exponent;
  }
  static unsigned exponent_field(const long double& x) { return sign_exponent_of(x) & 0x7fffu; }
  // whether x is normal (not zero, subnormal, infinite or NaN), and its parts
  static bool unpack(const long double& x, unpacked_binary& out) {
    const std::uint64_t significand = significand_of(x);
    const unsigned sign_exponent = sign_exponent_of(x);
    const unsigned field = sign_exponent & 0x7fffu;
    out = {significand, int(field) - wide_bias - 63, (sign_exponent >> 15) != 0};
    return (field - 1 < 0x7ffeu) & ((significand >> 63) != 0);
  }
  // the normal number significand 2^(top - 63), significand in [2^63, 2^64)
  static long double pack(bool negative, int top, uint128 significand) {
    const uint128 sign_exponent = (uint128(negative) << 15) | uint128(top + wide_bias);
    return std::bit_cast<long double>(uint128(std::uint64_t(significand)) | (sign_exponent << 64));
  }
  // |x| (finite) as an integer that counts the values from zero up: the
  // exponent field above the significand without its explicit leading bit
  static uint128 magnitude_key(const long double& x) {
    return (uint128(sign_exponent_of(x) & 0x7fffu) << 63) | (significand_of(x) & ~(std::uint64_t(1) << 63));
  }
  static long double from_magnitude_key(uint128 key, bool negative) {
    const uint128 field = key >> 63, lead = uint128(field != 0) << 63;
    return std::bit_cast<long double>((key & ~(~uint128(0) << 63)) | lead | ((field | uint128(negative) << 15) << 64));
  }
};

// IEEE binary128 (Boost's float128, whose backend holds a __float128): a
// 112-bit fraction field under a hidden leading bit.
template <boost::multiprecision::expression_template_option Templates>
struct emulated_format<boost::multiprecision::number<boost::multiprecision::backends::float128_backend, Templates>> {
  using type = boost::multiprecision::number<boost::multiprecision::backends::float128_backend, Templates>;
  static constexpr bool available = true;
  static constexpr int digits = 113;
  static constexpr uint128 hidden = uint128(1) << 112;
  template <class X>  // (a template, so that the backend is complete where it is used)
  static bool unpack(const X& x, unpacked_binary& out) {
    const uint128 bits = std::bit_cast<uint128>(x.backend().value());
    const unsigned field = unsigned(bits >> 112) & 0x7fffu;
    out = {(bits & (hidden - 1)) | hidden, int(field) - wide_bias - 112, (bits >> 127) != 0};
    return field - 1 < 0x7ffeu;
  }
  static type pack(bool negative, int top, uint128 significand) {
    const uint128 bits = (uint128(negative) << 127) | (uint128(top + wide_bias) << 112) | (significand - hidden);
    return type(std::bit_cast<__float128>(bits));
  }
  template <class X>
  static uint128 bits_of(const X& x) {
    return std::bit_cast<uint128>(x.backend().value());
  }
  template <class X>  // IEEE's bit patterns of magnitudes count the values already
  static uint128 magnitude_key(const X& x) {
    return bits_of(x) & ~(uint128(1) << 127);
  }
  static type from_magnitude_key(uint128 key, bool negative) {
    return type(std::bit_cast<__float128>(key | uint128(negative) << 127));
  }
};

// 256-bit unsigned integers, as the two halves the fma needs.
struct uint256 {
  uint128 high, low;
};

inline uint256 multiply(uint128 a, uint128 b, bool narrow) {
  if (narrow) return {0, a * b};  // both below 2^64
  const uint128 mask = ~std::uint64_t(0);
  const uint128 a0 = a & mask, a1 = a >> 64, b0 = b & mask, b1 = b >> 64;
  const uint128 middle = a0 * b1 + a1 * b0;  // below 2^114 for factors below 2^113
  const uint128 low = a0 * b0 + (middle << 64);
  return {a1 * b1 + (middle >> 64) + uint128(low < (middle << 64)), low};
}

// The code below has few branches, each of which the tests take both ways:
// a shift by 128 - s for s in [0, 127] is written (v >> 1) >> (127 - s).

// x 2^shift, shift in [0, 255], for an x that stays below 2^256
inline uint256 shifted_left(uint256 x, int shift) {
  if (shift >= 128) return {x.low << (shift - 128), 0};
  return {(x.high << shift) | ((x.low >> 1) >> (127 - shift)), x.low << shift};
}

// x 2^-shift, shift > 0, truncated, with the last bit set if any bit was lost
// (a sticky bit: see emulated_fma)
inline uint256 shifted_right_sticky(uint256 x, int shift) {
  if (shift >= 256) return {0, uint128((x.high | x.low) != 0)};
  uint128 lost;
  uint256 r;
  if (shift >= 128) {
    const int s = shift - 128;
    lost = x.low | ((x.high << 1) << (127 - s));
    r = {0, x.high >> s};
  } else {
    lost = x.low << (128 - shift);
    r = {x.high >> shift, (x.low >> shift) | (x.high << (128 - shift))};
  }
  r.low |= uint128(lost != 0);
  return r;
}

inline bool less(const uint256& a, const uint256& b) { return (a.high < b.high) | ((a.high == b.high) & (a.low < b.low)); }

inline uint256 plus(const uint256& a, const uint256& b) {
  const uint128 low = a.low + b.low;
  return {a.high + b.high + uint128(low < a.low), low};
}

inline uint256 minus(const uint256& a, const uint256& b) {  // a >= b
  return {a.high - b.high - uint128(a.low < b.low), a.low - b.low};
}

// a + b for magnitudes a, b with signs: the magnitude and its sign (that of
// an exact zero is the caller's to choose)
struct signed_uint256 {
  uint256 magnitude;
  bool negative;
};

inline signed_uint256 signed_sum(const uint256& a, bool a_negative, const uint256& b, bool b_negative) {
  if (a_negative == b_negative) return {plus(a, b), a_negative};
  if (less(a, b)) return {minus(b, a), b_negative};
  return {minus(a, b), a_negative};
}

// the index of the leading bit (-1 for 0), from countl_zero, which is 64 for a zero word
inline int top_bit(uint128 v) {
  const int high_zeros = std::countl_zero(std::uint64_t(v >> 64)), low_zeros = std::countl_zero(std::uint64_t(v));
  return 127 - high_zeros - (low_zeros & -int(high_zeros == 64));
}

inline int top_bit(const uint256& x) {
  const int high = top_bit(x.high), low = top_bit(x.low), high_set = -int(high >= 0);
  return ((128 + high) & high_set) | (low & ~high_set);
}

// An exact integer v, its leading bit at `top` (p <= top <= p + 126), as
// high + rest: high is v rounded to p bits, to nearest, ties to even, and
// rest = |v - high| exactly, both in units of v's bit 0. What TwoSum and
// TwoProd in integers (below) make of an exact sum or product.
struct rounded_parts {
  uint128 significand;  // high's p bits, the leading one at bit p - 1
  int top;              // high's leading bit: v's, one higher where rounding up carried
  uint128 rest;         // |v - high|, below 2^(top + 1 - p)
  int rest_top;         // rest's leading bit (-1 for an exact v)
  bool up;              // high lies beyond v: the rest's sign is the opposite of v's
};

template <int p>
rounded_parts rounded_to_nearest(const uint256& v, int top) {
  const int drop = top + 1 - p;  // bits below high's last one
  uint128 significand = (v.low >> drop) | (v.high << (128 - drop));
  const uint128 below = v.low & ((uint128(1) << drop) - 1), half = uint128(1) << (drop - 1);
  const bool up = (below > half) | ((below == half) & ((significand & 1) != 0));
  significand += uint128(up);
  const uint128 carry = significand >> p;  // 2^p: the next binade's leading one
  significand >>= carry;
  const uint128 rest = up ? (uint128(1) << drop) - below : below;
  return {significand, top + int(carry), rest, top_bit(rest), up};
}

// The rest's significand with its leading one at bit p - 1 (the rest of an
// exact sum or product is a p-bit number: any bits shifted out are zeros).
template <int p>
uint128 rest_significand(const rounded_parts& parts) {
  return parts.rest_top >= p - 1 ? parts.rest >> (parts.rest_top - (p - 1)) : parts.rest << ((p - 1) - parts.rest_top);
}

// TwoSum's pair, a + b rounded to nearest (ties to even) and the exact rest,
// in integer arithmetic, for binary128 (two_sum calls it). With both operands
// normal and x the one whose last bit lies higher, by d bits: for d <= 120
// the exact sum fits a 256-bit frame whose bit 0 is y's last bit (x's 113
// bits shifted by d); it is rounded to 113 bits there, and the rest (below
// 2^121, at most 113 bits wide: TwoSum's error is a binary128 value) is
// packed as it is. For d > 120, |y| < 2^-8 ulp(x), so x + y rounds to x and
// the rest is y. Zeros (the rest +0), other operands, a rest below the
// normal binades and a sum that overflows take Knuth's TwoSum, so every pair
// is the one TwoSum gives, bit for bit. x87 long double keeps TwoSum: its
// additions are instructions.
template <class T>
exact_pair<T> two_sum_in_integers(const T& a, const T& b) {
  using format = emulated_format<T>;
  constexpr int p = format::digits;
  unpacked_binary x, y;
  if (!(format::unpack(a, x) & format::unpack(b, y))) [[unlikely]] {
    using std::isfinite;
    if ((a == 0 || b == 0) && isfinite(a) && isfinite(b)) return {T(a + b), T(0)};
    return knuth_two_sum(a, b);
  }
  const bool swapped = x.exponent < y.exponent;
  if (swapped) std::swap(x, y);
  const int gap = x.exponent - y.exponent;
  if (gap > 120) return swapped ? exact_pair<T>{b, a} : exact_pair<T>{a, b};
  const uint256 x_frame = shifted_left({0, x.significand}, gap), y_frame{0, y.significand};
  const auto [sum, negative] = signed_sum(x_frame, x.negative, y_frame, y.negative);
  if ((sum.high | sum.low) == 0) return {T(0), T(0)};  // an exact cancellation: +0, as a + b
  const int top = top_bit(sum);
  const int drop = top + 1 - p;  // bits below the rounded sum's last one: at most 121
  if (drop <= 0) {  // exact, unless the cancellation leaves the normal binades
    if (y.exponent + top < 1 - wide_bias) [[unlikely]] return knuth_two_sum(a, b);
    return {format::pack(negative, y.exponent + top, sum.low << -drop), T(0)};
  }
  const rounded_parts high = rounded_to_nearest<p>(sum, top);
  const int binade = y.exponent + high.top;
  if ((binade > wide_bias) | ((high.rest != 0) & (y.exponent + high.rest_top < 1 - wide_bias))) [[unlikely]]
    return knuth_two_sum(a, b);
  const T rounded = format::pack(negative, binade, high.significand);
  if (high.rest == 0) return {rounded, T(0)};
  return {rounded, format::pack(negative != high.up, y.exponent + high.rest_top, rest_significand<p>(high))};
}

// a * b = high + low exactly, from one integer product of the significands,
// where the library's multiplication and fma_in_integers would each form it
// (binary128's two_prod). The same pair as a * b and
// fma(a, b, -(a * b)): high is the product rounded to nearest, ties to even,
// and low = ab - high has at most p significant bits, so it is exact wherever
// it is normal. False, and `out` untouched, where an operand is zero,
// subnormal, infinite or NaN, or high or a non-zero low leaves the normal
// binades: the caller then takes the library's product and the fma.
template <class T>
bool two_prod_in_integers(const T& a, const T& b, exact_pair<T>& out) {
  using format = emulated_format<T>;
  constexpr int p = format::digits;
  constexpr int least_binade = 1 - wide_bias, largest_binade = wide_bias;
  unpacked_binary x, y;
  if (!(format::unpack(a, x) & format::unpack(b, y))) [[unlikely]] return false;
  const uint256 product = multiply(x.significand, y.significand, p <= 64);
  const bool negative = x.negative != y.negative;
  const int last = x.exponent + y.exponent;  // the exponent of the product's bit 0
  const rounded_parts high = rounded_to_nearest<p>(product, top_bit(product));  // (its top: 2p - 2 or 2p - 1)
  const int binade = last + high.top;
  if ((binade > largest_binade) | (binade < least_binade) |
      ((high.rest != 0) & (last + high.rest_top < least_binade))) [[unlikely]]
    return false;
  out.high = format::pack(negative, binade, high.significand);
  // an exact product's error is +0, as the fma's exact zero sum is
  out.low = high.rest == 0 ? T(0) : format::pack(negative != high.up, last + high.rest_top, rest_significand<p>(high));
  return true;
}

// a * b + c rounded once in integer arithmetic, for the types of
// emulated_format (emulated_fma, below, calls it).
//
// Zero factors, a zero c, and subnormal, infinite or NaN operands are answered
// first (the library's fma takes the last three). Otherwise the exact product
// P = Ma Mb (2p - 1 or 2p bits, p = 64 or 113) and c's significand are placed
// in a 256-bit frame whose bit 253 holds the larger one's leading bit; the
// smaller one may fall partly below bit 0: it is shifted right with its lost
// bits ORed into its last bit. That is exact for the rounding: the larger one
// (at most 2p <= 226 bits wide) is a multiple of 2^28 in the frame, so
// larger +- smaller lies strictly between the same two consecutive even
// integers whether the smaller is exact or jammed, and no rounding boundary
// (a multiple of the guard bit's weight, 2 or more) lies between them: the
// result's leading bit is at 252 or above whenever bits were lost (the smaller
// then leads at 224 or below), so its guard bit is at 252 - p >= 139. Where no
// bits are lost the sum is exact. The sum is then rounded to p bits, to
// nearest, ties to even. An exact zero sum of non-zero terms is +0, as IEEE's.
// A result from the overflow threshold up is infinite, as IEEE's with its
// unbounded-exponent rounding beyond the largest value; a result below the
// least normal value goes to the library fma, which rounds it once among the
// subnormals.
template <class T>
T fma_in_integers(const T& a, const T& b, const T& c) {
  using format = emulated_format<T>;
  constexpr int p = format::digits;
  constexpr int least_binade = 1 - wide_bias, largest_binade = wide_bias;
  unpacked_binary x, y, z;
  const bool a_normal = format::unpack(a, x), b_normal = format::unpack(b, y), c_normal = format::unpack(c, z);
  if (!(a_normal & b_normal & c_normal)) [[unlikely]] {
    if (a == 0 || b == 0) {
      using std::isfinite;
      if (isfinite(a) && isfinite(b)) return T(a * b) + c;  // an exact zero, then one rounding
    } else if (c == 0 && a_normal && b_normal) {
      return T(a * b);  // a non-zero product, rounded once; its sign survives + c
    }
    using std::fma;
    return fma(a, b, c);
  }
  const uint256 product = multiply(x.significand, y.significand, p <= 64);
  const bool product_negative = x.negative != y.negative;
  const int product_exponent = x.exponent + y.exponent;  // of its last bit
  const int product_width = top_bit(product) + 1;
  const int product_top = product_exponent + product_width - 1, c_top = z.exponent + p - 1;
  const int frame = (product_top > c_top ? product_top : c_top) - 253;  // the exponent of the frame's bit 0
  auto place = [frame](const uint256& v, int exponent) {
    const int shift = exponent - frame;
    return shift >= 0 ? shifted_left(v, shift) : shifted_right_sticky(v, -shift);
  };
  const uint256 p_frame = place(product, product_exponent), c_frame = place({0, z.significand}, z.exponent);
  const auto [sum, negative] = signed_sum(p_frame, product_negative, c_frame, z.negative);
  if ((sum.high | sum.low) == 0) return T(0);  // an exact cancellation: +0
  const int top = top_bit(sum);
  int binade = frame + top;
  if (binade < least_binade) [[unlikely]] {  // subnormal or zero once rounded
    using std::fma;
    return fma(a, b, c);
  }
  // the leading bit to 255: the p bits of the significand, then the guard
  // bit, all in the high half (p <= 113), then the sticky bits
  const uint256 normalized = shifted_left(sum, 255 - top);
  uint128 significand = normalized.high >> (128 - p);
  const uint128 below = normalized.high & ((uint128(1) << (128 - p)) - 1);
  const uint128 half = uint128(1) << (127 - p);
  const bool guard = (below & half) != 0, sticky = ((below & (half - 1)) != 0) | (normalized.low != 0);
  significand += uint128(guard & (sticky | ((significand & 1) != 0)));  // to nearest, ties to even
  const uint128 carry = significand >> p;  // 2^p: the next binade's leading one
  significand >>= carry;
  binade += int(carry);
  if (binade > largest_binade) return negative ? -std::numeric_limits<T>::infinity() : std::numeric_limits<T>::infinity();
  return format::pack(negative, binade, significand);
}

// The neighbour of a finite x above (up) or below it, by one step of its
// magnitude's key; from a zero of either sign, the least subnormal.
template <class T>
T neighbour_by_bits(const T& x, bool up) {
  using format = emulated_format<T>;
  const uint128 key = format::magnitude_key(x);
  if (key == 0) return format::from_magnitude_key(1, !up);
  using std::signbit;
  const bool negative = signbit(x);
  return format::from_magnitude_key(up != negative ? key + 1 : key - 1, negative);
}

// a * b + c rounded once in x87 arithmetic, for factors with binades in
// [-4000, 4000] and |c| below 2^8001, from error-free parts as in Boldo and
// Melquiond's emulation ("Emulation of FMA and correctly rounded sums: proved
// algorithms using rounding to odd", IEEE TC 57(4), 2008), their rounding to
// odd replaced by a tie test. ph + pl = ab exactly (Veltkamp's split by 2^32 +
// 1 and Dekker's product: no split overflows and no partial product underflows
// in that range), th + tl = c + ph exactly (TwoSum), tail + e = tl + pl
// exactly (TwoSum), r = th + tail rounded. Then ab + c = th + tail + e, and
// its nearest is r unless th + tail is a rounding boundary (a midpoint) and e
// != 0, when it is r's neighbour on e's side. Why: if e = 0 that is plain.
// Otherwise tl != 0, so c + ph was inexact and |th| >= |ph| / 2 (Sterbenz:
// else it were exact), hence |tail| <= |tl| + |pl| <= 2 ulp(th) and ulp(tail)
// divides ulp(th) / 4, and so every p-bit number and midpoint near th + tail
// (they lie in th's binade or the one below: multiples of ulp(th) / 4); th +
// tail is a multiple of ulp(tail) too, and |e| <= ulp(tail) / 2, so a boundary
// other than th + tail lies at least ulp(tail) from it, beyond th + tail + e.
// For the tie test, th + tail = r + d exactly (Fast2Sum, exact for |tail| <=
// |th|, which holds where e != 0), and th + tail is a midpoint when d != 0 and
// r + 2d, the neighbour on d's side, lies 2d from r (for |d| below half the
// gap, r + 2d rounds to r or to that neighbour, neither 2d away). No result
// here is subnormal unless c + ph cancelled exactly (then e = 0), and none
// comes near overflow. A zero factor (or a subnormal, infinite or NaN operand)
// is outside the range: fma_in_integers answers it.
[[gnu::always_inline]] inline long double fma_by_exact_parts(long double a, long double b, long double c) {
  const long double product = a * b;
  const long double product_low = dekker_product_error(a, b, product);  // split by 2^32 + 1
  const auto [high, low] = two_sum(c, product);
  const auto [tail, tail_error] = two_sum(low, product_low);
  const auto [nearest, beyond] = ordered_two_sum(high, tail);
  const long double neighbour_step = beyond + beyond;
  if ((nearest + neighbour_step) - nearest == neighbour_step && beyond != 0 && tail_error != 0) [[unlikely]]
    return (tail_error > 0) == (beyond > 0) ? nearest + neighbour_step : nearest;
  return nearest;
}

// a * b + c rounded once, for the types of emulated_format: x87 long double
// from exact parts where its range allows, else in integers.
template <class T>
[[gnu::always_inline]] inline T emulated_fma(const T& a, const T& b, const T& c) {
  if constexpr (std::is_same_v<T, long double>) {
    using format = emulated_format<long double>;
    constexpr unsigned lowest = wide_bias - 4000, factor_span = 8000, c_highest = wide_bias + 8000;
    if ((format::exponent_field(a) - lowest <= factor_span) & (format::exponent_field(b) - lowest <= factor_span) &
        (format::exponent_field(c) <= c_highest)) [[likely]]
      return fma_by_exact_parts(a, b, c);
  }
  return fma_in_integers(a, b, c);
}

}  // namespace contact::detail
