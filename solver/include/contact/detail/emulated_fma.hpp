// a * b + c rounded once (to nearest, ties to even) in integer arithmetic, for
// the formats whose library fma is a software emulation that saves, changes and
// restores the floating-point environment on every call (glibc's fmal for x87
// long double, libquadmath's fmaq for binary128), and costs far more than the
// whole closed form around it. The result is the library's, bit for bit: an fma
// rounded once has one correct answer (tests/emulated_fma_test.cpp holds it to
// MPFR). Every other type keeps its own fma.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <boost/multiprecision/number.hpp>

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
  // whether x is normal (not zero, subnormal, infinite or NaN), and its parts
  static bool unpack(const long double& x, unpacked_binary& out) {
    const uint128 bits = std::bit_cast<uint128>(x);
    const std::uint64_t significand = std::uint64_t(bits);
    const unsigned sign_exponent = unsigned(bits >> 64) & 0xffffu;
    const unsigned field = sign_exponent & 0x7fffu;
    out = {significand, int(field) - wide_bias - 63, (sign_exponent >> 15) != 0};
    return field - 1 < 0x7ffeu && (significand >> 63) != 0;
  }
  // the normal number significand 2^(top - 63), significand in [2^63, 2^64)
  static long double pack(bool negative, int top, uint128 significand) {
    const uint128 sign_exponent = (uint128(negative) << 15) | uint128(top + wide_bias);
    return std::bit_cast<long double>(uint128(std::uint64_t(significand)) | (sign_exponent << 64));
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
  const uint128 carry = low < (middle << 64) ? 1 : 0;
  return {a1 * b1 + (middle >> 64) + carry, low};
}

// x 2^shift, shift in [0, 255], for an x that stays below 2^256
inline uint256 shifted_left(uint256 x, int shift) {
  if (shift >= 128) return {x.low << (shift - 128), 0};
  if (shift == 0) return x;
  return {(x.high << shift) | (x.low >> (128 - shift)), x.low << shift};
}

// x 2^-shift, shift > 0, truncated, with the last bit set if any bit was lost
// (a sticky bit: see emulated_fma)
inline uint256 shifted_right_sticky(uint256 x, int shift) {
  if (shift >= 256) return {0, uint128((x.high | x.low) != 0)};
  uint128 lost;
  uint256 r;
  if (shift >= 128) {
    const int s = shift - 128;
    lost = x.low | (s == 0 ? 0 : (x.high << (128 - s)));
    r = {0, x.high >> s};
  } else {
    lost = x.low << (128 - shift);
    r = {x.high >> shift, (x.low >> shift) | (x.high << (128 - shift))};
  }
  r.low |= uint128(lost != 0);
  return r;
}

inline bool less(const uint256& a, const uint256& b) { return a.high < b.high || (a.high == b.high && a.low < b.low); }

inline uint256 plus(const uint256& a, const uint256& b) {
  const uint128 low = a.low + b.low;
  return {a.high + b.high + uint128(low < a.low), low};
}

inline uint256 minus(const uint256& a, const uint256& b) {  // a >= b
  return {a.high - b.high - uint128(a.low < b.low), a.low - b.low};
}

inline int top_bit(const uint256& x) {  // x != 0
  auto top_of = [](uint128 v) {
    const std::uint64_t high = std::uint64_t(v >> 64);
    return high != 0 ? 127 - std::countl_zero(high) : 63 - std::countl_zero(std::uint64_t(v));
  };
  return x.high != 0 ? 128 + top_of(x.high) : top_of(x.low);
}

// a * b + c rounded once, for the types of emulated_format.
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
T emulated_fma(const T& a, const T& b, const T& c) {
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
  uint256 sum;
  bool negative = product_negative;
  if (product_negative == z.negative) {
    sum = plus(p_frame, c_frame);
  } else if (less(p_frame, c_frame)) {
    sum = minus(c_frame, p_frame);
    negative = z.negative;
  } else {
    sum = minus(p_frame, c_frame);
    if ((sum.high | sum.low) == 0) return T(0);  // an exact cancellation: +0
  }
  const int top = top_bit(sum);
  int binade = frame + top;
  if (binade < least_binade) [[unlikely]] {  // subnormal or zero once rounded
    using std::fma;
    return fma(a, b, c);
  }
  uint128 significand;
  if (top < p) {  // at most p bits: exact
    significand = sum.low << (p - 1 - top);
  } else {
    const int cut = top - p + 1;  // the bits below it are rounded off: the guard bit, then the sticky bits
    significand = cut >= 128 ? sum.high >> (cut - 128) : (sum.low >> cut) | (sum.high << (128 - cut));
    const int guard_position = cut - 1;
    const bool guard = guard_position >= 128 ? ((sum.high >> (guard_position - 128)) & 1) != 0
                                             : ((sum.low >> guard_position) & 1) != 0;
    bool sticky;
    if (guard_position >= 128) {
      const int s = guard_position - 128;
      sticky = sum.low != 0 || (s != 0 && (sum.high << (128 - s)) != 0);
    } else {
      sticky = guard_position != 0 && (sum.low << (128 - guard_position)) != 0;
    }
    if (guard && (sticky || (significand & 1) != 0)) {
      ++significand;
      if (significand >> p) {
        significand >>= 1;
        ++binade;
      }
    }
  }
  if (binade > largest_binade) return negative ? -std::numeric_limits<T>::infinity() : std::numeric_limits<T>::infinity();
  return format::pack(negative, binade, significand);
}

}  // namespace contact::detail
