// contact::solve_batch: the stable closed form of (A.2) over arrays.
//
// Same results as the scalar stable path, bit for bit: every lane gets exactly
// the s and the case that contact::solve_stable gives for it. Lanes whose
// u, dy and phi all lie inside detail::safe_window<T> (the scalar path's plain-T
// window, which holds every physically meaningful input) are solved without a
// branch: every lane evaluates the operations of all four cases, in the same
// order and with the same fma as stable.hpp, and selects its own result with
// masks, so the compiler vectorises the loop. A block with lanes outside that
// window runs again rescaled (with AVX-512, a vector of 8 lanes with such a
// lane runs rescaled instead of plain): u and dy move by one power of two to
// where phi's band leaves them room and s moves back, exactly (the
// homogeneity and the bands that solve_stable uses outside its plain window).
// The portable kernel solves the lanes that even that cannot answer by the
// scalar contact::solve_stable: phi in no band (phi >= 2^1021 in double,
// 2^125 in float; phi = 0; NaN, infinity, phi < 0), u and dy too far apart
// for the band, a zero or subnormal u or dy, subnormal phi in float, an
// impact using its own room, free flight outside the bands, and an s that is
// subnormal or overflows once moved back. The AVX-512 kernel (double) answers
// all of those in vector code, the lanes too far apart by scaled<double>'s
// own operations on eight lanes (far_eight), but for a case the binades
// cannot decide there, a release root within an ulp of the largest double,
// an s in the least normal binade or below before the move back or in the
// binade 2^1024 after it, a zero u or dy, phi = 0 (but for free flight) and
// invalid input.
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
// window (detail::common_window<T>: normal, phi > 0), inside
// detail::safe_window<T>, so the scalar path runs the same plain-T operations
// on these lanes; NaN, infinity, zero, phi < 0 and the extreme magnitudes all
// go to the rescaled pass and the scalar fix-up.
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
  __mmask8 is_impact, is_contact, is_release;
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
  return {s, _mm256_mask_sub_epi32(higher_case, is_free | is_contact, higher_case, one_case), is_impact, is_contact,
          is_release};
}

// fpclass categories: quiet NaN, +inf, -inf, signalling NaN; and +0, -0
inline constexpr int fpclass_not_finite = 0x01 | 0x08 | 0x10 | 0x80;
inline constexpr int fpclass_zero = 0x02 | 0x04;

// Subnormals and microcode assists (measured on this kernel's Intel Xeon,
// some 50 to 80 ns per instruction that takes one): getexp, getmant, compares,
// min and max take a subnormal operand without one; scalef, mul and fma with
// a subnormal operand, and scalef with a subnormal result, do not. So the
// kernels read subnormals by getmant and getexp, and form subnormal results
// as integers (value_of, moved_back_eight).

// x 2^k rounded once into the subnormals, or to 0, on the lanes of `lanes`
// (0 elsewhere), for x normal or zero in binade b (getexp's, or -1 for a
// significand in [0.5, 1)) and integer k with b + k below the normal
// binades: the integer of its bits, x 2^(k + 1074) rounded to an integer
// (roundscale, to nearest even; 2^52 is the least normal's bits), so that no
// operation has a subnormal result. From 2^-62 of x's binade down the
// integer is 0 all the same, which bounds the scalef.
CONTACT_BATCH_INLINE __m512d rounded_below_normal(__mmask8 lanes, __m512d x, __m512d binade, __m512d k) {
  const __m512d sign_bit = _mm512_set1_pd(-0.0);
  const __m512d units =
      _mm512_maskz_scalef_pd(lanes, _mm512_andnot_pd(sign_bit, x),
                             _mm512_max_pd(_mm512_sub_pd(k, _mm512_set1_pd(detail::phi_bands<double>::least_binade)),
                                           _mm512_sub_pd(_mm512_set1_pd(-62.0), binade)));
  const __m512i integer = _mm512_cvtpd_epu64(_mm512_roundscale_pd(units, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC));
  return _mm512_or_pd(_mm512_castsi512_pd(integer), _mm512_and_pd(x, sign_bit));
}


// phi_bands<double>' table as doubles, for the AVX-512 kernel, which reads the
// binades of u and dy with getexp (subnormals included) and moves them with
// scalef: per band, top - 1 (where the larger of |u|, |dy| moves), and the
// least binade the smaller may then have, for contact and release (lowest)
// and for an impact (impact_lowest).
struct band_binades {
  using bands = detail::phi_bands<double>;
  template <int bands::band::*member, int offset = 0>
  static constexpr std::array<double, bands::count> column = [] {
    std::array<double, bands::count> values{};
    for (int j = 0; j < bands::count; ++j) values[j] = bands::table[j].*member + offset;
    return values;
  }();
  static constexpr const auto& top_binade = column<&bands::band::top, -1>;
  static constexpr const auto& lowest = column<&bands::band::lowest>;
  static constexpr const auto& impact_lowest = column<&bands::band::impact_lowest>;
};

// Eight lanes' operands up to their square root: u, dy and phi as they are in
// the common window, else moved by phi's band (`shift` binades; 0 for the
// lanes that stay). The lanes outside `answerable` (the vector cannot solve
// them) take 1 for u, dy and phi, so that none of their products under- or
// overflows: a subnormal operand or result costs a microcode assist on many
// cores, about as much as the rest of the 8 lanes together.
struct eight_operands {
  __m512d u, dy, phi, phi_factor, dy_factor, shift;
  __mmask8 phi_moved;   // a subnormal phi: phi_factor = phi 2^64, dy_factor = dy 2^-64 (product_factors)
  __mmask8 answerable;
  __mmask8 free_flight;  // dy <= 0 and u <= -dy for finite u, dy and phi in [+0, inf): -u, whatever the band
  bool moved;           // some lane moved, or cannot be answered: the answers need moved_back_eight
  eight_terms terms;
};

