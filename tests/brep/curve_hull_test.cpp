// CurveHull (curve_hull.h): whether a B-spline or Bezier edge leaves a chord, from its control
// points, where samples at fixed fractions of the chord miss a hook between them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <GC_MakeCircle.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Trsf.hxx>

#include "brep/measure.h"
#include "brep/tessellator.h"
#include "curve_hull.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A rational cubic from (0, 0, 0) to (30, 0, 0) whose heavy second pole holds it by the chord for
// most of its parameter; past about 0.9 it hooks out towards its third pole and back, 2.15 from the
// chord at its farthest (t = 0.982), while every eighth of its parameter lies within 0.65 of it (as
// a fuzzed edge's last span: weights 476, 136, 1.05 and 0.018 on its last four poles).
Handle(Geom_BezierCurve) hook() {
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = gp_Pnt(0, 0, 0), poles(2) = gp_Pnt(10, 0, 0), poles(3) = gp_Pnt(20, 10, 0),
  poles(4) = gp_Pnt(30, 0, 0);
  TColStd_Array1OfReal weights(1, 4);
  weights(1) = 1, weights(2) = 1000, weights(3) = 10, weights(4) = 1;
  return new Geom_BezierCurve(poles, weights);
}

double distanceToChord(const gp_Pnt& p, const gp_Pnt& a, const gp_Pnt& b) {
  const gp_Vec ab(a, b), ap(a, p);
  const double t = std::clamp(ap.Dot(ab) / ab.SquareMagnitude(), 0.0, 1.0);
  return p.Distance(a.Translated(t * ab));
}

// The farthest of n + 1 even samples of the curve from its chord over [ta, tb].
double farthestSample(const BRepAdaptor_Curve& c, double ta, double tb, int n) {
  double farthest = 0;
  for (int i = 0; i <= n; ++i)
    farthest = std::max(farthest, distanceToChord(c.Value(ta + (tb - ta) * i / n), c.Value(ta), c.Value(tb)));
  return farthest;
}

TEST(CurveHull, FindsAHookBetweenTheSamples) {
  const BRepAdaptor_Curve curve(BRepBuilderAPI_MakeEdge(hook()).Edge());
  const double eighths = farthestSample(curve, 0, 1, 8), dense = farthestSample(curve, 0, 1, 100000);
  ASSERT_LT(eighths, 0.65);
  ASSERT_GT(dense, 2.1);
  ASSERT_LT(dense, 2.2);
  const CurveHull hull(curve);
  ASSERT_TRUE(hull.available());
  const gp_Pnt a = curve.Value(0), b = curve.Value(1);
  EXPECT_TRUE(hull.leaves(0, 1, a, b, 1.0));
  EXPECT_TRUE(hull.leaves(0, 1, a, b, 2.1));
  EXPECT_FALSE(hull.leaves(0, 1, a, b, 2.2));
  // Over its first half, against its own chord: as far as the densest sampling finds.
  const gp_Pnt c = curve.Value(0.5);
  const double half = farthestSample(curve, 0, 0.5, 100000);
  EXPECT_TRUE(hull.leaves(0, 0.5, a, c, 0.98 * half));
  EXPECT_FALSE(hull.leaves(0, 0.5, a, c, 1.02 * half));
}

// The same hook as a B-spline of three spans (knots at 0.5 and 0.99: the hook's farthest point in
// the middle one), its edge moved and turned by a location: the adaptor hands out the curve in place,
// and the control points are read there.
TEST(CurveHull, ReadsAMovedBSplineAcrossItsSpans) {
  Handle(Geom_BSplineCurve) bspline = GeomConvert::CurveToBSplineCurve(hook());
  bspline->InsertKnot(0.5);
  bspline->InsertKnot(0.99);
  ASSERT_EQ(bspline->NbKnots(), 4);
  gp_Trsf move;
  move.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 1)), 1.0);
  move.SetTranslationPart(gp_Vec(100, -50, 7));
  const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(bspline).Edge();
  const BRepAdaptor_Curve curve(TopoDS::Edge(edge.Moved(TopLoc_Location(move))));
  const CurveHull hull(curve);
  ASSERT_TRUE(hull.available());
  const gp_Pnt a = curve.Value(0), b = curve.Value(1);
  EXPECT_GT(a.Distance(gp_Pnt(0, 0, 0)), 50) << "the edge is moved";
  EXPECT_TRUE(hull.leaves(0, 1, a, b, 2.1));
  EXPECT_FALSE(hull.leaves(0, 1, a, b, 2.2));
  // A part of the curve: from 0.95 to its end, against its own chord.
  const double farthest = farthestSample(curve, 0.95, 1, 100000);
  const gp_Pnt c = curve.Value(0.95);
  EXPECT_TRUE(hull.leaves(0.95, 1, c, b, 0.98 * farthest));
  EXPECT_FALSE(hull.leaves(0.95, 1, c, b, 1.02 * farthest));
}

// Only a rational curve with uneven weights is searched: a circle (not a B-spline), a polynomial
// B-spline and a circle as a rational B-spline (weights 1 and 0.707) are left to their samples.
TEST(CurveHull, SearchesOnlyWhereTheSamplesMayMiss) {
  const Handle(Geom_Circle) circle = GC_MakeCircle(gp_Ax2(), 5).Value();
  const BRepAdaptor_Curve round(BRepBuilderAPI_MakeEdge(circle).Edge());
  EXPECT_FALSE(CurveHull(round).available());
  EXPECT_FALSE(CurveHull::samplesMayMiss(round));
  const BRepAdaptor_Curve conic(BRepBuilderAPI_MakeEdge(GeomConvert::CurveToBSplineCurve(circle)).Edge());
  EXPECT_TRUE(CurveHull(conic).available());
  EXPECT_FALSE(CurveHull::samplesMayMiss(conic));
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = gp_Pnt(0, 0, 0), poles(2) = gp_Pnt(10, 0, 0), poles(3) = gp_Pnt(20, 10, 0),
  poles(4) = gp_Pnt(30, 0, 0);
  const Handle(Geom_BezierCurve) polynomial = new Geom_BezierCurve(poles);
  EXPECT_FALSE(CurveHull::samplesMayMiss(BRepAdaptor_Curve(BRepBuilderAPI_MakeEdge(polynomial).Edge())));
  EXPECT_TRUE(CurveHull::samplesMayMiss(BRepAdaptor_Curve(BRepBuilderAPI_MakeEdge(hook()).Edge())));
}

// rational_hook_edge.brep (face_fuzz seed 1212, input 224): a B-spline face 67 across whose edge 0
// ends on such a hook (its last weight 0.018 against up to 476): 2.04 off the chord of level 0,
// whose eighths lie within 0.67. The triangles standing on that chord read 1.71, 1.58x level 0's
// tolerance; the edge is now halved there.
TEST(CurveHull, AFuzzedEdgesHookIsFollowedFromLevelZero) {
  auto model = test::loadTestData("rational_hook_edge.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::fuzzed("rational_hook_edge.brep", 0.00043998962443358706, 52.782482642862597), 1);
  ASSERT_TRUE(t);
  for (int k = 0; k <= 1; ++k)
    EXPECT_LE(measureFaces(*t, k).at(0).maxDeviation, t->schedule()[std::size_t(k)].chordal) << "level " << k;
}

}  // namespace
}  // namespace cetview::brep
