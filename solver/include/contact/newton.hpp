// Safeguarded Newton iteration on the residual of (A.2): the iterative method
// that the closed form replaces, kept as the baseline for accuracy and speed.
#pragma once

#include <cmath>
#include <limits>

#include "cases.hpp"
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
  if (dy > 0) {
    if (s <= dy) return {s + u + phi * (s - 2 * dy), 1 + phi};   // (A.18)
    const T squared_over_s = dy * (dy / s);
    return {s + u - phi * squared_over_s, 1 + phi * (squared_over_s / s)};  // (A.23) divided by s
  }
  if (s >= dy) return {s + u, T(1)};  // (A.5)
  const T ratio = dy / s;               // s < dy <= 0, so 0 <= ratio < 1
  return {s + u + phi * (dy - s) * (ratio - 1), 1 + phi * (1 - ratio * ratio)};  // (A.8): (dy-s)^2/s
}

}  // namespace newton_form

// Newton steps inside a bracket that always contains the root; a step that
// leaves the bracket is replaced by bisection. Stops when the bracket has no
// float strictly inside, or after a fixed number of iterations.
template <class T>
solution<T> solve_newton(const T& u, const T& dy, const T& phi, int max_iterations = 200) {
  using std::fabs;
  if (auto invalid = detail::reject_invalid(u, dy, phi)) return *invalid;
  const T at_kink = newton_form::residual_of(dy, u, dy, phi).residual;
  const bool root_below_kink = dy > 0 ? at_kink >= 0 : at_kink > 0;
  const contact_case which = dy > 0 ? (root_below_kink ? contact_case::contact : contact_case::release)
                                    : (root_below_kink ? contact_case::impact : contact_case::free);
  // The root lies on one side of dy; grow the other end of the bracket until the
  // residual changes sign. The residual grows at least like s, so this ends.
  T lower = dy, upper = dy;
  T reach = fabs(u) + fabs(dy) + 1;
  const T largest = (std::numeric_limits<T>::max)();
  for (;;) {
    if (root_below_kink) lower = dy - reach; else upper = dy + reach;
    const T end = root_below_kink ? lower : upper;
    const T r = newton_form::residual_of(end, u, dy, phi).residual;
    if ((root_below_kink ? r <= 0 : r >= 0) || reach == largest) break;
    reach = reach > largest / 2 ? largest : reach * 2;
  }
  if (at_kink == 0) return {dy, which};
  T s = lower / 2 + upper / 2;
  for (int i = 0; i < max_iterations; ++i) {
    const auto [r, slope] = newton_form::residual_of(s, u, dy, phi);
    if (r == 0) break;
    (r < 0 ? lower : upper) = s;
    T next = s - r / slope;
    if (!(next > lower && next < upper)) next = lower / 2 + upper / 2;
    if (next == s || next <= lower || next >= upper) break;
    s = next;
  }
  if (which == contact_case::impact && !(s < dy)) s = lower;
  if (which == contact_case::release && !(s > dy)) s = upper;
  return {s, which};
}

}  // namespace contact
