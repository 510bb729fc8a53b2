// The smallest scheme that produces (A.2): a mass on a spring against a
// one-sided barrier, stepped by the energy-conserving discrete-gradient
// midpoint rule (docs/equations.md, section 1, equations (S.1)-(S.10)). The
// report simulates it, the physical input family draws (u, dy, phi) from it,
// and the tests check its energy identity.
#pragma once

#include <cmath>

namespace contact::harness {

template <class T>
struct oscillator_state {
  T y, p;  // displacement and momentum
};

template <class T>
struct oscillator {
  T mass, spring, barrier_height, barrier_stiffness, dt;
  T a;    // (S.5) a = 2m / dt^2 + K / 2, theta = 1 / a
  T phi;  // (S.7) phi = theta k_b / 2

  oscillator(const T& m, const T& k, const T& h_b, const T& k_b, const T& step)
      : mass(m), spring(k), barrier_height(h_b), barrier_stiffness(k_b), dt(step),
        a(T(2) * m / (step * step) + k / T(2)), phi(k_b / (T(2) * a)) {}

  // (S.6) u = (K y - 2 p / dt) / a
  T u(const T& y, const T& p) const { return (spring * y - T(2) * p / dt) / a; }
  // (S.8) dy = h_b - y, the compression at step n
  T compression(const T& y) const { return barrier_height - y; }
  // (S.9) y' = y + s, p' = 2 m s / dt - p, for the root s of (A.2)
  oscillator_state<T> next(const oscillator_state<T>& now, const T& s) const {
    return {now.y + s, T(2) * mass * s / dt - now.p};
  }
  // (S.2) H = p^2 / (2m) + K y^2 / 2 + (k_b / 2) floor(h_b - y)^2, evaluated in T
  T energy(const oscillator_state<T>& x) const {
    const T gap = barrier_height - x.y;
    const T barrier = gap > 0 ? T(barrier_stiffness * gap * gap / T(2)) : T(0);
    return x.p * x.p / (T(2) * mass) + spring * x.y * x.y / T(2) + barrier;
  }
};

}  // namespace contact::harness
