// The check logic of the four fuzz targets, as plain functions of the input
// bytes. fuzz/targets/*.cpp wrap them for libFuzzer; fuzz/replay.cpp runs the
// committed corpus and regression files through them under ctest.
//
//   differential    (u, dy, phi) doubles from 24 raw bytes; every algorithm
//                   against the certified reference; aborts when the stable
//                   algorithm exceeds its proven bound, returns NaN, returns
//                   infinity where the exact root is not beyond DBL_MAX, picks
//                   a case other than the exact one, or violates
//                   complementarity.
//   cancellation    the textbook algorithm's ulp error, on inputs folded into
//                   the range where no overflow or underflow can occur,
//                   returned as a feedback bucket (case x log2 of the error) so
//                   that the fuzzer climbs towards the worst cancellation.
//                   Never aborts.
//   invariants      a sweep of nine nearby inputs, across the case boundaries
//                   when asked: s is non-increasing and 1-Lipschitz in u,
//                   non-decreasing and 2 phi-Lipschitz in dy, and the cases
//                   follow each other in the only possible order.
//   high_precision  the differential check for long double and float128.
#pragma once

#include <array>
#include <utility>

#include "common.hpp"

namespace contact::fuzz {

// ---- differential -------------------------------------------------------------

template <class T>
std::string reference_text(const reference::certified& exact) {
  std::string text = exact.s.to_string(20);
  if constexpr (std::is_same_v<T, double>) text += "  (rounded to double: " + hex(reference::rounded_to_double(exact.s)) + ")";
  return text;
}

// Whether the exact root lies beyond T's largest finite value, on the side of
// `positive`: infinity is then an acceptable answer (even where the root rounds
// to the largest finite value). The reference's s has a few hundred bits, too
// few to tell a root beyond the largest value by less than that from the value
// itself; complementarity tells it: release has s > dy, impact s < dy.
template <class T>
bool beyond_range(const reference::certified& exact, const T& dy, bool positive) {
  const T largest = (std::numeric_limits<T>::max)();
  if (positive && exact.which == contact_case::release && dy == largest) return true;
  if (!positive && exact.which == contact_case::impact && dy == -largest) return true;
  const reference::real bound = reference::exactly(largest, mpfr_get_prec(exact.s.get()));
  return mpfr_cmpabs(exact.s.get(), bound.get()) > 0 && (mpfr_sgn(exact.s.get()) > 0) == positive;
}

template <class T>
std::string type_prefix() {
  if constexpr (std::is_same_v<T, double>) return "";
  else if constexpr (std::is_same_v<T, long double>) return "long_double:";
  else return "float128:";
}

// What a differential check saw: the stable algorithm's error and the exact
// case (case invalid for an invalid input). The libFuzzer targets feed them
// back as coverage, so that campaigns climb towards the largest stable error.
struct differential_result {
  double stable_ulps = 0;
  contact_case which = contact_case::invalid;
};

// Feedback bucket of a stable error: an eighth of an ulp wide up to 8 ulps,
// one per case; 0 for invalid inputs.
inline constexpr int stable_buckets = 1 + 4 * 65;
inline int stable_bucket(const differential_result& r) {
  if (r.which == contact_case::invalid) return 0;
  const int fine = std::isfinite(r.stable_ulps) ? int(std::min(64.0, 8 * r.stable_ulps)) : 64;
  return 1 + (static_cast<int>(r.which) - 1) * 65 + fine;
}

// The differential check of one input of type T.
template <class T>
differential_result differential_check(const char* target, const triple<T>& x) {
  using std::isinf;
  using std::isnan;
  statistics& st = stats();
  ++st.inputs;
  if (!is_valid(x)) {
    ++st.invalid_inputs;
    for (const algorithm a : algorithms) {
      const solution<T> r = solve(x.u, x.dy, x.phi, a);
      if (!(isnan(r.s) && r.which == contact_case::invalid))
        fail(target, std::string(name_of(a)) + " did not reject an invalid input",
             describe_input(x) + "  got s = " + hex(r.s) + ", case " + case_label(r.which) +
                 "\n  expected NaN and case 0 invalid\n");
    }
    return {};
  }
  const reference::certified exact = reference::solve<T>(x.u, x.dy, x.phi);
  if (!exact.is_certified)
    fail(target, "the reference could not certify its root",
         describe_input(x) + "  reference s = " + exact.s.to_string(40) + ", case " + case_label(exact.which) + "\n");

  solution<T> results[3];
  double errors[3];
  for (int i = 0; i < 3; ++i) {
    results[i] = solve(x.u, x.dy, x.phi, algorithms[i]);
    errors[i] = reference::ulp_error<T>(results[i].s, exact);
    // infinity for a root beyond the largest finite T (even one that rounds to it) is right
    if (isinf(results[i].s) && errors[i] != 0 && beyond_range<T>(exact, x.dy, results[i].s > 0)) errors[i] = 0;
    st.record(type_prefix<T>() + std::string(name_of(algorithms[i])), errors[i], x, results[i].which);
  }
  static_assert(algorithms[1] == algorithm::stable);
  const solution<T>& got = results[1];
  const double error = errors[1];
  const double bound = stable_bound();

  std::string problem;
  if (isnan(got.s)) problem = "stable returned NaN for a valid input";
  else if (isinf(got.s) && error != 0)
    problem = "stable returned infinity where the exact root is a finite " + std::string(type_label<T>());
  else if (got.which != exact.which) problem = "stable chose the wrong case";
  else if (!(error <= bound)) problem = "stable exceeds its proven bound";
  else if (!lies_on_its_side(got.which, got.s, x.dy)) problem = "stable violates complementarity (s on the wrong side of dy for its case)";
  else {
    const solution<T> dispatched = solve(x.u, x.dy, x.phi);
    if (!(dispatched.s == got.s || (isnan(dispatched.s) && isnan(got.s))) || dispatched.which != got.which)
      problem = "contact::solve's default differs from solve_stable";
  }
  if (problem.empty()) return {error, exact.which};

  std::ostringstream details;
  details << describe_input(x) << "  expected s = " << reference_text<T>(exact) << "\n"
          << "  got      s = " << hex(got.s) << "   (" << decimal(got.s) << ")\n"
          << "  error      = " << error << " ulps (proven bound " << bound << " ulps)\n"
          << "  case: expected " << case_label(exact.which) << ", got " << case_label(got.which) << "\n";
  for (int i = 0; i < 3; ++i)
    if (i != 1)
      details << "  (" << name_of(algorithms[i]) << ": s = " << hex(results[i].s) << ", " << errors[i] << " ulps, case "
              << case_label(results[i].which) << ")\n";
  fail(target, problem, details.str());
}

inline differential_result check_differential(const std::uint8_t* data, std::size_t size) {
  const triple<double> x{take_double(data, size, 0), take_double(data, size, 8), take_double(data, size, 16)};
  return differential_check<double>("differential", x);
}

// ---- high precision -----------------------------------------------------------

// 48 bytes: three 16-byte values. Each is read as a binary128 and, from its
// first 10 bytes, as an x87 long double; both triples are checked.
struct high_precision_result {
  differential_result long_double, quad;
};

inline high_precision_result check_high_precision(const std::uint8_t* data, std::size_t size) {
  high_precision_result result;
  const triple<long double> x{take_long_double(data, size, 0), take_long_double(data, size, 16),
                              take_long_double(data, size, 32)};
  result.long_double = differential_check<long double>("high_precision", x);
#ifndef CONTACT_FUZZ_NO_FLOAT128
  const triple<contact::float128> q{take_float128(data, size, 0), take_float128(data, size, 16),
                                    take_float128(data, size, 32)};
  result.quad = differential_check<contact::float128>("high_precision", q);
#endif
  return result;
}

// ---- cancellation hunter ------------------------------------------------------

// The hunter's inputs: 24 raw bytes as three doubles, folded into the stable
// algorithm's plain window (|x| zero or within 2^-240 .. 2^240): a value whose
// exponent lies outside has its exponent field wrapped into the window (sign
// and significand kept), NaN and infinity included, and phi's sign is dropped.
// Every input is then valid and every double of the window is reachable as
// itself, and no intermediate of the textbook formulas can overflow or
// underflow, so that every error the hunter sees is rounding and cancellation.
// (Overflow and underflow of the textbook formulas are measured by the
// differential target, whose inputs are not folded.)
inline double fold_into_window(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  if ((bits << 1) == 0) return x;  // +-0
  constexpr std::uint64_t lowest = 1023 - 240, width = 480;  // biased exponents 783 .. 1262
  const std::uint64_t exponent = (bits >> 52) & 0x7ff;
  if (exponent < lowest || exponent >= lowest + width) {
    const std::uint64_t folded = lowest + exponent % width;
    bits = (bits & ~(std::uint64_t(0x7ff) << 52)) | (folded << 52);
  }
  std::memcpy(&x, &bits, 8);
  return x;
}

// Feedback buckets: 4 per binade of (1 + error) up to 2^64 ulps, then one per
// 16 binades, then NaN and infinity; one set per exact case.
namespace hunter {
inline constexpr int fine = 256;
inline constexpr int coarse = 128;
inline constexpr int per_case = fine + coarse + 2;
inline constexpr int total = 4 * per_case;

inline int bucket_of(double ulps) {
  if (std::isnan(ulps)) return fine + coarse;
  if (std::isinf(ulps)) return fine + coarse + 1;
  const double binades = std::log2(1 + ulps);
  if (binades < 64) return int(4 * binades);
  return fine + std::min(coarse - 1, int((binades - 64) / 16));
}
}  // namespace hunter

struct hunt_result {
  int bucket = -1;  // -1 for an invalid input
  double ulps = 0;
  triple<double> input{};
  contact_case which = contact_case::invalid;
};

inline hunt_result check_cancellation(const std::uint8_t* data, std::size_t size) {
  hunt_result result;
  result.input = {fold_into_window(take_double(data, size, 0)), fold_into_window(take_double(data, size, 8)),
                  std::fabs(fold_into_window(take_double(data, size, 16)))};
  const triple<double>& x = result.input;
  statistics& st = stats();
  ++st.inputs;
  const reference::certified exact = reference::solve<double>(x.u, x.dy, x.phi);
  const solution<double> got = solve_textbook(x.u, x.dy, x.phi);
  result.ulps = reference::ulp_error<double>(got.s, exact);
  result.which = exact.which;
  st.record("textbook", result.ulps, x, exact.which);
  result.bucket = (static_cast<int>(exact.which) - 1) * hunter::per_case + hunter::bucket_of(result.ulps);
  return result;
}

// ---- invariants ---------------------------------------------------------------

// Doubles as ordered integers (-0 and +0 both map to 0), for stepping in ulps.
inline std::int64_t key_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  const std::uint64_t magnitude = bits & ~(std::uint64_t(1) << 63);
  return (bits >> 63) ? -std::int64_t(magnitude) : std::int64_t(magnitude);
}

