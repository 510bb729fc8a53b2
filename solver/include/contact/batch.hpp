// contact::solve_batch: the stable closed form of (A.2) over arrays, and
// contact::solve_rounded_batch: the correctly rounded mode over arrays.
//
// Every lane gets exactly the s and the case that contact::solve_stable gives
// for it, bit for bit. float and double run a vector kernel (Google Highway),
// chosen at run time among those the library holds for the CPU (batch_targets);
// the lanes a vector cannot answer, and CPUs without fma, take solve_stable.
// Other types run solve_stable lane by lane. docs/glossary.md names the
// kernel's windows, bands and lanes.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <span>

#include "rounded.hpp"
#include "stable.hpp"

namespace contact {

// One instruction set the library holds a batch kernel for.
struct batch_target {
  const char* name;  // "avx3" (AVX-512), "avx2" (AVX2 and fma), "neon", ...; "scalar": solve_stable lane by lane
  bool supported;    // this CPU runs it
  // solve_batch on this kernel; returns how many lanes it left to solve_stable
  std::ptrdiff_t (*solve_double)(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n);
  std::ptrdiff_t (*solve_float)(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n);
  // solve_rounded_batch on this kernel; returns how many lanes it left to solve_rounded
  std::ptrdiff_t (*solve_rounded_double)(const double* u, const double* dy, const double* phi, double* s, int* which,
                                         std::ptrdiff_t n);
  std::ptrdiff_t (*solve_rounded_float)(const float* u, const float* dy, const float* phi, float* s, int* which,
                                        std::ptrdiff_t n);
};

// Every kernel compiled into the library, widest first, "scalar" last (always
// supported: the path CPUs without fma take, whose vector multiply-add would
// round twice). solve_batch runs the first supported one.
std::span<const batch_target> batch_targets();
const batch_target& chosen_batch_target();

template <class T>
using batch_array = Eigen::Array<T, Eigen::Dynamic, 1>;

namespace batch_detail {
// One lane's answer into the output arrays' places.
template <class T>
void store(const solution<T>& r, T& s, int& which) {
  s = r.s;
  which = static_cast<int>(r.which);
}

// The lanes one by one, for the types without a kernel.
template <class T, class Solve>
void each_lane(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n, Solve solve) {
  for (std::ptrdiff_t i = 0; i < n; ++i) store(solve(u[i], dy[i], phi[i]), s[i], which[i]);
}

// The Eigen form: s and which resized to the length of u, which dy and phi must have too.
template <class T, class Solve>
void on_arrays(const batch_array<T>& u, const batch_array<T>& dy, const batch_array<T>& phi, batch_array<T>& s,
               batch_array<int>& which, Solve solve) {
  eigen_assert(dy.size() == u.size() && phi.size() == u.size());
  s.resize(u.size());
  which.resize(u.size());
  solve(u.data(), dy.data(), phi.data(), s.data(), which.data(), u.size());
}

void solve_chosen(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n);
void solve_chosen(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n);
void solve_rounded_chosen(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n);
void solve_rounded_chosen(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n);
}  // namespace batch_detail

// Solves (A.2) for the n lanes u[i], dy[i], phi[i]; writes s[i] and the case
// number (contact_case as int: 0 invalid, 1..4 for (A.29)..(A.32)). The output
// arrays must not overlap the inputs. Any T that solve_stable accepts.
template <class T>
void solve_batch(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  if constexpr (detail::hardware_binary<T>) {
    batch_detail::solve_chosen(u, dy, phi, s, which, n);
  } else {
    batch_detail::each_lane(u, dy, phi, s, which, n, [](const T& a, const T& b, const T& c) { return solve_stable(a, b, c); });
  }
}

// The same for solve_rounded: every lane gets exactly solve_rounded's s and
// case. In float and double the kernels take the lanes inside the common
// window, or moved into it, by the fixed-bound step and its rounding test
// (rounded.hpp) in vectors; float's kernel takes the lanes its step leaves
// through double on double vectors, as solve_rounded<float> itself does. The
// lanes whose test fails, and every other lane, take solve_rounded. The other
// types run solve_rounded lane by lane. The types of
// contact::rounded_available only.
template <class T>
void solve_rounded_batch(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  if constexpr (detail::hardware_binary<T>) {
    batch_detail::solve_rounded_chosen(u, dy, phi, s, which, n);
  } else {
    batch_detail::each_lane(u, dy, phi, s, which, n, [](const T& a, const T& b, const T& c) { return solve_rounded(a, b, c); });
  }
}

// The Eigen forms: s and which are resized to the length of u; dy and phi must
// have that length too.
template <class T>
void solve_batch(const batch_array<T>& u, const batch_array<T>& dy, const batch_array<T>& phi, batch_array<T>& s,
                 batch_array<int>& which) {
  batch_detail::on_arrays(u, dy, phi, s, which, [](auto... x) { solve_batch<T>(x...); });
}

template <class T>
void solve_rounded_batch(const batch_array<T>& u, const batch_array<T>& dy, const batch_array<T>& phi, batch_array<T>& s,
                         batch_array<int>& which) {
  batch_detail::on_arrays(u, dy, phi, s, which, [](auto... x) { solve_rounded_batch<T>(x...); });
}

}  // namespace contact
