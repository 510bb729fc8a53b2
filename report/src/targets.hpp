// The batch kernels one by one: every target of contact::batch_targets() that
// this CPU runs is timed alone, as the row "batch[NAME]", wherever the report
// times batch (the scenes' timings in float and double, the throughput and
// batch across scenes); the row "batch" is solve_batch, the target dispatch
// chose. Likewise "rounded_batch[NAME]" beside rounded_batch.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "contact/batch.hpp"

namespace report {

// The targets this CPU runs, in the library's order (widest first, "scalar" last).
inline std::vector<const contact::batch_target*> supported_batch_targets() {
  std::vector<const contact::batch_target*> out;
  for (const contact::batch_target& t : contact::batch_targets())
    if (t.supported) out.push_back(&t);
  return out;
}

// "KERNEL[NAME]": the row of target NAME's kernel alone, KERNEL "batch" or "rounded_batch".
inline std::string target_row_name(std::string_view kernel, const contact::batch_target& t) {
  return std::string(kernel) + "[" + std::string(t.name) + "]";
}
inline std::string batch_row_name(const contact::batch_target& t) { return target_row_name("batch", t); }

// Whether `algorithm` names such a row of `kernel`.
inline bool is_target_row_of(std::string_view kernel, std::string_view algorithm) {
  return algorithm.size() > kernel.size() && algorithm.starts_with(kernel) && algorithm[kernel.size()] == '[';
}
inline bool is_batch_target_row(std::string_view algorithm) { return is_target_row_of("batch", algorithm); }

// The types the targets hold a kernel for; the others run solve_stable lane by lane under every target.
template <class T>
inline constexpr bool has_batch_kernels = std::is_same_v<T, double> || std::is_same_v<T, float>;

// Target t's kernel on n lanes of T: solve_batch's, or with `rounded` solve_rounded_batch's.
template <class T>
  requires has_batch_kernels<T>
void solve_on(const contact::batch_target& t, const T* u, const T* dy, const T* phi, T* s, int* which,
              std::ptrdiff_t n, bool rounded = false) {
  if constexpr (std::is_same_v<T, double>)
    (rounded ? t.solve_rounded_double : t.solve_double)(u, dy, phi, s, which, n);
  else
    (rounded ? t.solve_rounded_float : t.solve_float)(u, dy, phi, s, which, n);
}

}  // namespace report
