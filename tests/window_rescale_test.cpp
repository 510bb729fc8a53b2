// The rescaled path of solve_stable (u and dy moved into the plain window by a
// power of two, phi in the window) gives what by_safe_window gives (for inputs
// outside safe_window, the exact stage on scaled<T>): the same s bit for bit and the same case, on inputs outside the
// plain window, including results that are subnormal or overflow.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "contact/harness/families.hpp"
#include "contact/solve.hpp"
#include "contact/types.hpp"

namespace {

namespace harness = contact::harness;
using harness::distribution;
using shape = distribution::shape;

template <class T>
using bits = std::conditional_t<std::is_same_v<T, double>, std::uint64_t, std::uint32_t>;

// What every input outside the bit-pattern window got before the rescaled
// path: by_safe_window, the plain stage inside safe_window (zeros), else the exact stage on scaled<T>.
template <class T>
contact::solution<T> old_route(const T& u, const T& dy, const T& phi) {
  return contact::detail::by_safe_window(u, dy, phi);
}

template <class T>
::testing::AssertionResult same_as_by_safe_window(const T& u, const T& dy, const T& phi) {
  const auto fast = contact::solve_stable(u, dy, phi), slow = old_route(u, dy, phi);
  if (fast.which == slow.which && std::bit_cast<bits<T>>(fast.s) == std::bit_cast<bits<T>>(slow.s))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << std::hexfloat << "u=" << u << " dy=" << dy << " phi=" << phi
                                       << ": stable s=" << fast.s << " case " << int(fast.which)
                                       << ", by_safe_window s=" << slow.s << " case " << int(slow.which);
}

// A finite T with binade in [low, high] (subnormals below T's normal range), either sign.
template <class T>
T with_binade(harness::seeded_source& source, long low, long high) {
  const long lowest = harness::lowest_exponent<T>(), highest = harness::highest_exponent<T>();
  low = std::max(low, lowest);
  high = std::min(high, highest);
  return harness::random_sign(source, harness::log_uniform<T>(source, low, high));
}

// phi inside the plain window, anywhere in T's range (subnormal, huge, in
// every band), at the edges of a band, or 0 (which stays on the scaled path).
template <class T>
T any_phi(harness::seeded_source& source) {
  using bands = contact::detail::phi_bands<T>;
  const long half = contact::detail::plain_window<T>;
  switch (source.integer(0, 20)) {
    case 0: return T(0);
    case 1: case 2: case 3: case 4: case 5:
      return harness::log_uniform<T>(source, harness::lowest_exponent<T>(), harness::highest_exponent<T>());
    case 6: case 7: {  // the least or the greatest binade of a band
      const long band = source.integer(0, bands::count - 1);
      const long binade = bands::least_binade + (band << bands::band_bits) + (harness::coin(source) ? 0 : (1 << bands::band_bits) - 1);
      return harness::log_uniform<T>(source, binade, binade);
    }
    default: return harness::log_uniform<T>(source, -half, half - 1);
  }
}

template <class T>
void check_out_of_window(std::uint64_t seed, long count) {
  harness::seeded_source source(seed);
  const long half = contact::detail::plain_window<T>;
  const long lowest = harness::lowest_exponent<T>(), highest = harness::highest_exponent<T>();
  long failures = 0;
  for (long i = 0; i < count && failures < 10; ++i) {
    harness::input<T> x;
    switch (source.integer(0, 7)) {
      case 0: x = harness::any_input<T>(source); break;
      case 1: {  // u and dy within a band's room of each other, anywhere in T's range
        const long top = source.integer(lowest, highest);
        const long spread = source.integer(0, harness::coin(source) ? 2 * half + 2 : 4 * half + 8);
        const bool u_larger = harness::coin(source);
        const T larger = with_binade<T>(source, top, top), smaller = with_binade<T>(source, top - spread, top - spread);
        x = {u_larger ? larger : smaller, u_larger ? smaller : larger, any_phi<T>(source)};
        break;
      }
      case 2: {  // both case boundaries at any magnitude
        const T dy = with_binade<T>(source, lowest, highest), phi = any_phi<T>(source);
        const long steps = source.integer(-4, 4);
        x = dy <= 0 ? harness::on_free_impact_boundary(dy, phi, steps) : harness::on_contact_release_boundary(dy, phi, steps);
        break;
      }
      case 3: {  // near the subnormals: results that underflow
        x = {with_binade<T>(source, lowest, lowest + 2 * half), with_binade<T>(source, lowest, lowest + 2 * half),
             any_phi<T>(source)};
        break;
      }
      case 4: {  // near overflow: results beyond the largest finite T
        x = {with_binade<T>(source, highest - 2 * half, highest), with_binade<T>(source, highest - 8, highest),
             any_phi<T>(source)};
        break;
      }
      case 5: {  // impacts, u the larger and gap = -dy any number of binades below: the impact room
        const long top = source.integer(lowest, highest);
        const T larger = std::fabs(with_binade<T>(source, top, top));
        x = {larger, -std::fabs(with_binade<T>(source, lowest, top)), any_phi<T>(source)};
        break;
      }
      case 6: {  // contact and release with u and dy any number of binades apart
        const long top = source.integer(lowest, highest);
        const T larger = with_binade<T>(source, top, top), smaller = with_binade<T>(source, lowest, top);
        const bool u_larger = harness::coin(source);
        x = {u_larger ? larger : smaller, std::fabs(u_larger ? smaller : larger), any_phi<T>(source)};
        break;
      }
      default: {  // zeros with anything
        const T values[] = {T(0), T(-0.0), with_binade<T>(source, lowest, highest)};
        x = {values[source.integer(0, 2)], values[source.integer(0, 2)], any_phi<T>(source)};
        break;
      }
    }
    const auto result = same_as_by_safe_window(x.u, x.dy, x.phi);
    if (!result) ++failures;
    EXPECT_TRUE(result);
  }
}

TEST(WindowRescale, DoubleMatchesSolveAnywhereBitForBit) { check_out_of_window<double>(20261123, 400000); }
TEST(WindowRescale, FloatMatchesSolveAnywhereBitForBit) { check_out_of_window<float>(20261124, 400000); }

// One input for each way out of the rescaled path and each way through it.
TEST(WindowRescale, EachRouteMatchesSolveAnywhere) {
  const double max = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  const double inputs[][3] = {
      {0.0, 0.0, 1.0},               // both zero
      {0.0, -0x1p-600, 1.0},         // u zero: free
      {0x1p-600, 0.0, 3.0},          // dy zero: impact
      {0x1p-300, 0x1p-301, 1.0},     // contact with s = 0 exactly
      {0x1p-1060, -0x1p-1070, 1.0},  // impact with a subnormal s
      {-max, max / 2, 1.0},          // release with s beyond the largest double
      {max, -max, 0.5},              // impact near -max
      {0x1p700, 0x1p-300, 1.0},      // u and dy too far apart for one shift
      {1e-5, 1e-5, 1e300},           // phi above the window
      {1e-5, -1e-5, 0x1p1023},       // phi in no band: 2 (1 + phi) overflows
      {1e-5, -1e-5, 0x1p1021},       // phi at the end of the last band: in no band
      {1e-5, -1e-5, 0x1.fffffffffffffp1020},  // phi at the top of the last band
      {0x1p-3, -0x1p-2, 0x1.8p1020}, // impact with 2 (1 + phi) near 2^1023
      {1e-5, 1e-5, 0x1p974},         // phi at the foot of the last band
      {0x1p-1074, 0x1p1023, 0x1p-1074},  // u and dy too far apart for phi's band
      {1.0, -0x1p-1000, 1.0},        // impact: gap below the band's lowest, inside its impact room
      {0x1p500, -0x1p-900, 1.0},     // impact: gap below the impact room too
      {1e-5, -1e-5, tiny},           // phi subnormal
      {1e300, 1e300, -0.0},          // phi = -0
      {0.0, 1e300, 0.0},             // phi = 0: s = -0 from the scaled path's fma
      {std::nan(""), 1.0, 1.0},      // invalid
      {1.0, 1.0, -1.0},              // invalid
      {0x1p-1074, 0x1p-1074, 2.0},   // subnormal u and dy
  };
  for (const auto& in : inputs) EXPECT_TRUE(same_as_by_safe_window(in[0], in[1], in[2]));
  EXPECT_EQ(contact::solve_stable(-max, max / 2, 1.0).s, std::numeric_limits<double>::infinity());
  EXPECT_EQ(contact::solve_stable(0x1p-300, 0x1p-301, 1.0).s, 0.0);
  EXPECT_EQ(contact::solve_stable(0x1p-1060, -0x1p-1070, 1.0).which, contact::contact_case::impact);
}

// A band's bounds hold for every phi in it: they are monotone in phi's
// range, so any narrower range of phi inside a band leaves at least the
// band's room (top no lower, lowest no higher).
template <class T>
void expect_band_bounds_monotone() {
  using bands = contact::detail::phi_bands<T>;
  for (int j = 0; j < bands::count; ++j) {
    const int P = bands::first_of(j), Q = bands::last_of(j);
    const auto band = bands::table[j];
    for (int low = P; low <= Q; low += 5)
      for (int high = low; high <= Q; high += 7) {
        const auto narrower = bands::of(low, high);
        EXPECT_GE(narrower.top, band.top) << "band " << j << " phi binades " << low << ".." << high;
        EXPECT_LE(narrower.lowest, band.lowest) << "band " << j << " phi binades " << low << ".." << high;
        EXPECT_LE(narrower.impact_lowest, band.impact_lowest) << "band " << j << " phi binades " << low << ".." << high;
      }
    // the impact room is the band's room or more: an impact the band holds takes it either way
    EXPECT_LE(band.impact_lowest, band.lowest) << "band " << j;
  }
  // every band has room, the last one too: it ends where 2 (1 + phi) could overflow
  for (const auto& band : bands::table) EXPECT_LE(band.lowest, band.top - 1);
  EXPECT_EQ(bands::last_of(bands::count - 1), bands::overflow_binade - 4);
  EXPECT_EQ(contact::detail::binade_of(bands::end), bands::overflow_binade - 3);
}

// safe_window<T>::holds reads the bits of long double, float128 and MPFR
// numbers: it gives what its definition gives (x = 0, or |x| in [2^-E, 2^E]) at
// and beside both edges, and for infinity, NaN and the least subnormal.
template <class T>
void expect_safe_window_as_defined() {
  using std::fabs;
  using std::ldexp;
  const int E = static_cast<int>(contact::detail::safe_window<T>::half_width());
  const T top = ldexp(T(1), E), bottom = ldexp(T(1), -E), eps = std::numeric_limits<T>::epsilon();
  std::vector<T> xs = {T(0), T(1), top, T(top * (1 - eps / 2)), T(top * (1 + eps)), bottom, T(bottom * (1 - eps / 2)),
                       T(bottom * (1 + eps)), T(2 * top), T(bottom / 2), std::numeric_limits<T>::infinity(),
                       std::numeric_limits<T>::quiet_NaN()};
  if constexpr (std::numeric_limits<T>::is_bounded) xs.push_back(std::numeric_limits<T>::denorm_min());
  for (const T& magnitude : xs)
    for (const T& x : {magnitude, T(-magnitude)}) {
      const bool defined = x == 0 || (bottom <= fabs(x) && fabs(x) <= top);
      EXPECT_EQ(contact::detail::safe_window<T>::holds(x), defined) << x;
    }
}

TEST(WindowRescale, SafeWindowOnBitsHoldsAsDefined) {
  expect_safe_window_as_defined<long double>();
  expect_safe_window_as_defined<contact::float128>();
  expect_safe_window_as_defined<contact::mpfr_float>();
}

TEST(PhiBands, EachBandsBoundsHoldForEveryPhiInIt) {
  expect_band_bounds_monotone<double>();
  expect_band_bounds_monotone<float>();
}

// binade_of and scaled<T>::shifted (the rescaled path's moves) at the edges of T's range.
TEST(WindowRescale, BinadesAndExactShifts) {
  using contact::detail::binade_of;
  const auto scale_by_power_of_two = [](double x, long k) { return contact::detail::scaled<double>::shifted(x, k); };
  EXPECT_EQ(binade_of(std::numeric_limits<double>::denorm_min()), -1074);
  EXPECT_EQ(binade_of(-std::numeric_limits<double>::min()), -1022);
  EXPECT_EQ(binade_of(std::numeric_limits<double>::max()), 1023);
  EXPECT_EQ(binade_of(0x1.8p-1060), -1060);
  EXPECT_EQ(binade_of(std::numeric_limits<float>::denorm_min()), -149);
  EXPECT_EQ(binade_of(3.0f), 1);
  EXPECT_EQ(scale_by_power_of_two(std::numeric_limits<double>::denorm_min(), 1074 + 239), 0x1p239);
  EXPECT_EQ(scale_by_power_of_two(std::numeric_limits<double>::max(), -1023 - 240), 0x1.fffffffffffffp-240);
  EXPECT_EQ(scale_by_power_of_two(-0.0, 500), -0.0);
}

}  // namespace

