// An exhaustive check of scaled<T> (contact/detail/scaled.hpp), operator by
// operator, on miniature formats whose own exponent range is tiny, so that
// the shifts by exponent differences leave T's range, flush to zero or round
// into the subnormals, and the conversion back to T overflows and underflows.
// The header claims that the significand arithmetic rounds as T would with an
// unbounded exponent; the oracle is exact integer arithmetic (the dyadic
// numbers of exact_root.hpp) rounded once to T's precision, to nearest, ties
// to even, with an unbounded exponent. Operands are scaled values m 2^e with
// m every significand of the format in [0.5, 1), both signs, and 0, and e
// over about three times T's exponent range (below). Checked, each as its own
// property:
//
//   - every result of every operator is normalized: 0, or 0.5 <= |m| < 1, finite;
//   - a + b, a - b and fma(a, b, c) are the exact result rounded once, except
//     in case (a) of the header: the shifted term (the smaller by exponent, for
//     fma the addend or the product) lies below T's least normal value after
//     the shift, so T flushes it or rounds it to its subnormals. There the
//     header promises only an absolute error below T's least subnormal
//     relative to the larger term, which is checked as
//       |r - x| <= |rn(x) - x| + k * denorm_min(T) * 2^E,
//     x the exact result, rn(x) its correct rounding, E the exponent of the
//     larger term (the one the other is shifted to), k = 1 for a sum and
//     k = 2 for fma (there the product may be the one kept and rounded: its
//     rounding can move by up to twice what was dropped). On these formats
//     every sum of case (a) is rounded correctly all the same (the dropped
//     term lies far below half an ulp of the kept one, which is a value of
//     T); an fma is not where its product is a tie that the dropped addend
//     would have broken, so k = 2 is needed there;
//   - a * b, a / b (b != 0) and square_root(a) (a >= 0; NaN for a < 0) are
//     the exact result rounded once;
//   - exact_product(a, b): high + low is a b exactly;
//   - a > b and a == b are the exact comparisons;
//   - value() is the exact value rounded once into T, by T's own rules:
//     infinity from the rounding limit on, flushed to zero (of its sign)
//     below the least normal value, or with subnormals rounded to their spacing.
//
// Prints "scaled exhaustive: N operations checked, F failures", the counts
// per property and the first failures, and exits non-zero when F > 0.
#include <boost/multiprecision/cpp_int.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/detail/scaled.hpp"
#include "exact_root.hpp"
#include "mini_float.hpp"

