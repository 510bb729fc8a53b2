// The check logic of the four fuzz targets, as plain functions of the input
// bytes. fuzz/targets/*.cpp wrap them for libFuzzer; fuzz/replay.cpp runs the
// committed corpus and regression files through them under ctest.
//
//   differential    (u, dy, phi) doubles from 24 raw bytes; every algorithm
//                   against the certified reference; aborts when the stable
//                   algorithm exceeds the claimed bound of its branch, returns
//                   NaN, returns infinity where the exact root is not beyond
//                   DBL_MAX, picks a case other than the exact one, or
//                   violates complementarity.
//   cancellation    the textbook algorithm's ulp error, on inputs folded into
//                   the plain window (docs/equations.md, "The plain window"),
//                   where no overflow or underflow can occur, returned as a
//                   feedback bucket (case x log2 of the error) so that the
//                   fuzzer climbs towards the worst cancellation. Never aborts.
//   invariants      a sweep of nine nearby inputs, across the case boundaries
//                   when asked: s is non-increasing and 1-Lipschitz in u,
//                   non-decreasing and 2 phi-Lipschitz in dy, and the cases
//                   follow each other in the only possible order.
//   high_precision  the differential check for long double and float128.
//   rounded         solve_rounded in double and float, bit for bit against
//                   the reference root rounded to the type (exact case too).
#pragma once

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>

#include "common.hpp"
#include "contact/detail/float_tools.hpp"
#include "contact/detail/window.hpp"
#include "contact/rounded.hpp"