namespace {

// scaled<T>'s normalisation and shift on bits agree with frexp and ldexp,
// including the subnormals, zeros, infinities and shifts out of T's range.
template <class T>
void check_scaled_bits(std::uint64_t seed) {
  using S = contact::detail::scaled<T>;
  harness::seeded_source source(seed);
  const T specials[] = {T(0), T(-0.0), std::numeric_limits<T>::infinity(), std::numeric_limits<T>::denorm_min(),
                        std::numeric_limits<T>::min(), std::numeric_limits<T>::max()};
  const long range = harness::highest_exponent<T>() - harness::lowest_exponent<T>() + 4;
  for (int i = 0; i < 200000; ++i) {
    const T x = source.integer(0, 20) == 0 ? specials[source.integer(0, 5)] : harness::any_finite<T>(source);
    const long e = source.integer(-range, range);
    int k = 0;
    const T m = std::frexp(x, &k);
    const S n = S::normalized(x, e);
    ASSERT_EQ(std::bit_cast<bits<T>>(n.significand), std::bit_cast<bits<T>>(m)) << x;
    if (x != 0 && std::isfinite(x)) ASSERT_EQ(n.exponent, e + k) << x;
    ASSERT_EQ(std::bit_cast<bits<T>>(S::shifted(x, e)), std::bit_cast<bits<T>>(std::ldexp(x, int(e)))) << x << " " << e;
  }
  // moves that land in the subnormal range or just below or above it, where
  // the move rounds: ties to even, to zero, and onto the least normal value
  constexpr int digits = std::numeric_limits<T>::digits;
  for (int i = 0; i < 100000; ++i) {
    const T x = harness::any_finite<T>(source);
    if (!(std::fabs(x) >= std::numeric_limits<T>::min())) continue;  // a normal x only: its move is on bits
    int k = 0;
    std::frexp(x, &k);  // |x| in [2^(k-1), 2^k)
    const long landing = source.integer(-digits - 4, 2);  // binades above the least normal
    const long e = (std::numeric_limits<T>::min_exponent - 1 + landing) - (k - 1);
    ASSERT_EQ(std::bit_cast<bits<T>>(S::shifted(x, e)), std::bit_cast<bits<T>>(std::ldexp(x, int(e)))) << x << " " << e;
  }
}

TEST(WindowRescale, ScaledOnBitsAgreesWithFrexpAndLdexp) {
  check_scaled_bits<double>(7);
  check_scaled_bits<float>(8);
}

}  // namespace

