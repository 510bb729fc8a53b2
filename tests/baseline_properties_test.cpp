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

// Newton converges on the audio-rate inputs as far as the residual's own
// rounding lets it: the rounding error of R at the root, over R's slope, is
// about kappa ulps of s, kappa = 1 + (|u| + 2 phi |dy|) / ((1 + phi) |s|) (the
// terms R sums, over its slope at least 1 + phi on (A.31)'s side and about
// 1 elsewhere). Asserted where kappa <= 16 (NewtonLimit in baselines_test
// shows the ill-conditioned rest): within 2 kappa + 2 ulps.
TYPED_TEST(BaselineProperty, NewtonConvergesAsFarAsTheResidualIsConditioned) {
  using T = TypeParam;
  check_property<T>("newton accuracy", [] {
    const auto x = *physical_input<T>();
    const auto exact = reference_for(x);
    const auto computed = solve_newton(x.u, x.dy, x.phi);
    using std::fabs;
    const double s = fabs(double(computed.s)), dy = fabs(double(x.dy)), phi = double(x.phi);
    const double kappa = 1 + (fabs(double(x.u)) + 2 * phi * dy) / ((computed.which == contact_case::contact ? 1 + phi : 1) * s);
    RC_PRE(kappa <= 16 && 16 * s >= dy);
    const double error = reference::ulp_error(computed.s, exact);
    RC_LOG() << x << " kappa=" << kappa << " error=" << error << "\n";
    RC_ASSERT(error <= 2 * kappa + 2);
  });
}

}  // namespace
}  // namespace contact::testing
