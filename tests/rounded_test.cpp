// The correctly rounded mode (rounded.hpp): bit for bit against the certified
// reference rounded to T, on every input family and on the committed hard-case
// lists; the properties that correct rounding implies; and the counts the
// README quotes (failures, the slow path's share, stable's share of results
// that are not correctly rounded).
#include <cstdlib>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "harness.hpp"

namespace contact::testing {
namespace {

using rounded_types = ::testing::Types<float, double, long double, float128>;

// Whether s is exactly the MPFR number r: value, sign of zero and infinities alike.
template <class T>
bool same_value(const T& s, const reference::real& r) {
  using std::isinf;
  using std::isnan;
  using std::signbit;
  if (isnan(s) || mpfr_nan_p(r.get())) return false;
  if (isinf(s) || mpfr_inf_p(r.get())) return isinf(s) && mpfr_inf_p(r.get()) && (s < 0) == (mpfr_sgn(r.get()) < 0);
  if (s == 0 || mpfr_zero_p(r.get())) return s == 0 && mpfr_zero_p(r.get()) && bool(signbit(s)) == bool(mpfr_signbit(r.get()));
  return mpfr_cmp(as_real(s).get(), r.get()) == 0;
}

// A root of exactly 0 has no sign to round: (A.29) gives -u (so +0 for u = -0,
// which the reference, reading -0 as 0, calls -0) and (A.31) +0. A nonzero
// root that rounds to zero gives the zero of its sign.
template <class T>
bool correctly_rounded(const T& s, const reference::certified& exact, const T& u, const T& dy, const T& phi) {
  if (mpfr_zero_p(exact.s.get())) return s == 0;
  return same_value(s, reference::rounded_root(exact, u, dy, phi));
}

// ---- every input family against the reference ---------------------------------

struct tally {
  long cases = 0, wrong = 0, wrong_case = 0, slow = 0, stable_not_rounded = 0;
};

// Draws `count` inputs of a family (fixed seed) and counts what solve_rounded
// gets wrong against the reference, how often it took the slow path, and how
// often stable is not correctly rounded.
template <class T>
tally measure(const std::string& family, const rc::Gen<input<T>>& gen, int count) {
  set_up_type<T>();
  tally t;
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = count;
  rc::detail::TestMetadata metadata;
  metadata.id = metadata.description = "rounded " + family + " [" + std::string(type_name<T>) + "]";
  rc::detail::checkTestable(
      [&] {
        const auto x = *gen;
        const auto exact = reference_for(x);
        const auto traced = detail::solve_rounded_traced(x.u, x.dy, x.phi);
        ++t.cases;
        t.slow += traced.exact_decision;
        if (!correctly_rounded(traced.result.s, exact, x.u, x.dy, x.phi)) {
          if (++t.wrong <= 5) ADD_FAILURE() << family << ": " << x << " got " << traced.result.s << ", exact root " << exact.s.to_string(40);
        }
        if (traced.result.which != exact.which) ++t.wrong_case;
        if constexpr (std::is_same_v<T, double>)  // rounded_to<double> is the reference's own rounded_to_double
          if (!same_value(reference::rounded_to_double(exact.s), reference::rounded_to<double>(exact.s))) ++t.wrong;
        if (!correctly_rounded(solve_stable(x.u, x.dy, x.phi).s, exact, x.u, x.dy, x.phi)) ++t.stable_not_rounded;
      },
      metadata, params);
  return t;
}

template <class T>
int samples_for() {
  if constexpr (contact::detail::hardware_binary<T>) return 20000;
  if constexpr (std::is_same_v<T, long double>) return 5000;
  return 1000;
}

template <class T>
class RoundedAgainstReference : public ::testing::Test {};
TYPED_TEST_SUITE(RoundedAgainstReference, rounded_types, type_names_for_gtest);

// The result is the reference root rounded to T, bit for bit, and the case the
// exact case, on every family of harness.hpp; on the audio-rate inputs the
// exact decision runs for fewer than 1 in 1000.
TYPED_TEST(RoundedAgainstReference, EveryFamilyBitForBit) {
  using T = TypeParam;
  const int n = samples_for<T>();
  const std::pair<std::string, rc::Gen<input<T>>> families[] = {
      {"any_input", any_input<T>()},
      {"boundary_input", boundary_input<T>()},
      {"cancellation_input", cancellation_input<T>()},
      {"physical_input", physical_input<T>()},
      {"whole_range", whole_range_input<T>()},
  };
  for (const auto& [family, gen] : families) {
    const tally t = measure<T>(family, gen, n);
    std::printf("%-12s %-18s %6ld cases: %ld not correctly rounded, %ld wrong case, slow path %ld (%.2g), "
                "stable not correctly rounded %ld (%.3g)\n",
                std::string(type_name<T>).c_str(), family.c_str(), t.cases, t.wrong, t.wrong_case, t.slow,
                double(t.slow) / double(t.cases), t.stable_not_rounded, double(t.stable_not_rounded) / double(t.cases));
    ::testing::Test::RecordProperty(family + "_not_correctly_rounded", std::to_string(t.wrong));
    ::testing::Test::RecordProperty(family + "_slow_path", std::to_string(t.slow));
    EXPECT_EQ(t.wrong, 0) << family;
    EXPECT_EQ(t.wrong_case, 0) << family;
    EXPECT_EQ(t.cases, n) << family;
    if (family == "physical_input") EXPECT_LT(double(t.slow), 1e-3 * double(t.cases)) << family;
  }
}

// Why the mode exists: the stable path, within its proven few ulps, is not
// correctly rounded on a sizeable share of the audio-rate inputs.
TEST(StableIsNotCorrectlyRounded, OnASizeableShareOfAudioRateInputs) {
  const tally t = measure<double>("physical_input", physical_input<double>(), 20000);
  std::printf("stable not correctly rounded on %ld of %ld audio-rate inputs (%.3g)\n", t.stable_not_rounded, t.cases,
              double(t.stable_not_rounded) / double(t.cases));
  RecordProperty("stable_not_correctly_rounded", std::to_string(t.stable_not_rounded));
  EXPECT_GT(t.stable_not_rounded, t.cases / 20);
  EXPECT_EQ(t.wrong, 0);
}

// ---- the committed hard cases -----------------------------------------------------

struct hard_case {
  std::string line;
  double u, dy, phi, s;
  contact_case which;
};

// Every line "u dy phi expected_s expected_case" of tests/rounded_hard_cases/NAME.txt.
std::vector<hard_case> read_hard_cases(const std::string& name) {
  const std::string path = std::string(CONTACT_ROUNDED_HARD_CASES) + "/" + name + ".txt";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<hard_case> cases;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string text[5];
    for (auto& field : text) fields >> field;
    auto number = [](const std::string& t) { return std::strtod(t.c_str(), nullptr); };  // hex and inf, exactly
    cases.push_back({line, number(text[0]), number(text[1]), number(text[2]), number(text[3]),
                     static_cast<contact_case>(std::stoi(text[4]))});
  }
  return cases;
}

const char* const hard_case_files[] = {"exact_ties_contact", "exact_ties_release", "exact_ties_impact", "near_ties",
                                       "range_edges", "subnormal_phi"};

class RoundedHardCases : public ::testing::TestWithParam<const char*> {};
INSTANTIATE_TEST_SUITE_P(, RoundedHardCases, ::testing::ValuesIn(hard_case_files),
                         [](const auto& info) { return std::string(info.param); });

// Each listed input gives its expected step bit for bit, and the expected value
// is still what the reference says (the list cannot drift from it).
TEST_P(RoundedHardCases, EveryLineGivesItsExpectedStep) {
  const auto cases = read_hard_cases(GetParam());
  EXPECT_GE(cases.size(), 30u);
  for (const auto& c : cases) {
    const auto r = solve_rounded(c.u, c.dy, c.phi);
    EXPECT_TRUE(r.s == c.s || (std::isnan(r.s) && std::isnan(c.s))) << c.line << "\n  got " << r.s;
    EXPECT_EQ(std::signbit(r.s), std::signbit(c.s)) << c.line;
    EXPECT_EQ(r.which, c.which) << c.line;
    const auto exact = reference::solve(c.u, c.dy, c.phi);
    EXPECT_TRUE(correctly_rounded(c.s, exact, c.u, c.dy, c.phi)) << c.line << "\n  the reference root is " << exact.s.to_string(40);
    EXPECT_EQ(exact.which, c.which) << c.line;
  }
}

// The tie files hold exact ties: the root is a midpoint, and the answer is the
// even neighbour (its last significand bit is 0).
TEST(RoundedTies, TiesGoToTheEvenNeighbour) {
  for (const char* name : {"exact_ties_contact", "exact_ties_release", "exact_ties_impact"})
    for (const auto& c : read_hard_cases(name)) {
      const auto exact = reference::solve(c.u, c.dy, c.phi);
      reference::real at_54(54);
      EXPECT_EQ(mpfr_set(at_54.get(), exact.s.get(), MPFR_RNDN), 0) << c.line;   // 54 bits: a midpoint ...
      reference::real at_53(53);
      EXPECT_NE(mpfr_set(at_53.get(), exact.s.get(), MPFR_RNDN), 0) << c.line;   // ... and no double
      int exponent = 0;
      const double significand = std::frexp(std::fabs(c.s), &exponent);
      EXPECT_EQ(std::fmod(std::ldexp(significand, 53), 2.0), 0.0) << c.line;  // even
    }
}

// ---- properties -------------------------------------------------------------------

template <class T>
class RoundedProperty : public ::testing::Test {};
TYPED_TEST_SUITE(RoundedProperty, rounded_types, type_names_for_gtest);

// Rounding is monotonic and the root does not increase with u, so neither does s.
TYPED_TEST(RoundedProperty, StepDoesNotIncreaseWithU) {
  using T = TypeParam;
  check_property<T>("rounded monotonicity", [] {
    const auto x = *any_input<T>();
    const T other_u = *rc::gen::oneOf(any_finite<T>(), rc::gen::just(T(detail::next_up(x.u))));
    using std::isfinite;
    RC_PRE(isfinite(other_u));
    const T lower_u = x.u < other_u ? x.u : other_u, upper_u = x.u < other_u ? other_u : x.u;
    const T at_lower = solve_rounded(lower_u, x.dy, x.phi).s, at_upper = solve_rounded(upper_u, x.dy, x.phi).s;
    RC_LOG() << x << " u1=" << lower_u << " s1=" << at_lower << " u2=" << upper_u << " s2=" << at_upper << "\n";
    RC_ASSERT(at_lower >= at_upper);
  });
}

// Within half an ulp of the root, so within stable's bound + 0.5 ulp of stable.
TYPED_TEST(RoundedProperty, AgreesWithStableWithinItsBoundAndHalfAnUlp) {
  using T = TypeParam;
  check_property<T>("rounded vs stable", [] {
    const auto x = *any_input<T>();
    const auto exact = reference_for(x);
    RC_PRE(root_is_finite_in<T>(exact));
    const auto stable = solve_stable(x.u, x.dy, x.phi);
    const auto rounded = solve_rounded(x.u, x.dy, x.phi);
    using std::isfinite;
    RC_PRE(isfinite(stable.s) && isfinite(rounded.s));
    reference::real difference = as_real(rounded.s);
    mpfr_sub(difference.get(), difference.get(), as_real(stable.s).get(), MPFR_RNDN);
    RC_LOG() << x << " stable=" << stable.s << " rounded=" << rounded.s << "\n";
    RC_ASSERT(rounded.which == stable.which);
    RC_ASSERT(in_ulps<T>(difference, exact.s) <= stable_bound_for(stable.which, x.u) + 0.5);
  });
}

// Scaling u and dy by 2^k scales the root by 2^k, and rounding commutes with
// that wherever the results are normal: s scales exactly.
TYPED_TEST(RoundedProperty, ScalingUAndDyByPowerOfTwoScalesStepExactly) {
  using T = TypeParam;
  check_property<T>("rounded homogeneity", [] {
    assert_scaling_by_power_of_two_scales_step<T>([](const T& u, const T& dy, const T& phi) { return solve_rounded(u, dy, phi); },
                                                  false);
  });
}

// Complementarity holds weakly: the rounded root may be dy itself where the
// root lies within half an ulp of it, never beyond.
TYPED_TEST(RoundedProperty, StepLiesWeaklyOnItsCasesSide) {
  using T = TypeParam;
  check_property<T>("weak complementarity", [] {
    const auto x = *any_input<T>();
    const auto r = solve_rounded(x.u, x.dy, x.phi);
    RC_LOG() << x << " s=" << r.s << " case=" << int(r.which) << "\n";
    switch (r.which) {
      case contact_case::free: RC_ASSERT(r.s >= x.dy); break;
      case contact_case::release: RC_ASSERT(r.s >= x.dy); break;
      case contact_case::impact: RC_ASSERT(r.s <= x.dy); break;
      case contact_case::contact: RC_ASSERT(r.s <= x.dy); break;
      default: RC_FAIL("invalid case for a valid input");
    }
  });
}

TYPED_TEST(RoundedProperty, ZeroStiffnessGivesMinusU) {
  using T = TypeParam;
  check_property<T>("rounded phi = 0", [] {
    const T u = *any_finite<T>(), dy = *any_finite<T>();
    RC_ASSERT(solve_rounded(u, dy, T(0)).s == -u);
  });
}

TYPED_TEST(RoundedProperty, InvalidInputGivesNaNAndTheInvalidCase) {
  using T = TypeParam;
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  const T bad[][3] = {{nan, 1, 1}, {1, nan, 1}, {1, 1, nan}, {inf, 1, 1}, {1, -inf, 1}, {1, 1, inf}, {1, 1, -1}};
  for (const auto& x : bad) {
    const auto r = solve_rounded(x[0], x[1], x[2]);
    using std::isnan;
    EXPECT_TRUE(isnan(r.s));
    EXPECT_EQ(r.which, contact_case::invalid);
  }
}

// Inputs inside the plain window whose s0 is not: the wider type's step takes over
// where T has one (double), else the exact decision. (A.30) s ~ -u / (1 + phi) below
// the window, (A.31) s ~ eps dy below it (cancellation beyond p bits), (A.32) s ~
// sqrt(phi) dy above it.
TYPED_TEST(RoundedProperty, StepsOutsideTheWindowGoToTheWiderStepOrTheExactDecision) {
  using T = TypeParam;
  using std::ldexp;
  const long w = detail::safe_window<T>::half_width();
  const T eps = std::numeric_limits<T>::epsilon();
  const T inputs[][3] = {{ldexp(T(1), int(-w + 10)), T(0), ldexp(T(1), int(w - 10))},
                         {ldexp(T(1), int(-w + 41)), ldexp(T(1), int(-w + 40)), T(1 + eps)},
                         {T(0), ldexp(T(1), int(w - 10)), ldexp(T(1), int(w - 10))}};
  for (const auto& x : inputs) {
    const auto traced = detail::solve_rounded_traced(x[0], x[1], x[2]);
    const auto exact = reference::solve(x[0], x[1], x[2]);
    EXPECT_TRUE(correctly_rounded(traced.result.s, exact, x[0], x[1], x[2])) << x[0] << " " << x[1] << " " << x[2];
    EXPECT_EQ(traced.result.which, exact.which);
    if constexpr (!std::is_same_v<T, float>)
      EXPECT_EQ(traced.exact_decision, std::is_void_v<typename detail::wider_step<T>::type>) << x[0] << " " << x[1] << " " << x[2];
  }
}

// ---- dispatch ---------------------------------------------------------------------

TEST(RoundedDispatch, SolveWithTheRoundedAlgorithmIsSolveRounded) {
  EXPECT_EQ(name_of(algorithm::rounded), "rounded");
  EXPECT_EQ(algorithms[3], algorithm::rounded);
  const auto a = solve(0x1.3a92a30554801p-11, 0x1.a36e2eb1c432dp-14, 3.0, algorithm::rounded);
  const auto b = solve_rounded(0x1.3a92a30554801p-11, 0x1.a36e2eb1c432dp-14, 3.0);
  EXPECT_EQ(a.s, b.s);
  EXPECT_EQ(a.which, b.which);
  EXPECT_EQ(solve(3.0f, 1.0f, 3.0f, algorithm::rounded).s, 0.75f);
}

// The multiprecision types have no rounded mode: asking for it is refused, not
// answered by another algorithm.
TEST(RoundedDispatch, TypesWithoutARoundedModeRefuseIt) {
  static_assert(rounded_available<float> && rounded_available<double> && rounded_available<long double> &&
                rounded_available<float128>);
  static_assert(!rounded_available<bin_float_50> && !rounded_available<bin_float_100> && !rounded_available<mpfr_float>);
  EXPECT_THROW(solve(bin_float_50(3), bin_float_50(1), bin_float_50(3), algorithm::rounded), std::invalid_argument);
  set_up_type<mpfr_float>();
  EXPECT_THROW(solve(mpfr_float(3), mpfr_float(1), mpfr_float(3), algorithm::rounded), std::invalid_argument);
}

// The exact decision on its own, from a candidate far from the root: the walk
// gets there from anywhere (here 1000 ulps off, and from the wrong side of dy).
TEST(RoundedExactDecision, WalksFromAFarCandidate) {
  const double u = 0x1.3a92a30554801p-11, dy = 0x1.a36e2eb1c432dp-14, phi = 3.0;
  const auto exact = reference::solve(u, dy, phi);
  double start = solve_stable(u, dy, phi).s;
  for (int i = 0; i < 1000; ++i) start = std::nextafter(start, 1.0);
  const solution<double> from{start, exact.which};
  const auto walked = detail::rounded_by_exact_decision(u, dy, phi, &from);
  EXPECT_TRUE(walked.exact_decision);
  EXPECT_TRUE(correctly_rounded(walked.result.s, exact, u, dy, phi));
}

// Roots beyond the overflow threshold, from the largest double: the walk's first
// step up reaches infinity (double's own inputs of this kind are decided before,
// by long double's step).
TEST(RoundedExactDecision, WalksUpToInfinity) {
  int overflowing = 0;
  for (const auto& c : read_hard_cases("range_edges")) {
    if (!std::isinf(c.s)) continue;
    ++overflowing;
    const solution<double> from{std::numeric_limits<double>::max(), c.which};
    const auto walked = detail::rounded_by_exact_decision(c.u, c.dy, c.phi, &from);
    EXPECT_EQ(walked.result.s, c.s) << c.line;
  }
  EXPECT_GE(overflowing, 5);
}

// A root within half an ulp above -max, from -max: the walk's step down reads the
// midpoint below -max, beyond which T's next value would lie (an impact with u =
// max and a soft phi: s = -u + e, 0 < e <= 2 phi u, far below an ulp of max).
TEST(RoundedExactDecision, WalksDownToTheLargestNegativeValue) {
  const double max = std::numeric_limits<double>::max(), u = max, dy = -1.0, phi = 0x1p-60;
  const solution<double> from{-max, contact_case::impact};
  const auto walked = detail::rounded_by_exact_decision(u, dy, phi, &from);
  EXPECT_EQ(walked.result.s, -max);
  EXPECT_TRUE(correctly_rounded(walked.result.s, reference::solve(u, dy, phi), u, dy, phi));
}

// Ties reached after walking: from 5 ulps below and 5 ulps above the tie, the
// walk crosses the midpoints one by one and stops at the tie's even neighbour.
TEST(RoundedExactDecision, WalksToATieFromEitherSide) {
  for (const char* name : {"exact_ties_contact", "exact_ties_release", "exact_ties_impact"}) {
    const auto cases = read_hard_cases(name);
    ASSERT_FALSE(cases.empty());
    for (const auto& c : {cases.front(), cases.back()}) {
      for (const double direction : {-1.0, 1.0}) {
        double start = c.s;
        for (int i = 0; i < 5; ++i) start = std::nextafter(start, direction * HUGE_VAL);
        const solution<double> from{start, c.which};
        const auto walked = detail::rounded_by_exact_decision(c.u, c.dy, c.phi, &from);
        EXPECT_EQ(walked.result.s, c.s) << c.line << " from " << start;
      }
    }
  }
}

}  // namespace
}  // namespace contact::testing

