// scaled<T>: a significand of type T in [0.5, 1) and a separate integer
// exponent. Every operation rescales by an exact power of two, so the
// significand arithmetic rounds exactly as T would with an unbounded exponent
// range: no intermediate overflows or underflows. The only roundings beyond
// T's are (a) in a sum whose smaller term lies more than the whole exponent
// range of T below the larger (an absolute error below T's least subnormal
// relative to the larger term) and (b) at the end, in the conversion back to T.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "float_tools.hpp"

namespace contact::detail {

template <class T>
struct scaled {
  T significand{0};  // 0, or 0.5 <= |significand| < 1; NaN and inf kept as they are
  long exponent{0};

  scaled() = default;
  scaled(const T& x) { *this = normalized(x, 0); }  // NOLINT: implicit, as for T
  scaled(int x) : scaled(T(x)) {}                   // NOLINT

  static scaled normalized(const T& m, long e) {
    using std::frexp;
    using std::isfinite;
    scaled r;
    if constexpr (hardware_binary<T>) {  // frexp and ldexp's common case on the bits
      // frexp of a normal m, on its bits: the exponent field set to that of [0.5, 1)
      using layout = binary_layout<T>;
      using bits = typename layout::bits;
      constexpr int significand_bits = layout::significand_bits, bias = layout::bias;
      constexpr bits field_mask = layout::exponent_field;
      const bits b = std::bit_cast<bits>(m);
      const int field = int((b >> significand_bits) & field_mask);
      if (field != 0 && field != int(field_mask)) {
        r.significand = std::bit_cast<T>(bits((b & ~(field_mask << significand_bits)) | (bits(bias - 1) << significand_bits)));
        r.exponent = e + field - (bias - 1);
        return r;
      }
      if (field == int(field_mask) || m == 0) {  // infinity, NaN and zero stay as they are
        r.significand = m;
        return r;
      }
      return normalized(subnormal_as_integer(m), e - least_binade_of_bits);
    } else {
      if (m == 0 || !isfinite(m)) {
        r.significand = m;
        return r;
      }
      int k = 0;
      r.significand = frexp(m, &k);
      r.exponent = e + k;
      return r;
    }
  }

  // x * 2^shift, clamped so that huge shifts saturate to 0 or infinity.
  static T shifted(const T& x, long shift) {
    using std::ldexp;
    if constexpr (hardware_binary<T>) {  // frexp and ldexp's common case on the bits
      // ldexp on the bits: a normal result by moving the exponent field, zero
      // and infinity directly, a subnormal one by one multiplication
      using layout = binary_layout<T>;
      using bits = typename layout::bits;
      constexpr int significand_bits = layout::significand_bits;
      constexpr bits field_mask = layout::exponent_field;
      const bits b = std::bit_cast<bits>(x);
      const long field = long((b >> significand_bits) & field_mask);
      // x and x 2^shift both normal, the common case, first and in one branch
      // instead of five (unsigned: a field + shift that wraps lands far
      // outside the normal fields); the tests below then take the rest
      using unsigned_long = unsigned long;
      const unsigned_long normal_fields = unsigned_long(field_mask) - 1;  // 1 .. field_mask - 1, less one
      if ((unsigned_long(field) - 1 < normal_fields) & (unsigned_long(field) + unsigned_long(shift) - 1 < normal_fields))
        return std::bit_cast<T>(bits(b + (bits(shift) << significand_bits)));
      if (field == long(field_mask) || x == 0) return x;  // infinity, NaN and zero times 2^shift
      if (field == 0)  // (a shift from below -2^31 on gives zero all the same, and no overflow)
        return shifted(subnormal_as_integer(x), std::max(shift, long(INT_MIN)) - least_binade_of_bits);
      // beyond the whole exponent range either way; no sum below can overflow a long
      if (shift <= -2 * long(field_mask)) return std::copysign(T(0), x);
      if (shift >= 2 * long(field_mask)) return std::copysign(std::numeric_limits<T>::infinity(), x);
      const long target = field + shift;  // the exponent field the result would have (not normal: taken above)
      if (target >= long(field_mask)) return std::copysign(std::numeric_limits<T>::infinity(), x);
      // below 2^(1 - bias - significand_bits) / 2 (ties to the even zero) it rounds to zero
      if (target <= -significand_bits - 1) return std::copysign(T(0), x);
      // a subnormal result: an exact move to a normal binade `margin` above it,
      // then one multiplication by the normal 2^-margin, which rounds once, as ldexp
      constexpr int margin = significand_bits + 2;
      constexpr T down = std::bit_cast<T>(bits(bits(layout::bias - margin) << significand_bits));
      const bits field_cleared = b & ~(field_mask << significand_bits);
      return std::bit_cast<T>(bits(field_cleared | (bits(target + margin) << significand_bits))) * down;
    } else {
      constexpr long limit = INT_MAX / 2;
      if (shift > limit) shift = limit;
      if (shift < -limit) shift = -limit;
      return ldexp(x, static_cast<int>(shift));
    }
  }