inline double from_key(std::int64_t k) {
  const std::uint64_t bits = k >= 0 ? std::uint64_t(k) : ((std::uint64_t(1) << 63) | std::uint64_t(-k));
  double x;
  std::memcpy(&x, &bits, 8);
  return x;
}

inline double ulp_at(double x) {
  x = std::fabs(x);
  if (x < DBL_MIN) return std::numeric_limits<double>::denorm_min();
  int e = 0;
  std::frexp(x, &e);
  return std::ldexp(1.0, e - 53);
}

// Layout: byte 0 mode; bytes 1-24 u, dy, phi; byte 25 the step (2^(b % 48)
// ulps between neighbours); byte 26 which boundary (mode 3).
//   mode 0: u swept around u           mode 1: u swept around its case boundary
//   mode 2: dy swept around dy         mode 3: dy swept around 0, -u or u / (phi - 1)
inline void check_invariants(const std::uint8_t* data, std::size_t size) {
  statistics& st = stats();
  ++st.inputs;
  std::uint8_t head[1] = {0}, tail[2] = {0, 0};
  take_bytes(data, size, 0, head, 1);
  take_bytes(data, size, 25, tail, 2);
  const int mode = head[0] % 4;
  triple<double> base{take_double(data, size, 1), take_double(data, size, 9), take_double(data, size, 17)};
  if (!is_valid(base)) {
    ++st.invalid_inputs;
    return;
  }
  const bool sweep_u = mode < 2;
  double centre = sweep_u ? base.u : base.dy;
  if (mode == 1) centre = base.dy <= 0 ? -base.dy : std::fma(base.dy, base.phi, -base.dy);  // u = -dy or u = dy (phi - 1)
  if (mode == 3) {
    switch (tail[1] % 3) {
      case 0: centre = 0; break;
      case 1: centre = -base.u; break;  // u = -dy
      default: centre = base.phi == 1 ? 0 : base.u / (base.phi - 1);  // u = dy (phi - 1)
    }
  }
  if (!std::isfinite(centre)) centre = 0;
  const std::int64_t step = std::int64_t(1) << (tail[0] % 48);
  const std::int64_t limit = key_of(DBL_MAX);

  constexpr int points = 9;
  double x[points], s[points];
  contact_case which[points];
  bool present[points];
  const double bound = stable_bound();
  for (int i = 0; i < points; ++i) {
    const std::int64_t k = key_of(centre) + (i - points / 2) * step;
    present[i] = -limit <= k && k <= limit;
    if (!present[i]) continue;
    x[i] = from_key(k);
    triple<double> input = base;
    (sweep_u ? input.u : input.dy) = x[i];
    const solution<double> r = solve_stable(input.u, input.dy, input.phi);
    s[i] = r.s;
    which[i] = r.which;
    if (std::isnan(r.s) || r.which == contact_case::invalid)
      fail("invariants", "stable returned NaN for a valid input",
           describe_input(input) + "  got s = " + hex(r.s) + ", case " + case_label(r.which) + "\n");
  }

  for (int i = 0; i + 1 < points; ++i) {
    if (!present[i] || !present[i + 1]) continue;
    if (!std::isfinite(s[i]) || !std::isfinite(s[i + 1])) continue;  // the differential target judges infinities
    const long double a = s[i], b = s[i + 1];
    const long double tolerance = 2.0L * bound * ((long double)ulp_at(s[i]) + ulp_at(s[i + 1]));
    const long double distance = (long double)x[i + 1] - x[i];
    const long double lipschitz = sweep_u ? 1.0L : 2.0L * base.phi;
    const long double slack = 1 + std::ldexp(1.0L, -58);
    std::string problem;
    if (sweep_u) {
      if (b > a + tolerance) problem = "s increases with u";
      else if (base.dy <= 0 && which[i] == contact_case::impact && which[i + 1] == contact_case::free)
        problem = "the case goes from impact back to free as u increases";
      else if (base.dy > 0 && which[i] == contact_case::contact && which[i + 1] == contact_case::release)
        problem = "the case goes from contact back to release as u increases";
    } else if (b < a - tolerance) {
      problem = "s decreases as dy increases";
    }
    if (problem.empty() && std::fabs(b - a) > lipschitz * distance * slack + tolerance)
      problem = sweep_u ? "s jumps: |s(u2) - s(u1)| > |u2 - u1|" : "s jumps: |s(dy2) - s(dy1)| > 2 phi |dy2 - dy1|";
    if (problem.empty()) continue;
    triple<double> first = base, second = base;
    (sweep_u ? first.u : first.dy) = x[i];
    (sweep_u ? second.u : second.dy) = x[i + 1];
    std::ostringstream details;
    details << "  first input:\n" << describe_input(first) << "  first  s = " << hex(s[i]) << " (" << decimal(s[i])
            << "), case " << case_label(which[i]) << "\n"
            << "  second input:\n" << describe_input(second) << "  second s = " << hex(s[i + 1]) << " ("
            << decimal(s[i + 1]) << "), case " << case_label(which[i + 1]) << "\n"
            << "  tolerance " << double(tolerance) << " (" << bound << " ulps on each side, doubled)\n";
    fail("invariants", problem, details.str());
  }
}

// ---- by name --------------------------------------------------------------------

inline constexpr const char* target_names[] = {"differential", "cancellation", "invariants", "high_precision"};

inline bool run_check(const std::string& target, const std::uint8_t* data, std::size_t size) {
  if (target == "differential") check_differential(data, size);
  else if (target == "cancellation") check_cancellation(data, size);
  else if (target == "invariants") check_invariants(data, size);
  else if (target == "high_precision") check_high_precision(data, size);
  else return false;
  return true;
}

}  // namespace contact::fuzz
