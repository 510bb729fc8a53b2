// Error-free transformations, generic over any radix-2 scalar that rounds to
// nearest: a sum (Knuth's TwoSum, Dekker's Fast2Sum) and a product's rounding error (Dekker's
// product on Veltkamp's split), each exact barring overflow and underflow.
// One spelling for every caller: float_tools.hpp's product_error where T's fma
// is slow or not fused, the correctly rounded mode's products, and the x87 fma
// emulation.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

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

// A binary128 class type (Boost's float128): its additions run in software,
// and TwoSum's six of them cost more than the same pair found in integers
// (emulated_fma.hpp, which every header that solves in float128 includes).
template <class T>
inline constexpr bool binary128_class =
    !std::is_floating_point_v<T> && std::numeric_limits<T>::is_iec559 && std::numeric_limits<T>::digits == 113;

template <class T>
exact_pair<T> two_sum_in_integers(const T& a, const T& b);

template <class T>
exact_pair<T> knuth_two_sum(const T& a, const T& b) {
  T sum = a + b;
  T b_virtual = sum - a;
  T a_virtual = sum - b_virtual;
  return {sum, (a - a_virtual) + (b - b_virtual)};
}

// MPFR numbers (Boost's mpfr_float), whose every new number allocates
template <class T>
concept mpfr_number = requires(const T& x) { x.backend().data()->_mpfr_prec; };

// The same pair for MPFR, whose every operation makes a new number:
// Fast2Sum's three operations, the larger magnitude first, told apart by
// signs and comparisons, which make none. Either a zero operand goes to
// TwoSum: a zero error's sign may differ.
template <mpfr_number T>
exact_pair<T> two_sum_by_magnitude(const T& a, const T& b) {
  const int a_sign = a.sign(), b_sign = b.sign();
  if (a_sign == 0 || b_sign == 0) return knuth_two_sum(a, b);
  T sum = a + b;
  // |a| >= |b|: of a common sign, a lies as far from zero; of opposite signs,
  // the sum is zero or has a's sign (rounding keeps a sum's sign)
  const bool a_is_larger = a_sign == b_sign ? (a_sign > 0 ? !(a < b) : !(b < a)) : sum.sign() != b_sign;
  const T& larger = a_is_larger ? a : b;
  const T& smaller = a_is_larger ? b : a;
  // smaller - (sum - larger), the difference rounded into its right operand's
  // storage (MPFR allows it): Boost would subtract from a temporary right
  // operand by negating the reverse difference, a zero's sign flipped
  T error = sum - larger;
  eval_subtract(error.backend(), smaller.backend(), error.backend());
  return {std::move(sum), std::move(error)};
}

template <class T>
exact_pair<T> two_sum(const T& a, const T& b) {
  if constexpr (binary128_class<T>) {
    return two_sum_in_integers(a, b);
  } else if constexpr (mpfr_number<T>) {
    return two_sum_by_magnitude(a, b);
  } else {
    return knuth_two_sum(a, b);
  }
}

// a + b == sum + error exactly, for |a| >= |b| (or a zero), barring overflow
// (Dekker's Fast2Sum: three operations where TwoSum takes six).
template <class T>
exact_pair<T> ordered_two_sum(const T& a, const T& b) {
  T sum = a + b;
  return {sum, b - (sum - a)};
}

// Veltkamp's splitting constant 2^ceil(p/2) + 1: a constant for the hardware
// types, computed once for the other IEEE formats (binary128), and per call
// where the precision is chosen at run time (MPFR).
template <class T>
T veltkamp_splitter() {
  if constexpr (std::is_floating_point_v<T>) {
    return T((1ull << ((std::numeric_limits<T>::digits + 1) / 2)) + 1);
  } else if constexpr (std::numeric_limits<T>::is_iec559) {
    using std::ldexp;
    static const T splitter = ldexp(T(1), (precision_of<T>() + 1) / 2) + 1;
    return splitter;
  } else {
    using std::ldexp;
    return T(ldexp(T(1), (precision_of<T>() + 1) / 2) + 1);
  }
}

// a * b - product exactly, for product = a * b rounded to nearest: each factor
// split into halves of at most p/2 bits, whose partial products are exact.
// The split overflows within 2^-(p/2) of T's largest value.
template <class T>
T dekker_product_error(const T& a, const T& b, const T& product) {
  const T splitter = veltkamp_splitter<T>();
  auto split = [&](const T& x) {
    const T scaled = splitter * x;
    const T high = scaled - (scaled - x);
    return exact_pair<T>{high, x - high};
  };
  const auto [a_high, a_low] = split(a);
  const auto [b_high, b_low] = split(b);
  return ((a_high * b_high - product) + a_high * b_low + a_low * b_high) + a_low * b_low;
}

}  // namespace contact::detail
