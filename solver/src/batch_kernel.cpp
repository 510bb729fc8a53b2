// The batch kernel of solve_batch for one instruction set: this file is
// compiled once per target with that target's flags (solver/CMakeLists.txt),
// into the namespace contact::batch_kernels::CONTACT_BATCH_KERNEL_NAME, on
// Highway's vectors. The formulas, the pre-test, the exact decision and the
// clamps are stable.hpp's own templates, instantiated on `lanes` (below):
// every lane runs the operations solve_stable runs for it, so every answered
// lane is solve_stable's answer bit for bit.
//
// Two passes over each block of lanes. The first decides each lane's case and
// answers free flight (any valid input); it packs the other lanes by what
// they cost, as they are inside the common window, or moved by a power of two
// into phi's band box (the moved stage of solve_stable). The second solves
// each pack in whole vectors and moves s back. The rest (phi in no band, a
// subnormal phi in float, u and dy too far apart, zero or subnormal u or dy,
// an s that underflows or overflows once moved back, invalid input) go to
// solve_stable, one by one.
#include <hwy/highway.h>

#include <algorithm>
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

// Lanes packed by what they cost: the impacts and releases (a square root
// and a division each) and the contacts (a division), so that no lane waits
// on another case's operations. Each holds the lane's operands as the stable
// path takes them (moved by phi's band where the lane is), the move in bits
// (0: unmoved), and the lane's index in the arrays.
constexpr std::ptrdiff_t block = 256;

template <class T>
struct packed_lanes {
  using bits = typename detail::binary_layout<T>::bits;
  static constexpr std::ptrdiff_t capacity = block + 64;  // a whole vector past the count
  alignas(64) T u[capacity], dy[capacity], phi[capacity];
  alignas(64) bits offset[capacity];
  alignas(64) std::make_signed_t<bits> index[capacity];
  std::ptrdiff_t count = 0;
  bool moved = false;  // some lane has a non-zero offset
};

// The lane orders that bring a mask's lanes first, by the mask's bits: the
// compaction of vectors of up to 8 lanes (Highway's own compress copies a
// table onto the stack at every call for them; 16 lanes of float on AVX-512
// have an instruction).
template <std::size_t lanes_per_vector>
inline constexpr auto compaction_orders = [] {
  std::array<std::array<std::uint8_t, lanes_per_vector>, (std::size_t(1) << lanes_per_vector)> orders{};
  for (std::size_t bits = 0; bits < orders.size(); ++bits) {
    std::size_t k = 0;
    for (std::size_t j = 0; j < lanes_per_vector; ++j)
      if ((bits >> j) & 1) orders[bits][k++] = std::uint8_t(j);
    for (std::size_t j = 0; j < lanes_per_vector; ++j)
      if (!((bits >> j) & 1)) orders[bits][k++] = std::uint8_t(j);
  }
  return orders;
}();

// Appends the lanes of `lanes_of` to `into`, in order.
// A block's lanes as the first pass sorts them: by case, and by whether phi
// is subnormal (double: the first band), and those left to solve_stable.
template <class T>
struct sorted_lanes {
  packed_lanes<T> roots, contacts, roots_of_subnormal_phi, contacts_of_subnormal_phi, scalar;
};

