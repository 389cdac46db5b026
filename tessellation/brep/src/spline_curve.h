// Direct evaluation of a non-periodic B-spline curve in D dimensions from its poles (pcurves in
// the face's (u, v) plane: pcurve.h; edges' 3D curves: the edge discretisation). OpenCASCADE's
// curves find the span and rebuild its knots and poles on every call (Geom2d_BSplineCurve) or
// keep a per-span cache that is rebuilt whenever a point falls in another span and that threads
// cannot share (the adaptors): several times a direct evaluation for the scattered points of a
// discretisation. Immutable once made: any thread may evaluate.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <Geom2d_Curve.hxx>

#include "bspline_basis.h"

namespace cetview::brep {

template <int D>
class SplineCurve {
 public:
  // `flat`: the flat knot sequence (poles + degree + 1 knots); `poles`: D coordinates and the
  // weight per pole, the coordinates not yet multiplied by it. Null where that is not a curve this
  // class evaluates (degree out of range, knots not matching the poles).
  static std::shared_ptr<const SplineCurve> create(int degree, std::vector<double> flat, std::vector<double> poles) {
    const int count = static_cast<int>(poles.size() / (D + 1));
    if (degree < 1 || degree > kMaxBSplineDegree || count <= degree ||
        flat.size() != static_cast<std::size_t>(count + degree + 1))
      return nullptr;
    auto c = std::shared_ptr<SplineCurve>(new SplineCurve);
    c->knots_.degree = degree, c->knots_.poles = count;
    c->knots_.knots = std::move(flat);
    c->knots_.index(false);
    for (std::size_t i = 0; i < poles.size(); i += D + 1)
      for (int k = 0; k < D; ++k) poles[i + static_cast<std::size_t>(k)] *= poles[i + D];
    c->poles_ = std::move(poles);
    return c;
  }

  // The point at t, and with `d` its first derivative (D values each). A non-rational curve has
  // weights 1, and the division by them leaves its points as de Boor's steps made them.
  void evaluate(double t, double* p, double* d) const {
    switch (knots_.degree) {  // degrees 1 to 3 (nearly every curve) with their loops unrolled
      case 1:
        return evaluate<1>(t, p, d);
      case 2:
        return evaluate<2>(t, p, d);
      case 3:
        return evaluate<3>(t, p, d);
      default:
        return evaluate<0>(t, p, d);
    }
  }

 private:
  SplineCurve() = default;
  // De Boor's algorithm in homogeneous coordinates, each step (1 - a) d[j-1] + a d[j] with a by
  // division: at a clamped end every a is 0 or 1 exactly, and a polynomial curve passes through its
  // end poles to the last bit, as OpenCASCADE's does (a sum of basis functions with the knot
  // differences as reciprocals, as BSplineDirect evaluates surfaces, need not; nor the form
  // d[j-1] + a (d[j] - d[j-1])). The derivative comes from the two points before the last step:
  // p (d[p] - d[p-1]) / (U[s+1] - U[s]).
  template <int P>
  void evaluate(double t, double* p, double* d) const {
    const int s = knots_.span(t);
    const int q = P > 0 ? P : knots_.degree;
    const double* U = knots_.knots.data();
    double h[(P > 0 ? P : kMaxBSplineDegree) + 1][D + 1] = {};
    const double* a = poles_.data() + (D + 1) * static_cast<std::size_t>(s - q);
    for (int j = 0; j <= q; ++j)
      for (int k = 0; k <= D; ++k) h[j][k] = a[(D + 1) * j + k];
    double dh[D + 1] = {};
    for (int r = 1; r <= q; ++r) {
      if (r == q && d) {
        const double f = q / (U[s + 1] - U[s]);
        for (int k = 0; k <= D; ++k) dh[k] = f * (h[q][k] - h[q - 1][k]);
      }
      for (int j = q; j >= r; --j) {
        const double lo = U[s - q + j], hi = U[s + 1 + j - r];
        const double alpha = (t - lo) / (hi - lo);
        for (int k = 0; k <= D; ++k) h[j][k] = (1 - alpha) * h[j - 1][k] + alpha * h[j][k];
      }
    }
    const double w = h[q][D];
    for (int k = 0; k < D; ++k) p[k] = h[q][k] / w;
    if (!d) return;
    // C = A / w: C' = (A' - w' C) / w.
    for (int k = 0; k < D; ++k) d[k] = (dh[k] - dh[D] * p[k]) / w;
  }

  KnotSpans knots_;
  std::vector<double> poles_;  // x w, y w, (z w,) w
};

// The direct form of a pcurve where it is a non-periodic B-spline (trimmed or not: a trimmed curve
// is its basis curve at the same parameters), else null (a periodic curve's poles wrap around).
std::shared_ptr<const SplineCurve<2>> splineOf(const Handle(Geom2d_Curve)& curve);
// The same for an edge's 3D curve, moved by the edge's location as the adaptor moves its points;
// null for an edge without a 3D curve.
std::shared_ptr<const SplineCurve<3>> splineOf(const BRepAdaptor_Curve& curve);

}  // namespace cetview::brep
