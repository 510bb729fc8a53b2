// The scalar types the solver is instantiated for. Boost 1.74's expression
// templates break fma and generic code, so every multiprecision type is et_off.
#pragma once

#if defined(__STRICT_ANSI__)
#error "contact/types.hpp needs GNU extensions (-std=gnu++20): Boost 1.74's float128 uses __float128 literals"
#endif

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include "detail/float_tools.hpp"

namespace contact {

using float128 = boost::multiprecision::float128;
using bin_float_50 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>,
                                                   boost::multiprecision::et_off>;
using bin_float_100 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<100>,
                                                    boost::multiprecision::et_off>;
// MPFR at run-time precision: set it with mpfr_float::default_precision(digits10).
using mpfr_float = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                                 boost::multiprecision::et_off>;

// The registry: every scalar type the project instantiates, once, with its
// name. The CLI's --type, the report's scenes, the tests' typed suites and the
// fuzzers all take their list from here; a name not in it is an error.
template <class... Ts>
struct type_list {};
using scalar_types = type_list<float, double, long double, float128, bin_float_50, bin_float_100, mpfr_float>;

template <class T>
constexpr std::string_view type_name = "?";
template <> inline constexpr std::string_view type_name<float> = "float";
template <> inline constexpr std::string_view type_name<double> = "double";
template <> inline constexpr std::string_view type_name<long double> = "long_double";
template <> inline constexpr std::string_view type_name<float128> = "float128";
template <> inline constexpr std::string_view type_name<bin_float_50> = "cpp_bin_float_50";
template <> inline constexpr std::string_view type_name<bin_float_100> = "cpp_bin_float_100";
template <> inline constexpr std::string_view type_name<mpfr_float> = "mpfr";

template <class List>
struct names_in;
template <class... Ts>
struct names_in<type_list<Ts...>> {
  static constexpr std::array<std::string_view, sizeof...(Ts)> value{type_name<Ts>...};
};
inline constexpr auto type_names = names_in<scalar_types>::value;

// Calls f(T{}) for each registered T, in the registry's order.
template <class F>
void for_each_type(F&& f) {
  [&]<class... Ts>(type_list<Ts...>) { (f(Ts{}), ...); }(scalar_types{});
}

// Calls f(T{}) for the type named `name`; false if no registered type has that name.
template <class F>
[[nodiscard]] bool with_type(std::string_view name, F&& f) {
  bool found = false;
  for_each_type([&](auto zero) {
    if (!found && type_name<decltype(zero)> == name) {
      found = true;
      f(zero);
    }
  });
  return found;
}

// x as text that reads back as the same T: C99 hex for float and double,
// else enough decimal digits for T's significand (for mpfr, its run-time
// precision).
template <class T>
std::string round_trip_text(const T& x) {
  if constexpr (detail::hardware_binary<T>) {
    char text[64];
    std::snprintf(text, sizeof text, "%a", static_cast<double>(x));
    return text;
  } else {
    std::ostringstream out;
    const int round_trip_digits = static_cast<int>(std::ceil(detail::precision_of<T>() * 0.30102999566398120)) + 1;
    out << std::setprecision(round_trip_digits) << x;
    return out.str();
  }
}

}  // namespace contact
