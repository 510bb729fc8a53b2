// libFuzzer entry point of the 'invariants' target; the check is in ../checks.hpp.
#include <cstddef>
#include <cstdint>

#include "checks.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  contact::fuzz::print_stats_at_exit_if_asked();
  contact::fuzz::claimed();  // read the claimed bounds now: a missing or malformed file fails at start-up
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  contact::fuzz::check_invariants(data, size);
  return 0;
}
