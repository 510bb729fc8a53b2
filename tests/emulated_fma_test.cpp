// The fma emulated for x87 long double (exact parts, and integers outside
// its range) and binary128 (integers), contact/detail/emulated_fma.hpp,
// against MPFR's, rounded once in the same format (its precision, exponent
// range and subnormals): on random operands of every alignment of the product
// and the addend, and on hard ones (cancellation, results among the
// subnormals, overflow, exact zeros and ties); binary128's TwoSum in
// integers against Knuth's and MPFR's; and its exact product in integers
// against its product and MPFR's fma.
#include <mpfr.h>

// MPFR's binary128 conversions, declared with the __float128 that GCC and clang
// both know (mpfr.h declares them with _Float128, which clang 14's C++ lacks)
extern "C" int mpfr_set_float128(mpfr_ptr, __float128, mpfr_rnd_t);
extern "C" __float128 mpfr_get_float128(mpfr_srcptr, mpfr_rnd_t);

#include <bit>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "harness.hpp"

namespace contact::testing {
namespace {

using detail::uint128;

// The format's parts, independently of the code under test: x87's explicit
// leading bit, binary128's hidden one.
template <class T>
struct format;

template <>
struct format<long double> {
  static constexpr int digits = 64;
  // (-1)^negative (fraction bits, leading one included) 2^(binade - 63): field 1..32766, or 0 for subnormals
  static long double make(bool negative, int field, uint128 significand) {
    return std::bit_cast<long double>(uint128(std::uint64_t(significand)) |
                                      (uint128((unsigned(negative) << 15) | unsigned(field)) << 64));
  }
  static void to_mpfr(mpfr_ptr r, long double x) { mpfr_set_ld(r, x, MPFR_RNDN); }
  static long double from_mpfr(mpfr_srcptr r) { return mpfr_get_ld(r, MPFR_RNDN); }
  static uint128 bits(long double x) { return std::bit_cast<uint128>(x) & ((uint128(1) << 80) - 1); }
};

template <>
struct format<float128> {
  static constexpr int digits = 113;
  static float128 make(bool negative, int field, uint128 significand) {
    const uint128 fraction = significand & ((uint128(1) << 112) - 1);
    return float128(std::bit_cast<__float128>((uint128(negative) << 127) | (uint128(field) << 112) | fraction));
  }
  static void to_mpfr(mpfr_ptr r, const float128& x) { mpfr_set_float128(r, x.backend().value(), MPFR_RNDN); }
  static float128 from_mpfr(mpfr_srcptr r) { return float128(mpfr_get_float128(r, MPFR_RNDN)); }
  static uint128 bits(const float128& x) { return std::bit_cast<uint128>(x.backend().value()); }
};

// MPFR's fma rounded to nearest in T's format: precision, exponent range
// (normal binades -16382 .. 16383) and subnormals.
template <class T>
T mpfr_fma_in(const T& a, const T& b, const T& c) {
  constexpr int p = format<T>::digits;
  mpfr_t x, y, z, r;
  mpfr_inits2(p, x, y, z, r, static_cast<mpfr_ptr>(nullptr));
  format<T>::to_mpfr(x, a);
  format<T>::to_mpfr(y, b);
  format<T>::to_mpfr(z, c);
  const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
  mpfr_set_emin(-16380 - p);  // the least subnormal, 2^(-16381 - p) in MPFR's [0.5, 1) convention
  mpfr_set_emax(16384);
  const int inexact = mpfr_fma(r, x, y, z, MPFR_RNDN);
  mpfr_subnormalize(r, inexact, MPFR_RNDN);
  mpfr_set_emin(emin);
  mpfr_set_emax(emax);
  const T result = format<T>::from_mpfr(r);
  mpfr_clears(x, y, z, r, static_cast<mpfr_ptr>(nullptr));
  return result;
}

template <class T>
struct operands {
  T a, b, c;
};

// Draws of T: a random significand in a chosen binade.
template <class T>
struct draws {
  std::mt19937_64 random;
  explicit draws(std::uint64_t seed) : random(seed) {}
  uint128 bits() { return (uint128(random()) << 64) | random(); }
  bool coin() { return (random() & 1) != 0; }
  int in(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random); }
  // a normal number in binade e (-16382 .. 16383), with `width` significant bits
  T normal(int e, int width = format<T>::digits) {
    constexpr int p = format<T>::digits;
    const uint128 lead = uint128(1) << (p - 1);
    uint128 significand = lead | (bits() & (lead - 1));
    if (width < p) significand &= ~((uint128(1) << (p - width)) - 1);
    return format<T>::make(coin(), e + 16383, significand);
  }
  T subnormal() { return format<T>::make(coin(), 0, bits() & ((uint128(1) << (format<T>::digits - 1)) - 1)); }
  // a few neighbours away from a finite x (an infinite one stays)
  T stepped(T x) {
    using std::isinf;
    if (isinf(x)) return x;
    for (int k = in(-3, 3); k > 0 && x < (std::numeric_limits<T>::max)(); --k) x = boost::math::float_next(x);
    for (int k = in(-3, 3); k < 0 && x > -(std::numeric_limits<T>::max)(); ++k) x = boost::math::float_prior(x);
    return x;
  }

