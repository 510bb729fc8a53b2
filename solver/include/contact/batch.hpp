// contact::solve_batch: the stable closed form of (A.2) over arrays.
//
// Same results as the scalar stable path, bit for bit: every lane gets exactly
// the s and the case that contact::solve_stable gives for it. Lanes whose
// u, dy and phi all lie inside detail::safe_window<T> (the scalar path's plain-T
// window, which holds every physically meaningful input) are solved without a
// branch: every lane evaluates the operations of all four cases, in the same
// order and with the same fma as stable.hpp, and selects its own result with
// masks, so the compiler vectorises the loop. A block (or, with AVX-512, a
// vector of 8 lanes) with lanes outside that window runs again rescaled: u
// and dy move by one power of two to where phi's band leaves them room and s
// moves back, exactly (the homogeneity and the bands that solve_stable uses
// outside its plain window). The lanes that even that cannot answer (phi in
// no band: phi >= 2^1021 in double, 2^125 in float; subnormal phi in float;
// zero or subnormal u or dy; u and dy too far apart for the band; a subnormal
// or overflowing s; NaN, infinity, phi <= 0) are solved by the scalar
// contact::solve_stable.
//
// The exact criterion of (A.21), u + dy - phi dy >= 0, is decided as
// stable.hpp decides it: its pre-test (detail::estimate_contact, an fma
// against a proven margin) decides every lane whose sum is not within about
// an ulp of 0; the lanes it cannot decide (u within about an ulp of
// dy (phi - 1)) take the same exact expansion (two_prod, then Shewchuk's
// grow-expansion), in vector code, on the vectors that hold one.
//
// Vectorisation needs an fma instruction (x86-64-v3: -march=x86-64-v3 or
// -mfma) and -fno-math-errno (so that sqrt is an instruction without an errno
// branch). Without them the results are the same and the loop is scalar.
// Compile with -ffp-contract=off (or without fma hardware) so that the
// compiler fuses neither this loop nor stable.hpp differently.
#pragma once

#include <Eigen/Core>

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "stable.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#if defined(__GNUC__)
#define CONTACT_BATCH_INLINE inline __attribute__((always_inline))
#else
#define CONTACT_BATCH_INLINE inline
#endif

namespace contact {
namespace batch_detail {

template <class T>
inline constexpr bool has_lane_kernel = detail::hardware_binary<T>;

template <class T>
using bits_t = typename detail::binary_layout<T>::bits;

// Lanes solved per block; the scalar fix-up of out-of-window lanes happens per block.
inline constexpr std::ptrdiff_t block = 256;

// Lane masks: all ones for true, all zeros for false, as unsigned integers of
// T's width. Conditions are combined with &, | and ~ on masks (not && and || on
// bool), so the loop has no control flow and the compiler keeps masks in
// vector registers.
template <class T>
CONTACT_BATCH_INLINE bits_t<T> mask(bool c) {
  return bits_t<T>(0) - bits_t<T>(c);
}

// m ? a : b, as a blend of bit patterns: both operands are always computed, so
// the compiler neither moves their arithmetic into a branch nor needs to
// prove that it cannot trap (which -ftrapping-math, the default, forbids).
template <class T>
CONTACT_BATCH_INLINE T pick(bits_t<T> m, T a, T b) {
  using U = bits_t<T>;
  return std::bit_cast<T>(U((std::bit_cast<U>(a) & m) | (std::bit_cast<U>(b) & ~m)));
}

// The lane can take the branch-free path: u, dy and phi lie in the common
// window (detail::common_window<T>: normal, phi > 0), inside detail::safe_window<T>, so the scalar path runs the
// same plain-T operations on these lanes; NaN, infinity, zero, phi < 0 and the
// extreme magnitudes all go to the rescaled pass and the scalar fix-up.
template <class T>
CONTACT_BATCH_INLINE bits_t<T> inside_window(T abs_u, T abs_dy, T phi) {
  return mask<T>(detail::common_window_offsets(abs_u, abs_dy, phi) < detail::common_window_width<T>);
}

// Out-of-window lanes: (A.2) is homogeneous in (u, dy), so u and dy may move
// by one power of two and s back at the end, as solve_stable does outside its
// plain window: by phi's band (detail::phi_bands), the larger of |u| and |dy|
// into [2^(top-1), 2^top), taken only if the smaller then lies at or above
// 2^lowest. Inside that box no intermediate of the plain formulas over- or
// underflows (docs/equations.md, section 6; proofs/gappa/window/), so the
// plain-T lane computes what scaled<T> would, whichever power of two moved it.
// The shift is added to the bit patterns (in units of the exponent field),
// which is exact for normal u and dy landing on normal values. Zero,
// subnormal, infinite and NaN u or dy fail both_normal and, like phi in no
// band and a subnormal or overflowing s, go to the scalar path.
template <class T>
inline constexpr bits_t<T> significand_mask = (bits_t<T>(1) << detail::binary_layout<T>::significand_bits) - 1;

template <class T>
inline constexpr bits_t<T> sign_mask = detail::binary_layout<T>::sign;

template <class T>
CONTACT_BATCH_INLINE bits_t<T> both_normal(bits_t<T> u_bits, bits_t<T> dy_bits) {
  using layout = detail::binary_layout<T>;
  return mask<T>(layout::is_normal(u_bits & ~sign_mask<T>)) & mask<T>(layout::is_normal(dy_bits & ~sign_mask<T>));
}

// phi_bands<T>' table in the units the lane works in: the band's index read
// off phi's exponent field, and per band the bits of 2^(top-1) and the room
// top - 1 - lowest (how many binades the smaller of |u|, |dy| may lie below
// the larger), both in units of the exponent field, so that the lane looks
// them up and compares without converting binades.
template <class T>
struct band_moves {
  using U = bits_t<T>;
  using bands = detail::phi_bands<T>;
  static constexpr int significand_bits = detail::binary_layout<T>::significand_bits;
  static constexpr int bias = detail::binary_layout<T>::bias;

