/* A candidate that hangs: bisection with an absolute tolerance, which never
 * converges once the root is large enough that neighbouring doubles are
 * farther apart than the tolerance. */
#include <math.h>

static double residual(double s, double u, double dy, double phi) {
  const double gap = dy - s > 0 ? dy - s : 0, pd = dy > 0 ? dy : 0;
  return s == 0 ? u - 2 * phi * pd : s + u + phi * (gap * gap - pd * pd) / s;
}

double contact_candidate(double u, double dy, double phi, int* which) {
  double low = -1e300, high = 1e300;
  while (high - low > 1e-9) {
    const double mid = low / 2 + high / 2;
    if (residual(mid, u, dy, phi) < 0) low = mid;
    else high = mid;
  }
  *which = dy <= 0 ? (low >= dy ? 1 : 2) : (low <= dy ? 3 : 4);
  return low;
}
