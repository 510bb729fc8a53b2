// The stable path's arithmetic helpers on their own: ulp steps that saturate,
// and scaled<T>, whose every operation must round exactly as T does while its
// exponent never overflows or underflows.
#include <random>

#include "contact/detail/scaled.hpp"
#include "exhaustive/mini_float.hpp"
#include "harness.hpp"

namespace contact::testing {
namespace {

using detail::scaled;
constexpr double largest = std::numeric_limits<double>::max();
constexpr double inf = std::numeric_limits<double>::infinity();

template <class T>
void expect_neighbours_saturate() {
  const T big = (std::numeric_limits<T>::max)(), eps = std::numeric_limits<T>::epsilon();
  EXPECT_EQ(detail::next_up(T(1)), T(1) + eps);
  EXPECT_EQ(detail::next_down(T(1)), T(1) - eps / 2);
  EXPECT_EQ(detail::next_up(big), std::numeric_limits<T>::infinity());
  EXPECT_EQ(detail::next_down(T(-big)), -std::numeric_limits<T>::infinity());
}

TEST(Neighbours, StepOneUlpAndSaturateAtTheEndsOfTheRangeInFloat) { expect_neighbours_saturate<float>(); }

TEST(Neighbours, StepOneUlpAndSaturateAtTheEndsOfTheRangeInDouble) { expect_neighbours_saturate<double>(); }

// float and double step their bit patterns; Boost's float_next and float_prior
// are the specification, on zeros, subnormals, binade edges and random values.
template <class T>
void expect_neighbours_as_boost(std::uint64_t seed) {
  const T big = (std::numeric_limits<T>::max)(), tiny = std::numeric_limits<T>::denorm_min();
  const T edges[] = {T(0), T(-0.0), tiny, -tiny, (std::numeric_limits<T>::min)(), T(-(std::numeric_limits<T>::min)()),
                     T(1), T(-1), T(0.5), big, -big, -std::numeric_limits<T>::infinity()};
  auto expect_as_boost = [&](T x) {
    if (x < big) EXPECT_EQ(detail::next_up(x), boost::math::float_next(x)) << x;
    if (x > -big) EXPECT_EQ(detail::next_down(x), boost::math::float_prior(x)) << x;
  };
  for (T x : edges) expect_as_boost(x);
  harness::seeded_source source(seed);
  for (int i = 0; i < 100000; ++i) expect_as_boost(harness::any_finite<T>(source));
}

TEST(Neighbours, StepAsBoostDoesInDoubleAndFloat) {
  expect_neighbours_as_boost<double>(3);
  expect_neighbours_as_boost<float>(4);
}

// x87 long double and binary128 step their bits too (detail/emulated_fma.hpp)
TEST(Neighbours, StepAsBoostDoesInLongDoubleAndFloat128) {
  expect_neighbours_as_boost<long double>(5);
  expect_neighbours_as_boost<float128>(6);
}

// ulp_steps moves by k representable values, through zero, and stops at the
// largest finite value: a finite input stays finite.
template <class T>
void expect_ulp_steps_count_and_saturate() {
  const T big = (std::numeric_limits<T>::max)(), tiny = std::numeric_limits<T>::denorm_min();
  EXPECT_EQ(detail::ulp_steps(T(1), 3), detail::next_up(detail::next_up(detail::next_up(T(1)))));
  EXPECT_EQ(detail::ulp_steps(T(1), -1), detail::next_down(T(1)));
  EXPECT_EQ(detail::ulp_steps(T(0), 2), T(2 * tiny));
  EXPECT_EQ(detail::ulp_steps(tiny, -2), T(-tiny));
  EXPECT_EQ(detail::ulp_steps(detail::next_down(big), 5), big);
  EXPECT_EQ(detail::ulp_steps(T(-detail::next_down(big)), -5), -big);
}

TEST(Neighbours, UlpStepsCountAndSaturateInDouble) { expect_ulp_steps_count_and_saturate<double>(); }
TEST(Neighbours, UlpStepsCountAndSaturateInFloat) { expect_ulp_steps_count_and_saturate<float>(); }
TEST(Neighbours, UlpStepsCountAndSaturateInFloat128) { expect_ulp_steps_count_and_saturate<float128>(); }

// boost::math::float_next compares T with float literals, which does not
// compile for a type narrower than float: next_up steps the significand.
TEST(Neighbours, StepOneUlpInACppBinFloatNarrowerThanFloat) {
  using seven_bits = boost::multiprecision::number<
      boost::multiprecision::cpp_bin_float<7, boost::multiprecision::digit_base_2, void, std::int16_t, -60, 60>,
      boost::multiprecision::et_off>;
  expect_neighbours_saturate<seven_bits>();
  const seven_bits eps = std::numeric_limits<seven_bits>::epsilon(), least = (std::numeric_limits<seven_bits>::min)();
  EXPECT_EQ(detail::next_up(seven_bits(-2)), -2 + eps);  // into the binade below, half as wide
  EXPECT_EQ(detail::next_down(seven_bits(-1)), -1 - eps);
  EXPECT_EQ(detail::next_up(seven_bits(0)), least);   // no subnormals: the least normal value is next to 0
  EXPECT_EQ(detail::next_down(seven_bits(0)), -least);
  EXPECT_EQ(detail::next_up(-least), 0);
}

// Doubles whose products, quotients and sums of two or three stay normal.
rc::Gen<double> moderate() {
  return generator([](auto& source) { return harness::random_sign(source, harness::log_uniform<double>(source, -300, 300)); });
}

bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

TEST(Scaled, OperationsRoundAsDoubleDoesInTheNormalRange) {
  EXPECT_TRUE(rc::check("scaled +, -, *, /, fma and sqrt equal double's", [] {
    const double a = *moderate(), b = *moderate(), c = *moderate();
    const scaled<double> sa(a), sb(b), sc(c);
    RC_ASSERT(same((sa + sb).value(), a + b));
    RC_ASSERT(same((sa - sb).value(), a - b));
    RC_ASSERT(same((sa * sb).value(), a * b));
    RC_ASSERT(same((sa / sb).value(), a / b));
    RC_ASSERT(same(fused_multiply_add(sa, sb, sc).value(), std::fma(a, b, c)));
    RC_ASSERT(same(square_root(sa * sa).value(), std::fabs(a)));
    RC_ASSERT(same(square_root(scaled<double>(std::fabs(a))).value(), std::sqrt(std::fabs(a))));
    RC_ASSERT((sa > sb) == (a > b));
  }));
}

TEST(Scaled, IntermediatesBeyondDoublesRangeDoNotOverflowOrUnderflow) {
  const scaled<double> big(largest), tiny(0x1p-1074);
  EXPECT_EQ((big * big / big).value(), largest);
  EXPECT_EQ((tiny * tiny / tiny).value(), 0x1p-1074);
  EXPECT_EQ(square_root(big * big).value(), largest);
  // the rounding error of DBL_MAX^2, about 2^1942: the same as in double, 2^2048 lower
  const double m = std::ldexp(largest, -1024);
  const scaled<double> down = scaled<double>::normalized(0.5, -2047);  // 2^-2048
  EXPECT_EQ((fused_multiply_add(big, big, -(big * big)) * down).value(), std::fma(m, m, -(m * m)));
  EXPECT_NE(std::fma(m, m, -(m * m)), 0.0);
  EXPECT_EQ((big * big).value(), inf);  // only the final conversion saturates
  EXPECT_EQ((tiny * tiny).value(), 0.0);
}

// Special values, for double and for a software type (whose comparisons the
// compiler cannot fold into double's).
template <class T>
void expect_zero_operands_exact() {
  const scaled<T> zero(T(0)), x(T(3));
  EXPECT_EQ((zero + x).value(), T(3));
  EXPECT_EQ((x + zero).value(), T(3));
  EXPECT_EQ(fused_multiply_add(zero, x, x).value(), T(3));
  EXPECT_EQ(fused_multiply_add(x, zero, x).value(), T(3));
  EXPECT_EQ(fused_multiply_add(x, x, zero).value(), T(9));
  EXPECT_EQ(square_root(zero).value(), T(0));
  EXPECT_EQ(zero.sign(), 0);
}

TEST(Scaled, ZeroOperandsAreExactInDouble) { expect_zero_operands_exact<double>(); }

TEST(Scaled, ZeroOperandsAreExactInFloat128) { expect_zero_operands_exact<float128>(); }

template <class T>
void expect_non_finite_values_propagate() {
  using std::isnan;
  const T infinity = std::numeric_limits<T>::infinity();
  EXPECT_EQ(scaled<T>(infinity).value(), infinity);
  EXPECT_EQ(scaled<T>(T(-infinity)).value(), -infinity);
  EXPECT_TRUE(isnan(scaled<T>(std::numeric_limits<T>::quiet_NaN()).value()));
  EXPECT_TRUE(isnan(square_root(scaled<T>(T(-1))).value()));
}

TEST(Scaled, NonFiniteValuesAndNegativeRootsPropagateInDouble) { expect_non_finite_values_propagate<double>(); }

TEST(Scaled, NonFiniteValuesAndNegativeRootsPropagateInFloat128) { expect_non_finite_values_propagate<float128>(); }

TEST(Scaled, FmaWithTheAddendAboveTheProductRoundsOnce) {
  // 1 + 2^-60 * (1 + 2^-52): the product sits far below the addend
  const scaled<double> a(0x1p-60), b(1 + 0x1p-52), c(1.0);
  EXPECT_EQ(fused_multiply_add(a, b, c).value(), std::fma(0x1p-60, 1 + 0x1p-52, 1.0));
  const scaled<double> d(0x1.8p-53);  // above half an ulp of 1: rounds up once
  EXPECT_EQ(fused_multiply_add(d, scaled<double>(1.0), c).value(), 1 + 0x1p-52);
}

TEST(Scaled, ShiftsBeyondIntSaturateToInfinityOrZero) {
  EXPECT_EQ(scaled<double>::shifted(0.5, std::numeric_limits<long>::max()), inf);
  EXPECT_EQ(scaled<double>::shifted(-0.5, std::numeric_limits<long>::max()), -inf);
  EXPECT_EQ(scaled<double>::shifted(0.5, std::numeric_limits<long>::min()), 0.0);
  EXPECT_EQ(scaled<double>::shifted(0.5, 3), 4.0);
  // a subnormal x moves as the integer of its bits, with the shift clamped first
  const double least = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(scaled<double>::shifted(least, std::numeric_limits<long>::max()), inf);
  EXPECT_EQ(scaled<double>::shifted(-least, std::numeric_limits<long>::min()), -0.0);
  EXPECT_TRUE(std::signbit(scaled<double>::shifted(-least, std::numeric_limits<long>::min())));
  EXPECT_EQ(scaled<double>::shifted(least, 1074), 1.0);
}

// A subnormal moves as the integer of its bits times 2^-1074 (2^-149 in
// float), not through frexp and ldexp, which are slow there: the same values.
template <class T>
void expect_subnormals_move_as_ldexp_does() {
  const T least = std::numeric_limits<T>::denorm_min(), least_normal = std::numeric_limits<T>::min();
  const int digits = std::numeric_limits<T>::digits;
  long checked = 0;
  for (T x = least; x < least_normal; x = x * 2 + least * T(checked % 5)) {  // every subnormal binade, varied bits
    for (const T signed_x : {x, -x}) {
      for (long shift = -digits - 3; shift <= 2 * std::numeric_limits<T>::max_exponent + 3; shift += 7) {
        const T expected = std::ldexp(signed_x, int(shift)), got = contact::detail::scaled<T>::shifted(signed_x, shift);
        EXPECT_EQ(got, expected) << std::hexfloat << signed_x << " shifted by " << shift;
        EXPECT_EQ(std::signbit(got), std::signbit(expected));
        ++checked;
      }
      const scaled<T> held(signed_x);
      EXPECT_GE(std::fabs(held.significand), T(0.5));
      EXPECT_LT(std::fabs(held.significand), T(1));
      EXPECT_EQ(held.value(), signed_x);
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(Scaled, SubnormalsMoveAsLdexpDoesInDouble) { expect_subnormals_move_as_ldexp_does<double>(); }
TEST(Scaled, SubnormalsMoveAsLdexpDoesInFloat) { expect_subnormals_move_as_ldexp_does<float>(); }

// A cluster of the exact sign that T cannot hold: in a 6-bit format whose
// least normal value is 2^-12, u + dy - phi dy for u = -0.4296875,
// dy = 0.53125, phi = 0.19140625 is -2^-13, the low part of phi dy: shifted
// beside u it would flush to zero, and the sign with it (contact, not release).
TEST(Scaled, ExactSignHoldsInAFormatOfFewExponents) {
  using narrow_range = mini_float<6, -12, 17, true>;
  const narrow_range u(-0.4296875), dy(0.53125), phi(0.19140625);
  const scaled<narrow_range> dy_s(dy);
  const auto product = exact_product(scaled<narrow_range>(phi), dy_s);
  EXPECT_EQ(product[1].significand, narrow_range(0.5));  // 2^-13, below the format's range: only the scaled pair holds it
  EXPECT_EQ(product[1].exponent, -12);
  EXPECT_EQ(product[1].value(), 0);
  const std::array<scaled<narrow_range>, 4> terms = {scaled<narrow_range>(u), dy_s, -product[0], -product[1]};
  EXPECT_EQ(detail::sign_of_exact_sum(terms), -1);
  EXPECT_EQ(solve_stable(u, dy, phi).which, contact_case::release);
  EXPECT_EQ(solve_stable(u, dy, phi).which, reference::solve(-0.4296875, 0.53125, 0.19140625).which);
}

// The plain window leaves room for the formulas' least intermediates above T's
// least normal value, as for their largest below its largest value. In a 6-bit
// format from 2^-12 to 2^22, the 22 binades above 1 alone would give the window
// [2^-2, 2^2], where the low part of phi dy (down to 2^-14) underflows: these
// inputs came out contact, not release. The 12 binades below give [1, 1].
TEST(Window, LeavesRoomAboveTheLeastNormalValue) {
  using lopsided = mini_float<6, -12, 21, true>;
  EXPECT_EQ(detail::safe_window<lopsided>::half_width(), 0);
  EXPECT_EQ((detail::safe_window<mini_float<6, -21, 21, true>>::half_width()), 2);
  const lopsided u(-0.25), dy(0.3515625), phi(0.2890625);
  EXPECT_EQ(solve_stable(u, dy, phi).which, contact_case::release);
  EXPECT_EQ(reference::solve(-0.25, 0.3515625, 0.2890625).which, contact_case::release);
}

// min_of and max_of, the clamps' one instruction, give a < b ? a : b and
// a > b ? a : b in every registered type: b wherever the comparison fails,
// for a NaN on either side and for two zeros of either sign (what minsd and
// maxsd give for double and float, and ?: for the other types). The operands
// come through a function the compiler cannot see into: GCC 12 folds minsd
// and maxsd of constants as if they commuted (a NaN or a zero first comes
// back). The clamps never meet that case: their bounds are non-zero numbers,
// and s is a number for every valid input.
template <class T>
[[gnu::noipa]] T opaque(const T& x) {
  return x;
}

TYPED_TEST_SUITE(MinAndMax, all_types, type_names_for_gtest);
template <class T>
class MinAndMax : public ::testing::Test {};
TYPED_TEST(MinAndMax, AreTheComparisonsThatGiveTheSecondOperandWhenTheyFail) {
  using T = TypeParam;
  using std::isnan;
  using std::signbit;
  const T one = opaque(T(1)), two = opaque(T(2)), zero = opaque(T(0)), minus_zero = opaque(T(-T(0))),
          nan = opaque(std::numeric_limits<T>::quiet_NaN());
  EXPECT_EQ(detail::min_of(one, two), one);
  EXPECT_EQ(detail::min_of(two, one), one);
  EXPECT_EQ(detail::max_of(one, two), two);
  EXPECT_EQ(detail::max_of(two, one), two);
  EXPECT_TRUE(signbit(detail::min_of(zero, minus_zero)));
  EXPECT_FALSE(signbit(detail::min_of(minus_zero, zero)));
  EXPECT_TRUE(signbit(detail::max_of(zero, minus_zero)));
  EXPECT_FALSE(signbit(detail::max_of(minus_zero, zero)));
  EXPECT_EQ(detail::min_of(nan, one), one);
  EXPECT_EQ(detail::max_of(nan, one), one);
  EXPECT_TRUE(isnan(detail::min_of(one, nan)));
  EXPECT_TRUE(isnan(detail::max_of(one, nan)));
}

// square_root rounds to nearest in every registered type: it equals MPFR's
// correctly rounded root of the same x, at T's precision. (The stable path's
// proofs assume a correctly rounded square root.)
TYPED_TEST_SUITE(SquareRoot, all_types, type_names_for_gtest);
template <class T>
class SquareRoot : public ::testing::Test {};
TYPED_TEST(SquareRoot, IsCorrectlyRounded) {
  using T = TypeParam;
  check_property<T>("square_root rounds to nearest", [] {
    const long reach = std::min<long>(200, harness::highest_exponent<T>() / 2);
    const T x = *log_uniform<T>(-reach, reach);
    const int bits = detail::precision_of<T>();
    reference::real exact(bits);
    mpfr_sqrt(exact.get(), reference::exactly(x, std::max(64, bits)).get(), MPFR_RNDN);  // RN at T's precision
    const T root = detail::square_root(x);
    RC_ASSERT(mpfr_equal_p(reference::exactly(root, std::max(64, bits)).get(), exact.get()) != 0);
  });
}

// An MPFR number's value, sign (of zero too) and precision in bits, as text to compare
std::string bits_of(const mpfr_float& x) {
  using std::signbit;
  return x.str(0, std::ios_base::scientific) + (signbit(x) ? "-" : "+") + std::to_string(mpfr_get_prec(x.backend().data()));
}

// MPFR's TwoSum (detail::two_sum_by_magnitude, which two_sum takes for MPFR
// numbers): Fast2Sum on the operands ordered by signs and comparisons. Its pair must be Knuth's TwoSum's bit for bit, signs of zero
// included, and exact, on operands of either sign and any ratio of
// magnitudes: equal, opposite (an exact zero), one ulp apart, far apart, and
// zeros of either sign.
TEST(TwoSum, MpfrByMagnitudeIsKnuthsPairBitForBit) {
  const int saved = mpfr_float::default_precision();
  mpfr_float::default_precision(50);
  std::mt19937_64 random(20261129);
  std::uniform_real_distribution<double> significand(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300), kind(0, 7);
  const auto draw = [&] {
    using std::ldexp;
    return mpfr_float(ldexp(mpfr_float(significand(random)) * mpfr_float(significand(random)), exponent(random)));
  };
  long mismatches = 0, inexact = 0;
  for (int i = 0; i < 100000; ++i) {
    const mpfr_float a = kind(random) == 0 ? mpfr_float(i % 2 ? -0.0 : 0.0) : draw();
    mpfr_float b;
    switch (kind(random)) {
      case 0: b = mpfr_float(i % 3 ? -0.0 : 0.0); break;
      case 1: b = -a; break;
      case 2: b = a; break;
      case 3: b = -detail::next_up(a); break;
      case 4: b = detail::next_down(a) - a; break;
      default: b = draw();
    }
    const auto pair = detail::two_sum(a, b), knuth = detail::knuth_two_sum(a, b);
    if (bits_of(pair.high) != bits_of(knuth.high) || bits_of(pair.low) != bits_of(knuth.low)) {
      if (++mismatches <= 5)
        ADD_FAILURE() << "two_sum(" << bits_of(a) << ", " << bits_of(b) << ") = " << bits_of(pair.high) << " + "
                      << bits_of(pair.low);
    }
    reference::real sum(1024), expected(1024);
    mpfr_add(sum.get(), pair.high.backend().data(), pair.low.backend().data(), MPFR_RNDN);  // exact at 1024 bits
    mpfr_add(expected.get(), a.backend().data(), b.backend().data(), MPFR_RNDN);
    inexact += mpfr_equal_p(sum.get(), expected.get()) == 0;
  }
  mpfr_float::default_precision(saved);
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(inexact, 0);
}

// For MPFR, detail::fused_multiply_add rounds into the storage of an operand
// that is a temporary (the first, the third, or both). Its result must be
// Boost's fma's bit for bit, precision included: operands of one precision,
// and of mixed precisions (Boost's result takes the largest); addends that
// cancel the product exactly or nearly, zeros of either sign, far apart.
TEST(FusedMultiplyAdd, MpfrIntoATemporaryOperandIsBoostsFmaBitForBit) {
  const int saved = mpfr_float::default_precision();
  std::mt19937_64 random(20261130);
  std::uniform_real_distribution<double> significand(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300), kind(0, 5), digits(0, 2);
  const int precisions[] = {20, 50, 80};
  const auto draw = [&](int precision) {
    using std::ldexp;
    mpfr_float::default_precision(precision);
    return mpfr_float(ldexp(mpfr_float(significand(random)) * mpfr_float(significand(random)), exponent(random)));
  };
  long mismatches = 0;
  for (int i = 0; i < 100000; ++i) {
    const bool mixed = i % 4 == 0;
    const auto precision = [&] { return mixed ? precisions[digits(random)] : 50; };
    const mpfr_float a = draw(precision()), b = draw(precision());
    mpfr_float::default_precision(precision());
    mpfr_float c;
    switch (kind(random)) {
      case 0: c = mpfr_float(i % 2 ? -0.0 : 0.0); break;
      case 1: c = -(a * b); break;                  // the product rounded: the fma gives its error
      case 2: c = detail::next_up(mpfr_float(-(a * b))); break;
      default: c = draw(precision());
    }
    mpfr_float::default_precision(30);  // neither's result may depend on it
    using boost::multiprecision::fma;
    const std::string expected = bits_of(fma(a, b, c));
    const std::string into_first = bits_of(detail::fused_multiply_add(mpfr_float(a), b, c));
    const std::string into_third = bits_of(detail::fused_multiply_add(a, b, mpfr_float(c)));
    const std::string into_either = bits_of(detail::fused_multiply_add(mpfr_float(a), b, mpfr_float(c)));
    if (into_first != expected || into_third != expected || into_either != expected) {
      if (++mismatches <= 5)
        ADD_FAILURE() << "fma(" << bits_of(a) << ", " << bits_of(b) << ", " << bits_of(c) << ") = " << expected
                      << ", in place " << into_first << ", " << into_third << ", " << into_either;
    }
  }
  mpfr_float::default_precision(saved);
  EXPECT_EQ(mismatches, 0);
}

// detail::magnitude_exceeds compares magnitudes in place for MPFR: it must
// agree with fabs(x) > bound, on equal and opposite magnitudes, zeros and
// neighbours.
TEST(MagnitudeExceeds, MpfrIsFabsComparedWithTheBound) {
  const int saved = mpfr_float::default_precision();
  mpfr_float::default_precision(50);
  std::mt19937_64 random(20261131);
  std::uniform_real_distribution<double> value(-4.0, 4.0);
  std::uniform_int_distribution<int> kind(0, 4);
  long disagreements = 0;
  for (int i = 0; i < 100000; ++i) {
    const mpfr_float x(i % 7 == 0 ? (i % 2 ? -0.0 : 0.0) : value(random));
    using std::fabs;
    mpfr_float bound;
    switch (kind(random)) {
      case 0: bound = fabs(x); break;
      case 1: bound = detail::next_up(mpfr_float(fabs(x))); break;
      case 2: bound = detail::next_down(mpfr_float(fabs(x))); break;
      case 3: bound = mpfr_float(0); break;
      default: bound = fabs(mpfr_float(value(random)));
    }
    if (bound < 0) bound = mpfr_float(0);
    disagreements += detail::magnitude_exceeds(x, bound) != (fabs(x) > bound);
  }
  mpfr_float::default_precision(saved);
  EXPECT_EQ(disagreements, 0);
}

// The weakness square_root works around: libquadmath's own sqrtq is faithful,
// not correctly rounded. Over squares of random float128 significands, some
// roots come back one ulp off.
// Boost 1.74's cpp_bin_float misrounds a sum whose smaller term lies a
// quarter to half an ulp below the larger, with the other sign (half the time
// one ulp off). Its fma is emulated (Dekker's product, then sums), and ends in
// such a sum; detail::sum_of_head_and_tail rounds it instead. Found by
// StableProperty.ZeroStiffnessGivesMinusU on u = -6.0347e270: sqrt(fma(u, u, 0))
// was not |u|.
TEST(FusedMultiplyAdd, CppBinFloatWithAZeroAddendIsTheRoundedProduct) {
  using T = bin_float_50;
  const T u("-6.0347e270");
  EXPECT_EQ(detail::fused_multiply_add(u, u, T(0)), u * u);
  EXPECT_EQ(detail::square_root(detail::fused_multiply_add(u, u, T(0))), -u);
  std::mt19937_64 source(41);
  std::uniform_real_distribution<double> unit(0.5, 1.0);
  long mismatches = 0;
  for (int i = 0; i < 20000; ++i) {
    const T a = ldexp(T(unit(source)) + ldexp(T(unit(source)), -60) + ldexp(T(unit(source)), -120), 900);
    const T b = ldexp(T(unit(source)) + ldexp(T(unit(source)), -60) + ldexp(T(unit(source)), -120), -20);
    mismatches += detail::fused_multiply_add(a, b, T(0)) != a * b;
    // a head of 0: the product's own rounding error, exactly (here far below 1)
    const T small = ldexp(a, -1200);
    mismatches += detail::fused_multiply_add(small, b, T(-(small * b))) != detail::two_prod(small, b).low;
  }
  EXPECT_EQ(mismatches, 0);
}

// Every tail below an ulp of a head, against the same sum in twice the precision
// rounded once: powers of two among the heads (where the spacing halves below).
TEST(FusedMultiplyAdd, HeadAndTailRoundToNearestInCppBinFloat) {
  using T = bin_float_50;
  using Wide = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<120>, boost::multiprecision::et_off>;
  std::mt19937_64 source(42);
  std::uniform_real_distribution<double> unit(0.5, 1.0), fraction(-1.0, 1.0);
  long mismatches = 0;
  for (int i = 0; i < 20000; ++i) {
    const T head = i % 4 == 0 ? T(i % 8 == 0 ? 0.5 : -0.5)
                              : T(unit(source)) + ldexp(T(unit(source)), -60) + ldexp(T(unit(source)), -120);
    const T ulp = ldexp(T(1), 1 - std::numeric_limits<T>::digits);  // of a head in [0.5, 1)
    const T tail = ulp * T(fraction(source)) * (i % 3 == 0 ? T(0.25) : T(1)) + ldexp(ulp * T(fraction(source)), -70);
    const T nearest = T(Wide(head) + Wide(tail));
    mismatches += detail::sum_of_head_and_tail(head, tail) != nearest;
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(SquareRoot, Float128LibrarySqrtIsNotAlwaysCorrectlyRounded) {
  harness::seeded_source source(20261123);
  int off = 0;
  for (int i = 0; i < 20000; ++i) {
    const float128 x = harness::significand<float128>(source);
    using std::sqrt;
    off += sqrt(float128(x * x)) != x;
    EXPECT_EQ(detail::square_root(float128(x * x)), x);
  }
  EXPECT_GT(off, 0) << "sqrtq rounded every square root correctly: square_root's correction may no longer be needed";
}

// The hard inputs of square_root's midpoint tests: x the square of a midpoint
// between neighbouring float128 values, rounded to float128, so that the root
// lies within a few ulps of x of that midpoint, on either side.
TEST(SquareRoot, Float128RoundsToNearestNextToMidpoints) {
  harness::seeded_source source(20261127);
  const int bits = detail::precision_of<float128>();
  long wrong = 0;
  for (int i = 0; i < 20000; ++i) {
    const float128 r = harness::significand<float128>(source);
    reference::real midpoint(4 * bits), square(4 * bits), root(bits);
    mpfr_add(midpoint.get(), reference::exactly(r, 4 * bits).get(), reference::exactly(detail::next_up(r), 4 * bits).get(), MPFR_RNDN);
    mpfr_div_2ui(midpoint.get(), midpoint.get(), 1, MPFR_RNDN);
    mpfr_sqr(square.get(), midpoint.get(), MPFR_RNDN);  // exact at 4 bits
    const float128 x = detail::ulp_steps(float128(square.to_string(45).c_str()), long(i % 5) - 2);  // near it
    mpfr_sqrt(root.get(), reference::exactly(x, 2 * bits).get(), MPFR_RNDN);
    wrong += mpfr_equal_p(reference::exactly(detail::square_root(x), 2 * bits).get(), root.get()) == 0;
  }
  EXPECT_EQ(wrong, 0);
}

TEST(SquareRoot, Float128SpecialValuesPassThrough) {
  const float128 infinity = std::numeric_limits<float128>::infinity();
  using boost::multiprecision::isnan;
  EXPECT_EQ(detail::square_root(float128(0)), 0);
  EXPECT_EQ(detail::square_root(infinity), infinity);
  EXPECT_TRUE(isnan(detail::square_root(float128(-1))));
  EXPECT_TRUE(isnan(detail::square_root(std::numeric_limits<float128>::quiet_NaN())));
}

}  // namespace
}  // namespace contact::testing
