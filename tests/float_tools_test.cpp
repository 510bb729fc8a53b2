// The stable path's arithmetic helpers on their own: ulp steps that saturate,
// and scaled<T>, whose every operation must round exactly as T does while its
// exponent never overflows or underflows.
#include "contact/detail/scaled.hpp"
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

// Doubles whose products, quotients and sums of two or three stay normal.
rc::Gen<double> moderate() { return signed_(log_uniform<double>(-300, 300)); }

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
    RC_ASSERT(same(sqrt(sa * sa).value(), std::fabs(a)));
    RC_ASSERT(same(sqrt(scaled<double>(std::fabs(a))).value(), std::sqrt(std::fabs(a))));
    RC_ASSERT((sa > sb) == (a > b));
  }));
}

TEST(Scaled, IntermediatesBeyondDoublesRangeDoNotOverflowOrUnderflow) {
  const scaled<double> big(largest), tiny(0x1p-1074);
  EXPECT_EQ((big * big / big).value(), largest);
  EXPECT_EQ((tiny * tiny / tiny).value(), 0x1p-1074);
  EXPECT_EQ(sqrt(big * big).value(), largest);
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
  EXPECT_EQ(sqrt(zero).value(), T(0));
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
  EXPECT_TRUE(isnan(sqrt(scaled<T>(T(-1))).value()));
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
}

}  // namespace
}  // namespace contact::testing
