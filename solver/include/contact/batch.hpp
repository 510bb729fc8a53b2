// contact::solve_batch: the stable closed form of (A.2) over arrays.
//
// Same results as the scalar stable path, bit for bit: every lane gets exactly
// the s and the case that contact::solve_stable gives for it. Lanes whose
// u, dy and phi all lie inside detail::safe_window<T> (the scalar path's plain-T
// window, which holds every physically meaningful input) are solved without a
// branch: every lane evaluates the operations of all four cases, in the same
// order and with the same fma as stable.hpp, and selects its own result with
// masks, so the compiler vectorises the loop. The rare lanes outside that
// window (extreme magnitudes, NaN, infinity, phi < 0) are found by an OR over a
// block of lanes and solved by the scalar contact::solve_stable afterwards.
//
// The exact criterion of (A.21), u + dy - phi dy >= 0, is decided as in
// stable.hpp: phi dy as the exact pair of two_prod, then the sign of an exact
// sum of four terms. The scalar path builds a Shewchuk expansion with zero
// elimination, which branches; here the expansion is grown without zero
// elimination (Shewchuk 1997, Theorem 10: the components are then
// non-overlapping and in increasing order of magnitude, except that any may be
// zero), so the sign of the exact sum is the sign of the last non-zero
// component, found with selects. Both are exact, so they agree.
//
// Vectorisation needs an fma instruction (x86-64-v3: -march=x86-64-v3 or
// -mfma) and -fno-math-errno (so that sqrt is an instruction without an errno
// branch). Without them the results are the same and the loop is scalar.
// Compile with -ffp-contract=off (or without fma hardware) so that the
// compiler fuses neither this loop nor stable.hpp differently.
#pragma once

#include <Eigen/Core>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "stable.hpp"

