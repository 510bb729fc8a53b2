// An exhaustive check of solve_stable on miniature binary formats: every
// triple (u, dy, phi) of a few boxes of 6-bit formats, against exact arithmetic.
// It stands for a proof of the stable path at this precision (ctest label
// proofs). For each triple:
//
//   - the case is the exact case, the sign of R(dy) (docs/equations.md,
//     section 2): of u + dy for dy <= 0, of u + dy - phi dy for dy > 0;
//   - s lies on its case's side of dy;
//   - s is within its branch's bound of the exact root s*, the bound of
//     proofs/claimed_bounds.txt carried over to the format's precision (below);
//   - s is never NaN, and infinite only where s* lies beyond the largest
//     finite value, on the same side.
//
// Nothing computes s*. R increases, so |s - s*| <= B ulp(s*) exactly when
// R(s - B ulp(s*)) <= 0 <= R(s + B ulp(s*)); at a dyadic point the sign of R
// is the sign of a polynomial in integers. ulp(s*) is that of the binade of
// s*, found the same way, from the signs of R at +-2^j.
//
// Prints one line, "exhaustive: N triples checked, F failures", then the
// first failures if any, and exits non-zero when F > 0.
#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "contact/harness/claimed_bounds.hpp"
#include "contact/stable.hpp"
#include "mini_float.hpp"

namespace contact::testing {
namespace {

namespace mp = boost::multiprecision;

// ---- the formats and the boxes ------------------------------------------------

// 6 bits; normal numbers from 2^-20 to just below 2^22; no subnormals. The
// plain window (docs/equations.md, section 6) is [2^-2, 2^2], inside the
// central box: both paths run, and the switch between them. Fused: the
// solver's fma is the format's, rounded once; unfused: Dekker's product and
// the solver's own exact sum, as for cpp_bin_float.
template <bool Fused>
using format = mini_float<6, -20, 21, Fused>;

// The same with fewer exponents below 1 than above, down to 2^-12 = 2^-2p,
// the least at which scaled<T> forms the exact product of two significands.
// A cluster of four terms of the exact sign (down to 2^-33) does not fit, and
// the plain window shrinks to [1, 1]: its room below 1 bounds it, not above.
using few_below_one = mini_float<6, -12, 21, false>;

// 0 and every value of the binades 2^low <= |x| < 2^(high + 1).
struct binades {
  int low, high;
};

struct box {
  const char* name;
  binades u, dy, phi;  // u and dy of both signs, phi >= 0
};

// Every ratio |u| / |dy| from 2^-5 to 2^9 and every phi from 2^-6 to 2^10:
// the four cases and both boundaries, the cancellation of (A.31) near s = 0
// and of (A.32) for u >> sqrt(phi) dy, the window's edges. (s* scales with
// (u, dy), so wider boxes would mostly repeat these.)
constexpr box central{"central", {-6, 5}, {-3, -2}, {-6, 9}};
// The largest values: roots beyond and just below the largest finite value,
// the release clamp at the largest dy.
constexpr box top{"top", {19, 21}, {19, 21}, {-3, 3}};
// The least: roots below the least normal value, flushed to zero.
constexpr box bottom{"bottom", {-20, -18}, {-20, -18}, {-3, 3}};
constexpr box bottom_of_few{"bottom", {-12, -10}, {-12, -10}, {-3, 3}};

template <class T>
std::vector<T> values_in(binades range, bool both_signs) {
  std::vector<T> values{T(0)};
  for (int e = range.low; e <= range.high; ++e)
    for (int m = 1 << (T::precision - 1); m < (1 << T::precision); ++m) {
      const T x = ldexp(T(m), e - T::precision + 1);
      values.push_back(x);
      if (both_signs) values.push_back(-x);
    }
  return values;
}

// ---- exact dyadic arithmetic ------------------------------------------------

// Integers that throw std::overflow_error rather than wrap. A triple is
// checked in 128 bits, which suffice for the boxes above, and again in 256
// should they not (a root very many binades from the inputs).
using narrow = mp::number<mp::cpp_int_backend<128, 128, mp::signed_magnitude, mp::checked, void>, mp::et_off>;
using wide = mp::number<mp::cpp_int_backend<256, 256, mp::signed_magnitude, mp::checked, void>, mp::et_off>;

template <class Integer>
struct dyadic {
  Integer m = 0;  // the value m 2^e
  int e = 0;