namespace contact::testing {
namespace {

// The fast path's constants are the ones proofs.gappa.rounded proves sufficient:
// proofs/rounded_bounds.txt holds both to the same figures.
TEST(RoundedFastPath, FixedBoundsAreTheProvenOnes) {
  std::ifstream in(CONTACT_ROUNDED_BOUNDS);
  ASSERT_TRUE(in) << CONTACT_ROUNDED_BOUNDS;
  std::map<std::string, double> code;
  auto add = [&code](const std::string& type, auto bounds) {  // rounded_form::fixed_bound_exponents<digits>
    using exponents = decltype(bounds);
    code["contact_" + type] = std::ldexp(1.0, exponents::contact);
    code["impact_" + type] = std::ldexp(1.0, exponents::impact);
    code["release_" + type] = std::ldexp(1.0, exponents::release);
  };
  add("float", rounded_form::fixed_bound_exponents<24>{});
  add("double", rounded_form::fixed_bound_exponents<53>{});
  add("long_double", rounded_form::fixed_bound_exponents<64>{});
  add("float128", rounded_form::fixed_bound_exponents<113>{});
  std::set<std::string> seen;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line.substr(0, line.find('#')));
    std::string name, value;
    if (!(fields >> name >> value)) continue;
    ASSERT_TRUE(code.count(name)) << "unknown name in rounded_bounds.txt: " << name;
    EXPECT_EQ(code.at(name), std::strtod(value.c_str(), nullptr)) << name;
    seen.insert(name);
  }
  EXPECT_EQ(seen.size(), code.size());
}

