#include "methods.hpp"

#include <stdexcept>
#include <vector>

#include "contact/types.hpp"

namespace report {

std::string name_of(method m) {
  switch (m) {
    case method::batch: return "batch";
    case method::rounded_batch: return "rounded_batch";
    case method::boost_quadratic: return "boost_quadratic";
    case method::eigen_companion: return "eigen_companion";
    case method::boost_newton: return "boost_newton";
    case method::boost_halley: return "boost_halley";
    case method::boost_toms748: return "boost_toms748";
    case method::practitioner_newton: return "practitioner_newton";
    case method::textbook:
    case method::stable:
    case method::newton:
    case method::rounded: return std::string(contact::name_of(*library_algorithm(m)));
  }
  return "";  // a number that names no method
}

std::optional<method> method_named(std::string_view name) {
  for (method m : all_methods)
    if (name_of(m) == name) return m;
  return std::nullopt;
}

std::string unsupported(method m, std::string_view type) {
  bool runs = false;
  if (!contact::with_type(type, [&](auto zero) { runs = runs_in<decltype(zero)>(m); }))
    throw std::invalid_argument("unknown type '" + std::string(type) + "'");
  if (runs) return "";
  std::vector<std::string_view> where;
  contact::for_each_type([&](auto zero) {
    if (runs_in<decltype(zero)>(m)) where.push_back(contact::type_name<decltype(zero)>);
  });
  std::string list;
  for (std::size_t i = 0; i < where.size(); ++i)
    list += std::string(i == 0 ? "" : (i + 1 == where.size() ? " and " : ", ")) + std::string(where[i]);
  return name_of(m) + " runs in " + list + " only";
}

}  // namespace report
