// Simpler neighbours of a failing trial, for shrinking: each replaces one
// number by a simpler one (zero, its magnitude, fewer significant bits, an
// exponent nearer 0). "Simpler" is a score: the fewer bits and the smaller the
// exponent, the easier the reproducer is to read.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "properties.hpp"

namespace check {

// Significant bits plus a quarter of the binary exponent's size plus the sign; 0 for zero.
template <class T>
double complexity(const T& x) {
  using std::isfinite;
  if (x == 0) return 0;
  if (!isfinite(x)) return 1;  // NaN and infinity are as simple as input gets
  int exponent = 0;
  T m = std::frexp(std::fabs(x), &exponent);
  int bits = 0;
  while (m != 0) {
    m = m * 2;
    m -= std::floor(m);
    ++bits;
  }
  return bits + std::abs(exponent - 1) / 4.0 + (x < 0 ? 1 : 0);
}

template <class T>
double complexity(const trial<T>& t) {
  return complexity(t.x.u) + complexity(t.x.dy) + complexity(t.x.phi) + std::abs(t.k) / 8.0;
}

// x with its significand rounded to `bits` bits.
template <class T>
T with_bits(const T& x, int bits) {
  using std::isfinite;
  if (x == 0 || !isfinite(x)) return x;
  int exponent = 0;
  const T m = std::frexp(x, &exponent);
  return std::ldexp(std::nearbyint(std::ldexp(m, bits)), exponent - bits);
}

template <class T>
std::vector<T> simpler_values(const T& x) {
  using std::isfinite;
  std::vector<T> out;
  if (!isfinite(x) || x == 0) return out;
  out.push_back(T(0));
  if (x < 0) out.push_back(T(-x));
  for (int bits = 1; bits < contact::detail::precision_of<T>(); ++bits) out.push_back(with_bits(x, bits));
  int exponent = 0;
  std::frexp(x, &exponent);
  for (int target : {1, exponent / 2 + 1, exponent - 1, exponent + 1}) out.push_back(std::ldexp(x, target - exponent));
  out.erase(std::remove_if(out.begin(), out.end(), [&](const T& y) { return !isfinite(y) || complexity(y) >= complexity(x); }),
            out.end());
  return out;
}

// Every trial one step simpler than t, simplest first.
template <class T>
std::vector<trial<T>> simpler_trials(const trial<T>& t) {
  std::vector<trial<T>> out;
  for (T input<T>::*field : {&input<T>::u, &input<T>::dy, &input<T>::phi})
    for (const T& y : simpler_values(t.x.*field)) {
      trial<T> n = t;
      n.x.*field = y;
      out.push_back(n);
    }
  // all three at once to few bits, which saves rounds when every field can go
  for (int bits = 1; bits < contact::detail::precision_of<T>(); bits *= 2)
    out.push_back({{with_bits(t.x.u, bits), with_bits(t.x.dy, bits), with_bits(t.x.phi, bits)}, t.k});
  // u and dy together, which keeps a relation between them (u = -dy, a boundary)
  if (t.x.u != 0 && t.x.dy != 0 && std::isfinite(t.x.u) && std::isfinite(t.x.dy)) {
    int exponent = 0;
    std::frexp(std::max(std::fabs(t.x.u), std::fabs(t.x.dy)), &exponent);
    for (int target : {1, exponent / 2 + 1, exponent - 1, exponent + 1})
      out.push_back({{std::ldexp(t.x.u, target - exponent), std::ldexp(t.x.dy, target - exponent), t.x.phi}, t.k});
    for (int bits = 1; bits < contact::detail::precision_of<T>(); ++bits)
      out.push_back({{with_bits(t.x.u, bits), with_bits(t.x.dy, bits), t.x.phi}, t.k});
  }
  for (long k : {0L, t.k / 2, t.k - (t.k > 0) + (t.k < 0)})
    if (std::abs(k) < std::abs(t.k)) out.push_back({t.x, k});
  const double now = complexity(t);
  out.erase(std::remove_if(out.begin(), out.end(), [&](const trial<T>& n) { return !(complexity(n) < now); }), out.end());
  std::stable_sort(out.begin(), out.end(), [](const trial<T>& a, const trial<T>& b) { return complexity(a) < complexity(b); });
  return out;
}

}  // namespace check
