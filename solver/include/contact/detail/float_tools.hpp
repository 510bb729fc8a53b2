// Error-free transformations and ulp steps, generic over the scalar type.
// They find the scalar's own functions through ADL (`using std::fma`), so
// Boost.Multiprecision types (et_off) use theirs.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <boost/math/special_functions/next.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/multiprecision/traits/is_variable_precision.hpp>

#include "emulated_fma.hpp"
#include "error_free.hpp"

// Declared, not included: the core solver needs no quadmath header.
namespace boost::multiprecision::backends {
struct float128_backend;
}

namespace contact::detail {

// float or double: IEEE binary32 or binary64 in hardware, whose bit patterns
// the fast paths read and step (std::bit_cast to an unsigned integer of the
// same width). Every other type takes the generic path.
template <class T>
concept hardware_binary = std::is_same_v<T, float> || std::is_same_v<T, double>;

// A vector of lanes of float or double (the batch kernel's): its comparisons
// give a mask, not a bool, and it names the scalar of its lanes. The stable
// formulas are written once for scalars and lanes alike; where a scalar would
// branch, lanes select.
template <class T>
concept lane_vector = requires { typename T::lane_scalar; };

// T itself, or the scalar of T's lanes
template <class T>
struct scalar_of {
  using type = T;
};
template <lane_vector T>
struct scalar_of<T> {
  using type = typename T::lane_scalar;
};
template <class T>
using scalar_of_t = typename scalar_of<T>::type;

// float, double and their lanes: the types whose bit patterns the stable
// path steps (clamps) and whose selects need no branch
template <class T>
concept binary_bits = hardware_binary<T> || lane_vector<T>;

// The value make() gives, made where it costs least. The class types (the
// multiprecision numbers, scaled<T>) make it once, as constructing an MPFR
// number allocates. A run-time precision type (MPFR's mpfr_float) makes it at
// the current default precision, as Num(k) would, and again when that
// changes: Boost gives an operation's result the largest precision of its
// operands. The other types build it in place, where it costs nothing.
template <class Num, Num (*make)()>
[[gnu::always_inline]] inline decltype(auto) made_once() {
  if constexpr (boost::multiprecision::detail::is_variable_precision<Num>::value) {
    thread_local struct {
      unsigned digits10 = 0;
      Num value;
    } made;
    if (const unsigned digits10 = Num::default_precision(); made.digits10 != digits10) [[unlikely]] {
      made.value = make();
      made.digits10 = digits10;
    }
    return (made.value);
  } else if constexpr (std::is_class_v<Num> && !lane_vector<Num>) {
    static const Num value = make();
    return (value);
  } else {
    return make();
  }
}

// The formulas' small constants, numerator / denominator, exact in every type
template <class Num, int numerator, int denominator = 1>
Num make_constant() {
  return Num(scalar_of_t<Num>(numerator) / scalar_of_t<Num>(denominator));  // (lanes: in their scalar)
}

template <class Num, int numerator, int denominator = 1>
[[gnu::always_inline]] inline decltype(auto) constant() {
  return made_once<Num, make_constant<Num, numerator, denominator>>();
}

// The machine epsilon of Num (of its lanes' scalar)
template <class Num>
Num make_epsilon() {
  return Num(std::numeric_limits<scalar_of_t<Num>>::epsilon());
}

template <class Num>
[[gnu::always_inline]] inline decltype(auto) epsilon() {
  return made_once<Num, make_epsilon<Num>>();
}

// Whether T's fma rounds once. Boost 1.74's cpp_bin_float computes fma as a
// product and a sum, rounding twice; it gets Dekker's product instead.
template <class T>
struct has_fused_fma : std::true_type {};  // std::fma, fmaq (float128), mpfr_fma
template <unsigned Digits, boost::multiprecision::backends::digit_base_type Base, class Allocator, class Exponent,
          Exponent MinExponent, Exponent MaxExponent, boost::multiprecision::expression_template_option Templates>
struct has_fused_fma<boost::multiprecision::number<
    boost::multiprecision::backends::cpp_bin_float<Digits, Base, Allocator, Exponent, MinExponent, MaxExponent>, Templates>>
    : std::false_type {};

// T's fma where it is fused and fast; for x87 long double and binary128 the
// same single rounding in integer arithmetic (emulated_fma.hpp).
template <class T>
T fma_rounded_once(const T& a, const T& b, const T& c) {
  if constexpr (emulated_format<T>::available) {
    return emulated_fma(a, b, c);
  } else {
    using std::fma;
    return fma(a, b, c);
  }
}

// Whether T's fma is emulated in integers (x87 long double), where Dekker's
// product gives a product's exact error for about a quarter of the cost.
template <class T>
inline constexpr bool product_error_by_dekker = !has_fused_fma<T>::value ||
                                                (std::is_same_v<T, long double> && emulated_format<T>::available);

// a * b - product exactly, for product = a * b rounded, barring overflow (of
// the split, within 2^-(p/2) of T's largest value, in Dekker's case) and
// underflow of the error: T's own fused fma, or Veltkamp's split and Dekker's
// product, exact for any radix-2 T. (A caller that needs the product too takes
// two_prod, which forms binary128's pair from one product in integers.)
template <class T>
T fused_multiply_add(const T& a, const T& b, const T& c);

// For MPFR, an fma with a temporary operand rounds into that operand's
// storage (MPFR allows the aliasing), as Boost's operators do with their
// temporaries: the same value where the three share a precision, as they do
// when made at one default precision; otherwise Boost's fma, whose result
// takes the largest.
template <mpfr_number T>
T fused_multiply_add_into(T&& storage, const T& a, const T& b, const T& c) {
  const auto precision = storage.backend().data()->_mpfr_prec;
  if ((a.backend().data()->_mpfr_prec != precision) | (b.backend().data()->_mpfr_prec != precision) |
      (c.backend().data()->_mpfr_prec != precision)) [[unlikely]]
    return fma_rounded_once(a, b, c);
  eval_multiply_add(storage.backend(), a.backend(), b.backend(), c.backend());
  return std::move(storage);
}

template <mpfr_number T>
T fused_multiply_add(T&& a, const T& b, const T& c) {
  return fused_multiply_add_into(std::move(a), a, b, c);
}

template <mpfr_number T>
T fused_multiply_add(const T& a, const T& b, T&& c) {
  return fused_multiply_add_into(std::move(c), a, b, c);
}

template <mpfr_number T>
T fused_multiply_add(T&& a, const T& b, T&& c) {
  return fused_multiply_add_into(std::move(a), a, b, c);
}

// |x| > bound, for bound >= 0, without the number fabs would make for MPFR
template <class T>
bool magnitude_exceeds(const T& x, const T& bound) {
  if constexpr (mpfr_number<T>) {
    return mpfr_cmpabs(x.backend().data(), bound.backend().data()) > 0;
  } else {
    using std::fabs;
    return fabs(x) > bound;
  }
}

template <class T>
T product_error(const T& a, const T& b, const T& product) {
  if constexpr (!product_error_by_dekker<T>) {
    return fused_multiply_add(a, b, T(-product));  // the lanes' and scaled<T>'s own too
  } else {
    return dekker_product_error(a, b, product);
  }
}

// a * b == product + error exactly, barring overflow and underflow of the error.
template <class T>
exact_pair<T> two_prod(const T& a, const T& b) {
  if constexpr (binary128_class<T>) {  // both parts from one product in integers
    exact_pair<T> parts;
    if (two_prod_in_integers(a, b, parts)) [[likely]] return parts;
  }
  T product = a * b;
  T error = product_error(a, b, product);
  return {std::move(product), std::move(error)};  // (moved: copying an MPFR number allocates)
}

// head + tail rounded to nearest, for |tail| below an ulp of head, where
// Boost 1.74's cpp_bin_float adds wrongly: a tail between a quarter and half
// an ulp of opposite sign (the sum's guard bit set, its sticky bits lost in
// the borrow) comes back as a tie and rounds to even, one ulp off half the
// time. Below half an ulp the nearest is head itself, or, for a power of two
// head and a tail of opposite sign from a quarter of its ulp up, its lower
// neighbour (spaced half as far); a quarter exactly is a tie, to head, even.
template <class T>
T sum_of_head_and_tail(const T& head, const T& tail) {
  using std::fabs;
  using std::frexp;
  using std::ldexp;
  int binade = 0;
  const T fraction = frexp(head, &binade);  // head = fraction 2^binade, |fraction| in [0.5, 1)
  const T half_ulp = ldexp(T(1), binade - precision_of<T>() - 1);
  if (!(fabs(tail) < half_ulp) || head == 0) return head + tail;
  const bool lower_binade = fabs(fraction) == T(0.5) && (tail < 0) != (head < 0);
  if (lower_binade && fabs(tail) > half_ulp / 2) return head + (tail < 0 ? -half_ulp : half_ulp);
  return head;
}

// a * b + c with one rounding where T's fma is fused; otherwise the exact
// product and sum, rounded once at the end but for the low-order parts (within
// an ulp, and exact where a * b + c cancels, which is where it matters).
template <class T>
T fused_multiply_add(const T& a, const T& b, const T& c) {
  if constexpr (has_fused_fma<T>::value) {
    return fma_rounded_once(a, b, c);
  } else {
    const auto product = two_prod(a, b);
    const auto sum = two_sum(product.high, c);
    return sum_of_head_and_tail(sum.high, T(sum.low + product.low));
  }
}

template <class T>
T select(bool condition, const T& if_true, const T& if_false);

// The largest component of the exact sum of N numbers as an expansion, by
// Shewchuk's grow-expansion: the components stay non-overlapping and in order
// of increasing magnitude but for zeros among them, so the last non-zero one
// has the sign of the whole (0 when the sum is 0). Exact while no partial sum
// overflows. The zeros are kept rather than eliminated: a fixed number of
// two_sums and selects, without the branches on each error's zero that cost
// more, near the contact boundary, than they save, and a form the batch
// kernels vectorise (the AVX-512 one calls it on vectors of eight lanes).
template <class T, int N>
T leading_component_of_exact_sum(const T (&terms)[N]) {
  T expansion[N];
  // unrolled, so that the batch kernels' loop over lanes has no inner loop
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i) {
    T carry = terms[i];
#pragma GCC unroll 16
    for (int j = 0; j < i; ++j) {
      auto [sum, error] = two_sum(carry, expansion[j]);
      expansion[j] = error;
      carry = sum;
    }
    expansion[i] = carry;
  }
  T leading = T(0);
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i) leading = select(expansion[i] != T(0), expansion[i], leading);
  return leading;
}

