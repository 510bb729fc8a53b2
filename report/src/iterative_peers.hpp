// The iterative peers of the report's tables: what a user without the closed
// form runs on the residual R(s) of (A.2) instead, each as its users call it
// (not to half an ulp with a large cap), each with its iteration count.
//
//   boost_newton         Boost.Math tools::newton_raphson_iterate, digits = 0.6 of T's
//   boost_halley         Boost.Math tools::halley_iterate, digits = 0.4 of T's
//   boost_toms748        Boost.Math tools::toms748_solve, eps_tolerance<T>(T's digits),
//                        the midpoint of the bracket it returns
//   practitioner_newton  plain Newton as physical-modelling code runs it: relative step
//                        tolerance 1e-12, at most 20 steps, no bracket
//
// Boost's fractions are those of its root-finding examples: Newton doubles the
// correct digits per step, Halley triples them, so stopping at just over a half
// (a third) of the digits leaves the last step to supply the rest.
//
// All start from the kink s = dy, where the sign of R says on which side the
// root lies (docs/equations.md, section 2), as the library's newton does; that
// side is the case each reports. The Boost peers search the bracket the kink
// gives (bracket_from_kink). No peer moves its answer onto its case's side of
// dy: what that costs shows as complementarity violations.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <tuple>
#include <utility>

#include "contact/cases.hpp"
#include "contact/detail/float_tools.hpp"
#include "contact/detail/input.hpp"
#include "contact/newton.hpp"