  // band = (field + index_offset) >> band_bits, with field - bias the binade of a normal phi
  static constexpr int index_offset = -bias - bands::least_binade;
  static_assert(index_offset >= 0);
  static_assert(((int(std::bit_cast<U>(std::numeric_limits<T>::infinity()) >> significand_bits) + index_offset) >>
                 bands::band_bits) < bands::count,
                "any phi without its sign bit indexes the table; the phi test below refuses phi from bands::end up");
  static_assert([] {
    for (const auto& b : bands::table)
      if (b.top - 1 < b.lowest) return false;
    return true;
  }(), "every band has room (an unsigned room below zero would admit any spread)");

  // A subnormal phi's field (0) reads as binade -bias, which names the band of
  // every subnormal binade only if they all share a band: in double they do,
  // in float they straddle two, and subnormal phi goes to the scalar path.
  static constexpr bool subnormal_phi_in_one_band = ((-bias - bands::least_binade) >> bands::band_bits) == 0;
  static constexpr U phi_least = subnormal_phi_in_one_band ? U(1) : detail::binary_layout<T>::least_normal;
  static constexpr U phi_end = std::bit_cast<U>(bands::end);  // phi from here up is in no band

  static constexpr std::array<U, bands::count> top_binade = [] {  // bits(2^(top-1))
    std::array<U, bands::count> fields{};
    for (int j = 0; j < bands::count; ++j) fields[j] = U(bias + bands::table[j].top - 1) << significand_bits;
    return fields;
  }();
  static constexpr std::array<U, bands::count> room = [] {
    std::array<U, bands::count> rooms{};
    for (int j = 0; j < bands::count; ++j)
      rooms[j] = U(bands::table[j].top - 1 - bands::table[j].lowest) << significand_bits;
    return rooms;
  }();
};

// The shift (to add to the bit patterns of u and dy) by phi's band; `fits` is
// all ones where the lane may take it: u and dy normal, phi in (0, bands::end),
// and the binades of |u| and |dy| within the band's room.
// The table lookups are gathers (or a load per lane), never a branch.
template <class T>
CONTACT_BATCH_INLINE bits_t<T> band_rescaling(bits_t<T> u_bits, bits_t<T> dy_bits, bits_t<T> phi_bits, bits_t<T>& fits) {
  using U = bits_t<T>;
  using moves = band_moves<T>;
  const U abs_u = u_bits & ~sign_mask<T>, abs_dy = dy_bits & ~sign_mask<T>;
  const U larger_binade = (abs_u > abs_dy ? abs_u : abs_dy) & ~significand_mask<T>;
  const U smaller_binade = (abs_u > abs_dy ? abs_dy : abs_u) & ~significand_mask<T>;
  const U band =
      U(((phi_bits & ~sign_mask<T>) >> moves::significand_bits) + moves::index_offset) >> detail::phi_bands<T>::band_bits;
  const U phi_in_a_band = mask<T>(U(phi_bits - moves::phi_least) < U(moves::phi_end - moves::phi_least));
  fits = both_normal<T>(u_bits, dy_bits) & phi_in_a_band & mask<T>(U(larger_binade - smaller_binade) <= moves::room[band]);
  return U(moves::top_binade[band] - larger_binade);
}

// s moved back by the shift: exact where s is 0 or normal both before and
// after the move (before it, above the least normal binade, as solve_stable's
// moved_back asks); `normal` is all ones there, else zero. The band boxes bound
// the intermediates, not s: a subnormal s rounded where scaled<T> would not
// (and an infinite one has no exponent to move), so, as in solve_stable, the
// scalar path rounds those once.
template <class T>
CONTACT_BATCH_INLINE T scaled_back(T s, bits_t<T> shift, bits_t<T>& normal) {
  using U = bits_t<T>;
  const U s_bits = std::bit_cast<U>(s);
  const U abs_s = s_bits & ~sign_mask<T>;
  const U is_zero = mask<T>(abs_s == 0);
  using layout = detail::binary_layout<T>;
  normal = (mask<T>(layout::is_normal_above_least_binade(abs_s)) & mask<T>(layout::is_normal(U(abs_s - shift)))) | is_zero;
  return std::bit_cast<T>(U(s_bits - (shift & ~is_zero)));
}

// A subnormal phi (double only: float's subnormal phi stays on the scalar
// path) as an operand of a product costs a microcode assist on many cores,
// about as much as the rest of the rescaled pass. Its products are formed from
// detail::normal_factors_of's (phi 2^64) (dy 2^-64) instead, as the band route
// of solve_stable forms them; dy 2^-64 is exact, as phi's band (the first) has
// |dy| >= 2^lowest = 2^104 there.
template <class T>
CONTACT_BATCH_INLINE detail::normal_factors<T> product_factors(T phi, T dy) {
  if constexpr (band_moves<T>::subnormal_phi_in_one_band) {
    static_assert(detail::phi_bands<T>::table[0].lowest - 64 >= std::numeric_limits<T>::min_exponent);
    return detail::normal_factors_of(phi, dy);
  } else {
    return detail::factors_of<false>(phi, dy);
  }
}

// One lane of the branch-free path. Returns all ones if s and which are
// solve_stable's, and zero if the lane must be redone: it lies outside the
// vector window (with `rescaled`: u and dy cannot move into phi's band box, or
// s cannot move back), or, without `exact_decision`, (A.21)'s exact sum is so
// close to 0 that the pre-test below cannot tell its sign; those lanes, and only
// those, are also marked `undecided`, for a pass with `exact_decision`.
// With `rescaled`, u and dy first move by phi's band, and s back at the end.
template <bool rescaled, bool exact_decision = false, class T>
CONTACT_BATCH_INLINE bits_t<T> lane(T u_in, T dy_in, T phi, T& s_out, std::make_signed_t<bits_t<T>>& which_out,
                                    bits_t<T>& undecided) {
  using U = bits_t<T>;
  const U u_bits = std::bit_cast<U>(u_in), dy_bits = std::bit_cast<U>(dy_in);
  U inside, shift = 0;  // inside: the plain formulas are safe on the lane's (moved) operands
  if constexpr (rescaled) shift = band_rescaling<T>(u_bits, dy_bits, std::bit_cast<U>(phi), inside);
  const T u = std::bit_cast<T>(U(u_bits + shift)), dy = std::bit_cast<T>(U(dy_bits + shift));
  if constexpr (!rescaled) inside = inside_window(std::fabs(u), std::fabs(dy), phi);
  const U no_contact_before = mask<T>(dy <= 0);
  // phi's two products with dy, phi |dy| and phi (2 dy), as phi_factor times
  // dy_factor: the same exact products, so the same roundings.
  const auto factors = rescaled ? product_factors(phi, dy) : detail::factors_of<false>(phi, dy);
  const T phi_factor = factors.phi, dy_factor = factors.x;

  // Both square roots in one: (A.30) impact has stable_form::impact's
  // discriminant u^2 + 4 (phi gap) (u - gap), (A.32) release has
  // stable_form::release's u^2 + 4 ((phi dy) dy); the same roundings on the
  // lane's own operands. gap = -dy = |dy| on the lanes of (A.30), so phi gap
  // and phi dy are both phi |dy|, and u - gap is the same sum as u + dy.
  const T a = u + dy;
  const T x = phi_factor * std::fabs(dy_factor);         // impact: push = phi gap; release: phi dy
  const T z = x * pick(no_contact_before, a, dy);        // impact: push (u - gap); release: phi dy^2
  const T root = std::sqrt(std::fma(u, u, T(4) * z));

  // (A.21) stays in contact iff u + dy - phi dy >= 0 exactly: solve_stable's
  // pre-test (detail::estimate_contact) decides the lanes outside its margin.
  // The lanes it cannot decide, near the boundary, fail the passes without
  // `exact_decision`; a pass with it decides them by the exact sum, as
  // solve_stable does (phi dy as two_prod's exact pair; in the window and the
  // phi bands neither its low part nor a partial sum under- or overflows,
  // proofs/gappa/window/pretest.g.in). It runs only on blocks that need it:
  // the exact sum costs about as much as the rest of the lane.
  const auto [estimate, margin] = detail::estimate_contact(a, phi_factor, dy_factor);
  const U decided = mask<T>(std::fabs(estimate) > margin);
  U stays = mask<T>(estimate > 0);
  if constexpr (exact_decision) {
    const auto phi_dy = detail::two_prod(phi_factor, dy_factor);
    const T terms[4] = {u, dy, T(-phi_dy.high), T(-phi_dy.low)};
    stays = (decided & stays) | (~decided & mask<T>(!(detail::leading_component_of_exact_sum(terms) < 0)));
  }

  // The case masks, each from its own comparison where it can (fewer
  // instructions than ~ on masks). u <= gap is a <= 0: u + dy rounds to a number of its sign
  // (a sum is exact where it is subnormal, so it rounds to 0 only if it is 0).
  const U contact_before = mask<T>(dy > 0);
  const U is_free = no_contact_before & mask<T>(a <= 0);
  const U is_impact = no_contact_before & mask<T>(!(a <= 0));
  const U is_contact = contact_before & stays;
  const U is_release = contact_before ^ is_contact;

  // One division per lane: numerator and denominator of the lane's case, and
  // for impact the reciprocal of its denominator, which stable_form::impact's
  // compensated quotient takes (the same operations in the same order).
  const U rationalised = mask<T>(u > 0);
  const auto one_plus_phi = detail::two_sum(T(1), phi);
  const T impact_denominator = T(2) * one_plus_phi.high;
  T numerator = pick(rationalised, T(T(2) * z), T(root - u));  // release
  T denominator = pick(rationalised, T(u + root), T(2));
  numerator = pick(is_contact, std::fma(phi_factor, T(2) * dy_factor, -u), numerator);
  denominator = pick(is_contact, one_plus_phi.high, denominator);
  numerator = pick(is_impact, T(1), numerator);
  denominator = pick(is_impact, impact_denominator, denominator);
  const T quotient_or_inverse = numerator / denominator;
  const T push_error = std::fma(phi_factor, std::fabs(dy_factor), -x);
  const auto head = detail::two_sum(u, T(T(2) * x));
  const auto impact_numerator = detail::two_sum(head.high, root);
  const T numerator_low = impact_numerator.low + T(head.low + T(2) * push_error);
  const T inverse = quotient_or_inverse;
  const T quotient = impact_numerator.high * inverse;
  const T residual = std::fma(-quotient, impact_denominator, impact_numerator.high);
  // stable_form::impact's products with a subnormal phi from normal factors:
  // 2 phi q as (2 phi 2^64) (q 2^-64), phi 2^64 being phi_factor
  const T twice_low = pick(mask<T>(factors.moved), T(T(2) * phi_factor), T(one_plus_phi.low + one_plus_phi.low));
  const T correction = std::fma(-T(quotient * factors.down), twice_low, T(residual + numerator_low));
  T s = pick(is_impact, T(-std::fma(correction, inverse, quotient)), quotient_or_inverse);

  // The clamps of solve_stable, as one interval per case: [-u, next_down(dy)]
  // for impact (-u < dy there, so the order of solve_stable's two tests does
  // not matter), (-inf, dy] for contact, [next_up(dy), inf) for release. dy is
  // normal and not 0, so both neighbours are one step of its bits away from 0.
  constexpr T infinity = std::numeric_limits<T>::infinity();
  const T away_from_zero = std::bit_cast<T>(U(std::bit_cast<U>(dy) + 1));
  const T lower = pick(is_impact, T(-u), pick(is_release, away_from_zero, T(-infinity)));
  const T upper = pick(is_impact, away_from_zero, pick(is_contact, dy, infinity));
  s = s < lower ? lower : s;
  s = s > upper ? upper : s;
  s = pick(is_free, T(-u), s);  // (A.29): -u, as -u / 1 rounds, with no clamp

  U s_back_normal = ~U(0);
  s_out = rescaled ? scaled_back(s, shift, s_back_normal) : s;
  // the case number 1 + [impact] + 2 [dy > 0] + [release]; a true mask is -1
  using S = std::make_signed_t<U>;
  which_out = S(1) - S(is_impact) - S(2) * S(contact_before) - S(is_release);
  const U answerable = inside & s_back_normal;
  undecided = answerable & contact_before & ~decided;
  return answerable & (exact_decision ? ~U(0) : (no_contact_before | decided));
}

// The scalar path for lane i, where the vector path cannot answer.
template <class T>
void solve_scalar_lane(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t i) {
  const solution<T> r = solve_stable(u[i], dy[i], phi[i]);
  s[i] = r.s;
  which[i] = static_cast<int>(r.which);
}

// A block with lanes outside the window or undecided: every lane again,
// rescaled (the lanes inside give the same s, by homogeneity, as the plain-T
// rounding there is that of an unbounded exponent range), once more with the
// exact decision if lanes near the contact boundary are left (a lane solved
// by two passes gets the same answer from both; if the first pass already left
// lanes undecided, only this one runs), and the scalar path for the lanes that
// even these cannot answer.
template <class T>
[[gnu::noinline]] void solve_block_rescaled(const T* __restrict u, const T* __restrict dy, const T* __restrict phi,
                                            T* __restrict s, int* __restrict which, std::ptrdiff_t start,
                                            std::ptrdiff_t count, bool undecided_inside) {
  using case_number = std::make_signed_t<bits_t<T>>;
  case_number cases[block];
  bits_t<T> solved[block], undecided[block];
  // lanes inside the window that the pre-test left undecided need the exact
  // pass whatever the rescaled pass finds: it runs at once, without the other
  bits_t<T> any_undecided = bits_t<T>(undecided_inside);
  if (!undecided_inside)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
      solved[i] = lane<true>(u[start + i], dy[start + i], phi[start + i], s[start + i], cases[i], undecided[i]);
      any_undecided |= undecided[i];
    }
  if (any_undecided != 0)
    for (std::ptrdiff_t i = 0; i < count; ++i)
      solved[i] = lane<true, true>(u[start + i], dy[start + i], phi[start + i], s[start + i], cases[i], undecided[i]);
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    which[start + i] = static_cast<int>(cases[i]);
    if (!solved[i]) solve_scalar_lane(u, dy, phi, s, which, start + i);
  }
}