// Sign (-1, 0, +1) of the exact sum of N numbers.
template <class T, int N>
int sign_of_exact_sum(const T (&terms)[N]) {
  const T leading = leading_component_of_exact_sum(terms);
  return int(leading > T(0)) - int(T(0) > leading);
}

// The upper neighbour of a finite x below the largest value, for the types
// that boost::math::float_next cannot take: it compares T with float literals,
// which Boost.Multiprecision refuses for a type narrower than float (a
// cpp_bin_float of a few bits). With x = m 2^(e - digits), m an integer of
// digits bits, the neighbour is (m + 1) 2^(e - digits), or, from a negative
// power of two into the binade below, (1 - 2^digits) 2^(e - digits - 1); every
// step is exact, and ldexp flushes to zero what falls below the least normal
// value, the neighbour there of a type without subnormals. With subnormals,
// the values below twice the least normal value are the multiples of the least
// subnormal, so the neighbour is the exact sum.
template <class T>
T upper_neighbour_by_frexp(const T& x) {
  using std::fabs;
  using std::frexp;
  using std::ldexp;
  if constexpr (std::numeric_limits<T>::has_denorm == std::denorm_present) {
    if (fabs(x) < 2 * (std::numeric_limits<T>::min)()) return x + std::numeric_limits<T>::denorm_min();
  } else {
    if (x == 0) return (std::numeric_limits<T>::min)();
  }
  int exponent = 0;
  const int digits = precision_of<T>();
  const T m = ldexp(frexp(x, &exponent), digits);
  if (m == -ldexp(T(1), digits - 1)) return ldexp(T(1 - (1LL << digits)), exponent - digits - 1);
  return ldexp(m + T(1), exponent - digits);
}

