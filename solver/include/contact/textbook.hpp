// The appendix's summary (A.29)-(A.32) evaluated as printed, with its
// misprints corrected and nothing else: no rescaling, no rationalised root, no
// clamp. It is the formula a reader would type in, kept so that the tests and
// the report can show where it loses accuracy (cancellation in (A.31) near
// s = 0 and in (A.32) for u >> sqrt(phi) dy; overflow of u^2 beyond 1e154).
#pragma once

#include <cmath>

#include "cases.hpp"
#include "detail/input.hpp"

namespace contact {

template <class T>
solution<T> solve_textbook(const T& u, const T& dy, const T& phi) {
  using std::sqrt;
  if (auto invalid = detail::reject_invalid(u, dy, phi)) return *invalid;
  if (dy <= 0) {
    // (A.29); printed as u < -dy, but at u = -dy (A.30) gives s = dy, against its (A.7)
    if (u <= -dy) return {-u, contact_case::free};
    // (A.30); printed with 2 psi dy, which is 2 phi dy in (A.9)
    return {(2 * phi * dy - u - sqrt(u * u - 4 * phi * dy * (u + dy))) / (2 * (1 + phi)), contact_case::impact};
  }
  // (A.31); printed as (u - 2 phi dy) / (1 + phi), the negative of what (A.18) gives
  if (u >= dy * (phi - 1)) return {(2 * phi * dy - u) / (1 + phi), contact_case::contact};
  // (A.32), the root of (A.23) with its constant term's sign corrected: s^2 + u s - phi dy^2 = 0
  return {-u / 2 + sqrt(u * u + 4 * phi * dy * dy) / 2, contact_case::release};
}

}  // namespace contact