  friend int sign(const dyadic& a) { return a.m.sign(); }
  friend dyadic operator-(const dyadic& a) { return {-a.m, a.e}; }
  friend dyadic operator*(const dyadic& a, const dyadic& b) { return {a.m * b.m, a.e + b.e}; }
  friend dyadic operator+(const dyadic& a, const dyadic& b) {
    if (a.m == 0) return b;
    if (b.m == 0) return a;
    if (a.e >= b.e) return {shifted(a.m, a.e - b.e) + b.m, b.e};
    return {a.m + shifted(b.m, b.e - a.e), a.e};
  }
  friend dyadic operator-(const dyadic& a, const dyadic& b) { return a + (-b); }

 private:
  // cpp_int shifts magnitudes only
  static Integer shifted(const Integer& m, int k) { return m.sign() < 0 ? Integer(-(Integer(-m) << k)) : Integer(m << k); }
};

template <class Integer>
dyadic<Integer> power_of_two(int sign, int k) {
  return {Integer(sign), k};
}

template <class Integer>
dyadic<Integer> positive_part(const dyadic<Integer>& a) {
  return sign(a) > 0 ? a : dyadic<Integer>{};
}

// A finite double (every value of the format is one), exactly.
template <class Integer>
dyadic<Integer> exactly(double x) {
  if (x == 0) return {};
  int e = 0;
  const auto m = static_cast<std::int64_t>(std::ldexp(std::frexp(x, &e), 53));
  const int zeros = std::countr_zero(static_cast<std::uint64_t>(m < 0 ? -m : m));
  return {Integer(m >> zeros), e - 53 + zeros};
}

// ---- the exact root -----------------------------------------------------------

template <class Integer>
struct exact_input {
  dyadic<Integer> u, dy, phi, compression, compression_squared;  // floor(dy), floor(dy)^2

  exact_input(double u_, double dy_, double phi_)
      : u(exactly<Integer>(u_)), dy(exactly<Integer>(dy_)), phi(exactly<Integer>(phi_)) {
    compression = positive_part(dy);
    compression_squared = compression * compression;
  }

  // The sign of R(s). R(0) = u - 2 phi floor(dy); elsewhere s R(s) is the
  // polynomial s^2 + u s + phi (floor(dy - s)^2 - floor(dy)^2).
  int residual_sign(const dyadic<Integer>& s) const {
    if (sign(s) == 0) return sign(u - power_of_two<Integer>(1, 1) * phi * compression);
    const dyadic<Integer> gap = positive_part(dy - s);
    return sign(s * s + u * s + phi * (gap * gap - compression_squared)) * sign(s);
  }