namespace contact::testing {
namespace {

using detail::scaled;
// 128 bits hold every exact value here: 5-bit significands with exponents
// within 70 of each other, products of two, and quotients to 9 bits.
using integer = exact::narrow;
using number = exact::dyadic<integer>;

// ---- the formats and the operands ---------------------------------------------

// 5 bits; normal numbers from 2^-10 to just below 2^11: as few binades below
// 1 as exact_product allows (2^-2p, where the low part of a product of two
// significands is still normal), so the shifts of + and fma leave T's range
// from an exponent difference of 10 on. Its fma is rounded once, as
// fused_multiply_add's claim needs (Dekker's product is not, by design).
using flushing = mini_float<5, -10, 10, true>;
// the same with subnormals: a shifted term below 2^-10 is rounded to a
// multiple of 2^-14 instead of flushed, and value() rounds there
using gradual = mini_float<5, -10, 10, true, true>;

// Operand exponents: about three times the format's 21 binades, centred on 0,
// so that every exponent difference from 0 to 64 occurs (case (a) from 10 on),
// products and quotients reach exponents of +-64, and value() overflows and
// flushes. fma's factors take fewer exponents: it depends on their exponents
// only through their sum, whose difference with c's runs over the full range
// all the same.
constexpr int exponent_reach = 32;
constexpr int factor_exponents[] = {-1, 0, 1};

template <class T>
scaled<T> make(int m, long e) {
  scaled<T> x;
  x.significand = T(std::ldexp(double(m), -T::precision));
  x.exponent = e;
  return x;
}

// 0 and +-m 2^-p 2^e for every m of p bits and every e of `exponents`
template <class T>
std::vector<scaled<T>> operands(const std::vector<long>& exponents) {
  std::vector<scaled<T>> values{make<T>(0, 0)};
  for (long e : exponents)
    for (int m = 1 << (T::precision - 1); m < (1 << T::precision); ++m) {
      values.push_back(make<T>(m, e));
      values.push_back(make<T>(-m, e));
    }
  return values;
}

std::vector<long> range(long low, long high) {
  std::vector<long> r;
  for (long e = low; e <= high; ++e) r.push_back(e);
  return r;
}

// ---- exact values and roundings -------------------------------------------------

template <class T>
number exactly(const scaled<T>& x) {
  number v = exact::exactly<integer>(double(x.significand));
  v.e += int(x.exponent);
  return v;
}

bool equal(const number& a, const number& b) { return sign(a - b) == 0; }
number magnitude(const number& a) { return {abs(a.m), a.e}; }
int bit_length(const integer& a) { return a == 0 ? 0 : int(msb(abs(a))) + 1; }

// q 2^e, plus something below its last bit if sticky, rounded to a multiple
// of 2^quantum, to nearest, ties to even.
number rounded_at(bool negative, integer q, int e, bool sticky, int quantum) {
  if (e < quantum) {
    const int dropped = quantum - e;
    integer kept = q >> dropped;
    const integer rest = q - (kept << dropped), half = integer(1) << (dropped - 1);
    if (rest > half || (rest == half && (sticky || (kept & 1) != 0))) ++kept;
    q = kept;
    e = quantum;
  }
  return {negative ? integer(-q) : q, e};
}

// n / d 2^e (d > 0) rounded to p bits with an unbounded exponent.
number rounded_quotient(const integer& n, const integer& d, int e, int p) {
  if (n == 0) return {};
  // at least p + 2 bits of quotient, so that the remainder only breaks ties
  const int shift = std::max(0, bit_length(d) - bit_length(abs(n)) + p + 2);
  integer q, r;
  divide_qr(integer(abs(n) << shift), d, q, r);
  return rounded_at(n < 0, q, e - shift, r != 0, e - shift + bit_length(q) - p);
}

number rounded(const number& x, int p) { return rounded_quotient(x.m, 1, x.e, p); }

// sqrt(x) for x > 0, rounded to p bits: the integer root of x's significand
// shifted to an even exponent and at least 2p + 4 bits.
number rounded_root(const number& x, int p) {
  int shift = std::max(0, 2 * p + 4 - bit_length(x.m));
  if ((x.e - shift) % 2 != 0) ++shift;
  const integer m = x.m << shift;
  integer r;
  const integer root = boost::multiprecision::sqrt(m, r);
  const int e = (x.e - shift) / 2;
  return rounded_at(false, root, e, r != 0, e + bit_length(root) - p);
}

// x rounded into T as T rounds its own results (mini_float.hpp): to p bits,
// or with subnormals to their spacing below the least normal value; then
// infinite from 2^(greatest + 1) on and, without subnormals, zero below 2^least.
template <class T>
double into_format(const number& x) {
  constexpr int p = T::precision;
  if (x.m == 0) return 0;
  const bool negative = x.m < 0;
  const int binade = bit_length(x.m) - 1 + x.e;
  const int quantum = T::subnormals && binade < T::least_exponent ? T::least_exponent - p + 1 : binade - p + 1;
  const number r = rounded_at(negative, abs(x.m), x.e, false, quantum);
  const double v = std::ldexp(double(abs(r.m)), r.e);  // at most p + 1 bits: exact
  if (v >= std::ldexp(1.0, T::greatest_exponent + 1)) return negative ? -INFINITY : INFINITY;
  if (!T::subnormals && v < std::ldexp(1.0, T::least_exponent)) return negative ? -0.0 : 0.0;
  return negative ? -v : v;
}

// ---- the tally ----------------------------------------------------------------------

struct property {
  const char* name;
  long checked = 0, failed = 0;
  long case_a = 0, case_a_rounded = 0;  // of case (a), and how many are rounded correctly all the same
};

struct tally {
  std::vector<property> properties;
  std::vector<std::string> first_failures;
  static constexpr std::size_t kept = 20;

