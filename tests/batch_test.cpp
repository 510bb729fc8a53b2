// contact::solve_batch gives exactly what the scalar stable path gives: the
// same s, bit for bit, and the same case, for every lane.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "contact/batch.hpp"
#include "contact/harness/families.hpp"
#include "contact/solve.hpp"

namespace {

namespace harness = contact::harness;

template <class T>
struct lanes {
  std::vector<T> u, dy, phi;
  void add(T a, T b, T c) {
    u.push_back(a);
    dy.push_back(b);
    phi.push_back(c);
  }
};

// The input families of contact/harness/families.hpp, plus the lanes that
// only the batch kernels care about: zeros and subnormals, the plain window's
// edges, the contact/release boundary hit exactly, and invalid input.
template <class T>
lanes<T> inputs(std::size_t count, std::uint64_t seed, bool physical_only = false) {
  using harness::distribution;
  using shape = distribution::shape;
  harness::seeded_source source(seed);
  auto pick = [&](long n) { return source.integer(0, n - 1); };
  const distribution displacement{shape::log10, -8, -2, 0}, phi_physical{shape::log10, -3, 6, 1},
      phi_stiff{shape::log10, 6, 30, 1}, phi_soft{shape::log10, -30, -3, 1}, dy_wide{shape::log10, -10, 2, 1},
      phi_wide{shape::log10, -3, 12, 1}, dy_small{shape::log10, -8, -2, 1};
  lanes<T> in;
  auto add = [&](const harness::input<T>& x) { in.add(x.u, x.dy, x.phi); };
  while (in.u.size() < count) {
    switch (physical_only ? 0 : pick(11)) {
      case 0: add(harness::physical<T>(source, harness::audio_rate())); break;
      case 1: add(harness::box<T>(source, displacement, displacement, harness::coin(source) ? phi_stiff : phi_soft)); break;
      case 2: add(harness::free_impact_boundary<T>(source, dy_wide, phi_wide, 4)); break;
      case 3: add(harness::contact_release_boundary<T>(source, dy_wide, phi_wide, 4)); break;
      case 4:
        add(harness::contact_cancellation<T>(source, dy_small, {shape::log10, -3, 8, 1}, {shape::log10, -16, -1, 0}, 0));
        break;
      case 5: add(harness::release_cancellation<T>(source, dy_small, {shape::log10, 6, 16, 1}, {shape::log10, 0, 7, 1})); break;
      case 6: add(harness::whole_range<T>(source)); break;  // beyond the plain window too
      case 7: {  // zeros, signed zeros and subnormals
        const T tiny = std::numeric_limits<T>::denorm_min() * T(pick(1000) + 1);
        const T values[] = {T(0), T(-0.0), tiny, T(-tiny), T(1e-5), T(-1e-5)};
        const T u = values[pick(6)], dy = values[pick(6)];
        in.add(u, dy, std::fabs(values[pick(6)]));
        break;
      }
      case 8: {  // just inside and just outside the plain window's edges
        const long half = contact::detail::safe_window<T>::half_width();
        const T edge = std::ldexp(T(1), static_cast<int>(harness::coin(source) ? half : -half));
        const T e = contact::detail::ulp_steps(edge, pick(3) - 1);
        const T u = harness::random_sign(source, e), dy = harness::draw<T>(source, displacement);
        in.add(u, dy, harness::coin(source) ? e : harness::draw<T>(source, phi_physical));
        break;
      }
      case 9: {  // on the contact / release boundary exactly: u + dy - phi dy = 0 (often), phi dyadic
        const T dy = harness::draw<T>(source, dy_wide);
        const T phis[] = {T(0.5), T(1), T(2), T(3), T(1.5), T(5), T(0.75)};
        add(harness::on_contact_release_boundary(dy, phis[pick(7)], pick(3) - 1));
        break;
      }
      default: {  // invalid: NaN, infinity, phi < 0
        const T bad[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(), T(1e-4)};
        const T u = bad[pick(3)];
        in.add(u, T(1e-4), harness::coin(source) ? T(-1) : bad[pick(3)]);
        break;
      }
    }
  }
  return in;
}

// The same number, bit for bit (== and the same sign tell apart everything but NaN payloads).
template <class T>
bool identical(T a, T b) {
  return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
}

// solve: the batch kernel under test; by default the one solve_batch picks.
template <class T, class Solver = void (*)(const T*, const T*, const T*, T*, int*, std::ptrdiff_t)>
void expect_same_as_scalar(const lanes<T>& in, Solver solve = contact::solve_batch<T>) {
  const auto n = static_cast<std::ptrdiff_t>(in.u.size());
  std::vector<T> s(in.u.size());
  std::vector<int> which(in.u.size());
  solve(in.u.data(), in.dy.data(), in.phi.data(), s.data(), which.data(), n);
  long mismatches = 0;
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto scalar = contact::solve_stable(in.u[i], in.dy[i], in.phi[i]);
    const bool same_s = identical(scalar.s, s[i]);
    if (!same_s || static_cast<int>(scalar.which) != which[i]) {
      if (++mismatches <= 10)
        ADD_FAILURE() << std::hexfloat << "u=" << in.u[i] << " dy=" << in.dy[i] << " phi=" << in.phi[i]
                      << ": batch s=" << s[i] << " case " << which[i] << ", scalar s=" << scalar.s << " case "
                      << static_cast<int>(scalar.which);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(Batch, DoubleLanesEqualScalarStableBitForBit) { expect_same_as_scalar(inputs<double>(400000, 1)); }

// The common case of a synthesis engine: whole blocks of physical lanes, none of which needs the scalar fix-up.
TEST(Batch, PhysicalLanesEqualScalarStableBitForBit) { expect_same_as_scalar(inputs<double>(100000, 5, true)); }

// solve_batch takes the AVX-512 kernel for double where the compiler targets it;
// the portable kernel must then give the same lanes too.
TEST(Batch, PortableKernelDoubleLanesEqualScalarStableBitForBit) {
  expect_same_as_scalar(inputs<double>(200000, 6), contact::batch_detail::solve_lanes<double>);
}

TEST(Batch, PortableKernelPhysicalLanesEqualScalarStableBitForBit) {
  expect_same_as_scalar(inputs<double>(100000, 7, true), contact::batch_detail::solve_lanes<double>);
}

TEST(Batch, FloatLanesEqualScalarStableBitForBit) { expect_same_as_scalar(inputs<float>(200000, 2)); }

TEST(Batch, TheTestInputsHoldEveryCaseAndMostlyVectorLanes) {
  const auto in = inputs<double>(100000, 3);
  long seen[5] = {0, 0, 0, 0, 0};
  long inside = 0;
  for (std::size_t i = 0; i < in.u.size(); ++i) {
    seen[static_cast<int>(contact::solve_stable(in.u[i], in.dy[i], in.phi[i]).which)]++;
    inside += contact::detail::safe_window<double>::holds(in.u[i], in.dy[i], in.phi[i]);
  }
  for (int c = 0; c < 5; ++c) EXPECT_GT(seen[c], 1000) << "case " << c;
  EXPECT_GT(inside, 70000);  // most lanes take the vectorised path
}

TEST(Batch, EigenArraysOfAnyLengthEqualScalarStable) {
  for (long n : {0L, 1L, 7L, 255L, 256L, 257L, 1000L}) {
    const auto in = inputs<double>(static_cast<std::size_t>(n), 10 + static_cast<std::uint64_t>(n));
    contact::batch_array<double> u(n), dy(n), phi(n), s;
    contact::batch_array<int> which;
    for (long i = 0; i < n; ++i) u[i] = in.u[i], dy[i] = in.dy[i], phi[i] = in.phi[i];
    contact::solve_batch(u, dy, phi, s, which);
    ASSERT_EQ(s.size(), n);
    ASSERT_EQ(which.size(), n);
    for (long i = 0; i < n; ++i) {
      const auto scalar = contact::solve_stable(in.u[i], in.dy[i], in.phi[i]);
      EXPECT_TRUE(identical(scalar.s, s[i]));
      EXPECT_EQ(static_cast<int>(scalar.which), which[i]);
    }
  }
}

// A batch whose lanes outside the window all lie in whole vectors (AVX-512:
// vectors that run moved), after a vector inside.
TEST(Batch, WholeVectorsOutsideTheWindowAtTheEndEqualScalarStable) {
  lanes<double> in;
  for (int k = 0; k < 8; ++k) in.add(1e-4 * (k + 1), -2e-4, 10.0);            // inside the window
  for (int k = 0; k < 16; ++k) in.add(1e-300 * (k + 1), -2e-300, 0x1p-700);  // outside, in a band
  expect_same_as_scalar(in);
}

// Lanes for the rescaled pass's phi bands (detail::phi_bands): phi at both
// edges of every band and inside it, subnormal phi, phi in no band (from
// phi_bands::end: 2^1021 in double, 2^125 in float), and u, dy whose binades lie around the band's
// room apart (the larger anywhere in T's range, so that s sometimes cannot
// move back), plus lanes of (A.31) where 2 phi dy is close to u and s is far
// below u and dy.
template <class T>
lanes<T> band_inputs(std::uint64_t seed, int lanes_per_phi) {
  using bands = contact::detail::phi_bands<T>;
  using limits = std::numeric_limits<T>;
  harness::seeded_source source(seed);
  auto pick = [&](long n) { return static_cast<int>(source.integer(0, n - 1)); };
  auto at_binade = [&](int binade) { return std::ldexp(T(1 + harness::unit(source)), binade); };
  std::vector<T> phis;
  for (int j = 0; j < bands::count; ++j) {
    const int P = bands::first_of(j), width = bands::last_of(j) - P + 1;
    const T first = std::ldexp(T(1), P);
    phis.push_back(first);
    phis.push_back(contact::detail::next_up(first));
    if (j > 0) phis.push_back(contact::detail::next_down(first));  // the last of the band below
    for (int k = 0; k < 4; ++k) {
      const int binade = P + pick(width);
      if (binade < limits::max_exponent) phis.push_back(binade < limits::min_exponent - 1 ? std::ldexp(T(1), binade) * T(1 + pick(7)) : at_binade(binade));
    }
  }
  for (int k = 0; k < 8; ++k) phis.push_back(limits::denorm_min() * T(1 + source.integer(0, 1L << (limits::digits - 2))));
  phis.push_back(limits::min());
  phis.push_back(contact::detail::next_down(limits::min()));
  phis.push_back((limits::max)());
  phis.push_back(bands::end);  // the first phi in no band, and the last one in a band
  phis.push_back(contact::detail::next_down(bands::end));

  lanes<T> in;
  for (const T phi : phis) {
    const bool in_a_band = phi < bands::end;
    const int room = in_a_band ? bands::of_phi(phi).top - 1 - bands::of_phi(phi).lowest : 100;
    for (int k = 0; k < lanes_per_phi; ++k) {
      const int larger = limits::min_exponent - 1 + pick(limits::max_exponent - limits::min_exponent + 1);
      const int spread = pick(4) == 0 ? pick(room + 1) : room - 2 + pick(5);
      const T big = at_binade(larger), small = at_binade(larger - spread);  // small may be subnormal or 0
      const bool u_larger = harness::coin(source);
      in.add(harness::random_sign(source, u_larger ? big : small), harness::random_sign(source, u_larger ? small : big), phi);
    }
    for (int k = 0; k < lanes_per_phi / 4; ++k) {  // (A.31) with u = 2 phi dy, a few ulps off
      const T dy = at_binade(limits::min_exponent - 1 + pick(limits::max_exponent - limits::min_exponent + 1));
      const T u = contact::detail::ulp_steps(T(T(2) * phi * dy), pick(9) - 4);
      if (std::isfinite(u)) in.add(u, dy, phi);
    }
  }
  return in;
}

// What the rescaled pass may take on: u and dy normal, phi > 0 in a band, that is
// below phi_bands::end, and their binades at most the band's room apart.
template <class T>
bool inside_a_band_box(T u, T dy, T phi) {
  using bands = contact::detail::phi_bands<T>;
  if (!std::isnormal(u) || !std::isnormal(dy) || !(phi > 0) || !(phi < bands::end)) return false;
  const auto band = bands::of_phi(phi);
  const int u_binade = contact::detail::binade_of(u), dy_binade = contact::detail::binade_of(dy);
  return std::abs(u_binade - dy_binade) <= band.top - 1 - band.lowest;
}

// lane<true> answers only lanes inside a band box, and answers them as
// solve_stable does; and it answers most of those whose phi lies outside the
// vector window and whose s is normal (the rest: the pre-test's undecided
// lanes, and s subnormal before it moves back), the band's room included.

template <class T>
void expect_band_lanes_solved_in_vector_code(const lanes<T>& in) {
  using case_number = std::make_signed_t<contact::batch_detail::bits_t<T>>;
  long eligible = 0, solved = 0, solved_at_room = 0, mismatches = 0, outside_boxes = 0;

  for (std::size_t i = 0; i < in.u.size(); ++i) {
    const T u = in.u[i], dy = in.dy[i], phi = in.phi[i];
    T s;
    case_number which;
    contact::batch_detail::bits_t<T> undecided;
    const bool lane_solved = contact::batch_detail::lane<true>(u, dy, phi, s, which, undecided) != 0;
    const auto scalar = contact::solve_stable(u, dy, phi);
    const bool box = inside_a_band_box(u, dy, phi);
    if (lane_solved && (!identical(scalar.s, s) || static_cast<int>(scalar.which) != static_cast<int>(which))) {
      if (++mismatches <= 10)
        ADD_FAILURE() << std::hexfloat << "u=" << u << " dy=" << dy << " phi=" << phi << ": lane s=" << s << " case "
                      << which << ", scalar s=" << scalar.s << " case " << static_cast<int>(scalar.which);
    }
    if (lane_solved && !box && ++outside_boxes <= 10)
      ADD_FAILURE() << std::hexfloat << "outside every band box: u=" << u << " dy=" << dy << " phi=" << phi;
    // float's subnormal phi straddles two bands; the lane leaves it to the scalar path
    constexpr int least = contact::detail::common_window_least_phi<T>, width = 2 * contact::detail::common_window<T>;
    const bool phi_outside_vector_window = (std::ilogb(phi) >= least + width || std::ilogb(phi) < least) &&
                                           (std::is_same_v<T, double> || std::isnormal(phi));
    if (box && phi_outside_vector_window && (std::isnormal(scalar.s) || scalar.s == 0)) {
      ++eligible;
      solved += lane_solved;
      const auto band = contact::detail::phi_bands<T>::of_phi(phi);
      solved_at_room += lane_solved && std::abs(contact::detail::binade_of(u) - contact::detail::binade_of(dy)) ==
                                           band.top - 1 - band.lowest;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(outside_boxes, 0);
  EXPECT_GT(eligible, 1000);
  EXPECT_GT(solved, eligible * 9 / 10) << "of " << eligible;
  EXPECT_GT(solved_at_room, 50);
}

// With the exact decision, lane<true, true> answers every lane lane<true>
// answers, the same way, and the lanes lane<true> leaves undecided near the
// contact/release boundary, as solve_stable does.
template <class T>
void expect_exact_decision_answers_undecided_lanes(const lanes<T>& in) {
  using case_number = std::make_signed_t<contact::batch_detail::bits_t<T>>;
  long undecided_lanes = 0, wrong = 0;
  for (std::size_t i = 0; i < in.u.size(); ++i) {
    const T u = in.u[i], dy = in.dy[i], phi = in.phi[i];
    T s, s_exact;
    case_number which, which_exact;
    contact::batch_detail::bits_t<T> undecided, undecided_after_exact;
    const bool solved = contact::batch_detail::lane<true>(u, dy, phi, s, which, undecided) != 0;
    const bool exact_solved =
        contact::batch_detail::lane<true, true>(u, dy, phi, s_exact, which_exact, undecided_after_exact) != 0;
    const auto scalar = contact::solve_stable(u, dy, phi);
    undecided_lanes += undecided != 0;
    const bool same = identical(scalar.s, s_exact) && static_cast<int>(scalar.which) == static_cast<int>(which_exact);
    if (exact_solved != (solved || undecided != 0) || (exact_solved && !same)) {
      if (++wrong <= 10)
        ADD_FAILURE() << std::hexfloat << "u=" << u << " dy=" << dy << " phi=" << phi << ": exact lane s=" << s_exact
                      << " case " << which_exact << " (solved " << exact_solved << "), scalar s=" << scalar.s;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(undecided_lanes, in.u.size() / 20) << "of " << in.u.size();
}

TEST(Batch, ExactDecisionAnswersTheLanesNearTheContactBoundary) {
  for (std::uint64_t seed : {31, 32}) {
    harness::seeded_source source(seed);
    using harness::distribution;
    const distribution dy_wide{distribution::shape::log10, -10, 2, 1}, phi_wide{distribution::shape::log10, -3, 12, 1};
    lanes<double> near_double;
    lanes<float> near_float;
    for (int i = 0; i < 20000; ++i) {
      const auto x = harness::contact_release_boundary<double>(source, dy_wide, phi_wide, 4);
      near_double.add(x.u, x.dy, x.phi);
      const auto y = harness::contact_release_boundary<float>(source, dy_wide, phi_wide, 4);
      near_float.add(y.u, y.dy, y.phi);
    }
    expect_exact_decision_answers_undecided_lanes(near_double);
    expect_exact_decision_answers_undecided_lanes(near_float);
  }
}

// Within 8 ulps of u = dy (phi - 1), at physical magnitudes (inside the window)
// and at 2^+-500 (in phi's bands): nearly every lane needs the exact decision.
lanes<double> near_the_contact_boundary(std::uint64_t seed, int count) {
  harness::seeded_source source(seed);
  using harness::distribution;
  using shape = distribution::shape;
  const distribution dy_physical{shape::log10, -7, -3, 1}, phi_physical{shape::log10, -3, 6, 1},
      dy_wide{shape::log2, -500, 500, 1}, phi_wide{shape::log2, -500, 500, 1};
  lanes<double> in;
  for (int i = 0; i < count; ++i) {
    const bool wide = i % 2 == 1;
    const auto x = harness::contact_release_boundary<double>(source, wide ? dy_wide : dy_physical,
                                                             wide ? phi_wide : phi_physical, 8);
    in.add(x.u, x.dy, x.phi);
  }
  return in;
}

TEST(Batch, LanesNearTheContactBoundaryEqualScalarStableBitForBit) {
  expect_same_as_scalar(near_the_contact_boundary(33, 40000));
}

#if defined(__AVX512F__)
// The lanes of eight vector answers (rescaled_eight, far_eight) for in's lanes
// i to i + 7: bit for bit solve_stable's where `answered` says so, each
// mismatch a failure (the first 10 listed) added to `mismatches`. Returns the
// lanes answered, as a mask.
unsigned check_eight(const contact::batch_detail::eight_results& r, const lanes<double>& in, std::size_t i,
                     long& mismatches) {
  alignas(64) double s[8];
  alignas(32) int which[8];
  _mm512_store_pd(s, r.s);
  _mm256_store_si256(reinterpret_cast<__m256i*>(which), r.which);
  for (int k = 0; k < 8; ++k) {
    if (!(r.answered >> k & 1)) continue;
    const auto scalar = contact::solve_stable(in.u[i + k], in.dy[i + k], in.phi[i + k]);
    if ((!identical(scalar.s, s[k]) || static_cast<int>(scalar.which) != which[k]) && ++mismatches <= 10)
      ADD_FAILURE() << std::hexfloat << "u=" << in.u[i + k] << " dy=" << in.dy[i + k] << " phi=" << in.phi[i + k]
                    << ": vector s=" << s[k] << " case " << which[k] << ", scalar s=" << scalar.s << " case "
                    << static_cast<int>(scalar.which);
  }
  return r.answered;
}

contact::batch_detail::eight_results rescaled_eight_of(const lanes<double>& in, std::size_t i) {
  return contact::batch_detail::rescaled_eight(_mm512_loadu_pd(in.u.data() + i), _mm512_loadu_pd(in.dy.data() + i),
                                               _mm512_loadu_pd(in.phi.data() + i));
}

// The AVX-512 rescaled pass decides those lanes itself (decide_eight's exact
// sum), as solve_stable does, instead of leaving them to the scalar path.
TEST(Batch, RescaledPassDecidesTheLanesNearTheContactBoundaryInVectorCode) {
  const auto in = near_the_contact_boundary(34, 40000);
  long answered = 0, mismatches = 0;
  for (std::size_t i = 0; i + 8 <= in.u.size(); i += 8)
    answered += std::popcount(check_eight(rescaled_eight_of(in, i), in, i, mismatches));
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(answered, long(in.u.size()) * 9 / 10) << "of " << in.u.size();
}

// Lanes that the AVX-512 kernel answers in vector code and the portable
// kernel leaves to the scalar path, one kind per vector: subnormal u or dy,
// an impact in its own room (gap further below u than the band's room for
// contact and release), free flight at any magnitudes and any valid phi
// (0 and phi in no band included), and releases whose s overflows or falls
// among the subnormals once moved back.
lanes<double> lanes_for_the_avx512_kernel(std::uint64_t seed, int vectors_per_kind) {
  harness::seeded_source source(seed);
  auto power = [&](double low, double high) { return std::exp2(low + (high - low) * harness::unit(source)); };
  auto sign = [&] { return harness::coin(source) ? 1.0 : -1.0; };
  auto subnormal = [&] { return std::numeric_limits<double>::denorm_min() * double(source.integer(1, 1L << 40)); };
  lanes<double> in;
  for (int v = 0; v < vectors_per_kind; ++v) {
    for (int k = 0; k < 8; ++k) in.add(sign() * subnormal(), sign() * power(-1000, -200), power(-10, 10));
    for (int k = 0; k < 8; ++k) {  // phi in [2^-520, 2^-480], band 4: room 740 binades, an impact's 918
      const double u = power(400, 500);
      in.add(u, -u * power(-900, -760), power(-520, -480));
    }
    for (int k = 0; k < 8; ++k) {
      const double binade = -1074 + 2097 * harness::unit(source), phis[] = {0.0, power(-1074, 1023), 0x1p1022};
      in.add(-power(binade, 1023), -std::exp2(binade), phis[source.integer(0, 2)]);  // u <= -dy
    }
    for (int k = 0; k < 8; ++k) {
      const double dy = power(900, 1000);
      in.add(sign() * dy * power(-10, 0), dy, power(200, 900));
    }
    for (int k = 0; k < 8; ++k) in.add(sign() * power(-1060, -1000), subnormal(), power(0, 40));
  }
  return in;
}

TEST(Batch, Avx512KernelAnswersSubnormalOperandsImpactRoomFreeFlightAndOverflowInVectorCode) {
  const auto in = lanes_for_the_avx512_kernel(35, 100);
  constexpr int kinds = 5;
  long answered[kinds] = {}, lanes_of[kinds] = {}, mismatches = 0;
  for (std::size_t i = 0; i + 8 <= in.u.size(); i += 8) {
    const std::size_t kind = (i / 8) % kinds;
    lanes_of[kind] += 8;
    answered[kind] += std::popcount(check_eight(rescaled_eight_of(in, i), in, i, mismatches));
  }
  EXPECT_EQ(mismatches, 0);
  const char* names[kinds] = {"subnormal u", "impact room", "free flight", "overflowing release", "subnormal s"};
  for (int kind = 0; kind < kinds; ++kind) EXPECT_GT(answered[kind], lanes_of[kind] * 9 / 10) << names[kind];
  expect_same_as_scalar(in);
}

// u and dy further apart than any band's room (400 to 2000 binades), every
// case, phi anywhere: the lanes that the AVX-512 kernel solves with
// detail::scaled<double>'s operations on eight lanes (far_eight) instead of
// the scalar scaled path, bit for bit as that path does.
TEST(Batch, FarApartLanesTakeTheScaledPathInVectorCode) {
  harness::seeded_source source(36);
  auto power = [&](double low, double high) { return std::exp2(low + (high - low) * harness::unit(source)); };
  auto sign = [&] { return harness::coin(source) ? 1.0 : -1.0; };
  lanes<double> in;
  for (int i = 0; i < 8000; ++i) {
    const double larger = power(-674, 1023), smaller = power(-1074, std::log2(larger) - 400);
    const bool u_larger = harness::coin(source);
    in.add(sign() * (u_larger ? larger : smaller), sign() * (u_larger ? smaller : larger), power(-1074, 1023));
  }
  long answered = 0, mismatches = 0, not_free = 0;
  for (std::size_t i = 0; i + 8 <= in.u.size(); i += 8) {
    const __m512d u = _mm512_loadu_pd(in.u.data() + i), dy = _mm512_loadu_pd(in.dy.data() + i),
                  phi = _mm512_loadu_pd(in.phi.data() + i);
    auto r = contact::batch_detail::far_eight<false>(u, dy, phi);
    const auto impacts = contact::batch_detail::far_eight<true>(u, dy, phi);
    EXPECT_EQ(r.answered & impacts.answered, 0);
    r.s = _mm512_mask_mov_pd(r.s, impacts.answered, impacts.s);
    r.which = _mm256_mask_mov_epi32(r.which, impacts.answered, impacts.which);
    r.answered |= impacts.answered;
    answered += std::popcount(check_eight(r, in, i, mismatches));
    for (std::size_t k = i; k < i + 8; ++k)
      not_free += contact::solve_stable(in.u[k], in.dy[k], in.phi[k]).which != contact::contact_case::free;
  }
  EXPECT_EQ(mismatches, 0);
  // free flight (three eighths of them) is answered before, by moved_back_eight; the rest but a few
  // (binades that leave the case undecided, a release root within an ulp of overflow)
  EXPECT_GT(answered, not_free * 99 / 100) << "of " << not_free;
  expect_same_as_scalar(in);
}
#endif

TEST(Batch, RescaledLanesTakePhiBandsAsSolveStableDoes) {
  expect_band_lanes_solved_in_vector_code(band_inputs<double>(21, 200));
  expect_band_lanes_solved_in_vector_code(band_inputs<float>(22, 200));
}

TEST(Batch, DoubleBandLanesEqualScalarStableBitForBit) {
  const auto in = band_inputs<double>(23, 200);
  expect_same_as_scalar(in);                                            // AVX-512 where compiled for it
  expect_same_as_scalar(in, contact::batch_detail::solve_lanes<double>);  // the portable kernel
}

TEST(Batch, FloatBandLanesEqualScalarStableBitForBit) { expect_same_as_scalar(band_inputs<float>(24, 200)); }

TEST(Batch, LongDoubleLanesEqualScalarStable) {
  const auto in = inputs<long double>(2000, 4);
  expect_same_as_scalar(in);
}

}  // namespace
