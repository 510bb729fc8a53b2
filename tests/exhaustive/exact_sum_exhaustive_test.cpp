// An exhaustive check of the error-free transformations the case decision
// rests on (contact/detail/float_tools.hpp): two_sum, two_prod and
// sign_of_exact_sum, Shewchuk's grow-expansion. Their correctness does not
// depend on the format (any binary format rounding to nearest, ties to even,
// with gradual underflow, barring overflow), so every input of a few
// miniature formats stands for the property; bit-precise SMT on binary32 and
// binary64 does not finish (proofs/README.md). The oracle is double
// arithmetic, exact here: every value of these formats, every sum of four and
// every product of two is a double.
//
// Checked, each as its own property:
//
//   - two_sum(a, b) on every pair of two formats with subnormals: high is a + b
//     rounded once, and high + low is a + b exactly, wherever both operands lie
//     below the top two binades (so that no intermediate can overflow; the
//     pairs beyond are counted, and how many of them overflowed);
//   - two_prod(a, b) on every pair of the 8-bit format, with its fused fma and
//     with Dekker's product (the solver's path for a type whose fma rounds
//     twice): high is a b rounded once and high + low is a b exactly, wherever
//     a b lies below the top two binades and is a multiple of the least
//     subnormal (its low part is then representable), and for Dekker's both
//     operands lie below the largest value over 2^ceil(p/2) + 1 (the split);
//   - sign_of_exact_sum on every triple of a 5-bit format and on every
//     quadruple of a 3-bit one (the case decision sums four terms): the sign
//     of the exact sum, for terms below the top three binades.
//
// Prints "exact sums exhaustive: N inputs checked, F failures", the counts per
// property and the first failures, and exits non-zero when F > 0.
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "contact/detail/float_tools.hpp"
#include "mini_float.hpp"