template <class D>
HWY_INLINE void pack(D d, packed_lanes<hn::TFromD<D>>& into, hn::Mask<D> lanes_of, hn::Vec<D> u, hn::Vec<D> dy,
                     hn::Vec<D> phi, hn::Vec<hn::RebindToUnsigned<D>> offset, hn::Vec<hn::RebindToSigned<D>> index) {
  const hn::RebindToUnsigned<D> du;
  const hn::RebindToSigned<D> di;
  const std::ptrdiff_t at = into.count;
  constexpr std::size_t lanes_per_vector = hn::MaxLanes(D());
  if constexpr (lanes_per_vector <= 8 && !HWY_HAVE_SCALABLE) {
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(d, lanes_of, bits);
    const hn::Rebind<std::uint8_t, decltype(di)> d8;
    const hn::Rebind<std::int32_t, decltype(di)> d32;
    const auto order32 = hn::PromoteTo(d32, hn::LoadU(d8, compaction_orders<lanes_per_vector>[bits[0]].data()));
    hn::Vec<decltype(di)> order_lanes;
    if constexpr (sizeof(hn::TFromD<D>) == 8) order_lanes = hn::PromoteTo(di, order32);
    else order_lanes = order32;
    const auto order = hn::IndicesFromVec(d, order_lanes);
    auto first = [&](auto v) { return hn::BitCast(hn::DFromV<decltype(v)>(), hn::TableLookupLanes(hn::BitCast(d, v), order)); };
    hn::StoreU(first(u), d, into.u + at);
    hn::StoreU(first(dy), d, into.dy + at);
    hn::StoreU(first(phi), d, into.phi + at);
    hn::StoreU(first(offset), du, into.offset + at);
    hn::StoreU(first(index), di, into.index + at);
  } else {
    hn::StoreU(hn::Compress(u, lanes_of), d, into.u + at);
    hn::StoreU(hn::Compress(dy, lanes_of), d, into.dy + at);
    hn::StoreU(hn::Compress(phi, lanes_of), d, into.phi + at);
    hn::StoreU(hn::Compress(offset, hn::RebindMask(du, lanes_of)), du, into.offset + at);
    hn::StoreU(hn::Compress(index, hn::RebindMask(di, lanes_of)), di, into.index + at);
  }
  into.count += static_cast<std::ptrdiff_t>(hn::CountTrue(d, lanes_of));
}

// A lane's s, computed on its moved operands, moved back: exact where s is 0
// or the lane unmoved, or s normal above the least binade before the move and
// normal after it (solve_stable's moved_back); `moved_back` is false on the
// others, which underflow or overflow once moved back: solve_stable solves them.
template <class D>
HWY_INLINE lanes<D> move_back(D d, lanes<D> s, hn::Vec<hn::RebindToUnsigned<D>> offset, hn::Mask<D>& moved_back) {
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
  moved_back = hn::RebindMask(d, hn::Or(unmoved, hn::And(above_least_binade, normal_once_moved)));
  return hn::IfThenElse(hn::RebindMask(d, unmoved), s.v, hn::BitCast(d, hn::Sub(s_bits, offset)));
}

// (A.30) and (A.32): the impacts (dy <= 0) and the releases of `lanes`, each
// with its square root and one division: the impact's inverse of its
// denominator, or the release's quotient. With `phi_is_subnormal` the
// products with phi are formed from normal factors, as solve_stable forms
// them (stable_form::impact_quotient).
template <class D, bool phi_is_subnormal>
HWY_INLINE lanes<D> answer_roots(lanes<D> u, lanes<D> dy, lanes<D> phi) {
  using L = lanes<D>;
  const auto impact_side = dy <= L(0);
  const auto factors = detail::factors_of<phi_is_subnormal>(phi, fabs(dy));  // of phi |dy|
  const L sum = u + dy;                                      // impact: u - gap
  const L phi_dy = factors.phi * factors.x;                  // impact: push = phi gap; release: phi dy
  const L term = phi_dy * select(impact_side, sum, dy);      // impact: push (u - gap); release: phi dy^2
  const L root = square_root(stable_form::discriminant(u, term));
  const auto one_plus_phi = detail::two_sum(L(1), phi);
  const auto release = stable_form::release_fraction(u, term, root);
  const L quotient = select(impact_side, L(1), release.numerator) /
                     select(impact_side, stable_form::impact_denominator(one_plus_phi), release.denominator);
  const L push_error = fused_multiply_add(factors.phi, factors.x, -phi_dy);
  const L impact = stable_form::impact_quotient<phi_is_subnormal>(u, phi_dy, push_error, root, one_plus_phi, quotient, factors);
  return select(impact_side, detail::impact_clamped(impact, u, dy), detail::clamped_above_positive(quotient, dy));
}

