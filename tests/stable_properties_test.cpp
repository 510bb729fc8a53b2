// The properties the stable algorithm claims, for every scalar type, each
// checked by RapidCheck (with shrinking) on the generators of harness.hpp.
#include <array>
#include <thread>
#include <vector>

#include "harness.hpp"

namespace contact::testing {
namespace {

template <class T>
class StableProperty : public ::testing::Test {};
TYPED_TEST_SUITE(StableProperty, all_types, type_names_for_gtest);

// The forward error against the certified reference is within the bound that
// Gappa proves for the branch taken, whenever the exact root is a finite T.
TYPED_TEST(StableProperty, ForwardErrorWithinProvenBound) {
  using T = TypeParam;
  check_property<T>("forward error", [] {
    const auto x = *any_input<T>();
    const auto exact = reference_for(x);
    RC_PRE(root_is_finite_in<T>(exact));
    const auto computed = solve_stable(x.u, x.dy, x.phi);
    const double error = reference::ulp_error(computed.s, exact);
    RC_LOG() << x << " exact=" << exact.s.to_string(25) << " error=" << error << " ulp\n";
    RC_ASSERT(error <= stable_bound_for(computed.which, x.u));
  });
}

// The case is decided exactly: it is the reference's case, on every input.
TYPED_TEST(StableProperty, CaseIsTheExactCase) {
  using T = TypeParam;
  check_property<T>("exact case", [] {
    const auto x = *any_input<T>();
    RC_ASSERT(solve_stable(x.u, x.dy, x.phi).which == reference_for(x).which);
  });
}

// Complementarity: the returned s lies on the side of dy that its case claims
// (s >= dy, s < dy, s <= dy, s > dy), exactly, in T.
TYPED_TEST(StableProperty, ReturnedStepLiesOnItsCasesSide) {
  using T = TypeParam;
  check_property<T>("complementarity", [] {
    const auto x = *any_input<T>();
    const auto computed = solve_stable(x.u, x.dy, x.phi);
    RC_LOG() << x << " s=" << computed.s << " case=" << int(computed.which) << "\n";
    RC_ASSERT(lies_on_its_side(computed.which, computed.s, x.dy));
  });
}

// The residual of (A.2), evaluated exactly at the computed s, is what a forward
// error within the bound allows: |R(s)| <= max R' over [s, s*] * bound ulps.
// R is linear or concave on each side of the kink, so R' over the segment is at
// most its value at the ends or at the kink.
TYPED_TEST(StableProperty, ResidualAtComputedStepWithinRoundingBound) {
  using T = TypeParam;
  check_property<T>("residual", [] {
    const auto x = *any_input<T>();
    const auto exact = reference_for(x);
    RC_PRE(root_is_finite_in<T>(exact));
    const auto computed = solve_stable(x.u, x.dy, x.phi);
    using std::isfinite;
    RC_PRE(isfinite(computed.s) && computed.s != 0);
    const reference::real s = as_real(computed.s);
    reference::real residual = reference::residual_at(s, x.u, x.dy, x.phi);
    reference::real slope = reference::slope_at(s, x.dy, x.phi);
    for (const auto& other : {reference::slope_at(exact.s, x.dy, x.phi), reference::slope_at(as_real(x.dy), x.dy, x.phi)})
      if (mpfr_cmp(other.get(), slope.get()) > 0) mpfr_set(slope.get(), other.get(), MPFR_RNDN);  // both exact_bits wide
    // |R(s)| / R'max in ulps of T at the root: at most the forward error bound
    mpfr_div(residual.get(), residual.get(), slope.get(), MPFR_RNDU);
    const double residual_ulps = in_ulps<T>(residual, exact.s);
    RC_LOG() << x << " residual/slope=" << residual_ulps << " ulp\n";
    RC_ASSERT(residual_ulps <= stable_bound_for(computed.which, x.u) * (1 + 1e-9));
  });
}

// Continuity: the solutions at two inputs straddling a case boundary differ by
// no more than |du| (|ds/du| <= 1 since dR/ds >= 1 and dR/du = 1) plus the two
// rounding bounds.
TYPED_TEST(StableProperty, SolutionIsContinuousAcrossCaseBoundaries) {
  using T = TypeParam;
  check_property<T>("continuity", [] {
    const auto x = *boundary_input<T>();
    using std::fabs;
    using std::isfinite;
    using std::ldexp;
    RC_PRE(harness::in_reference_range(x.u));
    const T below = detail::next_down(x.u), above = detail::next_up(x.u);
    RC_PRE(isfinite(below) && isfinite(above));
    const auto low = solve_stable(below, x.dy, x.phi), high = solve_stable(above, x.dy, x.phi);
    RC_PRE(isfinite(low.s) && isfinite(high.s));
    const T larger = std::max(T(fabs(low.s)), T(fabs(high.s)));
    const double allowed = in_ulps<T>(as_real(T(above - below)), as_real(larger)) + 2 * stable_bound_any() +
                           2 * unfused_fma_allowance<T>;
    RC_LOG() << x << " s-=" << low.s << " s+=" << high.s << "\n";
    RC_ASSERT(ulps_apart(low.s, high.s) <= allowed * (1 + 1e-12));
  });
}

// Monotonicity: s does not increase with u, up to the two rounding bounds.
TYPED_TEST(StableProperty, StepDoesNotIncreaseWithU) {
  using T = TypeParam;
  check_property<T>("monotonicity", [] {
    const auto x = *any_input<T>();
    const T other_u = *any_finite<T>();
    const T lower_u = x.u < other_u ? x.u : other_u, upper_u = x.u < other_u ? other_u : x.u;
    const auto at_lower = solve_stable(lower_u, x.dy, x.phi), at_upper = solve_stable(upper_u, x.dy, x.phi);
    RC_LOG() << x << " u1=" << lower_u << " s1=" << at_lower.s << " u2=" << upper_u << " s2=" << at_upper.s << "\n";
    if (at_lower.s >= at_upper.s) return;
    using std::isfinite;
    RC_PRE(isfinite(at_lower.s) && isfinite(at_upper.s));
    RC_ASSERT(ulps_apart(at_lower.s, at_upper.s) <= 2 * stable_bound_any() + 2 * unfused_fma_allowance<T>);
  });
}

// Homogeneity: scaling u and dy by 2^k scales s by 2^k exactly, whether or not
// the scaling moves the input across the plain/scaled window, as long as s
// stays a normal number.
TYPED_TEST(StableProperty, ScalingUAndDyByPowerOfTwoScalesStepExactly) {
  using T = TypeParam;
  check_property<T>("homogeneity", [] {
    assert_scaling_by_power_of_two_scales_step<T>([](const T& u, const T& dy, const T& phi) { return solve_stable(u, dy, phi); },
                                                  true);
  });
}

// phi = 0 removes the barrier: s = -u exactly, whatever dy.
TYPED_TEST(StableProperty, ZeroStiffnessGivesMinusU) {
  using T = TypeParam;
  check_property<T>("phi = 0", [] {
    const T u = *any_finite<T>(), dy = *any_finite<T>();
    RC_ASSERT(solve_stable(u, dy, T(0)).s == -u);
  });
}

// A stiff barrier approaches the rigid one: arriving at the barrier stops at it
// (|s - dy| <= sqrt(|dy| (u + dy) / (1 + phi)) + |2 dy + u| / (1 + phi)); in
// persistent contact s -> 2 dy (|s - 2 dy| = |u + 2 dy| / (1 + phi) exactly);
// leaving contact, s -> sqrt(phi) dy (0 <= sqrt(u^2 + 4 phi dy^2) - 2 sqrt(phi) dy <= |u|).
// Evaluated in T, with a few of T's roundings as slack.
TYPED_TEST(StableProperty, StiffBarrierApproachesRigidLimit) {
  using T = TypeParam;
  check_property<T>("rigid limit", [] {
    const auto x = *physical_input<T>();
    const T phi = *log_uniform<T>(60, std::min<long>(200, harness::highest_exponent<T>() - 10));
    const auto computed = solve_stable(x.u, x.dy, phi);
    using std::fabs;
    using std::sqrt;
    const T &u = x.u, &dy = x.dy, &s = computed.s;
    const T rigid_release = sqrt(phi) * dy;
    const T slack = 16 * std::numeric_limits<T>::epsilon() * (fabs(s) + fabs(dy) + fabs(u) + fabs(rigid_release));
    RC_LOG() << x << " phi=" << phi << " s=" << s << " case=" << int(computed.which) << "\n";
    switch (computed.which) {
      case contact_case::impact:
        RC_ASSERT(fabs(s - dy) <= sqrt(fabs(dy) * (u + dy) / (1 + phi)) + fabs(2 * dy + u) / (1 + phi) + slack);
        break;
      case contact_case::contact: RC_ASSERT(fabs(s - 2 * dy) <= fabs(u + 2 * dy) / (1 + phi) + slack); break;
      case contact_case::release: RC_ASSERT(fabs(s - rigid_release) <= fabs(u) + slack); break;
      default: RC_ASSERT(s == -u);
    }
  });
}

// The root is unique and the reference certifies it: the exact residual
// changes sign across the reference's bracket, which is tiny.
TYPED_TEST(StableProperty, ReferenceCertifiesAUniqueRoot) {
  using T = TypeParam;
  check_property<T>("certified root", [] {
    const auto x = *any_input<T>();
    const auto exact = reference_for(x);
    RC_ASSERT(exact.is_certified);
    RC_ASSERT(mpfr_lessequal_p(exact.lower.get(), exact.s.get()) && mpfr_lessequal_p(exact.s.get(), exact.upper.get()));
  });
}

// Cross-type agreement: T's stable answer rounds from the same root as mpfr at
// 200 bits: their difference is within T's bound.
TYPED_TEST(StableProperty, AgreesWithMpfrWithinBound) {
  using T = TypeParam;
  check_property<T>("cross-type", [] {
    const auto x = *any_input<T>();
    const auto computed = solve_stable(x.u, x.dy, x.phi);
    using std::isfinite;
    RC_PRE(isfinite(computed.s));
    // mpfr at twice T's precision (at least 200 bits), inputs carried over exactly
    const int saved = mpfr_float::default_precision();
    mpfr_float::default_precision(std::max(61, 2 * int(detail::precision_of<T>() * 0.30103) + 2));
    auto to_mpfr = [](const T& v) {
      const reference::real exact = reference::exactly(v, std::max(64, detail::precision_of<T>()));
      mpfr_float m;
      mpfr_set(m.backend().data(), exact.get(), MPFR_RNDN);  // exact: m has more bits than T
      return m;
    };
    const auto wide = solve_stable(to_mpfr(x.u), to_mpfr(x.dy), to_mpfr(x.phi));
    const reference::real wide_s = reference::exactly(wide.s, 2048);
    mpfr_float::default_precision(saved);
    reference::real difference = as_real(computed.s);
    mpfr_sub(difference.get(), difference.get(), wide_s.get(), MPFR_RNDN);
    const double apart = in_ulps<T>(difference, wide_s);
    RC_ASSERT(wide.which == computed.which);
    RC_ASSERT(apart <= stable_bound_for(computed.which, x.u) + 0.01);
  });
}

// MPFR's answer depends on the default precision it is solved at, not on the
// precisions solved at before: Boost gives a result the largest precision of
// its operands, so the stable path's constants must follow the default.
TEST(StableMpfr, AnswersAtThePrecisionItIsSolvedAtWhateverCameBefore) {
  const int saved = mpfr_float::default_precision();
  const auto solve_each_case_at = [](int digits10) {
    mpfr_float::default_precision(digits10);
    std::vector<solution<mpfr_float>> answers;
    for (const auto& [u, dy, phi] : {std::array<const char*, 3>{"1e-3", "-0.5e-3", "10"},  // impact
                                     {"1e-3", "2e-3", "0.1"},                              // contact
                                     {"1e-3", "2e-3", "10"},                               // release, u > 0
                                     {"-1e-3", "2e-3", "10"}})                             // release, u <= 0
      answers.push_back(solve_stable(mpfr_float(u), mpfr_float(dy), mpfr_float(phi)));
    return answers;
  };
  solve_each_case_at(80);
  const auto after_wider = solve_each_case_at(30);
  std::vector<solution<mpfr_float>> in_a_fresh_thread;
  std::thread([&] { in_a_fresh_thread = solve_each_case_at(30); }).join();
  mpfr_float::default_precision(saved);
  ASSERT_EQ(after_wider.size(), in_a_fresh_thread.size());
  for (std::size_t i = 0; i < after_wider.size(); ++i) {
    EXPECT_EQ(after_wider[i].s.precision(), 30u) << "case " << i;
    EXPECT_EQ(after_wider[i].s.str(0, std::ios_base::scientific), in_a_fresh_thread[i].s.str(0, std::ios_base::scientific))
        << "case " << i;
    EXPECT_EQ(after_wider[i].which, in_a_fresh_thread[i].which) << "case " << i;
  }
}

}  // namespace
}  // namespace contact::testing
