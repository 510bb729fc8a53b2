// mini_float, the format of the exhaustive test, against exact rounding: every
// sum, difference, product, quotient, fma and square root of its values in
// the binades the exhaustive test uses most and at both ends of the range is
// the exact result rounded to nearest, ties to even, flushed to zero below the
// least normal value (or, with subnormals, rounded to a multiple of the least
// subnormal) and to infinity from the largest value's rounding limit up.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <cmath>
#include <vector>

#include "contact/detail/float_tools.hpp"
#include "contact/stable.hpp"
#include "exhaustive/exact_root.hpp"
#include "exhaustive/mini_float.hpp"

namespace contact::testing {
namespace {

using integer = boost::multiprecision::cpp_int;
using tiny = mini_float<6, -20, 21, true>;
using tiny_ieee = mini_float<6, -20, 21, true, true>;  // with subnormals
constexpr int p = tiny::precision;
static_assert(tiny_ieee::precision == p);

template <class T>
class MiniFloat : public ::testing::Test {};
using formats = ::testing::Types<tiny, tiny_ieee>;
TYPED_TEST_SUITE(MiniFloat, formats);

// Values as integers in units of 2^-scale: exact for every value of the
// format, and for their products in units of 2^-2 scale.
constexpr int scale = 120;

template <class T>
integer exactly(T x) {
  if (x == 0) return 0;
  int e = 0;
  const double m = std::frexp(double(x), &e);
  const integer significand = static_cast<long long>(std::ldexp(m, p));
  const int shift = e - p + scale;
  return shift >= 0 ? integer(significand << shift) : integer(significand >> -shift);
}

// n / (d 2^scale), d > 0, rounded into the format, as integer units of
// 2^-scale (or infinite).
struct rounded {
  bool infinite;
  integer units;
};

template <class T>
rounded round_to_format(const integer& n, const integer& d) {
  if (n == 0) return {false, 0};
  const integer a = abs(n);
  // e with 2^e <= |n| / (d 2^scale) < 2^(e + 1)
  auto at_least = [&](int e) { return e + scale >= 0 ? a >= (d << (e + scale)) : (a << -(e + scale)) >= d; };
  int e = int(msb(a)) - int(msb(d)) - scale;
  while (!at_least(e)) --e;
  while (at_least(e + 1)) ++e;
  // the quotient in units of ulp = 2^(e - p + 1) (below the least normal
  // value, with subnormals, of the least subnormal), to nearest, ties to even
  const bool subnormal = T::subnormals && e < T::least_exponent;
  const int ulp = (subnormal ? T::least_exponent : e) - p + 1 + scale;  // >= 0 for every exponent tested
  const integer units_of_ulp = d << ulp;
  integer q = a / units_of_ulp;
  const integer twice_rest = 2 * (a - q * units_of_ulp);
  if (twice_rest > units_of_ulp || (twice_rest == units_of_ulp && (q & 1) != 0)) ++q;
  if (subnormal) return {false, n < 0 ? integer(-(q << ulp)) : integer(q << ulp)};
  if (q == (integer(1) << p)) ++e;
  if (e > T::greatest_exponent) return {true, 0};
  if (e < T::least_exponent) return {false, 0};
  const integer magnitude = q << ulp;
  return {false, n < 0 ? integer(-magnitude) : magnitude};
}

template <class T>
bool is(T got, const rounded& expected) {
  if (expected.infinite) return std::isinf(double(got));
  return std::isfinite(double(got)) && exactly(got) == expected.units;
}

// Both signs of the binades around 1 and at both ends of the range (the
// subnormals included), and 0.
template <class T = tiny>
std::vector<T> sample() {
  std::vector<T> values{T(0)};
  if (T::subnormals)
    for (int m = 1; m < (1 << (p - 1)); ++m) {
      values.push_back(ldexp(T(m), T::least_exponent - p + 1));
      values.push_back(-values.back());
    }
  for (int e = T::least_exponent; e <= T::greatest_exponent; ++e) {
    if (e > T::least_exponent + 2 && std::abs(e) > 3 && e < T::greatest_exponent - 2) continue;
    for (int m = 1 << (p - 1); m < (1 << p); ++m) {
      values.push_back(ldexp(T(m), e - p + 1));
      values.push_back(-values.back());
    }
  }
  return values;
}

TYPED_TEST(MiniFloat, ArithmeticRoundsTheExactResult) {
  using T = TypeParam;
  const auto values = sample<T>();
  const integer one = integer(1) << scale;
  for (T x : values)
    for (T y : values) {
      const integer a = exactly(x), b = exactly(y);
      ASSERT_TRUE(is(x + y, round_to_format<T>(a + b, 1))) << double(x) << " + " << double(y);
      ASSERT_TRUE(is(x - y, round_to_format<T>(a - b, 1))) << double(x) << " - " << double(y);
      ASSERT_TRUE(is(x * y, round_to_format<T>(a * b, one))) << double(x) << " * " << double(y);
      if (y != 0) {
        ASSERT_TRUE(is(x / y, round_to_format<T>(b > 0 ? integer(a * one) : integer(-a * one), abs(b))))
            << double(x) << " / " << double(y);
      }
    }
}

// Products of [1, 2) x +-[1, 2) plus every sampled c: ties that c breaks, and
// cancellation.
TYPED_TEST(MiniFloat, FmaRoundsOnce) {
  using T = TypeParam;
  const auto values = sample<T>();
  const integer one = integer(1) << scale;
  for (T x : values)
    for (T y : values) {
      if (!(x >= 1 && x < 2 && fabs(y) >= 1 && fabs(y) < 2)) continue;
      for (T c : values)
        ASSERT_TRUE(is(fma(x, y, c), round_to_format<T>(exactly(x) * exactly(y) + exactly(c) * one, one)))
            << double(x) << " * " << double(y) << " + " << double(c);
    }
}

// r is the square root of x rounded to nearest when x lies strictly between
// the squares of the midpoints around r (a square root is never a midpoint).
TYPED_TEST(MiniFloat, SquareRootRoundsTheExactRoot) {
  using T = TypeParam;
  for (T x : sample<T>()) {
    if (!(x > 0)) continue;
    const T r = sqrt(x);
    int e = 0;
    frexp(r, &e);
    const integer root = exactly(r), half_ulp = integer(1) << (e - p - 1 + scale), square = exactly(x) << scale;
    EXPECT_LT((root - half_ulp) * (root - half_ulp), square) << double(x);
    EXPECT_GT((root + half_ulp) * (root + half_ulp), square) << double(x);
  }
}

// Products of values around 1 and small values land in the subnormal range;
// the sample's own products do not reach every rounding there.
TEST(MiniFloat, FmaRoundsOnceIntoSubnormals) {
  const integer one = integer(1) << scale;
  const auto values = sample<tiny_ieee>();
  for (tiny_ieee x : values)
    for (tiny_ieee y : values) {
      if (!(fabs(x) >= 1 && fabs(x) < 2 && fabs(y) < 4 * (std::numeric_limits<tiny_ieee>::min)())) continue;
      for (tiny_ieee c : values) {
        if (!(fabs(c) < 4 * (std::numeric_limits<tiny_ieee>::min)())) continue;
        ASSERT_TRUE(is(fma(x, y, c), round_to_format<tiny_ieee>(exactly(x) * exactly(y) + exactly(c) * one, one)))
            << double(x) << " * " << double(y) << " + " << double(c);
      }
    }
}

TEST(MiniFloat, GradualUnderflow) {
  using limits = std::numeric_limits<tiny_ieee>;
  static_assert(limits::is_iec559 && limits::has_denorm == std::denorm_present);
  static_assert(!std::numeric_limits<tiny>::is_iec559);
  const tiny_ieee least = (limits::min)(), least_subnormal = limits::denorm_min();
  EXPECT_EQ(double(least_subnormal), std::ldexp(1.0, -25));
  EXPECT_EQ(double(least / 2), std::ldexp(1.0, -21));
  EXPECT_EQ(least_subnormal / 2, 0);                          // a tie, to the even 0
  EXPECT_TRUE(std::signbit(double(-least_subnormal / 2)));
  EXPECT_EQ(least_subnormal * tiny_ieee(0.75), least_subnormal);
  EXPECT_EQ(least_subnormal * 3 / 2, 2 * least_subnormal);    // a tie, to the even 2
  EXPECT_EQ(least_subnormal * 5 / 2, 2 * least_subnormal);    // likewise
  EXPECT_EQ(least - least_subnormal + least_subnormal, least);
  EXPECT_EQ(double(least - least_subnormal), std::ldexp(31.0, -25));  // 5 bits below the least normal value
  EXPECT_EQ(ldexp(tiny_ieee(33), -26), ldexp(tiny_ieee(16), -25));    // 16.5 least subnormals, a tie to 16
  EXPECT_EQ(ldexp(tiny_ieee(1), -100000), 0);
}

TEST(MiniFloat, RangeEndsFlushAndOverflow) {
  const tiny least = (std::numeric_limits<tiny>::min)(), largest = (std::numeric_limits<tiny>::max)();
  EXPECT_EQ(double(least), std::ldexp(1.0, -20));
  EXPECT_EQ(double(largest), std::ldexp(2 - std::ldexp(1.0, 1 - p), 21));
  EXPECT_EQ(least / 2, 0);
  EXPECT_TRUE(std::signbit(double(-least / 2)));
  const tiny just_above = ldexp(tiny(33), -25);     // 33/32 least
  EXPECT_EQ(just_above * tiny(0.96875), least);     // (1 - 2^-10) least rounds up to the least normal value
  EXPECT_EQ(just_above * tiny(0.9375), 0);          // (1 - 2^-5 - 2^-6) least rounds below it: flushed
  EXPECT_TRUE(std::isinf(double(largest * 2)));
  EXPECT_TRUE(std::isinf(double(largest + ldexp(tiny(1), 21 - p))));     // half an ulp above rounds to 2^22
  EXPECT_EQ(largest + ldexp(tiny(1), 20 - p), largest);                   // a quarter ulp above does not
  EXPECT_EQ(ldexp(tiny(1), 100000), std::numeric_limits<tiny>::infinity());
  EXPECT_EQ(ldexp(tiny(1), -100000), 0);
  int e = 0;
  EXPECT_EQ(frexp(tiny(-3), &e), tiny(-0.75));
  EXPECT_EQ(e, 2);
}

// The solver's neighbours (float_tools.hpp) in a format narrower than float.
TEST(MiniFloat, NeighboursStepOneValueAmongSubnormals) {
  const tiny_ieee least_subnormal = std::numeric_limits<tiny_ieee>::denorm_min(), least = (std::numeric_limits<tiny_ieee>::min)();
  EXPECT_EQ(detail::next_up(tiny_ieee(0)), least_subnormal);
  EXPECT_EQ(detail::next_down(tiny_ieee(0)), -least_subnormal);
  EXPECT_EQ(detail::next_up(-least_subnormal), 0);
  EXPECT_EQ(detail::next_down(least), least - least_subnormal);
  EXPECT_EQ(detail::next_up(least), least + least_subnormal);
  EXPECT_EQ(detail::next_down(2 * least), 2 * least - least_subnormal);
  EXPECT_EQ(detail::next_up(2 * least), 2 * least + 2 * least_subnormal);
  for (tiny_ieee x : sample<tiny_ieee>()) {
    if (!(fabs(x) < (std::numeric_limits<tiny_ieee>::max)())) continue;
    const tiny_ieee above = detail::next_up(x);
    EXPECT_GT(above, x);
    EXPECT_EQ(detail::next_down(above), x) << double(x);
    // nothing lies between: the midpoint rounds to one of them
    const tiny_ieee middle(0.5 * (double(x) + double(above)));
    EXPECT_TRUE(middle == x || middle == above) << double(x);
  }
}

TEST(MiniFloat, NeighboursStepOneValue) {
  const tiny eps = std::numeric_limits<tiny>::epsilon(), least = (std::numeric_limits<tiny>::min)();
  EXPECT_EQ(detail::next_up(tiny(1)), 1 + eps);
  EXPECT_EQ(detail::next_down(tiny(1)), 1 - eps / 2);
  EXPECT_EQ(detail::next_up(tiny(-1)), -1 + eps / 2);
  EXPECT_EQ(detail::next_down(tiny(-1)), -1 - eps);
  EXPECT_EQ(detail::next_up(tiny(0)), least);
  EXPECT_EQ(detail::next_down(tiny(0)), -least);
  EXPECT_EQ(detail::next_up(-least), 0);
  EXPECT_EQ(detail::next_up((std::numeric_limits<tiny>::max)()), std::numeric_limits<tiny>::infinity());
  // every value of the sample and its neighbours, both ways
  for (tiny x : sample()) {
    if (!(fabs(x) < (std::numeric_limits<tiny>::max)())) continue;
    const tiny above = detail::next_up(x);
    EXPECT_GT(above, x);
    EXPECT_EQ(detail::next_down(above), x) << double(x);
  }
}

}  // namespace
}  // namespace contact::testing