namespace contact::fuzz {

// ---- differential -------------------------------------------------------------

// Where the stable algorithm sits in contact::algorithms.
inline constexpr std::size_t stable_index =
    std::size_t(std::ranges::find(algorithms, algorithm::stable) - std::ranges::begin(algorithms));
static_assert(stable_index < std::size(algorithms), "contact::algorithms has no stable algorithm");

template <class T>
std::string reference_text(const reference::certified& exact) {
  std::string text = exact.s.to_string(20);
  if constexpr (std::is_same_v<T, double>) text += "  (rounded to double: " + hex(reference::rounded_to_double(exact.s)) + ")";
  return text;
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

// One algorithm's answer to one input and its error in ulps of T.
template <class T>
struct algorithm_run {
  algorithm method;
  solution<T> result;
  double ulps;
};

template <class T>
using algorithm_runs = std::array<algorithm_run<T>, std::size(algorithms)>;

// Every algorithm must answer an invalid input with NaN and case invalid.
template <class T>
void check_rejects_invalid(const char* target, const input<T>& x) {
  using std::isnan;
  for (const algorithm a : algorithms) {
    const solution<T> r = solve(x.u, x.dy, x.phi, a);
    if (!(isnan(r.s) && r.which == contact_case::invalid))
      fail(target, std::string(name_of(a)) + " did not reject an invalid input",
           describe_input(x) + "  got s = " + hex(r.s) + ", case " + case_label(r.which) +
               "\n  expected NaN and case 0 invalid\n");
  }
}

// The reference's root; a root it cannot certify is a finding of its own.
template <class T>
reference::certified certified_root(const char* target, const input<T>& x) {
  reference::certified exact = reference::solve<T>(x.u, x.dy, x.phi);
  if (!exact.is_certified)
    fail(target, "the reference could not certify its root",
         describe_input(x) + "  reference s = " + exact.s.to_string(40) + ", case " + case_label(exact.which) + "\n");
  return exact;
}

// The ulp error of an answer: infinity is right (error 0) only for a root that
// rounds to it; release with dy the largest finite T gets no allowance here
// (the library answers the rounded root there, dy itself where it rounds to it).
template <class T>
double error_of(const solution<T>& r, const reference::certified& exact, const T&) {
  return reference::ulp_error<T>(r.s, exact);
}

template <class T>
algorithm_runs<T> run_every_algorithm(const input<T>& x, const reference::certified& exact) {
  algorithm_runs<T> runs;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const solution<T> r = solve(x.u, x.dy, x.phi, algorithms[i]);
    runs[i] = {algorithms[i], r, error_of(r, exact, x.dy)};
  }
  return runs;
}

template <class T>
void record_runs(const input<T>& x, const algorithm_runs<T>& runs) {
  for (const algorithm_run<T>& run : runs) stats().record(run_label<T>(run.method), run.ulps, x, run.result.which);
}

// The claimed bound of the branch that the exact case and the sign of u select.
template <class T>
double branch_bound(const input<T>& x, contact_case which) {
  return claimed().for_case(which, x.u > 0);
}

// What is wrong with stable's answer, or "": NaN, a spurious infinity, the
// wrong case, more error than its branch's claimed bound, complementarity.
template <class T>
std::string stable_problem(const input<T>& x, const algorithm_run<T>& stable, const reference::certified& exact) {
  using std::isinf;
  using std::isnan;
  const solution<T>& got = stable.result;
  if (isnan(got.s)) return "stable returned NaN for a valid input";
  if (isinf(got.s) && stable.ulps != 0)
    return "stable returned infinity where the exact root is a finite " + std::string(type_name<T>);
  if (got.which != exact.which) return "stable chose the wrong case";
  if (!(stable.ulps <= branch_bound(x, exact.which))) return "stable exceeds the claimed bound of its branch";
  if (!lies_on_its_side(got.which, got.s, x.dy))
    return "stable violates complementarity (s on the wrong side of dy for its case)";
  return "";
}

// contact::solve without an algorithm must be solve_stable, to the bit.
template <class T>
std::string default_problem(const input<T>& x, const solution<T>& stable) {
  using std::isnan;
  const solution<T> dispatched = solve(x.u, x.dy, x.phi);
  const bool same_s = dispatched.s == stable.s || (isnan(dispatched.s) && isnan(stable.s));
  if (!same_s || dispatched.which != stable.which) return "contact::solve's default differs from solve_stable";
  return "";
}

template <class T>
std::string differential_report(const input<T>& x, const algorithm_runs<T>& runs, const reference::certified& exact) {
  const algorithm_run<T>& stable = runs[stable_index];
  std::ostringstream details;
  details << describe_input(x) << "  expected s = " << reference_text<T>(exact) << "\n"
          << "  got      s = " << hex(stable.result.s) << "   (" << decimal(stable.result.s) << ")\n"
          << "  error      = " << stable.ulps << " ulps (claimed bound " << branch_bound(x, exact.which)
          << " ulps, branch " << harness::branch_of(exact.which, x.u > 0) << ")\n"
          << "  case: expected " << case_label(exact.which) << ", got " << case_label(stable.result.which) << "\n";
  for (const algorithm_run<T>& run : runs)
    if (run.method != algorithm::stable)
      details << "  (" << name_of(run.method) << ": s = " << hex(run.result.s) << ", " << run.ulps << " ulps, case "
              << case_label(run.result.which) << ")\n";
  return details.str();
}

// The differential check of one input of type T.
template <class T>
differential_result differential_check(const char* target, const input<T>& x) {
  statistics& st = stats();
  ++st.inputs;
  if (!is_valid(x)) {
    ++st.invalid_inputs;
    check_rejects_invalid(target, x);
    return {};
  }
  const reference::certified exact = certified_root(target, x);
  const algorithm_runs<T> runs = run_every_algorithm(x, exact);
  record_runs(x, runs);
  const algorithm_run<T>& stable = runs[stable_index];
  std::string problem = stable_problem(x, stable, exact);
  if (problem.empty()) problem = default_problem(x, stable.result);
  if (problem.empty()) return {stable.ulps, exact.which};
  fail(target, problem, differential_report(x, runs, exact));
}

inline differential_result check_differential(const std::uint8_t* data, std::size_t size) {
  const input<double> x{take_double(data, size, 0), take_double(data, size, 8), take_double(data, size, 16)};
  return differential_check<double>("differential", x);
}

// ---- high precision -----------------------------------------------------------

// 48 bytes: three 16-byte values. Each is read as a binary128 and, from its
// first 10 bytes, as an x87 long double; both triples are checked.
struct high_precision_result {
  differential_result long_double, quad;
};

inline high_precision_result check_high_precision(const std::uint8_t* data, std::size_t size) {
  const input<long double> x{take_long_double(data, size, 0), take_long_double(data, size, 16),
                             take_long_double(data, size, 32)};
  const input<contact::float128> q{take_float128(data, size, 0), take_float128(data, size, 16),
                                   take_float128(data, size, 32)};
  high_precision_result result;
  result.long_double = differential_check<long double>("high_precision", x);
  result.quad = differential_check<contact::float128>("high_precision", q);
  return result;
}

// ---- cancellation hunter ------------------------------------------------------

// The hunter's inputs: 24 raw bytes as three doubles, folded into the stable
// algorithm's plain window (|x| zero or within 2^-E .. 2^E, E =
// detail::plain_window<double>, docs/equations.md "The plain window"): a value
// whose exponent lies outside has its exponent field wrapped into the window
// (sign and significand kept), NaN and infinity included, and phi's sign is
// dropped. Every input is then valid and every double of the window below 2^E
// is reachable as itself, and no intermediate of the textbook formulas can
// overflow or underflow, so that every error the hunter sees is rounding and
// cancellation. (Overflow and underflow of the textbook formulas are measured
// by the differential target, whose inputs are not folded.)
inline double fold_into_window(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, 8);
  if ((bits << 1) == 0) return x;  // +-0
  constexpr std::uint64_t half_width = detail::plain_window<double>;
  constexpr std::uint64_t bias = std::numeric_limits<double>::max_exponent - 1;
  constexpr std::uint64_t lowest = bias - half_width, width = 2 * half_width;  // biased exponents of 2^-E .. 2^(E-1)
  static_assert(0 < lowest && lowest + width <= 2 * bias, "the plain window lies within double's normal range");
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
  input<double> x{};
  contact_case which = contact_case::invalid;
};

