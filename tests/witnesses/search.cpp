// Looks for the inputs on which each non-exact branch of solve_stable<double>
// loses the most ulps: random draws over the regimes the error analysis points
// at, then hill climbing on the error (moving one input by a few to 2^40 ulps),
// measured against the same formula in binary128 (enough for ranking: the
// stable forms do not cancel), and the best ones certified by the reference.
//
//   witness-search [iterations-per-start] [starts] [seed] [relative]
//
// With "relative" it climbs on |s - S| / |S| in units of 2^-53 instead (the
// quantity the Gappa proofs bound; the printed certified error stays in ulps).
// prints "branch u dy phi error" lines (hex), the format of
// proofs/witnesses.txt, best first per branch.
#include <quadmath.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "contact/reference.hpp"
#include "contact/stable.hpp"

namespace {

using quad = __float128;
using contact::contact_case;

struct input {
  double u, dy, phi;
};

std::string branch_of(const contact::solution<double>& r, double u) {
  switch (r.which) {
    case contact_case::impact: return "impact";
    case contact_case::release: return u > 0 ? "release_u_positive" : "release_u_nonpositive";
    case contact_case::contact: return "contact";
    default: return "free";
  }
}

// The exact root (to about 110 bits) of the branch's formula.
quad root_in_quad(const std::string& branch, const input& x) {
  const quad u = x.u, dy = x.dy, phi = x.phi;
  if (branch == "impact") {
    const quad gap = -dy, push = phi * gap;
    return -((u + 2 * push) + sqrtq(u * u + 4 * push * (u - gap))) / (2 * (1 + phi));
  }
  if (branch == "contact") return (2 * phi * dy - u) / (1 + phi);
  const quad st = phi * dy * dy, root = sqrtq(u * u + 4 * st);
  return u > 0 ? 2 * st / (u + root) : (root - u) / 2;
}

double ulp_of(double exact) {
  int e;
  std::frexp(exact, &e);
  return std::ldexp(1.0, std::max(e - 1, -1022) - 52);
}

bool relative = false;

// The error in ulps, or -1 if the input leaves `branch` or the plain window.
double error_of(const std::string& branch, const input& x) {
  if (!(x.phi >= 0) || !std::isfinite(x.u) || !std::isfinite(x.dy) || !std::isfinite(x.phi)) return -1;
  if (!contact::detail::inside_plain_window(x.u, x.dy, x.phi)) return -1;
  const auto r = contact::solve_stable(x.u, x.dy, x.phi);
  if (branch_of(r, x.u) != branch) return -1;
  const quad exact = root_in_quad(branch, x);
  const double e = static_cast<double>(exact);
  if (e == 0 || !std::isfinite(r.s)) return -1;
  // relative: in units of 2^-53 of the exact value, the measure Gappa bounds
  const quad unit = relative ? fabsq(exact) * quad(0x1p-53) : quad(ulp_of(e));
  return static_cast<double>(fabsq(quad(r.s) - exact) / unit);
}

std::mt19937_64 rng;
double uniform() { return std::uniform_real_distribution<double>(0, 1)(rng); }
double log_uniform(double lo, double hi) { return std::exp2(lo + (hi - lo) * uniform()); }
double random_bits(double x) {  // x with its significand's low 40 bits random
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  bits ^= rng() & ((std::uint64_t(1) << 40) - 1);
  std::memcpy(&x, &bits, 8);
  return x;
}

// A start in the branch, from the regimes the error analysis names.
input draw(const std::string& branch) {
  const int regime = int(rng() % 4);
  if (branch == "impact") {
    if (regime == 0) {
      // phi in [2^53, 2^54): 1 + phi rounds (a tie), push dominates the
      // numerator, gap at the top of its binade, phi and push at the bottom
      const double gap = random_bits(std::ldexp(1.9999, int(rng() % 8)));
      const double phi = random_bits(std::ldexp(1.0001, 53));
      const double u = gap * (1 + uniform());
      return {u, -gap, phi};
    }
    const double u = log_uniform(0, 1);
    const double gap = u * (regime == 1 ? uniform() : 1 - log_uniform(-40, -1));
    const double phi = regime == 3 ? log_uniform(-60, 0) : log_uniform(-20, 60);
    return {u, -gap, phi};
  }
  const double dy = log_uniform(0, 1);
  if (branch == "release_u_positive") {
    if (regime == 3) {
      // u well above 2 sqrt(phi) dy: u + root is about 2 u, so the two
      // roundings of phi dy^2 reach s undamped; phi dy, phi dy^2, u and
      // u + root at the bottom of their binades, s at the top of its own
      const double a = uniform() / 256, b = uniform() / 256, beta = a + 2 * b + uniform() / 64;
      const int p = 20 + int(rng() % 40);
      const double phi = random_bits(std::ldexp(1 + a, p)), dy = random_bits(1 + b);
      const int m = p / 2 + 8 + int(rng() % std::max(1, p / 2 - 10));
      return {random_bits(std::ldexp(1 + beta, m)), dy, phi};
    }
    const double phi = regime == 0 ? log_uniform(0.01, 3) : log_uniform(0, 60);
    const double u = dy * (phi - 1) * (regime == 1 ? log_uniform(-60, 0) : uniform());
    return {u, dy, phi};
  }
  const double phi = regime == 0 ? log_uniform(-60, 0) : log_uniform(-10, 60);
  const double u = regime == 1 ? -log_uniform(-80, -20) : -dy * log_uniform(-30, 30);
  return {u, dy, phi};
}

input mutate(const input& x) {
  input y = x;
  double* v = (&y.u) + (rng() % 3);
  const int step = int(rng() % 41);
  const double away = std::ldexp(1.0, step) * (rng() % 2 ? 1 : -1);
  std::uint64_t bits;
  std::memcpy(&bits, v, 8);
  bits += static_cast<std::int64_t>(away);
  std::memcpy(v, &bits, 8);
  return y;
}

struct found {
  input x;
  double error;
};

}  // namespace