namespace report::peers {

// What an iterative peer did: its solution and how many times it evaluated R
// (the Boost peers: inside Boost; the practitioner's Newton: its steps).
template <class T>
struct iterated {
  contact::solution<T> answer;
  int iterations;
};

// The Boost peers' max_iter.
inline constexpr std::uintmax_t boost_max_iterations = 50;

// The case that the residual at the kink decides: the library's rule
// (contact/newton.hpp), so that a boundary input, R(dy) = 0, takes the case the
// library gives it.
template <class T>
contact::contact_case case_at_kink(const T& dy, const T& residual_at_kink) {
  using contact::contact_case;
  if (dy > 0) return residual_at_kink >= 0 ? contact_case::contact : contact_case::release;
  return residual_at_kink > 0 ? contact_case::impact : contact_case::free;
}

constexpr bool root_below_kink(contact::contact_case c) {
  return c == contact::contact_case::contact || c == contact::contact_case::impact;
}

// R and its first two derivatives in s.
template <class T>
struct residual_derivatives {
  T value, slope, curvature;
};

// R, R' and R'' at s, for a search on the root's side of the kink. R and R'
// are the library's (newton_form::residual_of); at s = dy itself the
// derivatives are the one-sided ones of the root's side, since R' jumps there
// when dy = 0 and R'' whenever phi dy != 0. On each side (docs/equations.md, section 3):
//   free    (A.5)   R = s + u                          R'' = 0
//   contact (A.18)  R = (1 + phi) s + u - 2 phi dy     R'' = 0
//   impact  (A.8)   R = s + u + phi (dy - s)^2 / s     R'' = 2 phi dy^2 / s^3 (< 0: s < 0)
//   release (A.23)  R = s + u - phi dy^2 / s           R'' = -2 phi dy^2 / s^3 (< 0: s > 0)
// (on the impact side (dy - s)^2 / s = dy^2 / s - 2 dy + s, so its R'' is that of phi dy^2 / s).
template <class T>
residual_derivatives<T> derivatives_on_side(const T& s, const T& u, const T& dy, const T& phi, bool below_kink) {
  const auto [value, slope] = contact::newton_form::residual_of(s, u, dy, phi);
  const bool below = s < dy || (s == dy && below_kink);
  // at dy = 0 residual_of gives s = 0 the free side's slope; the impact side is the line (1 + phi) s + u
  if (dy == 0 && s == 0 && below) return {value, 1 + phi, T(0)};
  const bool curved = dy > 0 ? !below : below;  // release and impact
  if (!curved) return {value, slope, T(0)};
  const T ratio = dy / s;  // in [0, 1] on both curved sides: products stay within the range of phi / s
  const T magnitude = 2 * (phi * ratio * ratio / s);
  return {value, slope, dy > 0 ? T(-magnitude) : magnitude};
}

// The search interval on the root's side of the kink, with R(lower) <= 0 <= R(upper).
template <class T>
struct bracket {
  T lower, upper;
};

// Below the kink (impact, contact): [-u, dy]. R(-u) <= 0 there: for dy <= 0
// the phi term of R is <= 0 at every s < dy; for dy > 0 it is
// phi (s - 2 dy) = -phi (u + 2 dy) at s = -u, and R(dy) > 0 means u > -dy.
// (-u < dy follows from R(dy) > 0 in both cases.)
// Above it (free, release): [dy, |dy| + 2 b], b a bound of the root: twice b
// lies beyond the root whatever the rounding of b, and |dy| keeps the end
// above the kink. On the free side the root is -u, and b = max(0, -u). On the
// release side R(s) = s + u - phi dy^2 / s, and the root is
// (-u + sqrt(u^2 + 4 phi dy^2)) / 2 <= max(0, -u) + sqrt(phi) dy; for u > 0
// also R(s) > u - phi dy^2 / s >= 0 from s = phi dy^2 / u on, the bound that
// matters when u >> sqrt(phi) dy (the root is then far below sqrt(phi) dy, and
// a bracket that wide would cost the searches dozens of steps).
// The end is clamped to T's largest value; a root beyond it has no bracket.
template <class T>
bracket<T> bracket_from_kink(const T& u, const T& dy, const T& phi, bool below_kink) {
  using std::fabs;
  using std::sqrt;
  if (below_kink) return {T(-u), dy};
  const T zero(0);
  const T compression = (std::max)(zero, dy);
  T root_bound = (std::max)(zero, T(-u)) + sqrt(phi) * compression;
  // phi dy^2 / u ordered so that it cannot underflow where it matters; an
  // overflow to infinity (or NaN, infinity times 0) leaves the other bound
  if (u > 0) root_bound = (std::min)(root_bound, T(phi * compression * (compression / u)));
  const T beyond = fabs(dy) + 2 * root_bound;
  return {dy, (std::min)(beyond, (std::numeric_limits<T>::max)())};
}

// R and its derivatives on the root's side, as the Boost peers hand it to
// Boost, counting its evaluations: the iterations the report gives. They are
// the count Boost writes back into max_iter, except where halley_iterate
// searches beyond its bracket: there Boost's count can wrap below zero, so that
// it writes back more than it evaluated, and the search can run past max_iter.
template <class T>
class counted_residual {
 public:
  counted_residual(const T& u, const T& dy, const T& phi, bool below_kink)
      : u_(u), dy_(dy), phi_(phi), below_kink_(below_kink) {}
  residual_derivatives<T> operator()(const T& s) {
    ++evaluations_;
    return derivatives_on_side(s, u_, dy_, phi_, below_kink_);
  }
  int evaluations() const { return evaluations_; }

