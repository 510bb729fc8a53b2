// The few properties the textbook formula and the Newton baseline do claim.
#include "harness.hpp"

namespace contact::testing {
namespace {

template <class T>
class BaselineProperty : public ::testing::Test {};
using hardware_types = ::testing::Types<float, double, long double>;
TYPED_TEST_SUITE(BaselineProperty, hardware_types, type_names_for_gtest);

// Newton decides the case from the rounded residual at the kink and then
// clamps s onto that case's side: complementarity holds as it claims it.
TYPED_TEST(BaselineProperty, NewtonStepLiesOnItsCasesSide) {
  using T = TypeParam;
  check_property<T>("newton complementarity", [] {
    const auto x = *any_input<T>();
    const auto computed = solve_newton(x.u, x.dy, x.phi);
    RC_LOG() << x << " s=" << computed.s << " case=" << int(computed.which) << "\n";
    RC_ASSERT(lies_on_its_side(computed.which, computed.s, x.dy));
  });
}

// Away from the case boundaries the textbook criteria, evaluated in T, pick the
// exact case: an input whose R(dy) is far from zero cannot be misjudged.
TYPED_TEST(BaselineProperty, TextbookPicksTheExactCaseAwayFromBoundaries) {
  using T = TypeParam;
  check_property<T>("textbook case", [] {
    const auto x = *physical_input<T>();
    using std::fabs;
    const T criterion = x.dy <= 0 ? T(x.u + x.dy) : T(x.u - x.dy * (x.phi - 1));
    RC_PRE(fabs(criterion) > 64 * std::numeric_limits<T>::epsilon() * (fabs(x.u) + fabs(x.dy) * (1 + x.phi)));
    RC_ASSERT(solve_textbook(x.u, x.dy, x.phi).which == reference_for(x).which);
  });
}

// Newton converges on the audio-rate inputs to within a few ulps of the root,
// except where s is small against the terms of the residual, whose own
// rounding then limits it (NewtonLimit in baselines_test): asserted where
// 16 |s| >= |u| + 2 phi |dy| (the residual's terms at the root) and |dy|.
TYPED_TEST(BaselineProperty, NewtonConvergesWhereTheResidualIsWellConditioned) {
  using T = TypeParam;
  check_property<T>("newton accuracy", [] {
    const auto x = *physical_input<T>();
    const auto exact = reference_for(x);
    const auto computed = solve_newton(x.u, x.dy, x.phi);
    using std::fabs;
    RC_PRE(fabs(computed.s) * 16 >= fabs(x.u) + 2 * x.phi * fabs(x.dy) && fabs(computed.s) * 16 >= fabs(x.dy));
    const double error = reference::ulp_error(computed.s, exact);
    RC_LOG() << x << " error=" << error << "\n";
    RC_ASSERT(error <= 8.0);
  });
}

}  // namespace
}  // namespace contact::testing
