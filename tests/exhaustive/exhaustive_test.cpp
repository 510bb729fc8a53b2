// An exhaustive check of the stable path and the correctly rounded mode on
// miniature binary formats: every triple (u, dy, phi) of a few boxes of 6-bit
// formats, against exact arithmetic. It stands for a proof of both at this
// precision (ctest label proofs). For each triple:
//
//   - the case is the exact case, the sign of R(dy) (docs/equations.md,
//     section 2): of u + dy for dy <= 0, of u + dy - phi dy for dy > 0;
//   - s lies on its case's side of dy (for solve_rounded weakly: s may be dy);
//   - s is never NaN, and infinite only where s* rounds to that infinity (it
//     lies at or beyond the largest finite value plus half its ulp), release
//     with dy the largest finite value included;
//   - s is as accurate as the method promises: for solve_stable within its
//     branch's bound of proofs/claimed_bounds.txt carried over to the format's
//     precision (below); for solve_rounded, s* rounded to nearest, ties to
//     even, at the subnormal spacing below the least normal value
//     (exact::format_of::is_rounded_root), and a zero of the sign rounded.hpp
//     gives it. A 6-bit format has no fast path (rounded_form::has_fixed_bounds),
//     so every triple takes the exact decision; the fast path of double, long
//     double and float128 is proven by Gappa (proofs.gappa.rounded) and tested
//     (rounded_test).
//
// Nothing computes s*: every check is a sign of R at a dyadic point
// (exact_root.hpp). Each box must also reach all four cases on both the plain
// path and the scaled one where it says it does, or the box is a failure.
//
// Prints each failure as it finds it ("found: ..."), then one line,
// "exhaustive: N triples checked, F failures", the counts per method, and the
// first failures again, and exits non-zero when F > 0. A crash in the checked
// code prints the triple each thread was solving and exits with status 2.
// With --worst it then prints, per method, format and branch, the largest
// error found in ulps and the share of answers that are correctly rounded (a
// report; nothing is asserted on it).
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>
#include <initializer_list>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "contact/harness/claimed_bounds.hpp"
#include "contact/rounded.hpp"
#include "contact/stable.hpp"
#include "exact_root.hpp"
#include "mini_float.hpp"

