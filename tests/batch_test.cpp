// contact::solve_batch gives exactly what the scalar stable path gives: the
// same s, bit for bit, and the same case, for every lane, on every kernel the
// library holds that this CPU runs (contact::batch_targets; "scalar" is the
// path of CPUs without fma). Each test runs every such kernel. The RoundedBatch
// tests hold contact::solve_rounded_batch to solve_rounded likewise.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <cstdio>
#include <string>
#include <vector>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

#include "contact/batch.hpp"
#include "contact/harness/families.hpp"
#include "contact/solve.hpp"

namespace {

namespace harness = contact::harness;

template <class T>
using solution_of = contact::solution<T>;

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

template <class T>
using kernel = std::ptrdiff_t (*)(const T*, const T*, const T*, T*, int*, std::ptrdiff_t);

// solve_batch against solve_stable, or solve_rounded_batch against solve_rounded
enum class mode { stable, rounded };

template <class T>
kernel<T> kernel_of(const contact::batch_target& target, mode m) {
  if constexpr (std::is_same_v<T, double>) return m == mode::stable ? target.solve_double : target.solve_rounded_double;
  else return m == mode::stable ? target.solve_float : target.solve_rounded_float;
}

template <class T>
solution_of<T> scalar_solution(mode m, T u, T dy, T phi) {
  return m == mode::stable ? contact::solve_stable(u, dy, phi) : contact::solve_rounded(u, dy, phi);
}

// The kernels this CPU runs, printed once, so that a run says which it tested.
std::vector<contact::batch_target> runnable_targets() {
  std::vector<contact::batch_target> runnable;
  for (const auto& t : contact::batch_targets())
    if (t.supported) runnable.push_back(t);
  static const bool printed = [&] {
    std::printf("batch kernels this CPU runs:");
    for (const auto& t : runnable) std::printf(" %s", t.name);
    std::printf(" (solve_batch: %s)\n", contact::chosen_batch_target().name);
    return true;
  }();
  (void)printed;
  return runnable;
}

// Every runnable kernel gives the scalar path's answer on every lane; returns,
// per kernel, how many lanes it left to the scalar path.
template <class T>
std::vector<std::ptrdiff_t> expect_same_as_scalar(const lanes<T>& in, mode m = mode::stable) {
  const auto n = static_cast<std::ptrdiff_t>(in.u.size());
  std::vector<solution_of<T>> scalar;
  scalar.reserve(in.u.size());
  for (std::ptrdiff_t i = 0; i < n; ++i) scalar.push_back(scalar_solution(m, in.u[i], in.dy[i], in.phi[i]));
  std::vector<std::ptrdiff_t> left_to_scalar;
  for (const auto& target : runnable_targets()) {
    std::vector<T> s(in.u.size());
    std::vector<int> which(in.u.size());
    left_to_scalar.push_back(kernel_of<T>(target, m)(in.u.data(), in.dy.data(), in.phi.data(), s.data(), which.data(), n));
    long mismatches = 0;
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      if (!identical(scalar[i].s, s[i]) || static_cast<int>(scalar[i].which) != which[i]) {
        if (++mismatches <= 10)
          ADD_FAILURE() << target.name << (m == mode::rounded ? " rounded" : "") << std::hexfloat << ": u=" << in.u[i] << " dy=" << in.dy[i] << " phi=" << in.phi[i]
                        << ": batch s=" << s[i] << " case " << which[i] << ", scalar s=" << scalar[i].s << " case "
                        << static_cast<int>(scalar[i].which);
      }
    }
    EXPECT_EQ(mismatches, 0) << target.name << " on " << n << " lanes";
  }
  return left_to_scalar;
}

TEST(Batch, DoubleLanesEqualScalarStableBitForBit) { expect_same_as_scalar(inputs<double>(400000, 1)); }

TEST(Batch, FloatLanesEqualScalarStableBitForBit) { expect_same_as_scalar(inputs<float>(200000, 2)); }