template <class T>
  requires hardware_binary<T>
std::int64_t ordered_key(T x);
template <class T>
  requires hardware_binary<T>
T from_ordered_key(std::int64_t k);

// The neighbours of a finite x; they saturate at +-infinity instead of
// raising. binary32 and binary64 step their ordered bit patterns (the clamps
// of the stable path run them on every boundary input).
template <class T>
T next_up(const T& x) {
  if (x >= (std::numeric_limits<T>::max)()) return std::numeric_limits<T>::infinity();
  if constexpr (hardware_binary<T>) return from_ordered_key<T>(ordered_key(x) + 1);
  else if constexpr (emulated_format<T>::available) return neighbour_by_bits(x, true);
  else if constexpr (std::is_convertible_v<float, T>) return boost::math::float_next(x);
  else return upper_neighbour_by_frexp(x);
}

template <class T>
T next_down(const T& x) {
  if (x <= -(std::numeric_limits<T>::max)()) return -std::numeric_limits<T>::infinity();
  if constexpr (hardware_binary<T>) return from_ordered_key<T>(ordered_key(x) - 1);
  else if constexpr (emulated_format<T>::available) return neighbour_by_bits(x, false);
  else if constexpr (std::is_convertible_v<float, T>) return boost::math::float_prior(x);
  else return -upper_neighbour_by_frexp(T(-x));
}

