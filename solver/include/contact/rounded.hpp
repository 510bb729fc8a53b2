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
//    about 2^-2p |s| of the root. The bound's constants, per case and type,
//    are proven by Gappa from the stable path's proven bound
//    (fixed_bound_exponents). float's scalar path runs the stable formulas
//    in double instead (round_through_double); the float batch kernel takes
//    the step on float lanes inside float's common window, and the lanes it
//    leaves through double on double lanes.
// 2. A rounding test: if no rounding boundary (the midpoint between two
//    neighbouring T values) lies within the bound of s0 + delta, the root
//    rounds as s0 + delta does.
// 3. Otherwise, and outside the exponent window where step 1 is proven, double
//    takes steps 1 and 2 in long double where that is wider (wider_step); what
//    is still undecided takes the exact decision: R is strictly increasing, so
//    the root lies above a midpoint m exactly when R(m) < 0, and on each side
//    of dy the sign of R(m) is that of a polynomial in m, u, dy and phi whose
//    terms are products of T values. Each product is an exact expansion
//    (TwoProd on significands), the terms are scaled<T> (significand and
//    separate exponent, so nothing under- or overflows for any finite input),
//    and the sign of their sum is decided exactly (Shewchuk's expansion). An
//    exact zero is a tie, which goes to the even neighbour. Starting from the
//    best candidate at hand, the walk moves one T value at a time until the
//    root lies between the two midpoints.

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

// binary128 (Boost's float128), whose comparisons are library calls: x == 0
// costs as much as an addition, so the fast path's tests read its bits.
template <class T>
inline constexpr bool compared_on_bits = emulated_format<T>::available && !std::is_floating_point_v<T>;

// safe_window<T>::holds (|x| in [2^-w, 2^w] or x = 0, w = safe_window<T>::half_width()),
// which reads the bits of double, x87 long double and binary128; the fast path's
// analysis assumes u, dy, phi and s0 there. zero_allowed: whether x = 0 passes.
template <class T>
bool in_fast_window(const T& x, bool zero_allowed) {
  if constexpr (compared_on_bits<T>) {
    if (emulated_format<T>::magnitude_key(x) == 0) return zero_allowed;
  } else {
    if (x == 0) return zero_allowed;
  }
  return safe_window<T>::holds(x);
}

// phi < 0, for a phi that is not NaN.
template <class T>
bool negative_phi(const T& phi) {
  if constexpr (compared_on_bits<T>) {
    const uint128 bits = emulated_format<T>::bits_of(phi);
    return (bits >> 127) != 0 && emulated_format<T>::magnitude_key(phi) != 0;
  } else {
    return phi < 0;
  }
}

// A valid input whose u, dy and phi lie in the fast window (zeros included):
// where the fixed-bound step is proven.
template <class T>
bool inputs_in_fast_window(const T& u, const T& dy, const T& phi) {
  return in_fast_window(u, true) && in_fast_window(dy, true) && in_fast_window(phi, true) && !negative_phi(phi);
}

}  // namespace detail