template <class T>
void solve_lanes(const T* __restrict u, const T* __restrict dy, const T* __restrict phi, T* __restrict s,
                 int* __restrict which, std::ptrdiff_t n) {
  // The case numbers first go to a block-sized buffer of T's width, so that
  // the solving loop works on one vector width only (mixing int with double
  // would make the compiler solve two vectors at once and run out of registers).
  using case_number = std::make_signed_t<bits_t<T>>;
  case_number cases[block];
  for (std::ptrdiff_t start = 0; start < n; start += block) {
    const std::ptrdiff_t count = start + block < n ? block : n - start;
    bits_t<T> all_solved = ~bits_t<T>(0), any_undecided = 0;
    for (std::ptrdiff_t i = 0; i < count; ++i) {
      bits_t<T> undecided;
      all_solved &= lane<false>(u[start + i], dy[start + i], phi[start + i], s[start + i], cases[i], undecided);
      any_undecided |= undecided;
    }
    for (std::ptrdiff_t i = 0; i < count; ++i) which[start + i] = static_cast<int>(cases[i]);
    if (all_solved != ~bits_t<T>(0)) [[unlikely]]
      solve_block_rescaled(u, dy, phi, s, which, start, count, any_undecided != 0);
  }
}

#if defined(__AVX512F__)
// lane()'s terms, case tests, formulas and clamps on eight lanes: the one
// place they are written for the two AVX-512 passes. The contact
// numerator's product takes phi_factor dy_factor, which is phi dy (the
// rescaled pass splits a subnormal phi, as product_factors does).
struct eight_terms {
  __m512d a, x, z, root;
  __mmask8 no_contact_before;
};

