// Writes the hard-case lists of the correctly rounded mode (double), CORE-MATH
// style: inputs whose exact root is a rounding boundary (a midpoint between two
// doubles) or lies very close to one, and roots at the edges of double's range.
//
//     rounded-hard-cases DIR     (writes DIR/exact_ties_contact.txt, ..., DIR/subnormal_phi.txt)
//
// Each line is "u dy phi expected_s expected_case", C99 hex floats; expected_s
// is the certified reference root rounded to nearest (ties to even) with
// gradual underflow, expected_case the exact case (1-4). Every line is checked
// against the reference before it is written: the root is certified, it is
// exactly a midpoint for the tie files, and within 2^-16 ulp of one (but not on
// it) for near_ties.txt. The output is deterministic (fixed seeds).
#include <gmp.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "contact/reference.hpp"

namespace {

using contact::reference::real;
using u128 = unsigned __int128;

constexpr mpfr_prec_t bits = 512;

std::string hex(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}

// x (an integer below 2^128) times 2^e as a double; throws unless exact.
double exact_double(u128 x, int e) {
  const double high = static_cast<double>(static_cast<std::uint64_t>(x >> 64)) * 0x1p64;
  const double value = high + static_cast<double>(static_cast<std::uint64_t>(x));
  if (static_cast<u128>(value) != x) throw std::logic_error("not a double");
  return std::ldexp(value, e);
}

int significant_bits(u128 x) {
  if (x == 0) return 0;
  int low = 0, high = 127;
  while (!((x >> low) & 1)) ++low;
  while (!((x >> high) & 1)) --high;
  return high - low + 1;
}

// The distance of the exact root to the nearest midpoint between doubles, in
// ulps of double (0 for a tie; subnormal ulps below 2^-1022); negative if the
// root is 0 or beyond double's range.
double distance_to_midpoint(const real& root) {
  if (mpfr_zero_p(root.get()) || !mpfr_number_p(root.get())) return -1;
  long e = long(mpfr_get_exp(root.get())) - 1;  // 2^e <= |root| < 2^(e+1)
  if (e > 1023) return -1;
  if (e < -1022) e = -1022;
  real scaled(bits + 64), fraction(bits + 64);
  mpfr_abs(scaled.get(), root.get(), MPFR_RNDN);
  mpfr_mul_2si(scaled.get(), scaled.get(), 52 - e, MPFR_RNDN);  // |root| / ulp
  mpfr_frac(fraction.get(), scaled.get(), MPFR_RNDN);
  mpfr_sub_d(fraction.get(), fraction.get(), 0.5, MPFR_RNDN);
  return std::fabs(mpfr_get_d(fraction.get(), MPFR_RNDN));
}

class writer {
 public:
  writer(const std::string& path, const std::string& header) : out_(path) {
    if (!out_) throw std::runtime_error("cannot write " + path);
    out_ << header;
  }
  // Appends the input with its reference answer; `accept` checks the root.
  bool add(double u, double dy, double phi, const std::function<bool(const real&)>& accept) {
    if (!std::isfinite(u) || !std::isfinite(dy) || !std::isfinite(phi) || phi < 0) return false;
    const auto exact = contact::reference::solve(u, dy, phi, bits);
    if (!exact.is_certified || !accept(exact.s)) return false;
    const double s = mpfr_get_d(contact::reference::rounded_root(exact, u, dy, phi).get(), MPFR_RNDN);
    out_ << hex(u) << ' ' << hex(dy) << ' ' << hex(phi) << ' ' << hex(s) << ' ' << static_cast<int>(exact.which)
         << '\n';
    ++count_;
    return true;
  }
  int count() const { return count_; }

