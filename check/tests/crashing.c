/* A candidate that crashes: for a stiff barrier it reads through a pointer it
 * never set (a lookup table for phi > 1e6 that was never written). */
#include <stddef.h>

static volatile int* stiff_table = NULL;

double contact_candidate(double u, double dy, double phi, int* which) {
  *which = phi > 1e6 ? stiff_table[0] : 1;
  return -u + 0 * dy;
}