// (A.31): the contacts, one division each.
template <class D, bool phi_is_subnormal>
HWY_INLINE lanes<D> answer_contacts(lanes<D> u, lanes<D> dy, lanes<D> phi) {
  const auto factors = detail::factors_of<phi_is_subnormal>(phi, dy);
  const auto contact = stable_form::contact_fraction(u, phi, factors.phi, factors.x);
  return detail::contact_clamped(lanes<D>(contact.numerator / contact.denominator), dy);
}

// The packed lanes' s by `answer`, written to their places (their cases are
// written by the first pass); those whose s cannot move back, by
// solve_stable. Returns how many those were.
template <class D, class Answer>
HWY_INLINE std::ptrdiff_t solve_packed(D d, packed_lanes<hn::TFromD<D>>& lanes_in, const hn::TFromD<D>* u_in,
                                       const hn::TFromD<D>* dy_in, const hn::TFromD<D>* phi_in, hn::TFromD<D>* s_out,
                                       int* which_out, Answer answer) {
  using T = hn::TFromD<D>;
  using L = lanes<D>;
  const hn::RebindToUnsigned<D> du;
  const std::ptrdiff_t width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  for (std::ptrdiff_t k = lanes_in.count; k < lanes_in.count + width; ++k) {  // the last vector's unused lanes: 1 = 1 = 1
    lanes_in.u[k] = lanes_in.dy[k] = lanes_in.phi[k] = T(1);
    lanes_in.offset[k] = 0;
  }
  std::ptrdiff_t left = 0;
  for (std::ptrdiff_t k = 0; k < lanes_in.count; k += width) {
    L s = answer(L(hn::Load(d, lanes_in.u + k)), L(hn::Load(d, lanes_in.dy + k)), L(hn::Load(d, lanes_in.phi + k)));
    auto moved_back = hn::FirstN(d, width);
    if (lanes_in.moved) s = move_back(d, s, hn::Load(du, lanes_in.offset + k), moved_back);
    const std::ptrdiff_t lanes_here = std::min(width, lanes_in.count - k);
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
        if (!((moved_back_bits[j / 8] >> (j % 8)) & 1)) {
          const auto i = static_cast<std::ptrdiff_t>(lanes_in.index[k + j]);
          solve_stable_lane(u_in[i], dy_in[i], phi_in[i], s_out[i], which_out[i]);
          ++left;
        }
    }
  }
  lanes_in.count = 0;
  lanes_in.moved = false;
  return left;
}