// Whether T's sqrt rounds correctly. libquadmath's sqrtq (Boost's float128)
// does not: about one square of a random float128 in fifty gets back a root
// one ulp off.
template <class T>
struct has_correct_sqrt : std::true_type {};  // IEEE hardware sqrt, MPFR, cpp_bin_float
template <boost::multiprecision::expression_template_option Templates>
struct has_correct_sqrt<boost::multiprecision::number<boost::multiprecision::backends::float128_backend, Templates>>
    : std::false_type {};

// sqrt(x) rounded to nearest. Where T's own sqrt is only faithful (within an
// ulp), its result r is moved to a neighbour when the root lies beyond the
// midpoint between them. With r+ = next_up(r) and U the ulp of r, the upper
// midpoint m = (r + r+) / 2 has m^2 = r r+ + U^2 / 4, and x - r r+ is a
// multiple of U^2 (r and r+ are multiples of U, and x, near r^2, of its own
// ulp, a larger power of two), so sqrt(x) > m exactly when x - r r+ > 0: the
// sign of one fma, which rounding keeps. Likewise below, with r- = next_down(r)
// and U' the ulp of r- (U, or U / 2 when r is a power of two): the lower
// midpoint's square is r r- + U'^2 / 4 and x - r r- a multiple of U U', so
// sqrt(x) < that midpoint exactly when x - r r- <= 0. A root is never a
// midpoint, so there are no ties.
template <class T>
T square_root(const T& x) {
  using std::sqrt;
  T root = sqrt(x);
  if constexpr (!has_correct_sqrt<T>::value) {
    static_assert(has_fused_fma<T>::value, "the midpoint tests need an fma rounded once");
    using std::isfinite;
    if (!(x > 0) || !isfinite(x)) return root;
    // a faithful root is at most one neighbour away from the nearest
    const T above = next_up(root);
    if (fma_rounded_once(T(-root), above, x) > 0) return above;
    const T below = next_down(root);
    if (!(fma_rounded_once(T(-root), below, x) > 0)) return below;
  }
  return root;
}

// The layout of binary32 and binary64: the unsigned integer of T's width, the
// sign bit, the significand field's width, the exponent field's all-ones value
// (unshifted), the exponent bias, and the bits of the least normal value. The
// one place the bit-pattern code of the window, scaled<T>, the batch kernels
// and the rounded mode reads them from.
template <class T>
  requires hardware_binary<T>
struct binary_layout {
  using bits = std::conditional_t<std::is_same_v<T, double>, std::uint64_t, std::uint32_t>;
  static constexpr bits sign = bits(1) << (sizeof(bits) * 8 - 1);
  static constexpr int significand_bits = std::numeric_limits<T>::digits - 1;
  static constexpr bits exponent_field = bits(2 * std::numeric_limits<T>::max_exponent - 1);
  static constexpr int bias = std::numeric_limits<T>::max_exponent - 1;
  static constexpr bits least_normal = bits(1) << significand_bits;