// Physical inputs lie in the common window: the vectors answer every lane
// but the last few of the array (fewer than a vector).
TEST(Batch, PhysicalLanesEqualScalarStableAndStayInVectors) {
  const auto in = inputs<double>(100000, 5, true);
  const auto left = expect_same_as_scalar(in);
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (std::string(targets[k].name) != "scalar") EXPECT_LT(left[k], 16) << targets[k].name;
}

// A lane the vectors leave is solved by the scalar path once, and counted
// once: invalid lanes (a NaN phi) among lanes inside the common window, so
// that vectors mix the two and the lanes set aside outside the window end in
// part-vectors. The arrays are whole vectors on every target, so each kernel
// leaves exactly the invalid lanes.
template <class T>
void expect_invalid_lanes_left_once(std::uint64_t seed) {
  harness::seeded_source source(seed);
  using harness::distribution;
  const distribution displacement{distribution::shape::log10, -4, -2, 1}, phi{distribution::shape::log10, 0, 2, 1};
  lanes<T> in;
  long invalid = 0;
  for (int k = 0; k < 16 * 2000; ++k) {
    const bool is_invalid = source.integer(0, 6) == 0;
    invalid += is_invalid;
    in.add(harness::random_sign(source, harness::draw<T>(source, displacement)),
           harness::random_sign(source, harness::draw<T>(source, displacement)),
           is_invalid ? std::numeric_limits<T>::quiet_NaN() : harness::draw<T>(source, phi));
  }
  const auto left = expect_same_as_scalar(in);
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (std::string(targets[k].name) != "scalar") EXPECT_EQ(left[k], invalid) << targets[k].name;
}

TEST(Batch, EachLaneLeftToTheScalarPathIsCountedOnce) {
  expect_invalid_lanes_left_once<double>(28);
  expect_invalid_lanes_left_once<float>(29);
}

TEST(Batch, TheTestInputsHoldEveryCaseAndMostlyVectorLanes) {
  const auto in = inputs<double>(100000, 3);
  long seen[5] = {0, 0, 0, 0, 0};
  long inside = 0;
  for (std::size_t i = 0; i < in.u.size(); ++i) {
    seen[static_cast<int>(contact::solve_stable(in.u[i], in.dy[i], in.phi[i]).which)]++;
    inside += contact::detail::safe_window<double>::holds(in.u[i], in.dy[i], in.phi[i]);
  }
  for (int c = 0; c < 5; ++c) EXPECT_GT(seen[c], 1000) << "case " << c;
  EXPECT_GT(inside, 70000);
}

// The Eigen form of each mode, on arrays of lengths around the vectors' and blocks'.
void expect_eigen_arrays_equal_scalar(mode m, std::uint64_t seed) {
  for (long n : {0L, 1L, 7L, 255L, 256L, 257L, 1000L}) {
    const auto in = inputs<double>(static_cast<std::size_t>(n), seed + static_cast<std::uint64_t>(n));
    contact::batch_array<double> u(n), dy(n), phi(n), s;
    contact::batch_array<int> which;
    for (long i = 0; i < n; ++i) u[i] = in.u[i], dy[i] = in.dy[i], phi[i] = in.phi[i];
    if (m == mode::stable)
      contact::solve_batch(u, dy, phi, s, which);
    else
      contact::solve_rounded_batch(u, dy, phi, s, which);
    ASSERT_EQ(s.size(), n);
    ASSERT_EQ(which.size(), n);
    for (long i = 0; i < n; ++i) {
      const auto scalar = scalar_solution(m, in.u[i], in.dy[i], in.phi[i]);
      EXPECT_TRUE(identical(scalar.s, s[i]));
      EXPECT_EQ(static_cast<int>(scalar.which), which[i]);
    }
  }
}

TEST(Batch, EigenArraysOfAnyLengthEqualScalarStable) { expect_eigen_arrays_equal_scalar(mode::stable, 10); }