  contact_case exact_case() const {
    if (sign(dy) <= 0) return sign(u + dy) <= 0 ? contact_case::free : contact_case::impact;
    return sign(u + dy - phi * dy) >= 0 ? contact_case::contact : contact_case::release;
  }
};

// The root to 60 bits or so, by bisection on the sign of R: for the report only.
long double approximate_root(const exact_input<wide>& x) {
  auto sign_at = [&](long double t) {
    int e = 0;
    const long double m = std::frexp(t, &e);
    return x.residual_sign({wide(static_cast<std::int64_t>(std::ldexp(m, 62))), e - 62});
  };
  if (x.residual_sign({}) == 0) return 0;
  long double low = -1, high = 1;
  while (sign_at(low) > 0) low *= 2;
  while (sign_at(high) < 0) high *= 2;
  for (;;) {
    const long double middle = (low + high) / 2;
    if (middle == low || middle == high) return middle;
    (sign_at(middle) < 0 ? low : high) = middle;
  }
}

// ---- the check ------------------------------------------------------------------

// The claimed bounds at p bits. Gappa proves each branch's bound for binary64
// (proofs/gappa), but the argument holds at any precision: every intermediate
// is its exact value times a factor in [(1 - u)^m, (1 - u)^-m], u = 2^-p,
// where a rounding adds 1 to m, a product or quotient adds its operands' m, a
// sum of terms of one sign takes the larger m and a square root halves it.
// The branches' m are 3 (contact), 6 (impact), 6.5 and 3.5 (release, u > 0
// and u <= 0; Gappa finds 4.5, not knowing that halving is exact), the
// first-order terms of the proven bounds. So s is within relative error
// (1 - u)^-m - 1 <= m u / (1 - m u) of s*, that is within m / (1 - m u) ulps
// of s* (ulp(s*) > |s*| u). For binary64 that is m plus a term of order 2^-53,
// which the claimed k (3.01, 6.01, 6.51, 4.51) covers; at p bits the term is
// of order 2^-p, and k / (1 - k u) >= m / (1 - m u) covers it: 3.16, 6.63,
// 7.25 and 4.85 ulps at p = 6. Free is s = -u, exact. Without a fused fma,
// one ulp more, the allowance of the property tests (unfused_fma_allowance,
// tests/harness.hpp): a branch's fma is then an exact product and sum rounded
// twice at the end. A bound is kept as a whole number of 2^-16 ulps, rounded
// up, so that the check is exact.
constexpr int bound_fraction_bits = 16;

template <class T>
class checker {
 public:
  checker() {
    const auto& claimed = harness::project_bounds();
    const double unit_roundoff = std::ldexp(1.0, -precision);
    const double allowance = detail::has_fused_fma<T>::value ? 0 : 1;
    for (bool u_positive : {false, true})
      for (contact_case c : valid_cases) {
        const double k = claimed.for_case(c, u_positive);
        const double bound = k == 0 ? 0 : k / (1 - k * unit_roundoff) + allowance;
        bound_units_[u_positive][int(c)] = static_cast<long>(std::ceil(std::ldexp(bound, bound_fraction_bits)));
      }
  }

  // Why the solver's answer for (u, dy, phi) is wrong, or nothing.
  std::optional<std::string> failure(const T& u, const T& dy, const T& phi, const solution<T>& result) const {
    try {
      return failure_in<narrow>(u, dy, phi, result);
    } catch (const std::overflow_error&) {
      return failure_in<wide>(u, dy, phi, result);
    }
  }

  // The root, and the error in ulps of it against the bound: for the report.
  std::string error_of(const T& u, const T& dy, const T& phi, const solution<T>& result) const {
    const exact_input<wide> x{double(u), double(dy), double(phi)};
    const long double root = approximate_root(x);
    const int root_sign = -x.residual_sign({});
    const int binade = root_sign == 0 ? least_exponent - 1 : binade_of_root(x, root_sign, least_exponent);
    char text[160];
    std::snprintf(text, sizeof text, "the root is %.10Lg, s is %.3Lf ulps off, the bound %.3f", root,
                  (double(result.s) - root) / std::ldexp(1.0L, ulp_exponent(binade)),
                  std::ldexp(double(bound_units_[u > 0][int(x.exact_case())]), -bound_fraction_bits));
    return text;
  }

 private:
  static constexpr int precision = T::precision, least_exponent = T::least_exponent;
  long bound_units_[2][5] = {};

  // ulp(x) for x in binade j: 2^(j - p + 1); below the least normal value,
  // where the format holds only 0 and +-2^least_exponent, their spacing.
  static int ulp_exponent(int binade) { return binade < least_exponent ? least_exponent : binade - precision + 1; }

  // The binade j of the root, 2^j <= |s*| < 2^(j + 1) (least_exponent - 1
  // below the least normal value), for s* != 0 of sign root_sign, searched
  // from guess: |s*| < 2^j exactly when root_sign R(root_sign 2^j) > 0.
  template <class Integer>
  static int binade_of_root(const exact_input<Integer>& x, int root_sign, int guess) {
    auto below = [&](int j) { return root_sign * x.residual_sign(power_of_two<Integer>(root_sign, j)) > 0; };
    int j = std::max(guess, least_exponent);
    while (j > least_exponent && below(j)) --j;
    if (j == least_exponent && below(j)) return least_exponent - 1;
    while (!below(j + 1)) ++j;
    return j;
  }

