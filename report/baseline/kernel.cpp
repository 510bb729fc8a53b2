// One of the two baseline kernels (extract.sh): the AVX-512 kernel's
// solve_batch for double, behind a plain function. The build renames the
// baseline's namespace (-Dcontact=...), so that it links beside today's
// library, and gives this function its name (BASELINE_ENTRY).
#include <contact/batch.hpp>

void BASELINE_ENTRY(const double* u, const double* dy, const double* phi, double* s, int* which, long n) {
  contact::solve_batch<double>(u, dy, phi, s, which, n);
}
