// The batch kernel of solve_batch for one instruction set: this file is
// compiled once per target with that target's flags (solver/CMakeLists.txt),
// into the namespace contact::batch_kernels::CONTACT_BATCH_KERNEL_NAME, on
// Highway's vectors. The formulas, the pre-test, the exact decision and the
// clamps are stable.hpp's own templates, instantiated on `lanes` (below):
// every lane runs the operations solve_stable runs for it, so every answered
// lane is solve_stable's answer bit for bit.
//
// A vector answers the lanes inside the common window as they are, and the
// others that phi's band lets move (the moved stage of solve_stable): u and
// dy move by a power of two into the band's box and s moves back. Free flight
// is answered for any valid input. The rest (phi in no band or subnormal,
// u and dy too far apart, zero or subnormal u or dy, an s that underflows or
// overflows once moved back, invalid input) go to solve_stable, one by one.
#include <hwy/highway.h>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "batch_kernels.hpp"
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

// a < b on unsigned lanes, as a signed comparison of a and b with their top bits flipped
template <class DU>
HWY_INLINE hn::Mask<DU> unsigned_less(DU du, hn::Vec<DU> a, hn::Vec<DU> b) {
  using U = hn::TFromD<DU>;
  const hn::RebindToSigned<DU> di;
  const auto top = hn::Set(du, U(U(1) << (sizeof(U) * 8 - 1)));
  return hn::RebindMask(du, hn::Lt(hn::BitCast(di, hn::Xor(a, top)), hn::BitCast(di, hn::Xor(b, top))));
}

// phi_bands<T>' table in units of the exponent field, for the lanes' gathers:
// per band, the field of 2^(top - 1) (where the larger of |u|, |dy| moves) and
// the least fields the smaller may then have, for contact and release
// (lowest) and for an impact (impact_lowest).
template <class T>
struct band_fields {
  using bands = detail::phi_bands<T>;
  using layout = detail::binary_layout<T>;
  using field = std::make_signed_t<typename layout::bits>;
  // band = (field of |phi| + index_offset) >> band_bits
  static constexpr field index_offset = -layout::bias - bands::least_binade;
  static_assert(((2 * std::numeric_limits<T>::max_exponent - 1 + index_offset) >> bands::band_bits) < bands::count,
                "every |phi|, infinity and NaN included, indexes the table");
  template <int bands::band::*member, int offset>
  static constexpr std::array<field, bands::count> column = [] {
    std::array<field, bands::count> fields{};
    for (int j = 0; j < bands::count; ++j) fields[j] = field(layout::bias + bands::table[j].*member + offset);
    return fields;
  }();
  static constexpr const auto& top = column<&bands::band::top, -1>;
  static constexpr const auto& lowest = column<&bands::band::lowest, 0>;
  static constexpr const auto& impact_lowest = column<&bands::band::impact_lowest, 0>;
};

// What a vector of lanes answers: s, the case number as T, and which lanes.
template <class D>
struct answers {
  lanes<D> s;
  hn::Vec<D> which;
};

