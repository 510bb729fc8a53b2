// libFuzzer entry point of the 'rounded' target (solve_rounded in double and
// float, bit for bit against the reference root rounded to the type); the check
// is in ../checks.hpp. The exact case and the path taken (fast or exact
// decision) are fed back as coverage, per type.
#include <cstddef>
#include <cstdint>

#include "checks.hpp"
#include "feedback.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  contact::fuzz::print_stats_at_exit_if_asked();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto r = contact::fuzz::check_rounded(data, size);
  contact::fuzz::feedback<1, contact::fuzz::rounded_buckets>(contact::fuzz::rounded_bucket(r.in_double));
  contact::fuzz::feedback<2, contact::fuzz::rounded_buckets>(contact::fuzz::rounded_bucket(r.in_float));
  return 0;
}