// solve_in_band's move on eight lanes: the larger of |u|, |dy| to 2^(top - 1)
// by phi's band, where the smaller then lies at or above the band's least
// binade for its case (an impact's own room where dy <= 0). Binades by getexp,
// moves by getmant and scalef: exact, as the moved values are normal, for
// subnormal u and dy too (getexp and getmant take a subnormal operand without
// a microcode assist, scalef does not). The lanes of `inside` stay where they
// are. Zero and infinite u or dy (getexp gives -inf and +inf, and the room
// test fails), NaN and phi in no band are not answerable. Each mask is
// formed by the compare that tests its last condition, under the mask of the
// others: the pass costs some 40 of the rescaled vector's 100 cycles on the
// extreme scene, mostly in its instructions' count.
CONTACT_BATCH_INLINE eight_operands moved_operands(__m512d u, __m512d dy, __m512d phi, __mmask8 inside) {
  using moves = band_moves<double>;
  using layout = detail::binary_layout<double>;
  static_assert(detail::phi_bands<double>::count == 17 && moves::subnormal_phi_in_one_band,
                "bands 0 to 15 by permutes, 16 by a blend; a subnormal phi in band 0");
  const __m512i phi_bits = _mm512_castpd_si512(phi);
  // (a negative phi's sign bit gives an index the table lookups mask to garbage; phi_in_a_band refuses it)
  const __m512i band = _mm512_srli_epi64(
      _mm512_add_epi64(_mm512_srli_epi64(phi_bits, moves::significand_bits), _mm512_set1_epi64(moves::index_offset)),
      detail::phi_bands<double>::band_bits);
  const __mmask8 in_last = _mm512_cmpeq_epi64_mask(band, _mm512_set1_epi64(16));
  auto look_up = [&](const auto& table) {  // table[band]
    const __m512d low = _mm512_loadu_pd(table.data()), high = _mm512_loadu_pd(table.data() + 8);
    return _mm512_mask_blend_pd(in_last, _mm512_permutex2var_pd(low, band, high), _mm512_set1_pd(table[16]));
  };
  const __m512d sign_bit = _mm512_set1_pd(-0.0), infinity = _mm512_set1_pd(std::numeric_limits<double>::infinity());
  const __m512d u_binade = _mm512_getexp_pd(u), dy_binade = _mm512_getexp_pd(dy);
  const __m512d larger = _mm512_max_pd(u_binade, dy_binade), smaller = _mm512_min_pd(u_binade, dy_binade);
  // (max and min can hide a NaN binade, hence the ordered test)
  const __mmask8 ordered = _mm512_cmp_pd_mask(u, dy, _CMP_ORD_Q);
  const __mmask8 finite = _mm512_mask_cmp_pd_mask(ordered, larger, infinity, _CMP_LT_OQ);
  const __mmask8 impact_side = _mm512_cmp_pd_mask(dy, _mm512_setzero_pd(), _CMP_LE_OQ);
  // free flight (dy <= 0, u <= -dy, phi in [+0, inf)) is answered by
  // moved_back_eight, from the input itself: its lanes take 1 here, as the
  // others that need no move (its garbage impact formula, on a gap near u,
  // underflowed into microcode assists: measured 8.5 -> 5.5 ns per free lane
  // of the extreme scene)
  const __mmask8 free_flight = _mm512_mask_cmp_pd_mask(finite & impact_side, u, _mm512_xor_pd(dy, sign_bit), _CMP_LE_OQ);
  const __mmask8 phi_in_a_band =
      _mm512_mask_cmplt_epu64_mask(ordered & ~(inside | free_flight), _mm512_sub_epi64(phi_bits, _mm512_set1_epi64(moves::phi_least)),
                                   _mm512_set1_epi64(moves::phi_end - moves::phi_least));
  const __m512d least = _mm512_mask_blend_pd(impact_side, look_up(band_binades::lowest), look_up(band_binades::impact_lowest));
  const __m512d band_shift = _mm512_sub_pd(look_up(band_binades::top_binade), larger);
  const __mmask8 fits = _mm512_mask_cmp_pd_mask(phi_in_a_band, _mm512_add_pd(smaller, band_shift), least, _CMP_GE_OQ);

  eight_operands l;
  l.answerable = inside | fits;
  l.free_flight = _mm512_mask_cmplt_epu64_mask(free_flight, phi_bits, _mm512_castpd_si512(infinity));
  l.moved = true;
  l.shift = _mm512_maskz_mov_pd(fits, band_shift);
  const __m512d one = _mm512_set1_pd(1.0);
  l.u = _mm512_mask_scalef_pd(one, l.answerable, _mm512_getmant_pd(u, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src),
                              _mm512_add_pd(l.shift, u_binade));
  l.dy = _mm512_mask_scalef_pd(one, l.answerable, _mm512_getmant_pd(dy, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src),
                               _mm512_add_pd(l.shift, dy_binade));
  l.phi = _mm512_mask_mov_pd(one, l.answerable, phi);
  l.phi_factor = l.phi;
  l.dy_factor = l.dy;
  // product_factors(): a subnormal phi as (phi 2^64) (dy 2^-64); dy 2^-64 as a
  // product, not lane()'s quotient dy / 2^64: the same exact value, rounded
  // once either way, without a second division. A branch: few vectors hold
  // one, but for the scenes of subnormal phi, where nearly all do.
  l.phi_moved = _mm512_mask_cmplt_epu64_mask(l.answerable, _mm512_sub_epi64(phi_bits, _mm512_set1_epi64(1)),
                                             _mm512_set1_epi64(std::int64_t(layout::least_normal - 1)));
  if (l.phi_moved != 0) [[unlikely]] {
    l.phi_factor = _mm512_mask_mul_pd(l.phi, l.phi_moved, _mm512_cvtepi64_pd(phi_bits),
                                      _mm512_set1_pd(std::numeric_limits<double>::denorm_min() * 0x1p64));
    l.dy_factor = _mm512_mask_mul_pd(l.dy, l.phi_moved, l.dy, _mm512_set1_pd(0x1p-64));
  }
  return l;
}

// moved_back() on eight lanes: s moves back by scalef (+inf from
// 2^(max_exponent + 1) up), or as an integer where it lands below the normal
// binades, rounded once either way as the scaled path rounds it; then each
// case's clamps, on the unmoved u and dy (moved_back_below_normal's; they
// change no s that is normal once moved back). Free flight is answered for any valid input, moved or not, as
// solve_in_band answers it before any band. Returns the lanes answered: not
// those whose s, before the move back, is subnormal or in the least normal
// binade, nor those that land in the binade 2^max_exponent, where only the
// scaled path tells infinity from the largest double.
struct eight_results {
  __m512d s;
  __m256i which;
  __mmask8 answered;
};