template <class T>
class RoundedFixedStep : public ::testing::Test {};
using fixed_step_types = ::testing::Types<double, long double, float128>;
TYPED_TEST_SUITE(RoundedFixedStep, fixed_step_types, type_names_for_gtest);

// The step's s0 is the stable formula's value bit for bit (the Gappa models take the
// stable path's proven bound for it), computed here to share its square root.
TYPED_TEST(RoundedFixedStep, StartsFromTheStableFormula) {
  using T = TypeParam;
  static_assert(rounded_form::has_fixed_bounds<T>);
  set_up_type<T>();
  std::mt19937_64 engine(20261123);
  std::uniform_int_distribution<int> exponent(-80, 80), sign(0, 1);
  std::uniform_real_distribution<double> significand(1, 2);
  auto draw = [&](bool positive) {
    const T x = std::ldexp(significand(engine), exponent(engine)) * (1 + T(significand(engine)) / 0x1p53);
    return positive || sign(engine) ? x : T(-x);
  };
  const int n = std::is_same_v<T, double> ? 200000 : 20000;
  long counts[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const T u = draw(false), dy = draw(false), phi = draw(true);
    T s0, stable;
    if (dy < 0 && u > -dy) {
      s0 = rounded_form::impact_step(u, dy, phi).s0;
      stable = stable_form::impact(u, T(-dy), phi);
      ++counts[0];
    } else if (dy > 0) {
      const bool contact = detail::stays_in_contact<true>(u, dy, phi);
      s0 = contact ? rounded_form::contact_step(u, dy, phi).s0 : rounded_form::release_step(u, dy, phi).s0;
      stable = contact ? stable_form::contact(u, dy, phi) : stable_form::release(u, dy, phi);
      ++counts[contact ? 1 : 2];
    } else {
      continue;
    }
    EXPECT_TRUE(s0 == stable) << u << " " << dy << " " << phi;
  }
  for (long count : counts) EXPECT_GT(count, n / 20);
}