// The terms up to the square root: a = u + dy, x = phi |dy|, z as lane()'s.
CONTACT_BATCH_INLINE eight_terms first_terms(__m512d u, __m512d dy, __m512d phi_factor, __m512d dy_factor) {
  eight_terms t;
  t.no_contact_before = _mm512_cmp_pd_mask(dy, _mm512_setzero_pd(), _CMP_LE_OQ);
  t.a = _mm512_add_pd(u, dy);
  t.x = _mm512_mul_pd(phi_factor, _mm512_andnot_pd(_mm512_set1_pd(-0.0), dy_factor));
  t.z = _mm512_mul_pd(t.x, _mm512_mask_blend_pd(t.no_contact_before, dy, t.a));
  t.root = _mm512_sqrt_pd(_mm512_fmadd_pd(u, u, _mm512_mul_pd(_mm512_set1_pd(4.0), t.z)));
  return t;
}

// (A.21)'s decision on eight lanes: detail::estimate_contact's pre-test,
// fma(-phi dy, u + dy) against eps |u + dy|, and `stays` = estimate > 0 where
// it decides.
struct eight_decision {
  __mmask8 contact_before, decided, stays;
};

CONTACT_BATCH_INLINE eight_decision pretest_eight(__m512d dy, __m512d phi_factor, __m512d dy_factor,
                                                  const eight_terms& terms) {
  const __m512d zero = _mm512_setzero_pd(), sign_bit = _mm512_set1_pd(-0.0);
  // fnmadd: -(phi_factor dy_factor) + a, rounded once, as fma(-phi_factor, dy_factor, a)
  const __m512d estimate = _mm512_fnmadd_pd(phi_factor, dy_factor, terms.a);
  const __m512d margin =
      _mm512_mul_pd(_mm512_set1_pd(std::numeric_limits<double>::epsilon()), _mm512_andnot_pd(sign_bit, terms.a));
  eight_decision d;
  d.contact_before = _mm512_cmp_pd_mask(dy, zero, _CMP_GT_OQ);
  d.decided = _mm512_cmp_pd_mask(_mm512_andnot_pd(sign_bit, estimate), margin, _CMP_GT_OQ);
  d.stays = _mm512_mask_cmp_pd_mask(d.contact_before, estimate, zero, _CMP_GT_OQ);
  return d;
}

