// contact::solve: the closed-form solution of the one-sided contact step (A.2)
//
//     s + u + phi (floor(dy - s)^2 - floor(dy)^2) / s = 0,   floor(x) = max(x, 0),
//
// for any scalar type T with std-style sqrt, fma, frexp and ldexp (float, double,
// long double, and Boost.Multiprecision et_off types). Every finite u, dy and
// phi >= 0 is a valid input and (A.2) then has exactly one root. NaN or infinite
// input, or phi < 0, returns NaN with contact_case::invalid. phi = 0 gives s = -u.
#pragma once

#include <stdexcept>

#include "cases.hpp"
#include "newton.hpp"
#include "rounded.hpp"
#include "stable.hpp"
#include "textbook.hpp"

namespace contact {
namespace detail {

// Correct rounding exists for the types of rounded_available only; for the
// others (cpp_bin_float, mpfr) algorithm::rounded is refused, never replaced.
template <class T>
  requires rounded_available<T>
solution<T> solve_rounded_or_refuse(const T& u, const T& dy, const T& phi) {
  return solve_rounded(u, dy, phi);
}

template <class T>
solution<T> solve_rounded_or_refuse(const T&, const T&, const T&) {
  throw std::invalid_argument("contact::solve: algorithm 'rounded' is implemented for float, double, long double "
                              "and float128 only");
}

}  // namespace detail

template <class T>
solution<T> solve(const T& u, const T& dy, const T& phi, algorithm method = algorithm::stable) {
  switch (method) {
    case algorithm::textbook: return solve_textbook(u, dy, phi);
    case algorithm::newton: return solve_newton(u, dy, phi);
    case algorithm::rounded: return detail::solve_rounded_or_refuse(u, dy, phi);
    case algorithm::stable: break;
  }
  return solve_stable(u, dy, phi);
}

// textbook, stable and newton keep their positions (code indexes them); rounded is appended.
inline constexpr algorithm algorithms[] = {algorithm::textbook, algorithm::stable, algorithm::newton,
                                           algorithm::rounded};

}  // namespace contact