inline input<double> take_folded_input(const std::uint8_t* data, std::size_t size) {
  return {fold_into_window(take_double(data, size, 0)), fold_into_window(take_double(data, size, 8)),
          std::fabs(fold_into_window(take_double(data, size, 16)))};
}

// The textbook algorithm's error on x and its feedback bucket.
inline hunt_result measure_textbook(const input<double>& x) {
  const reference::certified exact = reference::solve<double>(x.u, x.dy, x.phi);
  const solution<double> got = solve_textbook(x.u, x.dy, x.phi);
  hunt_result result;
  result.x = x;
  result.ulps = reference::ulp_error<double>(got.s, exact);
  result.which = exact.which;
  result.bucket = (static_cast<int>(exact.which) - 1) * hunter::per_case + hunter::bucket_of(result.ulps);
  return result;
}

inline hunt_result check_cancellation(const std::uint8_t* data, std::size_t size) {
  statistics& st = stats();
  ++st.inputs;
  const hunt_result result = measure_textbook(take_folded_input(data, size));
  st.record(run_label<double>(algorithm::textbook), result.ulps, result.x, result.which);
  return result;
}

// ---- invariants ---------------------------------------------------------------

// Layout: byte 0 mode; bytes 1-24 u, dy, phi; byte 25 the step (2^(b % 48)
// ulps between neighbours); byte 26 which boundary (mode 3).
//   mode 0: u swept around u           mode 1: u swept around its case boundary
//   mode 2: dy swept around dy         mode 3: dy swept around 0, -u or u / (phi - 1)
struct sweep_request {
  int mode = 0;
  input<double> base{};
  int step_log2 = 0;  // neighbours are 2^step_log2 doubles apart
  int boundary = 0;   // mode 3: 0 for dy = 0, 1 for u = -dy, 2 for u = dy (phi - 1)

