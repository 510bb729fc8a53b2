// The certified reference checked on its own: every accuracy figure of the
// project is measured against it, so it must be right where we can tell by
// hand, and its certificate must be able to fail.
#include <vector>

#include "harness.hpp"

namespace contact::testing {
namespace {

constexpr double largest = std::numeric_limits<double>::max();
constexpr double inf = std::numeric_limits<double>::infinity();

reference::rational exact_rational(double x) { return reference::rational(reference::exactly(x, 256)); }

// The certificate of s for the input (u, dy, phi), at the default 256 bits.
bool certifies(double s, double u, double dy, double phi) {
  reference::real root = reference::exactly(s, 320), lower(320), upper(320);
  return reference::certify(root, lower, upper, exact_rational(u), exact_rational(dy), exact_rational(phi), 256);
}

TEST(Reference, ExactRootsAreReproducedExactly) {
  const auto exact = reference::solve(3.0, 1.0, 3.0);  // (A.31): s = 3/4
  EXPECT_TRUE(exact.is_certified);
  EXPECT_EQ(exact.which, contact_case::contact);
  EXPECT_EQ(reference::rounded_to_double(exact.s), 0.75);
  EXPECT_EQ(reference::ulp_error(0.75, exact), 0.0);
  EXPECT_EQ(reference::ulp_error(std::nextafter(0.75, 2.0), exact), 1.0);
}

TEST(Reference, EachCaseMatchesItsClosedFormByHand) {
  EXPECT_EQ(reference::rounded_to_double(reference::solve(-0.5, -1.0, 3.0).s), 0.5);   // (A.29) -u
  EXPECT_EQ(reference::rounded_to_double(reference::solve(2.0, 0.0, 3.0).s), -0.5);    // (A.30) -u / (1 + phi)
  EXPECT_EQ(reference::rounded_to_double(reference::solve(0.0, 1.0, 4.0).s), 2.0);     // (A.32) u <= 0
  EXPECT_EQ(reference::rounded_to_double(reference::solve(1.0, 1.0, 12.0).s), 3.0);    // (A.32) u > 0: 24 / (1 + 7)
}

// Rounding the working-precision root to double rounds twice: with a subnormal
// phi, (A.31)'s root lies about 2^-432 of itself above the midpoint 2 phi dy,
// so at 256 bits it is the midpoint, and ties to even would take the neighbour
// below. rounded_root decides on the exact sign of R at the midpoint instead.
TEST(Reference, RoundedRootDecidesARootNearerAMidpointThanTheWorkingPrecision) {
  const double u = -0x0.13fccb69b00b1p-1022, dy = 0x1.a6fb214114dfcp+477, phi = 0x0.0000000000007p-1022;
  const auto exact = reference::solve(u, dy, phi);
  EXPECT_EQ(reference::rounded_to_double(exact.s), 0x1.721bbd18f243cp-593);  // the midpoint, rounded to even
  EXPECT_EQ(mpfr_get_d(reference::rounded_root(exact, u, dy, phi).get(), MPFR_RNDN), 0x1.721bbd18f243dp-593);
}

// An exact tie stays a tie: R at the midpoint is zero and the even neighbour is taken
// ((A.31) with phi = 1: s = (2 dy - u) / 2 = 3 2^-1075, between the subnormals 2^-1074 and 2^-1073).
TEST(Reference, RoundedRootTakesTheEvenNeighbourOfAnExactTie) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const auto exact = reference::solve(tiny, 2 * tiny, 1.0);
  EXPECT_EQ(mpfr_get_d(reference::rounded_root(exact, tiny, 2 * tiny, 1.0).get(), MPFR_RNDN), 2 * tiny);
}

// The certificate tests the exact residual on both sides of s: a root above
// the true one fails the lower end, a root below it fails the upper end.
TEST(Reference, CertificateRejectsARootAboveTheTrueOne) { EXPECT_FALSE(certifies(1.5, 3.0, 1.0, 3.0)); }

TEST(Reference, CertificateRejectsARootBelowTheTrueOne) { EXPECT_FALSE(certifies(0.5, 3.0, 1.0, 3.0)); }

TEST(Reference, CertificateAcceptsTheTrueRoot) { EXPECT_TRUE(certifies(0.75, 3.0, 1.0, 3.0)); }

// At s = 0 the certificate is the limit of R at 0, u - 2 phi floor(dy).
TEST(Reference, ZeroIsCertifiedOnlyWhereItIsTheRoot) {
  const auto exact = reference::solve(2.0, 1.0, 1.0);  // (A.31): (2 - 2) / 2 = 0
  EXPECT_TRUE(mpfr_zero_p(exact.s.get()));
  EXPECT_TRUE(exact.is_certified);
  EXPECT_TRUE(certifies(0.0, 0.0, -1.0, 5.0));   // (A.29) with u = 0
  EXPECT_FALSE(certifies(0.0, 3.0, 1.0, 3.0));   // the root is 3/4
  EXPECT_FALSE(certifies(0.0, 1.0, -1.0, 5.0));  // the root is -1
}

TEST(Reference, AHigherPrecisionAgreesWithinTheLowerOnesBracket) {
  const double u = 0x1.3c0ca2a5b1d5dp-12, dy = 0x1.a36e2eb1c432dp-14, phi = 0x1.5bf0a8b145769p+9;
  const auto fine = reference::solve(u, dy, phi, 1024);
  const auto coarse = reference::solve(u, dy, phi);
  EXPECT_TRUE(fine.is_certified);
  EXPECT_TRUE(coarse.is_certified);
  EXPECT_EQ(mpfr_get_prec(fine.s.get()), 1024 + 64);
  EXPECT_LE(mpfr_cmp(coarse.lower.get(), fine.s.get()), 0);
  EXPECT_GE(mpfr_cmp(coarse.upper.get(), fine.s.get()), 0);
}

// A certified answer owns MPFR memory; moving it (as a growing vector does)
// must keep every value.
TEST(Reference, CertifiedAnswersSurviveMovesIntoAGrowingVector) {
  std::vector<reference::certified> answers;
  for (int k = 2; k <= 41; ++k) answers.push_back(reference::solve(double(k), 1.0, 3.0));  // (A.31): s = (6 - k) / 4
  for (int k = 2; k <= 41; ++k) {
    EXPECT_EQ(reference::rounded_to_double(answers[std::size_t(k - 2)].s), (6.0 - k) / 4) << k;
    EXPECT_TRUE(answers[std::size_t(k - 2)].is_certified);
  }
}

// An infinite answer is exact (0 ulp) when the root lies beyond the rounding
// threshold to that infinity, and infinitely wrong otherwise.
reference::certified root_at(double significand, long power_of_two) {
  reference::certified c{reference::real(320), reference::real(320), reference::real(320), contact_case::release, true};
  mpfr_set_d(c.s.get(), significand, MPFR_RNDN);
  mpfr_mul_2si(c.s.get(), c.s.get(), power_of_two, MPFR_RNDN);
  return c;
}

TEST(Reference, PlusInfinityIsExactOnlyForARootAboveTheLargestDouble) {
  EXPECT_EQ(reference::ulp_error(inf, reference::solve(-largest, largest, 1.0)), 0.0);  // (A.32): about 1.6 DBL_MAX
  EXPECT_EQ(reference::ulp_error(inf, root_at(1.0, 1024)), 0.0);
  EXPECT_EQ(reference::ulp_error(inf, root_at(largest, 0)), inf);
  EXPECT_EQ(reference::ulp_error(inf, root_at(-1.0, 1024)), inf);
}

TEST(Reference, MinusInfinityIsExactOnlyForARootBelowMinusTheLargestDouble) {
  EXPECT_EQ(reference::ulp_error(-inf, root_at(-1.0, 1024)), 0.0);
  EXPECT_EQ(reference::ulp_error(-inf, root_at(-largest, 0)), inf);
  EXPECT_EQ(reference::ulp_error(-inf, root_at(1.0, 1024)), inf);
}

// Release with dy the largest finite T answers +infinity by design (the only
// value on its side of dy); the checkers grade answers by accepted_ulp_error,
// whatever T they check (the fuzzers check float, double, long double and
// float128).
template <class T>
reference::certified release_root_at_the_largest() {
  reference::certified c{reference::exactly((std::numeric_limits<T>::max)(), 320), reference::real(320),
                         reference::real(320), contact_case::release, true};
  return c;
}

template <class T>
void expect_forced_infinity_exact() {
  const T largest = (std::numeric_limits<T>::max)(), infinity = std::numeric_limits<T>::infinity();
  const auto root = release_root_at_the_largest<T>();
  EXPECT_EQ(reference::ulp_error<T>(infinity, root), inf);
  EXPECT_EQ(reference::accepted_ulp_error<T>(infinity, root, largest), 0.0);
}

template <class T>
void expect_ulp_error_elsewhere() {
  using std::nextafter;
  const T largest = (std::numeric_limits<T>::max)(), infinity = std::numeric_limits<T>::infinity();
  const auto root = release_root_at_the_largest<T>();
  EXPECT_EQ(reference::accepted_ulp_error<T>(infinity, root, T(largest / 2)), inf);
  EXPECT_EQ(reference::accepted_ulp_error<T>(T(-infinity), root, largest), inf);
  EXPECT_EQ(reference::accepted_ulp_error<T>(T(largest / 2), root, largest),
            reference::ulp_error<T>(T(largest / 2), root));
}

TEST(Reference, AcceptedErrorCountsReleasesForcedInfinityAsExact) {
  expect_forced_infinity_exact<float>();
  expect_forced_infinity_exact<double>();
  expect_forced_infinity_exact<long double>();
  expect_forced_infinity_exact<boost::multiprecision::float128>();
}

TEST(Reference, AcceptedErrorIsTheUlpErrorEverywhereElse) {
  expect_ulp_error_elsewhere<float>();
  expect_ulp_error_elsewhere<double>();
  expect_ulp_error_elsewhere<long double>();
  expect_ulp_error_elsewhere<boost::multiprecision::float128>();
}

TEST(Reference, ANaNAnswerHasANaNError) {
  EXPECT_TRUE(std::isnan(reference::ulp_error(std::numeric_limits<double>::quiet_NaN(), root_at(1.0, 0))));
}

TEST(Reference, UlpsBelowTheNormalRangeAreTheSubnormalSpacing) {
  EXPECT_EQ(reference::ulp_error(0x1p-1074, root_at(0.0, 0)), 1.0);
  EXPECT_EQ(reference::ulp_error(0.0, root_at(0x1p-1070, 0)), 16.0);
}

}  // namespace
}  // namespace contact::testing
