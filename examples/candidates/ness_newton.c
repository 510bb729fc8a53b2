/* Newton's method on the residual of (A.2), in the manner of the NESS
 * project's string-barrier solver (see README.md here): start at s = 0, at
 * most 20 iterations, stop when the squared step falls below 1e-12, and
 * absolute thresholds near the double epsilon where s is too small to divide
 * by. Written for this project from that description.
 *
 *   cc -O2 -shared -fPIC -o libness_newton.so ness_newton.c -lm
 */
#include <math.h>

static double pos(double x) { return x > 0 ? x : 0; }

double contact_candidate(double u, double dy, double phi, int* which) {
  const double tiny = 2.2e-16;
  double s = 0;
  if (!isfinite(u) || !isfinite(dy) || !isfinite(phi) || phi < 0) {
    *which = 0;
    return NAN;
  }
  for (int i = 0; i < 20; ++i) {
    const double p = pos(dy - s), p0 = pos(dy);
    double r, slope;
    if (fabs(s) < tiny) {
      /* the limits as s -> 0 of the divided difference and of its derivative */
      r = s + u - 2 * phi * p0;
      slope = 1 + phi * (dy > 0 ? 1 : 0);
    } else {
      r = s + u + phi * (p * p - p0 * p0) / s;
      slope = 1 + phi * (-2 * p * s - (p * p - p0 * p0)) / (s * s);
    }
    if (fabs(slope) < tiny) break;
    const double step = r / slope;
    s -= step;
    if (step * step < 1e-12) break;
  }
  /* the case from the side of dy that s lies on */
  if (dy <= 0) *which = s >= dy ? 1 : 2;
  else *which = s <= dy ? 3 : 4;
  return s;
}
