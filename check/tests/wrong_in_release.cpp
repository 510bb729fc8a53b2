// The stable path with a fault planted where a physical model goes: in the
// release case with |dy| >= 1e-5 the answer is off by 1e-12 relative, about
// 4500 ulps. Everywhere else it is the stable path's answer.
#include <cmath>

#include "contact/solve.hpp"

extern "C" double contact_candidate(double u, double dy, double phi, int* which) {
  const auto r = contact::solve(u, dy, phi);
  *which = static_cast<int>(r.which);
  if (r.which == contact::contact_case::release && std::fabs(dy) >= 1e-5) return r.s * (1 + 1e-12);
  return r.s;
}
