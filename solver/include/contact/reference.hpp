// The certified reference solution of (A.2), in MPFR, against which every
// accuracy figure of the project is measured.
//
// The case is decided exactly, in rational arithmetic (GMP). s is then
// computed by the case's closed form in MPFR at `bits` >= 256 bits, and
// certified: the exact residual of (A.2) is evaluated in rational arithmetic at
// s - delta and s + delta (delta = 2^-(bits-8) |s|) and must change sign there.
// R is strictly increasing, so the one root lies in that bracket; when both
// ends round to the same value of T, that value is the correctly rounded root.
#pragma once

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cases.hpp"
#include "detail/float_tools.hpp"

namespace contact::reference {

// RAII for mpfr_t at a fixed precision. Movable (a certified answer goes into
// containers), not copyable: every copy the reference needs is an explicit mpfr_set.
class real {
 public:
  explicit real(mpfr_prec_t bits) { mpfr_init2(value_, bits); mpfr_set_zero(value_, 1); }
  real(real&& other) noexcept {
    mpfr_init2(value_, mpfr_get_prec(other.value_));
    mpfr_swap(value_, other.value_);
  }
  real(const real&) = delete;
  real& operator=(const real&) = delete;
  real& operator=(real&&) = delete;
  ~real() { mpfr_clear(value_); }
  mpfr_ptr get() { return value_; }
  mpfr_srcptr get() const { return value_; }
  std::string to_string(int digits = 40) const {
    char* text = nullptr;
    mpfr_asprintf(&text, "%.*Rg", digits, value_);
    std::string result(text);
    mpfr_free_str(text);
    return result;
  }

 private:
  mpfr_t value_;
};

// RAII for mpq_t: exact rationals, for signs that must not be rounded. Results
// are built in place (no copies exist to go wrong).
class rational {
 public:
  rational() { mpq_init(value_); }
  explicit rational(const real& x) { mpq_init(value_); mpfr_get_q(value_, x.get()); }
  rational(const rational&) = delete;
  rational& operator=(const rational&) = delete;
  ~rational() { mpq_clear(value_); }
  mpq_ptr get() { return value_; }
  mpq_srcptr get() const { return value_; }
  int sign() const { return mpq_sgn(value_); }
  friend rational operator+(const rational& a, const rational& b) { return {mpq_add, a, b}; }
  friend rational operator-(const rational& a, const rational& b) { return {mpq_sub, a, b}; }
  friend rational operator*(const rational& a, const rational& b) { return {mpq_mul, a, b}; }