int main(int argc, char** argv) {
  const long iterations = argc > 1 ? std::atol(argv[1]) : 20000;
  const int starts = argc > 2 ? std::atoi(argv[2]) : 200;
  rng.seed(argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 20261123);
  relative = argc > 4 && std::string(argv[4]) == "relative";
  const std::vector<std::string> branches = {"impact", "release_u_positive", "release_u_nonpositive", "contact"};
  for (const auto& branch : branches) {
    std::vector<found> best;
    for (int start = 0; start < starts; ++start) {
      // the best of a few random draws, then climbing from it
      found current{{}, -1};
      for (int i = 0; i < 200; ++i) {
        const input x = draw(branch);
        const double e = error_of(branch, x);
        if (e > current.error) current = {x, e};
      }
      if (current.error < 0) continue;
      for (long i = 0; i < iterations; ++i) {
        const input y = mutate(current.x);
        const double e = error_of(branch, y);
        if (e >= current.error) current = {y, e};
      }
      best.push_back(current);
    }
    std::sort(best.begin(), best.end(), [](const found& a, const found& b) { return a.error > b.error; });
    for (std::size_t i = 0; i < std::min<std::size_t>(best.size(), 5); ++i) {
      const auto& x = best[i].x;
      const auto exact = contact::reference::solve(x.u, x.dy, x.phi);
      const auto r = contact::solve_stable(x.u, x.dy, x.phi);
      const double certified = contact::reference::ulp_error(r.s, exact);
      std::printf("%-22s %a %a %a %.6f  # quad %.6f%s\n", branch.c_str(), x.u, x.dy, x.phi, certified,
                  best[i].error, exact.is_certified ? "" : " NOT CERTIFIED");
    }
    std::fflush(stdout);
  }
}
