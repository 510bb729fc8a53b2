// contact::solve_batch gives exactly what the scalar stable path gives: the
// same s, bit for bit, and the same case, for every lane.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "contact/batch.hpp"
#include "contact/solve.hpp"

namespace {

template <class T>
struct lanes {
  std::vector<T> u, dy, phi;
  void add(T a, T b, T c) {
    u.push_back(a);
    dy.push_back(b);
    phi.push_back(c);
  }
};

template <class T>
T log_uniform(std::mt19937_64& rng, double low, double high) {
  std::uniform_real_distribution<double> exponent(low, high);
  return static_cast<T>(std::pow(10.0, exponent(rng)));
}

template <class T>
T signed_value(std::mt19937_64& rng, double low, double high) {
  const T x = log_uniform<T>(rng, low, high);
  return (rng() & 1) ? x : T(-x);
}

template <class T>
T ulps_away(T x, long k) {
  for (; k > 0; --k) x = std::nextafter(x, std::numeric_limits<T>::infinity());
  for (; k < 0; ++k) x = std::nextafter(x, -std::numeric_limits<T>::infinity());
  return x;
}

// Physical, stiff and soft inputs, both case boundaries to a few ulps, the
// cancellation regions, zeros, subnormals, extreme magnitudes and invalid input.
template <class T>
lanes<T> inputs(std::size_t count, std::uint64_t seed, bool physical_only = false) {
  std::mt19937_64 rng(seed);
  lanes<T> in;
  const double top = std::numeric_limits<T>::max_exponent10 - 1.0;
  const double bottom = std::numeric_limits<T>::min_exponent10 - 5.0;
  while (in.u.size() < count) {
    switch (physical_only ? 0 : rng() % 11) {
      case 0:  // physical
        in.add(signed_value<T>(rng, -8, -2), signed_value<T>(rng, -8, -2), log_uniform<T>(rng, -3, 6));
        break;
      case 1:  // stiff and soft phi
        in.add(signed_value<T>(rng, -8, -2), signed_value<T>(rng, -8, -2),
               (rng() & 1) ? log_uniform<T>(rng, 6, 30) : log_uniform<T>(rng, -30, -3));
        break;
      case 2: {  // free / impact boundary: u = -dy within a few ulps
        const T dy = -log_uniform<T>(rng, -10, 2);
        in.add(ulps_away(T(-dy), long(rng() % 9) - 4), dy, log_uniform<T>(rng, -3, 12));
        break;
      }
      case 3: {  // contact / release boundary: u = dy (phi - 1) within a few ulps
        const T dy = log_uniform<T>(rng, -10, 2), phi = log_uniform<T>(rng, -3, 12);
        in.add(ulps_away(T(dy * (phi - 1)), long(rng() % 9) - 4), dy, phi);
        break;
      }
      case 4: {  // contact cancellation: s near 0
        const T dy = log_uniform<T>(rng, -8, -2), phi = log_uniform<T>(rng, -3, 8);
        const T t = 2 * phi * dy;
        in.add(std::fma(t, signed_value<T>(rng, -16, -1), t), dy, phi);
        break;
      }
      case 5: {  // release cancellation: u >> sqrt(phi) dy
        const T dy = log_uniform<T>(rng, -8, -2), phi = log_uniform<T>(rng, 6, 16);
        in.add(std::min(T(log_uniform<T>(rng, 0, 7) * std::sqrt(phi) * dy), T(dy * (phi - 1) / 2)), dy, phi);
        break;
      }
      case 6:  // anything in the whole range, including beyond the plain window
        in.add(signed_value<T>(rng, bottom, top), signed_value<T>(rng, bottom, top), log_uniform<T>(rng, bottom, top));
        break;
      case 7: {  // zeros, signed zeros and subnormals
        const T tiny = std::numeric_limits<T>::denorm_min() * T(rng() % 1000 + 1);
        const T pick[] = {T(0), T(-0.0), tiny, T(-tiny), T(1e-5), T(-1e-5)};
        in.add(pick[rng() % 6], pick[rng() % 6], std::fabs(pick[rng() % 6]));
        break;
      }
      case 8: {  // just inside and just outside the plain window's edges
        const long half = contact::detail::safe_window<T>::half_width();
        const T edge = std::ldexp(T(1), static_cast<int>((rng() & 1) ? half : -half));
        const T e = ulps_away(edge, long(rng() % 3) - 1);
        in.add((rng() & 1) ? e : T(-e), signed_value<T>(rng, -8, -2), (rng() & 1) ? e : log_uniform<T>(rng, -3, 6));
        break;
      }
      case 9: {  // on the contact / release boundary exactly: u + dy - phi dy = 0 (often), phi dyadic
        const T dy = log_uniform<T>(rng, -10, 2);
        const T phis[] = {T(0.5), T(1), T(2), T(3), T(1.5), T(5), T(0.75)};
        const T phi = phis[rng() % 7];
        in.add(ulps_away(T(dy * (phi - 1)), long(rng() % 3) - 1), dy, phi);
        break;
      }
      default: {  // invalid: NaN, infinity, phi < 0
        const T bad[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(), T(1e-4)};
        in.add(bad[rng() % 3], T(1e-4), (rng() & 1) ? T(-1) : bad[rng() % 3]);
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

TEST(Batch, LongDoubleLanesEqualScalarStable) {
  const auto in = inputs<long double>(2000, 4);
  expect_same_as_scalar(in);
}

}  // namespace