 private:
  rational(void (*operation)(mpq_ptr, mpq_srcptr, mpq_srcptr), const rational& a, const rational& b) {
    mpq_init(value_);
    operation(value_, a.value_, b.value_);
  }
  mpq_t value_;
};

// x of any binary floating type, exactly, as an MPFR number of `bits` >= its
// precision: the significand is peeled off 32 bits at a time, each step exact.
template <class T>
real exactly(const T& x, mpfr_prec_t bits) {
  using std::floor;
  using std::frexp;
  using std::ldexp;
  real result(bits);
  if (x == 0) return result;
  int exponent = 0;
  T rest = frexp(x < 0 ? T(-x) : x, &exponent);
  int consumed = 0;
  while (rest != 0) {
    rest = ldexp(rest, 32);
    T chunk = floor(rest);
    rest -= chunk;
    consumed += 32;
    mpfr_mul_2ui(result.get(), result.get(), 32, MPFR_RNDN);
    mpfr_add_ui(result.get(), result.get(), static_cast<unsigned long>(static_cast<double>(chunk)), MPFR_RNDN);
  }
  mpfr_mul_2si(result.get(), result.get(), static_cast<long>(exponent) - consumed, MPFR_RNDN);
  if (x < 0) mpfr_neg(result.get(), result.get(), MPFR_RNDN);
  return result;
}

struct certified {
  real s;               // the root, to the working precision
  real lower, upper;    // R(lower) <= 0 <= R(upper), exactly
  contact_case which;   // exact
  bool is_certified;    // false only if the bracket test failed (never seen; tested)
};

namespace detail_ref {

inline rational floor_squared(const rational& x) { return x.sign() > 0 ? x * x : rational(); }

// sign of R(s) = s + u + phi (floor(dy - s)^2 - floor(dy)^2) / s, exactly
// (as the sign of s R(s), a polynomial, times the sign of s); at s = 0 the sign
// of R's limit there, u - 2 phi floor(dy), the continuous extension (A.2) is
// read with.
inline int residual_sign(const rational& s, const rational& u, const rational& dy, const rational& phi) {
  if (s.sign() == 0) return (u - (dy.sign() > 0 ? phi * dy + phi * dy : rational())).sign();
  rational times_s = s * s + u * s + phi * (floor_squared(dy - s) - floor_squared(dy));
  return times_s.sign() * s.sign();
}

}  // namespace detail_ref

// The certificate of a root s of (A.2): sets [lower, upper] to s -+ a relative
// 2^-(bits - 8) of s and returns whether the exact residual changes sign
// across it, R(lower) <= 0 <= R(upper); R being increasing, the exact root then
// lies in [lower, upper]. At s = 0 the interval is the point 0, and the test is
// that the limit of R there, u - 2 phi floor(dy), vanishes.
inline bool certify(const real& s, real& lower, real& upper, const rational& u, const rational& dy,
                    const rational& phi, mpfr_prec_t bits) {
  if (mpfr_zero_p(s.get())) {
    mpfr_set_zero(lower.get(), 1);
    mpfr_set_zero(upper.get(), 1);
    return detail_ref::residual_sign(rational(), u, dy, phi) == 0;
  }
  real delta(mpfr_get_prec(s.get()));
  mpfr_abs(delta.get(), s.get(), MPFR_RNDN);
  mpfr_div_2ui(delta.get(), delta.get(), static_cast<unsigned long>(bits - 8), MPFR_RNDN);
  mpfr_sub(lower.get(), s.get(), delta.get(), MPFR_RNDD);
  mpfr_add(upper.get(), s.get(), delta.get(), MPFR_RNDU);
  return detail_ref::residual_sign(rational(lower), u, dy, phi) <= 0 &&
         detail_ref::residual_sign(rational(upper), u, dy, phi) >= 0;
}

// Solves (A.2) for finite u, dy and phi >= 0 given in type T.
template <class T>
certified solve(const T& u_in, const T& dy_in, const T& phi_in, mpfr_prec_t bits = 0) {
  const int digits = contact::detail::precision_of<T>();
  if (bits == 0) bits = std::max<mpfr_prec_t>(256, 4 * digits);
  const real u = exactly(u_in, bits), dy = exactly(dy_in, bits), phi = exactly(phi_in, bits);
  const rational uq(u), dyq(dy), phiq(phi);

  contact_case which;
  if (dyq.sign() <= 0) which = (uq + dyq).sign() <= 0 ? contact_case::free : contact_case::impact;
  else which = (uq + dyq - phiq * dyq).sign() >= 0 ? contact_case::contact : contact_case::release;

  // The closed forms, each from (A.2) (see stable.hpp for the derivations).
  // Exponents are unbounded here, and `work` bits of precision make every rounding negligible.
  const mpfr_prec_t work = bits + 64;
  real s(work), a(work), b(work), c(work);
  const auto r = MPFR_RNDN;
  switch (which) {
    case contact_case::free:  // (A.29)
      mpfr_neg(s.get(), u.get(), r);
      break;
    case contact_case::impact:  // (A.30): -(u - 2 phi dy + sqrt(u^2 - 4 phi dy (u + dy))) / (2 (1 + phi))
      mpfr_add(a.get(), u.get(), dy.get(), r);
      mpfr_mul(a.get(), a.get(), dy.get(), r);
      mpfr_mul(a.get(), a.get(), phi.get(), r);
      mpfr_mul_2ui(a.get(), a.get(), 2, r);
      mpfr_sqr(b.get(), u.get(), r);
      mpfr_sub(a.get(), b.get(), a.get(), r);
      mpfr_sqrt(a.get(), a.get(), r);
      mpfr_mul(b.get(), phi.get(), dy.get(), r);
      mpfr_mul_2ui(b.get(), b.get(), 1, r);
      mpfr_sub(b.get(), u.get(), b.get(), r);
      mpfr_add(a.get(), a.get(), b.get(), r);
      mpfr_add_ui(c.get(), phi.get(), 1, r);
      mpfr_mul_2ui(c.get(), c.get(), 1, r);
      mpfr_div(s.get(), a.get(), c.get(), r);
      mpfr_neg(s.get(), s.get(), r);
      break;
    case contact_case::contact:  // (A.31) corrected: (2 phi dy - u) / (1 + phi)
      mpfr_mul(a.get(), phi.get(), dy.get(), r);
      mpfr_mul_2ui(a.get(), a.get(), 1, r);
      mpfr_sub(a.get(), a.get(), u.get(), r);
      mpfr_add_ui(c.get(), phi.get(), 1, r);
      mpfr_div(s.get(), a.get(), c.get(), r);
      break;
    default: {  // (A.32), rationalised for u > 0: 2 phi dy^2 / (u + sqrt(u^2 + 4 phi dy^2))
      mpfr_sqr(a.get(), dy.get(), r);
      mpfr_mul(a.get(), a.get(), phi.get(), r);  // phi dy^2
      mpfr_mul_2ui(b.get(), a.get(), 2, r);
      mpfr_sqr(c.get(), u.get(), r);
      mpfr_add(b.get(), b.get(), c.get(), r);
      mpfr_sqrt(b.get(), b.get(), r);  // the root
      if (mpfr_sgn(u.get()) > 0) {
        mpfr_add(b.get(), b.get(), u.get(), r);
        mpfr_mul_2ui(a.get(), a.get(), 1, r);
        mpfr_div(s.get(), a.get(), b.get(), r);
      } else {
        mpfr_sub(s.get(), b.get(), u.get(), r);
        mpfr_div_2ui(s.get(), s.get(), 1, r);
      }
    }
  }

  certified result{real(work), real(work), real(work), which, false};
  mpfr_set(result.s.get(), s.get(), r);
  result.is_certified = certify(result.s, result.lower, result.upper, uq, dyq, phiq, bits);
  return result;
}

// R(s) of (A.2), exactly (in rationals), then rounded to `bits` bits; s != 0.
template <class T>
real residual_at(const real& s, const T& u, const T& dy, const T& phi, mpfr_prec_t bits = 256) {
  const mpfr_prec_t exact_bits = std::max<mpfr_prec_t>(bits, 4 * contact::detail::precision_of<T>());
  const rational sq(s), uq(exactly(u, exact_bits)), dyq(exactly(dy, exact_bits)), phiq(exactly(phi, exact_bits));
  const rational times_s = sq * sq + uq * sq + phiq * (detail_ref::floor_squared(dyq - sq) - detail_ref::floor_squared(dyq));
  rational quotient;
  mpq_div(quotient.get(), times_s.get(), sq.get());
  real result(bits);
  mpfr_set_q(result.get(), quotient.get(), MPFR_RNDN);
  return result;
}

// R'(s) on the side of the kink where s lies (R is C1 at the kink, so either
// side's formula serves at s = dy): 1 + phi, 1 + phi dy^2/s^2, 1, 1 + phi (1 - dy^2/s^2).
template <class T>
real slope_at(const real& s, const T& dy_in, const T& phi_in, mpfr_prec_t bits = 256) {
  const mpfr_prec_t exact_bits = std::max<mpfr_prec_t>(bits, 4 * contact::detail::precision_of<T>());
  const real dy = exactly(dy_in, exact_bits), phi = exactly(phi_in, exact_bits);
  real result(exact_bits), ratio(2 * exact_bits);  // 1 - dy^2/s^2 cancels: keep every bit of s
  const bool below_kink = mpfr_cmp(s.get(), dy.get()) <= 0;
  if (mpfr_sgn(dy.get()) > 0 && below_kink) {
    mpfr_add_ui(result.get(), phi.get(), 1, MPFR_RNDN);
  } else if (mpfr_sgn(dy.get()) > 0) {
    mpfr_div(ratio.get(), dy.get(), s.get(), MPFR_RNDN);
    mpfr_sqr(ratio.get(), ratio.get(), MPFR_RNDN);
    mpfr_mul(result.get(), ratio.get(), phi.get(), MPFR_RNDN);
    mpfr_add_ui(result.get(), result.get(), 1, MPFR_RNDN);
  } else if (!below_kink || mpfr_zero_p(s.get())) {
    mpfr_set_ui(result.get(), 1, MPFR_RNDN);
  } else {
    mpfr_div(ratio.get(), dy.get(), s.get(), MPFR_RNDN);
    mpfr_sqr(ratio.get(), ratio.get(), MPFR_RNDN);
    mpfr_ui_sub(ratio.get(), 1, ratio.get(), MPFR_RNDN);
    mpfr_mul(result.get(), ratio.get(), phi.get(), MPFR_RNDN);
    mpfr_add_ui(result.get(), result.get(), 1, MPFR_RNDN);
  }
  return result;
}

// One unit in the last place of T at x: 2^(max(e, emin) - p + 1), where
// 2^e <= |x| < 2^(e+1), emin is T's least normal exponent and p its precision;
// beyond T's largest finite value, the ulp of that value.
template <class T>
real ulp_of(const real& x) {
  const long p = contact::detail::precision_of<T>();
  // the software types' least exponents (-2^31) lie beyond MPFR's own range
  const long emin = std::max<long>(std::numeric_limits<T>::min_exponent - 1, mpfr_get_emin() + 2 * p + 64);
  const long emax = std::numeric_limits<T>::max_exponent - 1;
  long e = mpfr_zero_p(x.get()) ? emin : long(mpfr_get_exp(x.get())) - 1;
  e = std::clamp(e, emin, emax);
  real result(64);
  mpfr_set_ui_2exp(result.get(), 1, e - p + 1, MPFR_RNDN);
  return result;
}

// |computed - exact| in ulps of T at the exact root. NaN for a NaN answer;
// infinity for an infinite answer, unless the exact root is itself beyond
// T's range in that direction (then the rounded root is that infinity too).
template <class T>
double ulp_error(const T& computed, const certified& exact) {
  using std::isinf;
  using std::isnan;
  if (isnan(computed)) return std::numeric_limits<double>::quiet_NaN();
  if (isinf(computed)) {
    real largest = exactly((std::numeric_limits<T>::max)(), mpfr_get_prec(exact.s.get()));
    real half_ulp = ulp_of<T>(largest);
    mpfr_div_2ui(half_ulp.get(), half_ulp.get(), 1, MPFR_RNDN);
    mpfr_add(largest.get(), largest.get(), half_ulp.get(), MPFR_RNDN);  // the rounding threshold to infinity
    if (computed < 0) mpfr_neg(largest.get(), largest.get(), MPFR_RNDN);
    const bool beyond = computed > 0 ? mpfr_cmp(exact.s.get(), largest.get()) >= 0 : mpfr_cmp(exact.s.get(), largest.get()) <= 0;
    return beyond ? 0.0 : std::numeric_limits<double>::infinity();
  }
  real difference = exactly(computed, mpfr_get_prec(exact.s.get()) + 64);
  mpfr_sub(difference.get(), difference.get(), exact.s.get(), MPFR_RNDN);
  mpfr_abs(difference.get(), difference.get(), MPFR_RNDN);
  mpfr_div(difference.get(), difference.get(), ulp_of<T>(exact.s).get(), MPFR_RNDN);
  return mpfr_get_d(difference.get(), MPFR_RNDU);
}

// ulp_error, counting as 0 ulps +infinity for release with dy the largest
// finite T (only_infinity_on_its_side), the answer of an implementation that
// keeps release strictly above dy whatever the root rounds to. contact-check
// grades other implementations by it; the library's own answers are graded
// by ulp_error.
template <class T>
double accepted_ulp_error(const T& computed, const certified& exact, const T& dy) {
  if (only_infinity_on_its_side(exact.which, dy) && computed == std::numeric_limits<T>::infinity()) return 0.0;
  return ulp_error(computed, exact);
}

// x rounded to nearest (ties to even) in the format of T: T's precision, its
// gradual underflow and its overflow to infinity. Rounded to T's precision in
// MPFR's wide range first, then brought into T's range with the ternary value,
// so that nothing is rounded twice.
template <class T>
real rounded_to(const real& x) {
  const int p = contact::detail::precision_of<T>();
  real result(p);
  int inexact = mpfr_set(result.get(), x.get(), MPFR_RNDN);
  const mpfr_exp_t old_emin = mpfr_get_emin(), old_emax = mpfr_get_emax();
  // T's range in MPFR's convention (significand in [1/2, 1)): the least subnormal is 2^(emin - 1)
  mpfr_set_emin(std::numeric_limits<T>::min_exponent - p + 1);
  mpfr_set_emax(std::numeric_limits<T>::max_exponent);
  inexact = mpfr_check_range(result.get(), inexact, MPFR_RNDN);
  mpfr_subnormalize(result.get(), inexact, MPFR_RNDN);
  mpfr_set_emin(old_emin);
  mpfr_set_emax(old_emax);
  return result;
}

// The exact root rounded to nearest (ties to even) in T. Rounding s itself
// would round twice: a root within 2^-(bits-8) of a midpoint of T (with a
// subnormal phi, (A.31)'s root lies 2^-1074 of itself from a midpoint when
// 2 phi dy is one) can be rounded onto the midpoint at `bits` bits and then
// to the even neighbour, whichever side the root is on. So: when both ends of
// the certified bracket round alike, the root does too (rounding is monotonic);
// otherwise the bracket, far narrower than an ulp, holds the one midpoint m
// between the two, and the exact sign of R(m) decides (R is increasing: the
// root lies above m exactly when R(m) < 0); R(m) = 0 is a tie, m itself rounds
// to the even neighbour.
template <class T>
real rounded_root(const certified& exact, const T& u, const T& dy, const T& phi) {
  real low = rounded_to<T>(exact.lower), high = rounded_to<T>(exact.upper);
  if (mpfr_equal_p(low.get(), high.get())) return low;
  const int p = contact::detail::precision_of<T>();
  real midpoint(p + 8);
  if (mpfr_inf_p(high.get())) {  // the overflow threshold max + ulp(max)/2 = 2^emax (1 - 2^-(p+1))
    mpfr_set_ui_2exp(midpoint.get(), 1, std::numeric_limits<T>::max_exponent, MPFR_RNDN);
    real half_ulp(p + 8);
    mpfr_set_ui_2exp(half_ulp.get(), 1, std::numeric_limits<T>::max_exponent - p - 1, MPFR_RNDN);
    mpfr_sub(midpoint.get(), midpoint.get(), half_ulp.get(), MPFR_RNDN);
  } else {
    mpfr_add(midpoint.get(), low.get(), high.get(), MPFR_RNDN);  // exact: neighbours in T
    mpfr_div_2ui(midpoint.get(), midpoint.get(), 1, MPFR_RNDN);
  }
  const mpfr_prec_t bits = std::max<mpfr_prec_t>(64, 2 * p);
  const rational uq(exactly(u, bits)), dyq(exactly(dy, bits)), phiq(exactly(phi, bits));
  const int sign = detail_ref::residual_sign(rational(midpoint), uq, dyq, phiq);
  if (sign < 0) return high;
  if (sign > 0) return low;
  return rounded_to<T>(midpoint);
}

// The root rounded to nearest in double, with gradual underflow.
inline double rounded_to_double(const real& x) {
  const mpfr_exp_t old_emin = mpfr_get_emin(), old_emax = mpfr_get_emax();
  mpfr_set_emin(-1073);  // binary64's range in MPFR's convention (significand in [1/2, 1))
  mpfr_set_emax(1024);
  mpfr_t copy;
  mpfr_init2(copy, 53);
  int inexact = mpfr_set(copy, x.get(), MPFR_RNDN);
  inexact = mpfr_check_range(copy, inexact, MPFR_RNDN);
  mpfr_subnormalize(copy, inexact, MPFR_RNDN);
  const double result = mpfr_get_d(copy, MPFR_RNDN);
  mpfr_clear(copy);
  mpfr_set_emin(old_emin);
  mpfr_set_emax(old_emax);
  return result;
}

}  // namespace contact::reference
