// Shared pieces of the fuzz targets: input decoding, the proven bound of the
// stable algorithm, the failure report, and the statistics that the replay
// tool prints. Plain C++ (no libFuzzer header): the same code is compiled with
// clang + libFuzzer for campaigns and with g++ into the corpus replay of ctest.
#pragma once

#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <unistd.h>

#include "contact/reference.hpp"
#include "contact/solve.hpp"

#ifndef CONTACT_FUZZ_NO_FLOAT128
#include <quadmath.h>

#include "contact/types.hpp"
#endif

#ifndef CONTACT_CLAIMED_BOUNDS
#error "define CONTACT_CLAIMED_BOUNDS as the path of proofs/claimed_bounds.txt"
#endif

namespace contact::fuzz {

// ---- inputs ----------------------------------------------------------------

// Reads `count` bytes at `offset` of the input, zero-padded past its end, so
// every input of any length decodes and every bit pattern is reachable.
inline void take_bytes(const std::uint8_t* data, std::size_t size, std::size_t offset, void* out, std::size_t count) {
  std::memset(out, 0, count);
  if (offset < size) std::memcpy(out, data + offset, std::min(count, size - offset));
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

#ifndef CONTACT_FUZZ_NO_FLOAT128
// A binary128 from 16 raw bytes: every encoding is a valid value.
inline contact::float128 take_float128(const std::uint8_t* data, std::size_t size, std::size_t offset) {
  __float128 x;
  take_bytes(data, size, offset, &x, sizeof x);
  return contact::float128(x);
}
#endif

template <class T>
struct triple {
  T u, dy, phi;
};

template <class T>
bool is_valid(const triple<T>& x) {
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
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
    std::snprintf(text, sizeof text, formats.for_double, double(x));
  } else if constexpr (std::is_same_v<T, long double>) {
    std::snprintf(text, sizeof text, formats.for_long_double, x);
  }
#ifndef CONTACT_FUZZ_NO_FLOAT128
  else if constexpr (std::is_same_v<T, contact::float128>) {
    quadmath_snprintf(text, sizeof text, formats.for_float128, x.backend().value());
  }
#endif
  else {
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

template <class T>
const char* type_label() {
  if constexpr (std::is_same_v<T, double>) return "double";
  else if constexpr (std::is_same_v<T, long double>) return "long double";
  else return "float128";
}

inline const char* case_label(contact_case c) {
  switch (c) {
    case contact_case::free: return "1 free (A.29)";
    case contact_case::impact: return "2 impact (A.30)";
    case contact_case::contact: return "3 contact (A.31)";
    case contact_case::release: return "4 release (A.32)";
    default: return "0 invalid";
  }
}

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
std::string describe_input(const triple<T>& x) {
  std::ostringstream out;
  out << "  type: " << type_label<T>() << "\n"
      << "  u   = " << hex(x.u) << "   (" << decimal(x.u) << ")\n"
      << "  dy  = " << hex(x.dy) << "   (" << decimal(x.dy) << ")\n"
      << "  phi = " << hex(x.phi) << "   (" << decimal(x.phi) << ")\n";
  return out.str();
}

// ---- the proven bound ---------------------------------------------------------

// The largest of the per-branch bounds in proofs/claimed_bounds.txt: the last
// number on each non-comment line ('#' starts a comment). A missing file, or one
// without a bound, is a fatal error at start-up. A relative path is taken from the directory of the executable (OSS-Fuzz
// copies the file next to the fuzzers).
inline std::string bounds_path() {
  if (const char* override_path = std::getenv("CONTACT_CLAIMED_BOUNDS")) return override_path;
  std::string path = CONTACT_CLAIMED_BOUNDS;
  if (!path.empty() && path[0] != '/') {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
      exe[n] = '\0';
      std::string dir(exe);
      dir = dir.substr(0, dir.rfind('/'));
      path = dir + "/" + path;
    }
  }
  return path;
}

// Where the bound came from, for the replay tool's header line.
inline std::string& bound_source() {
  static std::string source;
  return source;
}

inline double load_stable_bound() {
  const std::string path = bounds_path();
  bound_source() = path;
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "==contact-fuzz== FATAL: cannot read the claimed bounds file %s\n", path.c_str());
    std::exit(2);
  }
  double largest = -1;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream fields(line);
    std::string token, last;
    while (fields >> token) last = token;
    if (last.empty()) continue;
    char* end = nullptr;
    const double value = std::strtod(last.c_str(), &end);
    if (end == last.c_str() || *end != '\0' || !(value >= 0) || !std::isfinite(value)) {
      std::fprintf(stderr, "==contact-fuzz== FATAL: %s: '%s' is not a bound\n", path.c_str(), line.c_str());
      std::exit(2);
    }
    largest = std::max(largest, value);
  }
  if (largest < 0) {
    std::fprintf(stderr, "==contact-fuzz== FATAL: %s holds no bound\n", path.c_str());
    std::exit(2);
  }
  return largest;
}

inline double stable_bound() {
  static const double bound = load_stable_bound();
  return bound;
}

// ---- statistics (printed by the replay tool's --stats) ----------------------

struct worst_case {
  double ulps = -1;
  std::string input;  // hex
  std::string which;
};

struct statistics {
  long inputs = 0, invalid_inputs = 0;
  // per label ("double stable", "long double textbook", ...)
  struct entry {
    std::string label;
    long runs = 0, non_finite = 0, over_1e6 = 0;
    worst_case worst;
  };
  entry entries[16];
  int count = 0;

  entry& of(const std::string& label) {
    for (int i = 0; i < count; ++i)
      if (entries[i].label == label) return entries[i];
    entries[count].label = label;
    return entries[count++];
  }

  template <class T>
  void record(const std::string& label, double ulps, const triple<T>& x, contact_case which) {
    entry& e = of(label);
    ++e.runs;
    if (!std::isfinite(ulps)) ++e.non_finite;
    if (ulps >= 1e6) ++e.over_1e6;
    const bool worse = std::isnan(ulps) ? !std::isnan(e.worst.ulps) : (!std::isnan(e.worst.ulps) && ulps > e.worst.ulps);
    if (worse || e.worst.ulps < 0) {
      e.worst.ulps = ulps;
      e.worst.input = "u=" + hex(x.u) + " dy=" + hex(x.dy) + " phi=" + hex(x.phi);
      e.worst.which = case_label(which);
    }
  }

  void print(std::FILE* out) const {
    std::fprintf(out, "inputs: %ld (invalid: %ld)\n", inputs, invalid_inputs);
    for (int i = 0; i < count; ++i) {
      const entry& e = entries[i];
      std::fprintf(out, "  %-22s runs %-8ld worst %-12.4g ulps  non-finite errors %-6ld >=1e6 ulps %-6ld at %s [%s]\n",
                   e.label.c_str(), e.runs, e.worst.ulps, e.non_finite, e.over_1e6, e.worst.input.c_str(),
                   e.worst.which.c_str());
    }
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