// lane<.., true>'s exact decision on eight lanes: whether u + dy - phi dy >= 0
// exactly, phi dy as two_prod(phi_factor, dy_factor)'s exact pair, the sign
// that of detail::leading_component_of_exact_sum itself, run on the vectors
// (GCC's vector arithmetic and ?:): the same two_sums in the same order.
// Exact wherever lane()'s is: in the window and on the band-moved operands.
CONTACT_BATCH_INLINE __mmask8 exact_sum_nonnegative_eight(__m512d u, __m512d dy, __m512d phi_factor,
                                                          __m512d dy_factor) {
  const __m512d high = _mm512_mul_pd(phi_factor, dy_factor);
  const __m512d low = _mm512_fmsub_pd(phi_factor, dy_factor, high);  // detail::two_prod
  const __m512d terms[4] = {u, dy, -high, -low};
  const __m512d leading = detail::leading_component_of_exact_sum(terms);
  return _mm512_cmp_pd_mask(leading, _mm512_setzero_pd(), _CMP_NLT_UQ);  // !(leading < 0)
}

// The pre-test's decision, completed by the exact one on the lanes of `lanes`
// it leaves undecided. Those are rare but for inputs within a few ulps of the
// contact boundary, where nearly every vector holds one: a branch, taken on
// such vectors only.
CONTACT_BATCH_INLINE eight_decision decide_eight(__m512d u, __m512d dy, __m512d phi_factor, __m512d dy_factor,
                                                 const eight_terms& terms, __mmask8 lanes) {
  eight_decision d = pretest_eight(dy, phi_factor, dy_factor, terms);
  const __mmask8 undecided = lanes & d.contact_before & ~d.decided;
  if (undecided != 0) [[unlikely]] {
    d.stays = (d.stays & d.decided) | (exact_sum_nonnegative_eight(u, dy, phi_factor, dy_factor) & ~d.decided);
    d.decided |= undecided;
  }
  return d;
}

struct eight_answers {
  __m512d s;
  __m256i which;
};

CONTACT_BATCH_INLINE eight_answers answer_eight(__m512d u, __m512d dy, __m512d phi, __m512d phi_factor,
                                                __m512d dy_factor, __mmask8 phi_moved, const eight_terms& terms,
                                                const eight_decision& decision) {
  const __m512d x = terms.x, z = terms.z, root = terms.root;
  const __mmask8 no_contact_before = terms.no_contact_before, contact_before = decision.contact_before;
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0), two = _mm512_set1_pd(2.0),
                sign_bit = _mm512_set1_pd(-0.0);
  const __m512i one_bit = _mm512_set1_epi64(1);
  // lane()'s !(a <= 0) is the unordered predicate NLE
  const __mmask8 is_free = _mm512_mask_cmp_pd_mask(no_contact_before, terms.a, zero, _CMP_LE_OQ);
  const __mmask8 is_impact = _mm512_mask_cmp_pd_mask(no_contact_before, terms.a, zero, _CMP_NLE_UQ);
  const __mmask8 is_contact = contact_before & decision.stays;
  const __mmask8 is_release = contact_before & ~decision.stays;
  const __mmask8 rationalised = _mm512_cmp_pd_mask(u, zero, _CMP_GT_OQ);
  // lane()'s one division: for impact, the reciprocal of the denominator,
  // and then stable_form::impact's compensated quotient (detail::two_sum run
  // on the vectors themselves, as GCC's vector arithmetic allows)
  const auto one_plus_phi = detail::two_sum(one, phi);
  const __m512d impact_denominator = _mm512_mul_pd(two, one_plus_phi.high);
  __m512d numerator = _mm512_mask_blend_pd(rationalised, _mm512_sub_pd(root, u), _mm512_mul_pd(two, z));
  __m512d denominator = _mm512_mask_blend_pd(rationalised, two, _mm512_add_pd(u, root));
  numerator = _mm512_mask_blend_pd(is_contact, numerator, _mm512_fmsub_pd(phi_factor, _mm512_mul_pd(two, dy_factor), u));
  denominator = _mm512_mask_blend_pd(is_contact, denominator, one_plus_phi.high);
  numerator = _mm512_mask_blend_pd(is_impact, numerator, one);
  denominator = _mm512_mask_blend_pd(is_impact, denominator, impact_denominator);
  const __m512d quotient_or_inverse = _mm512_div_pd(numerator, denominator);
  const __m512d push_error = _mm512_fmsub_pd(phi_factor, _mm512_andnot_pd(sign_bit, dy_factor), x);
  const auto head = detail::two_sum(u, _mm512_mul_pd(two, x));
  const auto impact_numerator = detail::two_sum(head.high, root);
  const __m512d numerator_low =
      _mm512_add_pd(impact_numerator.low, _mm512_add_pd(head.low, _mm512_mul_pd(two, push_error)));
  const __m512d inverse = quotient_or_inverse;
  const __m512d quotient = _mm512_mul_pd(impact_numerator.high, inverse);
  // fma(-q, b, c) as fnmadd, -fma(a, b, c) as fnmsub: negations are exact, so the same roundings
  const __m512d residual = _mm512_fnmadd_pd(quotient, impact_denominator, impact_numerator.high);
  // lane()'s products with a subnormal phi from normal factors (phi_moved: phi_factor is phi 2^64)
  const __m512d twice_low = _mm512_mask_blend_pd(phi_moved, _mm512_add_pd(one_plus_phi.low, one_plus_phi.low),
                                                 _mm512_mul_pd(two, phi_factor));
  const __m512d quotient_factor =
      _mm512_mask_mul_pd(quotient, phi_moved, quotient, _mm512_set1_pd(0x1p-64));
  const __m512d correction = _mm512_fnmadd_pd(quotient_factor, twice_low, _mm512_add_pd(residual, numerator_low));
  __m512d s = _mm512_mask_blend_pd(is_impact, quotient_or_inverse, _mm512_fnmsub_pd(correction, inverse, quotient));
  // lane()'s clamps: max and min give s < lower ? lower : s and s > upper ? upper : s (s is finite here)
  const __m512d minus_u = _mm512_xor_pd(u, sign_bit);
  const __m512d away_from_zero = _mm512_castsi512_pd(_mm512_add_epi64(_mm512_castpd_si512(dy), one_bit));
  s = _mm512_mask_max_pd(s, is_impact, s, minus_u);
  s = _mm512_mask_min_pd(s, is_impact, s, away_from_zero);
  s = _mm512_mask_min_pd(s, is_contact, s, dy);
  s = _mm512_mask_max_pd(s, is_release, s, away_from_zero);
  s = _mm512_mask_mov_pd(s, is_free, minus_u);
  const __m256i case_impact = _mm256_set1_epi32(int(contact_case::impact)),
                case_release = _mm256_set1_epi32(int(contact_case::release)), one_case = _mm256_set1_epi32(1);
  const __m256i higher_case = _mm256_mask_blend_epi32(no_contact_before, case_release, case_impact);
  return {s, _mm256_mask_sub_epi32(higher_case, is_free | is_contact, higher_case, one_case)};
}

