/* The appendix's closed form (A.29)-(A.32), typed in exactly as printed,
 * misprints included (docs/equations.md, section 4, lists them):
 *   - (A.29) u < -dy and (A.30) u >= -dy: the boundary u = -dy in the wrong case;
 *   - (A.30) has 2 psi dy, and psi is defined nowhere; a reader has to pick a
 *     value, and this one picks 1;
 *   - (A.31) has the numerator u - 2 phi dy, the negative of the root.
 * No check of the input either: the appendix has none.
 *
 *   cc -O2 -shared -fPIC -o libas_printed.so as_printed.c -lm
 */
#include <math.h>

static const double psi = 1.0; /* printed in (A.30), never defined */

double contact_candidate(double u, double dy, double phi, int* which) {
  if (dy <= 0) {
    if (u < -dy) { /* (A.29) */
      *which = 1;
      return -u;
    }
    *which = 2; /* (A.30) */
    return (2 * psi * dy - u - sqrt(u * u - 4 * phi * dy * (u + dy))) / (2 * (1 + phi));
  }
  if (u >= dy * (phi - 1)) { /* (A.31) */
    *which = 3;
    return (u - 2 * phi * dy) / (1 + phi);
  }
  *which = 4; /* (A.32) */
  return -u / 2 + sqrt(u * u + 4 * phi * dy * dy) / 2;
}