TEST(Batch, FloatEigenArraysEqualScalarStable) {
  const auto in = inputs<float>(1000, 12);
  const auto n = static_cast<long>(in.u.size());
  contact::batch_array<float> u(n), dy(n), phi(n), s;
  contact::batch_array<int> which;
  for (long i = 0; i < n; ++i) u[i] = in.u[i], dy[i] = in.dy[i], phi[i] = in.phi[i];
  contact::solve_batch(u, dy, phi, s, which);
  for (long i = 0; i < n; ++i) {
    const auto scalar = contact::solve_stable(in.u[i], in.dy[i], in.phi[i]);
    EXPECT_TRUE(identical(scalar.s, s[i]));
    EXPECT_EQ(static_cast<int>(scalar.which), which[i]);
  }
}

// Whole vectors outside the window, in a band, after a vector inside it.
TEST(Batch, WholeVectorsOutsideTheWindowAtTheEndEqualScalarStable) {
  lanes<double> in;
  for (int k = 0; k < 16; ++k) in.add(1e-4 * (k + 1), -2e-4, 10.0);            // inside the window
  for (int k = 0; k < 32; ++k) in.add(1e-300 * (k + 1), -2e-300, 0x1p-700);  // outside, in a band
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

// Lanes inside a band box are moved and answered in vector code, but for the
// few whose s cannot move back (subnormal or overflowing once moved back).
template <class T>
void expect_band_lanes_answered_in_vectors(const lanes<T>& in) {
  long in_a_box = 0;
  for (std::size_t i = 0; i < in.u.size(); ++i) in_a_box += inside_a_band_box(in.u[i], in.dy[i], in.phi[i]);
  const auto left = expect_same_as_scalar(in);
  const auto targets = runnable_targets();
  const long outside = static_cast<long>(in.u.size()) - in_a_box;
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (std::string(targets[k].name) != "scalar")
      EXPECT_LT(left[k], outside + in_a_box / 10) << targets[k].name << ": " << in_a_box << " of " << in.u.size() << " lanes in a band box";
}

// A subnormal phi in double (the first band): the vectors form its products
// from normal factors, as solve_stable does, and leave no lane of audio-rate
// u and dy to the scalar path.
TEST(Batch, SubnormalPhiLanesEqualScalarStableInVectors) {
  harness::seeded_source source(25);
  using harness::distribution;
  const distribution displacement{distribution::shape::log10, -7, -3, 0};
  lanes<double> in;
  for (int k = 0; k < 20000; ++k) {
    const double phi = std::numeric_limits<double>::denorm_min() * double(source.integer(1, (1L << 52) - 1));
    in.add(harness::random_sign(source, harness::draw<double>(source, displacement)),
           harness::random_sign(source, harness::draw<double>(source, displacement)), phi);
  }
  const auto left = expect_same_as_scalar(in);
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (std::string(targets[k].name) != "scalar") EXPECT_EQ(left[k], 0) << targets[k].name;
}

TEST(Batch, DoubleBandLanesEqualScalarStableInVectors) { expect_band_lanes_answered_in_vectors(band_inputs<double>(23, 200)); }

TEST(Batch, FloatBandLanesEqualScalarStableInVectors) { expect_band_lanes_answered_in_vectors(band_inputs<float>(24, 200)); }

// The extreme scene's lanes: u, dy and phi anywhere in the exponent range,
// mostly too far apart for phi's band (solve_stable's exact stage), or huge
// (release roots that overflow once moved back), or tiny (subnormal u and dy,
// and s that lands below the normal binades once moved back). The kernels
// answer them in vectors (scaled_lanes), but for the few whose case the
// dominant binade leaves open or whose root lies within an ulp of overflow.
template <class T>
lanes<T> far_and_extreme_lanes(std::uint64_t seed, int count) {
  using harness::distribution;
  using shape = distribution::shape;
  using limits = std::numeric_limits<T>;
  harness::seeded_source source(seed);
  const double least = limits::min_exponent - limits::digits, largest = limits::max_exponent - 0.1;
  const distribution anywhere{shape::log2, least, largest, 1}, huge{shape::log2, largest / 2, largest, 1},
      tiny{shape::log2, least, limits::min_exponent / 2.0, 1}, phi_moderate{shape::log2, -10, largest / 2, 1};
  lanes<T> in;
  for (int k = 0; k < count; ++k) {
    const int family = k % 3;
    const distribution& magnitude = family == 0 ? anywhere : family == 1 ? huge : tiny;
    in.add(harness::random_sign(source, harness::draw<T>(source, magnitude)), harness::random_sign(source, harness::draw<T>(source, magnitude)),
           harness::draw<T>(source, family == 0 ? anywhere : phi_moderate));
  }
  return in;
}

template <class T>
void expect_far_lanes_answered_in_vectors(const lanes<T>& in) {
  const auto left = expect_same_as_scalar(in);
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (std::string(targets[k].name) != "scalar") EXPECT_LT(left[k], static_cast<long>(in.u.size()) / 100) << targets[k].name;
}

TEST(Batch, DoubleFarAndExtremeLanesEqualScalarStableInVectors) {
  expect_far_lanes_answered_in_vectors(far_and_extreme_lanes<double>(26, 300000));
}

TEST(Batch, FloatFarAndExtremeLanesEqualScalarStable) {
  // (float's subnormal phi straddles two bands and stays with solve_stable: no bound on those left)
  expect_same_as_scalar(far_and_extreme_lanes<float>(27, 300000));
}

// Which components of the register state are in use (XGETBV with ECX = 1:
// bit 2, the upper halves of AVX's ymm registers; bit 6, those of AVX-512's
// zmm), where the CPU tells.
std::optional<std::uint64_t> register_state_in_use() {
#if defined(__x86_64__)
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (!__get_cpuid_count(0xd, 1, &a, &b, &c, &d) || !(a & (1u << 2))) return std::nullopt;
  unsigned low = 0, high = 0;
  asm volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(1));
  return (std::uint64_t(high) << 32) | low;
#else
  return std::nullopt;
#endif
}