  // Whether a magnitude (the bits of |x|) is a normal number, in one unsigned
  // comparison: zero and subnormals wrap around to the top, infinity and NaN
  // lie at or beyond the span.
  static bool is_normal(bits magnitude) {
    constexpr bits normal_span = bits((exponent_field << significand_bits) - least_normal);
    return bits(magnitude - least_normal) < normal_span;
  }
  // Whether it is normal and above the least normal binade, likewise. The moved
  // stage keeps a moved s only from there up: impact's quotient, which the
  // compensation corrects by less than 2^-50 of it, is then normal too
  // (proofs/gappa/window/impact_push_zero.g.in).
  static constexpr bits second_normal_binade = 2 * least_normal;
  static bool is_normal_above_least_binade(bits magnitude) {
    constexpr bits span = bits((exponent_field << significand_bits) - second_normal_binade);
    return bits(magnitude - second_normal_binade) < span;
  }
};

// x with its sign bit set (-|x|), and the value one bit pattern further from
// zero than x: for a finite x, next_down or next_up away from zero (from -0,
// the least negative subnormal). The clamps of the stable path step dy so,
// in scalars and in lanes alike (the lanes have their own overloads).
template <class T>
  requires hardware_binary<T>
T with_sign_bit(const T& x) {
  using layout = binary_layout<T>;
  return std::bit_cast<T>(typename layout::bits(std::bit_cast<typename layout::bits>(x) | layout::sign));
}

template <class T>
  requires hardware_binary<T>
T step_away_from_zero(const T& x) {
  using bits = typename binary_layout<T>::bits;
  return std::bit_cast<T>(bits(std::bit_cast<bits>(x) + 1));
}

// condition ? if_true : if_false without a branch, for conditions that are a
// coin toss on the inputs that reach them (the sign of u, say). A compiler
// may turn ?: into a branch, and GCC does at -O3 on release's operands; on a
// blend it cannot. With AVX-512 the values stay in their vector registers and
// the condition becomes a mask register (faster on the physical scene's
// inputs, where each solve makes one to three; SSE4.1's blendv was not);
// otherwise the blend is of bits, through the integer registers. Other types
// take ?:.
template <class T>
T select(bool condition, const T& if_true, const T& if_false) {
#if defined(__AVX512F__)
  if constexpr (std::is_same_v<T, double>) {
    return _mm_cvtsd_f64(_mm_mask_blend_pd(__mmask8(condition), _mm_set_sd(if_false), _mm_set_sd(if_true)));
  } else if constexpr (std::is_same_v<T, float>) {
    return _mm_cvtss_f32(_mm_mask_blend_ps(__mmask8(condition), _mm_set_ss(if_false), _mm_set_ss(if_true)));
  } else  // (the chain goes on below: no other branch is instantiated for double and float)
#endif
  if constexpr (hardware_binary<T>) {
    using bits = typename binary_layout<T>::bits;
    const bits chosen = bits(0) - bits(condition);  // all ones or all zeros
    return std::bit_cast<T>(bits((std::bit_cast<bits>(if_true) & chosen) | (std::bit_cast<bits>(if_false) & ~chosen)));
  } else {
    return condition ? if_true : if_false;
  }
}

// a < b ? a : b and a > b ? a : b, which are x86's minsd and maxsd (minss,
// maxss) exactly, whatever the operands: a NaN or a pair of zeros gives b
// (at run time: GCC folds constant operands as if the two commuted, a case
// the clamps never meet, their bounds being non-zero numbers and s a number
// for every valid input; tests/float_tools_test.cpp, MinAndMax). A clamp
// written so is one instruction, with no branch, compare or mask register;
// one of selects takes a compare, a mask and a blend and is slower, most on
// impact inputs (two clamps), so the stable path clamps with these. Written
// as intrinsics: GCC compiles the ?: form to minsd where it
// stands alone, but into a branch inside the moved stage, which is slower on
// the extreme scene's impact inputs.
template <class T>
T min_of(const T& a, const T& b) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>)
    return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(a), _mm_set_sd(b)));
  else if constexpr (std::is_same_v<T, float>)
    return _mm_cvtss_f32(_mm_min_ss(_mm_set_ss(a), _mm_set_ss(b)));
  else  // (discarded for double and float, as in select)
#endif
    return a < b ? a : b;
}

template <class T>
T max_of(const T& a, const T& b) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>)
    return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(a), _mm_set_sd(b)));
  else if constexpr (std::is_same_v<T, float>)
    return _mm_cvtss_f32(_mm_max_ss(_mm_set_ss(a), _mm_set_ss(b)));
  else  // (discarded for double and float, as in select)
