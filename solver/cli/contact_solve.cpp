// contact-solve: solves (A.2) for each line "u dy phi" of a file or stdin.
//
// Output: one line per input line, at the same position: "s case" (s as a C99
// hex float for float and double, a round-trip decimal for wider types; case
// 1-4 is (A.29)-(A.32)); a blank or comment line is echoed as it is; a bad
// line gives "error REASON" and a message with its line number on stderr.
// Exit status 1 if any line was bad, 2 for bad options or an unreadable file
// (and for --algo rounded with a type that has no correctly rounded mode).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "contact/solve.hpp"
#include "contact/types.hpp"
#include "read_number.hpp"

namespace {

// A hex float "[+-]0xH.HHHp[+-]D", read exactly into T (digit by digit, then scaled).
template <class T>
std::optional<T> parse_hex(const std::string& token) {
  using std::ldexp;
  std::size_t i = 0;
  bool negative = false;
  if (token[i] == '+' || token[i] == '-') negative = token[i++] == '-';
  if (token.compare(i, 2, "0x") != 0 && token.compare(i, 2, "0X") != 0) return std::nullopt;
  i += 2;
  T significand = 0;
  long exponent = 0;
  bool any_digit = false, point = false;
  for (; i < token.size() && (std::isxdigit(static_cast<unsigned char>(token[i])) || token[i] == '.'); ++i) {
    if (token[i] == '.') {
      if (point) return std::nullopt;
      point = true;
      continue;
    }
    const int digit = std::isdigit(static_cast<unsigned char>(token[i])) ? token[i] - '0'
                                                                         : std::tolower(token[i]) - 'a' + 10;
    significand = significand * 16 + digit;  // exact while the digits fit T's precision
    if (point) exponent -= 4;
    any_digit = true;
  }
  if (!any_digit) return std::nullopt;
  if (i < token.size()) {
    if (token[i] != 'p' && token[i] != 'P') return std::nullopt;
    const std::string power = token.substr(i + 1);
    if (power.empty()) return std::nullopt;
    std::size_t used = 0;
    long value = 0;
    try { value = std::stol(power, &used); } catch (...) { return std::nullopt; }
    if (used != power.size()) return std::nullopt;
    exponent += value;
  }
  exponent = std::clamp(exponent, -100000000L, 100000000L);
  const T value = ldexp(significand, static_cast<int>(exponent));
  return negative ? T(-value) : value;
}

template <class T>
std::optional<T> parse_number(const std::string& token, std::string& reason) {
  if constexpr (std::is_floating_point_v<T> || std::is_same_v<T, contact::float128>) {
    // decimal and hex alike, rounded once (read_number.hpp)
    const auto [value, status] = contact::cli::read_rounded<T>(token);
    if (status == contact::cli::reading::not_a_number) { reason = "'" + token + "' is not a number"; return std::nullopt; }
    if (status == contact::cli::reading::overflows) { reason = "'" + token + "' overflows " + std::string(contact::type_name<T>); return std::nullopt; }
    return value;
  } else {
    if (auto hex = parse_hex<T>(token)) return hex;
    const bool looks_numeric = token.find_first_not_of("0123456789+-.eE") == std::string::npos;  // (tokens are never empty)
    if (!looks_numeric) { reason = "'" + token + "' is not a number"; return std::nullopt; }
    try { return T(token); } catch (const std::exception&) { reason = "'" + token + "' is not a number"; return std::nullopt; }
  }
}

std::string why_invalid(bool u_finite, bool dy_finite, bool phi_finite) {
  if (!u_finite) return "u is not finite";
  if (!dy_finite) return "dy is not finite";
  if (!phi_finite) return "phi is not finite";
  // the library rejects nothing else: phi < 0 is the one finite invalid input
  return "phi is negative";
}

template <class T>
int run(std::istream& in, contact::algorithm method) {
  using std::isfinite;
  std::string line;
  int line_number = 0, bad_lines = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string content = line.substr(0, line.find('#'));
    std::istringstream fields(content);
    std::vector<std::string> tokens;
    for (std::string token; fields >> token;) tokens.push_back(token);
    if (tokens.empty()) {
      std::cout << line << '\n';
      continue;
    }
    std::string reason;
    std::optional<T> values[3];
    if (tokens.size() != 3) {
      reason = "expected 3 numbers (u dy phi), found " + std::to_string(tokens.size());
    } else {
      for (int k = 0; k < 3 && reason.empty(); ++k) values[k] = parse_number<T>(tokens[k], reason);
    }
    if (reason.empty()) {
      const T &u = *values[0], &dy = *values[1], &phi = *values[2];
      const auto result = contact::solve(u, dy, phi, method);
      if (result.which == contact::contact_case::invalid)
        reason = why_invalid(isfinite(u), isfinite(dy), isfinite(phi));
      else
        std::cout << contact::round_trip_text(result.s) << ' ' << static_cast<int>(result.which) << '\n';
    }
    if (!reason.empty()) {
      ++bad_lines;
      std::cout << "error " << reason << '\n';
      std::cerr << "contact-solve: line " << line_number << ": " << reason << '\n';
    }
  }
  return bad_lines == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Solves the one-sided contact step (A.2) for lines 'u dy phi' (decimal or C99 hex floats; '#' starts a comment)."};
  std::string algorithm_name = "stable", type_name = "double", file;
  unsigned mpfr_digits = 50;
  std::vector<std::string> algorithm_names;
  std::string known_types;
  for (auto name : contact::type_names) known_types += (known_types.empty() ? "" : ", ") + std::string(name);
  for (auto a : contact::algorithms) algorithm_names.emplace_back(contact::name_of(a));
  app.add_option("--algo", algorithm_name, "algorithm")->check(CLI::IsMember(algorithm_names))->capture_default_str();
  app.add_option("--type", type_name, "scalar type: " + known_types)->capture_default_str();
  app.add_option("--mpfr-digits", mpfr_digits, "decimal digits of the mpfr type")->check(CLI::Range(10u, 10000u))->capture_default_str();
  app.add_option("file", file, "input file (default: standard input)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  contact::mpfr_float::default_precision(mpfr_digits);
  contact::algorithm method = contact::algorithm::stable;
  for (auto a : contact::algorithms) if (contact::name_of(a) == algorithm_name) method = a;

  std::ifstream file_stream;
  if (!file.empty()) {
    file_stream.open(file);
    if (!file_stream) {
      std::cerr << "contact-solve: cannot read " << file << '\n';
      return 2;
    }
  }
  std::istream& in = file.empty() ? std::cin : file_stream;
  int status = 0;
  const bool known = contact::with_type(type_name, [&](auto zero) {
    using T = decltype(zero);
    if constexpr (!contact::rounded_available<T>) {
      if (method == contact::algorithm::rounded) {  // refused, never replaced by another algorithm
        std::cerr << "contact-solve: --algo rounded is not available for --type " << type_name
                  << " (correct rounding is implemented for float, double, long_double and float128)\n";
        status = 2;
        return;
      }
    }
    status = run<T>(in, method);
  });
  if (!known) {
    std::cerr << "contact-solve: unknown type '" << type_name << "' (known: " << known_types << ")\n";
    return 2;
  }
  return status;
}