namespace contact::testing {
namespace {

// ---- the formats and the boxes ------------------------------------------------

// 6 bits; normal numbers from 2^-20 to just below 2^22; no subnormals. The
// plain window (docs/equations.md, section 6) is [2^-2, 2^2], inside the
// central box: both paths run, and the switch between them. Fused: the
// solver's fma is the format's, rounded once; unfused: Dekker's product and
// the solver's own exact sum, as for cpp_bin_float.
template <bool Fused>
using format = mini_float<6, -20, 21, Fused>;

// The same with fewer exponents below 1 than above, down to 2^-12 = 2^-2p,
// the least at which scaled<T> forms the exact product of two significands.
// A cluster of four terms of the exact sign (down to 2^-33) does not fit, and
// the plain window shrinks to [1, 1]: its room below 1 bounds it, not above.
using few_below_one = mini_float<6, -12, 21, false>;

// The fused format with subnormals: IEEE 754's rules in miniature (as many
// binades below 1 as above, gradual underflow), which the correctly rounded
// mode asks for. Below 2^-20 the values are the multiples of 2^-25.
using ieee = mini_float<6, -20, 21, true, true>;

// 0 and every value of the binades 2^low <= |x| < 2^(high + 1).
struct binades {
  int low, high;
};

struct box {
  const char* name;
  binades u, dy, phi;         // u and dy of both signs, phi >= 0
  bool plain = false, scaled = true;  // the paths on which it reaches all four cases
};

// Every ratio |u| / |dy| from 2^-5 to 2^9 and every phi from 2^-6 to 2^10:
// the four cases and both boundaries, the cancellation of (A.31) near s = 0
// and of (A.32) for u >> sqrt(phi) dy, the window's edges. (s* scales with
// (u, dy), so wider boxes would mostly repeat these.)
constexpr box central{"central", {-6, 5}, {-3, -2}, {-6, 9}, true, true};
// Its window is [1, 1]: too narrow to reach all four cases on the plain path.
constexpr box central_of_few{"central", {-6, 5}, {-3, -2}, {-6, 9}};
// The largest values: roots beyond and just below the largest finite value,
// the release clamp at the largest dy.
constexpr box top{"top", {19, 21}, {19, 21}, {-3, 3}};
// The least: roots below the least normal value, flushed to zero.
constexpr box bottom{"bottom", {-20, -18}, {-20, -18}, {-3, 3}};
constexpr box bottom_of_few{"bottom", {-12, -10}, {-12, -10}, {-3, 3}};
// The largest and least phi, with moderate u and dy: 1 + phi and phi dy^2
// far from phi, release roots far above dy, contact roots near 2 dy.
constexpr box stiff{"stiff", {-3, 2}, {-3, -2}, {18, 21}, false, false};  // no contact: u < dy (phi - 1)
constexpr box soft{"soft", {-3, 2}, {-3, -2}, {-20, -17}};
constexpr box soft_of_few{"soft", {-3, 2}, {-3, -2}, {-12, -9}};
// Smaller boxes of the same kinds for the correctly rounded mode, which takes
// about five times as long per triple (the exact decision outside the window).
// Central: every ratio |u| / |dy| from about 2^-3 to 2^6 and phi from 2^-3 to 2^4,
// both case boundaries on both sides of the window's edges.
constexpr box central_of_rounded{"central", {-3, 2}, {-3, -2}, {-3, 3}, true, true};
constexpr box top_of_rounded{"top", {20, 21}, {20, 21}, {-2, 2}};
// with the subnormals of u and dy (values_in), and roots among them
constexpr box bottom_of_rounded{"bottom", {-20, -19}, {-20, -19}, {-2, 2}};
constexpr box stiff_of_rounded{"stiff", {-1, 0}, {-3, -2}, {19, 21}, false, false};
// with the subnormals of phi: the (A.31) root within about phi of 2 phi dy - u
constexpr box soft_of_rounded{"soft", {-2, 1}, {-3, -2}, {-20, -19}};

// A range from the least normal binade takes the subnormals too.
template <class T>
std::vector<T> values_in(binades range, bool both_signs) {
  std::vector<T> values{T(0)};
  if (T::subnormals && range.low == T::least_exponent)
    for (int m = 1; m < (1 << (T::precision - 1)); ++m) {
      const T x = ldexp(T(m), T::least_exponent - T::precision + 1);
      values.push_back(x);
      if (both_signs) values.push_back(-x);
    }
  for (int e = range.low; e <= range.high; ++e)
    for (int m = 1 << (T::precision - 1); m < (1 << T::precision); ++m) {
      const T x = ldexp(T(m), e - T::precision + 1);
      values.push_back(x);
      if (both_signs) values.push_back(-x);
    }
  return values;
}

// ---- the check ------------------------------------------------------------------

// The claimed bounds at p bits. Gappa proves each branch's bound for binary64
// (proofs/gappa), but the argument holds at any precision: every intermediate
// is its exact value times a factor in [(1 - u)^m, (1 - u)^-m], u = 2^-p,
// where a rounding adds 1 to m, a product or quotient adds its operands' m, a
// sum of terms of one sign takes the larger m and a square root halves it;
// the release proofs weight the terms of a sum by their shares instead. The
// branches' m are 3 (contact) and 2.52 (release, u <= 0, proven in ulps of s*
// directly), the first-order terms of the proven bounds. So s is within
// relative error (1 - u)^-m - 1 <= m u / (1 - m u) of s* (Bernoulli; to first
// order only for the weighted sums), that is within m / (1 - m u) ulps of s*
// (ulp(s*) > |s*| u). For binary64 that is m plus a term of order 2^-53, which
// the claimed k (3.01, 2.53) covers; at p bits the term is of order 2^-p, and
// k / (1 - k u) >= m / (1 - m u) covers it: 3.16 and 2.64 ulps at p = 6.
// Compensated impact and release (u > 0) have m = 2.5 and 3 (the root's share
// and the last rounding) and terms of order u^2 beside, which Gappa bounds for
// binary64 only; their 2.62 and 3.16 ulps at p = 6 are held by this check, not
// derived (it finds 1.28 and 2.40). An ulp is relative to the
// format, so the bound is the same number of ulps but for that term. Free is
// s = -u, exact. Without a fused fma, one ulp more, the allowance of the
// property tests (unfused_fma_allowance, tests/harness.hpp): a branch's fma
// is then an exact product and sum rounded twice at the end. A bound is kept
// as a whole number of 2^-16 ulps, rounded up, so that the check is exact.
constexpr int bound_fraction_bits = 16;

// What a method promises of its answer's accuracy.
enum class accuracy { claimed_bound, correctly_rounded };

template <class T>
struct method {
  const char* name;
  solution<T> (*solve)(const T&, const T&, const T&);
  accuracy promise;
};

template <class T>
class checker {
 public:
  explicit checker(accuracy promise) : promise_(promise) {
    const auto& claimed = harness::project_bounds();
    const double unit_roundoff = std::ldexp(1.0, -precision);
    const double allowance = detail::has_fused_fma<T>::value ? 0 : 1;
    for (bool u_positive : {false, true})
      for (contact_case c : valid_cases) {
        const double k = claimed.for_case(c, u_positive);
        const double bound = k == 0 ? 0 : k / (1 - k * unit_roundoff) + allowance;
        bound_units_[u_positive][int(c)] = static_cast<long>(std::ceil(std::ldexp(bound, bound_fraction_bits)));
      }
  }

