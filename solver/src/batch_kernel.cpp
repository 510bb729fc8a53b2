// The batch kernel of solve_batch for one instruction set: this file is
// compiled once per target with that target's flags (solver/CMakeLists.txt),
// into the namespace contact::batch_kernels::CONTACT_BATCH_KERNEL_NAME, on
// Highway's vectors. The formulas, the pre-test, the exact decision and the
// clamps are stable.hpp's own templates, instantiated on `lanes` (below):
// every lane runs the operations solve_stable runs for it, so every answered
// lane is solve_stable's answer bit for bit.
//
// Two passes over each block of lanes. The first decides each lane's case and
// answers free flight (any valid input) and, in the stable mode, the contacts
// inside the common window (one division, on every lane of the vector); it
// packs the other lanes by case, as they are inside the common window, or
// moved by a power of two into phi's band box (the moved stage of
// solve_stable), those outside the window once the block's others are packed.
// The second solves each pack in whole vectors by its case's formula alone
// (two vectors at a time in the stable mode) and moves s back; a last vector
// that a block leaves part-filled waits for the next block's lanes. The far
// lanes (u and dy too far apart for phi's band: solve_stable's exact stage)
// run on scaled_lanes. The rest (a subnormal phi in float, a zero u or dy, a
// far lane whose case the binades leave open, an s that underflows or
// overflows once moved back, invalid input) go to solve_stable, one by one.
#include <hwy/cache_control.h>
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "batch_kernels.hpp"
#include "contact/rounded.hpp"
#include "contact/stable.hpp"

namespace contact::batch_kernels::CONTACT_BATCH_KERNEL_NAME {

namespace hn = hwy::HWY_NAMESPACE;

std::int64_t highway_target() { return HWY_STATIC_TARGET; }

// Internal linkage: whatever this file instantiates on its lanes stays its own.
namespace {

template <class D>
struct lane_mask {
  hn::Mask<D> m;
};

template <class D>
HWY_INLINE lane_mask<D> operator!(lane_mask<D> a) { return {hn::Not(a.m)}; }
template <class D>
HWY_INLINE lane_mask<D> operator&(lane_mask<D> a, lane_mask<D> b) { return {hn::And(a.m, b.m)}; }
template <class D>
HWY_INLINE lane_mask<D> operator|(lane_mask<D> a, lane_mask<D> b) { return {hn::Or(a.m, b.m)}; }

// One vector of float or double lanes, with the arithmetic of a scalar, so
// that stable.hpp's templates take it as their Num (detail::lane_vector).
template <class D>
struct lanes {
  using lane_scalar = hn::TFromD<D>;
  hn::Vec<D> v;
  lanes() = default;
  lanes(hn::Vec<D> x) : v(x) {}
  explicit lanes(lane_scalar x) : v(hn::Set(D(), x)) {}
  explicit lanes(int x) : v(hn::Set(D(), lane_scalar(x))) {}
};

template <class D>
HWY_INLINE lanes<D> operator+(lanes<D> a, lanes<D> b) { return hn::Add(a.v, b.v); }
template <class D>
HWY_INLINE lanes<D> operator-(lanes<D> a, lanes<D> b) { return hn::Sub(a.v, b.v); }
template <class D>
HWY_INLINE lanes<D> operator*(lanes<D> a, lanes<D> b) { return hn::Mul(a.v, b.v); }
template <class D>
HWY_INLINE lanes<D> operator/(lanes<D> a, lanes<D> b) { return hn::Div(a.v, b.v); }
template <class D>
HWY_INLINE lanes<D> operator-(lanes<D> a) { return hn::Neg(a.v); }
template <class D>
HWY_INLINE lane_mask<D> operator<(lanes<D> a, lanes<D> b) { return {hn::Lt(a.v, b.v)}; }
template <class D>
HWY_INLINE lane_mask<D> operator>(lanes<D> a, lanes<D> b) { return {hn::Gt(a.v, b.v)}; }
template <class D>
HWY_INLINE lane_mask<D> operator<=(lanes<D> a, lanes<D> b) { return {hn::Le(a.v, b.v)}; }
template <class D>
HWY_INLINE lane_mask<D> operator>=(lanes<D> a, lanes<D> b) { return {hn::Ge(a.v, b.v)}; }
template <class D>
HWY_INLINE lane_mask<D> operator!=(lanes<D> a, lanes<D> b) { return {hn::Ne(a.v, b.v)}; }

// The operations stable.hpp calls unqualified (found here by argument-dependent lookup).
template <class D>
HWY_INLINE lanes<D> fused_multiply_add(lanes<D> a, lanes<D> b, lanes<D> c) { return hn::MulAdd(a.v, b.v, c.v); }
template <class D>
HWY_INLINE lanes<D> fma(lanes<D> a, lanes<D> b, lanes<D> c) { return hn::MulAdd(a.v, b.v, c.v); }
template <class D>
HWY_INLINE lanes<D> square_root(lanes<D> a) { return hn::Sqrt(a.v); }
template <class D>
HWY_INLINE lanes<D> fabs(lanes<D> a) { return hn::Abs(a.v); }
template <class D>
HWY_INLINE lanes<D> select(lane_mask<D> condition, lanes<D> if_true, lanes<D> if_false) {
  return hn::IfThenElse(condition.m, if_true.v, if_false.v);
}
// a < b ? a : b and a > b ? a : b, lane by lane, as detail::min_of and max_of
// (x86's min and max are exactly these, NaN and zeros included)
template <class D>
HWY_INLINE lanes<D> min_of(lanes<D> a, lanes<D> b) {
#if HWY_ARCH_X86
  return hn::Min(a.v, b.v);
#else
  return hn::IfThenElse(hn::Lt(a.v, b.v), a.v, b.v);
#endif
}
template <class D>
HWY_INLINE lanes<D> max_of(lanes<D> a, lanes<D> b) {
#if HWY_ARCH_X86
  return hn::Max(a.v, b.v);
#else
  return hn::IfThenElse(hn::Gt(a.v, b.v), a.v, b.v);
#endif
}

// detail::with_sign_bit and detail::step_away_from_zero on the lanes' bits
template <class D>
HWY_INLINE lanes<D> with_sign_bit(lanes<D> x) {
  return hn::Or(x.v, hn::Set(D(), hn::TFromD<D>(-0.0)));
}
template <class D>
HWY_INLINE lanes<D> step_away_from_zero(lanes<D> x) {
  const hn::RebindToUnsigned<D> du;
  return hn::BitCast(D(), hn::Add(hn::BitCast(du, x.v), hn::Set(du, 1)));
}

// detail::subnormal_phi_factors on lanes: (phi 2^64, x 2^-64), phi 2^64 from
// phi's bits, an integer that converts exactly
template <class D>
HWY_INLINE detail::normal_factors<lanes<D>> subnormal_phi_factors(lanes<D> phi, lanes<D> x) {
  using T = hn::TFromD<D>;
  constexpr T up = T(0x1p64), down = T(0x1p-64);
  const lanes<D> phi_up = hn::ConvertTo(D(), hn::BitCast(hn::RebindToSigned<D>(), phi.v));
  return {phi_up * lanes<D>(std::numeric_limits<T>::denorm_min() * up), x * lanes<D>(down), lanes<D>(down), true};
}

// a < b on unsigned lanes, as a signed comparison of a and b with their top bits flipped
template <class DU>
HWY_INLINE hn::Mask<DU> unsigned_less(DU du, hn::Vec<DU> a, hn::Vec<DU> b) {
  using U = hn::TFromD<DU>;
  const hn::RebindToSigned<DU> di;
  const auto top = hn::Set(du, U(U(1) << (sizeof(U) * 8 - 1)));
  return hn::RebindMask(du, hn::Lt(hn::BitCast(di, hn::Xor(a, top)), hn::BitCast(di, hn::Xor(b, top))));
}

// A non-negative finite magnitude (bits) as a normal value of T's lanes of
// the same significand, and the exponent field the magnitude would have with
// an unbounded exponent range: a subnormal's significand field is an integer
// k, which converts exactly, and the magnitude is k 2^-(bias - 1 +
// significand_bits) (as scaled<T> reads it; a product by a power of two would
// cost a microcode assist). Zero reads as zero, of field 0 - that offset.
// The exponent field of a magnitude's bits (sign bit clear), as signed lanes.
template <class D>
HWY_INLINE hn::Vec<hn::RebindToSigned<D>> field_of_magnitude(D, hn::Vec<hn::RebindToUnsigned<D>> magnitude) {
  return hn::BitCast(hn::RebindToSigned<D>(), hn::ShiftRight<detail::binary_layout<hn::TFromD<D>>::significand_bits>(magnitude));
}

template <class D>
struct normal_reading {
  hn::Vec<D> value;
  hn::Vec<hn::RebindToSigned<D>> field;
};

template <class D>
HWY_INLINE normal_reading<D> read_normal(D d, hn::Vec<hn::RebindToUnsigned<D>> magnitude) {
  using layout = detail::binary_layout<hn::TFromD<D>>;
  using U = typename layout::bits;
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  constexpr int integer_offset = layout::bias - 1 + layout::significand_bits;
  const auto subnormal = hn::RebindMask(d, hn::Not(unsigned_less(du, hn::Set(du, U(layout::least_normal - 1)), magnitude)));
  const auto value = hn::IfThenElse(subnormal, hn::ConvertTo(d, hn::BitCast(di, magnitude)), hn::BitCast(d, magnitude));
  const auto field = field_of_magnitude(d, hn::BitCast(du, value));
  return {value, hn::IfThenElse(hn::RebindMask(di, subnormal), hn::Sub(field, hn::Set(di, integer_offset)), field)};
}

// detail::scaled<T> on lanes: a significand of T's lanes in [0.5, 1) (or 0)
// and an exponent of integer lanes of T's width, for the lanes too far apart
// for any band, which solve_stable takes to its exact stage. Each operation
// below is scaled<T>'s, written with selects instead of branches, and gives
// its significand and exponent bit for bit: the significand operations are
// T's, and the moves by powers of two round once where scaled<T>::shifted
// does (a product by a normal power of two, exact unless its result is
// subnormal, rounds once as ldexp does). A lane whose operands leave what
// these cover (a NaN or infinite significand) ends with a NaN significand,
// and solve_stable takes it.
template <class D>
struct scaled_lanes {
  using lane_scalar = hn::TFromD<D>;  // a lane_vector: stable_form selects on it instead of branching
  using T = lane_scalar;
  using layout = detail::binary_layout<T>;
  using U = typename layout::bits;
  // The exponent is an integer held in T's own lanes (exact: far below
  // 2^digits), so that its sums, comparisons and selects are T's, which every
  // target has for 64-bit lanes, where AVX2 lacks 64-bit integer min, max and
  // arithmetic shifts.
  hn::Vec<D> significand, exponent;

  scaled_lanes() = default;
  scaled_lanes(hn::Vec<D> m, hn::Vec<D> e) : significand(m), exponent(e) {}
  explicit scaled_lanes(lanes<D> x) : scaled_lanes(normalized<true>(x.v, hn::Zero(D()))) {}
  explicit scaled_lanes(int x) : scaled_lanes(lanes<D>(x)) {}

  static constexpr int significand_bits = layout::significand_bits;
  static constexpr T half_field = T(layout::bias - 1);  // the exponent field of a significand in [0.5, 1)
  static constexpr int lift = std::numeric_limits<T>::digits + 11;  // 2^-lift moves a product down by one rounding
  // An integer n, |n| < 2^(significand_bits - 1), plus `integral` has n + 2^(significand_bits - 1)
  // as its significand field: the integer's bits are read off (and written into) that field.
  static constexpr T integral = T(3) * T(U(1) << (significand_bits - 1));