// ---- exact_root.hpp, the exhaustive test's other foundation ---------------------

namespace contact::testing {
namespace {

using format = exact::format_of<tiny>;
using exact_input = exact::input<exact::wide>;

template <class T>
exact_input exact_of(T u, T dy, T phi) { return {double(u), double(dy), double(phi)}; }

// Triples of the sample with the four cases and roots of every size.
template <class T = tiny, class Check>
void for_sampled_triples(Check check) {
  const auto values = sample<T>();
  for (std::size_t i = 0; i < values.size(); i += 13)
    for (std::size_t j = 0; j < values.size(); j += 7)
      for (std::size_t k = 0; k < values.size(); k += 9)
        if (!(values[k] < 0)) check(values[i], values[j], values[k]);
}

// Where the root is known in closed form: s* = -u in the free case. A u
// that is not a power of two nor the largest value has -u one ulp of s* from
// its upper neighbour.
TEST(ExactRoot, FreeRootIsMinusU) {
  long checked = 0;
  for_sampled_triples([&](tiny u, tiny dy, tiny phi) {
    const auto x = exact_of(u, dy, phi);
    if (x.exact_case() != contact_case::free) return;
    ++checked;
    ASSERT_EQ(x.residual_sign(exact::exactly<exact::wide>(double(-u))), 0) << double(u) << " " << double(dy);
    ASSERT_TRUE(format::is_rounded_root(x, -u));
    ASSERT_TRUE(format::within(x, -u, 0, 0));
    int e = 0;
    const bool power_of_two = fabs(frexp(u, &e)) == tiny(0.5);
    if (u == 0 || power_of_two || fabs(u) == (std::numeric_limits<tiny>::max)()) return;
    const tiny above = detail::next_up(tiny(-u));
    ASSERT_FALSE(format::is_rounded_root(x, above));
    ASSERT_FALSE(format::within(x, above, (1 << 16) - 1, 16));  // just under one ulp
    ASSERT_TRUE(format::within(x, above, 1 << 16, 16));         // one ulp
  });
  EXPECT_GT(checked, 10000);
}

// The binade of s* agrees with a close approximation (solve_stable in long
// double) wherever that lies clear of a power of two.
TEST(ExactRoot, BinadeOfTheRoot) {
  long checked = 0;
  for_sampled_triples([&](tiny u, tiny dy, tiny phi) {
    const auto x = exact_of(u, dy, phi);
    const long double root = solve_stable<long double>(double(u), double(dy), double(phi)).s;
    if (root == 0 || !std::isfinite(root)) return;
    int e = 0;
    const long double m = std::fabs(std::frexp(root, &e));
    if (m < 0.5L + 1e-12L || m > 1 - 1e-12L) return;
    ++checked;
    ASSERT_EQ(x.root_sign(), root > 0 ? 1 : -1);
    const int expected = std::max(e - 1, tiny::least_exponent - 1);
    ASSERT_EQ(format::binade_of_root(x, 0), expected) << double(u) << " " << double(dy) << " " << double(phi);
    ASSERT_EQ(format::binade_of_root(x, tiny::greatest_exponent), expected);
  });
  EXPECT_GT(checked, 100000);
}

template <class T>
class ExactRootOf : public ::testing::Test {};
TYPED_TEST_SUITE(ExactRootOf, formats);

// Exactly one value near the root (infinity included) is the root rounded
// as the format rounds, and it lies within half an ulp of it (0 within one).
TYPED_TEST(ExactRootOf, OneValueIsTheRoundedRoot) {
  using T = TypeParam;
  using format = exact::format_of<T>;
  long checked = 0;
  for_sampled_triples<T>([&](T u, T dy, T phi) {
    const auto x = exact_of(u, dy, phi);
    const T near = solve_stable(u, dy, phi).s;
    if (!isfinite(near)) return;
    // near and 12 values either side, infinity included
    std::vector<T> candidates{near}, rounded_roots;
    for (T s = near; candidates.size() < 13 && isfinite(s);) candidates.push_back(s = detail::next_down(s));
    for (T s = near; candidates.size() < 26 && isfinite(s);) candidates.push_back(s = detail::next_up(s));
    for (T s : candidates)
      if (format::is_rounded_root(x, s)) rounded_roots.push_back(s);
    ++checked;
    ASSERT_EQ(rounded_roots.size(), 1u) << double(u) << " " << double(dy) << " " << double(phi);
    // without subnormals 0 takes roots up to nearly the least normal value, one ulp below it
    const long half_ulp = 1 << 15, ulp = 1 << 16;
    const bool flushed = rounded_roots[0] == 0 && !T::subnormals;
    if (isfinite(rounded_roots[0])) ASSERT_TRUE(format::within(x, rounded_roots[0], flushed ? ulp : half_ulp, 16));
  });
  EXPECT_GT(checked, 100000);
}
}  // namespace
}  // namespace contact::testing
