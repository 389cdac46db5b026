// A free-form surface that is a plane, a sphere or a circular cylinder in disguise: STEP and IGES
// files often write every face as a B-spline, and a cylinder so written bends beside its boundary
// just as the real one does. The edges' standing-triangle tests, meant for surfaces that bend
// otherwise beside an edge than along it (tori, free-form faces), cut such a cylinder's straight
// seam into short pieces, and the refinement then filled the face with points where strips do
// (a shaft of radius 10 as NURBS at 0.001: 4994 triangles, BRepMesh 1324; as the cylinder it is,
// 1020).
#pragma once

#include <Adaptor3d_Surface.hxx>

namespace cetview::brep {

// Whether the surface over [u0, u1] x [v0, v1] is a plane, a sphere or a circular cylinder: every
// one of 9 x 9 samples within 1e-9 of the shape's size from it, its normal along the shape's.
bool isPlaneSphereOrCylinder(const Adaptor3d_Surface& surface, double u0, double u1, double v0, double v1);

}  // namespace cetview::brep
