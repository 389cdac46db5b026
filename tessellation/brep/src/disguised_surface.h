// A free-form surface that is a plane, a sphere or a circular cylinder in disguise: STEP and IGES
// files often write every face as a B-spline, and a cylinder so written bends beside its boundary
// just as the real one does. The edges' standing-triangle tests, meant for surfaces that bend
// otherwise beside an edge than along it (tori, free-form faces), cut such a cylinder's straight
// seam into short pieces, and the refinement then filled the face with points where strips do
// (a shaft of radius 10 as NURBS at 0.001: 4994 triangles, BRepMesh 1324; as the cylinder it is,
// 1020).
#pragma once

#include <functional>

#include <Adaptor3d_Surface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace cetview::brep {

// A surface's point and first derivatives at (u, v).
using SurfaceD1 = std::function<void(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv)>;

// Whether the surface over [u0, u1] x [v0, v1] is a plane, a sphere or a circular cylinder: every
// one of 9 x 9 samples within 1e-9 of the shape's size from it, its normal along the shape's. The
// shapes are fitted to 3 x 3 samples among them, and a free-form surface is given up on at
// its first sample off all of them (a face's 81 evaluations through OpenCASCADE's adaptor took
// 1.2 ms of shell1's 5.5).
bool isPlaneSphereOrCylinder(const SurfaceD1& d1, double u0, double u1, double v0, double v1);
bool isPlaneSphereOrCylinder(const Adaptor3d_Surface& surface, double u0, double u1, double v0, double v1);

}  // namespace cetview::brep