// lane<true, true> on eight lanes with AVX-512 written out, as
// solve_lanes_avx512 writes lane<false>: the same operations in the same order
// (first_terms, decide_eight, answer_eight), the band's table read with two
// permutes and a blend instead of two gathers. Takes the inputs' bits, returns
// the answers and the lanes they hold (the others need the scalar path).
struct rescaled_answers {
  __m512d s;
  __m256i which;
  __mmask8 answered;
};

CONTACT_BATCH_INLINE rescaled_answers rescaled_eight(__m512i u_bits, __m512i dy_bits, __m512i phi_bits) {
  using moves = band_moves<double>;
  using layout = detail::binary_layout<double>;
  static_assert(detail::phi_bands<double>::count == 17 && moves::subnormal_phi_in_one_band,
                "bands 0 to 15 by permutes, 16 by a blend; a subnormal phi in band 0");
  const __m512i sign_bits = _mm512_set1_epi64(std::int64_t(sign_mask<double>));
  const __m512i binade_bits = _mm512_set1_epi64(std::int64_t(~significand_mask<double> & ~sign_mask<double>));
  const __m512i least_normal = _mm512_set1_epi64(std::int64_t(layout::least_normal));
  const __m512i normal_span =
      _mm512_set1_epi64(std::int64_t((layout::exponent_field << layout::significand_bits) - layout::least_normal));
  const __m512i one_bit = _mm512_set1_epi64(1);
  auto is_normal = [&](__m512i magnitude) {  // layout::is_normal, per lane
    return _mm512_cmplt_epu64_mask(_mm512_sub_epi64(magnitude, least_normal), normal_span);
  };
  const __m512i second_normal_binade = _mm512_set1_epi64(std::int64_t(layout::second_normal_binade));
  const __m512i span_above_least_binade =
      _mm512_set1_epi64(std::int64_t((layout::exponent_field << layout::significand_bits) - layout::second_normal_binade));
  auto is_normal_above_least_binade = [&](__m512i magnitude) {  // layout::is_normal_above_least_binade, per lane
    return _mm512_cmplt_epu64_mask(_mm512_sub_epi64(magnitude, second_normal_binade), span_above_least_binade);
  };

  // band_rescaling(): the shift by phi's band, and the lanes it fits
  const __m512i abs_u = _mm512_andnot_si512(sign_bits, u_bits), abs_dy = _mm512_andnot_si512(sign_bits, dy_bits);
  const __m512i larger_binade = _mm512_and_si512(_mm512_max_epu64(abs_u, abs_dy), binade_bits);
  const __m512i smaller_binade = _mm512_and_si512(_mm512_min_epu64(abs_u, abs_dy), binade_bits);
  const __m512i band = _mm512_srli_epi64(
      _mm512_add_epi64(_mm512_srli_epi64(_mm512_andnot_si512(sign_bits, phi_bits), moves::significand_bits),
                       _mm512_set1_epi64(moves::index_offset)),
      detail::phi_bands<double>::band_bits);
  auto look_up = [&](const auto& table) {  // table[band]; any band beyond 16 reads garbage and fails phi_in_a_band
    const __m512i low = _mm512_loadu_si512(table.data()), high = _mm512_loadu_si512(table.data() + 8);
    const __m512i last = _mm512_set1_epi64(std::int64_t(table[16]));
    const __mmask8 in_last = _mm512_cmpeq_epi64_mask(band, _mm512_set1_epi64(16));
    return _mm512_mask_blend_epi64(in_last, _mm512_permutex2var_epi64(low, band, high), last);
  };
  const __mmask8 phi_in_a_band = _mm512_cmplt_epu64_mask(_mm512_sub_epi64(phi_bits, _mm512_set1_epi64(moves::phi_least)),
                                                         _mm512_set1_epi64(moves::phi_end - moves::phi_least));
  const __mmask8 fits = is_normal(abs_u) & is_normal(abs_dy) & phi_in_a_band &
                        _mm512_cmple_epu64_mask(_mm512_sub_epi64(larger_binade, smaller_binade), look_up(moves::room));
  const __m512i shift = _mm512_sub_epi64(look_up(moves::top_binade), larger_binade);
  const __m512d u = _mm512_castsi512_pd(_mm512_add_epi64(u_bits, shift));
  const __m512d dy = _mm512_castsi512_pd(_mm512_add_epi64(dy_bits, shift));
  const __m512d phi = _mm512_castsi512_pd(phi_bits);

  // product_factors(): a subnormal phi as (phi 2^64) (dy 2^-64)
  const __mmask8 subnormal_phi = _mm512_cmplt_epu64_mask(_mm512_sub_epi64(phi_bits, one_bit),
                                                         _mm512_sub_epi64(least_normal, one_bit));
  const __m512d phi_up = _mm512_mul_pd(_mm512_cvtepi64_pd(phi_bits),
                                       _mm512_set1_pd(std::numeric_limits<double>::denorm_min() * 0x1p64));
  const __m512d phi_factor = _mm512_mask_blend_pd(subnormal_phi, phi, phi_up);
  // dy 2^-64 as a product, not lane()'s quotient dy / 2^64: the same exact value, rounded once
  // either way, without a second division
  const __m512d dy_factor = _mm512_mask_blend_pd(subnormal_phi, dy, _mm512_mul_pd(dy, _mm512_set1_pd(0x1p-64)));

  const eight_terms terms = first_terms(u, dy, phi_factor, dy_factor);
  const eight_decision decision = decide_eight(u, dy, phi_factor, dy_factor, terms, fits);
  const eight_answers answers = answer_eight(u, dy, phi, phi_factor, dy_factor, subnormal_phi, terms, decision);
  const __m512d s = answers.s;

  // scaled_back(): s moves back where it is 0, or normal before and after
  const __m512i s_bits = _mm512_castpd_si512(s);
  const __m512i abs_s = _mm512_andnot_si512(sign_bits, s_bits);
  const __mmask8 s_zero = _mm512_cmpeq_epi64_mask(abs_s, _mm512_setzero_si512());
  const __mmask8 s_back_normal = (is_normal_above_least_binade(abs_s) & is_normal(_mm512_sub_epi64(abs_s, shift))) | s_zero;
  const __m512d s_back = _mm512_castsi512_pd(_mm512_mask_sub_epi64(s_bits, __mmask8(~s_zero), s_bits, shift));

  return {s_back, answers.which, __mmask8(fits & s_back_normal)};
}

