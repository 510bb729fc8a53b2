// The library's own stable path (contact::solve_stable) behind the candidate
// interface: what a candidate that passes looks like.
//
//   c++ -std=gnu++20 -O2 -shared -fPIC -I solver/include -o libstable.so examples/candidates/stable.cpp
//   contact-check --candidate lib:./libstable.so --max-ulp 4
#include "contact/stable.hpp"

extern "C" double contact_candidate(double u, double dy, double phi, int* which) {
  const auto answer = contact::solve_stable(u, dy, phi);
  *which = static_cast<int>(answer.which);
  return answer.s;
}

extern "C" float contact_candidate_f(float u, float dy, float phi, int* which) {
  const auto answer = contact::solve_stable(u, dy, phi);
  *which = static_cast<int>(answer.which);
  return answer.s;
}
