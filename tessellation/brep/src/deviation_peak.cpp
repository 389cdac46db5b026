#include "deviation_peak.h"

namespace cetview::brep {

bool quadraticDeviationPeak(const double middle[3], double b[3]) {
  const double m0 = middle[0], m1 = middle[1], m2 = middle[2];
  if (!(m0 > 0) || !(m1 > 0) || !(m2 > 0)) return false;
  // With b1 = x, b2 = y: q / 4 = m0 x y + m1 y (1 - x - y) + m2 x (1 - x - y), whose gradient
  // vanishes where [-2 m2, c; c, -2 m1] (x, y) = (-m2, -m1), c = m0 - m1 - m2: a maximum when that
  // Hessian is negative definite (its determinant positive: m2 > 0 already).
  const double c = m0 - m1 - m2;
  const double det = 4 * m1 * m2 - c * c;
  if (!(det > 0)) return false;
  b[1] = m1 * (m0 - m1 + m2) / det;
  b[2] = m2 * (m0 + m1 - m2) / det;
  b[0] = m0 * (m1 + m2 - m0) / det;
  return b[0] > 0 && b[1] > 0 && b[2] > 0;
}

}  // namespace cetview::brep