namespace rounded_form {

#if defined(__FMA__)
inline constexpr bool fma_instruction = true;
#else
inline constexpr bool fma_instruction = false;
#endif

// a * b = high + low exactly (barring underflow of low), inline: the hardware
// fma where the target has one (the batch kernels' lanes always do), float128's
// fma in integers (Dekker's seventeen operations in software cost four times
// as much), else Dekker's product on Veltkamp's split (a library fma call, on
// the baseline x86-64 target, is slower than the whole split; x87 long double
// has no hardware fma, and its own split is faster than its fma in integers).
template <class T>
[[gnu::always_inline]] inline detail::exact_pair<T> product(const T& a, const T& b) {
  if constexpr (detail::lane_vector<T> || (fma_instruction && detail::hardware_binary<T>) ||
                detail::binary128_class<T>) {
    return detail::two_prod(a, b);
  } else {
    const T high = a * b;
    return {high, detail::dekker_product_error(a, b, high)};
  }
}

// s0 (s0 + u), the term (A.30) and (A.32) share: s0 + u = sum.high + sum.low
// exactly (TwoSum), and s0 (s0 + u) = product.high + product.low up to the one
// rounding of s0 sum.low.
template <class T>
struct own_sum_product {
  detail::exact_pair<T> sum, product;
};

template <class T>
[[gnu::always_inline]] inline own_sum_product<T> times_own_sum(const T& s0, const T& u) {
  const auto sum = detail::two_sum(s0, u);
  const auto high = product(s0, sum.high);
  return {sum, {high.high, s0 * sum.low + high.low}};
}

// ---- one Newton step with a fixed, proven bound ---------------------------------
//
// The step below comes with a bound K |s0| on |s0 + delta - s*|, K a constant per
// case and per significand width ((A.30)'s grows as its two roots merge, below):
// proofs/gappa/rounded_<case>.g proves the
// relative bound from the stable path's proven bound on |s0 - s*|
// (claimed_bounds.txt, proven for 24, 53, 64 and 113 bits), and gappa_rounded checks
// that K covers it and the rounding test's own roundings
// (proofs/rounded_bounds.txt, which rounded_test holds these constants to). The
// models assume that no operation of the step over- or underflows, which holds
// when u, dy, phi and s0 lie in safe_window (docs/equations.md section 7; for
// float, only in its common window). Each
// case's slope is the exact derivative at the root, a quantity the stable formula
// already has (1 + phi, or the square root of the discriminant), so its reciprocal
// is computed alongside s0 rather than after the residual; Q(s0) is evaluated with
// error-free products and sums.

// log2 K per case, by significand width; a type of another width has no fast
// path (the exact decision decides).
template <int Digits>
struct fixed_bound_exponents {};
// binary32: the float batch kernel's lanes, inside float's common window only,
// whose floors keep every product of the step normal (docs/equations.md
// section 7); float's scalar path rounds through double (below).
template <>
struct fixed_bound_exponents<24> {
  static constexpr int contact = -42, impact = -39, release = -39;
};
template <>
struct fixed_bound_exponents<53> {  // binary64
  static constexpr int contact = -100, impact = -97, release = -96;
};
template <>
struct fixed_bound_exponents<64> {  // x87 extended
  static constexpr int contact = -122, impact = -119, release = -119;
};
template <>
struct fixed_bound_exponents<113> {  // binary128
  static constexpr int contact = -220, impact = -217, release = -217;
};

template <class T>  // (T, or the lanes of T)
using fixed_bounds_of = fixed_bound_exponents<std::numeric_limits<detail::scalar_of_t<T>>::digits>;

template <class T>
concept has_fixed_bounds = rounded_available<T> && requires { fixed_bounds_of<T>::contact; };

// 2^Exponent in T (a constant for the hardware types and their lanes).
template <class T, int Exponent>
T power_of_two() {
  if constexpr (detail::lane_vector<T>) {
    return T(power_of_two<detail::scalar_of_t<T>, Exponent>());
  } else if constexpr (std::is_floating_point_v<T>) {
    constexpr T power = [] {
      T x = 1;
      for (int k = 0; k < -Exponent; ++k) x /= 2;
      return x;
    }();
    return power;
  } else {
    using std::ldexp;
    static const T power = ldexp(T(1), Exponent);
    return power;
  }
}

// s0 + delta lies within `margin` of the root.
template <class T>
struct fixed_step {
  T s0, delta, margin;
};

// (A.31): Q(s) = (1 + phi) s - N, N = 2 phi dy - u, is linear, so Newton's step
// has no error of its own: delta = (N - (1 + phi) s0) / (1 + phi), and only the
// residual's roundings count. N and (1 + phi) s0 are each an exact sum of T values
// (products and sums without error); their leading terms agree to a few ulps, and
// what rounds is of order 2^-2p N, where 2 phi dy and u cancel as well (gap.low is
// zero then, by Sterbenz's lemma). So the margin is K |s0| however deep the
// cancellation. Like every step below, written once for T and for the batch
// kernels' lanes.
template <class T>
[[gnu::always_inline]] inline fixed_step<T> contact_step(const T& u, const T& dy, const T& phi) {
  using std::fabs;
  const T s0 = stable_form::contact(u, dy, phi);
  const T inverse = T(1) / T(T(1) + phi);
  const auto push = product(phi, T(T(2) * dy));
  const auto gap = detail::two_sum(push.high, T(-u));
  const auto numerator = detail::two_sum(gap.high, push.low);  // N = numerator + gap.low
  const auto denominator = detail::two_sum(T(1), phi);
  const auto slope = product(s0, denominator.high);  // (1 + phi) s0 = slope + denominator.low s0
  const T r = (numerator.high - slope.high) + (((numerator.low + gap.low) - slope.low) - denominator.low * s0);
  return {s0, r * inverse, power_of_two<T, fixed_bounds_of<T>::contact>() * fabs(s0)};
}

// (A.30): Q(s) = s (s + u) + phi (dy - s)^2, Q'(s*) = -sqrt(disc). Newton's square
// term grows as Q's two roots merge, so the margin is K (1 + phi) s0^2 / sqrt(disc),
// K |s0| over their relative distance (the discriminant is a sum of non-negative
// terms, u^2 > 0 among them, so the root is not 0 in the window).
template <class T>
[[gnu::always_inline]] inline fixed_step<T> impact_step(const T& u, const T& dy, const T& phi) {
  const auto [s0, root] = stable_form::impact_with_square_root(u, T(-dy), phi);
  const T denominator = T(1) + phi;
  const T inverse = T(1) / root;
  const auto a = times_own_sum(s0, u).product;
  const auto g = detail::two_sum(dy, T(-s0));
  const auto k = product(g.high, g.high);
  const T k_low = T(2) * g.high * g.low + k.low;
  const auto m = product(phi, k.high);
  const T m_low = phi * k_low + m.low;
  const T q = (a.high + m.high) + (a.low + m_low);
  return {s0, q * inverse, power_of_two<T, fixed_bounds_of<T>::impact>() * (denominator * s0 * s0 * inverse)};
}

// (A.32): Q(s) = s (s + u) - phi dy^2, Q'(s*) = sqrt(disc) > s*.
template <class T>
[[gnu::always_inline]] inline fixed_step<T> release_step(const T& u, const T& dy, const T& phi) {
  using std::fabs;
  const auto [s0, root] = stable_form::release_with_square_root(u, dy, phi);
  const T inverse = T(1) / root;
  const auto a = times_own_sum(s0, u).product;
  const auto b = product(phi, dy);
  const auto c = product(b.high, dy);
  const T c_low = b.low * dy + c.low;
  const T q = (a.high - c.high) + (a.low - c_low);
  return {s0, T(-q * inverse), power_of_two<T, fixed_bounds_of<T>::release>() * fabs(s0)};
}

// The root lies in [s0 + delta - margin, s0 + delta + margin]: the ends of that
// interval, each rounded once from an exact end that encloses it (the margin's
// constants cover the roundings of delta -+ margin too). Rounding to nearest is
// monotonic, so the root rounds at or between these two.
template <class T>
struct interval_ends {
  T below, above;
};

template <class T>
[[gnu::always_inline]] inline interval_ends<T> rounded_ends(const fixed_step<T>& step) {
  return {step.s0 + (step.delta - step.margin), step.s0 + (step.delta + step.margin)};
}

// When both ends round alike, the root rounds so. (binary128's ends are
// compared as bits: equal bits are equal values, and the only equal values
// with unequal bits, -0 and +0, merely fail the test.)
template <class T>
[[gnu::always_inline]] inline bool rounds_alike(const fixed_step<T>& step, T& rounded) {
  const auto [below, above] = rounded_ends(step);
  rounded = above;
  if constexpr (detail::compared_on_bits<T>)
    return detail::emulated_format<T>::bits_of(below) == detail::emulated_format<T>::bits_of(above);
  else return below == above;
}

// float: the stable path's formulas run in double. Their proven bounds
// (proofs/claimed_bounds.txt: at most 3.01 ulps of double at the root, every
// branch, before the clamps) put the root within 2^-50.4 |s| of the double
// result s: float inputs lie deep inside double's plain window, so every
// intermediate and the root are normal doubles. s -+ 2^-49 |s|, each rounded
// once in double, still enclose the root, and rounding to float is monotonic
// (overflow and the subnormals included): where both ends round to one float,
// so does the root. Both ends have the sign of s, which is the root's (the bound
// is relative), so a zero has the right sign; a zero s is an exact (A.31) root, +0.

// the bound on double's s (or on double lanes: the batch kernel's through_double)
template <class Num>
[[gnu::always_inline]] inline Num through_double_bound(const Num& s) {
  using std::fabs;
  return fabs(s) * Num(0x1p-49);
}

[[gnu::always_inline]] inline bool round_through_double(const float& u, const float& dy, const float& phi,
                                                        solution<float>& out) {
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
  const double bound = through_double_bound(s);
  const float below = static_cast<float>(s - bound), above = static_cast<float>(s + bound);
  out.s = above;  // the exact decision's candidate if the test below fails
  return below == above;
}

}  // namespace rounded_form