// The fast path's tests of the window, of phi's sign and of the ends' equality
// read binary128's bits (its comparisons are library calls); they answer as
// the comparisons do, at each edge and on every special value.
TYPED_TEST(RoundedFixedStep, WindowTestsOnBitsAnswerAsComparisons) {
  using T = TypeParam;
  using std::fabs;
  using std::isnan;
  using std::ldexp;
  using limits = std::numeric_limits<T>;
  set_up_type<T>();
  const int w = int(detail::safe_window<T>::half_width());
  const T lowest = ldexp(T(1), -w), highest = ldexp(T(1), w);
  std::vector<T> values = {T(0), limits::denorm_min(), limits::min(), T(1), T(3) / 2, (limits::max)(),
                           limits::infinity(), limits::quiet_NaN()};
  for (const T& edge : {lowest, highest})
    for (const T& x : {detail::next_down(edge), edge, detail::next_up(edge)}) values.push_back(x);
  const std::size_t positive = values.size();
  for (std::size_t i = 0; i < positive; ++i) values.push_back(T(-values[i]));
  for (const T& x : values) {
    for (bool zero_allowed : {false, true}) {
      const bool expected = x == 0 ? zero_allowed : (lowest <= fabs(x) && fabs(x) <= highest);
      EXPECT_EQ(detail::in_fast_window(x, zero_allowed), expected) << x << (zero_allowed ? " (zero allowed)" : "");
    }
    if (!isnan(x)) EXPECT_EQ(detail::negative_phi(x), x < 0) << x;
    for (const T& y : values) {
      if (isnan(x) || isnan(y)) continue;
      T rounded;
      const bool alike = rounded_form::rounds_alike(rounded_form::fixed_step<T>{T(0), x, y}, rounded);
      EXPECT_EQ(alike, T(x - y) == T(x + y)) << x << " " << y;
    }
  }
}

// (A.30)'s margin widens as Q's two roots merge (u just above -dy with a large phi:
// s near dy, the other root at phi dy / (1 + phi)), and the result stays correctly
// rounded there.
TYPED_TEST(RoundedFixedStep, ImpactMarginWidensAsTheRootsMerge) {
  using T = TypeParam;
  using std::fabs;
  using std::ldexp;
  set_up_type<T>();
  const T one = 1, u = 1 + ldexp(one, -52), dy = -1, phi = ldexp(one, 40);
  const auto apart = rounded_form::impact_step(T(2), T(-0.5), one);
  const auto close = rounded_form::impact_step(u, dy, phi);
  EXPECT_GT(close.margin / fabs(close.s0), 1000 * (apart.margin / fabs(apart.s0)));
  const auto traced = detail::solve_rounded_traced(u, dy, phi);
  EXPECT_TRUE(correctly_rounded(traced.result.s, reference::solve(u, dy, phi), u, dy, phi));
}

// (A.31) with 2 phi dy and u equal to 40 bits: s ~ 2^-41 dy, and the margin stays
// K |s0|, as without a cancellation: the step decides, correctly rounded.
TYPED_TEST(RoundedFixedStep, ContactMarginIgnoresTheCancellation) {
  using T = TypeParam;
  using std::fabs;
  using std::ldexp;
  set_up_type<T>();
  const T one = 1, u = 2 - ldexp(one, -40);
  const auto step = rounded_form::contact_step(u, one, one);
  EXPECT_EQ(step.margin, ldexp(fabs(step.s0), rounded_form::fixed_bounds_of<T>::contact));
  const auto traced = detail::solve_rounded_traced(u, one, one);
  EXPECT_FALSE(traced.exact_decision);
  EXPECT_TRUE(correctly_rounded(traced.result.s, reference::solve(u, one, one), u, one, one));
}

// (A.31) where 2 phi dy and u agree to 44 bits and more: u = 2 phi dy (1 - 2^-k),
// k from 44 to 52, and u the nearest T to 2 phi dy moved by 0 to 3 values of T, so
// that N = 2 phi dy - u is down to the product's own rounding error. The step
// decides nearly all (a tie or a root within about 2^-40 ulp of a midpoint takes the
// exact decision, and so does an exact zero root, outside the window: in long double
// and float128, 2 phi dy is often a T value itself), every result correctly rounded.
TYPED_TEST(RoundedFixedStep, ContactStepDecidesCancellationsOfAnyDepth) {
  using T = TypeParam;
  using std::ldexp;
  set_up_type<T>();
  std::mt19937_64 engine(20261127);
  std::uniform_real_distribution<double> factor(0.25, 4);
  std::uniform_int_distribution<int> bits(44, 52), steps(0, 3);
  const int n = std::is_same_v<T, double> ? 5000 : 500;
  int exact_decisions = 0, contacts = 0;
  for (int i = 0; i < n; ++i) {
    const T phi = factor(engine), dy = factor(engine);
    const T u = i % 2 ? T(2 * phi * dy) * (1 - ldexp(T(1), -bits(engine)))
                      : detail::ulp_steps(T(2 * phi * dy), -steps(engine));
    if (!detail::stays_in_contact<true>(u, dy, phi)) continue;
    ++contacts;
    const auto traced = detail::solve_rounded_traced(u, dy, phi);
    exact_decisions += traced.exact_decision && traced.result.s != 0;
    EXPECT_TRUE(correctly_rounded(traced.result.s, reference::solve(u, dy, phi), u, dy, phi)) << u << " " << dy << " " << phi;
  }
  EXPECT_GT(contacts, n / 2);
  EXPECT_LE(exact_decisions, contacts / 100);
}