// Each kernel returns with the upper halves of the vector registers clean, as
// the x86 ABI expects of a function that takes and returns no vector: the SSE
// code its caller runs next (libm's, say) would pay for every instruction
// while they are not. Arrays of every lane kind, and of far lanes alone
// (their pack solved only at the end of the call).
template <class T>
void expect_upper_halves_clean_after_each_kernel(std::uint64_t seed) {
  constexpr std::uint64_t upper_halves = (1u << 2) | (1u << 6);
  for (const auto& in : {inputs<T>(1000, seed), far_and_extreme_lanes<T>(seed + 1, 1000), far_and_extreme_lanes<T>(seed + 2, 8)}) {
    const auto n = static_cast<std::ptrdiff_t>(in.u.size());
    std::vector<T> s(in.u.size());
    std::vector<int> which(in.u.size());
    for (const auto& target : runnable_targets())
      for (mode m : {mode::stable, mode::rounded}) {
        kernel_of<T>(target, m)(in.u.data(), in.dy.data(), in.phi.data(), s.data(), which.data(), n);
        const auto in_use = register_state_in_use();
        ASSERT_TRUE(in_use.has_value());
        EXPECT_EQ(*in_use & upper_halves, 0u) << target.name << (m == mode::rounded ? " rounded" : "") << " on " << n << " lanes";
      }
  }
}

