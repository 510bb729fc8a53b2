// Exact comparisons of a candidate's answers with the certified reference, in
// MPFR and GMP: nothing here rounds in a way that could hide an error.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/reference.hpp"

namespace check {

using contact::reference::certified;
using contact::reference::exactly;
using contact::reference::rational;
using contact::reference::real;

inline constexpr mpfr_prec_t bits = 2400;  // holds any double or float and its ulp exactly, with room

using contact::reference::detail_ref::residual_sign;  // exact, at s = 0 too

// Whether the exact root lies within `ulps` ulps of s, the ulp of T taken at
// the far end of the interval (so the test agrees with an error in ulps of the
// root when the root lies in the next binade): R changes sign across it.
template <class T>
bool root_within(const T& s, const T& u, const T& dy, const T& phi, double ulps) {
  const real centre = exactly(s, bits);
  real width = contact::reference::ulp_of<T>(centre), far_end(bits);
  mpfr_mul_d(width.get(), width.get(), ulps, MPFR_RNDU);
  mpfr_abs(far_end.get(), centre.get(), MPFR_RNDN);
  mpfr_add(far_end.get(), far_end.get(), width.get(), MPFR_RNDU);
  real half_width = contact::reference::ulp_of<T>(far_end), lower(bits), upper(bits);
  mpfr_mul_d(half_width.get(), half_width.get(), ulps, MPFR_RNDU);
  mpfr_sub(lower.get(), centre.get(), half_width.get(), MPFR_RNDN);
  mpfr_add(upper.get(), centre.get(), half_width.get(), MPFR_RNDN);
  const rational uq(exactly(u, bits)), dyq(exactly(dy, bits)), phiq(exactly(phi, bits));
  return residual_sign(rational(lower), uq, dyq, phiq) <= 0 && residual_sign(rational(upper), uq, dyq, phiq) >= 0;
}

// (a - b) - (exact_a - exact_b) in units of ulp(exact_a) + ulp(exact_b):
// how much more a candidate moves between two inputs than the exact root does.
template <class T>
double excess_move(const T& a, const T& b, const certified& exact_a, const certified& exact_b, double scale_b = 1) {
  real difference = exactly(a, bits), term = exactly(b, bits), unit(bits);
  mpfr_mul_d(term.get(), term.get(), scale_b, MPFR_RNDN);  // scale_b is a power of two: exact
  mpfr_sub(difference.get(), difference.get(), term.get(), MPFR_RNDN);
  mpfr_sub(difference.get(), difference.get(), exact_a.s.get(), MPFR_RNDN);
  mpfr_set(term.get(), exact_b.s.get(), MPFR_RNDN);
  mpfr_mul_d(term.get(), term.get(), scale_b, MPFR_RNDN);
  mpfr_add(difference.get(), difference.get(), term.get(), MPFR_RNDN);
  const real unit_a = contact::reference::ulp_of<T>(exact_a.s);  // named: mpfr_set is a macro
  mpfr_set(unit.get(), unit_a.get(), MPFR_RNDN);
  real unit_b = contact::reference::ulp_of<T>(exact_b.s);
  mpfr_mul_d(unit_b.get(), unit_b.get(), scale_b, MPFR_RNDN);
  mpfr_add(unit.get(), unit.get(), unit_b.get(), MPFR_RNDN);
  mpfr_div(difference.get(), difference.get(), unit.get(), MPFR_RNDN);
  return mpfr_get_d(difference.get(), MPFR_RNDN);
}

// The certified root as T rounds it (hex) and in decimal.
template <class T>
std::string root_text(const certified& exact) {
  char hex[64];
  const double rounded = contact::reference::rounded_to_double(exact.s);
  std::snprintf(hex, sizeof hex, "%a", double(T(rounded)));
  return std::string(hex) + " (" + exact.s.to_string(17) + ")";
}

}  // namespace check