  bool sweeps_u() const { return mode < 2; }
  // base, with the swept variable set to `value`
  input<double> at(double value) const {
    input<double> x = base;
    (sweeps_u() ? x.u : x.dy) = value;
    return x;
  }
};

inline sweep_request take_sweep_request(const std::uint8_t* data, std::size_t size) {
  sweep_request r;
  r.mode = take_byte(data, size, 0) % 4;
  r.base = {take_double(data, size, 1), take_double(data, size, 9), take_double(data, size, 17)};
  r.step_log2 = take_byte(data, size, 25) % 48;
  r.boundary = take_byte(data, size, 26) % 3;
  return r;
}

// The value the sweep is centred on (0 where that is not finite).
inline double sweep_centre(const sweep_request& r) {
  const input<double>& b = r.base;
  double centre = r.sweeps_u() ? b.u : b.dy;
  if (r.mode == 1) centre = b.dy <= 0 ? -b.dy : std::fma(b.dy, b.phi, -b.dy);  // u = -dy or u = dy (phi - 1)
  if (r.mode == 3) {
    switch (r.boundary) {
      case 0: centre = 0; break;
      case 1: centre = -b.u; break;                               // u = -dy
      default: centre = b.phi == 1 ? 0 : b.u / (b.phi - 1);  // u = dy (phi - 1)
    }
  }
  return std::isfinite(centre) ? centre : 0;
}

struct sweep_point {
  bool present = false;  // false beyond the finite doubles
  double x = 0;          // the swept variable
  double s = 0;          // stable's answer
  double ulp = 0;        // one ulp of double at s (finite s only)
  contact_case which = contact_case::invalid;
};

inline constexpr int sweep_points = 9;
using sweep = std::array<sweep_point, sweep_points>;

// The swept values: 2^step_log2 doubles apart around the centre, absent where
// they would leave the finite doubles.
inline sweep place_sweep(const sweep_request& r) {
  const std::int64_t centre = detail::ordered_key(sweep_centre(r));
  const std::int64_t step = std::int64_t(1) << r.step_log2;
  const std::int64_t limit = detail::ordered_key((std::numeric_limits<double>::max)());
  sweep points;
  for (int i = 0; i < sweep_points; ++i) {
    const std::int64_t k = centre + (i - sweep_points / 2) * step;
    points[i].present = -limit <= k && k <= limit;
    if (points[i].present) points[i].x = detail::from_ordered_key<double>(k);
  }
  return points;
}

// One ulp of double at a finite x, as the reference counts it (reference::ulp_of).
inline double ulp_at(double x) {
  reference::real exact(std::numeric_limits<double>::digits);
  mpfr_set_d(exact.get(), x, MPFR_RNDN);  // exact
  return mpfr_get_d(reference::ulp_of<double>(exact).get(), MPFR_RNDN);
}

// Stable's answer at every point; NaN for a valid input is a finding.
inline void solve_sweep(const sweep_request& r, sweep& points) {
  for (sweep_point& p : points) {
    if (!p.present) continue;
    const input<double> x = r.at(p.x);
    const solution<double> got = solve_stable(x.u, x.dy, x.phi);
    p.s = got.s;
    p.which = got.which;
    if (std::isnan(got.s) || got.which == contact_case::invalid)
      fail("invariants", "stable returned NaN for a valid input",
           describe_input(x) + "  got s = " + hex(got.s) + ", case " + case_label(got.which) + "\n");
    if (std::isfinite(got.s)) p.ulp = ulp_at(got.s);
  }
}

