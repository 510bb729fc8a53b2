// The batch kernels' interface inside the library. Each kernel is
// batch_kernel.cpp compiled for one instruction set into a namespace of its
// own (contact::batch_kernels::<name>); the lanes it cannot answer go to
// solve_stable (or solve_rounded) through the out-of-line functions below, compiled for the
// baseline, so that no kernel's object holds an instruction-set-specific copy
// of code that another object shares (tests: batch.kernel_objects_own_their_code).
#pragma once

#include <cstddef>
#include <cstdint>

namespace contact::batch_kernels {

void solve_stable_lane(double u, double dy, double phi, double& s, int& which);
void solve_stable_lane(float u, float dy, float phi, float& s, int& which);
void solve_rounded_lane(double u, double dy, double phi, double& s, int& which);
void solve_rounded_lane(float u, float dy, float phi, float& s, int& which);

template <class T>
std::ptrdiff_t solve_stable_lanes(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  for (std::ptrdiff_t i = 0; i < n; ++i) solve_stable_lane(u[i], dy[i], phi[i], s[i], which[i]);
  return n;
}

template <class T>
std::ptrdiff_t solve_rounded_lanes(const T* u, const T* dy, const T* phi, T* s, int* which, std::ptrdiff_t n) {
  for (std::ptrdiff_t i = 0; i < n; ++i) solve_rounded_lane(u[i], dy[i], phi[i], s[i], which[i]);
  return n;
}

}  // namespace contact::batch_kernels

// Declares each kernel's entry points (batch_kernels.inc lists the kernels this build holds).
#define CONTACT_BATCH_KERNEL(name)                                                                       \
  namespace contact::batch_kernels::name {                                                              \
  std::int64_t highway_target();                                                                        \
  std::ptrdiff_t solve_double(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n); \
  std::ptrdiff_t solve_float(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n);      \
  std::ptrdiff_t solve_rounded_double(const double* u, const double* dy, const double* phi, double* s, int* which,         \
                                      std::ptrdiff_t n);                                                                  \
  std::ptrdiff_t solve_rounded_float(const float* u, const float* dy, const float* phi, float* s, int* which,              \
                                     std::ptrdiff_t n);                                                                   \
  }
#include "batch_kernels.inc"
#undef CONTACT_BATCH_KERNEL