#endif
    return a > b ? a : b;
}

// phi and a factor x of a product phi x, as factors of the same exact product
// that are normal where phi is a subnormal binary32 or binary64: (phi 2^64,
// x 2^-64), as a subnormal operand of a product or an fma costs a microcode
// assist on many cores. phi 2^64 is formed from phi's bits, an integer that
// converts exactly; x 2^-64 must be exact, which the callers with a subnormal
// phi, the moved stage's first band and the batch's rescaled pass over it,
// ensure (|x| >= 2^52 there: the first band's impact room in double, 2^23 in float).
// `down` is 2^-64 where moved, else 1, and scales another factor the same way.
template <class T>
struct normal_factors {
  T phi, x, down;
  bool moved;
};

// x > 0 subnormal (binary32 or binary64): one unsigned comparison of the bits;
// for either sign, pass |x|
template <class T>
  requires hardware_binary<T>
bool is_positive_subnormal(const T& x) {
  using bits = typename binary_layout<T>::bits;
  return bits(std::bit_cast<bits>(x) - 1) < bits(binary_layout<T>::least_normal - 1);
}

// The factors where phi is known to be subnormal (the moved stage's subnormal-phi path).
template <class T>
  requires hardware_binary<T>
normal_factors<T> subnormal_phi_factors(const T& phi, const T& x) {
  using bits = typename binary_layout<T>::bits;
  constexpr T up = T(0x1p64), down = T(0x1p-64);
  constexpr T least_subnormal_up = std::numeric_limits<T>::denorm_min() * up;
  return {T(std::make_signed_t<bits>(std::bit_cast<bits>(phi))) * least_subnormal_up, T(x * down), down, true};
}

// phi and x themselves, where nothing moves: references, as a copy of a
// multiprecision number allocates. Valid while phi and x are.
template <class T>
struct unmoved_factors {
  const T& phi;
  const T& x;
};

// The factors of phi x: unmoved unless `phi_is_subnormal`, a compile-time fact.
template <bool phi_is_subnormal, class T>
auto factors_of(const T& phi, const T& x) {
  if constexpr (phi_is_subnormal) return subnormal_phi_factors(phi, x);
  else return unmoved_factors<T>{phi, x};
}

// The factors for any phi > 0, by selects (the batch's lanes).
template <class T>
normal_factors<T> normal_factors_of(const T& phi, const T& x) {
  if constexpr (hardware_binary<T>) {
    const bool subnormal = is_positive_subnormal(phi);
    const auto moved = subnormal_phi_factors(phi, x);
    return {select(subnormal, moved.phi, phi), select(subnormal, moved.x, x), select(subnormal, moved.down, T(1)), subnormal};
  } else {
    return {phi, x, T(1), false};
  }
}

// binary32 and binary64 values as ordered integers (-0 and +0 both map to 0),
// so that k representable values apart is k integers apart.
template <class T>
  requires hardware_binary<T>
std::int64_t ordered_key(T x) {
  using bits = typename binary_layout<T>::bits;
  constexpr bits sign = binary_layout<T>::sign;
  const bits b = std::bit_cast<bits>(x);
  return (b & sign) ? -std::int64_t(b & ~sign) : std::int64_t(b);
}

template <class T>
  requires hardware_binary<T>
T from_ordered_key(std::int64_t k) {
  using bits = typename binary_layout<T>::bits;
  constexpr bits sign = binary_layout<T>::sign;
  return std::bit_cast<T>(k >= 0 ? bits(k) : bits(sign | bits(-k)));
}

// x moved by k representable values of T (through zero if need be),
// saturating at -+ the largest finite value: a finite x stays finite.
template <class T>
T ulp_steps(const T& x, long k) {
  if constexpr (hardware_binary<T>) {
    const std::int64_t largest = ordered_key((std::numeric_limits<T>::max)());
    std::int64_t key = ordered_key(x) + k;
    key = key > largest ? largest : (key < -largest ? -largest : key);
    return from_ordered_key<T>(key);
  } else {
    const T largest = (std::numeric_limits<T>::max)();
    T y = x;
    for (; k > 0 && y < largest; --k) y = next_up(y);
    for (; k < 0 && y > -largest; ++k) y = next_down(y);
    return y;
  }
}

}  // namespace contact::detail
