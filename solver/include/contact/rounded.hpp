// The correctly rounded root of (A.2): s is the exact root rounded to nearest,
// ties to even, in T (float, double, long double, float128), with the exact case.
//
// The method is that of correctly rounded libraries (CORE-MATH): a fast
// approximation with a rigorous error bound, a rounding test, and where the
// test cannot decide, an exact decision (the three steps: below, before the
// exact decision's code).
//
// Complementarity holds only weakly: where the root lies within half an ulp of
// dy, the correctly rounded value may be dy itself (impact s <= dy, release
// s >= dy). s is +-infinity only when the exact root rounds beyond T's range.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <type_traits>

#include "cases.hpp"
#include "detail/float_tools.hpp"
#include "detail/input.hpp"
#include "detail/scaled.hpp"
#include "stable.hpp"

namespace contact {

// The types with a correctly rounded mode: the IEEE binary types (float,
// double, long double, float128), with a fixed precision and exponent range and
// a fused fma. Not the other multiprecision types: cpp_bin_float has no fused
// fma, and MPFR's precision is chosen at run time. (A trait on numeric_limits,
// so that this header needs no float128, nor libquadmath's header.)
template <class T>
inline constexpr bool rounded_available = std::numeric_limits<T>::is_iec559 && std::numeric_limits<T>::radix == 2;

// The method, step by step:
//
// 1. A fast approximation with a rigorous error bound. The stable path gives s0
//    within a few ulps; one Newton step on the case's polynomial Q (the
//    quadratic or linear equation whose root the case's closed form is), with
//    Q(s0) evaluated by error-free transformations, gives s0 + delta within
//    about 2^-2p |s| of the root. In double inside the plain window the bound
//    is a constant per case, proven by Gappa from the stable path's proven
//    bound (fixed_bound_<case>); elsewhere it is computed as the step goes (no
//    a-priori error claim of the stable path enters).
// 2. A rounding test: if no rounding boundary (the midpoint between two
//    neighbouring T values) lies within the bound of s0 + delta, the root
//    rounds as s0 + delta does.
// 3. Otherwise, and outside the exponent window where step 1 is analysed, the
//    exact decision: R is strictly increasing, so the root lies above a
//    midpoint m exactly when R(m) < 0, and on each side of dy the sign of R(m)
//    is that of a polynomial in m, u, dy and phi whose terms are products of
//    T values. Each product is an exact expansion (TwoProd on significands),
//    the terms are scaled<T> (significand and separate exponent, so nothing
//    under- or overflows for any finite input), and the sign of their sum is
//    decided exactly (Shewchuk's expansion). An exact zero is a tie, which goes
//    to the even neighbour. Starting from the best candidate at hand, the walk
//    moves one T value at a time until the root lies between the two midpoints.

namespace detail {

// ---- the exact decision ------------------------------------------------------

// Exact sums of products of T values, as scaled terms: each product of k
// factors is the exact expansion of 2^(k-1) terms (TwoProd on the
// significands, which lie in [0.5, 1) and so never underflow).
template <class T, std::size_t Capacity>
class exact_sum {
 public:
  // adds coefficient * 2^shift * (product of the factors)
  void add(int coefficient, long shift, std::initializer_list<T> factors) {
    std::array<scaled<T>, 8> parts{scaled<T>::normalized(T(coefficient), shift)};
    std::size_t count = 1;
    for (const T& factor : factors) {
      const scaled<T> f(factor);
      if (f.significand == 0) return;
      std::array<scaled<T>, 8> next;
      std::size_t next_count = 0;
      for (std::size_t i = 0; i < count; ++i) {
        const auto [high, low] = two_prod(parts[i].significand, f.significand);
        const long exponent = parts[i].exponent + f.exponent;
        next[next_count++] = scaled<T>::normalized(high, exponent);
        if (low != 0) next[next_count++] = scaled<T>::normalized(low, exponent);
      }
      parts = next;
      count = next_count;
    }
    for (std::size_t i = 0; i < count; ++i) terms_[size_++] = parts[i];
  }

  // The sign of the exact sum: Shewchuk's grow-expansion with zero
  // elimination keeps the components non-overlapping and increasing, so the
  // last one has the sign of the whole.
  int sign() const {
    std::array<scaled<T>, Capacity> expansion;
    std::size_t length = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      scaled<T> carry = terms_[i];
      std::size_t kept = 0;
      for (std::size_t j = 0; j < length; ++j) {
        const auto [sum, error] = two_sum(carry, expansion[j]);
        carry = sum;
        if (error.significand != 0) expansion[kept++] = error;
      }
      if (carry.significand != 0) expansion[kept++] = carry;
      length = kept;
    }
    return length == 0 ? 0 : expansion[length - 1].sign();
  }