namespace detail {

// u, dy, phi as the rounded mode's calls take them: float and double by value,
// in registers (by reference, the caller stores them and the callee loads them
// back, on the common path); the wider types by reference (x87 long double
// travels through memory either way, and its copies cost more than its loads:
// docs/performance.md).
template <class T>
using operand = std::conditional_t<hardware_binary<T>, T, const T&>;

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
  const solution<T> stable = start ? *start : solve_stable(u, dy, phi);  // (never free flight: answered before)
  // stable's s is never -inf (no root lies below -max, and its (A.30) clamp keeps s >= -u)
  T s = walk_to_rounded_root(isinf(stable.s) ? (std::numeric_limits<T>::max)() : stable.s, u, dy, phi);
  if (s == 0) s = signed_zero_for_root(u, dy, phi);
  return {{s, stable.which}, true};
}

// The case of a valid input and its fixed-bound step: the stable path's case
// decision and its formulas, unclamped (Newton's step needs s0 near the root, not
// on its side of dy). Free flight (A.29) is exact and needs no step.
template <class T>
struct cased_step {
  rounded_form::fixed_step<T> step;
  contact_case which;
};

// The step of a case decided before (not free flight), for the moves beyond
// the window. Inlined, as fixed_bound_step's steps are on the common path: a
// step returned from a call travels through memory, and its reload stalls.
template <class T>
[[gnu::always_inline]] inline rounded_form::fixed_step<T> step_of_case(contact_case which, const T& u, const T& dy,
                                                                       const T& phi) {
  if (which == contact_case::impact) return rounded_form::impact_step(u, dy, phi);
  if (which == contact_case::contact) return rounded_form::contact_step(u, dy, phi);
  return rounded_form::release_step(u, dy, phi);
}