CONTACT_BATCH_INLINE eight_results moved_back_eight(const eight_operands& l, const eight_answers& answers, __m512d u,
                                                    __m512d dy) {
  // binade of s before the move back: normal above the least binade in [-1021, 1023] (getexp of 0 is -inf)
  const __m512d binade = _mm512_getexp_pd(answers.s);
  const __mmask8 normal_before = _mm512_cmp_pd_mask(binade, _mm512_set1_pd(std::numeric_limits<double>::min_exponent), _CMP_GE_OQ) &
                                 _mm512_cmp_pd_mask(binade, _mm512_set1_pd(std::numeric_limits<double>::max_exponent - 1), _CMP_LE_OQ);
  const __mmask8 below_top = _mm512_cmp_pd_mask(_mm512_sub_pd(binade, l.shift),
                                                _mm512_set1_pd(std::numeric_limits<double>::max_exponent), _CMP_NEQ_UQ);
  const __mmask8 s_zero = _mm512_cmp_pd_mask(answers.s, _mm512_setzero_pd(), _CMP_EQ_OQ);
  const __m512d sign_bit = _mm512_set1_pd(-0.0), minus_u = _mm512_xor_pd(u, sign_bit);
  const __m512i one_bit = _mm512_set1_epi64(1);
  // An s that lands below the normal binades is rounded by
  // rounded_below_normal, as value_of rounds, since a scalef with a subnormal
  // result costs a microcode assist. On the extreme scene 8% of
  // the lanes, in 48% of the vectors, land there: the route taken on those
  // vectors only measured 3.8% faster there than scalef alone, and taken on
  // every vector 2% slower.
  const __m512d back = _mm512_xor_pd(l.shift, sign_bit);
  const __mmask8 below_normal = _mm512_mask_cmp_pd_mask(__mmask8(~s_zero), _mm512_add_pd(binade, back),
                                                        _mm512_set1_pd(std::numeric_limits<double>::min_exponent - 1), _CMP_LT_OQ);
  __m512d s;
  if (below_normal == 0) [[likely]] {
    s = _mm512_scalef_pd(answers.s, back);
  } else {
    s = _mm512_mask_scalef_pd(rounded_below_normal(below_normal, answers.s, binade, back), __mmask8(~below_normal),
                              answers.s, back);
  }
  s = _mm512_mask_max_pd(s, answers.is_impact, s, minus_u);
  s = _mm512_mask_min_pd(s, answers.is_impact, s,
                         _mm512_castsi512_pd(_mm512_add_epi64(_mm512_castpd_si512(_mm512_or_pd(dy, sign_bit)), one_bit)));
  s = _mm512_mask_min_pd(s, answers.is_contact, s, dy);
  s = _mm512_mask_max_pd(s, answers.is_release, s, _mm512_castsi512_pd(_mm512_add_epi64(_mm512_castpd_si512(dy), one_bit)));
  s = _mm512_mask_mov_pd(s, l.free_flight, minus_u);
  const __m256i which = _mm256_mask_mov_epi32(answers.which, l.free_flight, _mm256_set1_epi32(int(contact_case::free)));
  const __mmask8 answered = (l.answerable & (s_zero | (normal_before & below_top))) | l.free_flight;
  return {s, which, answered};
}

CONTACT_BATCH_INLINE eight_answers solve_operands(const eight_operands& l) {
  const eight_decision decision = decide_eight(l.u, l.dy, l.phi_factor, l.dy_factor, l.terms, l.answerable);
  return answer_eight(l.u, l.dy, l.phi, l.phi_factor, l.dy_factor, l.phi_moved, l.terms, decision);
}

// Eight lanes outside the window, moved, solved and moved back: the kernel's
// path for vectors with such lanes, not pipelined (for tests).
CONTACT_BATCH_INLINE eight_results rescaled_eight(__m512d u, __m512d dy, __m512d phi) {
  eight_operands l = moved_operands(u, dy, phi, 0);
  l.terms = first_terms(l.u, l.dy, l.phi_factor, l.dy_factor);
  return moved_back_eight(l, solve_operands(l), u, dy);
}

// detail::scaled<double> on eight lanes, for the lanes no band holds (u and
// dy too far apart): the significand in [0.5, 1) (or a signed zero, with
// exponent 0) and the exponent, an integer held as a double. Each operation
// is scaled<T>'s own, on the same significands, so it rounds the same.
struct scaled_eight {
  __m512d significand, exponent;
};

// scaled<T>::normalized: a finite x 2^exponent with x normal or zero.
CONTACT_BATCH_INLINE scaled_eight normalized_eight(__m512d x, __m512d exponent) {
  const __mmask8 nonzero = _mm512_cmp_pd_mask(x, _mm512_setzero_pd(), _CMP_NEQ_UQ);
  return {_mm512_mask_getmant_pd(x, nonzero, x, _MM_MANT_NORM_p5_1, _MM_MANT_SIGN_src),
          _mm512_maskz_add_pd(nonzero, exponent, _mm512_add_pd(_mm512_getexp_pd(x), _mm512_set1_pd(1.0)))};
}

// A double, subnormal or not, as a scaled number.
CONTACT_BATCH_INLINE scaled_eight scaled_of_eight(__m512d x) { return normalized_eight(x, _mm512_setzero_pd()); }

CONTACT_BATCH_INLINE scaled_eight operator*(const scaled_eight& a, const scaled_eight& b) {
  return normalized_eight(_mm512_mul_pd(a.significand, b.significand), _mm512_add_pd(a.exponent, b.exponent));
}

CONTACT_BATCH_INLINE scaled_eight operator/(const scaled_eight& a, const scaled_eight& b) {
  return normalized_eight(_mm512_div_pd(a.significand, b.significand), _mm512_sub_pd(a.exponent, b.exponent));
}

CONTACT_BATCH_INLINE scaled_eight operator-(const scaled_eight& a) {
  return {_mm512_xor_pd(a.significand, _mm512_set1_pd(-0.0)), a.exponent};
}

// times 2^k, exactly, for a constant k (scaled<T>'s product by 2^k's scaled form)
CONTACT_BATCH_INLINE scaled_eight times_power_of_two(const scaled_eight& a, double k) {
  const __mmask8 nonzero = _mm512_cmp_pd_mask(a.significand, _mm512_setzero_pd(), _CMP_NEQ_UQ);
  return {a.significand, _mm512_mask_add_pd(a.exponent, nonzero, a.exponent, _mm512_set1_pd(k))};
}

