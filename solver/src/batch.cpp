// solve_batch's dispatch: the kernels this build holds, the CPU's choice among
// them (Highway's run-time detection), and the scalar path for the lanes the
// kernels cannot answer. Compiled for the baseline instruction set.
#include "contact/batch.hpp"

#include <hwy/targets.h>

#include <algorithm>
#include <array>

#include "batch_kernels.hpp"

namespace contact {
namespace batch_kernels {

// Cloned for x86-64-v3 where the compiler can (run-time choice by the loader):
// what solve_stable inlines here then uses the fma instruction, not a call.
#if defined(__x86_64__) && defined(__GNUC__)
#define CONTACT_SCALAR_CLONES [[gnu::target_clones("arch=x86-64-v3", "default")]]
#else
#define CONTACT_SCALAR_CLONES
#endif

CONTACT_SCALAR_CLONES void solve_stable_lane(double u, double dy, double phi, double& s, int& which) {
  batch_detail::store(solve_stable(u, dy, phi), s, which);
}

CONTACT_SCALAR_CLONES void solve_stable_lane(float u, float dy, float phi, float& s, int& which) {
  batch_detail::store(solve_stable(u, dy, phi), s, which);
}

CONTACT_SCALAR_CLONES void solve_rounded_lane(double u, double dy, double phi, double& s, int& which) {
  batch_detail::store(solve_rounded(u, dy, phi), s, which);
}

CONTACT_SCALAR_CLONES void solve_rounded_lane(float u, float dy, float phi, float& s, int& which) {
  batch_detail::store(solve_rounded(u, dy, phi), s, which);
}

}  // namespace batch_kernels

namespace {

bool cpu_runs(std::int64_t highway_target) { return (hwy::SupportedTargets() & highway_target) != 0; }

const auto& all_targets() {
  static const std::array targets{
#define CONTACT_BATCH_KERNEL(name)                                                                                 \
  batch_target{#name, cpu_runs(batch_kernels::name::highway_target()), &batch_kernels::name::solve_double, \
               &batch_kernels::name::solve_float, &batch_kernels::name::solve_rounded_double,             \
               &batch_kernels::name::solve_rounded_float},
#include "batch_kernels.inc"
#undef CONTACT_BATCH_KERNEL
      batch_target{"scalar", true, &batch_kernels::solve_stable_lanes<double>, &batch_kernels::solve_stable_lanes<float>,
                   &batch_kernels::solve_rounded_lanes<double>, &batch_kernels::solve_rounded_lanes<float>}};
  return targets;
}

// (scalar, the last, is always supported)
const batch_target& first_supported() {
  return *std::find_if(all_targets().begin(), all_targets().end(), [](const batch_target& t) { return t.supported; });
}

}  // namespace

std::span<const batch_target> batch_targets() { return all_targets(); }

const batch_target& chosen_batch_target() {
  static const batch_target& chosen = first_supported();
  return chosen;
}

namespace batch_detail {

void solve_chosen(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n) {
  chosen_batch_target().solve_double(u, dy, phi, s, which, n);
}

void solve_chosen(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n) {
  chosen_batch_target().solve_float(u, dy, phi, s, which, n);
}

void solve_rounded_chosen(const double* u, const double* dy, const double* phi, double* s, int* which, std::ptrdiff_t n) {
  chosen_batch_target().solve_rounded_double(u, dy, phi, s, which, n);
}

void solve_rounded_chosen(const float* u, const float* dy, const float* phi, float* s, int* which, std::ptrdiff_t n) {
  chosen_batch_target().solve_rounded_float(u, dy, phi, s, which, n);
}

}  // namespace batch_detail
}  // namespace contact