// The lanes outside the window that solve_lanes_avx512 leaves, for the
// rescaled pass: a vector with every lane outside by its first lane, solved in
// place; the lanes of a vector that mixes them with lanes inside (most vectors
// of the boundaries and phi scenes), packed with their indices, so that the
// lanes inside keep the first pass's answers and the rescaled pass runs on
// full vectors of lanes outside (measured on the boundaries scene: 7.3 -> 4.4
// ns per lane against a rescaled pass on every vector that holds one, phi
// scene 6.3 -> 5.4, physical and extreme unchanged). The passes over a batch
// of them run one after the other: they are independent, and out-of-order
// execution overlaps one's square root and division with the next one's.
struct pending_lanes {
  static constexpr int capacity = 256;
  // the packed lanes' inputs (bits) and indices, each with room for a whole vector written past the count
  alignas(64) std::int64_t u[capacity + 8], dy[capacity + 8], phi[capacity + 8], index[capacity + 8];
  int count = 0;
  static constexpr int vector_capacity = 32;
  std::ptrdiff_t vector_start[vector_capacity];
  int vector_count = 0;
  CONTACT_BATCH_INLINE void add(__mmask8 lanes, __m512i u_bits, __m512i dy_bits, __m512i phi_bits, __m512i indices) {
    _mm512_storeu_si512(u + count, _mm512_maskz_compress_epi64(lanes, u_bits));
    _mm512_storeu_si512(dy + count, _mm512_maskz_compress_epi64(lanes, dy_bits));
    _mm512_storeu_si512(phi + count, _mm512_maskz_compress_epi64(lanes, phi_bits));
    _mm512_storeu_si512(index + count, _mm512_maskz_compress_epi64(lanes, indices));
    count += std::popcount(unsigned(lanes));
  }
};

// rescaled_eight on the pending lanes, eight at a time, each answer written
// back to its lane; the scalar path for the lanes it cannot answer.
[[gnu::noinline]] inline void solve_pending(const double* __restrict u, const double* __restrict dy,
                                            const double* __restrict phi, double* __restrict s, int* __restrict which,
                                            const pending_lanes& lanes) {
  for (int v = 0; v < lanes.vector_count; ++v) {
    const std::ptrdiff_t i = lanes.vector_start[v];
    const rescaled_answers r =
        rescaled_eight(_mm512_loadu_si512(u + i), _mm512_loadu_si512(dy + i), _mm512_loadu_si512(phi + i));
    _mm512_storeu_pd(s + i, r.s);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(which + i), r.which);
    for (unsigned left = ~unsigned(r.answered) & 0xFFu; left != 0; left &= left - 1)
      solve_scalar_lane(u, dy, phi, s, which, i + std::countr_zero(left));
  }
  const __m512i one_bits = _mm512_castpd_si512(_mm512_set1_pd(1.0));  // for the lanes past the count
  for (int k = 0; k < lanes.count; k += 8) {
    const int active = std::min(8, lanes.count - k);
    const __mmask8 filled = __mmask8((1u << active) - 1);
    const rescaled_answers r = rescaled_eight(_mm512_mask_load_epi64(one_bits, filled, lanes.u + k),
                                              _mm512_mask_load_epi64(one_bits, filled, lanes.dy + k),
                                              _mm512_mask_load_epi64(one_bits, filled, lanes.phi + k));
    alignas(64) double answer_s[8];
    alignas(32) int answer_which[8];
    _mm512_store_pd(answer_s, r.s);
    _mm256_store_si256(reinterpret_cast<__m256i*>(answer_which), r.which);
    for (int j = 0; j < active; ++j) {  // every lane, without a branch; those not answered are solved again below
      s[lanes.index[k + j]] = answer_s[j];
      which[lanes.index[k + j]] = answer_which[j];
    }
    for (unsigned left = unsigned(filled & ~r.answered); left != 0; left &= left - 1)
      solve_scalar_lane(u, dy, phi, s, which, lanes.index[k + std::countr_zero(left)]);
  }
}

