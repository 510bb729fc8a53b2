// Shared pieces of the fuzz targets: input decoding, the claimed bounds of the
// stable algorithm, the failure report, and the statistics that the replay
// tool prints. Plain C++ (no libFuzzer header): the same code is compiled with
// clang + libFuzzer for campaigns and with g++ into the corpus replay of ctest.
//
// The vocabulary is the project's, not the fuzzers': type names come from
// contact/types.hpp, case names and equations from contact/cases.hpp, the
// input triple from contact/harness/families.hpp, and the bounds file is read
// by contact/harness/claimed_bounds.hpp.
#pragma once

#include <quadmath.h>
#include <unistd.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "contact/cases.hpp"
#include "contact/harness/claimed_bounds.hpp"
#include "contact/harness/families.hpp"
#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "contact/types.hpp"

#ifndef CONTACT_CLAIMED_BOUNDS
#error "define CONTACT_CLAIMED_BOUNDS as the path of proofs/claimed_bounds.txt"
#endif

namespace contact::fuzz {

using harness::input;

// ---- inputs ----------------------------------------------------------------

// Reads `count` bytes at `offset` of the input, zero-padded past its end, so
// every input of any length decodes and every bit pattern is reachable.
inline void take_bytes(const std::uint8_t* data, std::size_t size, std::size_t offset, void* out, std::size_t count) {
  std::memset(out, 0, count);
  if (offset < size) std::memcpy(out, data + offset, std::min(count, size - offset));
}

inline std::uint8_t take_byte(const std::uint8_t* data, std::size_t size, std::size_t offset) {
  std::uint8_t byte = 0;
  take_bytes(data, size, offset, &byte, 1);
  return byte;
}

// A double from 8 raw little-endian bytes: NaN, infinities, zeros and
// subnormals are all reachable, and a dictionary entry is the value itself.
inline double take_double(const std::uint8_t* data, std::size_t size, std::size_t offset) {
  double x;
  take_bytes(data, size, offset, &x, sizeof x);
  return x;
}

// An x87 long double from 10 raw bytes. The explicit integer bit is set from
// the exponent field (1 for normal numbers, infinities and NaN, 0 for zero and
// subnormals), so that every valid value is reachable and no unnormal or
// pseudo-denormal encoding is produced.
inline long double take_long_double(const std::uint8_t* data, std::size_t size, std::size_t offset) {
  static_assert(std::numeric_limits<long double>::digits == 64, "x87 extended precision expected");
  unsigned char bytes[sizeof(long double)] = {};
  take_bytes(data, size, offset, bytes, 10);
  std::uint64_t significand;
  std::uint16_t sign_exponent;
  std::memcpy(&significand, bytes, 8);
  std::memcpy(&sign_exponent, bytes + 8, 2);
  const std::uint64_t integer_bit = std::uint64_t(1) << 63;
  significand = (sign_exponent & 0x7fff) != 0 ? (significand | integer_bit) : (significand & ~integer_bit);
  std::memcpy(bytes, &significand, 8);
  long double x;
  std::memcpy(&x, bytes, sizeof x);
  return x;
}

// A binary128 from 16 raw bytes: every encoding is a valid value.
inline contact::float128 take_float128(const std::uint8_t* data, std::size_t size, std::size_t offset) {
  __float128 x;
  take_bytes(data, size, offset, &x, sizeof x);
  return contact::float128(x);
}

// Valid as the API defines it (finite u, dy, phi and phi >= 0), written out
// here rather than taken from the solver, whose rejection it checks.
template <class T>
bool is_valid(const input<T>& x) {
  using std::isfinite;
  return isfinite(x.u) && isfinite(x.dy) && isfinite(x.phi) && !(x.phi < 0);
}

// ---- printing --------------------------------------------------------------

// x printed with the printf format for its type: one for float and double,
// one for long double, one for float128 (quadmath).
struct printf_formats {
  const char *for_double, *for_long_double, *for_float128;
};

template <class T>
std::string printed(const T& x, const printf_formats& formats) {
  char text[128];
  if constexpr (contact::detail::hardware_binary<T>) {
    std::snprintf(text, sizeof text, formats.for_double, double(x));
  } else if constexpr (std::is_same_v<T, long double>) {
    std::snprintf(text, sizeof text, formats.for_long_double, x);
  } else if constexpr (std::is_same_v<T, contact::float128>) {
    quadmath_snprintf(text, sizeof text, formats.for_float128, x.backend().value());
  } else {
    static_assert(std::is_same_v<T, double>, "no printf format for this type");
  }
  return text;
}

template <class T>
std::string hex(const T& x) {
  return printed(x, {"%a", "%La", "%Qa"});
}

template <class T>
std::string decimal(const T& x) {
  return printed(x, {"%.17g", "%.21Lg", "%.36Qg"});
}

// "1 free (A.29)" ... "4 release (A.32)", "0 invalid": the number the CLI
// prints, the name and the equation of contact/cases.hpp.
inline std::string case_label(contact_case c) {
  std::string label = std::to_string(static_cast<int>(c)) + " " + std::string(name_of(c));
  if (c != contact_case::invalid) label += " " + std::string(equation_of(c));
  return label;
}

// "double stable", "long_double textbook", ...: what the statistics are kept per.
template <class T>
std::string run_label(algorithm a) {
  return std::string(type_name<T>) + " " + std::string(name_of(a));
}

// ---- findings ----------------------------------------------------------------

// The file being replayed, if any (set by the replay tool), for the report.
inline const char*& current_input_name() {
  static const char* name = nullptr;
  return name;
}

// The replay tool throws this instead of aborting, to report every failing file.
struct finding : std::exception {
  const char* what() const noexcept override { return "contact-fuzz finding"; }
};

inline bool& throw_on_finding() {
  static bool enabled = false;
  return enabled;
}

// Prints a finding and aborts: libFuzzer saves the input as a crash artifact,
// the replay test fails.
[[noreturn]] inline void fail(const char* target, const std::string& what, const std::string& details) {
  std::fprintf(stderr, "\n==contact-fuzz== FINDING in target '%s': %s\n", target, what.c_str());
  if (current_input_name()) std::fprintf(stderr, "  input file: %s\n", current_input_name());
  std::fprintf(stderr, "%s", details.c_str());
  std::fprintf(stderr, "==contact-fuzz== end of report\n");
  std::fflush(stderr);
  if (throw_on_finding()) throw finding();
  std::abort();
}

template <class T>
std::string describe_input(const input<T>& x) {
  std::ostringstream out;
  out << "  type: " << type_name<T> << "\n"
      << "  u   = " << hex(x.u) << "   (" << decimal(x.u) << ")\n"
      << "  dy  = " << hex(x.dy) << "   (" << decimal(x.dy) << ")\n"
      << "  phi = " << hex(x.phi) << "   (" << decimal(x.phi) << ")\n";
  return out.str();
}

// ---- the claimed bounds ---------------------------------------------------------

// Where proofs/claimed_bounds.txt is: $CONTACT_CLAIMED_BOUNDS, else the path
// compiled in; a relative one is taken from the directory of the executable
// (OSS-Fuzz copies the file next to the fuzzers).
inline std::string bounds_path() {
  if (const char* override_path = std::getenv("CONTACT_CLAIMED_BOUNDS")) return override_path;
  std::string path = CONTACT_CLAIMED_BOUNDS;
  if (!path.empty() && path[0] != '/') {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
      exe[n] = '\0';
      const std::string executable(exe);
      path = executable.substr(0, executable.rfind('/')) + "/" + path;
    }
  }
  return path;
}