  static HWY_INLINE hn::Vec<D> set(T x) { return hn::Set(D(), x); }
  // n 2^significand_bits as bits, two's complement (the offset 2^(significand_bits - 1)
  // moves out beyond the top bit)
  static HWY_INLINE hn::Vec<hn::RebindToUnsigned<D>> field_bits(hn::Vec<D> n) {
    return hn::ShiftLeft<significand_bits>(hn::BitCast(hn::RebindToUnsigned<D>(), hn::Add(n, set(integral))));
  }
  static HWY_INLINE hn::Vec<D> power_of_two(hn::Vec<D> k) { return hn::BitCast(D(), field_bits(hn::Add(k, set(T(layout::bias))))); }
  static HWY_INLINE hn::Vec<D> field_of(hn::Vec<D> x) {  // the exponent field of x's bits, as a value
    const hn::RebindToUnsigned<D> du;
    const auto field = hn::And(hn::ShiftRight<significand_bits>(hn::BitCast(du, x)), hn::Set(du, U(layout::exponent_field)));
    return hn::Sub(hn::BitCast(D(), hn::Or(field, hn::BitCast(du, set(integral)))), set(integral));
  }

  // scaled<T>::normalized(m, e): zero, infinity and NaN keep their
  // significand and get exponent 0; a subnormal m = k 2^-offset is read as
  // the integer k (read_normal), as scaled<T> reads it. Only an input can be
  // subnormal: a sum or an fma of aligned significands in [0.5, 1) is zero
  // or a multiple of 2^-(3 digits + 4), far above the subnormals.
  template <bool may_be_subnormal = false>
  static HWY_INLINE scaled_lanes normalized(hn::Vec<D> m, hn::Vec<D> e) {
    const D d;
    const hn::RebindToUnsigned<D> du;
    auto field = field_of(m);
    const auto subnormal = hn::And(hn::Eq(field, hn::Zero(d)), hn::Ne(m, hn::Zero(d)));
    if (may_be_subnormal && !hn::AllFalse(d, subnormal)) [[unlikely]] {
      constexpr int integer_offset = layout::bias - 1 + significand_bits;
      m = hn::IfThenElse(subnormal, hn::CopySignToAbs(read_normal(d, hn::AndNot(hn::Set(du, layout::sign), hn::BitCast(du, m))).value, m), m);
      e = hn::IfThenElse(subnormal, hn::Sub(e, set(T(integer_offset))), e);
      field = field_of(m);
    }
    const auto kept = hn::Or(hn::Eq(field, hn::Zero(d)), hn::Eq(field, set(T(layout::exponent_field))));  // zero, infinity, NaN
    const auto cleared = hn::AndNot(hn::Set(du, U(U(layout::exponent_field) << significand_bits)), hn::BitCast(du, m));
    const auto in_half = hn::BitCast(d, hn::Or(cleared, hn::Set(du, U(U(layout::bias - 1) << significand_bits))));
    return {hn::IfThenElse(kept, m, in_half), hn::IfThenElseZero(hn::Not(kept), hn::Add(e, hn::Sub(field, set(half_field))))};
  }

  // A significand aligned to a term `shift` <= 0 binades above it, where it
  // is added to that term (or to a product of two significands, in an fma):
  // x 2^shift, exact, down to 2^-(2 digits + 4). Below that the sum rounds as
  // it would with scaled<T>::shifted's tiny or subnormal value, as both lie
  // below half the least bit of the other term's exact value (2^-(2 digits) of
  // a product): the sum depends only on the sign of a non-zero one. Where
  // scaled<T>::shifted rounds x 2^shift to zero (`to_zero`), an fma must add
  // zero instead. No operand or result here is subnormal, which would cost
  // each vector a microcode assist.
  static HWY_INLINE hn::Vec<D> aligned(hn::Vec<D> x, hn::Vec<D> shift) {
    return hn::Mul(x, power_of_two(hn::Max(shift, set(T(-2 * std::numeric_limits<T>::digits - 4)))));
  }
  static HWY_INLINE hn::Mask<D> to_zero(hn::Vec<D> x, hn::Vec<D> shift) {
    constexpr T least = T(std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits);
    // x 2^shift <= 2^(least - 1), half the least subnormal: the tie goes to the even zero
    return hn::Or(hn::Lt(shift, set(least)), hn::And(hn::Eq(shift, set(least)), hn::Eq(hn::Abs(x), set(T(0.5)))));
  }

  // scaled<T>::shifted(x, shift) for shift <= 0: x 2^shift, rounded once (a
  // product by 2^(shift + lift), exact and normal, then by 2^-lift: the
  // vectors that hold such a lane pay an assist), zero where to_zero
  static HWY_INLINE hn::Vec<D> shifted_down(hn::Vec<D> x, hn::Vec<D> shift) {
    constexpr T least = T(std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits);
    const auto k = hn::Min(hn::Max(shift, set(least)), hn::Zero(D()));
    const auto rounded = hn::Mul(hn::Mul(x, power_of_two(hn::Add(k, set(T(lift))))), power_of_two(set(T(-lift))));
    return hn::IfThenElse(to_zero(x, shift), hn::CopySignToAbs(hn::Zero(D()), x), rounded);
  }

  // scaled<T>::value(): m 2^e in T, rounded once: a normal result on the
  // exponent field, a subnormal one (or zero) by shifted_down, infinity
  // beyond the largest binade
  HWY_INLINE hn::Vec<D> value() const {
    const D d;
    const hn::RebindToUnsigned<D> du;
    const auto least = set(T(std::numeric_limits<T>::min_exponent)), largest = set(T(std::numeric_limits<T>::max_exponent));
    auto finite = hn::BitCast(d, hn::Add(hn::BitCast(du, significand), field_bits(exponent)));
    const auto below_normal = hn::Lt(exponent, least);
    if (!hn::AllFalse(d, below_normal)) [[unlikely]]
      finite = hn::IfThenElse(below_normal, shifted_down(significand, hn::Min(exponent, hn::Zero(d))), finite);
    const auto infinite = hn::CopySignToAbs(set(std::numeric_limits<T>::infinity()), significand);
    return hn::IfThenElse(hn::Or(lost(), hn::Eq(significand, hn::Zero(d))), significand,
                          hn::IfThenElse(hn::Gt(exponent, largest), infinite, finite));
  }

  // the lanes this representation did not carry (a NaN or infinite significand)
  HWY_INLINE hn::Mask<D> lost() const { return hn::Not(hn::IsFinite(significand)); }

  friend HWY_INLINE scaled_lanes select(lane_mask<D> condition, scaled_lanes a, scaled_lanes b) {
    return {hn::IfThenElse(condition.m, a.significand, b.significand), hn::IfThenElse(condition.m, a.exponent, b.exponent)};
  }
  friend HWY_INLINE scaled_lanes operator-(scaled_lanes a) { return {hn::Neg(a.significand), a.exponent}; }
  // A product of two significands lies in [0.25, 1) and a quotient in
  // (0.5, 2) (each rounds to neither end): normalized by one step, which
  // keeps the chain of dependent operations short; a zero gets exponent 0,
  // and NaN and infinity stay.
  friend HWY_INLINE scaled_lanes operator*(scaled_lanes a, scaled_lanes b) {
    const D d;
    const auto product = hn::Mul(a.significand, b.significand);
    const auto low = hn::Lt(hn::Abs(product), set(T(0.5)));
    return {hn::IfThenElse(low, hn::Add(product, product), product),
            hn::IfThenElseZero(hn::Ne(product, hn::Zero(d)), hn::Sub(hn::Add(a.exponent, b.exponent), hn::IfThenElseZero(low, set(T(1)))))};
  }
  friend HWY_INLINE scaled_lanes operator/(scaled_lanes a, scaled_lanes b) {
    const D d;
    const auto quotient = hn::Div(a.significand, b.significand);
    const auto high = hn::Ge(hn::Abs(quotient), set(T(1)));
    return {hn::IfThenElse(high, hn::Mul(quotient, set(T(0.5))), quotient),
            hn::IfThenElseZero(hn::Ne(quotient, hn::Zero(d)), hn::Add(hn::Sub(a.exponent, b.exponent), hn::IfThenElseZero(high, set(T(1)))))};
  }
  // both aligned to the larger exponent (one of them by 2^0); a zero term gives the other
  friend HWY_INLINE scaled_lanes operator+(scaled_lanes a, scaled_lanes b) {
    const D d;
    const auto top = hn::Max(a.exponent, b.exponent);
    const scaled_lanes sum = normalized(hn::Add(aligned(a.significand, hn::Sub(a.exponent, top)), aligned(b.significand, hn::Sub(b.exponent, top))), top);
    return select(lane_mask<D>{hn::Eq(b.significand, hn::Zero(d))}, a, select(lane_mask<D>{hn::Eq(a.significand, hn::Zero(d))}, b, sum));
  }
  friend HWY_INLINE scaled_lanes operator-(scaled_lanes a, scaled_lanes b) { return a + (-b); }
  friend HWY_INLINE lane_mask<D> operator>(scaled_lanes a, scaled_lanes b) { return {hn::Gt((a - b).significand, hn::Zero(D()))}; }

  // a b + c rounded once: c aligned to the product, or the product's second
  // factor to c where c is the larger; a zero factor gives c
  friend HWY_INLINE scaled_lanes fused_multiply_add(scaled_lanes a, scaled_lanes b, scaled_lanes c) {
    const D d;
    const auto product_exponent = hn::Add(a.exponent, b.exponent);
    const auto c_larger = hn::And(hn::Lt(product_exponent, c.exponent), hn::Ne(c.significand, hn::Zero(d)));
    // (a zero c, of exponent 0, may lie above the product: it stays zero)
    const auto smaller = hn::IfThenElse(c_larger, b.significand, c.significand);
    const auto shift = hn::Min(hn::IfThenElse(c_larger, hn::Sub(product_exponent, c.exponent), hn::Sub(c.exponent, product_exponent)),
                               hn::Zero(d));
    // an addend that scaled<T> rounds to zero is zero; a factor whose product
    // lies below a quarter of c's ulp leaves c as it is either way
    const auto moved = hn::IfThenElse(to_zero(smaller, shift), hn::CopySignToAbs(hn::Zero(d), smaller), aligned(smaller, shift));
    const scaled_lanes fused = normalized(hn::MulAdd(a.significand, hn::IfThenElse(c_larger, moved, b.significand),
                                                     hn::IfThenElse(c_larger, c.significand, moved)),
                                          hn::IfThenElse(c_larger, c.exponent, product_exponent));
    const auto zero_factor = hn::Or(hn::Eq(a.significand, hn::Zero(d)), hn::Eq(b.significand, hn::Zero(d)));
    return select(lane_mask<D>{zero_factor}, c, fused);
  }

  // rounded to nearest: an odd exponent moves the significand into [0.25, 0.5)
  friend HWY_INLINE scaled_lanes square_root(scaled_lanes a) {
    const D d;
    const hn::RebindToUnsigned<D> du;
    const auto odd = hn::RebindMask(d, hn::Ne(hn::And(hn::BitCast(du, hn::Add(a.exponent, set(integral))), hn::Set(du, U(1))), hn::Zero(du)));
    const auto m = hn::IfThenElse(odd, hn::Mul(a.significand, set(T(0.5))), a.significand);
    const auto even = hn::IfThenElse(odd, hn::Add(a.exponent, set(T(1))), a.exponent);
    // the root of [0.25, 1) lies in [0.5, 1); of zero, zero, and of a negative, NaN (exponent 0)
    const auto non_positive = hn::Le(a.significand, hn::Zero(d));
    return {hn::Sqrt(hn::IfThenElse(non_positive, a.significand, m)), hn::IfThenElseZero(hn::Not(non_positive), hn::Mul(even, set(T(0.5))))};
  }