  // Why the answer for (u, dy, phi) is wrong, or nothing.
  std::optional<std::string> failure(const T& u, const T& dy, const T& phi, const solution<T>& result) const {
    try {
      return failure_in<exact::narrow>(u, dy, phi, result);
    } catch (const std::overflow_error&) {
      return failure_in<exact::wide>(u, dy, phi, result);
    }
  }

  // in ulps, for the report of a failure
  double bound(const T& u, contact_case c) const { return std::ldexp(double(bound_units_[u > 0][int(c)]), -bound_fraction_bits); }

 private:
  using format = exact::format_of<T>;
  static constexpr int precision = T::precision;
  accuracy promise_;
  long bound_units_[2][5] = {};

  // The sign of a zero result (rounded.hpp): free gives -u exactly; a root of
  // exactly 0 otherwise gives +0, and a nonzero root the zero of its sign.
  template <class Integer>
  static bool zero_is_negative(const exact::input<Integer>& x, const T& u, contact_case c) {
    if (c == contact_case::free) return !signbit(u);
    return x.root_sign() < 0;
  }

  template <class Integer>
  std::optional<std::string> failure_in(const T& u, const T& dy, const T& phi, const solution<T>& result) const {
    using std::isinf;
    using std::isnan;
    const exact::input<Integer> x{double(u), double(dy), double(phi)};
    const contact_case expected = x.exact_case();
    if (result.which != expected) return "the case is " + std::string(name_of(expected));
    const T& s = result.s;
    if (isnan(s)) return "NaN";
    if (promise_ == accuracy::correctly_rounded) {
      // weakly: the value nearest a root within half an ulp of dy is dy
      if (!lies_on_its_side(result.which, s, dy) && s != dy) return "s on the wrong side of dy";
    } else if (!lies_on_its_side(result.which, s, dy)) {
      return "s on the wrong side of dy";
    }
    if (isinf(s)) {
      // infinity is the root rounded only from the threshold, the largest value
      // plus half its ulp, on (a tie there goes to the even neighbour, infinity),
      // release with dy the largest value too
      const double half_ulp = std::ldexp(1.0, std::numeric_limits<T>::max_exponent - precision - 1);
      const auto threshold = exact::exactly<Integer>(double((std::numeric_limits<T>::max)()) + half_ulp);
      const bool rounds_to_infinity = s > 0 ? x.residual_sign(threshold) <= 0 : x.residual_sign(-threshold) >= 0;
      if (!rounds_to_infinity)
        return "infinite, but the root rounds to a finite value";
    }
    if (promise_ == accuracy::correctly_rounded) {
      if (!format::is_rounded_root(x, s)) return "not the root rounded to nearest";
      if (s == 0 && signbit(s) != zero_is_negative(x, u, expected)) return "the zero has the wrong sign";
      return std::nullopt;
    }
    if (isinf(s) || format::within(x, s, bound_units_[u > 0][int(expected)], bound_fraction_bits)) return std::nullopt;
    return "the error is beyond the bound";
  }
};

// The root to about 2^-60 relative, for reports: solve_stable in long double,
// whose own error (a few ulps of 2^-64) is far below an ulp of the format.
template <class T>
long double close_root(const T& u, const T& dy, const T& phi) {
  return solve_stable<long double>(double(u), double(dy), double(phi)).s;
}

// ---- the enumeration ---------------------------------------------------------------

// Per branch (free, impact, contact, release u <= 0, release u > 0) of the
// exact case: the largest error in ulps of s*, and how many answers are s*
// rounded to nearest.
constexpr int branches = 5;
constexpr const char* branch_names[branches] = {"free", "impact", "contact", "release_u_nonpositive", "release_u_positive"};
int branch_of(contact_case c, bool u_positive) { return c == contact_case::release ? 3 + u_positive : int(c) - 1; }

struct tally {
  long checked = 0, failed = 0;
  std::vector<std::pair<long, std::string>> first_failures;  // (position in the enumeration, what)
  static constexpr std::size_t kept = 10;
  bool reached[2][5] = {};  // [plain path][case]: some triple of the box got there
  // the report of --worst
  double worst[branches] = {};
  long counted[branches] = {}, rounded[branches] = {};

