// What the input families draw, the randomness they draw from, and the
// distribution of one number as the report's scenes name it. Light on purpose: the report's scene
// parser includes it without the families' Boost headers.
#pragma once

#include <cstdint>
#include <random>

namespace contact::harness {

template <class T>
struct input {
  T u, dy, phi;
};

// A source over std::mt19937_64: deterministic for a seed.
class seeded_source {
 public:
  explicit seeded_source(std::uint64_t seed) : engine_(seed) {}
  std::uint64_t bits() { return engine_(); }
  long integer(long low, long high) {
    const std::uint64_t span = std::uint64_t(high - low) + 1;
    return span == 0 ? low + long(engine_()) : low + long(engine_() % span);
  }

 private:
  std::mt19937_64 engine_;
};

template <class Source>
bool coin(Source& source) {
  return source.integer(0, 1) == 1;
}

// Uniform in [0, 1), 53 bits.
template <class Source>
double unit(Source& source) {
  return double(source.bits() >> 11) * 0x1p-53;
}

// A distribution of one number, as the report's scenes name them: a magnitude
// log-uniform over [10^low, 10^high] or [2^low, 2^high], uniform over [low, high],
// or the constant low; then a sign (+1, -1, or 0 for either with equal odds).
struct distribution {
  enum class shape { log10, log2, uniform, constant };
  shape kind = shape::constant;
  double low = 0, high = 0;
  int sign = 1;
};

}  // namespace contact::harness