// stage::plain on every lane of (u, dy, phi), on which plain arithmetic
// is safe: each case's parts from stable.hpp, one division and one square
// root per lane, numerator and denominator selected by case. The lanes of
// `answerable` that the pre-test leaves undecided (near the contact
// boundary) take the exact decision, on the vectors that hold one.
template <class D>
HWY_INLINE answers<D> answer_cases(D d, lanes<D> u, lanes<D> dy, lanes<D> phi, lane_mask<D> answerable) {
  using L = lanes<D>;
  using T = hn::TFromD<D>;
  const auto no_contact_before = dy <= L(0);
  const auto contact_before = dy > L(0);
  const L sum = u + dy;                                // impact: u - gap
  const L phi_dy = phi * fabs(dy);                     // impact: push = phi gap; release: phi dy
  const L term = phi_dy * select(no_contact_before, sum, dy);  // impact: push (u - gap); release: phi dy^2
  const L root = square_root(stable_form::discriminant(u, term));

  const auto [estimate, margin] = detail::estimate_contact(sum, phi, dy);  // (A.21)'s pre-test
  const auto decided = fabs(estimate) > margin;
  auto stays = estimate > L(0);
  if (!hn::AllFalse(d, (answerable & contact_before & !decided).m)) [[unlikely]]
    stays = (decided & stays) | (!decided & detail::exact_sum_nonnegative(u, dy, phi));

  const auto is_free = no_contact_before & (sum <= L(0));
  const auto is_impact = no_contact_before & !(sum <= L(0));
  const auto is_contact = contact_before & stays;
  const auto one_plus_phi = detail::two_sum(L(1), phi);
  const auto contact = stable_form::contact_fraction(u, phi, phi, dy);
  const auto release = stable_form::release_fraction(u, term, root);
  const L numerator = select(is_impact, L(1), select(is_contact, contact.numerator, release.numerator));
  const L denominator = select(is_impact, stable_form::impact_denominator(one_plus_phi),
                               select(is_contact, contact.denominator, release.denominator));
  const L quotient = numerator / denominator;  // impact: the inverse of its denominator
  const L push_error = fused_multiply_add(phi, fabs(dy), -phi_dy);
  const L impact = stable_form::impact_quotient<false>(u, phi_dy, push_error, root, one_plus_phi, quotient,
                                                       detail::factors_of<false>(phi, fabs(dy)));
  L s = select(is_contact, detail::contact_clamped(quotient, dy), detail::clamped_above_positive(quotient, dy));
  s = select(is_impact, detail::impact_clamped(impact, u, dy), s);
  s = select(is_free, -u, s);
  const auto which = hn::IfThenElse(is_free.m, hn::Set(d, T(1)),
                                    hn::IfThenElse(is_impact.m, hn::Set(d, T(2)),
                                                   hn::IfThenElse(is_contact.m, hn::Set(d, T(3)), hn::Set(d, T(4)))));
  return {s, which};
}

template <class D>
HWY_INLINE void store(D d, const answers<D>& a, hn::TFromD<D>* s, int* which) {
  hn::StoreU(a.s.v, d, s);
  if constexpr (sizeof(hn::TFromD<D>) == 8) {
    const hn::Rebind<std::int32_t, D> di32;
    hn::StoreU(hn::DemoteTo(di32, a.which), di32, which);
  } else {
    const hn::RebindToSigned<D> di32;
    hn::StoreU(hn::ConvertTo(di32, a.which), di32, which);
  }
}