TEST(Batch, KernelsReturnWithTheUpperHalvesOfVectorRegistersClean) {
  if (!register_state_in_use()) GTEST_SKIP() << "this CPU does not tell which register state is in use";
  expect_upper_halves_clean_after_each_kernel<double>(95);
  expect_upper_halves_clean_after_each_kernel<float>(98);
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

// Millions of lanes of every kind: random bit patterns (NaN, infinity,
// zeros and subnormals among them), log-uniform over the whole range, the
// specials and their neighbours, both case boundaries hit within a few ulps,
// and subnormal u, dy and phi.
template <class T>
lanes<T> lanes_of_every_kind(std::size_t count, std::uint64_t seed) {
  using bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  using limits = std::numeric_limits<T>;
  harness::seeded_source source(seed);
  auto random_bits = [&] { return std::bit_cast<T>(bits(std::uint64_t(source.integer(0, std::numeric_limits<long>::max())) * 2654435761u)); };
  const T specials[] = {T(0), T(-0.0), limits::denorm_min(), limits::min(), (limits::max)(), limits::infinity(),
                        limits::quiet_NaN(), T(1), T(-1), contact::detail::phi_bands<T>::end, limits::epsilon()};
  using harness::distribution;
  const distribution dy_wide{distribution::shape::log2, -limits::max_exponent + 8, limits::max_exponent - 8, 1},
      phi_wide{distribution::shape::log2, -limits::max_exponent + 8, limits::max_exponent - 8, 1};
  lanes<T> in;
  while (in.u.size() < count) {
    switch (source.integer(0, 5)) {
      case 0: in.add(random_bits(), random_bits(), random_bits()); break;
      case 1: { const auto x = harness::whole_range<T>(source); in.add(x.u, x.dy, x.phi); break; }
      case 2: {
        const T a = specials[source.integer(0, 10)], b = specials[source.integer(0, 10)];
        const T c = std::fabs(specials[source.integer(0, 10)]);
        in.add(contact::detail::ulp_steps(a, source.integer(-2, 2)), harness::random_sign(source, b),
               contact::detail::ulp_steps(c, source.integer(0, 2)));
        break;
      }
      case 3: { const auto x = harness::contact_release_boundary<T>(source, dy_wide, phi_wide, 4); in.add(x.u, x.dy, x.phi); break; }
      case 4: { const auto x = harness::free_impact_boundary<T>(source, dy_wide, phi_wide, 4); in.add(x.u, x.dy, x.phi); break; }
      default: {
        auto subnormal = [&] { return harness::random_sign(source, limits::denorm_min() * T(source.integer(1, 1L << (limits::digits - 2)))); };
        const auto x = harness::whole_range<T>(source);
        const int which = int(source.integer(0, 2));
        in.add(which == 0 ? subnormal() : x.u, which == 1 ? subnormal() : x.dy, which == 2 ? std::fabs(subnormal()) : x.phi);
        break;
      }
    }
  }
  return in;
}

TEST(Batch, MillionsOfDoubleLanesOfEveryKindEqualScalarStable) {
  for (std::uint64_t seed = 40; seed < 44; ++seed) expect_same_as_scalar(lanes_of_every_kind<double>(1000000, seed));
}

TEST(Batch, MillionsOfFloatLanesOfEveryKindEqualScalarStable) {
  for (std::uint64_t seed = 50; seed < 54; ++seed) expect_same_as_scalar(lanes_of_every_kind<float>(1000000, seed));
}

// The inputs at the top of the range (harness::top_of_range), in every lane
// position, among ordinary lanes: the finite results beside the largest T
// that solve_stable gives.
template <class T>
lanes<T> top_of_range_lanes() {
  auto in = inputs<T>(64, 5);
  for (int k = 0; k < 17; ++k)  // every offset within the widest vector
    for (const auto& x : harness::top_of_range<T>()) in.add(x.u, x.dy, x.phi);
  return in;
}

TEST(Batch, TopOfRangeLanesEqualScalarStable) {
  expect_same_as_scalar(top_of_range_lanes<double>());
  expect_same_as_scalar(top_of_range_lanes<float>());
}

// The public call (solve_batch or solve_rounded_batch: the kernel dispatch
// chose, or the scalar path lane by lane for the types without one).
template <class T>
void expect_the_call_equals_scalar(const lanes<T>& in, mode m) {
  std::vector<T> s(in.u.size());
  std::vector<int> which(in.u.size());
  const auto n = static_cast<std::ptrdiff_t>(in.u.size());
  if (m == mode::stable)
    contact::solve_batch(in.u.data(), in.dy.data(), in.phi.data(), s.data(), which.data(), n);
  else
    contact::solve_rounded_batch(in.u.data(), in.dy.data(), in.phi.data(), s.data(), which.data(), n);
  for (std::size_t i = 0; i < in.u.size(); ++i) {
    const auto scalar = scalar_solution(m, in.u[i], in.dy[i], in.phi[i]);
    EXPECT_TRUE(identical(scalar.s, s[i]));
    EXPECT_EQ(static_cast<int>(scalar.which), which[i]);
  }
}

TEST(Batch, LongDoubleLanesEqualScalarStable) { expect_the_call_equals_scalar(inputs<long double>(2000, 4), mode::stable); }

// ---- solve_rounded_batch ---------------------------------------------------------

// How many lanes each vector kernel left to the scalar path, below `most`.
void expect_few_left(const std::vector<std::ptrdiff_t>& left, long most, const char* what) {
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (std::string(targets[k].name) != "scalar") EXPECT_LT(left[k], most) << targets[k].name << ", " << what;
}

TEST(RoundedBatch, DoubleLanesEqualScalarRoundedBitForBit) { expect_same_as_scalar(inputs<double>(200000, 61), mode::rounded); }

TEST(RoundedBatch, FloatLanesEqualScalarRoundedBitForBit) { expect_same_as_scalar(inputs<float>(50000, 62), mode::rounded); }

// Physical inputs lie in the plain window, where the fixed-bound step decides
// all but a few lanes (proofs/rounded_bounds.txt: the margins are of order
// 2^-96 |s|): the vectors answer them.
TEST(RoundedBatch, PhysicalLanesEqualScalarRoundedAndStayInVectors) {
  const auto in = inputs<double>(100000, 63, true);
  expect_few_left(expect_same_as_scalar(in, mode::rounded), 100, "physical");
}

// Whether solve_rounded_batch's vectors can take a lane (not free flight):
// inside the common window, or moved into it by one power of two of u and dy
// (phi in the window's range, u and dy normal and less than its width apart).
template <class T>
bool rounded_vectors_reach(T u, T dy, T phi) {
  if (contact::detail::inside_common_window(u, dy, phi)) return true;
  constexpr int width = 2 * contact::detail::common_window<T>, least_phi = contact::detail::common_window_least_phi<T>;
  if (std::fpclassify(phi) != FP_NORMAL || phi < 0 || std::ilogb(phi) < least_phi || std::ilogb(phi) >= least_phi + width)
    return false;
  if (std::fpclassify(u) != FP_NORMAL || std::fpclassify(dy) != FP_NORMAL) return false;
  return std::abs(std::ilogb(u) - std::ilogb(dy)) < width;
}

// Whether float's rounded batch can take a lane through double (float's stable
// formulas on double lanes, as solve_rounded<float> runs them): u, dy and phi,
// widened, inside double's common window (not so a subnormal float).
bool through_double_reach(float u, float dy, float phi) {
  return contact::detail::inside_common_window(double(u), double(dy), double(phi));
}

// The lanes (not free flight) that `reach` leaves out.
template <class T, class Reach>
long lanes_out_of(const lanes<T>& in, Reach reach) {
  long out = 0;
  for (std::size_t i = 0; i < in.u.size(); ++i)
    out += !reach(in.u[i], in.dy[i], in.phi[i]) &&
           contact::solve_stable(in.u[i], in.dy[i], in.phi[i]).which != contact::contact_case::free;
  return out;
}

template <class T>
long lanes_out_of_reach(const lanes<T>& in) {
  return lanes_out_of(in, rounded_vectors_reach<T>);
}

// Float's lanes take the step on float vectors inside float's common window
// (u, dy from 2^-24, phi from 2^-9), or moved there (as the slow contacts
// here, speeds down to 1e-4 m/s, whose u lies below 2^-24): solve_rounded
// takes the lanes out of reach, and those whose root lies within the margin
// (2^-39 to 2^-42 of s, wider where (A.30)'s roots merge) of a float
// midpoint: below 0.5% of the others.
TEST(RoundedBatch, PhysicalFloatLanesEqualScalarRoundedAndStayInVectors) {
  const auto in = inputs<float>(100000, 64, true);
  long moved = 0;
  for (std::size_t i = 0; i < in.u.size(); ++i) moved += !contact::detail::inside_common_window(in.u[i], in.dy[i], in.phi[i]);
  EXPECT_GT(moved, 10000);
  const long out_of_reach = lanes_out_of_reach(in);
  EXPECT_LT(out_of_reach, 1000);
  expect_few_left(expect_same_as_scalar(in, mode::rounded), out_of_reach + 500, "physical float");
}

// Roots that are exact midpoints of T: with phi = 1, (A.31)'s root is dy - u / 2,
// a midpoint below dy in [1.5, 2) when u is an odd multiple of ulp(dy). No
// interval around a midpoint rounds to one value at both ends, so every such lane
// must leave the vectors, and solve_rounded rounds it to even; the lanes one ulp
// of u either side lie within 2^-p ulp of the midpoint, where the test may decide.
template <class T>
void expect_ties_left_to_scalar_rounded(std::uint64_t seed) {
  harness::seeded_source source(seed);
  constexpr T spacing = std::numeric_limits<T>::epsilon();  // ulp in [1, 2)
  lanes<T> ties, near_ties;
  for (int k = 0; k < 4000; ++k) {
    const T dy = T(1.5) + spacing * T(source.integer(0, (1L << 20) - 1));
    const T u = spacing * T(2 * source.integer(0, 1000) + 1);
    const T scale = std::ldexp(T(1), int(source.integer(-20, 6)));  // inside float's common window, or moved there
    ties.add(scale * u, scale * dy, T(1));
    near_ties.add(scale * std::nextafter(u, T(0)), scale * dy, T(1));
    near_ties.add(scale * std::nextafter(u, T(1)), scale * dy, T(1));
  }
  EXPECT_EQ(lanes_out_of_reach(ties), 0);
  const auto left = expect_same_as_scalar(ties, mode::rounded);
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k)
    EXPECT_EQ(left[k], static_cast<std::ptrdiff_t>(ties.u.size())) << targets[k].name;
  expect_same_as_scalar(near_ties, mode::rounded);
}