// How far two neighbouring answers may stray from the exact ones: `bound`
// ulps on each side, doubled.
inline long double pair_tolerance(const sweep_point& a, const sweep_point& b, double bound) {
  return 2.0L * bound * ((long double)a.ulp + b.ulp);
}

// s is non-increasing in u and non-decreasing in dy, up to the tolerance.
inline std::string monotonicity_problem(const sweep_request& r, const sweep_point& a, const sweep_point& b,
                                        long double tolerance) {
  const long double first = a.s, second = b.s;
  if (r.sweeps_u() && second > first + tolerance) return "s increases with u";
  if (!r.sweeps_u() && second < first - tolerance) return "s decreases as dy increases";
  return "";
}

// As u grows the case may only go free -> impact (dy <= 0), release -> contact (dy > 0).
inline std::string case_order_problem(const sweep_request& r, const sweep_point& a, const sweep_point& b) {
  if (!r.sweeps_u()) return "";
  if (r.base.dy <= 0 && a.which == contact_case::impact && b.which == contact_case::free)
    return "the case goes from impact back to free as u increases";
  if (r.base.dy > 0 && a.which == contact_case::contact && b.which == contact_case::release)
    return "the case goes from contact back to release as u increases";
  return "";
}

// |s2 - s1| <= |u2 - u1| and |s2 - s1| <= 2 phi |dy2 - dy1|, up to the tolerance.
inline std::string lipschitz_problem(const sweep_request& r, const sweep_point& a, const sweep_point& b,
                                     long double tolerance) {
  const long double first = a.s, second = b.s;
  const long double distance = (long double)b.x - a.x;
  const long double lipschitz = r.sweeps_u() ? 1.0L : 2.0L * r.base.phi;
  const long double slack = 1 + std::ldexp(1.0L, -58);
  if (std::fabs(second - first) <= lipschitz * distance * slack + tolerance) return "";
  return r.sweeps_u() ? "s jumps: |s(u2) - s(u1)| > |u2 - u1|" : "s jumps: |s(dy2) - s(dy1)| > 2 phi |dy2 - dy1|";
}

[[noreturn]] inline void fail_pair(const sweep_request& r, const sweep_point& a, const sweep_point& b,
                                   const std::string& problem, long double tolerance, double bound) {
  std::ostringstream details;
  details << "  first input:\n" << describe_input(r.at(a.x)) << "  first  s = " << hex(a.s) << " (" << decimal(a.s)
          << "), case " << case_label(a.which) << "\n"
          << "  second input:\n" << describe_input(r.at(b.x)) << "  second s = " << hex(b.s) << " (" << decimal(b.s)
          << "), case " << case_label(b.which) << "\n"
          << "  tolerance " << double(tolerance) << " (" << bound << " ulps on each side, doubled)\n";
  fail("invariants", problem, details.str());
}

// The checks of one pair of neighbours; infinities are the differential target's to judge.
inline void check_pair(const sweep_request& r, const sweep_point& a, const sweep_point& b, double bound) {
  if (!a.present || !b.present) return;
  if (!std::isfinite(a.s) || !std::isfinite(b.s)) return;
  const long double tolerance = pair_tolerance(a, b, bound);
  std::string problem = monotonicity_problem(r, a, b, tolerance);
  if (problem.empty()) problem = case_order_problem(r, a, b);
  if (problem.empty()) problem = lipschitz_problem(r, a, b, tolerance);
  if (!problem.empty()) fail_pair(r, a, b, problem, tolerance, bound);
}

inline void check_invariants(const std::uint8_t* data, std::size_t size) {
  statistics& st = stats();
  ++st.inputs;
  const sweep_request request = take_sweep_request(data, size);
  if (!is_valid(request.base)) {
    ++st.invalid_inputs;
    return;
  }
  sweep points = place_sweep(request);
  solve_sweep(request, points);
  const double bound = claimed().largest();  // neighbours may lie in different branches
  for (int i = 0; i + 1 < sweep_points; ++i) check_pair(request, points[i], points[i + 1], bound);
}