  property& operator[](const char* name) {
    for (auto& p : properties)
      if (std::strcmp(p.name, name) == 0) return p;
    properties.push_back({name});
    return properties.back();
  }
  // what() describes the operation, only on a failure: most of the time goes to the checks
  template <class Describe>
  void check(const char* name, bool ok, Describe what) {
    property& p = (*this)[name];
    ++p.checked;
    if (ok) return;
    ++p.failed;
    if (first_failures.size() < kept) first_failures.push_back(std::string(name) + ": " + what());
  }
};

template <class T>
std::string show(const scaled<T>& x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g*2^%ld", double(x.significand), x.exponent);
  return text;
}

// ---- the checks -----------------------------------------------------------------------

template <class T>
bool is_normalized(const scaled<T>& x) {
  const double m = std::fabs(double(x.significand));
  return m == 0 || (m >= 0.5 && m < 1);
}

template <class T>
class checker {
 public:
  checker(tally& t, const char* format) : t_(t), format_(format) {}

  // r, a result of the operation `what` describes, is x rounded once to T's precision
  template <class Describe>
  void rounds_once(const char* name, const scaled<T>& r, const number& x, Describe what) {
    const auto about = [&] { return label(what()) + " = " + show(r); };
    t_.check("normalized", is_normalized(r), about);
    t_.check(name, is_normalized(r) && equal(exactly(r), rounded(x, p)), about);
  }

  // A sum or fma: x = larger + smaller, the smaller shifted by `difference`
  // exponents down to the larger's exponent `top` before T adds it.
  template <class Describe>
  void sum_rounds(const char* name, const scaled<T>& r, const number& x, long difference, long top, int k, Describe what) {
    if (difference < -long(T::least_exponent)) return rounds_once(name, r, x, what);
    // case (a): the shifted term lies below T's least normal value
    const auto about = [&] { return label(what()) + " = " + show(r) + " (case (a))"; };
    t_.check("normalized", is_normalized(r), about);
    const number rn = rounded(x, p), got = exactly(r);
    const number allowance{integer(k), int(top) + denorm_min_exponent};
    t_.check(name, is_normalized(r) && sign(magnitude(got - x) - magnitude(rn - x) - allowance) <= 0, about);
    ++t_[name].case_a;
    t_[name].case_a_rounded += equal(got, rn);
  }

  void pair(const scaled<T>& a, const scaled<T>& b) {
    const number x = exactly(a), y = exactly(b);
    const auto operation = [&](const char* op) { return [&a, &b, op] { return std::string(op) + " " + show(a) + ", " + show(b); }; };
    const bool both = a.significand != 0 && b.significand != 0;
    const long difference = both ? std::abs(a.exponent - b.exponent) : 0, top = std::max(a.exponent, b.exponent);
    sum_rounds("a + b", a + b, x + y, difference, top, 1, operation("+"));
    sum_rounds("a - b", a - b, x - y, difference, top, 1, operation("-"));
    rounds_once("a * b", a * b, x * y, operation("*"));
    if (b.significand != 0) {
      const scaled<T> q = a / b;
      const auto about = [&] { return label(operation("/")()) + " = " + show(q); };
      t_.check("normalized", is_normalized(q), about);
      const number expected = rounded_quotient(y.m < 0 ? integer(-x.m) : x.m, abs(y.m), x.e - y.e, p);
      t_.check("a / b", is_normalized(q) && equal(exactly(q), expected), about);
    }
    const auto product = detail::exact_product(a, b);
    const auto about_product = [&] { return label(operation("exact_product")()) + " = " + show(product[0]) + " + " + show(product[1]); };
    t_.check("normalized", is_normalized(product[0]) && is_normalized(product[1]), about_product);
    t_.check("exact_product", equal(exactly(product[0]) + exactly(product[1]), x * y), about_product);
    t_.check("a > b", (a > b) == (sign(x - y) > 0), [&] { return label(operation(">")()); });
    t_.check("a == b", (a == b) == (sign(x - y) == 0), [&] { return label(operation("==")()); });
  }

