// libFuzzer entry point of the 'differential' target; the check is in
// ../checks.hpp. The stable algorithm's error (an eighth of an ulp per bucket,
// per case) is fed back as coverage, so that campaigns climb towards the
// largest error and test the proven bound where it is tightest.
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
  const auto r = contact::fuzz::check_differential(data, size);
  contact::fuzz::feedback<0, contact::fuzz::stable_buckets>(contact::fuzz::stable_bucket(r));
  return 0;
}