namespace contact {
namespace batch_detail {

template <class T>
inline constexpr bool has_lane_kernel = std::is_same_v<T, double> || std::is_same_v<T, float>;

template <class T>
using bits_t = std::conditional_t<std::is_same_v<T, double>, std::uint64_t, std::uint32_t>;

// Lanes solved per block; the scalar fix-up of out-of-window lanes happens per block.
inline constexpr std::ptrdiff_t block = 256;

template <class T>
struct window_bounds {
  T lowest, highest;
};

template <class T>
window_bounds<T> bounds() {
  const long half = detail::safe_window<T>::half_width();
  return {std::ldexp(T(1), static_cast<int>(-half)), std::ldexp(T(1), static_cast<int>(half))};
}

// c ? a : b, as a blend of bit patterns: both operands are always computed, so
// the compiler neither moves their arithmetic into a branch nor needs to
// prove that it cannot trap (which -ftrapping-math, the default, forbids).
template <class T>
inline T pick(bool c, T a, T b) {
  using U = bits_t<T>;
  const U mask = U(0) - U(c);
  return std::bit_cast<T>(U((std::bit_cast<U>(a) & mask) | (std::bit_cast<U>(b) & ~mask)));
}

// The part of every lane's work that needs no branch. Returns 1 if the lane
// lies outside the plain-T window (or is invalid) and so must be redone by the
// scalar path; s and which are then meaningless.
// The lane can take the branch-free path: u, dy and phi lie inside
// detail::safe_window<T> (or are 0), which excludes NaN and infinity, and phi >= 0.
template <class T>
inline bool inside_window(T u, T dy, T phi, T lowest, T highest) {
  const T au = std::fabs(u), ady = std::fabs(dy), aphi = std::fabs(phi);
  // bitwise & and |, not && and ||: no short-circuit, so no control flow
  return ((au == 0) | ((au >= lowest) & (au <= highest))) & ((ady == 0) | ((ady >= lowest) & (ady <= highest))) &
         ((aphi == 0) | ((aphi >= lowest) & (aphi <= highest))) & (phi >= 0);
}

template <class T>
inline unsigned lane(T u, T dy, T phi, T lowest, T highest, T& s_out, int& which_out) {
  using U = bits_t<T>;
  constexpr U sign_bit = U(1) << (sizeof(T) * 8 - 1);
  const bool inside = inside_window(u, dy, phi, lowest, highest);

  // (A.30) impact, stable_form::impact(u, gap = -dy, phi)
  const T gap = -dy;
  const T push = phi * gap;
  const T impact_discriminant = std::fma(u, u, T(4) * (push * (u - gap)));
  // (A.32) release, stable_form::release(u, dy, phi)
  const T stiffness_term = (phi * dy) * dy;
  const T release_discriminant = std::fma(u, u, T(4) * stiffness_term);

  const bool no_contact_before = dy <= 0;
  const T root = std::sqrt(pick(no_contact_before, impact_discriminant, release_discriminant));

  // (A.21) stays in contact: the sign of the exact sum u + dy - ph - pl,
  // where ph + pl = phi dy exactly; Knuth's TwoSum, grown without zero elimination.
  const T ph = phi * dy;
  const T pl = std::fma(phi, dy, -ph);
  auto two_sum = [](T a, T b, T& error) {
    const T sum = a + b;
    const T b_virtual = sum - a;
    const T a_virtual = sum - b_virtual;
    error = (a - a_virtual) + (b - b_virtual);
    return sum;
  };
  T e0, e1, e2;
  T top = two_sum(dy, u, e0);  // expansion {e0, top}
  T c = -ph;
  c = two_sum(c, e0, e0);
  top = two_sum(c, top, e1);  // expansion {e0, e1, top}
  c = -pl;
  c = two_sum(c, e0, e0);
  c = two_sum(c, e1, e1);
  top = two_sum(c, top, e2);  // expansion {e0, e1, e2, top}
  T leading = e0;
  leading = pick(e1 != 0, e1, leading);
  leading = pick(e2 != 0, e2, leading);
  leading = pick(top != 0, top, leading);
  const bool stays_in_contact = !(leading < 0);

  const bool is_free = no_contact_before & (u <= -dy);
  const bool is_impact = no_contact_before & !is_free;
  const bool is_contact = !no_contact_before & stays_in_contact;
  const bool release_rationalised = u > 0;

  // One division per lane: numerator and denominator of the lane's case.
  const T impact_numerator = -((u + T(2) * push) + root);
  const T impact_denominator = T(2) * (T(1) + phi);
  const T contact_numerator = std::fma(phi, T(2) * dy, -u);
  const T contact_denominator = T(1) + phi;
  const T release_numerator = pick(release_rationalised, T(2) * stiffness_term, root - u);
  const T release_denominator = pick(release_rationalised, u + root, T(2));
  T numerator = pick(is_contact, contact_numerator, release_numerator);
  T denominator = pick(is_contact, contact_denominator, release_denominator);
  numerator = pick(is_impact, impact_numerator, numerator);
  denominator = pick(is_impact, impact_denominator, denominator);
  numerator = pick(is_free, -u, numerator);
  denominator = pick(is_free, T(1), denominator);
  T s = numerator / denominator;

  // The clamps of solve_stable; next_down(dy) for dy <= 0 and next_up(dy) for dy > 0.
  const U dy_bits = std::bit_cast<U>(dy);
  const T below_dy = std::bit_cast<T>(U((dy_bits | sign_bit) + 1));
  const T above_dy = std::bit_cast<T>(U(dy_bits + 1));
  s = pick(is_impact & !(s < dy), below_dy, s);
  s = pick(is_contact & (s > dy), dy, s);
  s = pick(!no_contact_before & !is_contact & !(s > dy), above_dy, s);

  s_out = s;
  which_out = is_free ? 1 : (is_impact ? 2 : (is_contact ? 3 : 4));
  return inside ? 0u : 1u;
}

template <class T>
void solve_lanes(const T* __restrict u, const T* __restrict dy, const T* __restrict phi, T* __restrict s,
                 int* __restrict which, std::ptrdiff_t n) {
  const window_bounds<T> window = bounds<T>();
  const T lowest = window.lowest, highest = window.highest;
  for (std::ptrdiff_t start = 0; start < n; start += block) {
    const std::ptrdiff_t end = start + block < n ? start + block : n;
    unsigned outside = 0;
    for (std::ptrdiff_t i = start; i < end; ++i) outside |= lane(u[i], dy[i], phi[i], lowest, highest, s[i], which[i]);
    if (outside) {
      for (std::ptrdiff_t i = start; i < end; ++i) {
        if (!inside_window(u[i], dy[i], phi[i], lowest, highest)) {
          const solution<T> r = solve_stable(u[i], dy[i], phi[i]);
          s[i] = r.s;
          which[i] = static_cast<int>(r.which);
        }
      }
    }
  }
}

}  // namespace batch_detail

// Solves (A.2) for the n lanes u[i], dy[i], phi[i]; writes s[i] and the case
// number (contact_case as int: 0 invalid, 1..4 for (A.29)..(A.32)). The output
// arrays must not overlap the inputs. Any T that solve_stable accepts; float
// and double are vectorised, other types run the scalar path lane by lane.
template <class T>
void solve_batch(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  if constexpr (batch_detail::has_lane_kernel<T>) {
    batch_detail::solve_lanes(u, dy, phi, s, which, n);
  } else {
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const solution<T> r = solve_stable(u[i], dy[i], phi[i]);
      s[i] = r.s;
      which[i] = static_cast<int>(r.which);
    }
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
