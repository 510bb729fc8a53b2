// The batch kernels one by one: every target of contact::batch_targets() that
// this CPU runs is timed alone, as the row "batch[NAME]", wherever the report
// times batch (the scenes' timings in float and double, the throughput and
// batch across scenes); the row "batch" is solve_batch, the target dispatch chose.
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

// "batch[NAME]": the row of target NAME's kernel alone.
inline std::string batch_row_name(const contact::batch_target& t) { return "batch[" + std::string(t.name) + "]"; }

// Whether `algorithm` names such a row.
inline bool is_batch_target_row(std::string_view algorithm) { return algorithm.starts_with("batch["); }

// The types the targets hold a kernel for; the others run solve_stable lane by lane under every target.
template <class T>
inline constexpr bool has_batch_kernels = std::is_same_v<T, double> || std::is_same_v<T, float>;

// Target t's kernel on n lanes of T.
template <class T>
  requires has_batch_kernels<T>
void solve_on(const contact::batch_target& t, const T* u, const T* dy, const T* phi, T* s, int* which,
              std::ptrdiff_t n) {
  if constexpr (std::is_same_v<T, double>)
    t.solve_double(u, dy, phi, s, which, n);
  else
    t.solve_float(u, dy, phi, s, which, n);
}

}  // namespace report