// The bounds, read once, by the harness's parser; a file it rejects (missing,
// malformed, a branch without a bound) is fatal at start-up.
inline const harness::claimed_bounds& claimed() {
  static const harness::claimed_bounds bounds = [] {
    const std::string path = bounds_path();
    try {
      return harness::claimed_bounds::read(path);
    } catch (const std::runtime_error& error) {
      std::fprintf(stderr, "==contact-fuzz== FATAL: claimed bounds: %s\n", error.what());  // "FILE:LINE: reason"
      std::exit(2);
    }
  }();
  return bounds;
}

// Where the bounds came from, for the replay tool's header line.
inline const std::string& bound_source() {
  static const std::string source = bounds_path();
  return source;
}

// ---- statistics (printed by the replay tool's --stats) ----------------------

struct worst_case {
  double ulps = -1;
  std::string input;  // hex
  std::string which;
};

struct statistics {
  long inputs = 0, invalid_inputs = 0;

  // per run label ("double stable", "long_double textbook", ...)
  struct entry {
    std::string label;
    long runs = 0, non_finite = 0, over_1e6 = 0;
    worst_case worst;

    bool is_worse(double ulps) const {
      if (worst.ulps < 0) return true;  // the first run
      if (std::isnan(ulps)) return !std::isnan(worst.ulps);
      return !std::isnan(worst.ulps) && ulps > worst.ulps;
    }

    template <class T>
    void add(double ulps, const input<T>& x, contact_case which) {
      ++runs;
      if (!std::isfinite(ulps)) ++non_finite;
      if (ulps >= 1e6) ++over_1e6;
      if (!is_worse(ulps)) return;
      worst.ulps = ulps;
      worst.input = "u=" + hex(x.u) + " dy=" + hex(x.dy) + " phi=" + hex(x.phi);
      worst.which = case_label(which);
    }
  };
  std::vector<entry> entries;  // in the order the labels first occur

  entry& of(const std::string& label) {
    const auto found = std::find_if(entries.begin(), entries.end(), [&](const entry& e) { return e.label == label; });
    if (found != entries.end()) return *found;
    entry& added = entries.emplace_back();
    added.label = label;
    return added;
  }

  template <class T>
  void record(const std::string& label, double ulps, const input<T>& x, contact_case which) {
    of(label).add(ulps, x, which);
  }

  void print(std::FILE* out) const {
    std::fprintf(out, "inputs: %ld (invalid: %ld)\n", inputs, invalid_inputs);
    for (const entry& e : entries)
      std::fprintf(out, "  %-22s runs %-8ld worst %-12.4g ulps  non-finite errors %-6ld >=1e6 ulps %-6ld at %s [%s]\n",
                   e.label.c_str(), e.runs, e.worst.ulps, e.non_finite, e.over_1e6, e.worst.input.c_str(),
                   e.worst.which.c_str());
  }
};

inline statistics& stats() {
  static statistics* const s = new statistics;  // never destroyed: printed by an atexit handler
  return *s;
}

// With $CONTACT_FUZZ_STATS set, the statistics are printed to stderr at exit
// (the campaign runner replays its final corpus with -runs=0 this way).
inline void print_stats_at_exit_if_asked() {
  if (std::getenv("CONTACT_FUZZ_STATS") == nullptr) return;
  stats();
  std::atexit([] {
    std::fprintf(stderr, "==contact-fuzz== statistics\n");
    stats().print(stderr);
    std::fprintf(stderr, "==contact-fuzz== end of statistics\n");
  });
}

}  // namespace contact::fuzz
