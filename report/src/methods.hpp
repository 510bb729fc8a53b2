// The algorithms of the report's tables: the library's four
// (contact::algorithm), its batch API (stable and rounded), two quadratic peers (peers.hpp) and
// four iterative peers (iterative_peers.hpp). The switches on method name
// every one and have no default (-Werror=switch: a new one must be placed).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "contact/cases.hpp"
#include "contact/rounded.hpp"

namespace report {

enum class method {
  textbook,
  stable,
  newton,
  rounded,
  batch,
  rounded_batch,
  boost_quadratic,
  eigen_companion,
  boost_newton,
  boost_halley,
  boost_toms748,
  practitioner_newton
};
inline constexpr method all_methods[] = {method::textbook,        method::stable,          method::newton,
                                         method::rounded,         method::batch,           method::rounded_batch,
                                         method::boost_quadratic, method::eigen_companion,
                                         method::boost_newton,    method::boost_halley,    method::boost_toms748,
                                         method::practitioner_newton};

// The library algorithm that `m` is, or nothing for the report's own (batch and the peers).
constexpr std::optional<contact::algorithm> library_algorithm(method m) {
  switch (m) {
    case method::textbook: return contact::algorithm::textbook;
    case method::stable: return contact::algorithm::stable;
    case method::newton: return contact::algorithm::newton;
    case method::rounded: return contact::algorithm::rounded;
    case method::batch:
    case method::rounded_batch:
    case method::boost_quadratic:
    case method::eigen_companion:
    case method::boost_newton:
    case method::boost_halley:
    case method::boost_toms748:
    case method::practitioner_newton: break;
  }
  return std::nullopt;
}

// The methods that iterate on the residual: the report counts their iterations.
constexpr bool iterative(method m) {
  switch (m) {
    case method::newton:
    case method::boost_newton:
    case method::boost_halley:
    case method::boost_toms748:
    case method::practitioner_newton: return true;
    case method::textbook:
    case method::stable:
    case method::rounded:
    case method::batch:
    case method::rounded_batch:
    case method::boost_quadratic:
    case method::eigen_companion: break;
  }
  return false;
}

std::string name_of(method m);
std::optional<method> method_named(std::string_view name);

// Whether the report runs `m` in T. The Eigen peer (peers.hpp) calls
// std::isnan on T, which exists for the built-in floating-point types only;
// the correctly rounded mode exists for the IEEE types only (contact::rounded_available).
template <class T>
constexpr bool runs_in(method m) {
  if (m == method::eigen_companion) return std::is_floating_point_v<T>;
  if (m == method::rounded || m == method::rounded_batch) return contact::rounded_available<T>;
  return true;
}

// Whether `m` promises complementarity only weakly: the correctly rounded root
// may be dy itself where the exact root lies within half an ulp of it.
constexpr bool weakly_complementary(method m) { return m == method::rounded || m == method::rounded_batch; }

// Why `m` cannot run in the registered type named `type` (contact/types.hpp),
// or empty if it can; a name the registry does not hold throws std::invalid_argument.
std::string unsupported(method m, std::string_view type);

}  // namespace report