  T value() const { return shifted(significand, exponent); }
  int sign() const { return significand > 0 ? 1 : (significand < 0 ? -1 : 0); }

  friend scaled operator-(const scaled& a) { return {-a.significand, a.exponent, 0}; }
  friend scaled operator*(const scaled& a, const scaled& b) {
    return normalized(a.significand * b.significand, a.exponent + b.exponent);
  }
  friend scaled operator/(const scaled& a, const scaled& b) {
    return normalized(a.significand / b.significand, a.exponent - b.exponent);
  }
  friend scaled operator+(const scaled& a, const scaled& b) {
    if (b.significand == 0) return a;
    if (a.significand == 0) return b;
    if (a.exponent >= b.exponent)
      return normalized(a.significand + shifted(b.significand, b.exponent - a.exponent), a.exponent);
    return normalized(shifted(a.significand, a.exponent - b.exponent) + b.significand, b.exponent);
  }
  friend scaled operator-(const scaled& a, const scaled& b) { return a + (-b); }
  friend bool operator>(const scaled& a, const scaled& b) { return (a - b).sign() > 0; }
  friend bool operator==(const scaled& a, const scaled& b) { return (a - b).sign() == 0; }

  // a * b + c with the single rounding of T's fma.
  friend scaled fused_multiply_add(const scaled& a, const scaled& b, const scaled& c) {
    if (a.significand == 0 || b.significand == 0) return c;
    long product_exponent = a.exponent + b.exponent;
    if (c.significand == 0 || product_exponent >= c.exponent)
      return normalized(fused_multiply_add(a.significand, b.significand, shifted(c.significand, c.exponent - product_exponent)),
                        product_exponent);
    return normalized(fused_multiply_add(a.significand, shifted(b.significand, product_exponent - c.exponent), c.significand),
                      c.exponent);
  }

  // rounded to nearest (square_root of float_tools.hpp)
  friend scaled square_root(const scaled& a) {
    if (a.significand <= 0) return normalized(detail::square_root(a.significand), 0);
    // an even exponent halves exactly; the significand moves into [0.25, 1)
    // (the parity of the exponent is a coin toss: a select, not a branch)
    const bool odd = (a.exponent % 2) != 0;
    const T m = select(odd, T(a.significand / 2), a.significand);
    return normalized(detail::square_root(m), (a.exponent + long(odd)) / 2);
  }

  // A subnormal binary32 or binary64 x is k 2^-least_binade_of_bits for the
  // integer k of its significand field, which converts to T exactly (and
  // normal): frexp and ldexp take a slow path on subnormals, and so does any
  // product with one (a microcode assist on x86).
  static constexpr int least_binade_of_bits = [] {
    if constexpr (hardware_binary<T>) return binary_layout<T>::bias - 1 + binary_layout<T>::significand_bits;
    else return 0;
  }();
  static T subnormal_as_integer(const T& x) {
    using bits = typename binary_layout<T>::bits;
    const bits magnitude = std::bit_cast<bits>(x) & ~binary_layout<T>::sign;
    return std::copysign(T(std::make_signed_t<bits>(magnitude)), x);
  }

