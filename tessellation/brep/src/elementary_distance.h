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

  // The largest distance from a point of the flat triangle (a, b, c) to the surface, exactly, on
  // planes, cylinders and spheres (hasTriangleDeviation()); -1 elsewhere. The distance to a sphere's
  // centre or a cylinder's axis is convex, so over a triangle whose corners lie on the surface it
  // peaks at the corners (outside: 0) and dips either inside the triangle (at the foot of the
  // sphere's centre, or where the axis pierces it) or on an edge. `where`: the edge holding the
  // deepest point (0, 1, 2: the edge opposite that corner), or -1 for the inside.
  bool hasTriangleDeviation() const {
    return type_ == GeomAbs_Plane || type_ == GeomAbs_Cylinder || type_ == GeomAbs_Sphere;
  }
  double triangleDeviation(const gp_XYZ& a, const gp_XYZ& b, const gp_XYZ& c, int& where) const;

 private:
  GeomAbs_SurfaceType type_ = GeomAbs_OtherSurface;
  gp_Pnt origin_;               // plane origin; axis point of cylinders, cones and tori; sphere centre
  gp_Dir axis_;                 // plane normal; axis of cylinders, cones and tori
  double radius_ = 0;           // cylinder, sphere, torus major radius; cone radius at origin_
  double minor_ = 0;            // torus minor radius
  double cosA_ = 1, sinA_ = 0;  // cone semi-angle
};

}  // namespace cetview::brep