TEST(RoundedBatch, FloatTiesLeaveTheVectorsAndRoundToEven) { expect_ties_left_to_scalar_rounded<float>(75); }

TEST(RoundedBatch, DoubleTiesLeaveTheVectorsAndRoundToEven) { expect_ties_left_to_scalar_rounded<double>(76); }

// Each kernel gives solve_rounded's results, and leaves to it at least the
// `left_alone` lanes only it takes and at most `slack` more (the scalar target
// leaves every lane).
template <class T>
void expect_left_to_scalar_rounded(const lanes<T>& in, long left_alone, long slack) {
  const auto left = expect_same_as_scalar(in, mode::rounded);
  const auto targets = runnable_targets();
  for (std::size_t k = 0; k < targets.size(); ++k) {
    EXPECT_GE(left[k], left_alone) << targets[k].name;
    if (std::string(targets[k].name) != "scalar") EXPECT_LE(left[k], left_alone + slack) << targets[k].name;
  }
}

// The lanes of every phi band: those out of the vectors' reach (phi beyond the
// common window's range, where the step's bounds are not proven once phi's band
// has moved u and dy) go to solve_rounded; the vectors move the others into the
// window and keep all but a few: those whose rounding test fails, and the
// contacts whose root cancels so deeply that, moved, it leaves the plain window.
TEST(RoundedBatch, DoubleLanesOutOfReachGoToScalarRounded) {
  const auto in = band_inputs<double>(64, 50);
  const auto n = static_cast<long>(in.u.size());
  const long out_of_reach = lanes_out_of_reach(in);
  EXPECT_GT(out_of_reach, n / 4);
  expect_left_to_scalar_rounded(in, out_of_reach, n / 50);
}

