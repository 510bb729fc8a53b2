#include "type_ops.hpp"

#include <array>
#include <stdexcept>
#include <utility>

#include "contact/types.hpp"

namespace report {

namespace {

constexpr std::size_t registered_types = contact::type_names.size();
static_assert(registered_types == CONTACT_REPORT_TYPE_COUNT,
              "report/CMakeLists.txt compiles typed_instance.cpp once per registered type: its count must be "
              "contact::scalar_types' length");

template <std::size_t... index>
std::array<type_ops, registered_types> table(std::index_sequence<index...>) {
  return {ops_at<index>()...};
}

}  // namespace

const type_ops& ops_for(std::string_view type) {
  static const auto all = table(std::make_index_sequence<registered_types>{});
  for (const type_ops& ops : all)
    if (ops.name == type) return ops;
  throw std::invalid_argument("no registered type is named '" + std::string(type) + "'");
}

}  // namespace report
