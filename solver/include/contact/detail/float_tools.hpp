// Error-free transformations and ulp steps, generic over the scalar type.
// They find the scalar's own functions through ADL (`using std::fma`), so
// Boost.Multiprecision types (et_off) use theirs.
#pragma once

#include <cmath>
#include <limits>

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

// a * b == product + error exactly, barring overflow and underflow of the error.
template <class T>
exact_pair<T> two_prod(const T& a, const T& b) {
  using std::fma;
  T product = a * b;
  return {product, fma(a, b, -product)};
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
