// The input families: the one definition of how (u, dy, phi) triples are drawn
// for every check of the project. The property tests draw them through
// RapidCheck (so that failures shrink), the batch test, the report and the
// fuzz seed maker through a seeded engine; all of them call these functions.
//
// A family is a function of a randomness source and its parameters. A source
// is anything with
//     std::uint64_t bits()              64 uniformly random bits
//     long integer(long low, long high) uniform in [low, high]
// (`seeded_source` in random.hpp; the tests wrap RapidCheck's generators the same way).
// Every draw is in T with T's full precision, so the wider types get inputs
// that double cannot represent.
//
// Which region of (A.2) each family aims at is said in docs/equations.md,
// section "Where the closed form is hard".
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "contact/detail/float_tools.hpp"
#include "contact/harness/random.hpp"
#include "contact/harness/oscillator.hpp"

namespace contact::harness {

// A significand with T's full precision, uniform in [1, 2): 32 random bits at a
// time, exact while they fit; T rounds once at the end.
template <class T, class Source>
T significand(Source& source) {
  using std::ldexp;
  T fraction = 0;
  for (int words = (detail::precision_of<T>() + 31) / 32; words > 0; --words)
    fraction = ldexp(fraction + T(double(source.bits() >> 32)), -32);
  return T(1) + fraction;
}

// |x| log-uniform by binade over [2^low, 2^(high+1)), with T's full precision;
// binades below T's normal range land in the subnormals and lose bits as they should.
template <class T, class Source>
T log_uniform(Source& source, long low, long high) {
  using std::ldexp;
  return T(ldexp(significand<T>(source), int(source.integer(low, high))));
}

template <class T, class Source>
T random_sign(Source& source, const T& magnitude) {
  return coin(source) ? T(-magnitude) : magnitude;
}

// ---- how one number is drawn ---------------------------------------------------

template <class T, class Source>
T draw(Source& source, const distribution& d) {
  using std::ldexp;
  T magnitude;
  switch (d.kind) {
    case distribution::shape::constant: return T(d.low);
    case distribution::shape::uniform: return T(d.low + (d.high - d.low) * unit(source));
    default: {
      // a binade by the exponent's continuous distribution, then a uniform
      // significand in it, at T's precision; the two end binades are cut to the range
      const double per_unit = d.kind == distribution::shape::log10 ? 3.321928094887362 : 1.0;
      const double low = d.low * per_unit, high = d.high * per_unit;
      magnitude = 0;
      for (int tries = 0; tries < 64; ++tries) {
        const double exponent = low + (high - low) * unit(source);
        magnitude = ldexp(significand<T>(source), int(std::floor(exponent)));
        if (magnitude >= T(std::exp2(low)) && magnitude <= T(std::exp2(high))) break;
      }
    }
  }
  const int sign = d.sign != 0 ? d.sign : (coin(source) ? 1 : -1);
  return sign < 0 ? T(-magnitude) : magnitude;
}

// ---- T's whole range -------------------------------------------------------------

// The exponents the whole-range draws span: T's normal and subnormal range for
// the hardware types; for the software types (whose own range, 2^+-2^31, is
// beyond what the rational reference can hold) double's range, widened.
template <class T>
long lowest_exponent() {
  if constexpr (std::numeric_limits<T>::max_exponent < 20000)
    return std::numeric_limits<T>::min_exponent - detail::precision_of<T>();
  else
    return -1200;
}

template <class T>
long highest_exponent() {
  if constexpr (std::numeric_limits<T>::max_exponent < 20000)
    return std::numeric_limits<T>::max_exponent - 1;
  else
    return 1200;
}

// A finite T of any magnitude: log-uniform over the whole range, often near the
// bottom of it (subnormals), sometimes a signed zero.
template <class T, class Source>
T any_finite(Source& source) {
  const long low = lowest_exponent<T>(), high = highest_exponent<T>();
  const long pick = source.integer(0, 14);
  if (pick < 12) return random_sign(source, log_uniform<T>(source, low, high));
  if (pick < 14) return random_sign(source, log_uniform<T>(source, low, low + 60));
  return coin(source) ? T(0) : T(-0.0);
}

// phi of any size: the whole range, physical, stiff (1e210 and beyond), tiny, and zero.
template <class T, class Source>
T any_phi(Source& source) {
  const long low = lowest_exponent<T>(), high = highest_exponent<T>();
  const long pick = source.integer(0, 12);
  if (pick < 6) return log_uniform<T>(source, low, high);
  if (pick < 9) return log_uniform<T>(source, -10, 20);
  if (pick < 11) return log_uniform<T>(source, 700, std::min<long>(high, 1000));
  if (pick < 12) return log_uniform<T>(source, low, low + 40);
  return T(0);
}

// ---- the families ------------------------------------------------------------------

// u, dy and phi independently over T's whole range.
template <class T, class Source>
input<T> whole_range(Source& source) {
  const T u = any_finite<T>(source), dy = any_finite<T>(source), phi = any_phi<T>(source);
  return {u, dy, phi};
}

// u, dy and phi independently from the given distributions (phi as |phi|).
template <class T, class Source>
input<T> box(Source& source, const distribution& u, const distribution& dy, const distribution& phi) {
  using std::fabs;
  const T u_value = draw<T>(source, u), dy_value = draw<T>(source, dy), phi_value = fabs(draw<T>(source, phi));
  return {u_value, dy_value, phi_value};
}

// The parameters of a physical contact point, drawn, then turned into (u, dy,
// phi) by the scheme of docs/equations.md: (S.5)-(S.8).
struct physical_ranges {
  distribution mass, spring, barrier_stiffness, displacement, compression, velocity;
  distribution sample_rate{distribution::shape::constant, 44100, 44100, 1};
};

// The audio-rate ranges: m 1e-4..1e-2 kg, K 1..1e4 N/m, k_b 1e5..1e13 N/m,
// displacements and compressions 1e-7..1e-3 m either sign, speeds 1e-4..1 m/s.
inline physical_ranges audio_rate() {
  using s = distribution::shape;
  return {{s::log10, -4, -2, 1},  {s::log10, 0, 4, 1},   {s::log10, 5, 13, 1},
          {s::log10, -7, -3, 0},  {s::log10, -7, -3, 0}, {s::log10, -4, 0, 0}};
}

template <class T, class Source>
input<T> physical(Source& source, const physical_ranges& r) {
  using std::fabs;
  const T mass = fabs(draw<T>(source, r.mass)), spring = fabs(draw<T>(source, r.spring));
  const T stiffness = fabs(draw<T>(source, r.barrier_stiffness));
  const T y = draw<T>(source, r.displacement), dy = draw<T>(source, r.compression);
  const T velocity = draw<T>(source, r.velocity), rate = fabs(draw<T>(source, r.sample_rate));
  // the barrier height that gives this compression at y: dy = h_b - y (S.8)
  const oscillator<T> scheme(mass, spring, T(y + dy), stiffness, T(T(1) / rate));
  const T momentum = mass * velocity;
  return {scheme.u(y, momentum), dy, scheme.phi};
}

// The software types' least values (2^-2^31) lie beyond what the rational
// reference can hold: their checks stay at or above 2^lowest_exponent, or at 0.
template <class T>
bool in_reference_range(const T& x) {
  using std::fabs;
  using std::ldexp;
  if constexpr (std::numeric_limits<T>::max_exponent < 20000) return true;
  else return x != 0 && fabs(x) >= ldexp(T(1), int(lowest_exponent<T>()));
}

// x, or 0 where a step from 0 went below the reference's range.
template <class T>
T within_reference_range(const T& x) {
  return x == 0 || in_reference_range(x) ? x : T(0);
}

// On the (A.29)/(A.30) boundary (dy <= 0): u = -dy moved by `steps` values of T.
template <class T>
input<T> on_free_impact_boundary(const T& dy, const T& phi, long steps) {
  return {within_reference_range(detail::ulp_steps(T(-dy), steps)), dy, phi};
}

// On the (A.31)/(A.32) boundary (dy > 0): u = fl(dy (phi - 1)) moved by `steps`
// values of T (where dy (phi - 1) overflows, from the largest finite value).
template <class T>
input<T> on_contact_release_boundary(const T& dy, const T& phi, long steps) {
  using std::isfinite;
  T boundary = dy * (phi - 1);
  if (!isfinite(boundary)) boundary = (std::numeric_limits<T>::max)();
  return {within_reference_range(detail::ulp_steps(boundary, steps)), dy, phi};
}

// Inputs at the top of T's range, listed: dy or u the largest finite T, with
// u tiny or large and phi subnormal, 1, near 1 or huge beside it, in every
// case; where the exact root lies just above the largest T it rounds to it,
// or to infinity (phi = 1 + eps). For the types whose largest value the
// reference can hold (float to float128).
template <class T>
std::vector<input<T>> top_of_range() {
  const T largest = (std::numeric_limits<T>::max)(), tiny = std::numeric_limits<T>::denorm_min();
  const T eps = std::numeric_limits<T>::epsilon(), one = 1;
  return {
      {-one, largest, one},       {-tiny, largest, one},     {one, largest, T(one + eps)}, {-one, largest, T(one + eps)},
      {-largest, largest, tiny},  {-largest, largest, one},  {-tiny, largest, tiny},       {-largest, largest, T(0)},
      {T(0), largest, one},       {-largest, one, one},      {-largest, tiny, largest},    {largest, largest, one},
      {largest, T(0), tiny},      {largest, -tiny, one},     {largest, -largest, largest}, {-largest, T(0), one},
      {largest / 2, largest, tiny}, {-largest, largest / 2, T(2)},
  };
}

// The (A.29)/(A.30) boundary: dy <= 0 and u within `ulps` values of T of -dy.
template <class T, class Source>
input<T> free_impact_boundary(Source& source, const distribution& dy, const distribution& phi, long ulps) {
  using std::fabs;
  const T dy_value = -fabs(draw<T>(source, dy)), phi_value = fabs(draw<T>(source, phi));
  return on_free_impact_boundary(dy_value, phi_value, source.integer(-ulps, ulps));
}

// The (A.31)/(A.32) boundary: dy > 0 and u within `ulps` values of T of dy (phi - 1).
template <class T, class Source>
input<T> contact_release_boundary(Source& source, const distribution& dy, const distribution& phi, long ulps) {
  using std::fabs;
  const T dy_value = fabs(draw<T>(source, dy)), phi_value = fabs(draw<T>(source, phi));
  return on_contact_release_boundary(dy_value, phi_value, source.integer(-ulps, ulps));
}

// Contact only just begins: dy <= 0, u = -dy (1 + |r|).
template <class T, class Source>
input<T> impact_grazing(Source& source, const distribution& dy, const distribution& phi, const distribution& relative) {
  using std::fabs;
  using std::fma;
  const T dy_value = -fabs(draw<T>(source, dy)), phi_value = fabs(draw<T>(source, phi));
  return {T(fma(T(-dy_value), fabs(draw<T>(source, relative)), T(-dy_value))), dy_value, phi_value};
}

// (A.31) near s = 0: dy > 0, u = 2 phi dy (1 + r), then moved by up to `ulps`
// values of T; s = (2 phi dy - u) / (1 + phi) cancels in its numerator.
template <class T, class Source>
input<T> contact_cancellation(Source& source, const distribution& dy, const distribution& phi,
                              const distribution& relative, long ulps) {
  using std::fabs;
  using std::fma;
  const T dy_value = fabs(draw<T>(source, dy)), phi_value = fabs(draw<T>(source, phi));
  const T twice_push = 2 * phi_value * dy_value;
  const T u = fma(twice_push, draw<T>(source, relative), twice_push);
  return {within_reference_range(detail::ulp_steps(u, source.integer(-ulps, ulps))), dy_value, phi_value};
}

// (A.32) with u >> sqrt(phi) dy: dy > 0, u = |ratio| sqrt(phi) dy (halved
// dy (phi - 1) where that is not above it, so that the case stays release);
// the printed root -u/2 + sqrt(u^2 + 4 phi dy^2)/2 cancels.
template <class T, class Source>
input<T> release_cancellation(Source& source, const distribution& dy, const distribution& phi,
                              const distribution& ratio) {
  using std::fabs;
  using std::sqrt;
  const T dy_value = fabs(draw<T>(source, dy)), phi_value = fabs(draw<T>(source, phi));
  T u = fabs(draw<T>(source, ratio)) * sqrt(phi_value) * dy_value;
  const T boundary = dy_value * (phi_value - 1);
  if (!(u < boundary) && boundary > 0) u = boundary / 2;
  return {u, dy_value, phi_value};
}

// ---- the mixes the property tests draw from --------------------------------------

// Both case boundaries, to a few ulps, with dy (zeros included) and phi over T's whole range.
template <class T, class Source>
input<T> any_boundary(Source& source) {
  const T dy = any_finite<T>(source), phi = any_phi<T>(source);
  const long steps = source.integer(-4, 4);
  return dy <= 0 ? on_free_impact_boundary(dy, phi, steps) : on_contact_release_boundary(dy, phi, steps);
}

// Both cancellation regions over a wide range of magnitudes.
template <class T, class Source>
input<T> any_cancellation(Source& source) {
  using s = distribution::shape;
  if (coin(source))
    return contact_cancellation<T>(source, {s::log2, -60, 60, 1}, {s::log2, -30, 30, 1}, {s::constant, 0, 0, 1}, 6);
  return release_cancellation<T>(source, {s::log2, -60, 0, 1}, {s::log2, 40, 80, 1}, {s::log2, 5, 30, 1});
}

// Every family at once, for properties that must hold everywhere.
template <class T, class Source>
input<T> any_input(Source& source) {
  const long pick = source.integer(0, 12);
  if (pick < 6) return whole_range<T>(source);
  if (pick < 9) return any_boundary<T>(source);
  if (pick < 11) return any_cancellation<T>(source);
  return physical<T>(source, audio_rate());
}

}  // namespace contact::harness