// An exact tie is never decided by the step: the root lies on a midpoint, inside
// the step's interval however narrow, so the exact decision gives the even neighbour.
TEST(RoundedFixedStep, ContactTiesGoToTheExactDecision) {
  const auto ties = read_hard_cases("exact_ties_contact");
  ASSERT_FALSE(ties.empty());
  int in_window = 0;
  for (const auto& tie : ties) {
    if (!detail::inside_plain_window(tie.u, tie.dy, tie.phi) || !detail::in_fast_window(tie.s, false)) continue;
    ++in_window;
    const auto traced = detail::solve_rounded_traced(tie.u, tie.dy, tie.phi);
    EXPECT_TRUE(traced.exact_decision) << tie.line;
    EXPECT_EQ(traced.result.s, tie.s) << tie.line;
  }
  EXPECT_GT(in_window, 0);
}

// Inside the window, on ordinary inputs, the step decides: the exact decision is
// left to the rare inputs whose root lies near a midpoint.
TYPED_TEST(RoundedFixedStep, DecidesOrdinaryInputsWithoutTheExactDecision) {
  using T = TypeParam;
  set_up_type<T>();
  const T inputs[][3] = {{T(0.25), T(1), T(3)}, {T(3), T(1), T(0.5)}, {T(2), T(-0.5), T(1)}, {T(-1), T(1), T(1)}};
  for (const auto& x : inputs) {
    const auto traced = detail::solve_rounded_traced(x[0], x[1], x[2]);
    EXPECT_FALSE(traced.exact_decision) << x[0] << " " << x[1] << " " << x[2];
    EXPECT_TRUE(correctly_rounded(traced.result.s, reference::solve(x[0], x[1], x[2]), x[0], x[1], x[2]));
  }
}

// float's fast path (the stable formulas in double, both ends of the bound rounded to
// float) decides beyond float's range and among its subnormals too: where both ends
// round to infinity, or to one subnormal, so does the root; where they straddle the
// overflow threshold, the exact decision decides.
TEST(RoundedFloat, FastPathDecidesOverflowAndSubnormals) {
  const float overflow[3] = {-3e38f, 1e38f, 100.0f};  // (A.32), s about 1.2e39
  const float subnormal[3] = {-1e-40f, 1e-30f, 1e-10f};  // (A.31), s about 1e-40
  for (const auto& x : {overflow, subnormal}) {
    const auto traced = detail::solve_rounded_traced(x[0], x[1], x[2]);
    EXPECT_FALSE(traced.exact_decision) << x[0] << " " << x[1] << " " << x[2];
    EXPECT_TRUE(correctly_rounded(traced.result.s, reference::solve(x[0], x[1], x[2]), x[0], x[1], x[2]));
  }
  EXPECT_TRUE(std::isinf(solve_rounded(overflow[0], overflow[1], overflow[2]).s));
  EXPECT_EQ(std::fpclassify(solve_rounded(subnormal[0], subnormal[1], subnormal[2]).s), FP_SUBNORMAL);
  // (A.32) with s = sqrt(phi) dy = 2^128 (1 - 2^-25 - 2^-51 ...), 2^-51 below the overflow
  // threshold: one end rounds to infinity, the other to the largest float, so the exact
  // decision decides, from no candidate, and gives the largest float
  const float u = 0, dy = 0x1p126f, phi = 16 * (1 - 0x1p-24f);
  const auto near_threshold = detail::solve_rounded_traced(u, dy, phi);
  EXPECT_TRUE(near_threshold.exact_decision);
  EXPECT_EQ(near_threshold.result.s, std::numeric_limits<float>::max());
  EXPECT_TRUE(correctly_rounded(near_threshold.result.s, reference::solve(u, dy, phi), u, dy, phi));
}


// ---- double beyond its window: the wider type's step ------------------------------

using wide = detail::wider_step<double>::type;

// Where long double is wider than double and its window holds double's range (x87,
// binary128), double's inputs that its own step cannot take use long double's.
TEST(RoundedWiderStep, DoubleHasOneWhereLongDoubleIsWider) {
  if constexpr (std::numeric_limits<long double>::digits > 53 && std::numeric_limits<long double>::max_exponent > 4096)
    EXPECT_TRUE((std::is_same_v<wide, long double>));
  else
    EXPECT_TRUE((std::is_void_v<wide>));
}

