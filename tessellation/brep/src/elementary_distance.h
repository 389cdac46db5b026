// Exact distance from a point to an elementary surface (plane, cylinder, cone, sphere, torus) in
// closed form, a few dozen flops against a Gauss-Newton projection's two or more surface
// evaluations. It is the distance to the whole surface, not to a face of it: the refinement's
// samples lie on triangles close to their face, and its corresponding-point guard catches the rest.
#pragma once

#include <Adaptor3d_Surface.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

namespace cetview::brep {

class ElementaryDistance {
 public:
  // `surface` as placed in space (a BRepAdaptor_Surface applies its face's location).
  explicit ElementaryDistance(const Adaptor3d_Surface& surface);

  bool valid() const { return type_ != GeomAbs_OtherSurface; }  // an elementary surface
  double operator()(const gp_Pnt& m) const;  // valid() only

 private:
  GeomAbs_SurfaceType type_ = GeomAbs_OtherSurface;
  gp_Pnt origin_;               // plane origin; axis point of cylinders, cones and tori; sphere centre
  gp_Dir axis_;                 // plane normal; axis of cylinders, cones and tori
  double radius_ = 0;           // cylinder, sphere, torus major radius; cone radius at origin_
  double minor_ = 0;            // torus minor radius
  double cosA_ = 1, sinA_ = 0;  // cone semi-angle
};

}  // namespace cetview::brep