  // product and addend of every relative alignment, in the middle of the range
  operands<T> random_operands() {
    const int ea = in(-200, 200), eb = in(-200, 200);
    return {normal(ea), normal(eb), normal(ea + eb + in(-2 * format<T>::digits - 8, 2 * format<T>::digits + 8))};
  }

  // one of the hard kinds, in turn
  operands<T> hard_operands(int kind) {
    constexpr int p = format<T>::digits;
    switch (kind % 11) {
      case 0: {  // cancellation: c within a few ulps of -ab
        const T a = normal(in(-100, 100)), b = normal(in(-100, 100));
        return {a, b, stepped(T(-(a * b)))};
      }
      case 1: {  // exact zero: ab exact (short significands), c = -ab
        const T a = normal(in(-100, 100), p / 2), b = normal(in(-100, 100), p / 2);
        return {a, b, T(-(a * b))};
      }
      case 2: {  // zero operands, signed
        const T zero = coin() ? T(0) : T(-T(0));
        const T other = coin() ? normal(in(-100, 100)) : (coin() ? T(0) : T(-T(0)));
        const T c = coin() ? T(0) : (coin() ? T(-T(0)) : normal(in(-100, 100)));
        return coin() ? operands<T>{zero, other, c} : operands<T>{other, zero, c};
      }
      case 3: {  // results near and among the subnormals, and below the least
        const int e = in(-16382 - p - 4, -16382 + 4);
        const int ea = in(-8000, -100);
        const T a = normal(ea), b = normal(e - ea);
        const int pick = in(0, 3);
        const T c = pick == 0 ? T(0) : pick == 1 ? subnormal() : pick == 2 ? stepped(T(-(a * b))) : normal(in(-16382, -16382 + p));
        return {a, b, c};
      }
      case 4: {  // overflow: products and addends near the largest value
        const int ea = in(8000, 8300);
        const T a = normal(ea), b = normal(in(16380, 16384) - ea);
        const int pick = in(0, 2);
        const T c = pick == 0 ? normal(in(16370, 16383)) : pick == 1 ? stepped(T(-(a * b))) : normal(in(-100, 16383));
        return {a, b, c};
      }
      case 5: {  // ties: ab is half an ulp of c (a power of two times a short odd number), or a quarter
        const int e = in(-1000, 1000);
        const T c = normal(e);
        const T a = format<T>::make(coin(), e - p + in(-1, 0) + 16383, uint128(1) << (p - 1));
        const T b = T(in(1, 3) * 2 - 1) * (coin() ? 1 : -1);
        return {a, b, c};
      }
      case 6: {  // c a power of two, ab just below or above its gaps
        const int e = in(-1000, 1000);
        const T c = format<T>::make(coin(), e + 16383, uint128(1) << (p - 1));
        return {normal(e - p - in(0, 3) - 50), normal(50), c};
      }
      case 7: {  // ab exact or a tie (short significands), c so far below that only its sign counts
        const int ea = in(-100, 100), eb = in(-100, 100);
        return {normal(ea, (p + 2) / 2), normal(eb, p + 2 - (p + 2) / 2), normal(ea + eb - in(200, 400))};
      }
      case 8: {  // ab half an ulp of c plus or minus a full-width sliver
        const int e = in(-1000, 1000);
        const T b = format<T>::make(coin(), 16383 - in(0, 1), (uint128(1) << (p - 1)) | (bits() & ((uint128(1) << in(1, 40)) - 1)));
        return {format<T>::make(coin(), e - p + 16383, uint128(1) << (p - 1)), T(b * (b > 1 ? 1 : 2)), normal(e)};
      }
      case 9: {  // c plus or minus half (or a quarter of) its ulp and a sliver: ab = (1 + 2^-s)(1 - 2^-s) times
                 // that, whose rounding is the midpoint and whose error breaks the tie either way
        const int e = in(-1000, 1000), k = in(-100, 100), s = in(p / 2 + 1, p / 2 + 8);
        const uint128 lead = uint128(1) << (p - 1);
        const T c = coin() ? format<T>::make(coin(), e + 16383, lead) : normal(e);
        const T a = format<T>::make(coin(), k + 16383, lead | (uint128(1) << (p - 1 - s)));
        const T b = format<T>::make(coin(), e - p - in(0, 1) - k - 1 + 16383, (2 * lead - 1) & ~((uint128(1) << (p - s)) - 1));
        return {a, b, c};
      }
      default: {  // exponents over the whole range: every path, the library's fallbacks included
        auto any = [&] {
          const int pick = in(0, 9);
          return pick == 0 ? subnormal() : normal(in(-16382, 16383));
        };
        return {any(), any(), any()};
      }
    }
  }
};

template <class T>
std::string text(const T& x) {
  std::ostringstream out;
  out << std::setprecision(40) << x << " (bits " << std::hex << std::uint64_t(format<T>::bits(x) >> 64) << ":"
      << std::uint64_t(format<T>::bits(x)) << ")";
  return out.str();
}

// how many of the operands' emulated fmas differ from MPFR's, bit for bit
template <class T, class Draw>
long mismatches(long count, Draw draw) {
  long wrong = 0;
  for (long i = 0; i < count; ++i) {
    const operands<T> o = draw(i);
    const T emulated = detail::emulated_fma(o.a, o.b, o.c), expected = mpfr_fma_in(o.a, o.b, o.c);
    using std::isnan;  // NaN is NaN, whatever its payload
    const bool same = (isnan(emulated) && isnan(expected)) || format<T>::bits(emulated) == format<T>::bits(expected);
    if (!same && ++wrong <= 5)
      ADD_FAILURE() << "fma(" << text(o.a) << ", " << text(o.b) << ", " << text(o.c) << ") = " << text(emulated)
                    << ", MPFR: " << text(expected);
  }
  return wrong;
}

// Operands the library's fma answers, or that are answered before the
// integers: zero, subnormal and infinite factors and addends, each way
template <class T>
long mismatches_on_special_operands() {
  const T zero = 0, one = 1, least = (std::numeric_limits<T>::min)(), sub = least / 4, inf = std::numeric_limits<T>::infinity();
  const T three = 3, big = (std::numeric_limits<T>::max)();
  const operands<T> special[] = {{zero, inf, one},  {inf, zero, one},  {sub, three, zero}, {three, sub, zero},
                                 {three, three, zero}, {sub, three, one}, {inf, three, one}, {three, three, inf},
                                 {T(-zero), three, T(-zero)}, {big, big, T(-big)}, {least, least, one}, {sub, sub, zero}};
  std::size_t i = 0;
  return mismatches<T>(long(std::size(special)), [&](long) { return special[i++]; });
}

TEST(EmulatedFma, LongDoubleMatchesMpfrOnSpecialOperands) {
  if (!detail::emulated_format<long double>::available) GTEST_SKIP() << "long double is not x87's";
  EXPECT_EQ(mismatches_on_special_operands<long double>(), 0);
}

TEST(EmulatedFma, Float128MatchesMpfrOnSpecialOperands) { EXPECT_EQ(mismatches_on_special_operands<float128>(), 0); }

TEST(EmulatedFma, LongDoubleMatchesMpfrOnRandomOperands) {
  if (!detail::emulated_format<long double>::available) GTEST_SKIP() << "long double is not x87's";
  draws<long double> d(1);
  EXPECT_EQ(mismatches<long double>(1000000, [&](long) { return d.random_operands(); }), 0);
}

TEST(EmulatedFma, LongDoubleMatchesMpfrOnHardOperands) {
  if (!detail::emulated_format<long double>::available) GTEST_SKIP() << "long double is not x87's";
  draws<long double> d(2);
  EXPECT_EQ(mismatches<long double>(100000, [&](long i) { return d.hard_operands(int(i)); }), 0);
}

// x87 long double takes exact parts inside its range, the integers outside it:
// the integers alone, on the same random operands
TEST(EmulatedFma, LongDoubleInIntegersMatchesMpfrOnRandomOperands) {
  if (!detail::emulated_format<long double>::available) GTEST_SKIP() << "long double is not x87's";
  draws<long double> d(1);
  long wrong = 0;
  for (long i = 0; i < 1000000; ++i) {
    const auto o = d.random_operands();
    wrong += format<long double>::bits(detail::fma_in_integers(o.a, o.b, o.c)) !=
             format<long double>::bits(mpfr_fma_in(o.a, o.b, o.c));
  }
  EXPECT_EQ(wrong, 0);
}

// Where x87's fma is emulated, a product's exact error comes from Dekker's
// product instead (detail::product_error): the same value as MPFR's fma(a, b,
// -ab), on products of every binade the plain window holds and on short
// significands, whose error is zero.
TEST(EmulatedFma, LongDoubleProductErrorByDekkerMatchesMpfr) {
  if (!detail::emulated_format<long double>::available) GTEST_SKIP() << "long double is not x87's";
  static_assert(detail::product_error_by_dekker<long double>);
  draws<long double> d(5);
  long wrong = 0;
  for (long i = 0; i < 1000000; ++i) {
    const int width = i % 10 == 0 ? format<long double>::digits / 2 : format<long double>::digits;
    const long double a = d.normal(d.in(-4000, 4000), width), b = d.normal(d.in(-4000, 4000), width), product = a * b;
    wrong += format<long double>::bits(detail::product_error(a, b, product)) !=
             format<long double>::bits(mpfr_fma_in(a, b, (long double)(-product)));
  }
  EXPECT_EQ(wrong, 0);
}

TEST(EmulatedFma, Float128MatchesMpfrOnRandomOperands) {
  draws<float128> d(3);
  EXPECT_EQ(mismatches<float128>(1000000, [&](long) { return d.random_operands(); }), 0);
}

TEST(EmulatedFma, Float128MatchesMpfrOnHardOperands) {
  draws<float128> d(4);
  EXPECT_EQ(mismatches<float128>(100000, [&](long i) { return d.hard_operands(int(i)); }), 0);
}

// binary128's TwoSum in integers (detail::two_sum_in_integers, which two_sum
// calls for it): the pair Knuth's TwoSum gives, bit for bit (zeros' signs and
// the fallbacks' infinities and NaNs included), whose sum is MPFR's a + b
// rounded once in the format.
template <class Draw>
long two_sum_mismatches(long count, Draw draw) {
  long wrong = 0;
  for (long i = 0; i < count; ++i) {
    const auto [a, b] = draw(i);
    const auto pair = detail::two_sum_in_integers(a, b), knuth = detail::knuth_two_sum(a, b);
    using std::isnan;
    auto same = [](const float128& x, const float128& y) {
      return (isnan(x) && isnan(y)) || format<float128>::bits(x) == format<float128>::bits(y);
    };
    const bool right = same(pair.high, knuth.high) && same(pair.low, knuth.low) &&
                       same(pair.high, mpfr_fma_in(a, float128(1), b));
    if (!right && ++wrong <= 5)
      ADD_FAILURE() << "two_sum(" << text(a) << ", " << text(b) << ") = " << text(pair.high) << " + " << text(pair.low)
                    << ", Knuth's: " << text(knuth.high) << " + " << text(knuth.low);
  }
  return wrong;
}

// operands a binade or two to 130 binades apart (the frame's limit is 120), either sign
TEST(EmulatedTwoSum, Float128IsKnuthsOnRandomOperands) {
  draws<float128> d(5);
  EXPECT_EQ(two_sum_mismatches(1000000,
                               [&](long) {
                                 const int e = d.in(-200, 200);
                                 return std::pair{d.normal(e), d.normal(e + d.in(-130, 130))};
                               }),
            0);
}

// zeros of both signs, infinities and NaN beside each other and beside normal numbers
TEST(EmulatedTwoSum, Float128IsKnuthsOnSpecialOperands) {
  const float128 zero = 0, inf = std::numeric_limits<float128>::infinity();
  const float128 special[] = {zero, float128(-zero), float128(3), (std::numeric_limits<float128>::min)() / 4,
                              inf, float128(-inf), std::numeric_limits<float128>::quiet_NaN()};
  std::vector<std::pair<float128, float128>> pairs;
  for (const auto& a : special)
    for (const auto& b : special) pairs.emplace_back(a, b);
  EXPECT_EQ(two_sum_mismatches(long(pairs.size()), [&](long i) { return pairs[std::size_t(i)]; }), 0);
}

// the fma's hard kinds as sums ab + c: cancellation, exact zeros, signed zeros,
// subnormals, overflow, ties, powers of two, the whole range
TEST(EmulatedTwoSum, Float128IsKnuthsOnHardOperands) {
  draws<float128> d(6);
  EXPECT_EQ(two_sum_mismatches(100000,
                               [&](long i) {
                                 const operands<float128> o = d.hard_operands(int(i));
                                 return std::pair{float128(o.a * o.b), o.c};
                               }),
            0);
}

// binary128's exact product in integers (detail::two_prod_in_integers, which
// two_prod calls for it): the pair a * b and MPFR's fma(a, b,
// -(a * b)), bit for bit, through two_prod and product_error alike; where the
// integers decline (zero, subnormal, infinite or NaN operands, a part outside
// the normal binades), the library's product and the fma answer.
template <class Draw>
long two_prod_mismatches(long count, Draw draw) {
  long wrong = 0;
  for (long i = 0; i < count; ++i) {
    const auto [a, b] = draw(i);
    const float128 product = a * b, error = mpfr_fma_in(a, b, float128(-product));
    const auto pair = detail::two_prod(a, b);
    using std::isnan;
    auto same = [](const float128& x, const float128& y) {
      return (isnan(x) && isnan(y)) || format<float128>::bits(x) == format<float128>::bits(y);
    };
    const bool right =
        same(pair.high, product) && same(pair.low, error) && same(detail::product_error(a, b, product), error);
    if (!right && ++wrong <= 5)
      ADD_FAILURE() << "two_prod(" << text(a) << ", " << text(b) << ") = " << text(pair.high) << " + "
                    << text(pair.low) << ", expected " << text(product) << " + " << text(error);
  }
  return wrong;
}

// factors of every binade the window holds, full and half width (exact products)
TEST(EmulatedTwoProd, Float128IsTheProductAndItsFmaOnRandomOperands) {
  draws<float128> d(7);
  EXPECT_EQ(two_prod_mismatches(1000000,
                                [&](long i) {
                                  const int width = i % 10 == 0 ? format<float128>::digits / 2 : format<float128>::digits;
                                  return std::pair{d.normal(d.in(-4000, 4000), width), d.normal(d.in(-4000, 4000), width)};
                                }),
            0);
}

// the fma's hard kinds' factors: products among and below the subnormals,
// near overflow, ties and short significands, the whole range
TEST(EmulatedTwoProd, Float128IsTheProductAndItsFmaOnHardOperands) {
  draws<float128> d(8);
  EXPECT_EQ(two_prod_mismatches(100000,
                                [&](long i) {
                                  const operands<float128> o = d.hard_operands(int(i));
                                  return std::pair{o.a, o.b};
                                }),
            0);
}

// zeros of both signs, the least normal and a subnormal, the largest, infinities and NaN
TEST(EmulatedTwoProd, Float128IsTheProductAndItsFmaOnSpecialOperands) {
  const float128 zero = 0, inf = std::numeric_limits<float128>::infinity(), least = (std::numeric_limits<float128>::min)();
  const float128 special[] = {zero, float128(-zero), float128(3), least, float128(least / 4), float128(1 + least),
                              (std::numeric_limits<float128>::max)(), inf, float128(-inf),
                              std::numeric_limits<float128>::quiet_NaN()};
  std::vector<std::pair<float128, float128>> pairs;
  for (const auto& a : special)
    for (const auto& b : special) pairs.emplace_back(a, b);
  EXPECT_EQ(two_prod_mismatches(long(pairs.size()), [&](long i) { return pairs[std::size_t(i)]; }), 0);
}

}  // namespace
}  // namespace contact::testing
