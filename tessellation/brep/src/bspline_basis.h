// The knot side of direct B-spline evaluation: a direction's flat knot sequence with a bucket
// index to find a parameter's span in a step or two (surfaces, bspline_direct.h, and curves,
// spline_curve.h), and for surfaces the reciprocals of the knot differences each span's basis
// functions divide by and the basis functions themselves, with their first derivatives (curves
// use de Boor's algorithm instead). Immutable once indexed.
#pragma once

#include <vector>

namespace cetview::brep {

constexpr int kMaxBSplineDegree = 25;  // OpenCASCADE's own limit

// One direction of a non-periodic B-spline: its flat knot sequence (each knot repeated by its
// multiplicity: poles + degree + 1 of them) and a table of uniform buckets over the parameter
// range, each naming the span its start lies in, so a span is found in a step or two instead of a
// binary search. Spans are indices into the flat knot sequence: degree .. poles - 1.
struct KnotSpans {
  int degree = 0, poles = 0;
  std::vector<double> knots;
  double t0 = 0, perBucket = 0;
  std::vector<int> bucketSpan;
  // Per span: reciprocals of the knot differences its basis functions divide by (see basis()).
  std::vector<double> inverse;

  // After degree, poles and knots are set: the buckets, and the reciprocals unless not wanted (de
  // Boor's algorithm, which curves use, divides instead).
  void index(bool reciprocals = true);
  // The span holding t (the first span for parameters before it, the last for those past it: they
  // are evaluated on its polynomial, as OpenCASCADE does).
  int span(double t) const;
  // The same, but at an interior knot the span that ends there (the one below).
  int spanBelow(double t) const;
  const double* inverses(int s) const { return inverse.data() + (s - degree) * (degree * (degree + 1) / 2); }
};

// The reciprocals of the knot differences the degree-d basis functions of span s divide by (see
// basis() below): round j, term r: 1 / (U[s+r+1] - U[s+r+1-j]), 0 for coincident knots.
void knotReciprocals(const double* U, int d, int s, double* inv);

// Cox-de Boor, one degree at a time (The NURBS Book's triangular scheme), for the basis functions
// N[0..p] of a span at t (N[r] is N_{s-p+r, p}) and, when dN is not null, their first derivatives.
// The scheme divides by differences of knots only (round j, term r: U[s+r+1] - U[s+r+1-j]), so
// `inverse` holds their reciprocals for the span, j = 1..p, r = 0..j-1 (0 for coincident knots).
// Before the last round N holds the degree p - 1 functions, from which the derivatives follow:
//   N'_{i,p} = p (N_{i,p-1} / (U[i+p] - U[i]) - N_{i+1,p-1} / (U[i+p+1] - U[i+1])),
// whose knot differences are those of the last round.
// P > 0 fixes the degree at compile time (unrolled loops); P == 0 takes it from `degree`.
template <int P>
void basis(const double* U, const double* inverse, int degree, int s, double t, double* N, double* dN) {
  const int p = P > 0 ? P : degree;
  double left[kMaxBSplineDegree + 1], right[kMaxBSplineDegree + 1];
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - U[s + 1 - j];
    right[j] = U[s + j] - t;
    const double* inv = inverse + j * (j - 1) / 2;
    if (j == p && dN) {
      dN[0] = -p * N[0] * inv[0];
      for (int r = 1; r < p; ++r) dN[r] = p * (N[r - 1] * inv[r - 1] - N[r] * inv[r]);
      dN[p] = p * N[p - 1] * inv[p - 1];
    }
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] * inv[r];
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

}  // namespace cetview::brep
