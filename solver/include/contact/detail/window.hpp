// The plain window: the exponent range inside which plain T arithmetic cannot
// overflow or underflow in any stable formula. stable.hpp takes its plain path
// inside it and scaled<T> outside; batch.hpp's vector window lies inside it; the
// fuzzers fold inputs into it; docs/equations.md states the bound.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "float_tools.hpp"
#include "scaled.hpp"

namespace contact::detail {

// Half-width E of the window |x| in [2^-E, 2^E] (or x = 0): the formulas'
// intermediates are of degree three at most in u, dy and phi, and the least
// significant bit of a difference lies at most `digits` binades lower, so
// 4 E + digits + 8 binades must fit below T's largest exponent.
template <class T>
constexpr long window_half_width(long digits) {
  return (long(std::numeric_limits<T>::max_exponent) - digits) / 4 - 2;
}

// For the hardware types a compile-time constant: 240 for double, 24 for float.
template <class T>
  requires std::is_floating_point_v<T>
inline constexpr long plain_window = window_half_width<T>(std::numeric_limits<T>::digits);

template <class T>
struct safe_window {
  static long half_width() {
    if constexpr (std::is_floating_point_v<T>) return plain_window<T>;
    else return window_half_width<T>(precision_of<T>());
  }
  static bool holds(const T& x) {
    using std::fabs;
    const T magnitude = fabs(x);
    if (magnitude == 0) return true;
    if constexpr (std::numeric_limits<T>::is_bounded && std::numeric_limits<T>::max_exponent < 20000) {
      static const T lowest = scaled<T>::shifted(T(1), -half_width());
      static const T highest = scaled<T>::shifted(T(1), half_width());
      return lowest <= magnitude && magnitude <= highest;
    } else {
      const long bound = half_width();
      return scaled<T>::shifted(T(1), -bound) <= magnitude && magnitude <= scaled<T>::shifted(T(1), bound);
    }
  }
  static bool holds(const T& u, const T& dy, const T& phi) { return holds(u) && holds(dy) && holds(phi); }
};
static_assert(plain_window<double> == 240 && plain_window<float> == 24);

}  // namespace contact::detail