namespace {

// sign_of_dominant_term decides only where one term outweighs the rest, and
// then agrees with the exact sum.
TEST(WindowRescale, DominantTermDecidesOnlyWhereItOutweighsTheRest) {
  using S = contact::detail::scaled<double>;
  using terms = std::array<S, 4>;
  using contact::detail::sign_of_dominant_term;
  EXPECT_EQ(sign_of_dominant_term(terms{S(0.0), S(0.0), S(0.0), S(0.0)}), 0);
  EXPECT_EQ(sign_of_dominant_term(terms{S(0.0), S(-8.0), S(0.0), S(0.99)}), -1);
  EXPECT_EQ(sign_of_dominant_term(terms{S(0.0), S(-8.0), S(1.0), S(0.99)}), -1);  // exponents 4 and 1
  EXPECT_EQ(sign_of_dominant_term(terms{S(0.0), S(-8.0), S(2.0), S(0.99)}), 0);   // exponents 4 and 2
  EXPECT_EQ(sign_of_dominant_term(terms{S(0x1p-900), S(0x1p100), S(-0x1p97), S(0.0)}), 1);
  EXPECT_EQ(sign_of_dominant_term(terms{S(0x1p-900), S(0x1p100), S(-0x1.fp98), S(0.0)}), 0);
  harness::seeded_source source(9);
  for (int i = 0; i < 100000; ++i) {
    terms t;
    double plain[4];
    for (int k = 0; k < 4; ++k) {
      plain[k] = source.integer(0, 9) == 0 ? 0.0 : harness::random_sign(source, harness::log_uniform<double>(source, -8, 8));
      t[k] = S(plain[k]);
    }
    const int sign = sign_of_dominant_term(t);
    if (sign != 0) ASSERT_EQ(sign, contact::detail::sign_of_exact_sum(plain));
  }
}

}  // namespace