  void add(const tally& other) {
    checked += other.checked;
    failed += other.failed;
    first_failures.insert(first_failures.end(), other.first_failures.begin(), other.first_failures.end());
    std::sort(first_failures.begin(), first_failures.end());
    if (first_failures.size() > kept) first_failures.resize(kept);
    for (int p = 0; p < 2; ++p)
      for (int c = 0; c < 5; ++c) reached[p][c] = reached[p][c] || other.reached[p][c];
    for (int b = 0; b < branches; ++b) {
      worst[b] = std::max(worst[b], other.worst[b]);
      counted[b] += other.counted[b];
      rounded[b] += other.rounded[b];
    }
  }

  // Each failure is printed as it is found (a run that dies later has said
  // what it found), the first `printed` of the run; the first ones of each
  // box are kept for the summary too.
  static constexpr long printed = 200;
  void fail(long position, std::string what) {
    static std::atomic<long> found{0};
    if (const long n = found++; n <= printed) {
      static std::mutex printing;
      const std::lock_guard<std::mutex> lock(printing);
      if (n < printed) std::printf("  found: %s\n", what.c_str());
      else std::printf("  found: more failures, counted and not printed\n");
      std::fflush(stdout);
    }
    if (failed++ < long(kept)) first_failures.emplace_back(position, std::move(what));
  }
};

template <class T, class Integer>
void add_to_report_in(tally& mine, const T& u, const T& dy, const T& phi, const solution<T>& result) {
  const exact::input<Integer> x{double(u), double(dy), double(phi)};
  const int b = branch_of(result.which, u > 0);
  const int ulp = exact::format_of<T>::ulp_exponent_of_root(x, result.s);
  const bool rounded = exact::format_of<T>::is_rounded_root(x, result.s);
  const double error = double(std::fabs((double(result.s) - close_root(u, dy, phi)) / std::ldexp(1.0L, ulp)));
  mine.worst[b] = std::max(mine.worst[b], error);
  ++mine.counted[b];
  mine.rounded[b] += rounded;
}

template <class T>
void add_to_report(tally& mine, const T& u, const T& dy, const T& phi, const solution<T>& result) {
  using std::isinf;
  if (result.which == contact_case::invalid || isinf(result.s)) return;
  try {
    add_to_report_in<T, exact::narrow>(mine, u, dy, phi, result);
  } catch (const std::overflow_error&) {
    add_to_report_in<T, exact::wide>(mine, u, dy, phi, result);
  }
}

void print_report(const char* format_name, const tally& t) {
  for (int b = 0; b < branches; ++b)
    if (t.counted[b] > 0)
      std::printf("  %-14s %-22s worst %.3f ulps, %.1f%% correctly rounded (%ld answers)\n", format_name, branch_names[b],
                  t.worst[b], 100.0 * double(t.rounded[b]) / double(t.counted[b]), t.counted[b]);
}

// The triple each thread is solving, for the report of a crash in the checked
// code (a NaN that it did not expect can send it anywhere): printed by the
// handler of SIGSEGV, SIGFPE, SIGABRT and SIGBUS with the failures found so far.
struct under_test {
  std::atomic<double> u{0}, dy{0}, phi{0};
  std::atomic<const char*> what{""};
};
under_test current[2];

extern "C" void report_crash(int signal) {
  char text[300];
  for (const auto& c : current) {
    const int n = std::snprintf(text, sizeof text, "  crashed (signal %d) in %s at u=%.9g dy=%.9g phi=%.9g\n", signal,
                                c.what.load(), c.u.load(), c.dy.load(), c.phi.load());
    if (n > 0) (void)!write(2, text, std::size_t(std::min(n, int(sizeof text) - 1)));
  }
  std::_Exit(2);
}

// Every triple of the box, on two threads (the u values alternate).
template <class T>
tally check_box(const method<T>& m, const box& b, const char* format_name, bool report) {
  const checker<T> check(m.promise);
  const auto us = values_in<T>(b.u, true), dys = values_in<T>(b.dy, true), phis = values_in<T>(b.phi, false);
  constexpr int threads = 2;
  std::vector<tally> tallies(threads);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
    workers.emplace_back([&, t] {
      tally& mine = tallies[t];
      for (std::size_t i = t; i < us.size(); i += threads)
        for (std::size_t j = 0; j < dys.size(); ++j)
          for (std::size_t k = 0; k < phis.size(); ++k) {
            const T &u = us[i], &dy = dys[j], &phi = phis[k];
            current[t].u = double(u), current[t].dy = double(dy), current[t].phi = double(phi), current[t].what = m.name;
            const solution<T> result = m.solve(u, dy, phi);
            ++mine.checked;
            if (result.which != contact_case::invalid)
              mine.reached[detail::safe_window<T>::holds(u, dy, phi)][int(result.which)] = true;
            if (report) add_to_report(mine, u, dy, phi, result);
            const auto why = check.failure(u, dy, phi, result);
            if (!why) continue;
            char text[500];
            std::snprintf(text, sizeof text,
                          "%s %s %s: u=%.9g dy=%.9g phi=%.9g gives %s s=%.9g: %s; the root is %.10Lg, the bound %.3f ulps",
                          m.name, format_name, b.name, double(u), double(dy), double(phi),
                          std::string(name_of(result.which)).c_str(), double(result.s), why->c_str(), close_root(u, dy, phi),
                          check.bound(u, result.which));
            mine.fail(long((i * dys.size() + j) * phis.size() + k), text);
          }
    });
  for (auto& worker : workers) worker.join();
  tally total;
  for (const auto& t : tallies) total.add(t);
  // the box is there to reach these: a box that no longer does checks less than it says
  for (int plain = 0; plain < 2; ++plain) {
    if (!(plain ? b.plain : b.scaled)) continue;
    for (contact_case c : valid_cases)
      if (!total.reached[plain][int(c)]) {
        char text[200];
        std::snprintf(text, sizeof text, "%s %s %s: no triple reaches %s on the %s path", m.name, format_name, b.name,
                      std::string(name_of(c)).c_str(), plain ? "plain" : "scaled");
        total.fail(-1, text);
      }
  }
  return total;
}

template <class T>
solution<T> stable(const T& u, const T& dy, const T& phi) {
  return solve_stable(u, dy, phi);
}

template <class T>
solution<T> rounded(const T& u, const T& dy, const T& phi) {
  return solve_rounded(u, dy, phi);
}

// The methods, each with its own total.
enum method_id { stable_method, rounded_method, method_count };
constexpr const char* method_names[method_count] = {"stable", "rounded"};

// Every box of `boxes` for the method, on format T.
template <class T>
void check_format(method_id id, const char* format_name, std::initializer_list<box> boxes, tally (&totals)[method_count],
                  bool report) {
  method<T> m{method_names[stable_method], stable<T>, accuracy::claimed_bound};
  if (id == rounded_method) {
    if constexpr (rounded_available<T>) m = {method_names[rounded_method], rounded<T>, accuracy::correctly_rounded};
    else throw std::logic_error("solve_rounded does not take this format");
  }
  tally of_format;
  for (const box& b : boxes) of_format.add(check_box(m, b, format_name, report));
  totals[id].add(of_format);
  if (report) std::printf("%s, %s:\n", m.name, format_name), print_report(format_name, of_format);
}

}  // namespace
}  // namespace contact::testing