// A vector with lanes outside the common window: free flight answered for
// any valid input; the other lanes moved by phi's band where it lets them
// (solve_stable's moved stage), solved, and moved back where s stays normal;
// the rest by solve_stable.
template <class D>
HWY_NOINLINE std::ptrdiff_t solve_moved(D d, const hn::TFromD<D>* u_in, const hn::TFromD<D>* dy_in, const hn::TFromD<D>* phi_in,
                              hn::TFromD<D>* s_out, int* which_out, std::ptrdiff_t i, hn::Mask<D> inside_window) {
  using T = hn::TFromD<D>;
  using L = lanes<D>;
  using layout = detail::binary_layout<T>;
  using U = typename layout::bits;
  using fields = band_fields<T>;
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  constexpr int significand_bits = layout::significand_bits;
  const auto u = hn::LoadU(d, u_in + i), dy = hn::LoadU(d, dy_in + i), phi = hn::LoadU(d, phi_in + i);
  const auto magnitude = hn::Set(du, U(~layout::sign));
  const auto u_bits = hn::BitCast(du, u), dy_bits = hn::BitCast(du, dy), phi_bits = hn::BitCast(du, phi);
  const auto abs_u = hn::And(u_bits, magnitude), abs_dy = hn::And(dy_bits, magnitude);
  const auto least_normal = hn::Set(du, layout::least_normal);
  const auto normal_span = hn::Set(du, U((layout::exponent_field << significand_bits) - layout::least_normal));
  auto is_normal = [&](hn::Vec<decltype(du)> magnitude_bits) {
    return unsigned_less(du, hn::Sub(magnitude_bits, least_normal), normal_span);
  };

  const lane_mask<D> inside{inside_window};
  const auto infinity = hn::Set(d, std::numeric_limits<T>::infinity());
  const lane_mask<D> free_flight{hn::And(
      hn::And(hn::And(hn::Le(dy, hn::Zero(d)), hn::Le(u, hn::Neg(dy))), hn::And(hn::Gt(dy, hn::Neg(infinity)), hn::Gt(u, hn::Neg(infinity)))),
      hn::And(hn::Ge(phi, hn::Zero(d)), hn::Lt(phi, infinity)))};

  // the band of phi: its table row, and the shift (in binades) that moves the larger of |u|, |dy| to its top
  auto field_of = [&](hn::Vec<decltype(du)> magnitude_bits) {
    return hn::BitCast(di, hn::ShiftRight<significand_bits>(magnitude_bits));
  };
  const auto u_field = field_of(abs_u), dy_field = field_of(abs_dy);
  const auto larger = hn::Max(u_field, dy_field), smaller = hn::Min(u_field, dy_field);
  const auto band = hn::ShiftRight<fields::bands::band_bits>(
      hn::Add(field_of(hn::And(phi_bits, magnitude)), hn::Set(di, fields::index_offset)));
  const auto least = hn::IfThenElse(hn::RebindMask(di, hn::Le(dy, hn::Zero(d))),
                                    hn::GatherIndex(di, fields::impact_lowest.data(), band),
                                    hn::GatherIndex(di, fields::lowest.data(), band));
  const auto shift = hn::Sub(hn::GatherIndex(di, fields::top.data(), band), larger);
  const auto phi_in_a_band =
      unsigned_less(du, hn::Sub(phi_bits, least_normal), hn::Set(du, U(std::bit_cast<U>(fields::bands::end) - layout::least_normal)));
  const lane_mask<D> fits{hn::RebindMask(
      d, hn::AndNot(hn::RebindMask(di, inside_window),
                    hn::And(hn::RebindMask(di, hn::And(hn::And(is_normal(abs_u), is_normal(abs_dy)), phi_in_a_band)),
                            hn::Not(hn::Lt(hn::Add(smaller, shift), least)))))};
  const auto answerable = inside | fits;
  const auto offset = hn::ShiftLeft<significand_bits>(hn::BitCast(du, hn::IfThenElseZero(hn::RebindMask(di, fits.m), shift)));

  // the lanes that cannot be answered solve 1 = 1 = 1: no subnormal operand or result
  const auto one = hn::Set(d, T(1));
  const L moved_u = hn::IfThenElse(answerable.m, hn::BitCast(d, hn::Add(u_bits, offset)), one);
  const L moved_dy = hn::IfThenElse(answerable.m, hn::BitCast(d, hn::Add(dy_bits, offset)), one);
  answers<D> a = answer_cases(d, moved_u, moved_dy, L(hn::IfThenElse(answerable.m, phi, one)), answerable);

  // s moved back: exact where it is 0, or normal above the least binade
  // before the move and normal after it (solve_stable's move_back); the
  // others, subnormal or overflowing once moved back, go to solve_stable
  const auto s_bits = hn::BitCast(du, a.s.v);
  const auto s_magnitude = hn::And(s_bits, magnitude);
  const auto unmoved = hn::Or(hn::Eq(s_magnitude, hn::Zero(du)), hn::Eq(offset, hn::Zero(du)));
  const auto above_least_binade =
      unsigned_less(du, hn::Sub(s_magnitude, hn::Set(du, U(2 * layout::least_normal))),
                    hn::Set(du, U((layout::exponent_field << significand_bits) - 2 * layout::least_normal)));
  const auto moves_back = hn::And(above_least_binade, is_normal(hn::Sub(s_magnitude, offset)));
  const lane_mask<D> answered{hn::Or(hn::And(answerable.m, hn::RebindMask(d, hn::Or(unmoved, moves_back))), free_flight.m)};
  a.s = hn::IfThenElse(free_flight.m, hn::Neg(u), hn::IfThenElse(hn::RebindMask(d, unmoved), a.s.v, hn::BitCast(d, hn::Sub(s_bits, offset))));
  a.which = hn::IfThenElse(free_flight.m, one, a.which);
  store(d, a, s_out + i, which_out + i);

  if (hn::AllTrue(d, answered.m)) return 0;
  std::uint8_t answered_bits[16] = {};  // one bit per lane
  hn::StoreMaskBits(d, answered.m, answered_bits);
  std::ptrdiff_t left = 0;
  for (std::size_t j = 0; j < hn::Lanes(d); ++j)
    if (!((answered_bits[j / 8] >> (j % 8)) & 1)) {
      solve_stable_lane(u_in[i + j], dy_in[i + j], phi_in[i + j], s_out[i + j], which_out[i + j]);
      ++left;
    }
  return left;
}