// scaled<T>::shifted(x, shift) for a significand x and shift <= 0, as its sum
// or fma with another significand sees it: exact while normal (shift >= -1000),
// else a stand-in of its sign, 2^-1010, or 0 where shifted rounds to 0
// (shift <= -1075, or -1074 with |x| = 1/2). Below 2^-1000 the value cannot
// change a sum's rounding (below a quarter ulp of the other significand) nor
// an fma's (the exact product, a multiple of 2^-106, lies at least 2^-106
// from a rounding boundary unless on one, where only the sign tells), and
// the stand-in, normal, costs no microcode assist where a subnormal would.
CONTACT_BATCH_INLINE __m512d shifted_down_eight(__m512d x, __m512d shift) {
  const __mmask8 exact = _mm512_cmp_pd_mask(shift, _mm512_set1_pd(-1000.0), _CMP_GE_OQ);
  const __m512d sign_bit = _mm512_set1_pd(-0.0), abs_x = _mm512_andnot_pd(sign_bit, x);
  const __mmask8 rounds_to_zero =
      _mm512_cmp_pd_mask(shift, _mm512_set1_pd(-1075.0), _CMP_LE_OQ) |
      (_mm512_cmp_pd_mask(shift, _mm512_set1_pd(-1074.0), _CMP_EQ_OQ) &
       _mm512_cmp_pd_mask(abs_x, _mm512_set1_pd(0.5), _CMP_EQ_OQ)) |
      _mm512_cmp_pd_mask(x, _mm512_setzero_pd(), _CMP_EQ_OQ);
  const __m512d stand_in = _mm512_or_pd(_mm512_and_pd(x, sign_bit),
                                        _mm512_maskz_mov_pd(__mmask8(~rounds_to_zero), _mm512_set1_pd(0x1p-1010)));
  // (the shift clamped where the stand-in is taken, so that no lane's scalef underflows)
  return _mm512_mask_blend_pd(exact, stand_in, _mm512_scalef_pd(x, _mm512_max_pd(shift, _mm512_set1_pd(-1000.0))));
}

// scaled<T>'s operator+: a zero term gives the other one; the smaller moves
// into the larger's frame
CONTACT_BATCH_INLINE scaled_eight operator+(const scaled_eight& a, const scaled_eight& b) {
  const __mmask8 a_larger = _mm512_cmp_pd_mask(a.exponent, b.exponent, _CMP_GE_OQ);
  const __m512d large_exponent = _mm512_mask_blend_pd(a_larger, b.exponent, a.exponent);
  const __m512d large = _mm512_mask_blend_pd(a_larger, b.significand, a.significand);
  const __m512d small = _mm512_mask_blend_pd(a_larger, a.significand, b.significand);
  const __m512d small_exponent = _mm512_mask_blend_pd(a_larger, a.exponent, b.exponent);
  scaled_eight sum =
      normalized_eight(_mm512_add_pd(large, shifted_down_eight(small, _mm512_sub_pd(small_exponent, large_exponent))),
                       large_exponent);
  const __m512d zero = _mm512_setzero_pd();
  const __mmask8 a_zero = _mm512_cmp_pd_mask(a.significand, zero, _CMP_EQ_OQ);
  const __mmask8 b_zero = _mm512_cmp_pd_mask(b.significand, zero, _CMP_EQ_OQ);
  sum.significand = _mm512_mask_mov_pd(_mm512_mask_mov_pd(sum.significand, a_zero, b.significand), b_zero, a.significand);
  sum.exponent = _mm512_mask_mov_pd(_mm512_mask_mov_pd(sum.exponent, a_zero, b.exponent), b_zero, a.exponent);
  return sum;
}

// scaled<T>'s fused_multiply_add: a * b + c rounded once, the smaller of the
// product and c moved into the other's frame
CONTACT_BATCH_INLINE scaled_eight fused_multiply_add(const scaled_eight& a, const scaled_eight& b, const scaled_eight& c) {
  const __m512d zero = _mm512_setzero_pd();
  const __m512d product_exponent = _mm512_add_pd(a.exponent, b.exponent);
  const __mmask8 c_zero = _mm512_cmp_pd_mask(c.significand, zero, _CMP_EQ_OQ);
  const __mmask8 product_larger = c_zero | _mm512_cmp_pd_mask(product_exponent, c.exponent, _CMP_GE_OQ);
  // the smaller moves: c by c.e - pe <= 0 where the product is larger (c = 0
  // may give a shift > 0, which scalef takes: 0 2^k = 0), else b by pe - c.e < 0
  const __m512d shift = _mm512_sub_pd(c.exponent, product_exponent);
  const __m512d moved = shifted_down_eight(_mm512_mask_blend_pd(product_larger, b.significand, c.significand),
                                           _mm512_mask_xor_pd(shift, __mmask8(~product_larger), shift, _mm512_set1_pd(-0.0)));
  const __m512d addend = _mm512_mask_blend_pd(product_larger, c.significand, moved);
  const __m512d factor = _mm512_mask_blend_pd(product_larger, moved, b.significand);
  scaled_eight r = normalized_eight(_mm512_fmadd_pd(a.significand, factor, addend),
                                    _mm512_mask_blend_pd(product_larger, c.exponent, product_exponent));
  const __mmask8 product_zero =
      _mm512_cmp_pd_mask(a.significand, zero, _CMP_EQ_OQ) | _mm512_cmp_pd_mask(b.significand, zero, _CMP_EQ_OQ);
  r.significand = _mm512_mask_mov_pd(r.significand, product_zero, c.significand);
  r.exponent = _mm512_mask_mov_pd(r.exponent, product_zero, c.exponent);
  return r;
}

