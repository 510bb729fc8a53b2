// libFuzzer target of a candidate compiled in (ClusterFuzzLite, examples/ci):
// each input is three doubles (u, dy, phi); the candidate's answer must be within
// CONTACT_MAX_ULP ulps of the certified root, in the exact case, and NaN with
// case 0 for invalid input. A failure aborts with the input and both answers.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "contact/reference.hpp"

#ifndef CONTACT_MAX_ULP
#define CONTACT_MAX_ULP 4.0
#endif

extern "C" double contact_candidate(double u, double dy, double phi, int* which);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3 * sizeof(double)) return 0;
  double x[3];
  std::memcpy(x, data, sizeof x);
  const double u = x[0], dy = x[1], phi = x[2];
  int which = -1;
  const double s = contact_candidate(u, dy, phi, &which);
  const bool valid = std::isfinite(u) && std::isfinite(dy) && std::isfinite(phi) && !(phi < 0);
  if (!valid) {
    if (std::isnan(s) && which == 0) return 0;
    std::fprintf(stderr, "invalid input u=%a dy=%a phi=%a: s=%a case %d, expected NaN and case 0\n", u, dy, phi, s, which);
    std::abort();
  }
  const auto exact = contact::reference::solve<double>(u, dy, phi);
  const double error = contact::reference::accepted_ulp_error<double>(s, exact, dy);
  if (error <= CONTACT_MAX_ULP && which == static_cast<int>(exact.which)) return 0;
  std::fprintf(stderr, "u=%a dy=%a phi=%a: s=%a case %d; certified s*=%s case %d; error %g ulps (max %g)\n", u, dy, phi,
               s, which, exact.s.to_string(17).c_str(), static_cast<int>(exact.which), error, double(CONTACT_MAX_ULP));
  std::abort();
}
