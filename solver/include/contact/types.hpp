// The scalar types the solver is instantiated for. Boost 1.74's expression
// templates break fma and generic code, so every multiprecision type is et_off.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>
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

template <class T> constexpr std::string_view type_name = "?";
template <> constexpr std::string_view type_name<float> = "float";
template <> constexpr std::string_view type_name<double> = "double";
template <> constexpr std::string_view type_name<long double> = "long_double";
template <> constexpr std::string_view type_name<float128> = "float128";
template <> constexpr std::string_view type_name<bin_float_50> = "cpp_bin_float_50";
template <> constexpr std::string_view type_name<bin_float_100> = "cpp_bin_float_100";
template <> constexpr std::string_view type_name<mpfr_float> = "mpfr";

// Calls f(T{}) for the type named `name`; false if there is none.
template <class F>
bool with_type(std::string_view name, F&& f) {
  if (name == "float") return f(float{}), true;
  if (name == "double") return f(double{}), true;
  if (name == "long_double") return f((long double){}), true;
  if (name == "float128") return f(float128{}), true;
  if (name == "cpp_bin_float_50") return f(bin_float_50{}), true;
  if (name == "cpp_bin_float_100") return f(bin_float_100{}), true;
  if (name == "mpfr") return f(mpfr_float{}), true;
  return false;
}

// x as text that reads back as the same T: C99 hex for float and double,
// else enough decimal digits for T's significand (for mpfr, its run-time
// precision).
template <class T>
std::string round_trip_text(const T& x) {
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
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

inline constexpr std::string_view type_names[] = {"float", "double", "long_double", "float128",
                                                  "cpp_bin_float_50", "cpp_bin_float_100", "mpfr"};

}  // namespace contact