 private:
  std::array<scaled<T>, Capacity> terms_;
  std::size_t size_ = 0;
};

// Sign of R at m = c + h, where c is a T value and h = +-2^shift (half the gap
// to a neighbour of c), so that m has p + 1 bits. m != 0 (a midpoint never is),
// and `below_kink` says whether m < dy. The polynomial of m's side of dy,
// multiplied through by m where R has a division by m:
//   dy <= 0, m >= dy:  R = m + u                                          (A.29)
//   dy <= 0, m <  dy:  m R = m^2 + u m + phi (dy - m)^2,  m < 0           (A.30)
//   dy >  0, m <= dy:  R = (1 + phi) m + u - 2 phi dy                      (A.31)
//   dy >  0, m >  dy:  m R = m^2 + u m - phi dy^2,  m > 0                  (A.32)
// with m^2 = c^2 + 2 c h + h^2 expanded, each monomial a product of T values.
template <class T>
int residual_sign_at(const T& c, int h_sign, long h_shift, bool below_kink, const T& u, const T& dy,
                     const T& phi) {
  const T h = T(h_sign);  // the power of two goes into the terms' exponents
  if (dy <= 0 && !below_kink) {  // (A.29)
    exact_sum<T, 3> r;
    r.add(1, 0, {c});
    r.add(1, h_shift, {h});
    r.add(1, 0, {u});
    return r.sign();
  }
  if (dy <= 0) {  // (A.30): m^2 + u m + phi (dy^2 - 2 dy m + m^2), and m < 0
    exact_sum<T, 24> r;
    r.add(1, 0, {c, c});
    r.add(2, h_shift, {c, h});
    r.add(1, 2 * h_shift, {h, h});
    r.add(1, 0, {u, c});
    r.add(1, h_shift, {u, h});
    r.add(1, 0, {phi, dy, dy});
    r.add(-2, 0, {phi, dy, c});
    r.add(-2, h_shift, {phi, dy, h});
    r.add(1, 0, {phi, c, c});
    r.add(2, h_shift, {phi, c, h});
    r.add(1, 2 * h_shift, {phi, h, h});
    return -r.sign();
  }
  if (below_kink) {  // (A.31): m + phi m + u - 2 phi dy
    exact_sum<T, 8> r;
    r.add(1, 0, {c});
    r.add(1, h_shift, {h});
    r.add(1, 0, {phi, c});
    r.add(1, h_shift, {phi, h});
    r.add(1, 0, {u});
    r.add(-2, 0, {phi, dy});
    return r.sign();
  }
  exact_sum<T, 11> r;  // (A.32): m^2 + u m - phi dy^2, and m > 0
  r.add(1, 0, {c, c});
  r.add(2, h_shift, {c, h});
  r.add(1, 2 * h_shift, {h, h});
  r.add(1, 0, {u, c});
  r.add(1, h_shift, {u, h});
  r.add(-1, 0, {phi, dy, dy});
  return r.sign();
}

// Sign of R at the midpoint of neighbours low < high in T. An infinite
// neighbour stands for the next value T would have with a wider exponent, so
// the midpoint is then the overflow threshold +-(max + ulp(max)/2).
template <class T>
int residual_sign_between(const T& low, const T& high, const T& u, const T& dy, const T& phi) {
  using std::frexp;
  using std::isinf;
  const T max = (std::numeric_limits<T>::max)();
  const T gap = isinf(high) ? T(max - next_down(max)) : isinf(low) ? T(next_up(-max) + max) : T(high - low);  // exact
  int gap_exponent = 0;
  frexp(gap, &gap_exponent);  // gap = 2^(gap_exponent - 1), so gap / 2 = 2^(gap_exponent - 2)
  const long half_gap = long(gap_exponent) - 2;
  if (isinf(low)) return residual_sign_at(T(-max), -1, half_gap, true, u, dy, phi);  // below every finite dy
  return residual_sign_at(low, 1, half_gap, high <= dy, u, dy, phi);  // the midpoint < dy iff high <= dy
}

// The even one of neighbours low < high (an infinite high is the overflow: IEEE
// rounds the threshold itself to infinity). No root lies below -max ((A.29)
// s = -u, (A.30) s > -u, (A.31) s > -max / (1 + phi), (A.32) s > 0), so low is finite.
template <class T>
T even_of(const T& low, const T& high) {
  using std::fmod;
  using std::isinf;
  if (isinf(high)) return high;
  const T gap = high - low;  // the ulp they share (the smaller one at a binade edge)
  return fmod(low / gap, T(2)) == 0 ? low : high;
}

// The root rounded to nearest, found by walking from the candidate c (finite)
// one T value at a time: the root lies above the midpoint of c and its upper
// neighbour exactly when R is negative there.
template <class T>
T walk_to_rounded_root(T c, const T& u, const T& dy, const T& phi) {
  using std::isinf;
  if (c == 0) c = 0;  // one zero: the walk steps through +0 only
  auto sign_between = [&](const T& low, const T& high) {
    return residual_sign_between(low == 0 ? T(0) : low, high == 0 ? T(0) : high, u, dy, phi);
  };
  auto next_above = [](const T& x) { return x == 0 ? std::numeric_limits<T>::denorm_min() : next_up(x); };
  auto next_below = [](const T& x) { return x == 0 ? T(-std::numeric_limits<T>::denorm_min()) : next_down(x); };
  T above = next_above(c);
  int sign = sign_between(c, above);
  if (sign == 0) return even_of(c, above);
  if (sign < 0) {  // the root is above the upper midpoint: walk up
    for (;;) {
      c = above;
      if (isinf(c)) return c;
      above = next_above(c);
      sign = sign_between(c, above);
      if (sign == 0) return even_of(c, above);
      if (sign > 0) return c;
    }
  }
  T below = next_below(c);
  sign = sign_between(below, c);
  if (sign == 0) return even_of(below, c);
  if (sign > 0) {  // the root is below the lower midpoint: walk down (never below -max, see even_of)
    for (;;) {
      c = below;
      below = next_below(c);
      sign = sign_between(below, c);
      if (sign == 0) return even_of(below, c);
      if (sign < 0) return c;
    }
  }
  return c;
}

// The sign of the exact root when it rounds to zero: R(0) = u - 2 phi floor(dy)
// is the limit of R at 0, so the root is positive exactly when R(0) < 0. A root
// of exactly 0 gives +0, as (A.31) gives it; a negative one, -0.
template <class T>
T signed_zero_for_root(const T& u, const T& dy, const T& phi) {
  exact_sum<T, 3> at_zero;
  at_zero.add(1, 0, {u});
  if (dy > 0) at_zero.add(-2, 0, {phi, dy});
  return at_zero.sign() > 0 ? T(-0.0) : T(0);
}

// ---- the fast approximation ----------------------------------------------------

// Half the gaps from a normal x to its neighbours below and above: half the
// ulp of x, or a quarter towards zero when |x| is a power of two.
template <class T>
struct gap_pair {
  T below, above;
};

template <class T>
gap_pair<T> half_gaps(const T& x) {
  using std::fabs;
  T power;  // 2^e <= |x| < 2^(e+1)
  if constexpr (detail::hardware_binary<T>) {
    using layout = binary_layout<T>;  // the exponent field alone
    power = std::bit_cast<T>(std::bit_cast<typename layout::bits>(x) & (layout::exponent_field << layout::significand_bits));
  } else if constexpr (detail::emulated_format<T>::available) {  // x87 long double, binary128: the binade from the bits
    using format = detail::emulated_format<T>;
    detail::unpacked_binary parts;
    format::unpack(x, parts);
    power = format::pack(false, parts.exponent + format::digits - 1, detail::uint128(1) << (format::digits - 1));
  } else {
    using std::frexp;
    using std::ldexp;
    int e = 0;
    frexp(x, &e);
    power = ldexp(T(1), e - 1);
  }
  const T away = power * std::numeric_limits<T>::epsilon() / 2;  // ulp(x) / 2
  const T toward = fabs(x) == power ? T(away / 2) : away;
  return x > 0 ? gap_pair<T>{toward, away} : gap_pair<T>{away, toward};
}

}  // namespace detail