 private:
  std::ofstream out_;
  int count_ = 0;
};

const char* const format = "# u dy phi expected_s expected_case (C99 hex; written by generate.cpp, do not edit)\n";

bool is_tie(const real& root) { return distance_to_midpoint(root) == 0; }

// (A.31) s = (2 phi dy - u) / (1 + phi) with 1 + phi = 2^k: s = M 2^(j-k) for an
// odd M of 54 bits is a midpoint when dy = D 2^(j-1) and u = (A - M) 2^j,
// A = (2^k - 1) D, are doubles: D is chosen with (2^k - 1) D = M mod 2^12, so
// that A - M has trailing zeros, and D >= M / 2^(k-1) keeps the input in (A.31).
void exact_ties_contact(const std::string& dir) {
  writer w(dir + "/exact_ties_contact.txt",
           std::string(format) + "# (A.31) with phi = 2^k - 1 and 2 phi dy - u = M 2^j, M odd of 54 bits\n");
  std::mt19937_64 rng(31);
  while (w.count() < 40) {
    const int k = 2 + int(rng() % 20);
    const u128 M = (u128(1) << 53) | (rng() & ((std::uint64_t(1) << 53) - 1)) | 1;
    const u128 multiplier = (u128(1) << k) - 1;
    // inverse of the odd multiplier modulo 2^12 (Newton's iteration doubles the correct bits)
    u128 inverse = multiplier;
    for (int i = 0; i < 5; ++i) inverse = inverse * (2 - multiplier * inverse);
    const u128 mask = (u128(1) << 12) - 1;
    const u128 base = (M + (u128(1) << (k - 1)) - 1) / (u128(1) << (k - 1)) + (rng() % (1u << 20));
    const u128 D = base + (((M * inverse) - base) & mask);
    const u128 A = multiplier * D;
    if (A <= M || significant_bits(D) > 53 || significant_bits(A - M) > 53) continue;
    const int j = int(rng() % 1800) - 900;
    w.add(exact_double(A - M, j), exact_double(D, j - 1), double(multiplier), is_tie);
  }
}

// (A.32) s^2 + u s - phi dy^2 = 0 with s = a^2 2^e, a odd and a^2 of 54 bits (a
// midpoint): u = +-2^e, dy = a 2^g, phi = (a^2 +- 1) 2^(2e - 2g) make
// s (s + u) = a^2 (a^2 +- 1) 2^(2e) = phi dy^2 exactly.
void exact_ties_release(const std::string& dir) {
  writer w(dir + "/exact_ties_release.txt",
           std::string(format) + "# (A.32) with s = a^2 2^e, a odd, a^2 of 54 bits: u = +-2^e, dy = a 2^g, "
                                 "phi = (a^2 +- 1) 2^(2e-2g)\n");
  std::mt19937_64 rng(32);
  const std::uint64_t lowest = 94906267;  // ceil(2^26.5), odd: a^2 >= 2^53
  while (w.count() < 40) {
    const std::uint64_t a = (lowest + rng() % ((std::uint64_t(1) << 27) - lowest)) | 1;
    const u128 square = u128(a) * a;
    if (square < (u128(1) << 53) || square >= (u128(1) << 54)) continue;
    const bool negative_u = rng() % 2;
    const int e = int(rng() % 900) - 450, g = e - int(rng() % 24);
    const u128 coefficient = negative_u ? square - 1 : square + 1;  // even, so it has <= 53 bits
    w.add(negative_u ? -std::ldexp(1.0, e) : std::ldexp(1.0, e), exact_double(a, g),
          exact_double(coefficient, 2 * (e - g)), is_tie);
  }
}

// (A.30) s (s + u) + phi (dy - s)^2 = 0 with phi = 1, s = -a^2 2^e (a midpoint),
// dy - s = a 2^e: u = (a^2 + 1) 2^e and dy = -a (a - 1) 2^e are doubles.
void exact_ties_impact(const std::string& dir) {
  writer w(dir + "/exact_ties_impact.txt",
           std::string(format) + "# (A.30) with phi = 1, s = -a^2 2^e, a odd, a^2 of 54 bits: u = (a^2 + 1) 2^e, "
                                 "dy = -a (a - 1) 2^e\n");
  std::mt19937_64 rng(33);
  const std::uint64_t lowest = 94906267;
  while (w.count() < 30) {
    const std::uint64_t a = (lowest + rng() % ((std::uint64_t(1) << 27) - lowest)) | 1;
    const u128 square = u128(a) * a;
    if (square < (u128(1) << 53) || square >= (u128(1) << 54)) continue;
    const int e = int(rng() % 1800) - 900;
    w.add(exact_double(square + 1, e), -exact_double(u128(a) * (a - 1), e), 1.0, is_tie);
  }
}

// A random double with 53 random bits and a random exponent in [lo, hi].
double random_double(std::mt19937_64& rng, int lo, int hi) {
  const double m = 1 + std::ldexp(double(rng() >> 11), -53);
  return std::ldexp(m, lo + int(rng() % std::uint64_t(hi - lo + 1)));
}

// Roots within 2^-16 ulp of a midpoint, not on it, in each case and over
// magnitudes from the audio-rate range to 2^+-300. (A.31) and (A.32): the
// input is built around a midpoint m, rounding one input to a double, so the
// root misses m by the rounding error of a small quantity. (A.30): a random
// search, filtered by the linearised distance first.
void near_ties(const std::string& dir) {
  writer w(dir + "/near_ties.txt", std::string(format) + "# roots within 2^-16 ulp of a midpoint, not on it\n");
  std::mt19937_64 rng(34);
  const auto near = [](const real& root) {
    const double d = distance_to_midpoint(root);
    return d > 0 && d <= 0x1p-16;
  };
  const int ranges[][2] = {{-30, -10}, {-300, 300}, {-60, 60}};
  auto midpoint = [&](int lo, int hi, real& m) {  // a random midpoint > 0, and the double below it
    const double below = random_double(rng, lo, hi);
    mpfr_set_d(m.get(), below, MPFR_RNDN);
    int e = 0;
    std::frexp(below, &e);
    real half_ulp(64);
    mpfr_set_ui_2exp(half_ulp.get(), 1, e - 54, MPFR_RNDN);
    mpfr_add(m.get(), m.get(), half_ulp.get(), MPFR_RNDN);
  };
  const auto r = MPFR_RNDN;
  // (A.31), phi < 1: dy = RN((1 + phi) m / (2 phi)), u = RN(2 phi dy - (1 + phi) m)
  for (int found = 0, tries = 0; found < 12 && tries < 100000; ++tries) {
    const auto& range = ranges[found % 3];
    real m(bits), t(bits), v(bits);
    midpoint(range[0], range[1], m);
    const double phi = random_double(rng, -30, -1);
    mpfr_set_d(v.get(), phi, r);
    mpfr_add_ui(v.get(), v.get(), 1, r);
    mpfr_mul(t.get(), m.get(), v.get(), r);  // (1 + phi) m
    mpfr_div_d(v.get(), t.get(), 2 * phi, r);
    const double dy = mpfr_get_d(v.get(), r);
    mpfr_set_d(v.get(), dy, r);
    mpfr_mul_d(v.get(), v.get(), 2 * phi, r);
    mpfr_sub(v.get(), v.get(), t.get(), r);
    const double u = mpfr_get_d(v.get(), r);
    if (w.add(u, dy, phi, near)) ++found;
  }
  // (A.32), phi > 1: dy = RN(m / sqrt(phi)), u = RN((phi dy^2 - m^2) / m)
  for (int found = 0, tries = 0; found < 12 && tries < 100000; ++tries) {
    const auto& range = ranges[found % 3];
    real m(bits), v(bits), t(bits);
    midpoint(range[0], range[1], m);
    const double phi = random_double(rng, 1, 30);
    mpfr_set_d(v.get(), phi, r);
    mpfr_sqrt(v.get(), v.get(), r);
    mpfr_div(v.get(), m.get(), v.get(), r);
    const double dy = mpfr_get_d(v.get(), r);
    mpfr_set_d(v.get(), dy, r);
    mpfr_sqr(v.get(), v.get(), r);
    mpfr_mul_d(v.get(), v.get(), phi, r);
    mpfr_sqr(t.get(), m.get(), r);
    mpfr_sub(v.get(), v.get(), t.get(), r);
    mpfr_div(v.get(), v.get(), m.get(), r);
    const double u = mpfr_get_d(v.get(), r);
    if (w.add(u, dy, phi, near)) ++found;
  }
  // (A.30): s = -m, dy = s t, u = RN((s^2 + phi (dy - s)^2) / |s|); the root moves
  // from -m by about (u~ - u) / R'(-m), R' = 1 + phi (1 - dy^2 / s^2)
  for (int found = 0, tries = 0; found < 12 && tries < 20000000; ++tries) {
    const auto& range = ranges[found % 3];
    real m(bits), v(bits), t(bits), g(bits), exact_u(bits), slope(bits);
    midpoint(range[0], range[1], m);
    mpfr_neg(m.get(), m.get(), r);  // the midpoint, negative
    const double phi = random_double(rng, -10, 20);
    mpfr_mul_d(v.get(), m.get(), std::ldexp(double(rng() >> 11), -53), r);
    const double dy = mpfr_get_d(v.get(), MPFR_RNDU);  // in (s, 0]
    mpfr_set_d(g.get(), dy, r);
    mpfr_sub(g.get(), g.get(), m.get(), r);  // dy - s > 0
    mpfr_sqr(t.get(), g.get(), r);
    mpfr_mul_d(t.get(), t.get(), phi, r);
    mpfr_sqr(v.get(), m.get(), r);
    mpfr_add(t.get(), t.get(), v.get(), r);
    mpfr_div(exact_u.get(), t.get(), m.get(), r);
    mpfr_neg(exact_u.get(), exact_u.get(), r);
    const double u = mpfr_get_d(exact_u.get(), r);
    // linearised miss, in ulps of the root
    mpfr_set_d(v.get(), dy, r);
    mpfr_div(v.get(), v.get(), m.get(), r);
    mpfr_sqr(v.get(), v.get(), r);
    mpfr_ui_sub(v.get(), 1, v.get(), r);
    mpfr_mul_d(slope.get(), v.get(), phi, r);
    mpfr_add_ui(slope.get(), slope.get(), 1, r);
    mpfr_sub_d(v.get(), exact_u.get(), u, r);
    mpfr_div(v.get(), v.get(), slope.get(), r);
    int e = 0;
    std::frexp(mpfr_get_d(m.get(), r), &e);
    mpfr_mul_2si(v.get(), v.get(), 53 - e, r);
    if (std::fabs(mpfr_get_d(v.get(), r)) > 0x1p-15) continue;
    if (w.add(u, dy, phi, near)) ++found;
  }
}

// Roots at the edges of double's range: subnormal results in each case (and
// ties between subnormals), and roots near the overflow threshold
// DBL_MAX + ulp(DBL_MAX)/2, on both sides of it.
void range_edges(const std::string& dir) {
  writer w(dir + "/range_edges.txt", std::string(format) + "# subnormal roots, ties between subnormals, roots near overflow\n");
  std::mt19937_64 rng(35);
  const auto any = [](const real&) { return true; };
  const double tiny = std::numeric_limits<double>::denorm_min(), max = std::numeric_limits<double>::max();
  // (A.31) with phi = 1: s = (2 dy - u) / 2, a tie between subnormals when 2 dy - u is an odd multiple of 2^-1074
  for (int i = 0; i < 8; ++i) {
    const double dy = tiny * double(1 + rng() % 1000000), u = tiny * double(2 * (rng() % 100000) + 1);
    w.add(u, dy, 1.0, is_tie);
  }
  // subnormal roots in (A.30), (A.31), (A.32): tiny inputs
  for (int i = 0; i < 24; ++i) {
    const double phi = random_double(rng, -20, 20);
    const double a = random_double(rng, -1074, -1030), b = random_double(rng, -1074, -1030);
    switch (i % 3) {
      case 0: w.add(a, -b, phi, any); break;           // impact when a > b
      case 1: w.add(a, b, std::min(phi, 0.5), any); break;  // contact
      default: w.add(-a, b, phi + 1, any); break;       // release
    }
  }
  // (A.32) with u < 0 and phi dy^2 small: s = |u| + phi dy^2 / |u| + ..., placed
  // within a few ulps of the overflow threshold
  for (int i = 0; i < 16; ++i) {
    const double u = -(max - std::ldexp(double(rng() % 4), 971));
    const double c = 0.125 * double(1 + rng() % 24);  // phi dy^2 / |u| in ulps of DBL_MAX
    const double dy = std::ldexp(1.0, 600);
    const double phi = c * std::ldexp(1.0, 971) / dy / dy * (-u);
    w.add(u, dy, phi, any);
  }
  // (A.32) with dy = DBL_MAX: the root is within an ulp of DBL_MAX or beyond
  for (int i = 0; i < 6; ++i) w.add(std::ldexp(double(i), 970), max, 1 + std::ldexp(1.0, -52), any);
  // (A.32) with the root exactly on the overflow threshold (2^54 - 1) 2^970, a tie
  // that IEEE rounds to infinity: s + u = w = (2^27 + 1) 2^970, dy = (2^27 + 1) 2^970,
  // phi = 2^27 - 1, so that s w = (2^54 - 1)(2^27 + 1) 2^1940 = phi dy^2
  w.add(-std::ldexp(double((std::uint64_t(1) << 53) - (1u << 26) - 1), 971), std::ldexp(double((1u << 27) + 1), 970),
        double((1u << 27) - 1), is_tie);
  // (A.30) with roots near -DBL_MAX
  for (int i = 0; i < 8; ++i) {
    const double u = max - std::ldexp(double(rng() % 8), 971);
    const double dy = -(max - std::ldexp(double(rng() % (1u << 20)), 971));
    w.add(u, dy, random_double(rng, -40, -10), any);
  }
}

// (A.31) with a subnormal phi = k 2^-1074 (k odd) and dy = (M / k) 2^e, M an
// odd 54-bit multiple of k: 2 phi dy = M 2^(e-1073) is a midpoint, and the root
// (2 phi dy - u) / (1 + phi) lies about 2^-1074 of itself from it, on the side
// that -u - phi 2 phi dy picks: far below the reference's working precision,
// so only the exact sign of R at the midpoint tells the side (the reference
// root at `bits` bits is the midpoint itself). u is 0, subnormal or small
// normal, of either sign. The first three are the inputs of the shared
// families that exposed this (whole_range, double).
void subnormal_phi(const std::string& dir) {
  writer w(dir + "/subnormal_phi.txt",
           std::string(format) + "# (A.31) with subnormal phi: roots within about 2^-1074 of themselves from a midpoint\n");
  const auto near = [](const real& root) {
    const double d = distance_to_midpoint(root);
    return d >= 0 && d < 0x1p-40;
  };
  w.add(-0x0.13fccb69b00b1p-1022, 0x1.a6fb214114dfcp+477, 0x0.0000000000007p-1022, near);
  w.add(-0x0.000002e718d59p-1022, 0x1.b17938d742fdp+714, 0x0.0000000000025p-1022, near);
  w.add(0.0, 0x1.32bd8d44d0684p+951, 0x0.0000000000007p-1022, near);
  std::mt19937_64 rng(36);
  const double tiny = std::numeric_limits<double>::denorm_min();
  while (w.count() < 40) {
    const std::uint64_t k = 2 * (1 + rng() % 64) + 1;
    std::uint64_t m = (std::uint64_t(1) << 53) + (rng() >> 11);  // 54 bits
    m -= m % k;                                                   // a multiple of k ...
    if (m % 2 == 0) m += k;                                       // ... and odd
    if (m >> 54) continue;
    const double dy = exact_double(m / k, int(rng() % 1200) - 500);
    const double u_choices[] = {0.0, tiny * double(1 + rng() % 100000), -tiny * double(1 + rng() % 100000),
                                std::ldexp(double(rng() >> 11), -1060 - int(rng() % 20)),
                                -std::ldexp(double(rng() >> 11), -1060 - int(rng() % 20))};
    w.add(u_choices[rng() % 5], dy, tiny * double(k), near);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  exact_ties_contact(dir);
  exact_ties_release(dir);
  exact_ties_impact(dir);
  near_ties(dir);
  range_edges(dir);
  subnormal_phi(dir);
  return 0;
}
