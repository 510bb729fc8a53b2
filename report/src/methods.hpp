// The algorithms of the report's tables: the library's three
// (contact::algorithm), its batch API and two peers.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "contact/cases.hpp"

namespace report {

enum class method { textbook, stable, newton, batch, boost_quadratic, eigen_companion };
inline constexpr method all_methods[] = {method::textbook, method::stable,          method::newton,
                                         method::batch,    method::boost_quadratic, method::eigen_companion};

// The library algorithm that `m` is, or nothing for the report's own (batch and the peers).
constexpr std::optional<contact::algorithm> library_algorithm(method m) {
  switch (m) {
    case method::textbook: return contact::algorithm::textbook;
    case method::stable: return contact::algorithm::stable;
    case method::newton: return contact::algorithm::newton;
    default: return std::nullopt;
  }
}

std::string name_of(method m);
std::optional<method> method_named(std::string_view name);

// Whether the report runs `m` in T. The Eigen peer (peers.hpp) calls
// std::isnan on T, which exists for the built-in floating-point types only.
template <class T>
constexpr bool runs_in(method m) {
  return m != method::eigen_companion || std::is_floating_point_v<T>;
}

// Why `m` cannot run in the registered type named `type` (contact/types.hpp),
// or empty if it can; a name the registry does not hold throws std::invalid_argument.
std::string unsupported(method m, std::string_view type);

}  // namespace report
