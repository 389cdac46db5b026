// Exact geometric predicates: orientation and in-circle.
//
// Method: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
// Predicates", Discrete & Computational Geometry 18 (1997). A floating-point evaluation with a
// forward error bound decides almost every case; when the bound cannot decide, the determinant of
// the rounded coordinate differences is evaluated exactly (exact outright when no difference was
// rounded, and decisive whenever it is not nearly zero; for in-circle in double-word arithmetic
// with a proven eps^2 bound first, expansions only when that cannot decide), for in-circle then
// that value corrected by
// the first-order terms of the differences' rounding errors (Shewchuk's stage C: enough for points
// that are co-circular only up to rounding), and only then the full determinant with expansion
// arithmetic (expansion.h). The sign returned is always exact for
// finite double inputs whose products do not overflow or underflow.
#pragma once

#include "types.h"

namespace cet {

// > 0 if a, b, c are in counter-clockwise order, < 0 if clockwise, 0 if collinear.
// The magnitude is only meaningful when the fast filter decided (twice the signed area).
double orient2d(Point2 a, Point2 b, Point2 c);

// > 0 if d lies strictly inside the circle through a, b, c (given counter-clockwise),
// < 0 if strictly outside, 0 if the four points are co-circular.
double incircle(Point2 a, Point2 b, Point2 c, Point2 d);

// Counters for tests and benchmarks (not thread-safe to read while triangulating in another thread;
// relaxed atomics): how often the filter could not decide and the exact fallback ran, and how many
// of those needed the full expansion of the original coordinates (the rest were decided from the
// rounded differences, exactly, or for in-circle with their rounding errors to first order).
struct PredicateStats {
  unsigned long long orientExact = 0;
  unsigned long long incircleExact = 0;
  unsigned long long orientFullExpansion = 0;
  unsigned long long incircleFullExpansion = 0;
};
PredicateStats predicateStats();

}  // namespace cet