int main(int argc, char** argv) {
  using namespace contact::testing;
  const bool report = argc > 1 && std::strcmp(argv[1], "--worst") == 0;
  for (int signal : {SIGSEGV, SIGFPE, SIGABRT, SIGBUS}) std::signal(signal, report_crash);
  tally totals[method_count];
  check_format<format<true>>(stable_method, "fused", {central, top, bottom, stiff, soft}, totals, report);
  check_format<format<false>>(stable_method, "unfused", {central, top, bottom, stiff, soft}, totals, report);
  check_format<few_below_one>(stable_method, "few-below-one", {central_of_few, bottom_of_few, soft_of_few}, totals, report);
  check_format<ieee>(stable_method, "ieee", {bottom, soft}, totals, report);
  check_format<ieee>(rounded_method, "ieee",
                     {central_of_rounded, top_of_rounded, bottom_of_rounded, stiff_of_rounded, soft_of_rounded}, totals, report);
  tally total;
  for (const tally& t : totals) total.add(t);
  std::printf("exhaustive: %ld triples checked, %ld failures\n", total.checked, total.failed);
  for (int id = 0; id < method_count; ++id)
    std::printf("  %s: %ld triples, %ld failures\n", method_names[id], totals[id].checked, totals[id].failed);
  for (const auto& [position, what] : total.first_failures) std::printf("  %s\n", what.c_str());
  return total.failed > 0 ? 1 : 0;
}
