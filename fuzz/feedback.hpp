// Coverage feedback from values: bucket K calls a function of its own, whose
// coverage counter is the signal, so reaching a new bucket (a larger error) is
// new coverage to any SanitizerCoverage-based engine (libFuzzer, AFL++,
// honggfuzz), and the input is kept. Only the libFuzzer targets include this.
#pragma once

#include <array>
#include <cstdlib>
#include <utility>

namespace contact::fuzz {

template <int Family, int K>
__attribute__((noinline)) void bucket_reached() {
  static volatile int sink;
  sink = Family * 100000 + K;  // a distinct body per bucket
}

template <int Family, int... K>
constexpr std::array<void (*)(), sizeof...(K)> bucket_table(std::integer_sequence<int, K...>) {
  return {&bucket_reached<Family, K>...};
}

// $CONTACT_FUZZ_NO_FEEDBACK turns the feedback off, to measure what it brings.
inline bool feedback_enabled() {
  static const bool enabled = std::getenv("CONTACT_FUZZ_NO_FEEDBACK") == nullptr;
  return enabled;
}

// feedback<Family, N>(k): marks bucket k (0 <= k < N) of a family as reached.
template <int Family, int N>
inline void feedback(int k) {
  static constexpr auto table = bucket_table<Family>(std::make_integer_sequence<int, N>{});
  if (0 <= k && k < N && feedback_enabled()) table[k]();
}

}  // namespace contact::fuzz