template <class T>
[[gnu::always_inline]] inline cased_step<T> fixed_bound_step(const T& u, const T& dy, const T& phi) {
  if (dy <= 0) {
    if (u <= -dy) return {{T(-u), T(0), T(0)}, contact_case::free};  // (A.29) s = -u, exact
    return {rounded_form::impact_step(u, dy, phi), contact_case::impact};
  }
  if (stays_in_contact<true>(u, dy, phi)) return {rounded_form::contact_step(u, dy, phi), contact_case::contact};
  return {rounded_form::release_step(u, dy, phi), contact_case::release};
}

// The wider type whose step stands in for T's where T's cannot decide: one with
// proven bounds, a longer significand, and a fast window that holds every finite
// T with room (x87 long double or binary128, for double). void where there is
// none (a long double that is double, or double-double): the exact decision.
template <class T>
struct wider_step {
  using type = void;
};
template <>
struct wider_step<double> {
  using type = std::conditional_t<
      rounded_form::has_fixed_bounds<long double> && (std::numeric_limits<long double>::digits > 53) &&
          (window_half_width<long double>(std::numeric_limits<long double>::digits) >= 2 * 1075),
      long double, void>;
};

template <class T>
traced_solution<T> rounded_beyond_the_step(const T& u, const T& dy, const T& phi, const solution<T>* start);

// T's rounding of the root from a step on u, dy, phi in the fast window: where s0
// lies in the window too and the rounding test decides. Otherwise empty, and
// step.s0 the best candidate at hand.
template <class T>
[[gnu::always_inline]] inline std::optional<T> rounded_by_step(rounded_form::fixed_step<T>& step) {
  if (!in_fast_window(step.s0, false)) [[unlikely]] return std::nullopt;
  T rounded;
  if (rounded_form::rounds_alike(step, rounded)) [[likely]] return rounded;
  step.s0 += step.delta;  // the nearer candidate
  return std::nullopt;
}

template <class T>
std::optional<T> rounded_beside_an_input(const T& u, const T& dy, const T& phi, contact_case which);

// The fixed-bound step, for u, dy, phi inside the fast window (phi >= 0). Where
// s0 leaves the window or the rounding test fails (as where (A.30)'s roots
// merge under a stiff phi, and its margin widens), the value beside an input,
// the wider type's step or the exact decision decides, from the best candidate
// at hand.
template <class T>
traced_solution<T> rounded_by_fixed_bound(operand<T> u, operand<T> dy, operand<T> phi) {
  auto [step, which] = fixed_bound_step(u, dy, phi);
  if (which == contact_case::free) return {{step.s0, which}, false};
  if (auto decided = rounded_by_step(step)) [[likely]] return {{*decided, which}, false};
  if (auto beside = rounded_beside_an_input(u, dy, phi, which)) return {{*beside, which}, false};
  const solution<T> start{step.s0, which};
  return rounded_beyond_the_step<T>(u, dy, phi, &start);
}