// ---- rounded ---------------------------------------------------------------------

// What a rounded check saw: the exact case and whether the exact decision ran
// (the libFuzzer target feeds both back, so that campaigns reach the slow path
// in every case).
struct rounded_result {
  contact_case which = contact_case::invalid;
  bool exact_decision = false;
};

inline constexpr int rounded_buckets = 1 + 4 * 2;
inline int rounded_bucket(const rounded_result& r) {
  if (r.which == contact_case::invalid) return 0;
  return 1 + (static_cast<int>(r.which) - 1) * 2 + int(r.exact_decision);
}

// solve_rounded's answer is the reference root rounded to nearest (ties to
// even) in T, bit for bit, and its case the exact one. A root of exactly 0 has
// no sign to round ((A.29) gives -u, (A.31) +0): there any zero passes.
template <class T>
rounded_result rounded_check(const input<T>& x) {
  using std::isnan;
  using std::signbit;
  statistics& st = stats();
  ++st.inputs;
  const auto traced = detail::solve_rounded_traced(x.u, x.dy, x.phi);
  const solution<T>& got = traced.result;
  if (!is_valid(x)) {
    ++st.invalid_inputs;
    if (!(isnan(got.s) && got.which == contact_case::invalid))
      fail("rounded", "rounded did not reject an invalid input",
           describe_input(x) + "  got s = " + hex(got.s) + ", case " + case_label(got.which) + "\n");
    return {};
  }
  const reference::certified exact = certified_root("rounded", x);
  st.record(std::string(type_name<T>) + " rounded", error_of(got, exact, x.dy), x, got.which);
  const reference::real expected = reference::rounded_root(exact, x.u, x.dy, x.phi);
  const T want = T(mpfr_get_d(expected.get(), MPFR_RNDN));  // exact: expected has T's precision and range
  const bool zero_root = mpfr_zero_p(exact.s.get()) != 0;
  const bool same = zero_root ? got.s == 0 : (got.s == want && signbit(got.s) == signbit(want));
  if (!same || got.which != exact.which)
    fail("rounded", same ? "rounded chose the wrong case" : "rounded is not the correctly rounded root",
         describe_input(x) + "  expected s = " + hex(want) + "   (exact " + exact.s.to_string(40) + "), case " +
             case_label(exact.which) + "\n  got      s = " + hex(got.s) + ", case " + case_label(got.which) +
             (traced.exact_decision ? " (exact decision)" : " (fast path)") + "\n");
  return {exact.which, traced.exact_decision};
}

// 24 bytes: u, dy, phi as raw doubles; the first 4 bytes of each 8 also as a raw
// float, so that float's inputs are reached bit by bit as well.
struct rounded_pair_result {
  rounded_result in_double, in_float;
};

inline rounded_pair_result check_rounded(const std::uint8_t* data, std::size_t size) {
  const input<double> x{take_double(data, size, 0), take_double(data, size, 8), take_double(data, size, 16)};
  float f[3];
  for (int i = 0; i < 3; ++i) take_bytes(data, size, std::size_t(8 * i), &f[i], sizeof(float));
  return {rounded_check<double>(x), rounded_check<float>(input<float>{f[0], f[1], f[2]})};
}

// ---- by name --------------------------------------------------------------------

inline constexpr const char* target_names[] = {"differential", "cancellation", "invariants", "high_precision",
                                               "rounded"};

inline bool run_check(const std::string& target, const std::uint8_t* data, std::size_t size) {
  if (target == "differential") check_differential(data, size);
  else if (target == "cancellation") check_cancellation(data, size);
  else if (target == "invariants") check_invariants(data, size);
  else if (target == "high_precision") check_high_precision(data, size);
  else if (target == "rounded") check_rounded(data, size);
  else return false;
  return true;
}

}  // namespace contact::fuzz
