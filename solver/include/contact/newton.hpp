// Safeguarded Newton iteration on the residual of (A.2): the iterative method
// that the closed form replaces, kept as the baseline for accuracy and speed.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "cases.hpp"
#include "detail/float_tools.hpp"
#include "detail/input.hpp"
#include "stable.hpp"

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

// What an iteration did: the solution and how many residuals it evaluated
// after the one at the kink (the cost a caller pays).
template <class T>
struct newton_result {
  solution<T> answer;
  int iterations;
};

// Newton from the kink s = dy, where the sign of the residual says which side
// the root is on; a step that leaves the bracket of signs seen so far is
// replaced by its midpoint. R is linear on the sides of (A.29) and (A.31) and
// concave on those of (A.30) and (A.32). On the side of (A.30) the first step
// from the kink overshoots the root; after that, and on the other sides from the start, the iterates
// approach it monotonically. It stops, keeping the iterate of smaller |R|, when
//   - a Newton step rounds back to s itself, or stays on its side of the root
//     without shrinking |R| (near the root the rounded residual is noise, and
//     iterates that alternate by an ulp would otherwise run on),
//   - the bracket has collapsed to neighbouring values of T, or
//   - after max_iterations residuals.
// So it cannot cycle; what stopping early costs in accuracy is what the
// report and the tests measure.
template <class T>
newton_result<T> newton_iterate(const T& u, const T& dy, const T& phi, int max_iterations = 50) {
  using std::fabs;
  if (auto invalid = detail::reject_invalid(u, dy, phi)) return {*invalid, 0};
  auto [r, slope] = newton_form::residual_of(dy, u, dy, phi);
  // The case, and so the side of the kink the root lies on, from the exact
  // criteria: the rounded R(dy) can have the other sign within its rounding
  // error (u + dy rounds to dy beside a large dy). Where it does, the first
  // residual closes the bracket onto the kink and the iteration stops there.
  const contact_case which = detail::exact_case(u, dy, phi);
  const bool root_below_kink = which == contact_case::contact || which == contact_case::impact;
  // R is C1 at the kink except at dy = 0, where (A.8)'s side has slope 1 + phi
  // (it is the line (1 + phi) s + u there) and (A.5)'s side slope 1
  if (dy == 0 && which == contact_case::impact) slope = 1 + phi;
  const T largest = (std::numeric_limits<T>::max)();
  T lower = root_below_kink ? -largest : dy;
  T upper = root_below_kink ? dy : largest;
  T s = dy;
  int iterations = 0;
  while (r != 0 && iterations < max_iterations) {
    (r < 0 ? lower : upper) = s;
    if (!(detail::next_up(lower) < upper)) break;  // no value of T left strictly inside
    T next = s - r / slope;
    if (next == s) break;  // the step is below half an ulp of s: nothing left to gain
    const bool newton_step = next > lower && next < upper;
    if (!newton_step) next = bracket_midpoint(lower, upper);
    const auto [r_next, slope_next] = newton_form::residual_of(next, u, dy, phi);
    ++iterations;
    // a step that stays on its side of the root must shrink |R|, or the
    // residual is down to its rounding noise (s is then the better of the two)
    const bool same_side = (r_next < 0) == (r < 0);
    if (newton_step && same_side && !(fabs(r_next) < fabs(r))) break;
    s = next;
    r = r_next;
    slope = slope_next;
  }
  // A root above T's range: the residual has not changed sign at the largest
  // finite value. None lies below it: below the kink the root is at least -u
  // (R(-u) <= 0), and the bracket's lower end, -largest, is never above -u.
  if (!root_below_kink && upper == largest && newton_form::residual_of(largest, u, dy, phi).residual < 0)
    s = std::numeric_limits<T>::infinity();
  // Every iterate stays in the bracket, which holds the kink on the root's
  // side: only the strict sides of (A.30) and (A.32) can need a step off dy
  // (none above the largest finite dy, whose root is then finite: see above).
  if (which == contact_case::impact && !(s < dy)) s = detail::next_down(dy);
  if (which == contact_case::release && !(s > dy)) s = (std::min)(detail::next_up(dy), largest);  // dy = largest: dy itself
  return {{s, which}, iterations};
}

template <class T>
solution<T> solve_newton(const T& u, const T& dy, const T& phi, int max_iterations = 50) {
  return newton_iterate(u, dy, phi, max_iterations).answer;
}

}  // namespace contact
