// The oscillator scheme of contact/harness/oscillator.hpp produces (A.2):
// docs/equations.md, section 1. Checked in exact rational arithmetic, so that
// the identities hold to the last bit or fail.
#include <boost/multiprecision/gmp.hpp>

#include "contact/harness/oscillator.hpp"
#include "harness.hpp"

namespace contact::testing {
namespace {

using rational = boost::multiprecision::mpq_rational;
using scheme = harness::oscillator<rational>;

// A positive double of 2^[low, high], exactly as a rational.
rational positive(long low, long high) {
  return rational(*log_uniform<double>(low, high));
}

rational any_sign(long low, long high) { return rational(*rc::gen::element(-1, 1)) * positive(low, high); }

// R(s) of (A.2), exactly, for s != 0.
rational residual(const rational& s, const rational& u, const rational& dy, const rational& phi) {
  auto floor_squared = [](const rational& x) { return x > 0 ? rational(x * x) : rational(0); };
  return s + u + phi * (floor_squared(dy - s) - floor_squared(dy)) / s;
}

// (S.10): one step changes the energy by a s R(s), for every s. So H is
// conserved exactly when s is the root of (A.2), and the energy drift of a
// simulation measures the error of the solve.
TEST(Oscillator, OneStepChangesTheEnergyByASTimesTheResidual) {
  EXPECT_TRUE(rc::check("H[n+1] - H[n] = a s R(s)", [] {
    const scheme o(positive(-14, -6), positive(0, 14), any_sign(-24, -10), positive(16, 44),
                   positive(-16, -14));
    const harness::oscillator_state<rational> now{any_sign(-24, -10), any_sign(-20, 0)};
    const rational s = any_sign(-30, -8);
    const rational u = o.u(now.y, now.p), dy = o.compression(now.y);
    RC_ASSERT(o.energy(o.next(now, s)) - o.energy(now) == o.a * s * residual(s, u, dy, o.phi));
  }));
}

// (S.5)-(S.7): theta = 1/a and phi = theta k_b / 2, exactly.
TEST(Oscillator, StiffnessRatioIsHalfTheBarrierStiffnessOverA) {
  const scheme o(rational(1, 1000), rational(1000), rational(-1, 2000), rational(10000000000000), rational(1, 44100));
  EXPECT_EQ(o.a, rational(2, 1000) * 44100 * 44100 + 500);
  EXPECT_EQ(o.phi, rational(10000000000000) / (2 * o.a));
  EXPECT_EQ(o.u(rational(1, 1000), rational(3, 1000)), (rational(1) - rational(6, 1000) * 44100) / o.a);
}

}  // namespace
}  // namespace contact::testing