// T's rounding of the root from W's step: with lo and hi W's rounded ends of the
// step's interval, the root lies in [lo', hi'] whose roundings in W are lo and hi
// (rounded_ends), and W's rounding is monotonic and keeps T's midpoints (W has
// more bits and a wider exponent range), so where lo and hi lie strictly between
// the midpoints around a T value r, the root does too, and rounds to r. Beyond
// the largest T the midpoint is the overflow threshold t = max + ulp(max) / 2
// (the root rounds to infinity from t up); a zero takes the sign of the root,
// which lo > 0 or hi < 0 tells.
template <class T, class W>
bool rounds_alike_in(const rounded_form::fixed_step<W>& step, T& rounded) {
  using std::isinf;
  const auto [lo, hi] = rounded_form::rounded_ends(step);
  const T max = (std::numeric_limits<T>::max)();
  const W threshold = W(max) + (W(max) - W(next_down(max))) / 2;
  rounded = T(hi);
  if (isinf(rounded)) return rounded > 0 ? lo > threshold : hi < -threshold;
  if (rounded == 0 && !(lo > 0 || hi < 0)) return false;
  const W below = rounded == -max ? -threshold : (W(rounded) + W(next_down(rounded))) / 2;
  const W above = rounded == max ? threshold : (W(rounded) + W(next_up(rounded))) / 2;
  return below < lo && hi < above;
}

// x in W, exactly. A subnormal float or double goes through its significand as
// an integer (scaled<T>::subnormal_as_integer): loading a subnormal operand into
// the x87 unit costs a microcode assist, longer than W's whole step.
template <class W, class T>
W widened(const T& x) {
  if constexpr (hardware_binary<T>) {
    using std::fabs;
    if (is_positive_subnormal(T(fabs(x)))) [[unlikely]]
      return W(scaled<T>::subnormal_as_integer(x)) * rounded_form::power_of_two<W, -scaled<T>::least_binade_of_bits>();
  }
  return W(x);
}

// u, dy, phi of T (valid or not) solved by W's step and rounded to T; where W's
// window does not hold them or the rounding test fails, the exact decision.
template <class T, class W>
[[gnu::noinline]] traced_solution<T> rounded_by_wider_step(const T& u, const T& dy, const T& phi) {
  using std::fabs;
  const W wide_u = widened<W>(u), wide_dy = widened<W>(dy), wide_phi = widened<W>(phi);
  if (!inputs_in_fast_window(wide_u, wide_dy, wide_phi)) return rounded_by_exact_decision<T>(u, dy, phi, nullptr);
  const auto [step, which] = fixed_bound_step(wide_u, wide_dy, wide_phi);  // (never free flight: answered before)
  T rounded;
  W candidate = step.s0;
  if (in_fast_window(step.s0, false)) [[likely]] {
    if (rounds_alike_in(step, rounded)) [[likely]] return {{rounded, which}, false};
    // Where (A.30)'s roots merge (phi large, s near dy), Newton's margin can
    // exceed s0's own error: at most 3.01 ulps of W at the root in every case
    // (proofs/claimed_bounds.txt, proven at W's width), so within 2^(3 - p) |s0|.
    const W stable_margin = rounded_form::power_of_two<W, 3 - std::numeric_limits<W>::digits>() * fabs(step.s0);
    if (rounds_alike_in(rounded_form::fixed_step<W>{step.s0, W(0), stable_margin}, rounded))
      return {{rounded, which}, false};
    candidate += step.delta;
  }
  const solution<T> start{T(candidate), which};
  return rounded_by_exact_decision<T>(u, dy, phi, &start);
}

template <class T>
traced_solution<T> rounded_beyond_the_step(const T& u, const T& dy, const T& phi, const solution<T>* start) {
  using W = typename wider_step<T>::type;
  if constexpr (std::is_void_v<W>) return rounded_by_exact_decision<T>(u, dy, phi, start);
  else return rounded_by_wider_step<T, W>(u, dy, phi);
}