// scaled<T>'s square_root: an even exponent halves exactly
CONTACT_BATCH_INLINE scaled_eight square_root(const scaled_eight& a) {
  const __m512d half_exponent = _mm512_mul_pd(a.exponent, _mm512_set1_pd(0.5));
  const __mmask8 odd = _mm512_cmp_pd_mask(half_exponent, _mm512_roundscale_pd(half_exponent, _MM_FROUND_TO_NEG_INF),
                                          _CMP_NEQ_UQ);
  const __mmask8 positive = _mm512_cmp_pd_mask(a.significand, _mm512_setzero_pd(), _CMP_GT_OQ);
  const __m512d m = _mm512_mask_mul_pd(a.significand, odd & positive, a.significand, _mm512_set1_pd(0.5));
  const __m512d exponent = _mm512_maskz_mov_pd(
      positive, _mm512_mask_add_pd(half_exponent, odd, half_exponent, _mm512_set1_pd(0.5)));
  return normalized_eight(_mm512_sqrt_pd(m), exponent);
}

// scaled<T>::value(): m 2^e rounded once, into the subnormals (e <= -1022,
// m in [0.5, 1): rounded_below_normal) or to infinity; the normal route's
// shift is clamped where it is not taken, so that no operation underflows, as
// an underflowing one costs a microcode assist (measured on far-apart lanes,
// far_eight alone: 19.5 -> 12.2 ns per lane).
CONTACT_BATCH_INLINE __m512d value_of(const scaled_eight& a) {
  constexpr double least_normal_exponent = std::numeric_limits<double>::min_exponent;  // 2^-1022 = 0.5 2^-1021
  const __mmask8 below_normal = _mm512_cmp_pd_mask(a.exponent, _mm512_set1_pd(least_normal_exponent), _CMP_LT_OQ);
  const __m512d normal =
      _mm512_scalef_pd(a.significand, _mm512_max_pd(a.exponent, _mm512_set1_pd(least_normal_exponent)));
  return _mm512_mask_blend_pd(below_normal, normal,
                              rounded_below_normal(below_normal, a.significand, _mm512_set1_pd(-1.0), a.exponent));
}

// scaled<T>'s two_sum: the rounded sum and its error; a term more than p + 1
// binades below the other is the error itself
CONTACT_BATCH_INLINE detail::exact_pair<scaled_eight> two_sum(const scaled_eight& a, const scaled_eight& b) {
  const __m512d zero = _mm512_setzero_pd();
  const __mmask8 a_larger = _mm512_cmp_pd_mask(a.exponent, b.exponent, _CMP_GE_OQ);
  const scaled_eight large = {_mm512_mask_blend_pd(a_larger, b.significand, a.significand),
                              _mm512_mask_blend_pd(a_larger, b.exponent, a.exponent)};
  const scaled_eight small = {_mm512_mask_blend_pd(a_larger, a.significand, b.significand),
                              _mm512_mask_blend_pd(a_larger, a.exponent, b.exponent)};
  const __m512d gap = _mm512_sub_pd(large.exponent, small.exponent);
  const __mmask8 near = _mm512_cmp_pd_mask(gap, _mm512_set1_pd(std::numeric_limits<double>::digits + 1), _CMP_LE_OQ);
  const __m512d moved = _mm512_maskz_mov_pd(
      near, _mm512_scalef_pd(small.significand, _mm512_xor_pd(_mm512_min_pd(gap, _mm512_set1_pd(64.0)), _mm512_set1_pd(-0.0))));
  const auto pair = detail::two_sum(large.significand, moved);
  detail::exact_pair<scaled_eight> r = {normalized_eight(pair.high, large.exponent),
                                        normalized_eight(pair.low, large.exponent)};
  r.high = {_mm512_mask_blend_pd(near, large.significand, r.high.significand),
            _mm512_mask_blend_pd(near, large.exponent, r.high.exponent)};
  r.low = {_mm512_mask_blend_pd(near, small.significand, r.low.significand),
           _mm512_mask_blend_pd(near, small.exponent, r.low.exponent)};
  const __mmask8 a_zero = _mm512_cmp_pd_mask(a.significand, zero, _CMP_EQ_OQ);
  const __mmask8 b_zero = _mm512_cmp_pd_mask(b.significand, zero, _CMP_EQ_OQ);
  const scaled_eight sum = a + b;
  r.high = {_mm512_mask_mov_pd(r.high.significand, a_zero | b_zero, sum.significand),
            _mm512_mask_mov_pd(r.high.exponent, a_zero | b_zero, sum.exponent)};
  r.low = {_mm512_maskz_mov_pd(__mmask8(~(a_zero | b_zero)), r.low.significand),
           _mm512_maskz_mov_pd(__mmask8(~(a_zero | b_zero)), r.low.exponent)};
  return r;
}

// far_eight's lanes: finite, non-zero u, dy and phi, phi > 0
CONTACT_BATCH_INLINE __mmask8 far_eligible(__m512d u, __m512d dy, __m512d phi) {
  constexpr int not_finite_or_zero = fpclass_not_finite | fpclass_zero;
  return __mmask8(~(_mm512_fpclass_pd_mask(u, not_finite_or_zero) | _mm512_fpclass_pd_mask(dy, not_finite_or_zero) |
                    _mm512_fpclass_pd_mask(phi, not_finite_or_zero))) &
         _mm512_cmp_pd_mask(phi, _mm512_setzero_pd(), _CMP_GT_OQ);
}

// The scaled path's decision for dy > 0 where one term's binade outweighs
// the others (sign_of_dominant_binade): the lanes of far_eight it answers as
// contact, and as release. Binades by getexp (subnormals included); |phi dy|
// lies in [2^(bp + bd), 2^(bp + bd + 2)).
struct far_decision {
  __mmask8 contact, release;
};

CONTACT_BATCH_INLINE far_decision decide_far_eight(__m512d u, __m512d dy, __m512d phi) {
  const __m512d one = _mm512_set1_pd(1.0), two = _mm512_set1_pd(2.0), zero = _mm512_setzero_pd();
  const __m512d u_least = _mm512_getexp_pd(u), dy_least = _mm512_getexp_pd(dy);
  const __m512d product_least = _mm512_add_pd(_mm512_getexp_pd(phi), dy_least);
  const __m512d u_bound = _mm512_add_pd(u_least, one), dy_bound = _mm512_add_pd(dy_least, one);
  const __m512d product_bound = _mm512_add_pd(product_least, two);
  const __mmask8 u_dominates = _mm512_cmp_pd_mask(u_least, _mm512_max_pd(dy_bound, product_bound), _CMP_GT_OQ);
  const __mmask8 dy_dominates = _mm512_cmp_pd_mask(dy_least, _mm512_max_pd(u_bound, product_bound), _CMP_GT_OQ);
  const __mmask8 product_dominates = _mm512_cmp_pd_mask(product_least, _mm512_max_pd(u_bound, dy_bound), _CMP_GT_OQ);
  const __mmask8 u_positive = _mm512_cmp_pd_mask(u, zero, _CMP_GT_OQ);
  const __mmask8 lanes = far_eligible(u, dy, phi) & _mm512_cmp_pd_mask(dy, zero, _CMP_GT_OQ);
  const __mmask8 stays = (u_dominates & u_positive) | dy_dominates;
  return {__mmask8(lanes & stays), __mmask8(lanes & ~stays & (u_dominates | product_dominates))};
}

