// A face's pcurve (an edge's curve in the face's (u, v) plane) as the edge discretisation reads
// it: the faces' normals along every segment it tries, the chords it stands triangles on. A
// non-periodic B-spline pcurve (trimmed or not), the common kind on free-form faces, is evaluated
// directly from its poles (spline_curve.h); others go through OpenCASCADE. Immutable: copies share
// the direct form, any thread may evaluate.
//
// The face mesher keeps OpenCASCADE's evaluation for its boundary points: they go into the
// triangulation, whose Delaunay ties (cocircular points along regular boundaries) make a face's
// mesh follow the last bit of its boundary's (u, v); the direct form, no less exact but rounding
// otherwise, changed the sample models' meshes both ways (Ball 8944 -> 8994 triangles at 0.1%).
#pragma once

#include <Geom2d_Curve.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>

#include <memory>

#include "spline_curve.h"

namespace cetview::brep {

class Pcurve {
 public:
  Pcurve() = default;
  explicit Pcurve(const Handle(Geom2d_Curve)& curve);

  bool isNull() const { return curve_.IsNull(); }
  // Whether points come from the poles directly rather than through OpenCASCADE (tests).
  bool direct() const { return spline_ != nullptr; }

  gp_Pnt2d value(double t) const;
  void d1(double t, gp_Pnt2d& p, gp_Vec2d& v) const;

 private:
  Handle(Geom2d_Curve) curve_;
  std::shared_ptr<const SplineCurve<2>> spline_;
};

}  // namespace cetview::brep