// float: the lanes out of the step's reach (and those whose step fails) go
// through double on double vectors, where solve_rounded<float>'s own formulas
// take them: gathered from a block that holds a few (below a quarter of its
// phi outside float's common window), or the whole block where they abound.
// Only lanes outside double's common window (subnormal floats) go straight to
// solve_rounded, with those whose test fails in double too.
TEST(RoundedBatch, FloatLanesOutOfReachGoThroughDoubleOnVectors) {
  const auto abounding = band_inputs<float>(77, 200);  // 200 lanes of each phi in turn
  const auto n = static_cast<long>(abounding.u.size());
  EXPECT_GT(lanes_out_of_reach(abounding), n / 4);
  expect_left_to_scalar_rounded(abounding, lanes_out_of(abounding, through_double_reach), n / 50);
  // the same lanes, one in eight of a physical draw's, at random places
  const auto physical = inputs<float>(7 * abounding.u.size(), 78, true);
  lanes<float> few;
  harness::seeded_source source(79);
  std::size_t next_physical = 0;
  for (std::size_t k = 0; k < abounding.u.size(); ++k) {
    const auto run = static_cast<std::size_t>(source.integer(0, 14));
    for (std::size_t j = 0; j < run && next_physical < physical.u.size(); ++j, ++next_physical)
      few.add(physical.u[next_physical], physical.dy[next_physical], physical.phi[next_physical]);
    few.add(abounding.u[k], abounding.dy[k], abounding.phi[k]);
  }
  const auto few_n = static_cast<long>(few.u.size());
  const long out_of_reach = lanes_out_of_reach(few);
  EXPECT_LT(out_of_reach, few_n / 8);
  EXPECT_GT(out_of_reach, 10000);
  expect_left_to_scalar_rounded(few, lanes_out_of(few, through_double_reach), few_n / 200);
}

