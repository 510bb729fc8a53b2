// libFuzzer entry point of the 'high_precision' target (long double and
// float128 against the reference); the check is in ../checks.hpp. As in the
// differential target, the stable error is fed back as coverage, per type.
#include <cstddef>
#include <cstdint>

#include "checks.hpp"
#include "feedback.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  contact::fuzz::print_stats_at_exit_if_asked();
  contact::fuzz::claimed();  // read the claimed bounds now: a missing or malformed file fails at start-up
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto r = contact::fuzz::check_high_precision(data, size);
  contact::fuzz::feedback<1, contact::fuzz::stable_buckets>(contact::fuzz::stable_bucket(r.long_double));
  contact::fuzz::feedback<2, contact::fuzz::stable_buckets>(contact::fuzz::stable_bucket(r.quad));
  return 0;
}