// The first pass over one vector at lane i: free flight answered (s = -u for
// any valid input, written now); the other lanes that the vectors can take,
// inside the common window or moved by phi's band (solve_stable's moved stage),
// have their case decided as solve_stable decides it and are packed by it;
// the rest are noted for solve_stable.
template <class D>
HWY_INLINE void sort_vector(D d, const hn::TFromD<D>* u_in, const hn::TFromD<D>* dy_in, const hn::TFromD<D>* phi_in,
                            hn::TFromD<D>* s_out, int* which_out, std::ptrdiff_t i, sorted_lanes<hn::TFromD<D>>& sorted) {
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

  // the common window (detail::common_window_offsets): the OR of the offsets
  // of |u|, |dy| and phi from the window's lower ends lies below its width
  // (a negative phi, zeros, subnormals, infinity and NaN fail it)
  const auto lowest_uv = hn::Set(du, detail::common_window_lowest_uv<T>);
  const auto window_offsets = hn::Or(hn::Or(hn::Sub(abs_u, lowest_uv), hn::Sub(abs_dy, lowest_uv)),
                                     hn::Sub(phi_bits, hn::Set(du, detail::common_window_lowest_phi<T>)));
  const auto inside = hn::RebindMask(d, unsigned_less(du, window_offsets, hn::Set(du, detail::common_window_width<T>)));

  L moved_u = u, moved_dy = dy, moved_phi = phi;
  L phi_factor = phi, dy_factor = dy;  // phi dy as their product (detail::factors_of)
  auto offset = hn::Zero(du);
  lane_mask<D> answerable{inside}, free_flight{hn::FirstN(d, 0)}, subnormal_phi{hn::FirstN(d, 0)};
  if (!hn::AllTrue(d, inside)) [[unlikely]] {
    // free flight for any valid input (dy <= 0, u <= -dy, u and dy finite, phi in [+0, inf))
    const auto infinity = hn::Set(d, std::numeric_limits<T>::infinity());
    free_flight.m = hn::And(hn::And(hn::And(hn::Le(dy, hn::Zero(d)), hn::Le(u, hn::Neg(dy))),
                                    hn::And(hn::Gt(dy, hn::Neg(infinity)), hn::Gt(u, hn::Neg(infinity)))),
                            hn::And(hn::Ge(phi, hn::Zero(d)), hn::Lt(phi, infinity)));
    // phi's band: the shift (in binades) that moves the larger of |u|, |dy| to
    // the band's top, taken where u and dy are normal, phi in a band, and the
    // smaller then at or above the band's least binade for its case
    const auto least_normal = hn::Set(du, layout::least_normal);
    const auto normal_span = hn::Set(du, U((layout::exponent_field << significand_bits) - layout::least_normal));
    auto is_normal = [&](hn::Vec<decltype(du)> magnitude_bits) {
      return unsigned_less(du, hn::Sub(magnitude_bits, least_normal), normal_span);
    };
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
    // a subnormal phi in double: every subnormal binade lies in the first band
    // (in float they straddle two: solve_stable takes them)
    constexpr bool subnormal_phi_in_vectors = ((-layout::bias - fields::bands::least_binade) >> fields::bands::band_bits) == 0;
    const auto phi_least = hn::Set(du, subnormal_phi_in_vectors ? U(1) : layout::least_normal);
    const auto phi_in_a_band =
        unsigned_less(du, hn::Sub(phi_bits, phi_least), hn::Sub(hn::Set(du, std::bit_cast<U>(fields::bands::end)), phi_least));
    const auto fits = hn::AndNot(hn::RebindMask(di, inside),
                                 hn::And(hn::RebindMask(di, hn::And(hn::And(is_normal(abs_u), is_normal(abs_dy)), phi_in_a_band)),
                                         hn::Not(hn::Lt(hn::Add(smaller, shift), least))));
    answerable.m = hn::Or(inside, hn::RebindMask(d, fits));
    offset = hn::ShiftLeft<significand_bits>(hn::BitCast(du, hn::IfThenElseZero(fits, shift)));
    // the lanes that cannot be answered solve 1 = 1 = 1: no subnormal operand or result
    const auto one = hn::Set(d, T(1));
    moved_u = hn::IfThenElse(answerable.m, hn::BitCast(d, hn::Add(u_bits, offset)), one);
    moved_dy = hn::IfThenElse(answerable.m, hn::BitCast(d, hn::Add(dy_bits, offset)), one);
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

  // (A.21)'s decision, as solve_cases takes it: the pre-test, and the exact
  // sum for the lanes it leaves undecided near the boundary
  const auto contact_before = moved_dy > L(0);
  const L sum = moved_u + moved_dy;
  const auto [estimate, margin] = detail::estimate_contact(sum, phi_factor, dy_factor);
  const auto decided = fabs(estimate) > margin;
  auto stays = estimate > L(0);
  // (with a subnormal phi the pre-test decides every valid lane, proofs/README.md;
  // should it not, solve_stable takes the lane)
  answerable = answerable & !(subnormal_phi & contact_before & !decided);
  if (!hn::AllFalse(d, (answerable & contact_before & !decided).m)) [[unlikely]]
    stays = (decided & stays) | (!decided & detail::exact_sum_nonnegative(moved_u, moved_dy, moved_phi));

  // (A.29): s = -u, written now, and every lane's case; the second pass
  // writes the other lanes' s, solve_stable the lanes it solves
  free_flight = free_flight | (answerable & !contact_before & (sum <= L(0)));
  const auto is_contact = answerable & contact_before & stays;
  hn::StoreU(hn::Neg(u), d, s_out + i);
  const auto which = hn::IfThenElse(free_flight.m, hn::Set(d, T(contact_case::free)),
                                    hn::IfThenElse(contact_before.m,
                                                   hn::IfThenElse(stays.m, hn::Set(d, T(contact_case::contact)),
                                                                  hn::Set(d, T(contact_case::release))),
                                                   hn::Set(d, T(contact_case::impact))));
  if constexpr (sizeof(T) == 8) {
    const hn::Rebind<std::int32_t, D> di32;
    hn::StoreU(hn::DemoteTo(di32, which), di32, which_out + i);
  } else {
    hn::StoreU(hn::ConvertTo(di, which), di, which_out + i);
  }
  const auto index = hn::Add(hn::Iota(di, 0), hn::Set(di, static_cast<hn::TFromD<decltype(di)>>(i)));
  const auto is_root = answerable & !free_flight & !is_contact;
  if (hn::AllTrue(d, inside)) [[likely]] {
    pack(d, sorted.contacts, is_contact.m, moved_u.v, moved_dy.v, moved_phi.v, offset, index);
    pack(d, sorted.roots, is_root.m, moved_u.v, moved_dy.v, moved_phi.v, offset, index);
    return;
  }
  pack(d, sorted.contacts, (is_contact & !subnormal_phi).m, moved_u.v, moved_dy.v, moved_phi.v, offset, index);
  pack(d, sorted.roots, (is_root & !subnormal_phi).m, moved_u.v, moved_dy.v, moved_phi.v, offset, index);
  pack(d, sorted.contacts_of_subnormal_phi, (is_contact & subnormal_phi).m, moved_u.v, moved_dy.v, moved_phi.v, offset, index);
  pack(d, sorted.roots_of_subnormal_phi, (is_root & subnormal_phi).m, moved_u.v, moved_dy.v, moved_phi.v, offset, index);
  pack(d, sorted.scalar, (!(answerable | free_flight)).m, u, dy, phi, offset, index);
  sorted.roots.moved = sorted.contacts.moved = sorted.roots_of_subnormal_phi.moved = sorted.contacts_of_subnormal_phi.moved = true;
}

template <class T>
std::ptrdiff_t solve(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  std::ptrdiff_t i = 0, left = 0;
#if HWY_NATIVE_FMA
  using D = hn::ScalableTag<T>;
  const D d;
  const auto width = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  sorted_lanes<T> sorted;
  while (i + width <= n) {
    const std::ptrdiff_t end = std::min(n - n % width, i + block);
    for (; i < end; i += width) sort_vector(d, u, dy, phi, s, which, i, sorted);
    left += solve_packed(d, sorted.roots, u, dy, phi, s, which, [](auto... x) { return answer_roots<D, false>(x...); });
    left += solve_packed(d, sorted.contacts, u, dy, phi, s, which, [](auto... x) { return answer_contacts<D, false>(x...); });
    if (sorted.roots_of_subnormal_phi.count != 0)
      left += solve_packed(d, sorted.roots_of_subnormal_phi, u, dy, phi, s, which,
                           [](auto... x) { return answer_roots<D, true>(x...); });
    if (sorted.contacts_of_subnormal_phi.count != 0)
      left += solve_packed(d, sorted.contacts_of_subnormal_phi, u, dy, phi, s, which,
                           [](auto... x) { return answer_contacts<D, true>(x...); });
    packed_lanes<T>& scalar = sorted.scalar;
    for (std::ptrdiff_t k = 0; k < scalar.count; ++k) {
      const auto lane = static_cast<std::ptrdiff_t>(scalar.index[k]);
      solve_stable_lane(u[lane], dy[lane], phi[lane], s[lane], which[lane]);
    }
    left += scalar.count;
    scalar.count = 0;
  }
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
