// Direct evaluation of a (non-periodic) B-spline surface from its poles: the basis functions of
// the two knot spans are computed per call (Cox-de Boor's triangular scheme). Surfaces of degree 4
// or more one way (rational sweeps of degree 2 x 6-11 are common) with few spans instead get the
// polynomial patch of every pair of non-empty spans, poles folded in, when the evaluator is made: a
// point is then two nested Horner schemes (final level alone: Propeller.rle 33 -> 26 ms, Ball.brep
// 26 -> 20 ms, and 25 -> 19 ms once the empty spans of repeated knots stopped counting).
// Either way nothing changes after creation.
//
// OpenCASCADE evaluates a B-spline through a per-span cache: the span's polynomial coefficients,
// rebuilt whenever a point falls in another span than the last one. That pays off for points
// clustered in one span and costs several times a direct evaluation for scattered ones: the coarse
// levels of a face with thousands of spans (occ/terrain.brep: 309 x 320 bicubic spans) ask nearly
// every point in a new span. Over the sample models, evaluating every point directly was as fast
// as leaving runs of points in one span to OpenCASCADE's cache, or faster (occ/terrain.brep 10%).
// SurfaceEval and the edge discretisation use it for every point of a B-spline face; an instance
// is immutable, so threads share it, and a point's value does not depend on the points before it.
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <memory>
#include <vector>

#include "bspline_basis.h"

namespace cetview::brep {

class BSplineDirect {
 public:
  // The surface moved by `placement` (a face's location). Null for a periodic surface (its poles
  // wrap around) or a degree beyond kMaxDegree.
  static std::unique_ptr<BSplineDirect> create(const Handle(Geom_BSplineSurface)& surface,
                                               const gp_Trsf& placement = gp_Trsf());

  static constexpr int kMaxDegree = kMaxBSplineDegree;

  // Whether points go through the polynomial patches (see buildPatches), for tests.
  bool usesPatches() const { return !patches_.empty(); }
  // Whether the poles are read in place from the surface's own array (see poles_), for tests.
  bool readsPolesInPlace() const { return !surface_.IsNull(); }

  BSplineDirect(const BSplineDirect&) = delete;  // poles_ may point into ownPoles_
  BSplineDirect& operator=(const BSplineDirect&) = delete;

  // Index of the knot span holding the parameter (the first span for parameters before it, the
  // last for those past it: they are evaluated on its polynomial, as OpenCASCADE does). Spans are
  // indices into the flat knot sequence: degree .. poles - 1.
  int uSpan(double u) const { return u_.span(u); }
  int vSpan(double v) const { return v_.span(v); }
  // The same, but at an interior knot the span that ends there (the one below): the side of a face
  // whose parameter box ends at the knot, where the surface may be only C0 (a crease or a fold).
  int uSpanBelow(double u) const { return u_.spanBelow(u); }
  int vSpanBelow(double v) const { return v_.spanBelow(v); }

  // At (u, v) in spans (su, sv) as uSpan(u), vSpan(v) give them.
  gp_Pnt value(double u, double v, int su, int sv) const;
  void d1(double u, double v, int su, int sv, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const;
  gp_Pnt value(double u, double v) const { return value(u, v, uSpan(u), vSpan(v)); }
  void d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const { d1(u, v, uSpan(u), vSpan(v), p, du, dv); }

 private:
  // One direction: its knots (bspline_basis.h) and, for the patches, its spans' polynomials.
  struct Direction : KnotSpans {
    // For the patches: span s's basis functions N_{s-p+j} as polynomials in tau = (t - mid) / length
    // about the span's midpoint, coefficient k of function j at power[(s - p) * (p+1)^2 + j (p+1) + k].
    std::vector<double> power, mid, length;  // mid, length per span (length 0: an empty span)
    void buildPower();
    // Per span: its patch's index among the non-empty spans, -1 for an empty one (see buildPatches).
    std::vector<int> patchIndex;
    int patchSpans = 0;
    void numberSpans();
  };
  BSplineDirect() = default;
  // High degrees (kPatchDegree or more either way) with few spans: each pair of non-empty spans'
  // polynomial patch in powers of the local parameters, poles folded in, built once (immutable
  // after), so a point costs two nested Horner schemes instead of the basis functions and their
  // weighted sum.
  static constexpr int kPatchDegree = 4;
  // At most this many times the poles' own memory (a single span's patch is the size of its poles;
  // many small spans of high degree would multiply it), and 2 MiB; the empty spans of repeated
  // knots have no patch and do not count.
  static constexpr std::size_t kPatchRatio = 4;
  static constexpr std::size_t kPatchDoubles = std::size_t(1) << 18;
  void buildPatches();
  template <bool kDerivatives>
  void evaluatePatch(double u, double v, int su, int sv, double* out) const;
  std::vector<double> patches_;  // per non-empty span pair (u major): (p+1) x (q+1) coefficients of 4 doubles
  template <bool kDerivatives>
  void evaluate(double u, double v, int su, int sv, double* out) const;
  template <bool kDerivatives, int S>
  void evaluateWithStride(double u, double v, int su, int sv, double* out) const;
  template <bool kDerivatives, int S, int PU>
  void evaluateWithU(double u, double v, int su, int sv, double* out) const;
  // S: doubles per pole (3, or 4 with the weight); degrees fixed at compile time, or 0.
  template <bool kDerivatives, int S, int PU, int PV>
  void evaluate(double u, double v, int su, int sv, double* out) const;

  Direction u_, v_;
  bool rational_ = false;
  // Poles row by row (u index major), stride_ doubles each: rational, x w, y w, z w and the weight
  // w (in ownPoles_); otherwise x, y, z, read in place from the surface's own array where the
  // placement is the identity (occ/terrain.brep: 3.2 MB that a copy wrote afresh, 774 page
  // faults on every load), else from a moved copy in ownPoles_.
  const double* poles_ = nullptr;
  int stride_ = 4;
  std::vector<double> ownPoles_;
  Handle(Geom_BSplineSurface) surface_;  // keeps the poles read in place alive
};

}  // namespace cetview::brep