// The same lanes with AVX-512 written out, for double: the operations of lane()
// in the same order, with the masks in mask registers. Measured on Zen 5, in
// cache, against the vectorised lane() at about 1.0 ns per lane:
// - each selection, clamp and case test is one instruction (about 65 per 8
//   lanes against about 95): about 0.85 ns;
// - the square root of the next 8 lanes is issued before the division of
//   these 8 (both run on one unit, and out-of-order execution alone does not
//   overlap them across iterations): about 0.76 ns.
// The lanes outside the window are collected by index and solved out of line
// (solve_pending: rescaled_eight, then the scalar path for what that cannot answer).
inline void solve_lanes_avx512(const double* __restrict u_in, const double* __restrict dy_in, const double* __restrict phi_in,
                      double* __restrict s_out, int* __restrict which_out, std::ptrdiff_t n) {
  const __m512i sign_bits = _mm512_set1_epi64(std::int64_t(sign_mask<double>));
  const __m512i lowest_uv = _mm512_set1_epi64(std::int64_t(detail::common_window_lowest_uv<double>));  // 2^L
  const __m512i lowest_phi = _mm512_set1_epi64(std::int64_t(detail::common_window_lowest_phi<double>));  // 2^M
  const __m512i width = _mm512_set1_epi64(std::int64_t(detail::common_window_width<double>));
  std::ptrdiff_t i = 0;
  // 8 lanes up to their square root, which is issued one vector ahead
  struct up_to_root {
    __m512d u, dy, phi;
    __mmask8 inside;
    eight_terms terms;
  };
  auto start = [&](std::ptrdiff_t j) {
    up_to_root l;
    const __m512i u_bits = _mm512_loadu_si512(u_in + j), dy_bits = _mm512_loadu_si512(dy_in + j);
    const __m512i phi_bits = _mm512_loadu_si512(phi_in + j);
    // inside_window()'s test: the OR of the three offsets from 2^-E (a negative
    // or NaN phi fails it)
    const __m512i spread = _mm512_ternarylogic_epi64(_mm512_sub_epi64(_mm512_andnot_si512(sign_bits, u_bits), lowest_uv),
                                                     _mm512_sub_epi64(_mm512_andnot_si512(sign_bits, dy_bits), lowest_uv),
                                                     _mm512_sub_epi64(phi_bits, lowest_phi), 0xFE);
    l.inside = _mm512_cmplt_epu64_mask(spread, width);
    // The lanes outside are answered again later, rescaled; here they take 1
    // for u, dy and phi (masked loads: no extra arithmetic), so that none of
    // their products under- or overflows. A subnormal operand or result costs
    // a microcode assist on many cores, about as much as the rest of the 8
    // lanes together: measured 11.8 -> 5.8 ns per lane where u and dy span
    // 2^+-1000, no change on physical inputs.
    const __m512d one = _mm512_set1_pd(1.0);
    l.u = _mm512_mask_loadu_pd(one, l.inside, u_in + j);
    l.dy = _mm512_mask_loadu_pd(one, l.inside, dy_in + j);
    l.phi = _mm512_mask_loadu_pd(one, l.inside, phi_in + j);
    l.terms = first_terms(l.u, l.dy, l.phi, l.dy);
    return l;
  };
  up_to_root next{};
  if (n >= 8) next = start(0);
  pending_lanes pending;
  const __m512i lane_numbers = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
  for (; i + 8 <= n; i += 8) {
    const up_to_root l = next;
    if (i + 16 <= n) next = start(i + 8);
    const __m512d u = l.u, dy = l.dy, phi = l.phi;
    // every lane inside is decided, by the pre-test or exactly
    const eight_decision decision = decide_eight(u, dy, phi, dy, l.terms, l.inside);
    const eight_answers answers = answer_eight(u, dy, phi, phi, dy, __mmask8(0), l.terms, decision);
    _mm512_storeu_pd(s_out + i, answers.s);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(which_out + i), answers.which);
    // the lanes outside, noted for solve_pending, out of line, so that the hot
    // loop stays short (the branches are never taken on physical inputs, and
    // nearly always on the wide scenes, where most vectors hold such a lane)
    const __mmask8 outside = __mmask8(~l.inside);
    if (outside != 0) {
      if (outside == 0xFF)
        pending.vector_start[pending.vector_count++] = i;
      else
        pending.add(outside, _mm512_loadu_si512(u_in + i), _mm512_loadu_si512(dy_in + i),
                    _mm512_loadu_si512(phi_in + i), _mm512_add_epi64(_mm512_set1_epi64(i), lane_numbers));
      if (pending.count > pending_lanes::capacity - 8 || pending.vector_count == pending_lanes::vector_capacity)
          [[unlikely]] {
        solve_pending(u_in, dy_in, phi_in, s_out, which_out, pending);
        pending.count = 0;
        pending.vector_count = 0;
      }
    }
  }
  if (pending.count != 0 || pending.vector_count != 0) solve_pending(u_in, dy_in, phi_in, s_out, which_out, pending);
  for (; i < n; ++i) solve_scalar_lane(u_in, dy_in, phi_in, s_out, which_out, i);  // the last n mod 8 lanes
}
#endif

}  // namespace batch_detail

// Solves (A.2) for the n lanes u[i], dy[i], phi[i]; writes s[i] and the case
// number (contact_case as int: 0 invalid, 1..4 for (A.29)..(A.32)). The output
// arrays must not overlap the inputs. Any T that solve_stable accepts; float
// and double are vectorised, other types run the scalar path lane by lane.
template <class T>
void solve_batch(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  if constexpr (batch_detail::has_lane_kernel<T>) {
#if defined(__AVX512F__)
    if constexpr (std::is_same_v<T, double>) {
      batch_detail::solve_lanes_avx512(u, dy, phi, s, which, n);
      return;
    }
#endif
    batch_detail::solve_lanes(u, dy, phi, s, which, n);
  } else {
    for (std::ptrdiff_t i = 0; i < n; ++i) batch_detail::solve_scalar_lane(u, dy, phi, s, which, i);
  }
}

template <class T>
using batch_array = Eigen::Array<T, Eigen::Dynamic, 1>;

// The Eigen form: s and which are resized to the length of u; dy and phi must
// have that length too.
template <class T>
void solve_batch(const batch_array<T>& u, const batch_array<T>& dy, const batch_array<T>& phi, batch_array<T>& s,
                 batch_array<int>& which) {
  eigen_assert(dy.size() == u.size() && phi.size() == u.size());
  s.resize(u.size());
  which.resize(u.size());
  solve_batch(u.data(), dy.data(), phi.data(), s.data(), which.data(), u.size());
}

}  // namespace contact
