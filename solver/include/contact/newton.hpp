// Safeguarded Newton iteration on the residual of (A.2): the iterative method
// that the closed form replaces, kept as the baseline for accuracy and speed.
#pragma once

#include <cmath>
#include <limits>

#include "cases.hpp"
#include "detail/float_tools.hpp"
#include "detail/input.hpp"

namespace contact {
namespace newton_form {

// The residual of (A.2) and its derivative on each side of the kink s = dy,
// with the quotient (floor(dy - s)^2 - floor(dy)^2) / s divided out, so that
// it is continuous at s = 0 and needs no division by s where s can vanish.
template <class T>
struct residual_and_slope {
  T residual, slope;
};

template <class T>
residual_and_slope<T> residual_of(const T& s, const T& u, const T& dy, const T& phi) {
  // Products are ordered so that nothing under- or overflows unless the term
  // itself does: dy / s is a ratio of magnitude below one in both regions.
  if (dy > 0) {
    if (s <= dy) return {s + u + phi * (s - 2 * dy), 1 + phi};  // (A.18)
    const T ratio = dy / s;                                      // 0 < ratio < 1
    return {s + u - phi * ratio * dy, 1 + phi * ratio * ratio};  // (A.23) divided by s
  }
  if (s >= dy) return {s + u, T(1)};  // (A.5)
  const T ratio = dy / s;              // s < dy <= 0, so 0 <= ratio < 1
  return {s + u + phi * ((dy - s) * (ratio - 1)), 1 + phi * (1 - ratio * ratio)};  // (A.8): (dy-s)^2/s
}

}  // namespace newton_form

// The midpoint of a bracket, geometric when its ends share a sign and lie
// binades apart, so that a safeguard step gains a bit of the exponent as well.
template <class T>
T bracket_midpoint(const T& lower, const T& upper) {
  using std::sqrt;
  if (lower > 0 && upper > 4 * lower) return sqrt(lower) * sqrt(upper);
  if (upper < 0 && lower < 4 * upper) return -(sqrt(-lower) * sqrt(-upper));
  return lower / 2 + upper / 2;
}

// Newton from the kink s = dy, where the sign of the residual says which side
// the root is on. R is C1 there and linear or concave on each side, so from the
// kink the iterates approach the root monotonically; a step that leaves the
// bracket of signs seen so far is replaced by its midpoint. Stops when a step no
// longer changes s by more than half an ulp, or after max_iterations.
template <class T>
solution<T> solve_newton(const T& u, const T& dy, const T& phi, int max_iterations = 4096) {
  using std::fabs;
  if (auto invalid = detail::reject_invalid(u, dy, phi)) return *invalid;
  const T at_kink = newton_form::residual_of(dy, u, dy, phi).residual;
  const bool root_below_kink = dy > 0 ? at_kink >= 0 : at_kink > 0;
  const contact_case which = dy > 0 ? (root_below_kink ? contact_case::contact : contact_case::release)
                                    : (root_below_kink ? contact_case::impact : contact_case::free);
  if (at_kink == 0) return {dy, which};

  const T largest = (std::numeric_limits<T>::max)();
  const T half_epsilon = std::numeric_limits<T>::epsilon() / 2;
  T lower = root_below_kink ? -largest : dy;
  T upper = root_below_kink ? dy : largest;
  T s = dy;
  for (int i = 0; i < max_iterations; ++i) {
    const auto [r, slope] = newton_form::residual_of(s, u, dy, phi);
    if (r == 0) break;
    (r < 0 ? lower : upper) = s;
    T next = s - r / slope;
    if (!(next >= lower && next <= upper)) next = bracket_midpoint(lower, upper);
    // (a collapsed bracket converges too: its only point is s itself)
    const bool converged = fabs(next - s) <= half_epsilon * fabs(s);
    s = next;
    if (converged) break;
  }
  // A root above T's range: the residual has not changed sign at the largest
  // finite value. None lies below it: below the kink the root is at least -u
  // (R(-u) <= 0), and the bracket's lower end, -largest, is never above -u.
  if (upper == largest && newton_form::residual_of(largest, u, dy, phi).residual < 0)
    s = std::numeric_limits<T>::infinity();
  // Every iterate stays in the bracket, which holds the kink on the root's
  // side: only the strict sides of (A.30) and (A.32) can need a step off dy.
  if (which == contact_case::impact && !(s < dy)) s = detail::next_down(dy);
  if (which == contact_case::release && !(s > dy)) s = detail::next_up(dy);
  return {s, which};
}

}  // namespace contact