// stable_form::contact on scaled numbers: (2 phi dy - u) / (1 + phi), clamped
CONTACT_BATCH_INLINE __m512d far_contact_eight(__m512d u_in, __m512d dy_in, __m512d phi_in) {
  const scaled_eight u = scaled_of_eight(u_in), dy = scaled_of_eight(dy_in), phi = scaled_of_eight(phi_in);
  const scaled_eight unit = {_mm512_set1_pd(0.5), _mm512_set1_pd(1.0)};  // scaled 1
  const scaled_eight contact = fused_multiply_add(phi, times_power_of_two(dy, 1), -u) / (unit + phi);
  return _mm512_min_pd(value_of(contact), dy_in);
}

// stable_form::release on scaled numbers: 2 phi dy^2 / (u + root) for u > 0,
// else (root - u) / 2; both sums are root + |u| (scaled sums commute), so one
// sum and one quotient. An infinite s from a root below 2^(max_exponent + 1)
// is `near_infinity`: only the exact test tells it from the largest double.
struct far_release_answers {
  __m512d s;
  __mmask8 near_infinity;
};

CONTACT_BATCH_INLINE far_release_answers far_release_eight(__m512d u_in, __m512d dy_in, __m512d phi_in) {
  const scaled_eight u = scaled_of_eight(u_in), dy = scaled_of_eight(dy_in), phi = scaled_of_eight(phi_in);
  const __m512d two = _mm512_set1_pd(2.0), sign_bit = _mm512_set1_pd(-0.0);
  const __mmask8 u_positive = _mm512_cmp_pd_mask(u_in, _mm512_setzero_pd(), _CMP_GT_OQ);
  const scaled_eight stiffness_term = (phi * dy) * dy;
  const scaled_eight root = square_root(fused_multiply_add(u, u, times_power_of_two(stiffness_term, 2)));
  const scaled_eight sum = root + scaled_eight{_mm512_andnot_pd(sign_bit, u.significand), u.exponent};
  const scaled_eight twice_stiffness = times_power_of_two(stiffness_term, 1);
  const scaled_eight numerator = {_mm512_mask_blend_pd(u_positive, sum.significand, twice_stiffness.significand),
                                  _mm512_mask_blend_pd(u_positive, sum.exponent, twice_stiffness.exponent)};
  const scaled_eight denominator = {_mm512_mask_blend_pd(u_positive, _mm512_set1_pd(0.5), sum.significand),
                                    _mm512_mask_blend_pd(u_positive, two, sum.exponent)};  // scaled 2, or the sum
  const scaled_eight release = numerator / denominator;
  const __m512d above_dy = _mm512_castsi512_pd(_mm512_add_epi64(_mm512_castpd_si512(dy_in), _mm512_set1_epi64(1)));
  const __m512d s = _mm512_max_pd(value_of(release), above_dy);
  return {s, __mmask8(_mm512_fpclass_pd_mask(s, 0x08) &
                      _mm512_cmp_pd_mask(release.exponent, _mm512_set1_pd(std::numeric_limits<double>::max_exponent + 1),
                                         _CMP_LE_OQ))};
}

// solve_cases<false> on eight lanes whose u, dy, phi are finite and
// non-zero, phi > 0 (free flight is answered before): the scaled path's
// formulas and clamps, for the impacts (dy < 0) or, without `impact_side`,
// for contact and release (dy > 0) with the scaled path's decision where one
// term's binade outweighs the others (sign_of_dominant_binade). One side at a
// time, as each formula costs some 300 instructions here. Leaves to the
// scalar path the other side's lanes, a lane the binades leave undecided, and
// a release root that rounds to infinity from within an ulp of the largest
// double (release_root_rounds_to_infinity decides those).
template <bool impact_side>
CONTACT_BATCH_INLINE eight_results far_eight(__m512d u_in, __m512d dy_in, __m512d phi_in) {
  if constexpr (impact_side) {
    const __mmask8 eligible = far_eligible(u_in, dy_in, phi_in);
    const scaled_eight u = scaled_of_eight(u_in), dy = scaled_of_eight(dy_in), phi = scaled_of_eight(phi_in);
    const __m512d zero = _mm512_setzero_pd(), sign_bit = _mm512_set1_pd(-0.0);
    const __m512i one_bit = _mm512_set1_epi64(1);
    const scaled_eight unit = {_mm512_set1_pd(0.5), _mm512_set1_pd(1.0)};  // scaled 1
    // stable_form::impact_with_square_root, gap = -dy: -N / D, N and D carried as exact pairs
    const __mmask8 impact =
        _mm512_cmp_pd_mask(dy_in, zero, _CMP_LT_OQ) & _mm512_cmp_pd_mask(u_in, _mm512_xor_pd(dy_in, sign_bit), _CMP_GT_OQ);
    const scaled_eight gap = -dy;
    const scaled_eight push = phi * gap;
    const scaled_eight push_error = fused_multiply_add(phi, gap, -push);
    const scaled_eight root = square_root(fused_multiply_add(u, u, times_power_of_two(push * (u + (-gap)), 2)));
    const auto head = two_sum(u, times_power_of_two(push, 1));
    const auto numerator = two_sum(head.high, root);
    const scaled_eight numerator_low = numerator.low + (head.low + times_power_of_two(push_error, 1));
    const auto one_plus_phi = two_sum(unit, phi);
    const scaled_eight denominator = times_power_of_two(one_plus_phi.high, 1);
    const scaled_eight inverse = unit / denominator;
    const scaled_eight quotient = numerator.high * inverse;
    const scaled_eight residual = fused_multiply_add(-quotient, denominator, numerator.high);
    const scaled_eight correction =
        fused_multiply_add(-quotient, one_plus_phi.low + one_plus_phi.low, residual + numerator_low);
    __m512d s = _mm512_xor_pd(value_of(fused_multiply_add(correction, inverse, quotient)), sign_bit);
    s = _mm512_max_pd(s, _mm512_xor_pd(u_in, sign_bit));  // impact_clamped
    s = _mm512_min_pd(s, _mm512_castsi512_pd(_mm512_add_epi64(_mm512_castpd_si512(_mm512_or_pd(dy_in, sign_bit)), one_bit)));
    return {s, _mm256_set1_epi32(int(contact_case::impact)), __mmask8(eligible & impact)};
  } else {
    const far_decision decision = decide_far_eight(u_in, dy_in, phi_in);
    const far_release_answers release = far_release_eight(u_in, dy_in, phi_in);
    const __mmask8 stays = decision.contact;
    const __m256i which = _mm256_mask_blend_epi32(stays, _mm256_set1_epi32(int(contact_case::release)),
                                                  _mm256_set1_epi32(int(contact_case::contact)));
    return {_mm512_mask_blend_pd(stays, release.s, far_contact_eight(u_in, dy_in, phi_in)), which,
            __mmask8(decision.contact | (decision.release & ~release.near_infinity))};  // (decide_far_eight's lanes are eligible)
  }
}