namespace {

// The exact sign of u + dy - phi dy, from scaled<T>'s exact product and sum.
template <class T>
int exact_contact_sign(const T& u, const T& dy, const T& phi) {
  using S = contact::detail::scaled<T>;
  const auto product = contact::detail::exact_product(S(phi), S(dy));
  return contact::detail::sign_of_exact_sum(std::array<S, 4>{S(u), S(dy), -product[0], -product[1]});
}

// sign_of_dominant_binade, the scaled path's first test of (A.21), decides
// only where one term's binade outweighs the other two, and then as the exact
// sum does. u and phi's binades are drawn near dy's and the thresholds (a
// term's least binade one above the others' bounds) so that its edges are hit,
// and across the whole range with zeros and subnormals.
template <class T>
void check_dominant_binade(std::uint64_t seed) {
  using contact::detail::sign_of_dominant_binade;
  constexpr int least = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits;  // 2^least: least subnormal
  constexpr int most = std::numeric_limits<T>::max_exponent - 1;
  harness::seeded_source source(seed);
  int decided[3] = {0, 0, 0};  // -1, 0, +1
  for (int i = 0; i < 300000; ++i) {
    const bool near = source.integer(0, 3) != 0;
    const long dy_binade = source.integer(near ? least + 8 : least, near ? most - 8 : most);
    auto nearby = [&](long center) { return std::clamp<long>(center + source.integer(-6, 6), least, most); };
    const T dy = harness::log_uniform<T>(source, dy_binade, dy_binade);
    const long u_binade = near ? nearby(dy_binade) : source.integer(least, most);
    const T u = source.integer(0, 9) == 0 ? T(0) : harness::random_sign(source, harness::log_uniform<T>(source, u_binade, u_binade));
    const long phi_binade = near ? std::clamp<long>(source.integer(-6, 6), least, most) : source.integer(least, most);
    const T phi = source.integer(0, 9) == 0 ? T(0) : harness::log_uniform<T>(source, phi_binade, phi_binade);
    const int sign = sign_of_dominant_binade(u, dy, phi);
    ++decided[sign + 1];
    if (sign != 0) ASSERT_EQ(sign, exact_contact_sign(u, dy, phi)) << std::hexfloat << u << " " << dy << " " << phi;
  }
  // not vacuous: both signs are decided, and some inputs left to the exact sum
  EXPECT_GT(decided[0], 10000);
  EXPECT_GT(decided[2], 10000);
  EXPECT_GT(decided[1], 10000);
}

TEST(WindowRescale, DominantBinadeDecidesOnlyWhereOneTermOutweighsTheRest) {
  using contact::detail::sign_of_dominant_binade;
  // u's least binade must exceed the others' bounds: 2^11 does over dy < 2^10, 2^10 does not
  EXPECT_EQ(sign_of_dominant_binade(0x1p11, 0x1.fffp9, 0.0), 1);
  EXPECT_EQ(sign_of_dominant_binade(-0x1p11, 0x1.fffp9, 0.0), -1);
  // where no binade outweighs the rest, u + dy's does: here -2^-3 (exact), over no
  // phi dy, or over phi dy < 2^-4, but not over phi dy < 2^-3; an exact zero, never
  EXPECT_EQ(sign_of_dominant_binade(-0x1p10, 0x1.fffp9, 0.0), -1);
  EXPECT_EQ(sign_of_dominant_binade(-0x1p10, 0x1.fffp9, 0x1p-15), -1);
  EXPECT_EQ(sign_of_dominant_binade(-0x1p10, 0x1.fffp9, 0x1p-14), 0);
  EXPECT_EQ(sign_of_dominant_binade(-1.0, 1.0, 0.0), 0);
  // u + dy overflows: infinity reads as binade 1024, and the exact sum lies above 2^1023
  EXPECT_EQ(sign_of_dominant_binade(0x1.8p1023, 0x1.8p1023, 0x1p-2), 1);  // phi dy < 2^1023
  // phi dy = 1 here, in [2^0, 2^2) as far as the binades tell: it outweighs u < 2^-1, not u < 2^0
  EXPECT_EQ(sign_of_dominant_binade(0x1.fp-2, 0x1p-3, 0x1p3), -1);
  EXPECT_EQ(sign_of_dominant_binade(0x1.fp-1, 0x1p-3, 0x1p3), 0);  // and rightly: the sum is +0x1.8p-4
  EXPECT_EQ(sign_of_dominant_binade(0x1.fp-2, 1.5, 1.5), 0);
  EXPECT_EQ(sign_of_dominant_binade(0.0, 0x1p-1074, 0.0), 1);
  check_dominant_binade<double>(21);
  check_dominant_binade<float>(22);
}

}  // namespace
