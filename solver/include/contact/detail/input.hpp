// Input validation shared by every algorithm: bad input is part of the API.
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "../cases.hpp"

namespace contact::detail {

// NaN or infinite u, dy or phi, or phi < 0 (phi = k_b / (2a) cannot be negative):
// the answer is NaN with the `invalid` case, never a finite number.
template <class T>
std::optional<solution<T>> reject_invalid(const T& u, const T& dy, const T& phi) {
  using std::isfinite;
  if (isfinite(u) && isfinite(dy) && isfinite(phi) && !(phi < 0)) return std::nullopt;
  return solution<T>{std::numeric_limits<T>::quiet_NaN(), contact_case::invalid};
}

}  // namespace contact::detail