  template <class Integer>
  std::optional<std::string> failure_in(const T& u, const T& dy, const T& phi, const solution<T>& result) const {
    const exact_input<Integer> x{double(u), double(dy), double(phi)};
    const contact_case expected = x.exact_case();
    if (result.which != expected) return "the case is " + std::string(name_of(expected));
    const T& s = result.s;
    if (isnan(s)) return "NaN";
    if (!lies_on_its_side(result.which, s, dy)) return "s on the wrong side of dy";
    if (isinf(s)) {
      const auto largest = exactly<Integer>(double((std::numeric_limits<T>::max)()));
      const bool root_beyond = s > 0 ? x.residual_sign(largest) < 0 : x.residual_sign(-largest) > 0;
      if (root_beyond) return std::nullopt;
      return "infinite, but the root is not beyond the largest finite value";
    }
    const int root_sign = -x.residual_sign({});
    int binade = least_exponent - 1;  // for s* = 0, the ulp of the flushed range
    if (root_sign != 0) {
      int guess = least_exponent;
      if (s != 0 && (s > 0) == (root_sign > 0)) {
        frexp(s, &guess);
        --guess;
      }
      binade = binade_of_root(x, root_sign, guess);
    }
    const long units = bound_units_[u > 0][int(expected)];
    const dyadic<Integer> reach{Integer(units), ulp_exponent(binade) - bound_fraction_bits};
    const auto exact_s = exactly<Integer>(double(s));
    if (x.residual_sign(exact_s - reach) <= 0 && x.residual_sign(exact_s + reach) >= 0) return std::nullopt;
    return "the error is beyond the bound";
  }

};

// ---- the enumeration ---------------------------------------------------------------

struct tally {
  long checked = 0, failed = 0;
  std::vector<std::pair<long, std::string>> first_failures;  // (position in the enumeration, what)
  static constexpr std::size_t kept = 10;

  // other's failures after this one's, or merged by position
  void add(const tally& other, bool by_position = false) {
    checked += other.checked;
    failed += other.failed;
    first_failures.insert(first_failures.end(), other.first_failures.begin(), other.first_failures.end());
    if (by_position) std::sort(first_failures.begin(), first_failures.end());
    if (first_failures.size() > kept) first_failures.resize(kept);
  }
};

// Every triple of the box, on two threads (the u values alternate).
template <class T>
tally check_box(const box& b, const char* format_name) {
  const checker<T> check;
  const auto us = values_in<T>(b.u, true), dys = values_in<T>(b.dy, true), phis = values_in<T>(b.phi, false);
  constexpr int threads = 2;
  std::vector<tally> tallies(threads);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      tally& mine = tallies[t];
      for (std::size_t i = t; i < us.size(); i += threads)
        for (std::size_t j = 0; j < dys.size(); ++j)
          for (std::size_t k = 0; k < phis.size(); ++k) {
            const T &u = us[i], &dy = dys[j], &phi = phis[k];
            const solution<T> result = solve_stable(u, dy, phi);
            ++mine.checked;
            const auto why = check.failure(u, dy, phi, result);
            if (!why) continue;
            if (mine.failed++ >= long(tally::kept)) continue;
            char text[500];
            std::snprintf(text, sizeof text, "%s %s: u=%.9g dy=%.9g phi=%.9g gives %s s=%.9g: %s; %s", format_name, b.name,
                          double(u), double(dy), double(phi), std::string(name_of(result.which)).c_str(), double(result.s),
                          why->c_str(), check.error_of(u, dy, phi, result).c_str());
            mine.first_failures.emplace_back(long((i * dys.size() + j) * phis.size() + k), text);
          }
    });
  for (auto& worker : workers) worker.join();
  tally total;
  for (const auto& t : tallies) total.add(t, true);
  return total;
}

}  // namespace
}  // namespace contact::testing

int main() {
  using namespace contact::testing;
  tally total;
  for (const box& b : {central, top, bottom}) {
    total.add(check_box<format<true>>(b, "fused"));
    total.add(check_box<format<false>>(b, "unfused"));
  }
  for (const box& b : {central, bottom_of_few}) total.add(check_box<few_below_one>(b, "few-below-one"));
  std::printf("exhaustive: %ld triples checked, %ld failures\n", total.checked, total.failed);
  for (const auto& [position, what] : total.first_failures) std::printf("  %s\n", what.c_str());
  return total.failed > 0 ? 1 : 0;
}
