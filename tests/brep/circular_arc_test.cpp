// Circles written as B-splines (circular_arc.h): found on rational conversions of arcs and whole
// circles, with their radius, centre and turn; the parameters at equal angles land on those angles;
// an ellipse and polynomial curves through points of a circle are not taken for circles.
#include <gtest/gtest.h>

#include <cmath>

#include <ElCLib.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>

#include "circular_arc.h"

namespace cetview::brep {
namespace {

const gp_Ax2 kPlace(gp_Pnt(1, -2, 3), gp_Dir(1, 2, 2), gp_Dir(2, -1, 0));

Handle(Geom_BSplineCurve) rationalArc(double radius, double from, double to) {
  Handle(Geom_Circle) circle = new Geom_Circle(gp_Circ(kPlace, radius));
  return GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(circle, from, to));
}

TEST(CircularArc, FindsARationalArcAndItsEqualAngles) {
  for (const double to : {0.7, M_PI, 4.5}) {
    SCOPED_TRACE("arc to " + std::to_string(to));
    const Handle(Geom_BSplineCurve) spline = rationalArc(5, 0.2, to);
    ASSERT_TRUE(spline->IsRational());
    const GeomAdaptor_Curve curve(spline);
    const double first = curve.FirstParameter(), last = curve.LastParameter();
    const std::optional<CircularArc> arc = circularArcOf(curve, first, last, false);
    ASSERT_TRUE(arc);
    EXPECT_NEAR(arc->radius, 5, 1e-12);
    EXPECT_LT(arc->center.Distance(kPlace.Location()), 1e-12);
    EXPECT_NEAR(arc->angle, to - 0.2, 1e-12);
    for (int i = 1; i < 7; ++i) {
      const double phi = arc->angle * i / 7;
      const double t = arc->parameterAt(curve, first, last, phi);
      const gp_Pnt expected = ElCLib::Value(0.2 + phi, gp_Circ(kPlace, 5));
      EXPECT_LT(curve.Value(t).Distance(expected), 1e-11) << "angle " << phi;
    }
  }
}

TEST(CircularArc, FindsAWholeCircle) {
  Handle(Geom_Circle) circle = new Geom_Circle(gp_Circ(kPlace, 2));
  const Handle(Geom_BSplineCurve) spline = GeomConvert::CurveToBSplineCurve(circle);
  const GeomAdaptor_Curve curve(spline);
  const std::optional<CircularArc> arc = circularArcOf(curve, curve.FirstParameter(), curve.LastParameter(), true);
  ASSERT_TRUE(arc);
  EXPECT_NEAR(arc->radius, 2, 1e-12);
  EXPECT_DOUBLE_EQ(arc->angle, 2 * M_PI);
  const double t = arc->parameterAt(curve, curve.FirstParameter(), curve.LastParameter(), 1.5 * M_PI);
  EXPECT_NEAR(arc->angleOf(curve.Value(t)), 1.5 * M_PI, 1e-12);
}

TEST(CircularArc, OtherCurvesAreNotCircles) {
  // An ellipse (radii 5 and 4.9).
  Handle(Geom_Ellipse) ellipse = new Geom_Ellipse(gp_Elips(kPlace, 5, 4.9));
  const Handle(Geom_BSplineCurve) flattened = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(ellipse, 0, 2));
  const GeomAdaptor_Curve ellipseCurve(flattened);
  EXPECT_FALSE(circularArcOf(ellipseCurve, ellipseCurve.FirstParameter(), ellipseCurve.LastParameter(), false));
  // A polynomial B-spline through 9 points of a circle: near it (about 1e-5 off), not on it.
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 9);
  for (int i = 1; i <= 9; ++i) points->SetValue(i, ElCLib::Value(0.2 * i, gp_Circ(kPlace, 5)));
  GeomAPI_Interpolate interpolate(points, Standard_False, 1e-9);
  interpolate.Perform();
  ASSERT_TRUE(interpolate.IsDone());
  const GeomAdaptor_Curve near(interpolate.Curve());
  EXPECT_FALSE(circularArcOf(near, near.FirstParameter(), near.LastParameter(), false));
  // A polynomial curve through three points of a circle.
  Handle(TColgp_HArray1OfPnt) s = new TColgp_HArray1OfPnt(1, 3);
  s->SetValue(1, gp_Pnt(0, 0, 0)), s->SetValue(2, gp_Pnt(1, 1, 0)), s->SetValue(3, gp_Pnt(2, 0, 0));
  GeomAPI_Interpolate bend(s, Standard_False, 1e-9);
  bend.Perform();
  ASSERT_TRUE(bend.IsDone());
  const GeomAdaptor_Curve parabola(bend.Curve());
  EXPECT_FALSE(circularArcOf(parabola, parabola.FirstParameter(), parabola.LastParameter(), false));
}

// Straight B-splines, as OpenCASCADE writes many lines (hammer.brep): their samples lie on a circle
// of radius 1e13 or more within 1e-9 of it, turning by rounding noise. A polynomial one cannot be a
// circle; a rational one turns by nothing.
TEST(CircularArc, StraightSplinesAreNotCircles) {
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 5);
  for (int i = 1; i <= 5; ++i) points->SetValue(i, gp_Pnt(3.0 * i, 1.0 - 0.5 * i, 2.0 * i * (1 + 1e-13 * i)));
  GeomAPI_Interpolate interpolate(points, Standard_False, 1e-9);
  interpolate.Perform();
  ASSERT_TRUE(interpolate.IsDone());
  const GeomAdaptor_Curve polynomial(interpolate.Curve());
  EXPECT_FALSE(circularArcOf(polynomial, polynomial.FirstParameter(), polynomial.LastParameter(), false));
  TColgp_Array1OfPnt poles(1, 3);
  poles(1) = gp_Pnt(0, 0, 0), poles(2) = gp_Pnt(1, 2, 3.0000000001), poles(3) = gp_Pnt(2, 4, 6);
  TColStd_Array1OfReal weights(1, 3);
  weights(1) = 1, weights(2) = 3, weights(3) = 1;
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0, knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = 3, mults(2) = 3;
  const GeomAdaptor_Curve rational(new Geom_BSplineCurve(poles, weights, knots, mults, 2));
  EXPECT_FALSE(circularArcOf(rational, 0, 1, false));
}

}  // namespace
}  // namespace cetview::brep