// The first `remaining` of eight lanes (all eight from 8 up): a batch's last vector.
CONTACT_BATCH_INLINE __mmask8 first_lanes(int remaining) {
  return remaining >= 8 ? __mmask8(0xFF) : __mmask8((1u << remaining) - 1);
}

// The left lanes of dy > 0, eight at a time: gathered, decided
// (decide_far_eight), and packed by case, so that each lane runs its own
// case's formula: both on every lane cost three divisions and square roots
// per vector where one case needs one or two, and far lanes wait on them
// (measured on the extreme scene's far lanes, the moved attempt included:
// 19.4 -> 15.3 ns per lane). Lanes the binades leave undecided, and a release
// root near the largest double, go to the scalar path.
struct far_packed {
  static constexpr int capacity = 256;
  alignas(64) double u[capacity + 8], dy[capacity + 8], phi[capacity + 8];  // room for a vector past the count
  alignas(64) std::int64_t index[capacity + 8];
  int count = 0;
  CONTACT_BATCH_INLINE void add(__mmask8 lanes, __m512d u_lanes, __m512d dy_lanes, __m512d phi_lanes, __m512i indices) {
    _mm512_storeu_pd(u + count, _mm512_maskz_compress_pd(lanes, u_lanes));
    _mm512_storeu_pd(dy + count, _mm512_maskz_compress_pd(lanes, dy_lanes));
    _mm512_storeu_pd(phi + count, _mm512_maskz_compress_pd(lanes, phi_lanes));
    _mm512_storeu_si512(index + count, _mm512_maskz_compress_epi64(lanes, indices));
    count += std::popcount(unsigned(lanes));
  }
  // each packed vector's answers, the lanes it answers, by `answer`; the rest by the scalar path
  template <class Answer>
  CONTACT_BATCH_INLINE void solve(const double* __restrict u_in, const double* __restrict dy_in, const double* __restrict phi_in,
                                  double* __restrict s, int* __restrict which, contact_case which_case, Answer answer) {
    for (int k = 0; k < count; k += 8) {
      const __mmask8 active = first_lanes(count - k);
      const __m512d one = _mm512_set1_pd(1.0);
      const __m512i lane_index = _mm512_maskz_loadu_epi64(active, index + k);
      const auto [lane_s, answered_lanes] = answer(_mm512_mask_loadu_pd(one, active, u + k),
                                                   _mm512_mask_loadu_pd(one, active, dy + k),
                                                   _mm512_mask_loadu_pd(one, active, phi + k));
      const __mmask8 answered = active & answered_lanes;
      _mm512_mask_i64scatter_pd(s, answered, lane_index, lane_s, 8);
      _mm512_mask_i64scatter_epi32(which, answered, lane_index, _mm256_set1_epi32(int(which_case)), 4);
      for (unsigned left = active & ~answered; left != 0; left &= left - 1)
        solve_scalar_lane(u_in, dy_in, phi_in, s, which, index[k + std::countr_zero(left)]);
    }
    count = 0;
  }
};

// The lanes the vectors leave, by index, solved out of line a batch at a
// time (solve_left_lanes).
struct left_lanes {
  static constexpr int capacity = 256;
  alignas(64) std::int64_t index[capacity + 8];  // room for a whole vector written past the count
  int count = 0;
  CONTACT_BATCH_INLINE void add(__mmask8 lanes, __m512i indices) {
    _mm512_storeu_si512(index + count, _mm512_maskz_compress_epi64(lanes, indices));
    count += std::popcount(unsigned(lanes));
  }
};

// Eight at a time, gathered, by far_eight of their side (most of them: u and
// dy too far apart for any band), and the scalar path for what that cannot
// answer; for dy > 0 packed by case first (far_packed).
template <bool impact_side>
[[gnu::noinline]] void solve_left_lanes(const double* __restrict u, const double* __restrict dy,
                                               const double* __restrict phi, double* __restrict s,
                                               int* __restrict which, left_lanes& lanes) {
  const __m512d one = _mm512_set1_pd(1.0);
  [[maybe_unused]] far_packed contacts, releases;
  for (int k = 0; k < lanes.count; k += 8) {
    const __mmask8 active = first_lanes(lanes.count - k);
    const __m512i index = _mm512_maskz_loadu_epi64(active, lanes.index + k);
    const __m512d u_lanes = _mm512_mask_i64gather_pd(one, active, index, u, 8),
                  dy_lanes = _mm512_mask_i64gather_pd(one, active, index, dy, 8),
                  phi_lanes = _mm512_mask_i64gather_pd(one, active, index, phi, 8);
    __mmask8 answered;
    if constexpr (impact_side) {
      const eight_results r = far_eight<true>(u_lanes, dy_lanes, phi_lanes);
      answered = active & r.answered;
      _mm512_mask_i64scatter_pd(s, answered, index, r.s, 8);
      _mm512_mask_i64scatter_epi32(which, answered, index, r.which, 4);
    } else {
      const far_decision decision = decide_far_eight(u_lanes, dy_lanes, phi_lanes);
      contacts.add(active & decision.contact, u_lanes, dy_lanes, phi_lanes, index);
      releases.add(active & decision.release, u_lanes, dy_lanes, phi_lanes, index);
      answered = active & (decision.contact | decision.release);
    }
    for (unsigned left = active & ~answered; left != 0; left &= left - 1)
      solve_scalar_lane(u, dy, phi, s, which, lanes.index[k + std::countr_zero(left)]);
  }
  if constexpr (!impact_side) {
    contacts.solve(u, dy, phi, s, which, contact_case::contact, [](__m512d u_lanes, __m512d dy_lanes, __m512d phi_lanes) {
      return std::pair{far_contact_eight(u_lanes, dy_lanes, phi_lanes), __mmask8(0xFF)};
    });
    releases.solve(u, dy, phi, s, which, contact_case::release, [](__m512d u_lanes, __m512d dy_lanes, __m512d phi_lanes) {
      const far_release_answers r = far_release_eight(u_lanes, dy_lanes, phi_lanes);
      return std::pair{r.s, __mmask8(~r.near_infinity)};
    });
  }
  lanes.count = 0;
}

