/* Newton's method on the residual of (A.2), in float, the way physical-modelling
 * code runs it at audio rate: start at the kink s = dy, stop when the step is
 * below a relative tolerance of 1e-6 or after 20 iterations; the case is read
 * off the side of dy where s ends up.
 *
 *   cc -O2 -shared -fPIC -o libfloat_newton.so float_newton.c -lm
 *   contact-check --candidate lib:./libfloat_newton.so --type float
 */
#include <math.h>

static float positive(float x) { return x > 0 ? x : 0; }

float contact_candidate_f(float u, float dy, float phi, int* which) {
  const float pd = positive(dy);
  float s = dy;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const float gap = positive(dy - s);
    float r, slope;
    if (s == 0) { /* the limit of R and R' at s = 0 */
      r = u - 2 * phi * pd;
      slope = 1 + phi;
    } else {
      r = s + u + phi * (gap * gap - pd * pd) / s;
      slope = 1 + phi * (pd * pd - gap * gap) / (s * s) - 2 * phi * gap / s;
    }
    const float step = r / slope;
    s -= step;
    if (fabsf(step) <= 1e-6f * fabsf(s)) break;
  }
  if (dy <= 0) *which = s >= dy ? 1 : 2;
  else *which = s <= dy ? 3 : 4;
  return s;
}
