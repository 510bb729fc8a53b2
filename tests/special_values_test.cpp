// Special values and hard cases, for every algorithm: the documented answers to
// bad input, the exact cases, and a list of inputs that once were hard.
#include "harness.hpp"

namespace contact::testing {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

class EveryAlgorithm : public ::testing::TestWithParam<algorithm> {};
INSTANTIATE_TEST_SUITE_P(, EveryAlgorithm, ::testing::ValuesIn(algorithms),
                         [](const auto& info) { return std::string(name_of(info.param)); });

TEST_P(EveryAlgorithm, NonFiniteOrNegativePhiIsInvalidAndNaN) {
  const double bad[][3] = {{nan, 1, 1}, {1, nan, 1}, {1, 1, nan}, {inf, 1, 1}, {1, -inf, 1},
                           {1, 1, inf}, {1, 1, -1}, {1, 1, -0x1p-1074}, {-inf, -inf, -inf}};
  for (const auto& x : bad) {
    const auto r = solve(x[0], x[1], x[2], GetParam());
    EXPECT_EQ(r.which, contact_case::invalid) << x[0] << " " << x[1] << " " << x[2];
    EXPECT_TRUE(std::isnan(r.s));
  }
}

TEST_P(EveryAlgorithm, NegativeZeroPhiIsValid) {
  EXPECT_EQ(solve(1e-3, 1e-4, -0.0, GetParam()).s, -1e-3);
}

// (The textbook form fails this for subnormal u: see TextbookFailure.)
TEST_P(EveryAlgorithm, ZeroStiffnessGivesMinusUExactly) {
  for (double u : {1e-3, -1e-3, 1e-100, -1e100})
    for (double dy : {1e-4, -1e-4, 0.0, -0.0, 1e300}) EXPECT_EQ(solve(u, dy, 0.0, GetParam()).s, -u) << u << " " << dy;
}

TEST(StableAndNewton, ZeroStiffnessGivesMinusUExactlyForSubnormalU) {
  for (double u : {0x1p-1074, -0x1p-1074, 0x1.8p-1060})
    for (double dy : {1e-4, -1e-4, 0.0, -0.0}) {
      EXPECT_EQ(solve_stable(u, dy, 0.0).s, -u) << u << " " << dy;
      EXPECT_EQ(solve_newton(u, dy, 0.0).s, -u) << u << " " << dy;
    }
}

// At rest on the barrier's edge (u = dy = 0) nothing moves, in every case.
TEST_P(EveryAlgorithm, RestAtTheEdgeStaysAtRest) {
  for (double phi : {0.0, 1e-3, 1.0, 1e6, 1e300}) EXPECT_EQ(solve(0.0, 0.0, phi, GetParam()).s, 0.0);
}

// Each case on a plain input, with its equation's closed form evaluated by hand.
TEST_P(EveryAlgorithm, EachCaseOnAPlainInput) {
  struct {
    double u, dy, phi, s;
    contact_case which;
  } const cases[] = {
      {-0.5, -1.0, 3.0, 0.5, contact_case::free},              // (A.29) s = -u
      {2.0, 0.0, 3.0, -0.5, contact_case::impact},             // (A.30) dy = 0: s = -u / (1 + phi)
      {3.0, 1.0, 3.0, 0.75, contact_case::contact},            // (A.31) (2 phi dy - u) / (1 + phi) = 3/4
      {0.0, 1.0, 4.0, 2.0, contact_case::release},             // (A.32) sqrt(4 phi dy^2) / 2 = 2
      {1.0, -1.0, 3.0, -1.0, contact_case::free},              // boundary u = -dy belongs to (A.29): s = dy
      {2.0, 1.0, 3.0, 1.0, contact_case::contact},             // boundary u = dy (phi - 1): s = dy
  };
  for (const auto& c : cases) {
    const auto r = solve(c.u, c.dy, c.phi, GetParam());
    EXPECT_EQ(r.which, c.which) << c.u << " " << c.dy << " " << c.phi;
    EXPECT_EQ(r.s, c.s) << c.u << " " << c.dy << " " << c.phi;
  }
}

TEST(Cases, EachCaseNamesItsEquation) {
  EXPECT_EQ(equation_of(contact_case::free), "(A.29)");
  EXPECT_EQ(equation_of(contact_case::impact), "(A.30)");
  EXPECT_EQ(equation_of(contact_case::contact), "(A.31)");
  EXPECT_EQ(equation_of(contact_case::release), "(A.32)");
  EXPECT_EQ(equation_of(contact_case::invalid), "invalid");
}

TEST(Cases, EachCaseHasItsName) {
  EXPECT_EQ(name_of(contact_case::free), "free");
  EXPECT_EQ(name_of(contact_case::impact), "impact");
  EXPECT_EQ(name_of(contact_case::contact), "contact");
  EXPECT_EQ(name_of(contact_case::release), "release");
  EXPECT_EQ(name_of(contact_case::invalid), "invalid");
  EXPECT_EQ(std::size(valid_cases), 4u);
}

TEST(Cases, AnInvalidResultLiesOnNoSide) {
  EXPECT_FALSE(lies_on_its_side(contact_case::invalid, 0.0, 0.0));
  EXPECT_FALSE(lies_on_its_side(contact_case::invalid, nan, 1.0));
}

// A case number that names no case (contact-check casts a candidate's answer)
// reads as invalid: its name, its equation, no side.
TEST(Cases, ANumberThatNamesNoCaseReadsAsInvalid) {
  const auto unknown = static_cast<contact_case>(7);
  EXPECT_EQ(name_of(unknown), "invalid");
  EXPECT_EQ(equation_of(unknown), "invalid");
  EXPECT_FALSE(lies_on_its_side(unknown, 0.0, 0.0));
  EXPECT_FALSE(lies_on_its_side(unknown, 2.0, 1.0));
}

TEST(Algorithms, EachHasItsOwnName) {
  EXPECT_EQ(name_of(algorithm::textbook), "textbook");
  EXPECT_EQ(name_of(algorithm::stable), "stable");
  EXPECT_EQ(name_of(algorithm::newton), "newton");
  EXPECT_EQ(name_of(algorithm::rounded), "rounded");
  EXPECT_EQ(name_of(static_cast<algorithm>(9)), "");  // a number that names no algorithm has no name
}

// contact::solve's default is stable, and so is its answer to a number that
// names no algorithm.
TEST(Algorithms, SolveOfANumberThatNamesNoAlgorithmIsStable) {
  const double inputs[][3] = {{-0.5, -1.0, 3.0}, {2.0, 0.0, 3.0}, {3.0, 1.0, 3.0}, {0.1, 1.0, 4.0}, {nan, 1.0, 1.0}};
  for (const auto& x : inputs) {
    const auto r = solve(x[0], x[1], x[2], static_cast<algorithm>(9));
    const auto stable = solve_stable(x[0], x[1], x[2]);
    EXPECT_EQ(r.which, stable.which) << x[0] << " " << x[1] << " " << x[2];
    EXPECT_TRUE(r.s == stable.s || (std::isnan(r.s) && std::isnan(stable.s))) << x[0] << " " << x[1] << " " << x[2];
  }
}

// At the top of the range (harness::top_of_range): the exact case, and a
// finite result within its branch's bound wherever the exact root rounds to a
// finite value (release with dy the largest T included, where that value is dy
// itself: lies_on_its_side admits it), infinity only where it rounds to infinity.
template <class T>
class TopOfRange : public ::testing::Test {};
using types_with_a_reachable_largest = ::testing::Types<float, double, long double, float128>;
TYPED_TEST_SUITE(TopOfRange, types_with_a_reachable_largest, type_names_for_gtest);

TYPED_TEST(TopOfRange, StableIsInfiniteExactlyWhereTheRootRoundsToInfinityAndElseWithinBound) {
  using T = TypeParam;
  int finite_roots = 0;
  for (const auto& x : harness::top_of_range<T>()) {
    const auto exact = reference::solve(x.u, x.dy, x.phi);
    ASSERT_TRUE(exact.is_certified) << x;
    const bool rounds_finite = mpfr_number_p(reference::rounded_root<T>(exact, x.u, x.dy, x.phi).get());
    finite_roots += rounds_finite;
    const auto got = solve_stable(x.u, x.dy, x.phi);
    EXPECT_EQ(got.which, exact.which) << x;
    EXPECT_TRUE(lies_on_its_side(got.which, got.s, x.dy)) << x;
    if (rounds_finite)
      EXPECT_LE(reference::ulp_error(got.s, exact), stable_bound_for(exact.which, x.u)) << x << " s=" << got.s;
    else
      EXPECT_EQ(got.s, std::numeric_limits<T>::infinity()) << x;
  }
  EXPECT_GE(finite_roots, 14);  // the list is mostly of finite roots beside infinite operands' neighbours
}

// newton's case is the exact one at the top of the range, where its rounded
// residual at the kink can have the other sign (u + dy rounds to dy), and its
// s lies on that case's side.
TYPED_TEST(TopOfRange, NewtonPicksTheExactCase) {
  using T = TypeParam;
  auto inputs = harness::top_of_range<T>();
  inputs.push_back({T(-1), T(0x1.fffffep+127), T(1)});  // the largest float as a dy of this type
  inputs.push_back({T(-1), T(0x1p+100), T(1)});
  for (const auto& x : inputs) {
    const auto exact = reference::solve(x.u, x.dy, x.phi);
    const auto got = solve_newton(x.u, x.dy, x.phi);
    EXPECT_EQ(got.which, exact.which) << x;
    EXPECT_TRUE(lies_on_its_side(got.which, got.s, x.dy)) << x << " s=" << got.s;
  }
}

// Release with dy the largest T: the largest T, dy itself, is admitted on
// release's side, and only there.
TEST(Cases, ReleaseAdmitsDyOnItsSideOnlyWhereDyIsTheLargest) {
  const double largest = std::numeric_limits<double>::max();
  EXPECT_TRUE(lies_on_its_side(contact_case::release, largest, largest));
  EXPECT_TRUE(lies_on_its_side(contact_case::release, inf, largest));
  EXPECT_FALSE(lies_on_its_side(contact_case::release, 1.0, 1.0));
  EXPECT_FALSE(lies_on_its_side(contact_case::release, 0.5, 1.0));
  EXPECT_TRUE(only_infinity_on_its_side(contact_case::release, largest));
  EXPECT_FALSE(only_infinity_on_its_side(contact_case::contact, largest));
  EXPECT_FALSE(only_infinity_on_its_side(contact_case::release, 1.0));
  EXPECT_FALSE(lies_on_its_side(contact_case::release, std::nextafter(largest, 0.0), std::nextafter(largest, 0.0)));
  EXPECT_FALSE(lies_on_its_side(contact_case::impact, -largest, -largest));
}

// A release root between the largest double and the threshold of rounding to
// infinity (the largest plus half its ulp) rounds to the largest double; its
// computed value, a few ulps off, can lie beyond the threshold. Stable answers
// the largest double there: the exact sign of R at the threshold decides, not
// R at the largest double (which answered +infinity, an infinite error, before).
// Found near the threshold by a search of release inputs.
TEST(Cases, ReleaseRootJustBelowTheThresholdOfInfinityAnswersTheLargestDouble) {
  const double largest = std::numeric_limits<double>::max();
  const std::array<std::array<double, 3>, 5> near_threshold = {{
      {-0x1.944d435081324p+1017, 0x1.a29e835c0e448p+998, 0x1.7a398262b99dep+50},
      {-0x1.fa2cbc99b7b9bp+1003, 0x1.df508714e112p+1009, 0x1.241abfd8639b9p+28},
      {-0x1.210ded927c697p+1019, 0x1.bfcc2c9e2a78p+1000, 0x1.42dc66249ff68p+46},
      {0.0, 0x1.b02ba83f96baap+995, 0x1.674f6afc931bp+56},
      {-0x1.5d10799f0de3cp+1021, 0x1.794d1e5584965p+994, 0x1.8710f8cf6330ep+58},
  }};
  for (const auto& [u, dy, phi] : near_threshold) {
    const auto exact = reference::solve(u, dy, phi);
    ASSERT_TRUE(exact.is_certified);
    EXPECT_EQ(reference::rounded_to_double(exact.s), largest) << std::hexfloat << u << " " << dy << " " << phi;
    const auto got = solve_stable(u, dy, phi);
    EXPECT_EQ(got.which, contact_case::release);
    EXPECT_EQ(got.s, largest) << std::hexfloat << u << " " << dy << " " << phi;
  }
}

TEST(Types, EveryNamedTypeDispatchesAndAnUnknownNameDoesNot) {
  int called = 0;
  const auto count_call = [&](auto) { ++called; };
  for (auto name : type_names) EXPECT_TRUE(with_type(name, count_call)) << name;
  EXPECT_EQ(called, int(type_names.size()));
  EXPECT_FALSE(with_type("half", count_call));
  EXPECT_EQ(called, int(type_names.size()));
  int visited = 0;
  for_each_type([&](auto zero) { EXPECT_EQ(type_name<decltype(zero)>, type_names[visited++]); });
  EXPECT_EQ(visited, int(type_names.size()));
}

// Inputs that broke an earlier version or sit on a knife edge (hex, exact).
// Each line: the stable answer's error against the reference, within bound.
TEST(StableHardCases, ListedInputsStayWithinBound) {
  const double hard[][3] = {
      {0x1.f72131f09bb4p-203, 0x1.8f573f2bfc85cp-738, 0x1.d262f1e08e256p+1005},  // release, s >> dy
      {0x1.0fafed26833acp+999, -0x1.f3712352ac9fbp+598, 0x1.4e76d5ad11612p+450},  // impact, u near overflow
      {0x1.7c4d7ec49ad9fp+110, 0x1.a9342c259ff79p+940, 0x1.9273bacd647d1p+178},   // release, s overflows
      {0x1.3a92a30554801p-11, 0x1.a36e2eb1c432dp-14, 0x1.8p+1},                  // contact, s ~ 0
      {0x1.0624dd2f1a9fcp-10, -0x1.a36e2eb1c432dp-14, 0x1.7e43c8800759cp+996},    // impact, root rounds onto dy
      {1e300, -1e-300, 1e300},                                                    // impact, scaled path
      {1e150, 1e-150, 1e308},                                                     // release, s = 1e-142
      {0x1p-1074, 0x1p-1074, 0x1p+1023},                                          // subnormal u and dy
      {-0x1p-1074, 0x1p-1074, 1.0},                                               // boundary on subnormals
      {0x1.fffffffffffffp+1023, -0x1.fffffffffffffp+1023, 0x1.fffffffffffffp+1023},
      {0x1.fffffffffffffp+1023, -0x1.fffffffff7fffp+1023, 0x1.4ffffffffffffp-15},  // impact, root -DBL_MAX (was -inf)
      {-0x1.5593cp+1001, 0x1.cbd305836fdf4p+1021, 0x1.3d645a1cac083p+4},          // release, root just below DBL_MAX (was +inf)
  };
  for (const auto& x : hard) {
    const auto exact = reference::solve(x[0], x[1], x[2]);
    const auto r = solve_stable(x[0], x[1], x[2]);
    EXPECT_EQ(r.which, exact.which);
    EXPECT_TRUE(lies_on_its_side(r.which, r.s, x[1]));
    if (std::isfinite(reference::rounded_to_double(exact.s)))
      EXPECT_LE(reference::ulp_error(r.s, exact), stable_bound(r.which, x[0] > 0)) << x[0] << " " << x[1] << " " << x[2];
    else
      EXPECT_TRUE(std::isinf(r.s));
  }
}

// The inputs of proofs/witnesses.txt: the largest errors a search found per
// branch ("branch u dy phi ulps"). 3 ulps is the bound the project aims at for
// every branch; a witness above it shows that the branch's formula cannot be
// proven to 3 ulps, whatever the proof, and its error stays below the claimed
// bound, or the proofs would be wrong. The recorded error is checked, so the
// file cannot drift from the reference.
TEST(StableWitnesses, EachWitnessIsCertifiedInItsBranchAndWithinTheClaimedBound) {
  constexpr double target = 3;
  std::ifstream in(CONTACT_WITNESSES);
  ASSERT_TRUE(in) << "cannot read " << CONTACT_WITNESSES;
  std::map<std::string, int> witnesses;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line.substr(0, line.find('#')));
    std::string branch, text[4];
    if (!(fields >> branch)) continue;
    for (auto& field : text) ASSERT_TRUE(fields >> field) << line;
    const double u = std::strtod(text[0].c_str(), nullptr), dy = std::strtod(text[1].c_str(), nullptr),
                 phi = std::strtod(text[2].c_str(), nullptr), recorded = std::strtod(text[3].c_str(), nullptr);
    ++witnesses[branch];
    const auto exact = reference::solve(u, dy, phi);
    ASSERT_TRUE(exact.is_certified) << line;
    const auto r = solve_stable(u, dy, phi);
    EXPECT_EQ(r.which, exact.which) << line;
    EXPECT_EQ(harness::branch_of(r.which, u > 0), branch) << line;
    const double error = reference::ulp_error(r.s, exact);
    EXPECT_NEAR(error, recorded, 1e-6) << line;
    if (recorded > target) EXPECT_GT(error, target) << line;
    EXPECT_LE(error, stable_bound(r.which, u > 0)) << line;
  }
  for (const char* branch : {"impact", "release_u_positive", "release_u_nonpositive"})
    EXPECT_GE(witnesses[branch], 1) << "no witness for " << branch;
}

