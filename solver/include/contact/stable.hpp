// The stable closed form of (A.2).
//
// Each case formula (stable_form) is derived from (A.2) itself (the printed
// summary has misprints, see proofs/README.md) and written so that no step
// subtracts nearly equal numbers. The case is decided exactly (the criteria are
// signs of exact sums), and s is then clamped onto the side of dy that its case
// claims: a rounding can move it at most one ulp, onto dy itself. solve_stable
// runs the formulas in one of three stages (detail::stage, below): plain T where
// no intermediate can overflow or underflow, the same after moving u and dy by
// a power of two, or scaled<T> (exact rescaling at every step). They run the
// same operations on the same significands, so the stage changes speed, never
// the result (barring the final rounding of a result in T's subnormal range).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>

#include "cases.hpp"
#include "detail/float_tools.hpp"
#include "detail/input.hpp"
#include "detail/scaled.hpp"
#include "detail/window.hpp"

namespace contact {
namespace stable_form {

// Each formula below is written once, for a scalar Num and for the batch
// kernel's lanes alike (detail::lane_vector): the kernel runs each case's
// formula on whole vectors (of lanes packed by case, or for the contact, on
// the lanes as they come), as the scalar path runs it on one input.

// A quotient before its one division.
template <class Num>
struct fraction {
  Num numerator, denominator;
};

// The discriminants of (A.30) and (A.32), u^2 + 4 term: term = phi gap (u - gap)
// for the impact, phi dy^2 for the release.
template <class Num>
[[gnu::always_inline]] inline Num discriminant(const Num& u, const Num& term) {
  using detail::fused_multiply_add;
  return fused_multiply_add(u, u, detail::constant<Num, 4>() * term);
}

// (A.30), from the quadratic (A.9) (1+phi) s^2 + (u - 2 phi dy) s + phi dy^2 = 0,
// with gap = -dy >= 0 and u > gap. Its smaller root is wanted; with dy <= 0 and
// u > 0 both summands of the numerator are negative, so the textbook root has no
// cancellation. The discriminant u^2 - 4 phi dy (u + dy) is a sum of
// non-negative terms; u - gap is exact when they are close (Sterbenz).
//
// Compensated: s = -N / D with N = u + 2 phi gap + root and D = 2 (1 + phi).
// Rounded as written, N's three roundings and D's one would each cost up to an
// ulp of s (4.49 ulps found, proofs/witnesses.txt); here N and D are carried
// as exact pairs (two_sum, and the fma that gives phi gap's rounding error),
// and the quotient by D's high part is corrected by its residual. What is
// left is the root's error, at most half of N, and the last rounding: 2.5 ulps
// proven (proofs/gappa/stable_impact.g). The reciprocal of D depends on phi
// alone, so the only division runs beside the square root.
template <class Num>
struct impact_root {
  Num s, square_root;  // (A.30)'s root, and the square root of its discriminant
};

// D = 2 (1 + phi), from 1 + phi as an exact pair
template <class Num>
[[gnu::always_inline]] inline Num impact_denominator(const detail::exact_pair<Num>& one_plus_phi) {
  return detail::constant<Num, 2>() * one_plus_phi.high;
}

// -N / D from N's parts, D and inverse = 1 / D: push = phi gap with its rounding
// error push_error, root = sqrt of the discriminant. `factors` are phi's and
// gap's (detail::factors_of): with a subnormal phi the products with phi are
// formed from normal factors of the same exact products, (phi 2^64) (x 2^-64),
// as a subnormal operand costs a microcode assist; the values are the same.
template <bool phi_is_subnormal, class Num, class Factors>
[[gnu::always_inline]] inline Num impact_quotient(const Num& u, const Num& push, const Num& push_error, const Num& root,
                                                  const detail::exact_pair<Num>& one_plus_phi, const Num& denominator,
                                                  const Num& inverse, const Factors& factors) {
  using detail::fused_multiply_add;
  using detail::two_sum;
  const auto& two = detail::constant<Num, 2>();
  const auto head = two_sum(u, two * push);
  const auto numerator = two_sum(head.high, root);
  const Num numerator_low = numerator.low + (head.low + two * push_error);
  const Num quotient = numerator.high * inverse;
  const Num residual = fused_multiply_add(-quotient, denominator, numerator.high);
  const Num addend = residual + numerator_low;
  const Num correction = [&] {
    // 2 phi q: (2 phi 2^64) (q 2^-64) where phi is subnormal (1 + phi's low part is phi itself)
    if constexpr (phi_is_subnormal) {
      return fused_multiply_add(-Num(quotient * factors.down), Num(two * factors.phi), addend);
    } else {
      return fused_multiply_add(-quotient, Num(one_plus_phi.low + one_plus_phi.low), addend);
    }
  }();
  return -fused_multiply_add(correction, inverse, quotient);
}

// Always inlined, as is impact below: a call from solve_stable's common path
// would save registers around it.
template <bool phi_is_subnormal = false, class Num>
[[gnu::always_inline]] inline impact_root<Num> impact_with_square_root(const Num& u, const Num& gap, const Num& phi) {
  using detail::fused_multiply_add;
  using detail::square_root;
  using detail::two_sum;
  const auto factors = detail::factors_of<phi_is_subnormal>(phi, gap);
  const auto [push, push_error] = detail::two_prod(factors.phi, factors.x);  // phi |dy|
  Num root = square_root(discriminant(u, Num(push * (u - gap))));
  const auto& one = detail::constant<Num, 1>();
  const auto one_plus_phi = two_sum(one, phi);
  const Num denominator = impact_denominator(one_plus_phi);
  const Num inverse = one / denominator;
  return {impact_quotient<phi_is_subnormal>(u, push, push_error, root, one_plus_phi, denominator, inverse, factors),
          std::move(root)};
}

template <bool phi_is_subnormal = false, class Num>
[[gnu::always_inline]] inline Num impact(const Num& u, const Num& gap, const Num& phi) {
  return impact_with_square_root<phi_is_subnormal>(u, gap, phi).s;
}

// (A.31) corrected: (A.18) (1+phi) s + u - 2 phi dy = 0 gives
// s = (2 phi dy - u) / (1 + phi). The numerator cancels as s -> 0; the fma
// leaves it a single rounding. 2 dy, not 2 phi, so that nothing overflows.
// phi_factor dy_factor is phi dy (detail::factors_of).
template <class Num>
[[gnu::always_inline]] inline fraction<Num> contact_fraction(const Num& u, const Num& phi, const Num& phi_factor,
                                                             const Num& dy_factor) {
  using detail::fused_multiply_add;
  return {fused_multiply_add(phi_factor, detail::constant<Num, 2>() * dy_factor, -u), detail::constant<Num, 1>() + phi};
}

template <bool phi_is_subnormal = false, class Num>
Num contact(const Num& u, const Num& dy, const Num& phi) {
  const auto factors = detail::factors_of<phi_is_subnormal>(phi, dy);
  const auto [numerator, denominator] = contact_fraction(u, phi, factors.phi, factors.x);
  return numerator / denominator;
}

// (A.32), from (A.23) corrected: s^2 + u s - phi dy^2 = 0, positive root
// s = (-u + sqrt(u^2 + 4 phi dy^2)) / 2. For u <= 0 nothing cancels: s =
// (root - u) / 2, 2.52 ulps proven (proofs/gappa/stable_release_u_nonpositive.g).
// For u > 0 the sum cancels, so the root is rationalised, s = 2 phi dy^2 /
// (u + root), and compensated: rounded as written, phi dy^2's two roundings,
// u + root's and the quotient's would cost up to 4.78 ulps. Here phi dy^2 is
// the pair st + st_low, u + root an exact pair (two_sum), and the quotient by
// its high part is corrected by the residual; what is left is the root's
// error (the discriminant rounded twice) and the last rounding: 3.0 ulps
// proven (proofs/gappa/stable_release_u_positive.g). Both divide once, by
// release_denominator.

// phi dy^2 = high + low to about 2^-104 of it: high = (phi dy) dy as rounded
// twice, low from phi dy's rounding error (phi_dy_error, two_prod's low part)
// and the product's.
template <class Num>
struct stiffness_pair {
  Num high, low;
};

template <class Num>
[[gnu::always_inline]] inline stiffness_pair<Num> stiffness_of(const Num& phi_dy, const Num& phi_dy_error, const Num& dy) {
  using detail::fused_multiply_add;
  auto product = detail::two_prod(phi_dy, dy);
  return {std::move(product.high), fused_multiply_add(phi_dy_error, dy, product.low)};
}

// The release's parts are selected by the sign of u, not branched on: it is a
// coin toss on physical inputs. The wide types branch (release_with_square_root),
// and take the parts for u > 0 alone where u_is_positive, a compile-time fact.

// The discriminant's term: the pair's sum for u > 0, where the compensation
// needs it; the high part for u <= 0, as proven.
template <bool u_is_positive, class Num>
[[gnu::always_inline]] inline Num release_term(const Num& u, const stiffness_pair<Num>& stiffness) {
  using detail::select;
  if constexpr (u_is_positive) return stiffness.high + stiffness.low;
  else return select(u > Num(0), Num(stiffness.high + stiffness.low), stiffness.high);
}

// The division's operand: u + root (u_plus_root's high part) for u > 0, 2 for u <= 0.
template <bool u_is_positive, class Num>
[[gnu::always_inline]] inline decltype(auto) release_denominator(const Num& u, const detail::exact_pair<Num>& u_plus_root) {
  using detail::select;
  if constexpr (u_is_positive) return (u_plus_root.high);
  else return select(u > Num(0), u_plus_root.high, Num(2));
}

// u > 0: 2 st / (u + root) from q = 2 st inverse, corrected by the residual
// 2 (st + st_low) - q (u + root) (two fmas: q (u + root)'s high part exactly).
template <class Num>
[[gnu::always_inline]] inline Num rationalised_quotient(const stiffness_pair<Num>& stiffness,
                                                        const detail::exact_pair<Num>& u_plus_root, const Num& inverse) {
  using detail::fused_multiply_add;
  const auto& two = detail::constant<Num, 2>();
  const Num twice = two * stiffness.high;
  const Num quotient = twice * inverse;
  const Num residual = fused_multiply_add(-quotient, u_plus_root.high, twice);
  const Num correction = fused_multiply_add(-quotient, u_plus_root.low, Num(residual + two * stiffness.low));
  return fused_multiply_add(correction, inverse, quotient);
}

// u <= 0: (root - u) / 2, as (root - u) half with half = 1/2, the same value.
template <class Num>
[[gnu::always_inline]] inline Num plain_release(const Num& u, const Num& root, const Num& half) {
  return (root - u) * half;
}

// s from its parts, with inverse = 1 / release_denominator(u, u_plus_root).
template <bool u_is_positive, class Num>
[[gnu::always_inline]] inline Num release_quotient(const Num& u, const stiffness_pair<Num>& stiffness, const Num& root,
                                                   const detail::exact_pair<Num>& u_plus_root, const Num& inverse) {
  using detail::select;
  if constexpr (u_is_positive) return rationalised_quotient(stiffness, u_plus_root, inverse);
  else return select(u > Num(0), rationalised_quotient(stiffness, u_plus_root, inverse), plain_release(u, root, inverse));
}

template <class Num>
struct release_root {
  Num s, square_root;  // (A.32)'s root, and the square root of its discriminant
};

template <bool phi_is_subnormal = false, class Num>
[[gnu::always_inline]] inline release_root<Num> release_with_square_root(const Num& u, const Num& dy, const Num& phi) {
  using detail::square_root;
  const auto factors = detail::factors_of<phi_is_subnormal>(phi, dy);  // phi dy, from normal factors
  // The wide types (and scaled<T>) branch: their fma is a library call or an
  // emulation, of which u <= 0 needs none of the compensation's.
  constexpr bool branched = !detail::binary_bits<Num>;
  if constexpr (branched) {
    if (!(u > detail::constant<Num, 0>())) {
      Num root = square_root(discriminant(u, Num(Num(factors.phi * factors.x) * dy)));
      return {plain_release(u, root, detail::constant<Num, 1, 2>()), std::move(root)};
    }
  }
  const auto phi_dy = detail::two_prod(factors.phi, factors.x);
  const auto stiffness = stiffness_of(phi_dy.high, phi_dy.low, dy);
  Num root = square_root(discriminant(u, release_term<branched>(u, stiffness)));
  const auto u_plus_root = detail::two_sum(u, root);
  const Num inverse = detail::constant<Num, 1>() / release_denominator<branched>(u, u_plus_root);
  return {release_quotient<branched>(u, stiffness, root, u_plus_root, inverse), std::move(root)};
}

template <bool phi_is_subnormal = false, class Num>
[[gnu::always_inline]] inline Num release(const Num& u, const Num& dy, const Num& phi) {
  return release_with_square_root<phi_is_subnormal>(u, dy, phi).s;
}

}  // namespace stable_form

namespace detail {

// The sign of the exact sum u + dy - phi dy in plain T, with phi dy as the
// exact pair of two_prod. Out of line: the few inputs that need it pay for
// the call, the common path keeps a small stack frame.
template <class T>
[[gnu::noinline]] auto exact_sum_nonnegative(T u, T dy, T phi) {
  const auto product = two_prod(phi, dy);
  const T terms[4] = {u, dy, -product.high, -product.low};
  return !(leading_component_of_exact_sum(terms) < T(0));
}

// The sign of the exact sum u + dy - phi dy (dy > 0, phi >= 0, u finite) when
// the binades alone tell it, else 0. |x| lies in [2^b, 2^(b+1)) for b =
// binade_of(x), and |phi dy| in [2^(bp + bd), 2^(bp + bd + 2)): a term whose
// least magnitude is 2^lo with lo above every other term's bound 2^hi
// exceeds the other two together (below 2 2^hi <= 2^lo), so its sign is the
// sum's. A zero u or phi is a term that is absent. Otherwise u + dy rounded,
// with b = binade_of(fl(u + dy)) (max_exponent for an infinite one), has the
// sign of the exact u + dy, whose magnitude is at least 2^b - 2^(b-p); where b
// lies above phi dy's bound, that outweighs phi dy (u and dy cancelling, mostly).
template <class T>
  requires detail::hardware_binary<T>
int sign_of_dominant_binade(const T& u, const T& dy, const T& phi) {
  constexpr int absent = std::numeric_limits<int>::min() / 2;  // below every bound, and no sum below overflows
  const int dy_least = binade_of(dy), dy_bound = dy_least + 1;
  const int u_least = u == 0 ? absent : binade_of(u), u_bound = u_least + 1;
  const int product_least = phi == 0 ? absent : binade_of(phi) + dy_least, product_bound = product_least + 2;
  if (u_least > std::max(dy_bound, product_bound)) return u > 0 ? 1 : -1;
  if (dy_least > std::max(u_bound, product_bound)) return 1;
  if (product_least > std::max(u_bound, dy_bound)) return -1;
  const T sum = u + dy;
  if (sum != 0 && binade_of(sum) > product_bound) return sum > 0 ? 1 : -1;
  return 0;
}

// (A.21)'s pre-test: the sign of the exact sum u + dy - phi dy from two
// roundings, where they tell it. With sum = fl(u + dy) and estimate =
// fma(-phi, dy, sum) (phi dy as phi_factor dy_factor, the same exact product),
// the estimate has the sign of the fma's exact value sum - phi dy (rounding
// keeps signs), which differs from the exact sum by sum's rounding error
// alone, at most 2^-p |sum|. So where |estimate| > margin = eps |sum| the
// estimate's sign is the exact one (decision/pretest_margin, which allows for
// the margin's underflow: sum is exact there). Only inputs within about an ulp
// of the boundary are left to the exact sum. The scalar path and both batch
// kernels decide by it. (For cpp_bin_float, whose fma rounds its low-order
// parts once more, the estimate's sign can differ from its exact value's only
// where that is below 2^-2p (|sum| + |phi dy|), far inside the margin.)
template <class T>
struct contact_estimate {
  T estimate, margin;
};

template <class T>
contact_estimate<T> estimate_contact(const T& sum, const T& phi_factor, const T& dy_factor) {
  using std::fabs;
  return {fused_multiply_add(-phi_factor, dy_factor, sum), epsilon<T>() * fabs(sum)};
}

// (A.21) u >= dy (phi - 1), i.e. the exact sum u + dy - phi dy is >= 0, where
// the pre-test tells it: +1, -1, or 0 within the margin.
template <bool phi_is_subnormal = false, class T>
int estimated_contact_sign(const T& u, const T& dy, const T& phi) {
  const auto factors = factors_of<phi_is_subnormal>(phi, dy);  // phi dy, from normal factors (impact_with_square_root)
  const auto [estimate, margin] = estimate_contact(T(u + dy), factors.phi, factors.x);
  if (magnitude_exceeds(estimate, margin)) return estimate > 0 ? 1 : -1;
  return 0;
}

// Otherwise phi dy enters as the exact pair of two_prod, and the sign is that
// of an exact sum.
template <bool plain, class T>
bool stays_in_contact(const T& u, const T& dy, const T& phi) {
  if constexpr (plain) {
    if (const int sign = estimated_contact_sign(u, dy, phi)) return sign > 0;
    return exact_sum_nonnegative(u, dy, phi);
  } else {  // discarded, branches and all, where plain
    // Far from the boundary one term decides, exactly, without sorting the
    // terms. For float and double its binade tells (most inputs here lie
    // outside every phi band, u and dy hundreds of binades apart), before any
    // scaled<T> is built, which saves most of the work on such contact and
    // release inputs. Those it leaves undecided (phi dy rounding up to a power
    // of two among them) go straight to the exact sum.
    auto terms = [&] {
      const scaled<T> dy_s(dy);
      const auto product = exact_product(scaled<T>(phi), dy_s);
      return std::array<scaled<T>, 4>{scaled<T>(u), dy_s, -product[0], -product[1]};
    };
    if constexpr (hardware_binary<T>) {
      if (const int sign = sign_of_dominant_binade(u, dy, phi)) return sign > 0;
      return sign_of_exact_sum(terms()) >= 0;
    } else {
      const auto built = terms();
      if (const int sign = sign_of_dominant_term(built)) return sign > 0;
      return sign_of_exact_sum(built) >= 0;
    }
  }
}

// The exact case of a valid input, by the criteria (A.29)/(A.30) (dy <= 0:
// u <= -dy, an exact comparison) and (A.31)/(A.32) (dy > 0: the exact sign of
// u + dy - phi dy), as the stable path decides them; for the other algorithms,
// whose own arithmetic can round across a boundary.
template <class T>
contact_case exact_case(const T& u, const T& dy, const T& phi) {
  if (dy <= 0) return u <= -dy ? contact_case::free : contact_case::impact;
  const bool contact = safe_window<T>::holds(u, dy, phi) ? stays_in_contact<true>(u, dy, phi) : stays_in_contact<false>(u, dy, phi);
  return contact ? contact_case::contact : contact_case::release;
}

// Whether the (A.32) root rounds to +infinity: whether it lies at or beyond
// the threshold t = max + h, h half the ulp of the largest finite T (at t
// itself the tie goes to the even neighbour, 2^max_exponent). R increases, so
// it does exactly when R(t) <= 0, that is (release: s > dy, (A.23))
// max^2 + 2 h max + h^2 + u max + u h - phi dy^2 <= 0: the sign of an exact
// sum of products, each split into exact pairs on scaled<T>, where nothing
// overflows (the products by powers of two of h are exact).
template <class T>
bool release_root_rounds_to_infinity(const T& u, const T& dy, const T& phi) {
  using S = scaled<T>;
  using std::ldexp;
  const S largest((std::numeric_limits<T>::max)());
  const S half_ulp(ldexp(T(1), std::numeric_limits<T>::max_exponent - precision_of<T>() - 1));
  const S u_s(u), dy_s(dy);
  const auto square = exact_product(largest, largest), linear = exact_product(u_s, largest);
  const auto phi_dy = exact_product(S(phi), dy_s);
  const auto high = exact_product(phi_dy[0], dy_s), low = exact_product(phi_dy[1], dy_s);
  const std::array<S, 11> terms = {square[0], square[1], largest * (half_ulp + half_ulp), half_ulp * half_ulp,
                                   linear[0], linear[1], u_s * half_ulp,
                                   -high[0], -high[1], -low[0], -low[1]};
  return sign_of_exact_sum(terms) <= 0;
}

// The clamps of the stages (below), the neighbours of dy as next_down and next_up
// give them. For float and double a neighbour is one step of dy's bit pattern
// away from zero (from -0 for dy = +0), cheap enough to compute whether or not
// the clamp takes it, so that each clamp is one min or max (min_of, max_of):
// near a rigid or a vanishing barrier the computed root lands on -u or dy
// about half the time, and a branch there is a coin toss. s comes by value and
// moves through, as a copy of an MPFR number allocates.
template <class T>
T clamped_below_nonpositive(T s, const T& dy) {  // dy <= 0: s < dy, else next_down(dy)
  if constexpr (binary_bits<T>) {
    return min_of(s, step_away_from_zero(with_sign_bit(dy)));  // s < dy ? s : below (s < below iff s < dy, or s is below itself)
  } else {
    return s < dy ? std::move(s) : next_down(dy);
  }
}

template <class T>
T clamped_above_positive(T s, const T& dy) {  // dy > 0: s > dy, else next_up(dy)
  if constexpr (binary_bits<T>) {
    return max_of(s, step_away_from_zero(dy));  // s > dy ? s : above (likewise)
  } else {
    return s > dy ? std::move(s) : next_up(dy);
  }
}

// Each case's clamps onto its side of dy.
template <class T>
T impact_clamped(T s, const T& u, const T& dy) {
  // the root lies in (-u, dy): R(-u) = -phi (dy + u)^2 / u < 0 < R(dy) = dy + u;
  // clamping to -u also keeps a root near -DBL_MAX from rounding to -inf
  s = max_of(T(-u), s);  // s < -u ? -u : s
  return clamped_below_nonpositive(std::move(s), dy);
}

template <class T>
T contact_clamped(const T& s, const T& dy) {
  return min_of(dy, s);  // s > dy ? dy : s
}

// (A.29), where dy <= 0 and u <= -dy: s = -u, exact for any finite u.
template <class T>
solution<T> free_flight(const T& u) {
  return {-u, contact_case::free};
}

// Free flight for any valid input: dy <= 0, u <= -dy, u and dy finite, phi in
// [+0, inf). For T (&, not &&: no branch) and for the batch kernel's
// lanes (a mask) alike.
template <class Num>
[[gnu::always_inline]] inline auto free_flight_anywhere(const Num& u, const Num& dy, const Num& phi) {
  const Num zero(0), infinity(std::numeric_limits<scalar_of_t<Num>>::infinity());
  return (dy <= zero) & (u <= -dy) & (dy > -infinity) & (u > -infinity) & (phi >= zero) & (phi < infinity);
}

// Each case's answer: its formula's s, clamped onto the case's side of dy.
template <class T>
solution<T> impact_answer(T s, const T& u, const T& dy) {
  return {impact_clamped(std::move(s), u, dy), contact_case::impact};
}

template <class T>
solution<T> contact_answer(const T& s, const T& dy) {
  return {contact_clamped(s, dy), contact_case::contact};
}

template <class T>
solution<T> release_answer(T s, const T& dy) {
  return {clamped_above_positive(std::move(s), dy), contact_case::release};
}

// The stages of solve_stable. Each gives the same s and case, bit for bit,
// wherever it answers:
//   plain  the case formulas in plain T, for a valid input on which no
//          intermediate can overflow or underflow: the common path;
//   moved  float and double outside the common window: u and dy moved by a
//          power of two to where phi's band leaves room for them, solved as
//          plain solves them, and s moved back;
//   exact  the same formulas on scaled<T>: any other valid input.
// by_safe_window, after exact, sends any input to plain or exact, or answers
// it as invalid.
namespace stage {

// The plain stage: free flight, or the case's formula in plain T and its
// clamp. Always inlined, so that solve_stable's common path holds it whole at
// any optimisation level: its only call is the exact decision's, out of line,
// for the few inputs within about an ulp of the contact/release boundary.
template <class T>
[[gnu::always_inline]] inline solution<T> plain(const T& u, const T& dy, const T& phi) {
  if (dy <= 0) {
    const T gap = -dy;
    if (u <= gap) return free_flight(u);
    return impact_answer(stable_form::impact(u, gap, phi), u, dy);
  }
  if (stays_in_contact<true>(u, dy, phi)) return contact_answer(stable_form::contact(u, dy, phi), dy);
  return release_answer(stable_form::release(u, dy, phi), dy);
}

// The exact stage: plain's cases on scaled<T>, which rounds as T would with
// an unbounded exponent range.
template <class T>
inline solution<T> exact_cases(const T& u, const T& dy, const T& phi) {
  using S = scaled<T>;
  if (dy <= 0) {
    if (u <= -dy) return free_flight(u);
    return impact_answer(stable_form::impact(S(u), S(T(-dy)), S(phi)).value(), u, dy);
  }
  if (stays_in_contact<false>(u, dy, phi)) return contact_answer(stable_form::contact(S(u), S(dy), S(phi)).value(), dy);
  const S root = stable_form::release(S(u), S(dy), S(phi));
  T s = clamped_above_positive(root.value(), dy);
  // A root a few ulps below the threshold of rounding to infinity (the
  // largest T plus half its ulp) can be computed beyond it and round to
  // infinity; the largest T is then the nearer, and only the exact sign of R
  // at the threshold tells. A computed root from 2^(max_exponent + 1) up (a
  // scaled exponent beyond max_exponent + 1) needs no such test: release's
  // error bound, a few ulps, keeps the exact root beyond 2^max_exponent too.
  // With dy the largest T the clamp's next_up(dy) is infinity, and the same
  // test gives the largest T, dy itself, where the root rounds to it
  // (lies_on_its_side admits it there).
  // (Inside the plain window the root is below 2^(2E + 1), far from the largest T.)
  using std::isinf;
  if (isinf(s) && root.exponent <= std::numeric_limits<T>::max_exponent + 1 && !release_root_rounds_to_infinity(u, dy, phi))
    s = (std::numeric_limits<T>::max)();
  return {s, contact_case::release};
}

// The exact stage out of line, as its callers seldom need it; by value, so
// that the moved stage reaches it by a tail call with its arguments in
// registers. For float and double flattened, so that scaled<T>'s operations,
// called a few dozen times, inline into it; not for the multiprecision types,
// whose operations are too large to inline so often.
template <class T>
  requires hardware_binary<T>
[[gnu::noinline, gnu::flatten]] solution<T> exact(T u, T dy, T phi) {
  return exact_cases(u, dy, phi);
}

template <class T>
[[gnu::noinline]] solution<T> exact(T u, T dy, T phi) {
  return exact_cases(u, dy, phi);
}

}  // namespace stage

// Any input: invalid input gets NaN and the case `invalid`; a valid one, the
// plain stage inside safe_window, else the exact stage. The whole of
// solve_stable for the types other than float and double.
template <class T>
solution<T> by_safe_window(const T& u, const T& dy, const T& phi) {
  if (auto invalid = reject_invalid(u, dy, phi)) return *invalid;
  if (safe_window<T>::holds(u, dy, phi)) return stage::plain(u, dy, phi);
  return stage::exact(u, dy, phi);
}

// The moved stage, for float and double. (A.2) is homogeneous in (u, dy):
// s(2^k u, 2^k dy, phi) = 2^k s(u, dy, phi), with the same case. With phi > 0
// finite, finite u and dy move by one exact power of two to where phi's band
// (phi_bands) leaves room for them, the plain formulas solve them, and s moves
// back. There plain T rounds as the unbounded exponent range of scaled<T> does
// (docs/equations.md, section 6), and scaled<T> commutes with powers of two, so
// this is the exact stage's answer wherever s is normal or zero both before and
// after it moves back (the clamps' dy, -u and neighbours of dy scale with it:
// dy is normal whenever its neighbour s is); elsewhere the exact stage rounds
// it once. Each part below that is out of line takes its arguments by value
// and is reached by a tail call, so that the stage's route saves no register
// and spills nothing.
namespace stage {

// The moved stage's exit for phi = 0, phi from the end of the last band up and
// invalid input, out of line, so that it is reached by a tail call.
template <class T>
  requires hardware_binary<T>
[[gnu::noinline]] solution<T> outside_bands(T u, T dy, T phi) {
  return by_safe_window(u, dy, phi);
}

// The cases of u and dy moved into phi's band, free flight answered before:
// plain's formulas. Impact or not, and contact or release, are coin tosses on
// such inputs; early_u and early_dy, the unmoved input where it is normal,
// give the same signs of dy and u + dy sooner than the moved values, which
// come at the end of a chain of integer operations (a branch on them would be
// found mispredicted only at its end). So the two-rounding estimate of the
// early input (which may over- or underflow, so that it only guesses) takes
// the branch early; the pre-test of the moved input, late, only confirms it,
// and almost always does. The few inputs the pre-test leaves undecided get no
// answer here: the caller takes the exact decision out of line, so that this
// path makes no call that values must survive. With phi_is_subnormal, the
// products with phi are formed from normal factors (stable_form::impact_quotient).
template <bool phi_is_subnormal, class T>
inline std::optional<solution<T>> moved_cases(const T& u, const T& dy, const T& phi, const T& early_u,
                                              const T& early_dy) {
  if (early_dy <= 0) return impact_answer(stable_form::impact<phi_is_subnormal>(u, T(-dy), phi), u, dy);
  auto contact = [&] { return contact_answer(stable_form::contact<phi_is_subnormal>(u, dy, phi), dy); };
  auto release = [&] { return release_answer(stable_form::release<phi_is_subnormal>(u, dy, phi), dy); };
  const auto factors = factors_of<phi_is_subnormal>(phi, early_dy);  // early = moved where phi is subnormal
  const bool likely_contact = fused_multiply_add(-factors.phi, factors.x, T(early_u + early_dy)) > 0;
  const int sign = estimated_contact_sign<phi_is_subnormal>(u, dy, phi);
  if (likely_contact) {
    if (sign > 0) [[likely]] return contact();
  } else {
    if (sign < 0) [[likely]] return release();
  }
  if (sign > 0) return contact();
  if (sign < 0) return release();
  return std::nullopt;
}

// A moved s, normal, whose move back underflows: the exact stage's s, which
// rounds the same significand once into T's subnormals (scaled<T>::value()),
// and then clamps it onto its case's side of dy. The clamps in the moved frame
// change nothing here: each moves s toward a bound that moves with it, and
// rounding keeps the order of s and that bound.
template <class T>
[[gnu::noinline]] solution<T> move_back_below_normal(T moved_s, contact_case which, T u, T dy, int shift) {
  const T s = scaled<T>::shifted(moved_s, -shift);
  switch (which) {
    case contact_case::impact: return impact_answer(s, u, dy);
    case contact_case::contact: return contact_answer(s, dy);
    default: return release_answer(s, dy);  // release (free flight is answered unmoved)
  }
}

// The answer for u and dy moved by 2^shift (moved_s and which), moved back. Its
// parts come as scalars, not as a solution<T>, so that they stay in registers.
template <class T>
[[gnu::always_inline]] inline solution<T> move_back(const T& moved_s, contact_case which, T u, T dy, T phi, int shift) {
  using layout = binary_layout<T>;
  using bits = typename layout::bits;
  const bits offset = bits(shift) << layout::significand_bits;
  const bits s_magnitude = std::bit_cast<bits>(moved_s) & ~layout::sign;
  if (s_magnitude == 0) return {moved_s, which};
  // s normal both before and after the move: the exponent field moves, exactly
  // (a move beyond either end wraps or reaches the sign bit, which is_normal
  // refuses). The bands bound the intermediates, not the final division, so s
  // itself is checked too, and before the move from above the least normal
  // binade (impact's quotient, just below s, must be normal); no test input has
  // made it fail, hence one branch for both tests.
  const bool inside_normal = layout::is_normal_above_least_binade(s_magnitude);
  const bool moved_normal = layout::is_normal(bits(s_magnitude - offset));
  const int moved_binade = int(s_magnitude >> layout::significand_bits) - layout::bias - shift;
  // Only a release root overflows (|s| < max(|u|, |dy|) in the other cases).
  // From 2^(max_exponent + 1) up, the exact stage's s is infinite too, and its
  // root, a few ulps from s, lies beyond the largest T: it keeps the infinity.
  // A select, not a branch: the test would wait for the root, and on inputs
  // of the whole range many release roots overflow.
  const bool overflows = moved_binade > std::numeric_limits<T>::max_exponent;
  if (inside_normal & (moved_normal | overflows)) [[likely]]
    return {select(moved_normal, std::bit_cast<T>(bits(std::bit_cast<bits>(moved_s) - offset)), std::numeric_limits<T>::infinity()),
            which};
  // s subnormal or zero once moved back (u or dy subnormal, mostly): one
  // rounding of the moved s, as the exact stage makes; in the binade just
  // beyond the largest T, or where the moved s is not normal, the exact stage decides
  if (inside_normal & (moved_binade < std::numeric_limits<T>::min_exponent - 1))
    return move_back_below_normal(moved_s, which, u, dy, shift);
  return exact(u, dy, phi);
}

// An input the pre-test left undecided: plain's exact decision, out of line.
template <class T>
[[gnu::noinline, gnu::flatten]] solution<T> moved_exactly(T moved_u, T moved_dy, T u, T dy, T phi, int shift) {
  const auto inside = plain(moved_u, moved_dy, phi);
  return move_back(inside.s, inside.which, u, dy, phi, shift);
}

// A subnormal phi (the first band), out of line, as few inputs have one. The
// moved u and dy, normal, stand for the unmoved ones too. The pre-test always
// decides here: with dy > 0 in binade e, a non-zero u + dy is a multiple of
// 2^(e - p) (u near -dy lies in dy's binade or the one below), so
// |fl(u + dy)| >= 2^(e - p), while phi dy < 2^(emin + e + 1) lies below
// 2^(-p - 2) of it: the estimate is fl(u + dy) within far less than the
// margin's eps |fl(u + dy)| of it; and where u + dy = 0 the margin is 0 and
// the estimate -phi dy, normal in the band, is not. (Were it ever undecided,
// its NaN would take move_back to the exact stage, which would answer.)
template <class T>
[[gnu::noinline]] solution<T> moved_subnormal_phi(T moved_u, T moved_dy, T u, T dy, T phi, int shift) {
  const solution<T> inside = moved_cases<true>(moved_u, moved_dy, phi, moved_u, moved_dy)
                                 .value_or(solution<T>{std::numeric_limits<T>::quiet_NaN(), contact_case::invalid});
  return move_back(inside.s, inside.which, u, dy, phi, shift);
}

// The move itself, from the binades of the larger and the smaller non-zero one
// of |u| and |dy| on; both_normal: u and dy are normal, and move on their bits.
template <bool both_normal, class T>
[[gnu::always_inline]] inline solution<T> in_band(T u, T dy, T phi, int larger, int smaller) {
  using layout = binary_layout<T>;
  using bits = typename layout::bits;
  const auto band = phi_bands<T>::of_phi(phi);
  const int shift = band.top - 1 - larger;  // the larger of |u|, |dy| into [2^(top-1), 2^top)
  // u and dy too far apart for the band: valid, and outside safe_window (a band
  // holds all of it), so the exact stage. An impact (dy <= 0 once free flight
  // is answered) has a room of its own, as u is the larger: gap may lie far
  // lower (a select: the case is a coin toss).
  static_assert(phi_bands<T>::holds_safe_window);
  // (and where phi is subnormal, gap 2^-64 stays exact: detail::subnormal_phi_factors)
  static_assert(phi_bands<T>::table[0].impact_lowest - 64 >= std::numeric_limits<T>::min_exponent);
  if (smaller + shift < select(dy <= 0, band.impact_lowest, band.lowest)) return exact(u, dy, phi);
  // the band puts both in its normal binades: for normal u and dy the move is exact on the exponent field
  const bits offset = bits(shift) << layout::significand_bits;
  const T moved_u = both_normal ? std::bit_cast<T>(bits(std::bit_cast<bits>(u) + offset)) : scaled<T>::shifted(u, shift);
  const T moved_dy = both_normal ? std::bit_cast<T>(bits(std::bit_cast<bits>(dy) + offset)) : scaled<T>::shifted(dy, shift);
  if (is_positive_subnormal(phi)) [[unlikely]] return moved_subnormal_phi(moved_u, moved_dy, u, dy, phi, shift);
  // a subnormal u or dy would cost the early estimate a microcode assist; the moved ones are normal
  const auto inside = moved_cases<false>(moved_u, moved_dy, phi, both_normal ? u : moved_u, both_normal ? dy : moved_dy);
  if (!inside) [[unlikely]] return moved_exactly(moved_u, moved_dy, u, dy, phi, shift);
  return move_back(inside->s, inside->which, u, dy, phi, shift);
}

// Zeros and subnormals (infinities and NaN go on), out of line, so that the
// route of normal inputs makes no call but tail calls.
template <class T>
[[gnu::noinline]] solution<T> moved_not_normal(T u, T dy, T phi) {
  using layout = binary_layout<T>;
  using bits = typename layout::bits;
  constexpr bits infinite = std::bit_cast<bits>(std::numeric_limits<T>::infinity());
  const bits u_magnitude = std::bit_cast<bits>(u) & ~layout::sign, dy_magnitude = std::bit_cast<bits>(dy) & ~layout::sign;
  if (u_magnitude >= infinite || dy_magnitude >= infinite) return by_safe_window(u, dy, phi);
  // (u and dy both zero is free flight, answered before)
  const int u_binade = u_magnitude == 0 ? binade_of(dy) : binade_of(u);
  const int dy_binade = dy_magnitude == 0 ? u_binade : binade_of(dy);
  return in_band<false>(u, dy, phi, std::max(u_binade, dy_binade), std::min(u_binade, dy_binade));
}

// The moved stage's entry. Free flight needs no arithmetic, hence no band: it
// is answered first, for any finite u and dy and valid phi (the answer
// by_safe_window gives them), before the tests of phi and of zeros and
// subnormals that it does not need (also for u and dy too far apart for any
// band). One branch: the sign of dy is a coin toss. (phi = -0 is valid and
// passes, as phi >= 0.) phi = 0 stays with by_safe_window: there scaled<T>'s
// fma returns -u itself for s = -u = 0, a zero of the other sign than plain
// T's fma gives.
template <class T>
  requires hardware_binary<T>
[[gnu::noinline, gnu::flatten]] solution<T> moved(T u, T dy, T phi) {
  using layout = binary_layout<T>;
  using bits = typename layout::bits;
  if (free_flight_anywhere(u, dy, phi)) return free_flight(u);
  if (!(phi > 0) || !(phi < phi_bands<T>::end)) return outside_bands(u, dy, phi);
  const bits u_magnitude = std::bit_cast<bits>(u) & ~layout::sign, dy_magnitude = std::bit_cast<bits>(dy) & ~layout::sign;
  if (!(layout::is_normal(u_magnitude) && layout::is_normal(dy_magnitude))) [[unlikely]]
    return moved_not_normal(u, dy, phi);
  // max and min by arithmetic, as a compiler may turn std::max into a branch
  // here, and which of u, dy is larger is a coin toss
  const int u_binade = int(u_magnitude >> layout::significand_bits) - layout::bias;
  const int dy_binade = int(dy_magnitude >> layout::significand_bits) - layout::bias;
  const int spread = std::abs(u_binade - dy_binade);
  const int larger = (u_binade + dy_binade + spread) / 2;
  return in_band<true>(u, dy, phi, larger, larger - spread);
}

}  // namespace stage

}  // namespace detail

// Always inlined, with the plain stage, so that the common path runs in the
// caller itself at any optimisation level; the other stages are calls.
template <class T>
[[gnu::always_inline]] inline solution<T> solve_stable(const T& u, const T& dy, const T& phi) {
  if constexpr (detail::hardware_binary<T>) {
    // the common input, tested on its bits: valid, non-zero, well inside the plain window
    if (detail::inside_common_window(u, dy, phi)) [[likely]] return detail::stage::plain(u, dy, phi);
    return detail::stage::moved(u, dy, phi);
  } else {
    return detail::by_safe_window(u, dy, phi);
  }
}

}  // namespace contact