// The rounding test on W's interval, on intervals made to measure: strictly
// between two midpoints it rounds, touching one it refuses; beyond the largest
// double the overflow threshold is the midpoint; a zero needs the root's sign.
TEST(RoundedWiderStep, RoundsOnlyIntervalsStrictlyBetweenMidpoints) {
  if constexpr (!std::is_void_v<wide>) {
    using step = rounded_form::fixed_step<wide>;
    const wide one = 1, ulp = std::numeric_limits<double>::epsilon(), tiny = one / (1ull << 62);
    const double largest = std::numeric_limits<double>::max();
    const wide max = largest, threshold = max + (max - wide(detail::next_down(largest))) / 2;
    const wide least = std::numeric_limits<double>::denorm_min();
    double rounded = 0;
    EXPECT_TRUE(detail::rounds_alike_in(step{one + ulp / 4, 0, ulp / 8}, rounded));
    EXPECT_EQ(rounded, 1.0);
    EXPECT_FALSE(detail::rounds_alike_in(step{one + ulp / 2, 0, 0}, rounded));           // on the midpoint
    EXPECT_FALSE(detail::rounds_alike_in(step{one + ulp / 2 - tiny, 0, tiny}, rounded));  // touching it
    EXPECT_FALSE(detail::rounds_alike_in(step{one - ulp / 4, 0, 0}, rounded));            // below 1 the gap halves
    EXPECT_TRUE(detail::rounds_alike_in(step{one - ulp / 8, 0, 0}, rounded));
    EXPECT_EQ(rounded, 1.0);
    EXPECT_TRUE(detail::rounds_alike_in(step{threshold * (1 - tiny), 0, 0}, rounded));
    EXPECT_EQ(rounded, largest);
    EXPECT_FALSE(detail::rounds_alike_in(step{threshold, 0, 0}, rounded));  // a tie, which goes to infinity
    EXPECT_TRUE(detail::rounds_alike_in(step{threshold * (1 + tiny), 0, 0}, rounded));
    EXPECT_EQ(rounded, std::numeric_limits<double>::infinity());
    EXPECT_TRUE(detail::rounds_alike_in(step{-threshold * (1 + tiny), 0, 0}, rounded));
    EXPECT_EQ(rounded, -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(detail::rounds_alike_in(step{-threshold * (1 - tiny), 0, 0}, rounded));
    EXPECT_EQ(rounded, -largest);
    EXPECT_TRUE(detail::rounds_alike_in(step{least / 4, 0, least / 8}, rounded));
    EXPECT_TRUE(rounded == 0 && !std::signbit(rounded));
    EXPECT_TRUE(detail::rounds_alike_in(step{-least / 4, 0, least / 8}, rounded));
    EXPECT_TRUE(rounded == 0 && std::signbit(rounded));
    EXPECT_FALSE(detail::rounds_alike_in(step{0, 0, least / 8}, rounded));  // either sign
    EXPECT_TRUE(detail::rounds_alike_in(step{least * 3 / 4, 0, least / 8}, rounded));
    EXPECT_EQ(rounded, std::numeric_limits<double>::denorm_min());
  }
}

// Inputs of double beyond its plain window, of the kinds the default scenes hold:
// roots beyond the largest double, roots that round to zero or to subnormals, (A.30)
// with its roots merged by a huge phi (where s0's own bound decides), and each case
// across the whole range. All correctly rounded, without the exact decision.
TEST(RoundedWiderStep, DecidesDoubleBeyondItsWindow) {
  if constexpr (!std::is_void_v<wide>) {
    const double inputs[][3] = {
        {-0x1p1000, 0x1p1000, 0x1p60},                                              // (A.32) beyond the largest double
        {-0x1.3dbaa455d755fp+1000, 0x1.7p1013, 0x1.2895b0feab1fp+20},               // (A.32) just below it
        {0x1p-1000, -0x1p-1070, 0x1p500},                                           // (A.30) rounds to -0
        {0x1.0bb0d908e3ce1p-1000, 0x1p-1060, 0x1p300},                              // (A.31) subnormal root
        {0x1.586434330bd8dp-837, -0x1.00d38a5b9755dp-929, 0x1.0245bd016e778p+285},  // (A.30) roots merged
        {0x1.2f65c5dcfe976p+731, -0x1.c383bfa2a2c0cp+684, 0x1.5fc5200b36796p+703},  // (A.30) roots merged
        {0x1.3e11c018d9ecfp-932, -0x1.4861p-1050, 0x1.17f38143ca2efp+813},          // (A.30) subnormal dy
        {-0x1.3dbaa455d755fp+542, 0x1.0bb0d908e3ce1p+521, 0x1p-700},                // (A.32) phi below the window
        {0x1.9e8fe1e522847p+504, 0x1.4052c91825b57p+514, 0x1.432ebdcfc2f7p-12}};    // (A.31) u, dy above the window
    for (const auto& x : inputs) {
      const auto traced = detail::solve_rounded_traced(x[0], x[1], x[2]);
      const auto exact = reference::solve(x[0], x[1], x[2]);
      EXPECT_FALSE(traced.exact_decision) << x[0] << " " << x[1] << " " << x[2];
      EXPECT_TRUE(correctly_rounded(traced.result.s, exact, x[0], x[1], x[2])) << x[0] << " " << x[1] << " " << x[2];
      EXPECT_EQ(traced.result.which, exact.which) << x[0] << " " << x[1] << " " << x[2];
    }
  }
}

// ---- beside an input: stiff and soft phi far beyond the window --------------------

// Draws uniform in [0, 1) and log-uniform in 2^[low, high].
struct log2_draws {
  std::mt19937_64 engine;
  explicit log2_draws(std::uint64_t seed) : engine(seed) {}
  double unit() { return std::uniform_real_distribution<double>(0, 1)(engine); }
  double log2_uniform(double low, double high) { return std::exp2(low + (high - low) * unit()); }
};

// Per case, how many of `count` inputs (draw) a shortcut `decide` (given the exact
// case: the value beside an input, or the moves below) rounds, each checked
// against the reference.
struct decided_tally {
  long decided[5] = {}, seen[5] = {}, wrong = 0;
};

template <class T, class Draw, class Decide>
decided_tally decided_against_reference(int count, Draw draw, Decide decide) {
  decided_tally t;
  for (int k = 0; k < count; ++k) {
    const auto [u, dy, phi] = draw();
    const auto exact = reference::solve(u, dy, phi);
    const int which = static_cast<int>(exact.which);
    ++t.seen[which];
    if (exact.which == contact_case::free) continue;
    const std::optional<T> decided = decide(u, dy, phi, exact.which);
    if (!decided) continue;
    ++t.decided[which];
    if (!correctly_rounded(*decided, exact, u, dy, phi) && ++t.wrong <= 5)
      ADD_FAILURE() << std::hexfloat << "u=" << double(u) << " dy=" << double(dy) << " phi=" << double(phi) << ": "
                    << double(*decided) << ", exact root " << exact.s.to_string(40);
  }
  return t;
}

// Physical u and dy (some of them powers of two, where the gap below halves) with
// phi log-uniform over the binades [lowest_binade, highest_binade], as the phi
// scene draws them: a draw for decided_against_reference.
template <class T>
auto physical_with_phi(std::uint64_t seed, int lowest_binade, int highest_binade) {
  return [random = std::mt19937_64(seed), lowest_binade, highest_binade]() mutable {
    auto uniform = [&](double low, double high) { return std::uniform_real_distribution<double>(low, high)(random); };
    auto physical = [&] {
      const T magnitude = (random() % 4 == 0) ? T(std::ldexp(1.0, int(uniform(-23, -10)))) : T(std::pow(10.0, uniform(-7, -3)));
      return random() % 2 ? magnitude : T(-magnitude);
    };
    const T u = physical(), dy = physical();
    return std::array<T, 3>{u, dy, T(std::ldexp(uniform(1, 2), int(uniform(lowest_binade, highest_binade))))};
  };
}

// With phi far above or below the plain window: how many the value beside an
// input decides.
template <class T>
decided_tally beside_an_input_on(std::uint64_t seed, int count, int lowest_binade, int highest_binade) {
  auto draw = physical_with_phi<T>(seed, lowest_binade, highest_binade);
  return decided_against_reference<T>(count, draw, [](const T& u, const T& dy, const T& phi, contact_case which) {
    return detail::rounded_beside_an_input(u, dy, phi, which);
  });
}

// Stiff phi (2^300 to 2^1000): every (A.30) rounds to dy (and the rare (A.31),
// u >= phi dy, to 2 dy); (A.32)'s root grows as sqrt(phi) |dy| and has no such value.
TEST(RoundedBesideAnInput, StiffImpactsRoundToDy) {
  const auto t = beside_an_input_on<double>(91, 20000, 300, 1000);
  EXPECT_EQ(t.wrong, 0);
  const int impact = static_cast<int>(contact_case::impact), contact = static_cast<int>(contact_case::contact);
  EXPECT_GT(t.seen[impact], 1000);
  EXPECT_EQ(t.decided[impact], t.seen[impact]);
  EXPECT_EQ(t.decided[contact], t.seen[contact]);
  EXPECT_EQ(t.decided[static_cast<int>(contact_case::release)], 0);
}

// Soft and subnormal phi (2^-1074 to 2^-300): every (A.31), (A.30) and (A.32)
// rounds to -u (a release there has u < -dy < 0).
TEST(RoundedBesideAnInput, SoftInputsRoundToMinusU) {
  const auto t = beside_an_input_on<double>(92, 20000, -1074, -300);
  EXPECT_EQ(t.wrong, 0);
  for (const auto which : {contact_case::contact, contact_case::impact, contact_case::release}) {
    const int c = static_cast<int>(which);
    EXPECT_GT(t.seen[c], 1000) << c;
    EXPECT_EQ(t.decided[c], t.seen[c]) << c;
  }
}

// Stiff phi with u far above |dy| and u / phi far below it: the root lies within
// sqrt(|dy| u / phi) + 3 u / phi of dy, far under half its gap. Every such
// (A.30) rounds to dy. (The looser bound 4 max(u, |dy|) / sqrt(phi) decides 285 of
// these 4,000.)
TEST(RoundedBesideAnInput, StiffImpactsWithUFarAboveDyRoundToDy) {
  log2_draws draw(20261131);
  const auto t = decided_against_reference<double>(
      4000,
      [&] {
        const double gap = draw.log2_uniform(-300, 300), ratio = draw.log2_uniform(100, 400);
        return std::tuple{gap * ratio, -gap, ratio * draw.log2_uniform(120, 300)};
      },
      [](double u, double dy, double phi, contact_case which) {
        return detail::rounded_beside_an_input(u, dy, phi, which);
      });
  EXPECT_EQ(t.wrong, 0);
  const int impact = static_cast<int>(contact_case::impact);
  EXPECT_EQ(t.seen[impact], 4000);
  EXPECT_EQ(t.decided[impact], t.seen[impact]);
}

// Physical u and dy under a stiff phi (2^300 to 2^1000), as the phi scene draws
// them, solved whole: inside long double's and float128's windows the step's
// (A.30) margin widens as the roots merge and its test fails, and the value
// beside dy decides instead; double, outside its window, takes it first. All
// correctly rounded, and fewer than 1 in 100 take the exact decision.
TYPED_TEST(RoundedFixedStep, StiffImpactsTheStepCannotDecideRoundToDy) {
  using T = TypeParam;
  long exact_decisions = 0;
  const auto t = decided_against_reference<T>(
      16000, physical_with_phi<T>(97, 300, 1000), [&](const T& u, const T& dy, const T& phi, contact_case) {
        const auto traced = detail::solve_rounded_traced(u, dy, phi);
        exact_decisions += traced.exact_decision;
        return std::optional<T>(traced.result.s);
      });
  const int impact = static_cast<int>(contact_case::impact);
  long solved = 0;
  for (const long decided : t.decided) solved += decided;
  EXPECT_EQ(t.wrong, 0);
  EXPECT_GT(t.seen[impact], 1800);  // (about one draw in eight)
  EXPECT_LE(exact_decisions, solved / 100);
}

// Near the window's edge the sliver is as wide as the gap: most inputs there are
// left to the step, and whatever is decided is right.
TEST(RoundedBesideAnInput, DecidesOnlyWhereTheSliverIsNarrowerThanHalfTheGap) {
  const auto t = beside_an_input_on<double>(93, 20000, -60, 60);
  EXPECT_EQ(t.wrong, 0);
  long decided = 0, seen = 0;
  for (int c = 2; c <= 4; ++c) decided += t.decided[c], seen += t.seen[c];
  EXPECT_GT(decided, 0);
  EXPECT_LT(decided, seen / 2);
}

// The value beside the root is taken only where it is a finite, non-zero T, in
// every type with a fast path.
TYPED_TEST(RoundedFixedStep, NeitherZeroNorInfinityIsTheValueBeside) {
  using T = TypeParam;
  const T big = (std::numeric_limits<T>::max)(), small = T(1e-5), stiff = T(0x1p1000), soft = T(0x1p-1000);
  EXPECT_FALSE(detail::rounded_beside_an_input(T(-T(0)), small, soft, contact_case::contact));  // r = -u = +0
  EXPECT_FALSE(detail::rounded_beside_an_input(small, big, stiff, contact_case::contact));      // r = 2 dy overflows
  EXPECT_FALSE(detail::rounded_beside_an_input(small, T(0), stiff, contact_case::impact));      // r = dy = 0
  EXPECT_FALSE(detail::rounded_beside_an_input(small, T(-small), T(0.5), contact_case::impact));  // phi in (1/4, 1)
  EXPECT_FALSE(detail::rounded_beside_an_input(small, small, stiff, contact_case::release));    // u > 0: no value beside
  EXPECT_EQ(detail::rounded_beside_an_input(small, T(-small / 2), stiff, contact_case::impact), T(-small / 2));  // r = dy
  EXPECT_FALSE(detail::rounded_beside_an_input(small, T(-small / 2), T(4), contact_case::impact));  // sliver too wide
  EXPECT_EQ(detail::rounded_beside_an_input(small, small, T(0), contact_case::contact), T(-small));  // phi = 0: s = -u
}

// An exact tie moved beyond double's window (homogeneity: u and dy times 2^600
// move the root, a midpoint, by 2^600) stays a tie, which no interval of W can
// place on one side: the exact decision decides it, to the even neighbour.
TEST(RoundedWiderStep, LeavesTiesBeyondTheWindowToTheExactDecision) {
  if constexpr (!std::is_void_v<wide>) {
    int moved = 0;
    for (const char* name : {"exact_ties_contact", "exact_ties_release", "exact_ties_impact"})
      for (const auto& tie : read_hard_cases(name)) {
        for (const int shift : {600, -600}) {
          const double u = std::ldexp(tie.u, shift), dy = std::ldexp(tie.dy, shift), s = std::ldexp(tie.s, shift);
          if (!std::isnormal(u) || !std::isnormal(dy) || !std::isnormal(s) || detail::inside_plain_window(u, dy, tie.phi))
            continue;
          ++moved;
          const auto traced = detail::solve_rounded_traced(u, dy, tie.phi);
          EXPECT_TRUE(traced.exact_decision) << tie.line;
          EXPECT_EQ(traced.result.s, s) << tie.line;
        }
      }
    EXPECT_GE(moved, 30);
  }
}

// ---- moved into the window ----------------------------------------------------------

// u and dy of either sign, their binades drawn from [u_low, u_high] and [dy_low,
// dy_high], phi's from [phi_low, phi_high]: per case, how many the moves decide.
decided_tally moves_on(std::uint64_t seed, int count, std::array<int, 2> u_binades, std::array<int, 2> dy_binades,
                      std::array<int, 2> phi_binades) {
  std::mt19937_64 random(seed);
  auto uniform = [&](double low, double high) { return std::uniform_real_distribution<double>(low, high)(random); };
  auto in = [&](std::array<int, 2> binades) { return std::ldexp(uniform(1, 2), int(uniform(binades[0], binades[1] + 1))); };
  auto draw = [&] {
    const double u = in(u_binades), dy = in(dy_binades);
    return std::array<double, 3>{random() % 2 ? u : -u, random() % 2 ? dy : -dy, in(phi_binades)};
  };
  return decided_against_reference<double>(count, draw, [](double u, double dy, double phi, contact_case which) {
    return detail::rounded_by_moves(u, dy, phi, which);
  });
}

// (A.32) with phi far above the window: dy moves by 2^j and phi by 2^-2j, which
// keeps its polynomial, into [1, 4). (Up to phi = 2^900: beyond, dy 2^j lies too
// far above these u for one window.) (A.30)'s own move of phi (below) needs u
// far above |dy|, which these impacts never have.
TEST(RoundedByMoves, StiffReleasesMovePhiIntoTheWindow) {
  const auto t = moves_on(94, 20000, {-23, -10}, {-23, -10}, {241, 900});
  EXPECT_EQ(t.wrong, 0);
  const int release = static_cast<int>(contact_case::release);
  EXPECT_GT(t.seen[release], 4000);
  EXPECT_EQ(t.decided[release], t.seen[release]);
  EXPECT_EQ(t.decided[static_cast<int>(contact_case::impact)], 0);  // (u and |dy| too close for (A.30)'s move)
}

// u and dy far above or below the window, phi inside it: homogeneity moves them
// by one power of two, and the root back. Every case is decided but where its
// root leaves the normal range or lies too near a midpoint.
TEST(RoundedByMoves, FarMagnitudesMoveIntoTheWindow) {
  for (const auto& [seed, low, high] : {std::array<int, 3>{95, 300, 1000}, std::array<int, 3>{96, -1000, -300}}) {
    const auto t = moves_on(seed, 20000, {low, high}, {low, high}, {-200, 200});
    EXPECT_EQ(t.wrong, 0);
    for (const auto which : {contact_case::contact, contact_case::impact, contact_case::release}) {
      const int c = static_cast<int>(which);
      EXPECT_GT(t.seen[c], 1000) << c;
      EXPECT_GT(t.decided[c], t.seen[c] * 8 / 10) << c;
    }
  }
}

// (A.31) with phi beyond the window either way and u near the scale of 2 phi dy
// (so that the value beside an input does not decide): phi moves near 2^220 or
// 2^-220, which changes the root by less than 2^-219 of it, and the margin,
// doubled, covers that. Every contact is decided, and correctly rounded (a root
// among the subnormals is left to the wider step: EachEdgeIsDecidedOrLeftAsDocumented).
TEST(RoundedByMoves, ContactsMovePhiIntoTheWindow) {
  log2_draws draw(20261128);
  int k = 0;
  const auto t = decided_against_reference<double>(
      4000,
      [&] {
        const double dy = draw.log2_uniform(-30, 30);
        const double phi = ++k % 2 ? draw.log2_uniform(241, 900) : draw.log2_uniform(-900, -241);  // normal roots
        const double u = phi > 1 ? dy * phi * (1 + draw.unit()) : 2 * phi * dy * (4 * draw.unit() - 2);
        return std::tuple{u, dy, phi};
      },
      [](double u, double dy, double phi, contact_case which) { return detail::rounded_by_moves(u, dy, phi, which); });
  EXPECT_EQ(t.wrong, 0);
  const int contact = static_cast<int>(contact_case::contact);
  EXPECT_GT(t.seen[contact], 3000);
  EXPECT_EQ(t.decided[contact], t.seen[contact]);
}

// (A.30) with a stiff phi and u / phi far above |dy| (the root near -u / phi, where
// the value beside dy does not decide): phi moves near 2^220 with u, which moves the root by
// far less than the impact margin. Every such impact is decided, correctly rounded.
TEST(RoundedByMoves, StiffImpactsMovePhiIntoTheWindow) {
  log2_draws draw(20261129);
  const auto t = decided_against_reference<double>(
      4000,
      [&] {
        const double dy = -draw.log2_uniform(-30, 30), phi = draw.log2_uniform(241, 700);
        return std::tuple{-dy * phi * draw.log2_uniform(4, 250), dy, phi};  // u / phi >= 2^4 |dy|: s near -u / phi
      },
      [](double u, double dy, double phi, contact_case which) { return detail::rounded_by_moves(u, dy, phi, which); });
  EXPECT_EQ(t.wrong, 0);
  const int impact = static_cast<int>(contact_case::impact);
  EXPECT_GT(t.seen[impact], 3000);
  EXPECT_GT(t.decided[impact], t.seen[impact] * 99 / 100);
}

// (A.30) with phi |dy| far below u (at most 2^-480 of it), phi soft to stiff: dy
// is left out, which moves the root by less than 2^-233 of it, and the margin,
// doubled, covers that. Every such impact is decided, correctly rounded.
TEST(RoundedByMoves, ImpactsLeaveOutADyFarBelowU) {
  log2_draws draw(20261130);
  const auto t = decided_against_reference<double>(
      4000,
      [&] {
        const double u = draw.log2_uniform(300, 1000), phi = draw.log2_uniform(-200, 300);
        return std::tuple{u, -u / std::max(phi, 1.0) * draw.log2_uniform(-700, -480), phi};
      },
      [](double u, double dy, double phi, contact_case which) { return detail::rounded_by_moves(u, dy, phi, which); });
  EXPECT_EQ(t.wrong, 0);
  const int impact = static_cast<int>(contact_case::impact);
  EXPECT_EQ(t.seen[impact], 4000);
  EXPECT_EQ(t.decided[impact], t.seen[impact]);
}

// Zeros move too, a root beyond the largest double is infinite, and u or dy far
// below the other is left out where the case allows; what cannot move, or cannot
// move back, is left to the wider step.
TEST(RoundedByMoves, EachEdgeIsDecidedOrLeftAsDocumented) {
  struct example {
    double u, dy, phi;
    bool decided;
  };
  const example examples[] = {
      {0, 0x1p600, 0.5, true},                        // (A.31), u = 0
      {0x1p600, 0, 3, true},                          // (A.30), dy = 0: s = -u / (1 + phi)
      {0x1p600, -0x1p-600, 0.5, true},                // (A.30), dy far below u: left out, the margin doubled
      {0x1p600, -0x1p-600, 0x1p700, true},            // (A.30), likewise, with phi moved to 2^220 and u with it
      {0x1p-600, 0x1p600, 0.5, true},                 // (A.31), u far below dy: left out, the margin doubled
      {0x1p600, 0x1p-600, 0x1p-300, true},            // (A.31), dy far below u: left out likewise
      {0x1p-600, 0x1p600, 0, false},                  // (A.31) with phi = 0: s = -u, u not left out
      {0x1p700, 0x1p300, 0x1p300, true},              // (A.31), phi beyond the window: to 2^220, u with it
      {0x1p-300, 0x1p300, 0x1p-600, true},            // (A.31), phi below it: to 2^-220, dy the other way
      {0x1p700, -0x1p300, 0x1p300, true},             // (A.30), phi beyond the window: to 2^220, u with it
      {0x1p301, -0x1p300, 0x1p300, false},            // (A.30), u too close to |dy| for that move
      {0x1p700, -0x1p300, 0x1p-300, false},           // (A.30), a soft phi: beside -u, never moved
      {0x1p-1050, 0x1p-1049, 0.5, false},             // (A.31), its root subnormal
      {0x1p700, 0x1p1000, 0x1p100, true},             // (A.32), its root beyond the largest double: infinity
      {0x1p-600, 0x1p300, 0x1p100, true},             // (A.32), u far below 2^j dy: left out, the margin doubled
      {0x1p-600, 0x1p300, 0.5, true},                 // (A.31), u as far below dy: left out too
      {0x1.8p-600, 0x1p-600, 0x1.8p-1, false}};       // (A.31), a root of exactly 0
  for (const auto& x : examples) {
    const auto exact = reference::solve(x.u, x.dy, x.phi);
    const auto moved = detail::rounded_by_moves(x.u, x.dy, x.phi, exact.which);
    EXPECT_EQ(moved.has_value(), x.decided) << x.u << " " << x.dy << " " << x.phi;
    if (moved) EXPECT_TRUE(correctly_rounded(*moved, exact, x.u, x.dy, x.phi)) << x.u << " " << x.dy << " " << x.phi;
  }
  // an exact tie moved beyond the window stays a tie, which the step leaves undecided
  int ties = 0;
  for (const char* name : {"exact_ties_contact", "exact_ties_release", "exact_ties_impact"})
    for (const auto& tie : read_hard_cases(name)) {
      const double u = std::ldexp(tie.u, 600), dy = std::ldexp(tie.dy, 600);
      if (!std::isnormal(u) || !std::isnormal(dy)) continue;
      ++ties;
      EXPECT_FALSE(detail::rounded_by_moves(u, dy, tie.phi, detail::exact_case(u, dy, tie.phi))) << tie.line;
    }
  EXPECT_GE(ties, 10);
}

}  // namespace
}  // namespace contact::testing