// The same lanes with AVX-512 written out, for double: the operations of lane()
// in the same order, with the masks in mask registers. Measured on Zen 5, in
// cache, against the vectorised lane() at about 1.0 ns per lane:
// - each selection, clamp and case test is one instruction (about 65 per 8
//   lanes against about 95): about 0.85 ns;
// - the square root of the next 8 lanes is issued before the division of
//   these 8 (both run on one unit, and out-of-order execution alone does not
//   overlap them across iterations): about 0.76 ns.
// A vector with a lane outside the window runs moved (moved_operands) in the
// same loop, its move issued a vector earlier still (measured 3% faster on
// the extreme scene, and no slower on the physical one), and its lanes that
// even that cannot answer are noted for solve_left_lanes, out of line.
inline void solve_lanes_avx512(const double* __restrict u_in, const double* __restrict dy_in, const double* __restrict phi_in,
                      double* __restrict s_out, int* __restrict which_out, std::ptrdiff_t n) {
  const __m512i sign_bits = _mm512_set1_epi64(std::int64_t(sign_mask<double>));
  const __m512i lowest_uv = _mm512_set1_epi64(std::int64_t(detail::common_window_lowest_uv<double>));  // 2^L
  const __m512i lowest_phi = _mm512_set1_epi64(std::int64_t(detail::common_window_lowest_phi<double>));  // 2^M
  const __m512i width = _mm512_set1_epi64(std::int64_t(detail::common_window_width<double>));
  auto prepare = [&](std::ptrdiff_t j) __attribute__((always_inline)) {
    const __m512d u = _mm512_loadu_pd(u_in + j), dy = _mm512_loadu_pd(dy_in + j), phi = _mm512_loadu_pd(phi_in + j);
    // inside_window()'s test: the OR of the three offsets from the window's
    // lower ends (a negative or NaN phi fails it)
    const __m512i spread =
        _mm512_ternarylogic_epi64(_mm512_sub_epi64(_mm512_andnot_si512(sign_bits, _mm512_castpd_si512(u)), lowest_uv),
                                  _mm512_sub_epi64(_mm512_andnot_si512(sign_bits, _mm512_castpd_si512(dy)), lowest_uv),
                                  _mm512_sub_epi64(_mm512_castpd_si512(phi), lowest_phi), 0xFE);
    const __mmask8 inside = _mm512_cmplt_epu64_mask(spread, width);
    eight_operands l;
    if (inside == 0xFF) [[likely]] {
      l.u = u;
      l.dy = l.dy_factor = dy;
      l.phi = l.phi_factor = phi;
      l.shift = _mm512_setzero_pd();
      l.phi_moved = 0;
      l.answerable = 0xFF;
      l.free_flight = 0;  // (the plain answers hold it)
      l.moved = false;
    } else {
      l = moved_operands(u, dy, phi, inside);
    }
    return l;
  };
  std::ptrdiff_t i = 0;
  eight_operands next{}, after{};
  if (n >= 8) {
    next = prepare(0);
    next.terms = first_terms(next.u, next.dy, next.phi_factor, next.dy_factor);
  }
  if (n >= 16) after = prepare(8);
  left_lanes left_impacts, left_others;  // dy < 0, and the rest
  const __m512i lane_numbers = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
  for (; i + 8 <= n; i += 8) {
    const eight_operands l = next;
    // a pipeline of three: the lanes two vectors on are moved, the next
    // vector's square root is issued, before this one's division
    if (i + 16 <= n) {
      next = after;
      next.terms = first_terms(next.u, next.dy, next.phi_factor, next.dy_factor);
    }
    if (i + 24 <= n) after = prepare(i + 16);
    const eight_answers answers = solve_operands(l);
    if (!l.moved) [[likely]] {
      _mm512_storeu_pd(s_out + i, answers.s);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(which_out + i), answers.which);
      continue;
    }
    const eight_results r = moved_back_eight(l, answers, _mm512_loadu_pd(u_in + i), _mm512_loadu_pd(dy_in + i));
    _mm512_storeu_pd(s_out + i, r.s);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(which_out + i), r.which);
    // without a branch on whether there are any: on the wide scenes that is a coin toss
    const __m512i indices = _mm512_add_epi64(_mm512_set1_epi64(i), lane_numbers);
    const __mmask8 impact_side = _mm512_cmp_pd_mask(_mm512_loadu_pd(dy_in + i), _mm512_setzero_pd(), _CMP_LT_OQ);
    left_impacts.add(__mmask8(~r.answered & impact_side), indices);
    left_others.add(__mmask8(~r.answered & ~impact_side), indices);
    if (left_impacts.count > left_lanes::capacity - 8)
      solve_left_lanes<true>(u_in, dy_in, phi_in, s_out, which_out, left_impacts);
    if (left_others.count > left_lanes::capacity - 8)
      solve_left_lanes<false>(u_in, dy_in, phi_in, s_out, which_out, left_others);
  }
  if (left_impacts.count != 0) solve_left_lanes<true>(u_in, dy_in, phi_in, s_out, which_out, left_impacts);
  if (left_others.count != 0) solve_left_lanes<false>(u_in, dy_in, phi_in, s_out, which_out, left_others);
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
