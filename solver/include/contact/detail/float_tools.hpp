// Error-free transformations and ulp steps, generic over the scalar type.
// They find the scalar's own functions through ADL (`using std::fma`), so
// Boost.Multiprecision types (et_off) use theirs.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <boost/math/special_functions/next.hpp>
#include <boost/math/tools/precision.hpp>

namespace contact::detail {

// Significand bits of T; for MPFR at run-time precision, the current default.
template <class T>
int precision_of() {
  return boost::math::tools::digits<T>();
}

// a + b == sum + error exactly, barring overflow (Knuth's TwoSum).
template <class T>
struct exact_pair {
  T high, low;
};

template <class T>
exact_pair<T> two_sum(const T& a, const T& b) {
  T sum = a + b;
  T b_virtual = sum - a;
  T a_virtual = sum - b_virtual;
  return {sum, (a - a_virtual) + (b - b_virtual)};
}

// Whether T's fma rounds once. Boost 1.74's cpp_bin_float computes fma as a
// product and a sum, rounding twice; it gets Dekker's product instead.
template <class T>
struct has_fused_fma : std::true_type {};  // std::fma, fmaq (float128), mpfr_fma
template <unsigned Digits, boost::multiprecision::backends::digit_base_type Base, class Allocator, class Exponent,
          Exponent MinExponent, Exponent MaxExponent, boost::multiprecision::expression_template_option Templates>
struct has_fused_fma<boost::multiprecision::number<
    boost::multiprecision::backends::cpp_bin_float<Digits, Base, Allocator, Exponent, MinExponent, MaxExponent>, Templates>>
    : std::false_type {};

// a * b == product + error exactly, barring overflow and underflow of the error.
template <class T>
exact_pair<T> two_prod(const T& a, const T& b) {
  using std::fma;
  const T product = a * b;
  if constexpr (has_fused_fma<T>::value) {
    return {product, fma(a, b, -product)};
  } else {  // Veltkamp's split and Dekker's product, exact for any radix-2 T
    using std::ldexp;
    const T splitter = ldexp(T(1), (precision_of<T>() + 1) / 2) + 1;
    auto split = [&](const T& x) {
      const T scaled = splitter * x;
      const T high = scaled - (scaled - x);
      return exact_pair<T>{high, x - high};
    };
    const auto [a_high, a_low] = split(a);
    const auto [b_high, b_low] = split(b);
    const T error = ((a_high * b_high - product) + a_high * b_low + a_low * b_high) + a_low * b_low;
    return {product, error};
  }
}

// a * b + c with one rounding where T's fma is fused; otherwise the exact
// product and sum, rounded once at the end but for the low-order parts (within
// an ulp, and exact where a * b + c cancels, which is where it matters).
template <class T>
T fused_multiply_add(const T& a, const T& b, const T& c) {
  if constexpr (has_fused_fma<T>::value) {
    using std::fma;
    return fma(a, b, c);
  } else {
    const auto product = two_prod(a, b);
    const auto sum = two_sum(product.high, c);
    return sum.high + (sum.low + product.low);
  }
}

// Sign (-1, 0, +1) of the exact sum of N numbers, by Shewchuk's grow-expansion:
// the components stay non-overlapping, so the largest non-zero one has the sign
// of the whole. Exact while no partial sum overflows.
template <class T, int N>
int sign_of_exact_sum(const T (&terms)[N]) {
  T expansion[N];
  int length = 0;
  for (int i = 0; i < N; ++i) {
    T carry = terms[i];
    int kept = 0;
    for (int j = 0; j < length; ++j) {
      auto [sum, error] = two_sum(carry, expansion[j]);
      carry = sum;
      if (error != 0) expansion[kept++] = error;
    }
    if (carry != 0) expansion[kept++] = carry;
    length = kept;
  }
  if (length == 0) return 0;
  return expansion[length - 1] > 0 ? 1 : -1;
}

// The neighbours of x; they saturate at +-infinity instead of raising.
template <class T>
T next_up(const T& x) {
  if (x >= (std::numeric_limits<T>::max)()) return std::numeric_limits<T>::infinity();
  return boost::math::float_next(x);
}

template <class T>
T next_down(const T& x) {
  if (x <= -(std::numeric_limits<T>::max)()) return -std::numeric_limits<T>::infinity();
  return boost::math::float_prior(x);
}

}  // namespace contact::detail