// The input on which the uncompensated (A.30) form, -((u + 2 push) + root) /
// (2 (1 + phi)), lost 4.49 ulps: phi near 2^53, where 1 + phi rounds a tie, and
// the numerator's three roundings each cost an ulp of s. The compensated form
// takes exactly those roundings out; what is left is the root's share and the
// last rounding.
TEST(StableWitnesses, CompensatedImpactIsWithinAnUlpWhereThePlainFormLostFourAndAHalf) {
  const double u = 0x1.fb6f56b79d768p+4, dy = -0x1.ffffe7b4a1fb1p+3, phi = 0x1.00062a6b49593p+53;
  const auto exact = reference::solve(u, dy, phi);
  ASSERT_TRUE(exact.is_certified);
  const double gap = -dy, push = phi * gap;
  const double plain = -((u + 2 * push) + std::sqrt(std::fma(u, u, 4 * (push * (u - gap))))) / (2 * (1 + phi));
  EXPECT_GT(reference::ulp_error(plain, exact), 4.4);
  const auto r = solve_stable(u, dy, phi);
  EXPECT_EQ(r.which, contact_case::impact);
  EXPECT_LE(reference::ulp_error(r.s, exact), 1.0);
}

// The input on which the rationalised (A.32) root rounded as written, 2 phi dy^2
// / (u + root), lost 4.09 ulps: u far above 2 sqrt(phi) dy, so u + root is
// about 2 u and phi dy^2's two roundings reach s undamped, with u + root's and
// the quotient's. The compensated form carries phi dy^2 and u + root as pairs
// and corrects the quotient; what is left is the root's share and the last rounding.
TEST(StableWitnesses, CompensatedReleaseIsWithinAnUlpAndAHalfWhereTheRationalisedFormLostFour) {
  const double u = 0x1.01564fa9cc90ep+33, dy = 0x1.0055fb8a9aaacp+0, phi = 0x1.00a36a661eb6dp+47;
  const auto exact = reference::solve(u, dy, phi);
  ASSERT_TRUE(exact.is_certified);
  const double stiffness = (phi * dy) * dy;
  const double rationalised = 2 * stiffness / (u + std::sqrt(std::fma(u, u, 4 * stiffness)));
  EXPECT_GT(reference::ulp_error(rationalised, exact), 4.0);
  const auto r = solve_stable(u, dy, phi);
  EXPECT_EQ(r.which, contact_case::release);
  EXPECT_LE(reference::ulp_error(r.s, exact), 1.5);
}

}  // namespace
}  // namespace contact::testing