// ---- far beyond the window: the root beside a value the inputs make ---------------
//
// Where phi lies far above or below the scale of u and dy, the root lies within
// a sliver of a T value r made exactly from the inputs, and rounds to r when
// the sliver is narrower than half the gap from |r| to its lower neighbour (the
// narrower gap, on either side). With M = max(|u|, |dy|):
//   (A.31) s = (2 phi dy - u) / (1 + phi): |s - 2 dy| = |u + 2 dy| / (1 + phi) <= 3 M / phi,
//          and |s + u| = phi |u + 2 dy| / (1 + phi) <= 3 phi M; r = 2 dy for phi >= 1, else -u.
//   (A.30), dy < 0 < dy + u, phi >= 1: s = dy - d, d the larger root of
//          (1 + phi) d^2 - (2 dy + u) d + dy (dy + u) = 0 (dy (dy + u) < 0), so d <=
//          |2 dy + u| / (1 + phi) + sqrt(|dy| (dy + u) / (1 + phi)) <= 3 M / phi + sqrt(|dy| M / phi)
//          (M = u), under twice the larger term; r = dy.
//   (A.30), phi <= 1/4: s = -u + e; with f(e) = e (u - e) - phi (dy + u - e)^2 = -Q(-u + e),
//          f(0) < 0 and, at e1 = 2 phi (dy + u)^2 / u <= 2 phi u <= u / 2 (also <= 2 (dy + u)),
//          f(e1) >= e1 u / 2 - phi (dy + u)^2 = 0: Q(-u) > 0 >= Q(-u + e1), so the smaller
//          root lies in (-u, -u + e1], e <= 2 phi u; r = -u.
//   (A.32), u < 0: s = (|u| + sqrt(u^2 + 4 phi dy^2)) / 2 <= |u| + phi dy^2 / |u|; r = -u.
// Each bound is a power of two, from the binades b of the inputs (x in [2^b,
// 2^(b+1)), binade_of; a zero phi below the least subnormal's; 3 < 2^2; a
// square root's exponent halved and rounded up), so no arithmetic rounds. The
// gap below |r| is at least 2^(b - p), b = binade_of(r): an ulp of r's binade,
// or of the one below where |r| is a power of two; among the subnormals, more.
// So where b - p exceeds the bound's exponent, the sliver is narrower than half
// of either gap.
// `which` is the exact case of a valid input, not free flight.
template <class T>
std::optional<T> rounded_beside_an_input(const T& u, const T& dy, const T& phi, contact_case which) {
  using std::fabs;
  using std::isfinite;
  constexpr int p = std::numeric_limits<T>::digits;
  const int phi_binade = phi == 0 ? std::numeric_limits<T>::min_exponent - p - 1 : binade_of(phi);
  const int largest = binade_of(max_of(T(fabs(u)), T(fabs(dy))));  // M's
  T r;
  int sliver;  // the root lies within 2^sliver of r
  if (which == contact_case::contact) {
    if (phi >= T(1)) {
      r = T(2) * dy;
      sliver = largest + 3 - phi_binade;
    } else {
      r = -u;
      sliver = phi_binade + largest + 4;
    }
  } else if (which == contact_case::impact) {
    if (phi >= T(1)) {
      if (dy == 0) return std::nullopt;  // (r = 0; and binade_of wants a non-zero x)
      r = dy;
      const int drift = largest + 3 - phi_binade;                          // 3 M / phi
      const int spread = (binade_of(dy) + largest + 3 - phi_binade) >> 1;  // sqrt(|dy| M / phi), rounded up
      sliver = std::max(drift, spread) + 1;
    } else if (phi <= T(0.25)) {
      r = -u;
      sliver = phi_binade + binade_of(u) + 3;
    } else {
      return std::nullopt;
    }
  } else {  // release
    if (!(u < 0)) return std::nullopt;
    r = -u;
    sliver = phi_binade + 2 * binade_of(dy) + 4 - binade_of(u);
  }
  if (r == 0 || !isfinite(r)) return std::nullopt;
  if (binade_of(r) - p > sliver) return r;
  return std::nullopt;
}