// Returns how many lanes it left to solve_stable.
template <class D>
HWY_INLINE std::ptrdiff_t solve_vector(D d, const hn::TFromD<D>* u_in, const hn::TFromD<D>* dy_in, const hn::TFromD<D>* phi_in,
                             hn::TFromD<D>* s_out, int* which_out, std::ptrdiff_t i) {
  using T = hn::TFromD<D>;
  using U = typename detail::binary_layout<T>::bits;
  const hn::RebindToUnsigned<D> du;
  const auto u = hn::LoadU(d, u_in + i), dy = hn::LoadU(d, dy_in + i), phi = hn::LoadU(d, phi_in + i);
  // the common window (detail::common_window_offsets): the OR of the offsets
  // of |u|, |dy| and phi from the window's lower ends lies below its width
  // (a negative phi, zeros, subnormals, infinity and NaN fail it)
  const auto magnitude = hn::Set(du, U(~detail::binary_layout<T>::sign));
  const auto lowest_uv = hn::Set(du, detail::common_window_lowest_uv<T>);
  const auto offsets = hn::Or(hn::Or(hn::Sub(hn::And(hn::BitCast(du, u), magnitude), lowest_uv),
                                     hn::Sub(hn::And(hn::BitCast(du, dy), magnitude), lowest_uv)),
                              hn::Sub(hn::BitCast(du, phi), hn::Set(du, detail::common_window_lowest_phi<T>)));
  const auto inside = hn::RebindMask(d, unsigned_less(du, offsets, hn::Set(du, detail::common_window_width<T>)));
  if (hn::AllTrue(d, inside)) [[likely]] {
    store(d, answer_cases(d, lanes<D>(u), lanes<D>(dy), lanes<D>(phi), lane_mask<D>{inside}), s_out + i, which_out + i);
    return 0;
  }
  return solve_moved(d, u_in, dy_in, phi_in, s_out, which_out, i, inside);
}

template <class T>
std::ptrdiff_t solve(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  std::ptrdiff_t i = 0, left = 0;
#if HWY_NATIVE_FMA
  const hn::ScalableTag<T> d;
  const auto width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  for (; i + width <= n; i += width) left += solve_vector(d, u, dy, phi, s, which, i);
#endif
  // the last lanes (and every lane where the vectors' multiply-add would round twice)
  return left + solve_stable_lanes(u + i, dy + i, phi + i, s + i, which + i, n - i);
}

}  // namespace

std::ptrdiff_t solve_double(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n) {
  return solve(u, dy, phi, s, which, n);
}

std::ptrdiff_t solve_float(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n) {
  return solve(u, dy, phi, s, which, n);
}

}  // namespace contact::batch_kernels::CONTACT_BATCH_KERNEL_NAME