  void triple(const scaled<T>& a, const scaled<T>& b, const scaled<T>& c) {
    const number x = exactly(a) * exactly(b) + exactly(c);
    const long product_exponent = a.exponent + b.exponent;
    const bool all = a.significand != 0 && b.significand != 0 && c.significand != 0;
    const long difference = all ? std::abs(product_exponent - c.exponent) : 0;
    sum_rounds("fma", fused_multiply_add(a, b, c), x, difference, std::max(product_exponent, c.exponent), 2,
               [&] { return "fma " + show(a) + ", " + show(b) + ", " + show(c); });
  }

  void single(const scaled<T>& a) {
    const number x = exactly(a);
    const scaled<T> r = square_root(a);
    const auto about = [&] { return label("sqrt " + show(a)) + " = " + show(r); };
    if (x.m > 0) {
      t_.check("normalized", is_normalized(r), about);
      t_.check("square_root", is_normalized(r) && equal(exactly(r), rounded_root(x, p)), about);
    } else if (x.m == 0) {
      t_.check("square_root", r.significand == 0, about);
    } else {
      t_.check("square_root", std::isnan(double(r.significand)), about);  // no real root
    }
    const double got = double(a.value()), expected = into_format<T>(x);
    t_.check("value()", got == expected && std::signbit(got) == std::signbit(expected),
             [&] { return label("value " + show(a)) + " = " + std::to_string(got) + ", not " + std::to_string(expected); });
  }

 private:
  static constexpr int p = T::precision;
  // denorm_min(T) = 2^denorm_min_exponent: the least normal value without subnormals
  static constexpr int denorm_min_exponent = T::subnormals ? T::least_exponent - p + 1 : T::least_exponent;
  tally& t_;
  const char* format_;

  std::string label(const std::string& what) const { return std::string(format_) + ": " + what; }
};

template <class T>
void check_format(const char* name, tally& t) {
  checker<T> check(t, name);
  const auto all = operands<T>(range(-exponent_reach, exponent_reach));
  const auto factors = operands<T>({std::begin(factor_exponents), std::end(factor_exponents)});
  for (const auto& a : all) check.single(a);
  for (const auto& a : all)
    for (const auto& b : all) check.pair(a, b);
  for (const auto& a : operands<T>({0}))
    for (const auto& b : factors)
      for (const auto& c : all) check.triple(a, b, c);
}

}  // namespace
}  // namespace contact::testing

int main() {
  using namespace contact::testing;
  const auto start = std::chrono::steady_clock::now();
  tally t;
  try {
    check_format<flushing>("flushing", t);
    check_format<gradual>("gradual", t);
  } catch (const std::overflow_error& e) {
    std::printf("scaled exhaustive: an exact value left 128 bits (%s)\n", e.what());
    return 1;
  }
  // an operation is counted once, by its own property, not again by "normalized"
  long checked = 0, failed = 0;
  for (const auto& p : t.properties) {
    if (std::strcmp(p.name, "normalized") != 0) checked += p.checked;
    failed += p.failed;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("scaled exhaustive: %ld operations checked, %ld failures\n", checked, failed);
  for (const auto& p : t.properties) {
    std::printf("  %-14s %9ld checked, %ld failures", p.name, p.checked, p.failed);
    if (p.case_a > 0) std::printf(" (%ld of case (a), %ld of them rounded correctly all the same)", p.case_a, p.case_a_rounded);
    std::printf("\n");
  }
  std::printf("  %.1f s\n", seconds);
  for (const auto& f : t.first_failures) std::printf("  %s\n", f.c_str());
  return failed > 0 ? 1 : 0;
}