// ---- moved into the window: (A.2)'s symmetries --------------------------------------
//
// (A.2) is homogeneous in u, dy and s: s(2^k u, 2^k dy, phi) = 2^k s(u, dy, phi), in
// the same case (each criterion is the sign of a sum homogeneous in u and dy). And
// (A.32)'s polynomial s^2 + u s - phi dy^2 is the same when dy moves by 2^j and phi
// by 2^-2j, so a release's root is too (its case, decided before, does not move).
// (A.31)'s root N / (1 + phi), N = 2 phi dy - u, is nearly so when phi lies beyond the
// window: phi moved to 2^j phi near 2^-220 with dy moved by 2^-j keeps N and gives
// N / (1 + 2^j phi) = s (1 - e), 0 < e < 2^j phi < 2^-219; phi moved to 2^-j phi near
// 2^220 with u moved by 2^-j gives 2^-j N / (1 + 2^-j phi) = s (1 - e'), 0 < e' <
// 2^j / phi < 2^-219. (A.30) with a stiff phi moves the same way, where u then
// lies at least 3 binades above |dy|: the moved Q'' = 2^-j (Q + (2^j - 1) s^2),
// so Q''(s*) < s*^2, and Q''(dy) < 0 puts s* below the moved root r'', where
// the slope's magnitude is at least sqrt(disc''): r'' - s* < s*^2 / sqrt(disc''),
// and |s*| <= u / (1 + phi) + 2 |dy| lies below 0.51 sqrt(disc''), so s* is within
// 4.2 r''^2 / sqrt(disc'') of r'', far below the impact margin's K (1 + 2^-j phi)
// r''^2 / sqrt(disc''). Where these moves bring u, dy, phi and s0 into the fast
// window, the fixed-bound step rounds the moved root 2^k s (or its near value, the
// margin doubled) to r', and r = 2^-k r' is the root's
// rounding wherever r is a finite normal T: the T values and midpoints around r'
// move with it onto those around r (at the least normal value the moved frame's
// lower midpoint lies above T's, so a root above it is above T's too). Otherwise
// empty. For double, the type whose window the report's extreme inputs leave
// (long double's and float128's hold all but the ends of their ranges). Two more
// cases are decided: a moved rounding beyond the largest double means a root at
// or beyond the overflow threshold, which rounds to infinity; and u or dy too
// far below the other for the window. A release's root moves by at most |u|
// when u does (|ds/du| < 1), so its step runs with u = 0; in (A.31), with phi
// (moved) in [2^-240, 2^241], the smaller of u and 2 phi dy lies below 2^-235 of
// the larger, so N and the root move by less than that when it is dropped. In
// (A.30), u > |dy| = g, and with g dropped the root is -u / (1 + phi): the root
// lies between (u + 2 phi g) / (1 + phi) and u / (1 + phi) - 2 phi g^2 / u in
// magnitude (sqrt(a^2 - b) >= a - b / a, a = u + 2 phi g, b = 4 (1 + phi) phi
// g^2), within eps and eps (1 + phi) g / u of it, relatively, eps = 2 phi g / u:
// both below 2^-234 once g (moved) lies below 2^-240 with phi below 2^241 and u
// at binade 237. The margin, doubled, covers each. `which` is the exact case,
// not free flight.
inline std::optional<double> rounded_by_moves(double u, double dy, double phi, contact_case which) {
  using S = scaled<double>;
  constexpr int window = plain_window<double>;
  int u_move = 0, dy_move = 0, phi_move = 0;  // the moves above, before u and dy move by 2^shift
  bool near_value = false;                    // phi moved for (A.31) or (A.30): the moved root is near 2^shift s
  if (which == contact_case::release) {
    dy_move = binade_of(phi) >> 1;  // phi into [1, 4) (a zero phi stays zero)
    phi_move = -2 * dy_move;
  } else if (!in_fast_window(phi, true)) {
    if (which == contact_case::impact && !(phi > 1)) return std::nullopt;  // (a soft one: beside -u)
    near_value = true;
    if (phi > 1) {
      u_move = phi_move = 220 - binade_of(phi);
    } else {
      phi_move = -220 - binade_of(phi);
      dy_move = -phi_move;
    }
  }
  // the larger of |u|, |dy| moved to binade window - 3, so that s0, below
  // 3 max(|u|, |dy|) in every case, stays inside; the smaller must stay inside
  // too (u and dy are not both zero outside free flight), unless it may be dropped
  const int u_binade = u == 0 ? binade_of(dy) + dy_move : binade_of(u) + u_move;
  const int dy_binade = dy == 0 ? u_binade : binade_of(dy) + dy_move;
  const int shift = window - 3 - std::max(u_binade, dy_binade);
  if (near_value && which == contact_case::impact && !(u_binade >= dy_binade + 3)) return std::nullopt;
  const bool u_negligible = (which == contact_case::release || (which == contact_case::contact && phi != 0)) &&
                            u_binade + shift < -window;
  const bool dy_negligible =
      (which == contact_case::contact || which == contact_case::impact) && dy_binade + shift < -window;
  if (std::min(u_binade, dy_binade) + shift < -window && !u_negligible && !dy_negligible) return std::nullopt;
  const double moved_u = u_negligible ? 0.0 : S::shifted(u, shift + u_move);
  const double moved_dy = dy_negligible ? 0.0 : S::shifted(dy, shift + dy_move);
  const double moved_phi = S::shifted(phi, phi_move);
  auto step = step_of_case(which, moved_u, moved_dy, moved_phi);
  // 2^j dy leads at binade window - 3 and phi moved is at least 1, so s0 >= 2^(window - 4),
  // and the margin K |s0| lies far above |u| moved, below 2^(1 - window)
  static_assert(window - 4 + rounded_form::fixed_bounds_of<double>::release > 1 - window);
  static_assert(rounded_form::fixed_bounds_of<double>::contact > -219 + 1);  // K |s0| > 2^-219 |s|
  if (u_negligible || dy_negligible || near_value) step.margin += step.margin;
  const auto moved = rounded_by_step(step);
  if (!moved) return std::nullopt;
  const int binade_back = binade_of(*moved) - shift;
  if (binade_back >= std::numeric_limits<double>::max_exponent) return std::copysign(HUGE_VAL, *moved);
  if (binade_back < std::numeric_limits<double>::min_exponent - 1) return std::nullopt;
  return S::shifted(*moved, -shift);
}