namespace contact::testing {
namespace {

// 8 bits, normal binades 2^-14 .. 2^15, subnormals down to 2^-21: binary16's
// exponent range with a shorter significand, 7,937 finite values.
using eight_bits = mini_float<8, -14, 15, true, true>;
using eight_bits_dekker = mini_float<8, -14, 15, false, true>;
using five_bits = mini_float<5, -6, 7, true, true>;
using three_bits = mini_float<3, -5, 5, true, true>;

struct tally {
  long long checked = 0, failures = 0;
  void fail(const char* property, double a, double b, double high, double low) {
    if (failures++ < 5) std::printf("  FAIL %s: a = %a, b = %a: high %a, low %a\n", property, a, b, high, low);
  }
};

// Every finite value of T below 2^top_binade in magnitude (0 once), as doubles.
template <class T>
std::vector<double> values_of(int top_binade) {
  const double least_subnormal = std::ldexp(1.0, T::least_exponent - T::precision + 1);
  std::vector<double> values{0.0};
  for (double x = least_subnormal; x < std::ldexp(1.0, top_binade); x += least_subnormal * std::ldexp(1.0, std::max(0, std::ilogb(x) - T::least_exponent))) {
    values.push_back(x);
    values.push_back(-x);
  }
  return values;
}

template <class T>
void check_two_sum(tally& t, const char* name) {
  const std::vector<double> all = values_of<T>(T::greatest_exponent + 1);
  const double beyond = std::ldexp(1.0, T::greatest_exponent - 1);
  long long near_overflow = 0, overflowed = 0;
  for (double a : all)
    for (double b : all) {
      const auto [high, low] = detail::two_sum(T(a), T(b));
      const double h = static_cast<double>(high), l = static_cast<double>(low);
      if (std::fabs(a) >= beyond || std::fabs(b) >= beyond) {
        ++near_overflow;
        overflowed += !std::isfinite(h) || !std::isfinite(l);
        continue;
      }
      ++t.checked;
      if (h != static_cast<double>(T(a + b)) || h + l != a + b) t.fail(name, a, b, h, l);
    }
  std::printf("  %s: %zu values, %lld pairs checked; %lld with an operand in the top two binades, of which %lld overflowed\n",
              name, all.size(), (long long)(all.size() * all.size()) - near_overflow, near_overflow, overflowed);
}

template <class T>
void check_two_prod(tally& t, const char* name) {
  const std::vector<double> all = values_of<T>(T::greatest_exponent + 1);
  const double beyond = std::ldexp(1.0, T::greatest_exponent - 1);
  const double least_subnormal = std::ldexp(1.0, T::least_exponent - T::precision + 1);
  // Dekker's split multiplies an operand by 2^ceil(p/2) + 1, which must not overflow
  const double split_limit = detail::has_fused_fma<T>::value
                                 ? std::numeric_limits<double>::infinity()
                                 : std::ldexp(1.0, T::greatest_exponent - (T::precision + 1) / 2);
  long long counted = 0;
  for (double a : all)
    for (double b : all) {
      const double product = a * b;  // exact: 16 significant bits
      if (std::fabs(product) >= beyond || std::fmod(product, least_subnormal) != 0) continue;
      if (std::fabs(a) >= split_limit || std::fabs(b) >= split_limit) continue;
      ++counted;
      const auto [high, low] = detail::two_prod(T(a), T(b));
      const double h = static_cast<double>(high), l = static_cast<double>(low);
      if (h != static_cast<double>(T(product)) || h + l != product) t.fail(name, a, b, h, l);
    }
  t.checked += counted;
  std::printf("  %s: %lld pairs checked (product in range and a multiple of the least subnormal, operands below the split's limit)\n",
              name, counted);
}

// The check can fail: Fast2Sum (high = a + b, low = b - (high - a)) is exact
// only for |a| >= |b|; taken for any order, it must fail on some pair.
template <class T>
void check_that_fast_two_sum_needs_its_order(tally& t) {
  const std::vector<double> all = values_of<T>(T::greatest_exponent - 1);
  long long inexact = 0;
  for (double a : all)
    for (double b : all) {
      const T high = T(a) + T(b);
      const T low = T(b) - (high - T(a));
      inexact += static_cast<double>(high) + static_cast<double>(low) != a + b;
    }
  std::printf("  Fast2Sum without its order |a| >= |b|: inexact on %lld of %zu pairs (must be some)\n", inexact,
              all.size() * all.size());
  if (inexact == 0) t.fail("Fast2Sum without its order is never caught", 0, 0, 0, 0);
}

int exact_sign(double x) { return (x > 0) - (x < 0); }

template <class T, int N>
void check_sign_of_exact_sum(tally& t, const char* name) {
  const std::vector<double> terms = values_of<T>(T::greatest_exponent - 2);
  long long counted = 0;
  int index[N] = {};
  for (;;) {
    T x[N];
    double sum = 0;  // exact: at most 4 terms of a few binades
    for (int i = 0; i < N; ++i) {
      x[i] = T(terms[index[i]]);
      sum += terms[index[i]];
    }
    ++counted;
    if (detail::sign_of_exact_sum(x) != exact_sign(sum))
      t.fail(name, terms[index[0]], terms[index[1]], sum, double(detail::sign_of_exact_sum(x)));
    int i = 0;
    while (i < N && ++index[i] == int(terms.size())) index[i++] = 0;
    if (i == N) break;
  }
  t.checked += counted;
  std::printf("  %s: %zu values, %lld %d-tuples checked\n", name, terms.size(), counted, N);
}

}  // namespace
}  // namespace contact::testing

int main() {
  using namespace contact::testing;
  tally t;
  check_two_sum<eight_bits>(t, "two_sum, 8 bits");
  check_two_sum<five_bits>(t, "two_sum, 5 bits");
  check_that_fast_two_sum_needs_its_order<five_bits>(t);
  check_two_prod<eight_bits>(t, "two_prod, 8 bits, fused fma");
  check_two_prod<eight_bits_dekker>(t, "two_prod, 8 bits, Dekker");
  check_sign_of_exact_sum<five_bits, 3>(t, "sign_of_exact_sum, 5 bits");
  check_sign_of_exact_sum<three_bits, 4>(t, "sign_of_exact_sum, 3 bits");
  std::printf("exact sums exhaustive: %lld inputs checked, %lld failures\n", t.checked, t.failures);
  return t.failures == 0 ? 0 : 1;
}