namespace rounded_form {

// Veltkamp's splitting constant 2^ceil(p/2) + 1.
template <class T>
T veltkamp_splitter() {
  if constexpr (std::is_floating_point_v<T>) {
    return T(1ull << ((std::numeric_limits<T>::digits + 1) / 2)) + 1;
  } else {
    using std::ldexp;
    static const T splitter = ldexp(T(1), (detail::precision_of<T>() + 1) / 2) + 1;
    return splitter;
  }
}

// a * b = high + low exactly (barring underflow of low), inline: the hardware
// fma where the target has one, else Dekker's product on Veltkamp's split (a
// library fma call, on the baseline x86-64 target, is slower than the whole
// split; x87 long double and float128 have no hardware fma at all).
template <class T>
[[gnu::always_inline]] inline detail::exact_pair<T> product(const T& a, const T& b) {
#if defined(__FMA__)
  if constexpr (detail::hardware_binary<T>) return detail::two_prod(a, b);
#endif
  const T splitter = veltkamp_splitter<T>();
  auto split = [&](const T& x) {
    const T scaled = splitter * x;
    const T high = scaled - (scaled - x);
    return detail::exact_pair<T>{high, x - high};
  };
  const T high = a * b;
  const auto [a_high, a_low] = split(a);
  const auto [b_high, b_low] = split(b);
  return {high, ((a_high * b_high - high) + a_high * b_low + a_low * b_high) + a_low * b_low};
}

// Q(s0), Q'(s0) of the case's polynomial Q, with error bounds, an upper bound
// on Q's leading coefficient (0 for a linear Q), and the sign Q' has at the
// wanted root (0: any, for a linear Q).
template <class T>
struct residual {
  T value, error, slope, slope_error, curvature;
  int root_slope_sign;
};

// Every rounding below errs by at most eps |result| + eta (eps = 2^-p; eta, the
// absolute error of an underflow, is at most half the least subnormal: the least
// normal is taken, so that no bound has a subnormal operand, which costs time);
// the bounds add these up, with the terms that the exact expansions leave out.
template <class T>
constexpr T eps = std::numeric_limits<T>::epsilon() / 2;
template <class T>
constexpr T eta = (std::numeric_limits<T>::min)();

// (A.31): Q(s) = (1 + phi) s + u - 2 phi dy = s0 D - N with N = 2 phi dy - u =
// n.high + n.low + p.low and D = 1 + phi = d.high + d.low, each split exact.
template <class T>
residual<T> contact(const T& s0, const T& u, const T& dy, const T& phi) {
  using std::fabs;
  const auto p = product(phi, T(2 * dy));
  const auto n = detail::two_sum(p.high, T(-u));
  const auto d = detail::two_sum(T(1), phi);
  const auto t = product(s0, d.high);                  // t.high ~ n.high
  const T r1 = (t.high - n.high) + t.low;              // s0 d.high - n.high, small
  const T r2 = s0 * d.low - (n.low + p.low);
  const T q = r1 + r2;
  // r1: 2 roundings; r2: 3 (s0 d.low, n.low + p.low, the difference); q: 1
  const T error = eps<T> * (2 * fabs(r1) + fabs(s0 * d.low) + 2 * fabs(n.low + p.low) + 2 * fabs(r2) + fabs(q)) +
                  10 * eta<T>;
  return {q, error, d.high, fabs(d.low), T(0), 0};
}

// s0 (s0 + u), the term (A.30) and (A.32) share: s0 + u = sum.high + sum.low
// exactly (TwoSum), and s0 (s0 + u) = product.high + product.low up to the one
// rounding of s0 sum.low, which the bounds count as eps |s0 sum.low|.
template <class T>
struct own_sum_product {
  detail::exact_pair<T> sum, product;
};

template <class T>
own_sum_product<T> times_own_sum(const T& s0, const T& u) {
  const auto sum = detail::two_sum(s0, u);
  const auto high = product(s0, sum.high);
  return {sum, {high.high, s0 * sum.low + high.low}};
}

// (A.32): Q(s) = s (s + u) - phi dy^2, Q'(s) = 2 s + u, the larger root, Q' > 0 there.
template <class T>
residual<T> release(const T& s0, const T& u, const T& dy, const T& phi) {
  using std::fabs;
  const auto [w, a] = times_own_sum(s0, u);
  const auto b = product(phi, dy);
  const auto c = product(b.high, dy);
  const T c_low = b.low * dy + c.low;     // phi dy^2 = c.high + c_low
  const T q1 = a.high - c.high, q2 = a.low - c_low, q = q1 + q2;
  const T error = eps<T> * (fabs(s0 * w.low) + 2 * fabs(a.low) + fabs(b.low * dy) + 2 * fabs(c_low) + fabs(q1) +
                            fabs(q2) + fabs(q)) + 12 * eta<T>;
  const T slope = w.high + s0;  // 2 s0 + u - w.low
  return {q, error, slope, T(fabs(w.low) + eps<T> * fabs(slope) + eta<T>), T(1), 1};
}

// (A.30): Q(s) = s (s + u) + phi (dy - s)^2, Q'(s) = 2 s + u - 2 phi (dy - s),
// the smaller root, Q' < 0 there.
template <class T>
residual<T> impact(const T& s0, const T& u, const T& dy, const T& phi) {
  using std::fabs;
  const auto [w, a] = times_own_sum(s0, u);
  const auto g = detail::two_sum(dy, T(-s0));  // dy - s0, exact
  const auto k = product(g.high, g.high);
  const T k_low = 2 * g.high * g.low + k.low;  // (dy - s0)^2 = k.high + k_low + g.low^2
  const auto m = product(phi, k.high);
  const T m_low = phi * k_low + m.low;         // phi (dy - s0)^2 = m.high + m_low
  const T q1 = a.high + m.high, q2 = a.low + m_low, q = q1 + q2;
  const T k_error = eps<T> * (fabs(2 * g.high * g.low) + 2 * fabs(k_low) + eps<T> * k.high) + 4 * eta<T>;  // + g.low^2
  const T error = eps<T> * (fabs(s0 * w.low) + 2 * fabs(a.low) + fabs(phi * k_low) + 2 * fabs(m_low) + fabs(q1) +
                            fabs(q2) + fabs(q)) + phi * k_error + 12 * eta<T>;
  const T slope1 = s0 + w.high, slope2 = phi * g.high, slope = slope1 - 2 * slope2;
  const T slope_error =
      eps<T> * (fabs(slope1) + 2 * slope2 + fabs(slope)) + fabs(w.low) + 2 * phi * fabs(g.low) + 4 * eta<T>;
  return {q, error, slope, slope_error, T(1 + phi), -1};
}

// s0 + delta (high + low exactly) and a bound on its distance to the root.
template <class T>
struct approximation {
  T high, low, bound;
  bool valid;  // false: no bound could be given (the exact decision takes over)
};

// One Newton step s0 + delta, delta = -Q(s0) / Q'(s0), on the case's polynomial Q
// of leading coefficient a (the curvature bound). The bound is computed
// alongside delta, not from it: it uses a cap on |delta| of 2^(5-p) |s0| (16 ulps;
// the stable path is within 3.01), and a step beyond the cap is refused. With
// rho = slope_error / |slope|:
// - delta rounded: |delta~ - delta| (1 - rho) <= 2 eps |delta~| + eta + error / |slope| + rho |delta~|
//   (1 / |slope| and the product each round once).
// - Newton's own error: Q is quadratic, so s0 + delta - s* = a e^2 / Q'(s0) exactly,
//   e = s0 - s*. With Q'(s0) of the sign Q' has at the wanted root (s0 on the
//   root's side of the parabola's vertex), |e| <= 2 |delta|: for roots s* and
//   s' = s* + D (the smaller root wanted), Q(s0) = a e (e - D), Q'(s0) = a (2e - D) < 0
//   for e < D/2, and |delta| / |e| = |e - D| / |2e - D| >= 1/2 there (mirrored for
//   the larger root).
// The sum is doubled, which covers the roundings of the bound's own evaluation.
template <class T>
approximation<T> newton_step(const T& s0, const residual<T>& q) {
  using std::fabs;
  const T magnitude = fabs(q.slope);
  const T inverse = 1 / magnitude;
  const T delta = (q.slope > 0 ? T(-q.value) : q.value) * inverse;
  const T cap = fabs(s0) * (32 * eps<T>);
  const T rho = q.slope_error * inverse;  // <= 1/4 (checked below), so 1 / (1 - rho) <= 4/3 < 1.5
  const T step_error = ((2 * eps<T> + rho) * cap + eta<T> + q.error * inverse) * T(1.5);
  const T delta_bound = cap + step_error;
  const T newton_error = q.curvature * 4 * delta_bound * delta_bound * (inverse * T(1.5));
  // the sign of Q'(s0) is certain and that of Q' at the wanted root, and the step within the cap
  const bool root_side = q.root_slope_sign == 0 || (q.slope > 0) == (q.root_slope_sign > 0);
  const bool valid = magnitude > 4 * q.slope_error && root_side && fabs(delta) <= cap;
  const auto [high, low] = detail::two_sum(s0, delta);
  return {high, low, 2 * (step_error + newton_error) + eta<T>, valid};
}

// Whether the approximation rounds as the root does: no midpoint between
// high and a neighbour lies within the bound of high + low. Both ends are
// rounded sums, and rounding is monotonic, so the comparisons with the exact
// half gaps are safe: low + bound >= gap/2 would round to >= gap/2.
template <class T>
bool rounds_as_root(const approximation<T>& x) {
  if (!x.valid) return false;
  const auto gaps = detail::half_gaps(x.high);
  return T(x.low + x.bound) < gaps.above && T(x.low - x.bound) > -gaps.below;
}

// ---- double: one Newton step with a fixed, proven bound ------------------------
//
// Inside the plain window, in double, the step below comes with a bound K |s0| on
// |s0 + delta - s*| that is a constant per case: proofs/gappa/rounded_<case>.g
// proves the relative bound from the stable path's proven bound on |s0 - s*|
// (claimed_bounds.txt), and gappa_rounded checks that K covers it and the
// rounding test's own roundings (proofs/rounded_bounds.txt, which rounded_test
// holds these constants to). Each case's slope is the exact derivative at the
// root, a quantity the stable formula already has (1 + phi, or the square root
// of the discriminant), so its reciprocal is computed alongside s0 rather than
// after the residual; Q(s0) is evaluated with error-free products and sums.
inline constexpr double fixed_bound_contact = 0x1p-94;
inline constexpr double fixed_bound_impact = 0x1p-93;
inline constexpr double fixed_bound_release = 0x1p-96;
// Where the bound is proven: in (A.31) the inputs' cancellation is limited,
// phi dy <= 64 (1 + phi) |s0|; in (A.30) the two roots of Q are apart, sqrt(disc)
// >= (1 + phi) |s0| / 16 (Newton's quadratic term grows as they merge).
inline constexpr double contact_cancellation_limit = 64;
inline constexpr double impact_separation_limit = 0x1p-4;

struct fixed_step {
  double s0, delta;
  bool bounded;  // false: outside the conditions the fixed bound is proven under
};

// (A.31): Q(s) = (1 + phi) s - (2 phi dy - u); Q(s0) = phi (2 dy - s0) - (u + s0) exactly
// as (m.high - w.high) + (m.low + phi g.low - w.low), m.high and w.high close.
inline fixed_step contact_step(double u, double dy, double phi) {
  using std::fabs;
  const double denominator = 1 + phi;
  const double s0 = std::fma(phi, 2 * dy, -u) / denominator;  // stable_form::contact
  const double inverse = 1 / denominator;
  const auto g = detail::two_sum(2 * dy, -s0);
  const auto m = product(phi, g.high);
  const auto w = detail::two_sum(u, s0);
  const double r = (m.high - w.high) + ((m.low + phi * g.low) - w.low);
  return {s0, r * inverse, phi * dy <= contact_cancellation_limit * (denominator * fabs(s0))};
}

// (A.30): Q(s) = s (s + u) + phi (dy - s)^2, Q'(s*) = -sqrt(disc).
inline fixed_step impact_step(double u, double dy, double phi) {
  using std::fabs;
  const auto [s0, root] = stable_form::impact_with_square_root(u, -dy, phi);
  const double denominator = 1 + phi;
  const double inverse = 1 / root;
  const auto a = times_own_sum(s0, u).product;
  const auto g = detail::two_sum(dy, -s0);
  const auto k = product(g.high, g.high);
  const double k_low = 2 * g.high * g.low + k.low;
  const auto m = product(phi, k.high);
  const double m_low = phi * k_low + m.low;
  const double q = (a.high + m.high) + (a.low + m_low);
  return {s0, q * inverse, root >= impact_separation_limit * (denominator * fabs(s0))};
}

// (A.32): Q(s) = s (s + u) - phi dy^2, Q'(s*) = sqrt(disc) > s*: always bounded.
inline fixed_step release_step(double u, double dy, double phi) {
  const auto [s0, root] = stable_form::release_with_square_root(u, dy, phi);
  const double inverse = 1 / root;
  const auto a = times_own_sum(s0, u).product;
  const auto b = product(phi, dy);
  const auto c = product(b.high, dy);
  const double c_low = b.low * dy + c.low;
  const double q = (a.high - c.high) + (a.low - c_low);
  return {s0, -q * inverse, true};
}

// The root lies in [s0 + delta - K |s0|, s0 + delta + K |s0|], and both ends as
// rounded here enclose that interval (K covers these roundings too); rounding
// to nearest is monotonic, so when both ends round alike the root rounds so.
inline bool rounds_alike(double s0, double delta, double factor, double& rounded) {
  const double margin = factor * std::fabs(s0);
  const double below = s0 + (delta - margin);
  rounded = s0 + (delta + margin);
  return below == rounded;
}

// float: the stable path's formulas run in double. Their proven bounds
// (proofs/claimed_bounds.txt: at most 3.01 ulps of double at the root, every
// branch, before the clamps) put the root within 2^-49 |s| of the double result:
// float inputs lie deep inside double's plain window, so every intermediate and
// the root are normal doubles. The float midpoints are exact doubles.
inline bool round_through_double(const float& u, const float& dy, const float& phi, solution<float>& out) {
  const double wide_u = u, wide_dy = dy, wide_phi = phi;
  double s;
  if (dy <= 0) {
    if (u <= -dy) {
      out = {-u, contact_case::free};  // (A.29) s = -u, exact
      return true;
    }
    out.which = contact_case::impact;  // (A.30)
    s = stable_form::impact(wide_u, -wide_dy, wide_phi);
  } else if (detail::stays_in_contact<true>(wide_u, wide_dy, wide_phi)) {  // exact, as in float
    out.which = contact_case::contact;  // (A.31)
    s = stable_form::contact(wide_u, wide_dy, wide_phi);
  } else {
    out.which = contact_case::release;  // (A.32)
    s = stable_form::release(wide_u, wide_dy, wide_phi);
  }
  const double bound = std::fabs(s) * 0x1p-49;
  const float rounded = static_cast<float>(s);
  out.s = rounded;  // the exact decision's candidate if the test below fails
  if (!(std::fabs(rounded) < std::numeric_limits<float>::max())) return false;
  const double above = (double(rounded) + double(detail::ulp_steps(rounded, 1))) / 2;
  const double below = (double(rounded) + double(detail::ulp_steps(rounded, -1))) / 2;
  return s + bound < above && s - bound > below;
}

}  // namespace rounded_form