// Everything but double's and float's common cases, out of line so that its
// caller stays small: outside the window where the Newton step is proven
// (invalid input included), or for a type with no proven bound, the value
// beside an input, double's moves into the window, else the wider type's step
// or the exact decision.
template <class T>
[[gnu::noinline]] traced_solution<T> solve_rounded_general(operand<T> u, operand<T> dy, operand<T> phi) {
  if constexpr (rounded_form::has_fixed_bounds<T>) {
    if (inputs_in_fast_window(u, dy, phi)) return rounded_by_fixed_bound<T>(u, dy, phi);
  }
  if (!reject_invalid(u, dy, phi)) {
    const contact_case which = exact_case(u, dy, phi);
    if (which == contact_case::free) return {{T(-u), which}, false};  // (A.29) exact
    if (auto beside = rounded_beside_an_input(u, dy, phi, which)) return {{*beside, which}, false};
    if constexpr (std::is_same_v<T, double>) {
      if (auto moved = rounded_by_moves(u, dy, phi, which)) return {{*moved, which}, false};
    }
  }
  return rounded_beyond_the_step<T>(u, dy, phi, nullptr);
}

// solve_rounded, and whether it needed the exact decision (for the tests and
// the measurements of the slow path's share). Inline, with float's common case:
// a float result returned from a call travels through memory in pieces of
// other sizes, a store-forwarding stall as long as float's whole step.
template <class T>
[[gnu::always_inline]] inline traced_solution<T> solve_rounded_traced(const T& u, const T& dy, const T& phi) {
  static_assert(rounded_available<T>, "solve_rounded: correct rounding is implemented for float, double, "
                                      "long double and float128 only");
  if constexpr (std::is_same_v<T, float>) {
    using std::isfinite;
    solution<float> result{};  // (the exact decision answers invalid input before reading it)
    if (!reject_invalid(u, dy, phi) && rounded_form::round_through_double(u, dy, phi, result)) [[likely]]
      return {result, false};
    return rounded_by_exact_decision<T>(u, dy, phi, isfinite(result.s) ? &result : nullptr);
  } else {
    if constexpr (std::is_same_v<T, double>) {
      if (inside_plain_window(u, dy, phi)) [[likely]] return rounded_by_fixed_bound<T>(u, dy, phi);
    }
    return solve_rounded_general<T>(u, dy, phi);
  }
}

}  // namespace detail

// The exact root of (A.2) rounded to nearest (ties to even) in T, and the exact
// case. Invalid input gives NaN and contact_case::invalid.
template <class T>
solution<T> solve_rounded(const T& u, const T& dy, const T& phi) {
  return detail::solve_rounded_traced(u, dy, phi).result;
}

}  // namespace contact