TEST(RoundedBatch, LanesNearBothBoundariesEqualScalarRounded) {
  expect_same_as_scalar(near_the_contact_boundary(65, 20000), mode::rounded);
  lanes<double> in;
  harness::seeded_source source(66);
  using harness::distribution;
  const distribution dy_wide{distribution::shape::log10, -10, 2, 1}, phi_wide{distribution::shape::log10, -3, 12, 1};
  for (int k = 0; k < 20000; ++k) {
    const auto x = harness::free_impact_boundary<double>(source, dy_wide, phi_wide, 4);
    in.add(x.u, x.dy, x.phi);
  }
  expect_same_as_scalar(in, mode::rounded);
}

TEST(RoundedBatch, FarExtremeAndTopOfRangeLanesEqualScalarRounded) {
  expect_same_as_scalar(far_and_extreme_lanes<double>(67, 50000), mode::rounded);
  expect_same_as_scalar(top_of_range_lanes<double>(), mode::rounded);
  expect_same_as_scalar(top_of_range_lanes<float>(), mode::rounded);
}

TEST(RoundedBatch, MillionsOfDoubleLanesOfEveryKindEqualScalarRounded) {
  for (std::uint64_t seed = 70; seed < 72; ++seed) expect_same_as_scalar(lanes_of_every_kind<double>(1000000, seed), mode::rounded);
}

TEST(RoundedBatch, MillionsOfFloatLanesOfEveryKindEqualScalarRounded) {
  for (std::uint64_t seed = 72; seed < 74; ++seed) expect_same_as_scalar(lanes_of_every_kind<float>(1000000, seed), mode::rounded);
}

TEST(RoundedBatch, LongDoubleLanesEqualScalarRounded) {
  expect_the_call_equals_scalar(inputs<long double>(2000, 68), mode::rounded);
}

TEST(RoundedBatch, EigenArraysOfAnyLengthEqualScalarRounded) { expect_eigen_arrays_equal_scalar(mode::rounded, 80); }

TEST(RoundedBatch, TheDispatchedKernelEqualsScalarRoundedInDoubleAndFloat) {
  expect_the_call_equals_scalar(inputs<double>(5000, 69), mode::rounded);
  expect_the_call_equals_scalar(inputs<float>(5000, 70), mode::rounded);
}

TEST(Batch, ScalarIsAlwaysAKernelAndTheLastOne) {
  const auto targets = contact::batch_targets();
  ASSERT_FALSE(targets.empty());
  EXPECT_STREQ(targets.back().name, "scalar");
  EXPECT_TRUE(targets.back().supported);
  EXPECT_TRUE(contact::chosen_batch_target().supported);
}

}  // namespace