namespace detail {

// safe_window<T>::holds (|x| in [2^-w, 2^w] or x = 0, w = safe_window<T>::half_width()),
// for double on the exponent bits; the fast path's analysis assumes u, dy, phi
// and s0 there. zero_allowed: whether x = 0 passes.
template <class T>
bool in_fast_window(const T& x, bool zero_allowed) {
  if (x == 0) return zero_allowed;
  if constexpr (std::is_same_v<T, double>) return magnitude_inside_plain_window(x);
  else return safe_window<T>::holds(x);
}

template <class T>
struct traced_solution {
  solution<T> result;
  bool exact_decision;  // whether the slow path (the walk over midpoints) ran
};

// The exact decision, walking from `start` (its case is the exact case; its s,
// if finite, is the first candidate), or without one from the stable path's result.
template <class T>
[[gnu::noinline]] traced_solution<T> rounded_by_exact_decision(const T& u, const T& dy, const T& phi,
                                                               const solution<T>* start) {
  using std::isinf;
  if (auto invalid = reject_invalid(u, dy, phi)) return {*invalid, false};
  const solution<T> stable = start ? *start : solve_stable(u, dy, phi);
  if (stable.which == contact_case::free) return {{T(-u), contact_case::free}, false};  // (A.29) exact
  // stable's s is never -inf (no root lies below -max, and its (A.30) clamp keeps s >= -u)
  T s = walk_to_rounded_root(isinf(stable.s) ? (std::numeric_limits<T>::max)() : stable.s, u, dy, phi);
  if (s == 0) s = signed_zero_for_root(u, dy, phi);
  return {{s, stable.which}, true};
}

// double inside the plain window: the fixed-bound step. Empty where its
// conditions fail (the run-time bound then decides); a failed rounding test
// goes to the exact decision, from s0 + delta.
inline std::optional<traced_solution<double>> rounded_by_fixed_bound(double u, double dy, double phi) {
  rounded_form::fixed_step step;
  contact_case which;
  double factor;
  if (dy < 0) {
    if (u <= -dy) return traced_solution<double>{{-u, contact_case::free}, false};  // (A.29) s = -u, exact
    step = rounded_form::impact_step(u, dy, phi);
    which = contact_case::impact;
    factor = rounded_form::fixed_bound_impact;
  } else if (stays_in_contact<true>(u, dy, phi)) {
    step = rounded_form::contact_step(u, dy, phi);
    which = contact_case::contact;
    factor = rounded_form::fixed_bound_contact;
  } else {
    step = rounded_form::release_step(u, dy, phi);
    which = contact_case::release;
    factor = rounded_form::fixed_bound_release;
  }
  if (!step.bounded || !magnitude_inside_plain_window(step.s0)) return std::nullopt;
  double rounded;
  if (rounded_form::rounds_alike(step.s0, step.delta, factor, rounded)) [[likely]]
    return traced_solution<double>{{rounded, which}, false};
  const solution<double> start{step.s0 + step.delta, which};
  return rounded_by_exact_decision<double>(u, dy, phi, &start);
}

// Everything but double's fixed-bound step, out of line so that the step's
// caller stays small.
template <class T>
[[gnu::noinline]] traced_solution<T> solve_rounded_general(const T& u, const T& dy, const T& phi) {
  using std::isfinite;
  if constexpr (std::is_same_v<T, float>) {
    if (auto invalid = reject_invalid(u, dy, phi)) return {*invalid, false};
    solution<float> result;
    if (rounded_form::round_through_double(u, dy, phi, result)) return {result, false};
    return rounded_by_exact_decision<T>(u, dy, phi, isfinite(result.s) ? &result : nullptr);
  } else {
    // Outside the window where the Newton step is analysed (invalid input
    // included), straight to the exact decision.
    if (!(in_fast_window(u, true) && in_fast_window(dy, true) && in_fast_window(phi, true) && !(phi < 0)))
      return rounded_by_exact_decision<T>(u, dy, phi, nullptr);
    // The stable path's case decision and its formulas, unclamped: Newton's step
    // needs s0 near the root, not on its side of dy.
    solution<T> start;
    rounded_form::residual<T> q;
    if (dy <= 0) {
      if (u <= -dy) return {{T(-u), contact_case::free}, false};  // (A.29) s = -u, exact
      start = {stable_form::impact(u, T(-dy), phi), contact_case::impact};  // (A.30)
      if (!in_fast_window(start.s, false)) return rounded_by_exact_decision<T>(u, dy, phi, &start);
      q = rounded_form::impact(start.s, u, dy, phi);
    } else if (stays_in_contact<true>(u, dy, phi)) {
      start = {stable_form::contact(u, dy, phi), contact_case::contact};  // (A.31)
      if (!in_fast_window(start.s, false)) return rounded_by_exact_decision<T>(u, dy, phi, &start);
      q = rounded_form::contact(start.s, u, dy, phi);
    } else {
      start = {stable_form::release(u, dy, phi), contact_case::release};  // (A.32)
      if (!in_fast_window(start.s, false)) return rounded_by_exact_decision<T>(u, dy, phi, &start);
      q = rounded_form::release(start.s, u, dy, phi);
    }
    const auto x = rounded_form::newton_step(start.s, q);
    if (rounded_form::rounds_as_root(x)) return {{x.high, start.which}, false};
    if (x.valid) start.s = x.high;
    return rounded_by_exact_decision<T>(u, dy, phi, &start);
  }
}

// solve_rounded, and whether it needed the exact decision (for the tests and
// the measurements of the slow path's share).
template <class T>
traced_solution<T> solve_rounded_traced(const T& u, const T& dy, const T& phi) {
  static_assert(rounded_available<T>, "solve_rounded: correct rounding is implemented for float, double, "
                                      "long double and float128 only");
  if constexpr (std::is_same_v<T, double>) {
    if (inside_plain_window(u, dy, phi)) [[likely]] {
      if (auto fixed = rounded_by_fixed_bound(u, dy, phi)) [[likely]] return *fixed;
    }
  }
  return solve_rounded_general(u, dy, phi);
}

}  // namespace detail

// The exact root of (A.2) rounded to nearest (ties to even) in T, and the exact
// case. Invalid input gives NaN and contact_case::invalid.
template <class T>
solution<T> solve_rounded(const T& u, const T& dy, const T& phi) {
  return detail::solve_rounded_traced(u, dy, phi).result;
}

}  // namespace contact