  // detail::two_sum on scaled<T>: one alignment; the smaller below half an
  // ulp of the larger is the error itself; a zero term gives the sum and zero
  friend HWY_INLINE detail::exact_pair<scaled_lanes> two_sum(scaled_lanes a, scaled_lanes b) {
    const D d;
    const auto a_larger = lane_mask<D>{hn::Ge(a.exponent, b.exponent)};
    const scaled_lanes large = select(a_larger, a, b), small = select(a_larger, b, a);
    const auto gap = hn::Sub(large.exponent, small.exponent);
    const auto pair = detail::two_sum(lanes<D>(large.significand), lanes<D>(aligned(small.significand, hn::Neg(gap))));
    const scaled_lanes high = normalized(pair.high.v, large.exponent), low = normalized(pair.low.v, large.exponent);
    const auto apart = lane_mask<D>{hn::Gt(gap, set(T(std::numeric_limits<T>::digits + 1)))};
    const auto zero_term = lane_mask<D>{hn::Or(hn::Eq(a.significand, hn::Zero(d)), hn::Eq(b.significand, hn::Zero(d)))};
    return {select(zero_term, select(lane_mask<D>{hn::Eq(a.significand, hn::Zero(d))}, b, a), select(apart, large, high)),
            select(zero_term, scaled_lanes(hn::Zero(d), hn::Zero(d)), select(apart, small, low))};
  }
};

// Two vectors as one number: each operation runs on the first, then on the
// second. A root's formula (on lanes, or on scaled_lanes for a far lane) is
// one long chain of dependent operations, which a vector alone runs mostly
// waiting on each result; two chains side by side fill those waits. (The
// masks of its comparisons are a twin of masks.)
template <class X>
struct twin {
  X first, second;
};

template <class X>
struct twin_number : twin<X> {
  using lane_scalar = typename X::lane_scalar;
  twin_number() = default;
  twin_number(X a, X b) : twin<X>{a, b} {}
  explicit twin_number(int x) : twin<X>{X(x), X(x)} {}
  template <class Y>
  explicit twin_number(const twin_number<Y>& y) : twin<X>{X(y.first), X(y.second)} {}
};

template <class X>
HWY_INLINE twin_number<X> operator+(const twin_number<X>& a, const twin_number<X>& b) { return {a.first + b.first, a.second + b.second}; }
template <class X>
HWY_INLINE twin_number<X> operator-(const twin_number<X>& a, const twin_number<X>& b) { return {a.first - b.first, a.second - b.second}; }
template <class X>
HWY_INLINE twin_number<X> operator*(const twin_number<X>& a, const twin_number<X>& b) { return {a.first * b.first, a.second * b.second}; }
template <class X>
HWY_INLINE twin_number<X> operator/(const twin_number<X>& a, const twin_number<X>& b) { return {a.first / b.first, a.second / b.second}; }
template <class X>
HWY_INLINE twin_number<X> operator-(const twin_number<X>& a) { return {-a.first, -a.second}; }
template <class X>
HWY_INLINE auto operator>(const twin_number<X>& a, const twin_number<X>& b) {
  return twin<decltype(a.first > b.first)>{a.first > b.first, a.second > b.second};
}
template <class M, class X>
HWY_INLINE twin_number<X> select(const twin<M>& condition, const twin_number<X>& a, const twin_number<X>& b) {
  return {select(condition.first, a.first, b.first), select(condition.second, a.second, b.second)};
}
template <class X>
HWY_INLINE twin_number<X> fused_multiply_add(const twin_number<X>& a, const twin_number<X>& b, const twin_number<X>& c) {
  return {fused_multiply_add(a.first, b.first, c.first), fused_multiply_add(a.second, b.second, c.second)};
}
template <class X>
HWY_INLINE twin_number<X> square_root(const twin_number<X>& a) { return {square_root(a.first), square_root(a.second)}; }
template <class X>
HWY_INLINE detail::exact_pair<twin_number<X>> two_sum(const twin_number<X>& a, const twin_number<X>& b) {
  using detail::two_sum;
  auto x = two_sum(a.first, b.first), y = two_sum(a.second, b.second);
  return {{x.high, y.high}, {x.low, y.low}};
}
// f on the first halves, then on the second: a twin of its results
template <class F, class... X>
HWY_INLINE auto each_half(F f, const twin_number<X>&... x) -> twin_number<decltype(f(x.first...))> {
  return {f(x.first...), f(x.second...)};
}
// (the roots of a subnormal phi, two vectors at a time)
template <class X>
HWY_INLINE detail::normal_factors<twin_number<X>> subnormal_phi_factors(const twin_number<X>& phi, const twin_number<X>& x) {
  const auto a = subnormal_phi_factors(phi.first, x.first), b = subnormal_phi_factors(phi.second, x.second);
  return {{a.phi, b.phi}, {a.x, b.x}, {a.down, b.down}, true};
}

template <class D>
using lane_pair = twin_number<lanes<D>>;

// phi_bands<T>' table in units of the exponent field, one entry per band for
// the lanes' gather: the field of 2^(top - 1) (where the larger of |u|, |dy|
// moves) and the least fields the smaller may then have, for contact and
// release (lowest) and for an impact (impact_lowest), each a signed bit field
// of a third of the entry, so that one gather reads all three.
template <class T>
struct band_fields {
  using bands = detail::phi_bands<T>;
  using layout = detail::binary_layout<T>;
  using field = std::make_signed_t<typename layout::bits>;
  // band = (field of |phi| + index_offset) >> band_bits
  static constexpr field index_offset = -layout::bias - bands::least_binade;
  static_assert(((2 * std::numeric_limits<T>::max_exponent - 1 + index_offset) >> bands::band_bits) < bands::count,
                "every |phi|, infinity and NaN included, indexes the table");
  static constexpr int width = 8 * sizeof(field) / 3;
  enum part { top_part, lowest_part, impact_lowest_part };
  static constexpr std::array<field, bands::count> table = [] {
    using entry = typename layout::bits;
    std::array<field, bands::count> entries{};
    for (int j = 0; j < bands::count; ++j) {
      entry bits = 0;
      auto put = [&](int part, int value) {
        if (value < -(1 << (width - 1)) || value >= (1 << (width - 1))) throw "a band's field exceeds its part of the entry";
        bits |= (entry(value) & ((entry(1) << width) - 1)) << (part * width);
      };
      put(top_part, layout::bias + bands::table[j].top - 1);
      put(lowest_part, layout::bias + bands::table[j].lowest);
      put(impact_lowest_part, layout::bias + bands::table[j].impact_lowest);
      entries[j] = std::bit_cast<field>(bits);
    }
    return entries;
  }();
  // one part of gathered entries, sign-extended
  template <part which, class V>
  static HWY_INLINE V read(V entries) {
    constexpr int bits = 8 * sizeof(field);
    return hn::ShiftRight<bits - width>(hn::ShiftLeft<bits - width * (which + 1)>(entries));
  }
};

// Lanes packed by case: the impacts, the releases and the contacts, so that
// each vector runs one case's operations only (a square root and a division
// for a root, a division for a contact; the stable mode packs only the moved
// contacts, as those inside the window cost less answered at once). Each holds
// the lane's operands as the stable path takes them (moved by phi's band where
// the lane is), the move in bits (0: unmoved), and the lane's index in the arrays.
constexpr std::ptrdiff_t block = 256;

template <class T>
struct packed_lanes {
  using bits = typename detail::binary_layout<T>::bits;
  // a block's lanes, those waiting from the block before (fewer than an
  // answer of up to two vectors takes) and the last answer's padding
  static constexpr std::ptrdiff_t capacity = block + 4 * HWY_MAX_BYTES / sizeof(T);
  alignas(64) T u[capacity], dy[capacity], phi[capacity];
  alignas(64) bits offset[capacity];
  alignas(64) std::make_signed_t<bits> index[capacity];
  std::ptrdiff_t count = 0;  // (the packs of a case count in case_counts while sort_vector fills them)
  bool moved = false;        // offset is kept (some lane may have a non-zero one); else every offset is 0
};

// The lane orders that bring a mask's lanes first, by the mask's bits: the
// compaction of vectors of up to 8 lanes (Highway's own compress copies a
// table onto the stack at every call for them; 16 lanes of float on AVX-512
// have an instruction). Each order moves the lanes' 32-bit parts (two for a
// double), which every target permutes in one instruction: AVX2 has no
// permute of 64-bit lanes by a vector, and Highway would widen the order there.
template <std::size_t lanes_per_vector, std::size_t parts_per_lane>
inline constexpr auto compaction_orders = [] {
  constexpr std::size_t parts = lanes_per_vector * parts_per_lane;
  std::array<std::array<std::uint8_t, parts>, (std::size_t(1) << lanes_per_vector)> orders{};
  for (std::size_t bits = 0; bits < orders.size(); ++bits) {
    std::size_t k = 0;
    auto append = [&](std::size_t j) {
      for (std::size_t part = 0; part < parts_per_lane; ++part) orders[bits][k++] = std::uint8_t(j * parts_per_lane + part);
    };
    for (std::size_t j = 0; j < lanes_per_vector; ++j)
      if ((bits >> j) & 1) append(j);
    for (std::size_t j = 0; j < lanes_per_vector; ++j)
      if (!((bits >> j) & 1)) append(j);
  }
  return orders;
}();

// The 32-bit parts of D's vectors, and a row of those tables as their permutation.
template <class D>
using parts_of = hn::Repartition<std::uint32_t, D>;

template <class D, std::size_t parts>
HWY_INLINE auto lane_order(D, const std::array<std::uint8_t, parts>& row) {
  const parts_of<D> d32;
  return hn::IndicesFromVec(d32, hn::PromoteTo(d32, hn::LoadU(hn::Rebind<std::uint8_t, decltype(d32)>(), row.data())));
}

// A block's lanes as the first pass sorts them: by case, and by whether phi
// is subnormal (double: the first band), and those left to the scalar path.
template <class T>
struct sorted_lanes {
  packed_lanes<T> outside;  // the lanes outside the common window, sorted after the block's others
  packed_lanes<T> impacts, releases, contacts, scalar;
  packed_lanes<T> impacts_of_subnormal_phi, releases_of_subnormal_phi, contacts_of_subnormal_phi;
  packed_lanes<T> far_impacts, far_contacts, far_releases;  // u and dy too far apart for the band, unmoved
};

// The counts of the packs of a case while sort_vector fills them: a local of
// solve's loop over a block, kept in registers (a count in the pack's own
// object, or in any object whose address leaves solve, would be stored and
// read again around every store of the pack's indices).
struct case_counts {
  std::ptrdiff_t impacts = 0, releases = 0, contacts = 0;
};

// Appends the lanes of `lanes_of` to `into`, in order.
template <class D>
HWY_INLINE void pack(D d, packed_lanes<hn::TFromD<D>>& into, std::ptrdiff_t& count, hn::Mask<D> lanes_of, hn::Vec<D> u, hn::Vec<D> dy,
                     hn::Vec<D> phi, hn::Vec<hn::RebindToUnsigned<D>> offset, hn::Vec<hn::RebindToSigned<D>> index) {
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  const std::ptrdiff_t at = count;
  constexpr std::size_t lanes_per_vector = hn::MaxLanes(D());
  if constexpr (lanes_per_vector <= 8 && !HWY_HAVE_SCALABLE) {
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(d, lanes_of, bits);
    constexpr std::size_t parts_per_lane = sizeof(hn::TFromD<D>) / 4;
    const auto order = lane_order(d, compaction_orders<lanes_per_vector, parts_per_lane>[bits[0]]);
    auto first = [&](auto v) {
      return hn::BitCast(hn::DFromV<decltype(v)>(), hn::TableLookupLanes(hn::BitCast(parts_of<D>(), v), order));
    };
    hn::StoreU(first(u), d, into.u + at);
    hn::StoreU(first(dy), d, into.dy + at);
    hn::StoreU(first(phi), d, into.phi + at);
    if (into.moved) hn::StoreU(first(offset), du, into.offset + at);
    hn::StoreU(first(index), di, into.index + at);
  } else {
    hn::StoreU(hn::Compress(u, lanes_of), d, into.u + at);
    hn::StoreU(hn::Compress(dy, lanes_of), d, into.dy + at);
    hn::StoreU(hn::Compress(phi, lanes_of), d, into.phi + at);
    if (into.moved) hn::StoreU(hn::Compress(offset, hn::RebindMask(du, lanes_of)), du, into.offset + at);
    hn::StoreU(hn::Compress(index, hn::RebindMask(di, lanes_of)), di, into.index + at);
  }
  count += static_cast<std::ptrdiff_t>(hn::CountTrue(d, lanes_of));
}

// A lane's s, computed on its moved operands, moved back: exact where s is 0
// or the lane unmoved, or s normal above the least binade before the move and
// normal after it (solve_stable's moved_back); `moved_back` is false on the
// others, which underflow or overflow once moved back: solve_stable solves them.
// (exact_only: the rounded mode's, whose s moves back only where exactly: the
// others would round twice.)
template <bool exact_only, class D>
HWY_INLINE lanes<D> move_back(D d, lanes<D> s, hn::Vec<hn::RebindToUnsigned<D>> offset, hn::Mask<D>& moved_back,
                              hn::Mask<D>& below_normal) {
  using layout = detail::binary_layout<hn::TFromD<D>>;
  using U = typename layout::bits;
  constexpr int significand_bits = layout::significand_bits;
  const hn::RebindToUnsigned<D> du;
  const auto s_bits = hn::BitCast(du, s.v);
  const auto s_magnitude = hn::And(s_bits, hn::Set(du, U(~layout::sign)));
  const auto unmoved = hn::Or(hn::Eq(s_magnitude, hn::Zero(du)), hn::Eq(offset, hn::Zero(du)));
  const auto above_least_binade =
      unsigned_less(du, hn::Sub(s_magnitude, hn::Set(du, U(2 * layout::least_normal))),
                    hn::Set(du, U((layout::exponent_field << significand_bits) - 2 * layout::least_normal)));
  const auto normal_once_moved =
      unsigned_less(du, hn::Sub(hn::Sub(s_magnitude, offset), hn::Set(du, layout::least_normal)),
                    hn::Set(du, U((layout::exponent_field << significand_bits) - layout::least_normal)));
  const auto moved = hn::IfThenElse(hn::RebindMask(d, unmoved), s.v, hn::BitCast(d, hn::Sub(s_bits, offset)));
  moved_back = hn::RebindMask(d, hn::Or(unmoved, hn::And(above_least_binade, normal_once_moved)));
  if (exact_only || hn::AllTrue(d, moved_back)) [[likely]] return moved;
  // a release root from 2^(max_exponent + 1) up once moved back: infinity, as
  // solve_stable's move_back gives it (the binade 2^max_exponent, just beyond
  // the largest T, stays with solve_stable)
  const hn::RebindToSigned<D> di;
  const auto moved_field = hn::Sub(field_of_magnitude(d, s_magnitude),
                                   hn::ShiftRight<significand_bits>(hn::BitCast(di, offset)));
  const auto overflows = hn::And(hn::RebindMask(d, above_least_binade),
                                 hn::RebindMask(d, hn::Gt(moved_field, hn::Set(di, hn::TFromD<decltype(di)>(layout::exponent_field)))));
  moved_back = hn::Or(moved_back, overflows);
  below_normal = hn::And(hn::RebindMask(d, above_least_binade), hn::RebindMask(d, hn::Lt(moved_field, hn::Set(di, 1))));
  return hn::IfThenElse(overflows, hn::CopySignToAbs(hn::Set(d, std::numeric_limits<hn::TFromD<D>>::infinity()), s.v), moved);
}

// (A.30), (A.31) and (A.32), each on a pack of its own, as solve_stable
// solves them (stable_form's formulas, then the clamp onto the case's side).
// With `phi_is_subnormal` the products with phi are formed from normal
// factors (detail::factors_of). The roots take two vectors at a time
// (lane_pair: a root is one long chain, twin_number).
template <class D, bool phi_is_subnormal>
HWY_INLINE lane_pair<D> answer_impacts(lane_pair<D> u, lane_pair<D> dy, lane_pair<D> phi) {
  const auto clamped = [](lanes<D> s, lanes<D> u, lanes<D> dy) { return detail::impact_clamped(s, u, dy); };
  return each_half(clamped, stable_form::impact<phi_is_subnormal>(u, -dy, phi), u, dy);
}

template <class D, bool phi_is_subnormal>
HWY_INLINE lane_pair<D> answer_releases(lane_pair<D> u, lane_pair<D> dy, lane_pair<D> phi) {
  const auto clamped = [](lanes<D> s, lanes<D> dy) { return detail::clamped_above_positive(s, dy); };
  return each_half(clamped, stable_form::release<phi_is_subnormal>(u, dy, phi), dy);
}

template <class D, bool phi_is_subnormal>
HWY_INLINE lanes<D> answer_contacts(lanes<D> u, lanes<D> dy, lanes<D> phi) {
  return detail::contact_clamped(stable_form::contact<phi_is_subnormal>(u, dy, phi), dy);
}

template <class D, bool phi_is_subnormal>
HWY_INLINE lane_pair<D> answer_contacts(lane_pair<D> u, lane_pair<D> dy, lane_pair<D> phi) {
  return each_half([](lanes<D> u, lanes<D> dy, lanes<D> phi) { return answer_contacts<D, phi_is_subnormal>(u, dy, phi); }, u, dy, phi);
}

// ---- the correctly rounded mode (solve_rounded_batch) ----------------------------
//
// The lanes inside the common window, or moved into it, take solve_rounded's
// fixed-bound step (rounded_form's steps, on lanes) and its rounding test; the
// root rounds as both ends of the step's interval round. A lane whose test
// fails, or whose s0 leaves the plain window, gets NaN: solve_rounded decides it
// (in float, first through double on double vectors: left_lanes).

// float's step is proven on float lanes only where no product of the step
// rounds below the normal range (docs/equations.md section 7): u and dy from
// 2^L are multiples of 2^(L - 23), phi from 2^M of 2^(M - 23), and the deepest
// product, phi (dy - s0)^2's error term, is a multiple of their product.
static_assert(2 * (detail::common_window_least_uv<float> - (std::numeric_limits<float>::digits - 1)) +
                      (detail::common_window_least_phi<float> - (std::numeric_limits<float>::digits - 1)) >=
                  std::numeric_limits<float>::min_exponent - 1);

// x normal (not zero) inside the plain window: detail::magnitude_inside_plain_window
template <class D>
HWY_INLINE hn::Mask<D> inside_plain_window(D d, lanes<D> x) {
  using window = detail::plain_window_bits<hn::TFromD<D>>;
  const hn::RebindToUnsigned<D> du;
  const auto offset = hn::Sub(hn::BitCast(du, hn::Abs(x.v)), hn::Set(du, window::lowest));
  return hn::RebindMask(d, unsigned_less(du, offset, hn::Set(du, window::span + 1)));
}

// (the first pass packs for these only lanes inside the common window, which
// lies inside the plain window)
template <class D>
HWY_INLINE lanes<D> rounded_or_undecided(D d, const rounded_form::fixed_step<lanes<D>>& step) {
  const auto [below, above] = rounded_form::rounded_ends(step);
  const auto decided = hn::And(inside_plain_window(d, step.s0), hn::Eq(below.v, above.v));
  return hn::IfThenElse(decided, above.v, hn::Set(d, std::numeric_limits<hn::TFromD<D>>::quiet_NaN()));
}

// (A.30), (A.31), (A.32), each on a pack of its own
template <class D>
HWY_INLINE lanes<D> rounded_impacts(lanes<D> u, lanes<D> dy, lanes<D> phi) {
  return rounded_or_undecided(D(), rounded_form::impact_step(u, dy, phi));
}

template <class D>
HWY_INLINE lanes<D> rounded_contacts(lanes<D> u, lanes<D> dy, lanes<D> phi) {
  return rounded_or_undecided(D(), rounded_form::contact_step(u, dy, phi));
}

template <class D>
HWY_INLINE lanes<D> rounded_releases(lanes<D> u, lanes<D> dy, lanes<D> phi) {
  return rounded_or_undecided(D(), rounded_form::release_step(u, dy, phi));
}

// float's stable root s, computed on double lanes that hold floats
// (rounded_form::round_through_double, solve_rounded<float>'s own test): s where
// both ends of its bound round to one float, NaN (solve_rounded) where not.
template <class D>
HWY_INLINE lanes<D> through_double(lanes<D> s) {
  static_assert(std::is_same_v<hn::TFromD<D>, double>);
  const hn::Rebind<float, D> df;
  const lanes<D> bound = rounded_form::through_double_bound(s);
  const auto below = hn::PromoteTo(D(), hn::DemoteTo(df, (s - bound).v));
  const auto above = hn::PromoteTo(D(), hn::DemoteTo(df, (s + bound).v));
  return hn::IfThenElse(hn::Eq(below, above), above, hn::Set(D(), std::numeric_limits<double>::quiet_NaN()));
}

// The exact stage (detail::stage::exact) of the lanes too far apart for the
// band, each case on scaled_lanes; a lane scaled_lanes did not carry, or a
// release root that rounds to infinity below 2^(max_exponent + 2) (only the
// exact sign at the threshold tells it), gets NaN: solve_stable solves it.
// x's value in T, NaN on the lanes x did not carry
template <class D>
HWY_INLINE lanes<D> value_of(const scaled_lanes<D>& x) {
  return hn::IfThenElse(x.lost(), hn::Set(D(), std::numeric_limits<hn::TFromD<D>>::quiet_NaN()), x.value());
}

// the clamped s where the value was a number (x86's min and max give their
// second operand where either is NaN: a clamp may turn NaN into a number)
template <class D>
HWY_INLINE lanes<D> where_carried(lanes<D> value, lanes<D> s) { return hn::IfThenElse(hn::IsNaN(value.v), value.v, s.v); }

// Each case two vectors at a time (twin_number).
template <class D>
HWY_INLINE lane_pair<D> far_impacts(lane_pair<D> u, lane_pair<D> dy, lane_pair<D> phi) {
  using S = twin_number<scaled_lanes<D>>;
  const S root = stable_form::impact(S(u), S(-dy), S(phi));
  auto s = [](const scaled_lanes<D>& x, lanes<D> u, lanes<D> dy) {
    const auto value = value_of(x);
    return where_carried(value, detail::impact_clamped(value, u, dy));
  };
  return each_half(s, root, u, dy);
}

template <class D>
HWY_INLINE lane_pair<D> far_contacts(lane_pair<D> u, lane_pair<D> dy, lane_pair<D> phi) {
  using S = twin_number<scaled_lanes<D>>;
  const S root = stable_form::contact(S(u), S(dy), S(phi));
  auto s = [](const scaled_lanes<D>& x, lanes<D> dy) {
    const auto value = value_of(x);
    return where_carried(value, detail::contact_clamped(value, dy));
  };
  return each_half(s, root, dy);
}

template <class D>
HWY_INLINE lane_pair<D> far_releases(lane_pair<D> u, lane_pair<D> dy, lane_pair<D> phi) {
  using S = twin_number<scaled_lanes<D>>;
  using T = hn::TFromD<D>;
  const S root = stable_form::release(S(u), S(dy), S(phi));
  auto s = [](const scaled_lanes<D>& x, lanes<D> dy) {
    const auto value = value_of(x);
    const auto s = where_carried(value, detail::clamped_above_positive(value, dy));
    const auto near_threshold = hn::Not(hn::Gt(x.exponent, hn::Set(D(), T(std::numeric_limits<T>::max_exponent + 1))));
    return lanes<D>(hn::IfThenElse(hn::And(hn::IsInf(s.v), near_threshold), hn::Set(D(), std::numeric_limits<T>::quiet_NaN()), s.v));
  };
  return each_half(s, root, dy);
}

// What a kernel computes: solve_stable's results, solve_rounded's, or
// solve_rounded's in float on double lanes that hold floats (through_double).
enum class kernel_mode { stable, rounded, rounded_through_double };

// The scalar path of each mode, for the lanes the vectors leave.
template <kernel_mode mode, class T>
void solve_lane(T u, T dy, T phi, T& s, int& which) {
  if constexpr (mode == kernel_mode::stable) {
    solve_stable_lane(u, dy, phi, s, which);
  } else if constexpr (mode == kernel_mode::rounded) {
    solve_rounded_lane(u, dy, phi, s, which);
  } else {  // (exact: the lanes hold floats)
    float rounded;
    solve_rounded_lane(float(u), float(dy), float(phi), rounded, which);
    s = rounded;
  }
}

template <kernel_mode mode, class T>
std::ptrdiff_t solve(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n);

// The lanes the vectors leave, each solved at once by the mode's scalar path.
template <kernel_mode mode, class T>
struct left_lanes {
  const T *u, *dy, *phi;
  T* s;
  int* which;
  std::ptrdiff_t count = 0;  // how many the scalar path solved
  void take(std::ptrdiff_t i) {
    solve_lane<mode>(u[i], dy[i], phi[i], s[i], which[i]);
    ++count;
  }
  void finish() {}
};

// float's rounded mode: float's step reaches less far than float's stable
// formulas in double (phi above float's common window, a root that leaves the
// plain window far below its inputs), which solve_rounded<float> itself runs
// (rounded_form::round_through_double). The lanes float's vectors leave are
// gathered, widened (exactly) and solved on double vectors by them, a block at
// a time; the scalar path takes what those leave.
template <>
struct left_lanes<kernel_mode::rounded, float> {
  const float *u, *dy, *phi;
  float* s;
  int* which;
  std::ptrdiff_t count = 0;
  std::ptrdiff_t gathered = 0;
  static constexpr std::ptrdiff_t few_lanes = 8;  // fewer go to solve_rounded at once
  alignas(64) std::int32_t index[block + 64];  // (whole vectors past `gathered`)
  void take(std::ptrdiff_t i) {
    index[gathered++] = static_cast<std::int32_t>(i);
    if (gathered == block) finish();
  }
  void finish() {
    if (gathered < few_lanes) {  // (a pass over double vectors would cost more)
      for (std::ptrdiff_t k = 0; k < gathered; ++k) {
        const std::int32_t i = index[k];
        solve_lane<kernel_mode::rounded>(u[i], dy[i], phi[i], s[i], which[i]);
      }
      count += gathered;
      gathered = 0;
      return;
    }
    const hn::ScalableTag<double> d;
    const hn::Rebind<float, decltype(d)> df;
    const hn::Rebind<std::int32_t, decltype(d)> di;
    const auto width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
    const std::ptrdiff_t padded = (gathered + width - 1) / width * width;
    std::fill(index + gathered, index + padded, index[0]);
    alignas(64) double wide_u[block + 64], wide_dy[block + 64], wide_phi[block + 64], wide_s[block + 64];
    alignas(64) int wide_which[block + 64];
    for (std::ptrdiff_t k = 0; k < padded; k += width) {
      const auto at = hn::Load(di, index + k);
      hn::Store(hn::PromoteTo(d, hn::GatherIndex(df, u, at)), d, wide_u + k);
      hn::Store(hn::PromoteTo(d, hn::GatherIndex(df, dy, at)), d, wide_dy + k);
      hn::Store(hn::PromoteTo(d, hn::GatherIndex(df, phi, at)), d, wide_phi + k);
    }
    std::fill(wide_u + gathered, wide_u + padded, 1.0);  // the padding solves 1 = 1 = 1
    std::fill(wide_dy + gathered, wide_dy + padded, 1.0);
    std::fill(wide_phi + gathered, wide_phi + padded, 1.0);
    count += solve<kernel_mode::rounded_through_double>(wide_u, wide_dy, wide_phi, wide_s, wide_which, padded);
    for (std::ptrdiff_t k = 0; k < gathered; ++k) {
      s[index[k]] = static_cast<float>(wide_s[k]);  // (exact: a float)
      which[index[k]] = wide_which[k];
    }
    gathered = 0;
  }
  // The lanes [first, first + n) through double, whole: a block in which many
  // lanes lie beyond float's step (phi_often_beyond_common_window). (n: whole
  // vectors of float)
  void take_whole(std::ptrdiff_t first, std::ptrdiff_t n) {
    const hn::ScalableTag<double> d;
    const hn::Rebind<float, decltype(d)> df;
    const auto width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
    alignas(64) double wide_u[block], wide_dy[block], wide_phi[block], wide_s[block];
    for (std::ptrdiff_t k = 0; k < n; k += width) {
      hn::Store(hn::PromoteTo(d, hn::LoadU(df, u + first + k)), d, wide_u + k);
      hn::Store(hn::PromoteTo(d, hn::LoadU(df, dy + first + k)), d, wide_dy + k);
      hn::Store(hn::PromoteTo(d, hn::LoadU(df, phi + first + k)), d, wide_phi + k);
    }
    count += solve<kernel_mode::rounded_through_double>(wide_u, wide_dy, wide_phi, wide_s, which + first, n);
    for (std::ptrdiff_t k = 0; k < n; k += width) hn::StoreU(hn::DemoteTo(df, hn::Load(d, wide_s + k)), df, s + first + k);
  }
};

// Whether a quarter or more of the n lanes from phi have phi outside float's
// common window (where float's step does not take a lane): such a block goes
// through double whole, where the first pass and the gathers of the lanes
// left would cost more.
template <class D>
HWY_INLINE bool phi_often_beyond_common_window(D d, const float* phi, std::ptrdiff_t n) {
  const hn::RebindToUnsigned<D> du;
  const auto lowest = hn::Set(du, detail::common_window_lowest_phi<float>);
  const auto width = hn::Set(du, detail::common_window_width<float>);
  std::size_t beyond = 0;
  for (std::ptrdiff_t k = 0; k < n; k += static_cast<std::ptrdiff_t>(hn::Lanes(d)))
    beyond += hn::CountTrue(du, hn::Not(unsigned_less(du, hn::Sub(hn::BitCast(du, hn::LoadU(d, phi + k)), lowest), width)));
  return 4 * static_cast<std::ptrdiff_t>(beyond) >= n;
}

// The packed lanes' s by `answer`, written to their places (their cases are
// written by the first pass); those whose s is NaN or cannot move back go to
// `left`. `clamp` (s, u, dy) is the lanes' clamp onto the side of dy of their
// case; `answer` takes vectors_per_answer vectors at once (two as a lane_pair).
// Before the call's last block only whole answers are given: the lanes of a
// last, partly filled one wait in the pack for the next block's (padding
// costs as much as lanes, and the rare packs, of a few lanes a block, would
// be mostly padding).
template <int vectors_per_answer, kernel_mode mode, class D, class Answer, class Clamp>
HWY_INLINE void solve_packed(D d, packed_lanes<hn::TFromD<D>>& lanes_in, left_lanes<mode, hn::TFromD<D>>& left,
                             Answer answer, Clamp clamp, bool last_block) {
  const auto *u_in = left.u, *dy_in = left.dy;
  auto* s_out = left.s;
  using T = hn::TFromD<D>;
  using L = lanes<D>;
  const hn::RebindToUnsigned<D> du;
  const std::ptrdiff_t width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  const std::ptrdiff_t step = vectors_per_answer * width;
  const std::ptrdiff_t solved = last_block ? lanes_in.count : lanes_in.count - lanes_in.count % step;
  if (last_block) {
    for (std::ptrdiff_t k = lanes_in.count; k < lanes_in.count + step; ++k) {  // the last answer's unused lanes: 1 = 1 = 1
      lanes_in.u[k] = lanes_in.dy[k] = lanes_in.phi[k] = T(1);
      lanes_in.offset[k] = 0;
      lanes_in.index[k] = 0;  // a lane of the arrays, for the gathers below
    }
  }
  // the vector at k: s moved back and written
  auto write_back = [&](std::ptrdiff_t k, L s) __attribute__((always_inline)) {
    auto moved_back = hn::FirstN(d, width);
    if (lanes_in.moved) {
      const L moved_s = s;
      const auto offset = hn::Load(du, lanes_in.offset + k);
      auto below_normal = hn::FirstN(d, 0);
      s = move_back<mode != kernel_mode::stable>(d, s, offset, moved_back, below_normal);
      if (!hn::AllFalse(d, below_normal)) [[unlikely]] {
        // an s that lands below the normal binades once moved back: rounded
        // once there, as solve_stable's move_back_below_normal rounds it
        // (scaled<T>), then clamped in the unmoved frame
        const hn::RebindToSigned<D> di;
        const scaled_lanes<D> x(moved_s);
        const auto shift = hn::ConvertTo(d, hn::ShiftRight<detail::binary_layout<T>::significand_bits>(hn::BitCast(di, offset)));
        const L rounded = scaled_lanes<D>::shifted_down(x.significand, hn::Sub(x.exponent, shift));
        const auto index = hn::Load(di, lanes_in.index + k);
        const L clamped = clamp(rounded, L(hn::GatherIndex(d, u_in, index)), L(hn::GatherIndex(d, dy_in, index)));
        s = hn::IfThenElse(below_normal, clamped.v, s.v);
        moved_back = hn::Or(moved_back, below_normal);
      }
    }
    moved_back = hn::AndNot(hn::IsNaN(s.v), moved_back);  // (far lanes: a NaN s is one scaled_lanes did not carry)
    const std::ptrdiff_t lanes_here = std::clamp(solved - k, std::ptrdiff_t(0), width);
    if (lanes_here == width) {
      hn::ScatterIndex(s.v, d, s_out, hn::Load(hn::RebindToSigned<D>(), lanes_in.index + k));
    } else {
      alignas(64) T s_lanes[64];
      hn::Store(s.v, d, s_lanes);
      for (std::ptrdiff_t j = 0; j < lanes_here; ++j) s_out[lanes_in.index[k + j]] = s_lanes[j];
    }
    if (!hn::AllTrue(d, moved_back)) [[unlikely]] {
      std::uint8_t moved_back_bits[16] = {};  // one bit per lane
      hn::StoreMaskBits(d, moved_back, moved_back_bits);
      for (std::ptrdiff_t j = 0; j < lanes_here; ++j)
        if (!((moved_back_bits[j / 8] >> (j % 8)) & 1)) left.take(lanes_in.index[k + j]);
    }
  };
  auto operands = [&](std::ptrdiff_t k, const T* of) { return L(hn::Load(d, of + k)); };
  for (std::ptrdiff_t k = 0; k < solved; k += step) {
    if constexpr (vectors_per_answer == 1) {
      write_back(k, answer(operands(k, lanes_in.u), operands(k, lanes_in.dy), operands(k, lanes_in.phi)));
    } else {
      auto pair = [&](const T* of) { return lane_pair<D>(operands(k, of), operands(k + width, of)); };
      const lane_pair<D> s = answer(pair(lanes_in.u), pair(lanes_in.dy), pair(lanes_in.phi));
      write_back(k, s.first);
      write_back(k + width, s.second);
    }
  }
  // the lanes that wait (fewer than an answer takes) to the front, in whole
  // vectors (where nothing was solved they are there already)
  const std::ptrdiff_t waiting = lanes_in.count - solved;
  if (waiting != 0 && solved != 0) {
    const hn::RebindToSigned<D> di;
    for (std::ptrdiff_t k = 0; k < step; k += width) {
      hn::Store(hn::Load(d, lanes_in.u + solved + k), d, lanes_in.u + k);
      hn::Store(hn::Load(d, lanes_in.dy + solved + k), d, lanes_in.dy + k);
      hn::Store(hn::Load(d, lanes_in.phi + solved + k), d, lanes_in.phi + k);
      if (lanes_in.moved) hn::Store(hn::Load(du, lanes_in.offset + solved + k), du, lanes_in.offset + k);
      hn::Store(hn::Load(di, lanes_in.index + solved + k), di, lanes_in.index + k);
    }
  }
  lanes_in.count = waiting;
  lanes_in.moved = lanes_in.moved && waiting != 0;
}

// The case numbers of T's lanes as the int lanes of the `which` array
template <class D>
HWY_INLINE auto case_numbers(D d, hn::Vec<D> cases) {
  const hn::Rebind<std::int32_t, D> di32;
  if constexpr (sizeof(hn::TFromD<D>) == 8) return hn::DemoteTo(di32, cases);
  else return hn::ConvertTo(di32, cases);
}

// Each lane's case, as solve_cases decides (A.21): the pre-test, and the
// exact sum for the lanes it leaves undecided near the boundary; u, dy, phi
// as the stable path takes them (moved), phi dy as phi_factor dy_factor. Every
// lane is decided: a lane that is not to be answered solves 1 = 1 = 1 (a
// contact, decided by the pre-test, with no subnormal operand), and its caller
// masks its case. Few masks are kept: AVX-512 holds masks in eight registers,
// and more of them are spilled and reloaded.
template <class D>
struct lane_cases {
  lane_mask<D> free_flight, impact, contact, release;
  hn::Vec<D> which;  // the case numbers (contact_case), in T
  lane_mask<D> undecided;  // the lanes the pre-test left to the exact sum
};

template <class D>
HWY_INLINE lane_cases<D> decide_cases(D d, lanes<D> u, lanes<D> dy, lanes<D> phi, lanes<D> phi_factor, lanes<D> dy_factor) {
  using T = hn::TFromD<D>;
  using L = lanes<D>;
  const auto contact_before = dy > L(0), impact_before = dy <= L(0);
  const L sum = u + dy;
  const auto [estimate, margin] = detail::estimate_contact(sum, phi_factor, dy_factor);
  const auto decided = fabs(estimate) > margin;
  auto stays = estimate > L(0);
  const auto undecided = contact_before & !decided;
  if (!hn::AllFalse(d, undecided.m)) [[unlikely]]
    stays = (decided & stays) | (!decided & detail::exact_sum_nonnegative(u, dy, phi));
  lane_cases<D> cases{impact_before & (sum <= L(0)), {}, contact_before & stays, contact_before & !stays, {}, undecided};
  cases.impact = impact_before & !cases.free_flight;
  cases.which = hn::IfThenElse(cases.free_flight.m, hn::Set(d, T(contact_case::free)),
                               hn::IfThenElse(contact_before.m,
                                              hn::IfThenElse(stays.m, hn::Set(d, T(contact_case::contact)),
                                                             hn::Set(d, T(contact_case::release))),
                                              hn::Set(d, T(contact_case::impact))));
  return cases;
}

// The entries of phi's bands (band_fields) for a vector of phi, gathered.
template <class D>
HWY_INLINE hn::Vec<hn::RebindToSigned<D>> band_entries(D d, hn::Vec<D> phi) {
  using T = hn::TFromD<D>;
  using U = typename detail::binary_layout<T>::bits;
  using fields = band_fields<T>;
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  const auto phi_field = field_of_magnitude(d, hn::And(hn::BitCast(du, phi), hn::Set(du, U(~detail::binary_layout<T>::sign))));
  const auto band = hn::ShiftRight<fields::bands::band_bits>(hn::Add(phi_field, hn::Set(di, fields::index_offset)));
  return hn::GatherIndex(di, fields::table.data(), band);
}

// The first pass over lanes outside the common window and not in free
// flight, a vector of the `outside` pack (`valid`: the lanes of the pack; the
// others repeat its last lane): the lanes moved by phi's band into the window
// (solve_stable's moved stage) and the far lanes have their case decided and
// are packed by it; the rest are noted for solve_stable. (`entries`:
// band_entries of phi, in the stable mode, which moves by phi's band.)
template <kernel_mode mode, class D>
HWY_INLINE void sort_outside_vector(D d, hn::Vec<D> u, hn::Vec<D> dy, hn::Vec<D> phi, hn::Vec<hn::RebindToSigned<D>> index,
                                      hn::Mask<D> valid, int* which_out, sorted_lanes<hn::TFromD<D>>& sorted,
                                      hn::Vec<hn::RebindToSigned<D>> entries) {
  using T = hn::TFromD<D>;
  using L = lanes<D>;
  using layout = detail::binary_layout<T>;
  using U = typename layout::bits;
  using fields = band_fields<T>;
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  constexpr int significand_bits = layout::significand_bits;
  constexpr bool rounded_mode = mode != kernel_mode::stable;
  const auto magnitude = hn::Set(du, U(~layout::sign));
  const auto u_bits = hn::BitCast(du, u), dy_bits = hn::BitCast(du, dy), phi_bits = hn::BitCast(du, phi);
  const auto abs_u = hn::And(u_bits, magnitude), abs_dy = hn::And(dy_bits, magnitude);

  L moved_u = u, moved_dy = dy, moved_phi = phi;
  L phi_factor = phi, dy_factor = dy;  // phi dy as their product (detail::factors_of)
  auto offset = hn::Zero(du);
  lane_mask<D> answerable{hn::FirstN(d, 0)}, subnormal_phi{hn::FirstN(d, 0)};
  lane_mask<D> far_impact{hn::FirstN(d, 0)}, far_contact{hn::FirstN(d, 0)}, far_release{hn::FirstN(d, 0)};
  {
    // phi's band: the shift (in binades) that moves the larger of |u|, |dy| to
    // the band's top, taken where u and dy are finite and non-zero, phi in a
    // band, and the smaller then at or above the band's least binade for its case
    const auto least_normal = hn::Set(du, layout::least_normal);
    const auto one_bit = hn::Set(du, U(1));
    auto is_finite_nonzero = [&](hn::Vec<decltype(du)> magnitude_bits) {
      return unsigned_less(du, hn::Sub(magnitude_bits, one_bit), hn::Set(du, U((layout::exponent_field << significand_bits) - 1)));
    };
    // subnormal u and dy read as normal values (read_normal), on the vectors
    // that hold one (the rounded mode moves normal u and dy only: it reads
    // none). The test may also take a vector for a zero (or, through Min, a
    // NaN): such a lane is not finite_uv, and what it reads does not matter.
    normal_reading<D> u_read{hn::BitCast(d, abs_u), field_of_magnitude(d, abs_u)}, dy_read{hn::BitCast(d, abs_dy), field_of_magnitude(d, abs_dy)};
    const bool subnormal_uv =
        !rounded_mode && !hn::AllFalse(d, hn::Lt(hn::Min(hn::BitCast(d, abs_u), hn::BitCast(d, abs_dy)),
                                                 hn::Set(d, std::numeric_limits<T>::min())));
    if (subnormal_uv) [[unlikely]] {
      u_read = read_normal(d, abs_u);
      dy_read = read_normal(d, abs_dy);
    }
    const auto u_field = u_read.field, dy_field = dy_read.field;
    const auto larger = hn::Max(u_field, dy_field), smaller = hn::Min(u_field, dy_field);
    // a subnormal phi in double: every subnormal binade lies in the first band
    // (in float they straddle two: solve_stable takes them)
    constexpr bool subnormal_phi_in_vectors = ((-layout::bias - fields::bands::least_binade) >> fields::bands::band_bits) == 0;
    const auto finite_uv = hn::RebindMask(di, hn::And(is_finite_nonzero(abs_u), is_finite_nonzero(abs_dy)));
    auto shift = hn::Zero(di);     // the move of u and dy, in binades
    auto fits = hn::FirstN(di, 0);  // the lanes it takes
    if constexpr (mode == kernel_mode::rounded) {
      // The rounded mode's step is proven inside the common window only (phi's
      // band would move u and dy beyond it): where phi lies in the window's
      // range and u and dy are normal and less than its width apart, one exact
      // move by 2^shift, the larger to the window's top binade, brings the lane
      // inside, in the same case, its root moved by 2^shift; solve_rounded takes
      // the others (the far lanes too).
      constexpr int top = layout::bias + detail::common_window_least_uv<T> + 2 * detail::common_window<T> - 1;
      constexpr int bottom = layout::bias + detail::common_window_least_uv<T>;
      const auto phi_inside = unsigned_less(du, hn::Sub(phi_bits, hn::Set(du, detail::common_window_lowest_phi<T>)),
                                            hn::Set(du, detail::common_window_width<T>));
      const auto normal_uv = hn::And(hn::Gt(u_field, hn::Zero(di)), hn::Gt(dy_field, hn::Zero(di)));
      shift = hn::Sub(hn::Set(di, top), larger);
      fits = hn::AndNot(hn::Lt(hn::Add(smaller, shift), hn::Set(di, bottom)),
                        hn::And(hn::And(finite_uv, normal_uv), hn::RebindMask(di, phi_inside)));
    } else if constexpr (mode == kernel_mode::rounded_through_double) {
      // (no move: float's rounding would then be taken at the moved scale; the
      // normal floats lie inside double's common window)
    } else {
      const auto least = hn::IfThenElse(hn::RebindMask(di, hn::Le(dy, hn::Zero(d))), fields::template read<fields::impact_lowest_part>(entries),
                                        fields::template read<fields::lowest_part>(entries));
      shift = hn::Sub(fields::template read<fields::top_part>(entries), larger);
      const auto phi_least = hn::Set(du, subnormal_phi_in_vectors ? U(1) : layout::least_normal);
      const auto phi_in_a_band =
          unsigned_less(du, hn::Sub(phi_bits, phi_least), hn::Sub(hn::Set(du, std::bit_cast<U>(fields::bands::end)), phi_least));
      const auto normal_in_band = hn::And(finite_uv, hn::RebindMask(di, phi_in_a_band));
      const auto too_far = hn::Lt(hn::Add(smaller, shift), least);
      fits = hn::AndNot(too_far, normal_in_band);
      // u and dy too far apart for the band, or a finite phi beyond the last
      // band (outside safe_window: safe_window<T>::holds bounds phi far below
      // it): solve_stable's exact stage, on scaled_lanes, for the impacts, and
      // for the contacts and releases whose case the dominant binade decides
      // (detail::sign_of_dominant_binade, on the exponent fields); the others
      // stay with solve_stable
      static_assert(detail::plain_window<T> < fields::bands::last_phi_binade);
      const auto beyond_bands = hn::RebindMask(di, hn::And(hn::Ge(phi, hn::Set(d, fields::bands::end)), hn::IsFinite(phi)));
      const auto far = hn::Or(hn::And(normal_in_band, too_far), hn::And(finite_uv, beyond_bands));
      if (!hn::AllFalse(di, far)) [[unlikely]] {
        const auto phi_field = read_normal(d, hn::And(phi_bits, magnitude)).field;
        const auto product_field = hn::Sub(hn::Add(phi_field, dy_field), hn::Set(di, layout::bias));  // phi dy in [2^field, 2^(field + 2))
        const auto one = hn::Set(di, 1), two = hn::Set(di, 2);
        const auto u_wins = hn::Gt(u_field, hn::Max(hn::Add(dy_field, one), hn::Add(product_field, two)));
        const auto dy_wins = hn::Gt(dy_field, hn::Max(hn::Add(u_field, one), hn::Add(product_field, two)));
        const auto product_wins = hn::Gt(product_field, hn::Add(larger, one));
        const auto u_positive = hn::RebindMask(di, hn::Gt(u, hn::Zero(d)));
        const auto contact_side = hn::RebindMask(di, hn::Gt(dy, hn::Zero(d)));
        far_impact.m = hn::RebindMask(d, hn::AndNot(contact_side, far));
        far_contact.m = hn::RebindMask(d, hn::And(hn::And(far, contact_side), hn::Or(dy_wins, hn::And(u_wins, u_positive))));
        far_release.m = hn::RebindMask(d, hn::And(hn::And(far, contact_side), hn::Or(product_wins, hn::AndNot(u_positive, u_wins))));
      }
    }
    answerable.m = hn::RebindMask(d, fits);
    offset = hn::ShiftLeft<significand_bits>(hn::BitCast(du, hn::IfThenElseZero(fits, shift)));
    // the lanes that cannot be answered solve 1 = 1 = 1: no subnormal operand or result
    const auto one = hn::Set(d, T(1));
    if (subnormal_uv) [[unlikely]] {  // the normal reading moved by the shift, less its own offset, and the sign
      auto moved = [&](normal_reading<D> read, hn::Vec<decltype(du)> bits) {
        const auto reading_offset = hn::Sub(field_of_magnitude(d, hn::BitCast(du, read.value)), read.field);
        const auto moved_offset = hn::ShiftLeft<significand_bits>(hn::BitCast(du, hn::IfThenElseZero(fits, hn::Sub(shift, reading_offset))));
        return hn::BitCast(d, hn::Or(hn::Add(hn::BitCast(du, read.value), moved_offset), hn::AndNot(magnitude, bits)));
      };
      moved_u = hn::IfThenElse(answerable.m, moved(u_read, u_bits), one);
      moved_dy = hn::IfThenElse(answerable.m, moved(dy_read, dy_bits), one);
    } else {
      moved_u = hn::IfThenElse(answerable.m, hn::BitCast(d, hn::Add(u_bits, offset)), one);
      moved_dy = hn::IfThenElse(answerable.m, hn::BitCast(d, hn::Add(dy_bits, offset)), one);
    }
    moved_phi = hn::IfThenElse(answerable.m, phi, one);
    phi_factor = moved_phi;
    dy_factor = moved_dy;
    if constexpr (subnormal_phi_in_vectors) {
      subnormal_phi = answerable & lane_mask<D>{hn::RebindMask(d, unsigned_less(du, hn::Sub(phi_bits, hn::Set(du, U(1))),
                                                                                 hn::Sub(least_normal, hn::Set(du, U(1)))))};
      if (!hn::AllFalse(d, subnormal_phi.m)) [[unlikely]] {
        const auto factors = subnormal_phi_factors(moved_phi, moved_dy);
        phi_factor = select(subnormal_phi, factors.phi, moved_phi);
        dy_factor = select(subnormal_phi, factors.x, moved_dy);
      }
    }
  }

  auto cases = decide_cases(d, moved_u, moved_dy, moved_phi, phi_factor, dy_factor);
  // (with a subnormal phi the pre-test decides every valid lane,
  // proofs/README.md; should it not, solve_stable takes the lane)
  const auto undecided_by_subnormal_phi = subnormal_phi & cases.undecided;
  answerable = answerable & !undecided_by_subnormal_phi;
  subnormal_phi = subnormal_phi & !undecided_by_subnormal_phi;
  // (the lanes not answered solve 1 = 1 = 1, a contact, or are left undecided)
  cases.contact = cases.contact & answerable;
  cases.release = cases.release & answerable;
  const auto far_which = hn::IfThenElse(far_impact.m, hn::Set(d, T(contact_case::impact)),
                                        hn::IfThenElse(far_contact.m, hn::Set(d, T(contact_case::contact)),
                                                       hn::Set(d, T(contact_case::release))));
  const auto far = far_impact | far_contact | far_release;
  const hn::Rebind<std::int32_t, D> di32;
  // (the repeated last lane writes what it writes: the same case to the same place)
  const auto index32 = [&] {  // (an index is below 2^30: its low half)
    if constexpr (sizeof(T) == 8) return hn::BitCast(di32, hn::TruncateTo(hn::Rebind<std::uint32_t, D>(), hn::BitCast(du, index)));
    else return index;
  }();
  hn::ScatterIndex(case_numbers(d, hn::IfThenElse(far.m, far_which, cases.which)), di32, which_out, index32);
  // The valid lanes of `lanes_of` to a pack: at once for the cases' packs,
  // where a test would branch by the data and mispredict more often than a
  // pack costs; the rare packs behind a test, one for the three packs of a
  // subnormal phi (which of them a vector fills is as unpredictable).
  auto pack_valid = [&](packed_lanes<T>& into, std::ptrdiff_t& count, lane_mask<D> lanes_of, hn::Vec<D> u, hn::Vec<D> dy,
                        hn::Vec<D> phi, hn::Vec<decltype(du)> offset) {
    pack(d, into, count, hn::And(lanes_of.m, valid), u, dy, phi, offset, index);
  };
  if (!hn::AllFalse(d, far.m)) [[unlikely]] {
    const auto none = hn::Zero(du);
    pack_valid(sorted.far_impacts, sorted.far_impacts.count, far_impact, u, dy, phi, none);
    pack_valid(sorted.far_contacts, sorted.far_contacts.count, far_contact, u, dy, phi, none);
    pack_valid(sorted.far_releases, sorted.far_releases.count, far_release, u, dy, phi, none);
  }
  // the packs that may now take a moved lane keep offsets from here on (0 for
  // the lanes they hold)
  auto keep_offsets = [](packed_lanes<T>& pack) {
    if (!pack.moved) std::fill_n(pack.offset, pack.count, typename packed_lanes<T>::bits(0));
    pack.moved = true;
  };
  keep_offsets(sorted.impacts);
  keep_offsets(sorted.releases);
  keep_offsets(sorted.contacts);
  pack_valid(sorted.impacts, sorted.impacts.count, cases.impact & !subnormal_phi, moved_u.v, moved_dy.v, moved_phi.v, offset);
  pack_valid(sorted.releases, sorted.releases.count, cases.release & !subnormal_phi, moved_u.v, moved_dy.v, moved_phi.v, offset);
  pack_valid(sorted.contacts, sorted.contacts.count, cases.contact & !subnormal_phi, moved_u.v, moved_dy.v, moved_phi.v, offset);
  if (!hn::AllFalse(d, hn::And(subnormal_phi.m, valid))) {
    // (three inlined calls: a loop over a list of (pack, mask) kept the list
    // on the stack and each pack's count in memory)
    auto pack_subnormal = [&](packed_lanes<T>& into, lane_mask<D> lanes_of) __attribute__((always_inline)) {
      keep_offsets(into);
      pack_valid(into, into.count, lanes_of & subnormal_phi, moved_u.v, moved_dy.v, moved_phi.v, offset);
    };
    pack_subnormal(sorted.impacts_of_subnormal_phi, cases.impact);
    pack_subnormal(sorted.releases_of_subnormal_phi, cases.release);
    pack_subnormal(sorted.contacts_of_subnormal_phi, cases.contact);
  }
  const auto left_to_scalar = !(answerable | cases.free_flight | far);
  if (!hn::AllFalse(d, hn::And(left_to_scalar.m, valid))) pack_valid(sorted.scalar, sorted.scalar.count, left_to_scalar, u, dy, phi, offset);
}

// The first pass over one vector at lane i: free flight answered (s = -u for
// any valid input, written now); the lanes inside the common window have
// their case decided as solve_stable decides it and are packed by it; the
// others go to the `outside` pack, which sort_outside_vector sorts once the
// block's vectors are through (a vector that mixes both would otherwise take
// the longer path for all its lanes, free flight's too).
template <kernel_mode mode, class D>
HWY_INLINE void sort_vector(D d, const hn::TFromD<D>* u_in, const hn::TFromD<D>* dy_in, const hn::TFromD<D>* phi_in,
                            hn::TFromD<D>* s_out, int* which_out, std::ptrdiff_t i, sorted_lanes<hn::TFromD<D>>& sorted,
                            case_counts& counts) {
  using T = hn::TFromD<D>;
  using L = lanes<D>;
  using layout = detail::binary_layout<T>;
  using U = typename layout::bits;
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  const auto u = hn::LoadU(d, u_in + i), dy = hn::LoadU(d, dy_in + i), phi = hn::LoadU(d, phi_in + i);
  const auto magnitude = hn::Set(du, U(~layout::sign));
  const auto abs_u = hn::And(hn::BitCast(du, u), magnitude), abs_dy = hn::And(hn::BitCast(du, dy), magnitude);

  // the common window (detail::common_window_offsets): the OR of the offsets
  // of |u|, |dy| and phi from the window's lower ends lies below its width
  // (a negative phi, zeros, subnormals, infinity and NaN fail it)
  const auto lowest_uv = hn::Set(du, detail::common_window_lowest_uv<T>);
  const auto window_offsets = hn::Or(hn::Or(hn::Sub(abs_u, lowest_uv), hn::Sub(abs_dy, lowest_uv)),
                                     hn::Sub(hn::BitCast(du, phi), hn::Set(du, detail::common_window_lowest_phi<T>)));
  const auto inside = hn::RebindMask(d, unsigned_less(du, window_offsets, hn::Set(du, detail::common_window_width<T>)));
  const auto index = hn::Add(hn::Iota(di, 0), hn::Set(di, static_cast<hn::TFromD<decltype(di)>>(i)));
  // (the other lanes' case numbers: sort_outside_vector's)
  const hn::Rebind<std::int32_t, D> di32;
  // The lanes inside the window, decided and answered or packed. Where a
  // vector mixes both (`free_flight`: its lanes in free flight, known), the lanes
  // outside solve 1 = 1 = 1 here, a contact, decided at once and with no
  // subnormal operand; their case and s are theirs where they are in free
  // flight, and sort_outside_vector's (or solve_stable's) where not.
  // Always inlined: the compiler's own choice left it a call per vector in
  // some instantiations (float on AVX-512), which then saves and restores
  // the loop's registers around every vector.
  auto sort_inside = [&](auto every_lane_inside, const hn::Mask<D>* free_flight) __attribute__((always_inline)) {
    constexpr bool all_inside = decltype(every_lane_inside)::value;
    auto own = [&](hn::Vec<D> x) {
      if constexpr (all_inside) return L(x);
      else return L(hn::IfThenElse(inside, x, hn::Set(d, T(1))));
    };
    const L own_u = own(u), own_dy = own(dy), own_phi = own(phi);
    const auto cases = decide_cases(d, own_u, own_dy, own_phi, own_phi, own_dy);
    auto contact = cases.contact.m;
    auto which = cases.which;
    if constexpr (!all_inside) {
      contact = hn::And(contact, inside);
      which = hn::IfThenElse(*free_flight, hn::Set(d, T(contact_case::free)), which);
    }
    hn::StoreU(case_numbers(d, which), di32, which_out + i);
    const auto unmoved = hn::Zero(du);
    pack(d, sorted.impacts, counts.impacts, cases.impact.m, u, dy, phi, unmoved, index);
    pack(d, sorted.releases, counts.releases, cases.release.m, u, dy, phi, unmoved, index);
    if constexpr (mode == kernel_mode::stable) {
      // (A.31) here, on every lane: its one division costs less than a pack
      const L contact_s = answer_contacts<D, false>(own_u, own_dy, own_phi);
      hn::StoreU(hn::IfThenElse(contact, contact_s.v, hn::Neg(u)), d, s_out + i);  // (A.29): s = -u
    } else {  // (the rounded modes' step may leave a contact to the scalar path, which the packs' pass does)
      hn::StoreU(hn::Neg(u), d, s_out + i);  // (A.29): s = -u
      pack(d, sorted.contacts, counts.contacts, contact, u, dy, phi, unmoved, index);
    }
  };
  if (hn::AllTrue(d, inside)) [[likely]] {
    sort_inside(std::true_type{}, nullptr);
    return;
  }
  const auto free_flight = detail::free_flight_anywhere(L(u), L(dy), L(phi)).m;
  if (hn::AllFalse(d, inside)) {
    hn::StoreU(hn::Neg(u), d, s_out + i);  // (A.29): s = -u; the second pass writes the other lanes' s
    hn::StoreU(case_numbers(d, hn::IfThenElseZero(free_flight, hn::Set(d, T(contact_case::free)))), di32, which_out + i);
  } else {
    sort_inside(std::false_type{}, &free_flight);
  }
  pack(d, sorted.outside, sorted.outside.count, hn::Not(hn::Or(inside, free_flight)), u, dy, phi, hn::Zero(du), index);
}

// The block's `outside` pack (not empty) through sort_outside_vector, in
// whole vectors: the last one's unused lanes repeat its last lane. The case
// packs hold their counts by now. Out of line, with its loop: the common
// path's loop stays small, and the outside lanes' constants and saved
// registers are set up once a block, not once a vector.
template <kernel_mode mode, class D>
HWY_NOINLINE void sort_outside_lanes(D d, int* which_out, sorted_lanes<hn::TFromD<D>>& sorted) {
  auto& outside = sorted.outside;
  const std::ptrdiff_t width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  for (std::ptrdiff_t k = outside.count; k < outside.count + width; ++k) {
    outside.u[k] = outside.u[outside.count - 1];
    outside.dy[k] = outside.dy[outside.count - 1];
    outside.phi[k] = outside.phi[outside.count - 1];
    outside.index[k] = outside.index[outside.count - 1];
  }
  const hn::RebindToSigned<D> di;
  // phi's band entries gathered a vector ahead: the gather's wait overlaps
  // the vector before, where the vector's own work would wait on it
  auto entries_at = [&](std::ptrdiff_t k) {
    if constexpr (mode == kernel_mode::stable) return band_entries(d, hn::Load(d, outside.phi + k));
    else return hn::Zero(di);  // (unused)
  };
  auto next_entries = entries_at(0);
  for (std::ptrdiff_t k = 0; k < outside.count; k += width) {
    const auto entries = next_entries;
    if (k + width < outside.count) next_entries = entries_at(k + width);
    sort_outside_vector<mode>(d, hn::Load(d, outside.u + k), hn::Load(d, outside.dy + k), hn::Load(d, outside.phi + k),
                              hn::Load(di, outside.index + k), hn::FirstN(d, static_cast<std::size_t>(outside.count - k)), which_out,
                              sorted, entries);
  }
  outside.count = 0;
}

// Every lane of a pack to `left`.
template <kernel_mode mode, class T>
void leave_each_lane(packed_lanes<T>& pack, left_lanes<mode, T>& left) {
  for (std::ptrdiff_t k = 0; k < pack.count; ++k) left.take(pack.index[k]);
  pack.count = 0;
  pack.moved = false;
}

// Arrays too long for the cache stream from memory: the first pass asks for
// each array's lines 1.5 KB ahead, as the hardware's prefetcher alone leaves
// it waiting on memory. Not further: asked a block or two ahead, the memory
// and the arithmetic overlapped less (docs/performance.md, "The stream's
// prefetch distance").
template <class T>
constexpr std::ptrdiff_t prefetch_distance = 1536 / sizeof(T);
constexpr std::ptrdiff_t streamed_lanes = std::ptrdiff_t(1) << 15;

// solve_batch, or solve_rounded_batch in the rounded mode: the first pass is
// the same (the exact case of every lane, free flight answered, but moves
// into the common window in place of phi's bands); the rounded mode answers
// the lanes of the case packs by their fixed-bound step and rounding test and
// leaves the rest to solve_rounded.
template <kernel_mode mode, class T>
std::ptrdiff_t solve(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  std::ptrdiff_t i = 0;
  left_lanes<mode, T> left{u, dy, phi, s, which};
#if HWY_NATIVE_FMA
  using D = hn::ScalableTag<T>;
  const D d;
  const auto width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  sorted_lanes<T> sorted;
  const bool streamed = n >= streamed_lanes;
  // the first pass over the lanes [i, end)
  auto first_pass = [&](std::ptrdiff_t end) __attribute__((always_inline)) {
    case_counts counts{sorted.impacts.count, sorted.releases.count, sorted.contacts.count};
    for (; i < end; i += width) {
      if (streamed && i + prefetch_distance<T> < n) [[likely]] {
        hwy::Prefetch(u + i + prefetch_distance<T>);
        hwy::Prefetch(dy + i + prefetch_distance<T>);
        hwy::Prefetch(phi + i + prefetch_distance<T>);
        __builtin_prefetch(s + i + prefetch_distance<T>, 1);
        __builtin_prefetch(which + i + prefetch_distance<T>, 1);
      }
      sort_vector<mode>(d, u, dy, phi, s, which, i, sorted, counts);
    }
    sorted.impacts.count = counts.impacts;
    sorted.releases.count = counts.releases;
    sorted.contacts.count = counts.contacts;
    if (sorted.outside.count != 0) sort_outside_lanes<mode>(d, which, sorted);
  };
  const std::ptrdiff_t vector_lanes = n - n % width;
  while (i < vector_lanes) {
    const std::ptrdiff_t end = std::min(vector_lanes, i + block);
    if constexpr (mode == kernel_mode::rounded && std::is_same_v<T, float>) {
      if (phi_often_beyond_common_window(d, phi + i, end - i)) {
        left.take_whole(i, end - i);
        i = end;
      } else {
        first_pass(end);
      }
    } else {
      first_pass(end);
    }
    // the packs of each case, by its case's answer in this mode (whole
    // answers only until the last block)
    const bool last_block = end == vector_lanes;
    using L = lanes<D>;
    auto impact_clamp = [](L s, L u, L dy) { return detail::impact_clamped(s, u, dy); };
    auto release_clamp = [](L s, L, L dy) { return detail::clamped_above_positive(s, dy); };
    auto contact_clamp = [](L s, L, L dy) { return detail::contact_clamped(s, dy); };
    auto solve_cases = [&]<int vectors_per_answer = 1>(packed_lanes<T>& impacts, packed_lanes<T>& releases, packed_lanes<T>& contacts,
                                                       auto impact, auto release, auto contact) {
      solve_packed<vectors_per_answer>(d, impacts, left, impact, impact_clamp, last_block);
      solve_packed<vectors_per_answer>(d, releases, left, release, release_clamp, last_block);
      solve_packed<vectors_per_answer>(d, contacts, left, contact, contact_clamp, last_block);
    };
    if constexpr (mode == kernel_mode::rounded_through_double) {
      // (float's stable formulas, as round_through_double takes them: unclamped)
      solve_cases(sorted.impacts, sorted.releases, sorted.contacts,
                  [](L u, L dy, L phi) { return through_double(stable_form::impact(u, -dy, phi)); },
                  [](L u, L dy, L phi) { return through_double(stable_form::release(u, dy, phi)); },
                  [](L u, L dy, L phi) { return through_double(stable_form::contact(u, dy, phi)); });
    } else if constexpr (mode == kernel_mode::rounded) {
      // (the rounded mode's first pass packs no lane of a subnormal phi and no
      // far lane: phi lies in the common window's range, and the far lanes go
      // with the scalar pack)
      solve_cases(sorted.impacts, sorted.releases, sorted.contacts, [](auto... x) { return rounded_impacts<D>(x...); },
                  [](auto... x) { return rounded_releases<D>(x...); }, [](auto... x) { return rounded_contacts<D>(x...); });
    } else {
      solve_cases.template operator()<2>(sorted.impacts, sorted.releases, sorted.contacts,
                                         [](auto... x) { return answer_impacts<D, false>(x...); },
                                         [](auto... x) { return answer_releases<D, false>(x...); },
                                         [](auto... x) { return answer_contacts<D, false>(x...); });
      if (sorted.impacts_of_subnormal_phi.count + sorted.releases_of_subnormal_phi.count + sorted.contacts_of_subnormal_phi.count != 0)
        solve_cases.template operator()<2>(sorted.impacts_of_subnormal_phi, sorted.releases_of_subnormal_phi,
                                           sorted.contacts_of_subnormal_phi, [](auto... x) { return answer_impacts<D, true>(x...); },
                                           [](auto... x) { return answer_releases<D, true>(x...); },
                                           [](auto... x) { return answer_contacts<D, true>(x...); });
      if (sorted.far_impacts.count + sorted.far_releases.count + sorted.far_contacts.count != 0)
        solve_cases.template operator()<2>(sorted.far_impacts, sorted.far_releases, sorted.far_contacts,
                                           [](auto... x) { return far_impacts<D>(x...); },
                                           [](auto... x) { return far_releases<D>(x...); },
                                           [](auto... x) { return far_contacts<D>(x...); });
    }
    leave_each_lane(sorted.scalar, left);
    left.finish();
  }
#endif
  // the last lanes (and every lane where the vectors' multiply-add would round twice)
  for (; i < n; ++i) left.take(i);
  left.finish();
  return left.count;
}

// The packs hold lane indices of T's width (32 bits in float): longer arrays
// go in pieces of 2^30 lanes.
template <kernel_mode mode, class T>
std::ptrdiff_t solve_in_pieces(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  constexpr std::ptrdiff_t piece = std::ptrdiff_t(1) << 30;
  std::ptrdiff_t left = 0;
  for (std::ptrdiff_t first = 0; first < n; first += piece)
    left += solve<mode>(u + first, dy + first, phi + first, s + first, which + first, std::min(piece, n - first));
  return left;
}

}  // namespace

std::ptrdiff_t solve_double(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n) {
  return solve_in_pieces<kernel_mode::stable>(u, dy, phi, s, which, n);
}

std::ptrdiff_t solve_float(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n) {
  return solve_in_pieces<kernel_mode::stable>(u, dy, phi, s, which, n);
}

std::ptrdiff_t solve_rounded_double(const double* u, const double* dy, const double* phi, double* s, int* which,
                                    std::ptrdiff_t n) {
  return solve_in_pieces<kernel_mode::rounded>(u, dy, phi, s, which, n);
}

std::ptrdiff_t solve_rounded_float(const float* u, const float* dy, const float* phi, float* s, int* which,
                                   std::ptrdiff_t n) {
  return solve_in_pieces<kernel_mode::rounded>(u, dy, phi, s, which, n);
}

}  // namespace contact::batch_kernels::CONTACT_BATCH_KERNEL_NAME
