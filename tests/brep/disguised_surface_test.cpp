// Free-form surfaces that are planes, spheres or circular cylinders (disguised_surface.h): found on
// their NURBS conversions; a cone, a torus, a cylinder bumped by a micron and a saddle are not.
#include <gtest/gtest.h>

#include <cmath>

#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Ax3.hxx>

#include "disguised_surface.h"

namespace cetview::brep {
namespace {

const gp_Ax3 kPlace(gp_Pnt(1, -2, 3), gp_Dir(1, 2, 2), gp_Dir(2, -1, 0));

// `surface` over [u0, u1] x [v0, v1] as a B-spline, and the test over its whole range.
bool asNurbs(const Handle(Geom_Surface)& surface, double u0, double u1, double v0, double v1) {
  const Handle(Geom_BSplineSurface) nurbs =
      GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1));
  double a = 0, b = 0, c = 0, d = 0;
  nurbs->Bounds(a, b, c, d);
  return isPlaneSphereOrCylinder(GeomAdaptor_Surface(nurbs), a, b, c, d);
}

TEST(DisguisedSurface, FindsPlanesSpheresAndCylinders) {
  EXPECT_TRUE(asNurbs(new Geom_Plane(kPlace), -3, 5, 0, 2));
  EXPECT_TRUE(asNurbs(new Geom_CylindricalSurface(kPlace, 10), 0, 2 * M_PI, 0, 5));
  EXPECT_TRUE(asNurbs(new Geom_CylindricalSurface(kPlace, 0.01), 0.3, 1.2, -40, 5));
  EXPECT_TRUE(asNurbs(new Geom_SphericalSurface(kPlace, 3), 0.2, 2.5, -1, 0.5));
}

TEST(DisguisedSurface, OtherSurfacesAreNot) {
  EXPECT_FALSE(asNurbs(new Geom_ConicalSurface(kPlace, 0.3, 5), 0, 2 * M_PI, 0, 5));
  EXPECT_FALSE(asNurbs(new Geom_ToroidalSurface(kPlace, 10, 2), 0, 1, 0, 1.5));
  // A saddle, and a cylinder of radius 10 with one pole moved by a micron.
  TColgp_Array2OfPnt saddle(1, 3, 1, 3);
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j) saddle(i, j) = gp_Pnt(i, j, (i - 2) * (j - 2));
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0, knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = 3, mults(2) = 3;
  const Handle(Geom_BSplineSurface) saddleSurface = new Geom_BSplineSurface(saddle, knots, knots, mults, mults, 2, 2);
  EXPECT_FALSE(isPlaneSphereOrCylinder(GeomAdaptor_Surface(saddleSurface), 0, 1, 0, 1));
  const Handle(Geom_BSplineSurface) bumped = GeomConvert::SurfaceToBSplineSurface(
      new Geom_RectangularTrimmedSurface(new Geom_CylindricalSurface(kPlace, 10), 0.0, 1.5, 0.0, 5.0));
  bumped->SetPole(2, 2, bumped->Pole(2, 2).Translated(gp_Vec(0, 0, 1e-6)));
  double a = 0, b = 0, c = 0, d = 0;
  bumped->Bounds(a, b, c, d);
  EXPECT_FALSE(isPlaneSphereOrCylinder(GeomAdaptor_Surface(bumped), a, b, c, d));
}

}  // namespace
}  // namespace cetview::brep