 private:
  const T& u_;
  const T& dy_;
  const T& phi_;
  bool below_kink_;
  int evaluations_ = 0;
};

// Runs `search(lower, upper, residual, max_iter)`, a Boost root finder on the
// bracket that the kink gives, with max_iter at the cap. A root at the kink
// needs no search (and would leave an empty bracket). Boost reports a failure
// (no sign change, an empty bracket) by throwing: the answer is then NaN.
template <class T, class Search>
iterated<T> search_from_kink(const T& u, const T& dy, const T& phi, Search search) {
  if (auto invalid = contact::detail::reject_invalid(u, dy, phi)) return {*invalid, 0};
  const T at_kink = contact::newton_form::residual_of(dy, u, dy, phi).residual;
  const contact::contact_case which = case_at_kink(dy, at_kink);
  if (at_kink == 0) return {{dy, which}, 0};
  const bool below = root_below_kink(which);
  const auto [lower, upper] = bracket_from_kink(u, dy, phi, below);
  counted_residual<T> residual(u, dy, phi, below);
  std::uintmax_t max_iter = boost_max_iterations;
  try {
    const T s = search(lower, upper, residual, max_iter);
    return {{s, which}, residual.evaluations()};
  } catch (const std::exception&) {
    return {{std::numeric_limits<T>::quiet_NaN(), which}, residual.evaluations()};
  }
}

template <class T>
int digits_of() {
  return contact::detail::precision_of<T>();
}

// newton_raphson_iterate from s = dy.
template <class T>
iterated<T> solve_boost_newton(const T& u, const T& dy, const T& phi) {
  return search_from_kink(u, dy, phi, [&](const T& lower, const T& upper, counted_residual<T>& residual,
                                          std::uintmax_t& max_iter) {
    const auto value_and_slope = [&](const T& s) {
      const auto d = residual(s);
      return std::pair<T, T>(d.value, d.slope);
    };
    const int digits = static_cast<int>(digits_of<T>() * 0.6);
    return boost::math::tools::newton_raphson_iterate(value_and_slope, dy, lower, upper, digits, max_iter);
  });
}

// halley_iterate from s = dy.
template <class T>
iterated<T> solve_boost_halley(const T& u, const T& dy, const T& phi) {
  return search_from_kink(u, dy, phi, [&](const T& lower, const T& upper, counted_residual<T>& residual,
                                          std::uintmax_t& max_iter) {
    const auto value_and_derivatives = [&](const T& s) {
      const auto d = residual(s);
      return std::tuple<T, T, T>(d.value, d.slope, d.curvature);
    };
    const int digits = static_cast<int>(digits_of<T>() * 0.4);
    return boost::math::tools::halley_iterate(value_and_derivatives, dy, lower, upper, digits, max_iter);
  });
}

// toms748_solve on the bracket (it evaluates R at both ends itself).
template <class T>
iterated<T> solve_boost_toms748(const T& u, const T& dy, const T& phi) {
  return search_from_kink(u, dy, phi, [&](const T& lower, const T& upper, counted_residual<T>& residual,
                                          std::uintmax_t& max_iter) {
    const auto value = [&](const T& s) { return residual(s).value; };
    const boost::math::tools::eps_tolerance<T> tolerance(static_cast<unsigned>(digits_of<T>()));
    const auto [low, high] = boost::math::tools::toms748_solve(value, lower, upper, tolerance, max_iter);
    return T(low + (high - low) / 2);
  });
}

// Plain Newton as physical-modelling code writes it: from the kink, with the
// slope of the side the iterate is on (newton_form::residual_of, which puts
// s = dy on the side of (A.18) or (A.5)); it stops when a step is at most
// 1e-12 of |s| or after 20 steps, and counts its steps (each evaluates R once,
// the first at the kink). Nothing keeps it on the root's side: an iterate that
// crosses the kink continues with the other side's formula. The tolerance is
// the same literal in every type: in float, below its epsilon, only a step of
// zero meets it.
template <class T>
iterated<T> solve_practitioner_newton(const T& u, const T& dy, const T& phi) {
  using std::fabs;
  constexpr int max_steps = 20;
  const T tolerance(1e-12);
  if (auto invalid = contact::detail::reject_invalid(u, dy, phi)) return {*invalid, 0};
  T s = dy;
  contact::contact_case which = contact::contact_case::invalid;
  int steps = 0;
  while (steps < max_steps) {
    const auto [r, slope] = contact::newton_form::residual_of(s, u, dy, phi);
    if (steps == 0) which = case_at_kink(dy, r);
    const T step = r / slope;
    s -= step;
    ++steps;
    if (fabs(step) <= tolerance * fabs(s)) break;
  }
  return {{s, which}, steps};
}

}  // namespace report::peers