 private:
  scaled(const T& m, long e, int) : significand(m), exponent(e) {}
};

// TwoSum of two scaled numbers as IEEE arithmetic with an unbounded exponent
// would compute it, and as detail::two_sum's six sums on scaled<T> do (the
// rounded sum and its error are unique), with one alignment instead of six:
// when the smaller lies more than p + 1 binades below the larger it is below
// half an ulp of it, so the rounded sum is the larger and the error the
// smaller; otherwise the smaller's significand shifts into the larger's frame
// without loss (its lowest bit stays above 2^(-2p-2)). A zero term gives the
// other one, exactly (sign_of_exact_sum keeps the zeros of its expansion; one
// test, as `|`, for either). The exact decisions and the compensated impact
// form run it.
template <class T>
exact_pair<scaled<T>> two_sum(const scaled<T>& a, const scaled<T>& b) {
  if ((a.significand == 0) | (b.significand == 0)) return {a + b, scaled<T>()};
  const bool a_larger = a.exponent >= b.exponent;
  const scaled<T>& large = a_larger ? a : b;
  const scaled<T>& small = a_larger ? b : a;
  const long gap = large.exponent - small.exponent;
  if (gap > long(precision_of<T>()) + 1) return {large, small};
  const auto [sum, error] = two_sum(large.significand, scaled<T>::shifted(small.significand, -gap));
  return {scaled<T>::normalized(sum, large.exponent), scaled<T>::normalized(error, large.exponent)};
}

// a * b as an exact pair high + low, by two_prod of the significands: their
// product lies in [0.25, 1) and its low part is a multiple of 2^-2 digits,
// which T holds unless its least normal value lies fewer than 2 digits
// binades below 1; no intermediate can overflow.
template <class T>
std::array<scaled<T>, 2> exact_product(const scaled<T>& a, const scaled<T>& b) {
  const auto product = two_prod(a.significand, b.significand);
  const long exponent = a.exponent + b.exponent;
  return {scaled<T>::normalized(product.high, exponent), scaled<T>::normalized(product.low, exponent)};
}

// The sign of the exact sum when one term outweighs all the others together,
// else 0. A non-zero scaled x = m 2^e has |x| in [2^(e-1), 2^e), so a term
// whose exponent lies at least 3 above every other's exceeds their sum
// (below (N-1) 2^(e-3), which is at most 2^(e-1) for N <= 5).
template <class T, std::size_t N>
  requires(N <= 5)
int sign_of_dominant_term(const std::array<scaled<T>, N>& terms) {
  std::size_t top = 0;  // the term of largest exponent; terms[0] while all are 0
  for (std::size_t i = 1; i < N; ++i)
    if (terms[i].significand != 0 && (terms[top].significand == 0 || terms[i].exponent > terms[top].exponent)) top = i;
  for (std::size_t i = 0; i < N; ++i)
    if (i != top && terms[i].significand != 0 && terms[i].exponent > terms[top].exponent - 3) return 0;
  return terms[top].sign();  // 0 when every term is 0
}

// Whether T holds, as a normal number, the least significant bit of any
// cluster of N terms below (shifted so that its largest lies in [0.5, 1)): its
// neighbours lie at most digits + 3 binades apart, so it reaches down to
// 2^-((N - 1) (digits + 3) + digits). Every type of the registry has the room
// for the four terms of the case criterion; float lacks it for eight, and the
// exhaustive test's formats of few exponents below 1 for four. A decision at
// compile time, so that no instantiation carries a branch it never takes (a
// variable, so that no code of its own is left unrun either). MPFR
// at run-time precision (digits = INT_MAX) has 2^30 binades below 1.
template <class T, std::size_t N>
inline constexpr bool clusters_fit =
    std::numeric_limits<T>::digits == std::numeric_limits<int>::max() ||
    long(std::numeric_limits<T>::min_exponent) - 1 <=
        -(long(N - 1) * (long(std::numeric_limits<T>::digits) + 3) + long(std::numeric_limits<T>::digits));

// Sign of the exact sum of scaled numbers of any magnitudes. Terms are sorted
// by exponent and cut into clusters wherever two neighbours lie more than
// digits + 3 binades apart; a non-zero cluster sum is at least the least
// significant bit of its smallest term, which outweighs everything below the
// gap, so the first non-zero cluster decides. A cluster is shifted so that its
// largest term lies in [0.5, 1) and summed in T, exactly, when T holds its
// least significant bit as a normal number (clusters_fit). Otherwise the whole
// sum is taken as an expansion of scaled numbers: slower, and exact as well,
// since scaled<T> sums round as T's would with an unbounded exponent.
template <class T, std::size_t N>
int sign_of_exact_sum(std::array<scaled<T>, N> terms) {
  if constexpr (!clusters_fit<T, N>) {
    scaled<T> expansion[N];
    std::copy(terms.begin(), terms.end(), expansion);
    return sign_of_exact_sum(expansion);
  } else {
    const long gap = long(precision_of<T>()) + 3;
    // insertion sort, zeros last, then by decreasing exponent: the clusters and
    // the sign do not depend on the order of equal exponents, and for four terms
    // it beats std::sort's general machinery
    auto before = [](const scaled<T>& a, const scaled<T>& b) {
      if ((a.significand == 0) != (b.significand == 0)) return b.significand == 0;
      return a.exponent > b.exponent;
    };
    for (std::size_t k = 1; k < N; ++k)
      for (std::size_t j = k; j > 0 && before(terms[j], terms[j - 1]); --j) std::swap(terms[j], terms[j - 1]);
    std::size_t i = 0;
    while (i < N && terms[i].significand != 0) {
      const long top = terms[i].exponent;
      long previous = top;
      T cluster[N];
      std::size_t count = 0;
      for (; i < N && terms[i].significand != 0 && previous - terms[i].exponent <= gap; ++i) {
        cluster[count++] = scaled<T>::shifted(terms[i].significand, terms[i].exponent - top);
        previous = terms[i].exponent;
      }
      for (std::size_t k = count; k < N; ++k) cluster[k] = 0;
      if (int sign = sign_of_exact_sum(cluster)) return sign;
    }
    return 0;
  }
}

}  // namespace contact::detail
