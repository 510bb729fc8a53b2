// The peers of the report's tables: general quadratic solvers applied to the
// quadratic of each case of (A.2). The case is decided by the printed criteria
// (as the textbook path does); the quadratics are the corrected (A.9) and
// (A.23), and the contact case's equation (A.18) is linear.
//
//   impact  (A.9):  (1 + phi) s^2 + (u - 2 phi dy) s + phi dy^2 = 0, smaller root
//   contact (A.18): (1 + phi) s + (u - 2 phi dy) = 0
//   release (A.23): s^2 + u s - phi dy^2 = 0, larger root
#pragma once

#include <boost/math/tools/roots.hpp>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/cases.hpp"
#include "contact/detail/input.hpp"

namespace report::peers {

template <class T, class Quadratic, class Linear>
contact::solution<T> by_case(const T& u, const T& dy, const T& phi, Quadratic quadratic, Linear linear) {
  using contact::contact_case;
  if (auto invalid = contact::detail::reject_invalid(u, dy, phi)) return *invalid;
  if (dy <= 0) {
    if (u <= -dy) return {T(-u), contact_case::free};
    const auto [low, high] = quadratic(T(1 + phi), T(u - 2 * phi * dy), T(phi * dy * dy));
    return {low, contact_case::impact};
  }
  if (u >= dy * (phi - 1)) return {linear(T(1 + phi), T(u - 2 * phi * dy)), contact_case::contact};
  const auto [low, high] = quadratic(T(1), u, T(-(phi * dy * dy)));
  return {high, contact_case::release};
}

// Boost.Math tools::quadratic_roots (Boost >= 1.72): roots in ascending order.
template <class T>
contact::solution<T> solve_boost(const T& u, const T& dy, const T& phi) {
  return by_case(
      u, dy, phi,
      [](const T& a, const T& b, const T& c) { return boost::math::tools::quadratic_roots(a, b, c); },
      [](const T& b, const T& c) { return boost::math::tools::quadratic_roots(T(0), b, c).first; });
}

// Eigen's PolynomialSolver: the eigenvalues of the companion matrix (balanced,
// then Eigen's real Schur form); the real parts of the two roots, ordered.
template <class T>
contact::solution<T> solve_eigen(const T& u, const T& dy, const T& phi) {
  return by_case(
      u, dy, phi,
      [](const T& a, const T& b, const T& c) {
        Eigen::PolynomialSolver<T, 2> solver;
        solver.compute(Eigen::Matrix<T, 3, 1>(c, b, a));
        const T r0 = solver.roots()[0].real(), r1 = solver.roots()[1].real();
        if (std::isnan(r0) || std::isnan(r1)) return std::pair<T, T>(std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN());
        return std::pair<T, T>(std::min(r0, r1), std::max(r0, r1));
      },
      [](const T& b, const T& c) {
        Eigen::PolynomialSolver<T, 1> solver;
        solver.compute(Eigen::Matrix<T, 2, 1>(c, b));
        return T(solver.roots()[0].real());
      });
}

}  // namespace report::peers
