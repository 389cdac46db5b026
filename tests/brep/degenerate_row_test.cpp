// A degenerate edge's row (SurfaceEval's degenerate rows): a B-spline's pole row is often collapsed
// only to a micron, its first derivative along the row small but not noise, and the normal it gives
// swings along the row. Points on a degenerate edge therefore take the estimated normal of a pole
// (pointNormal() says they have no regular one), also where the edge's pcurve strays a few
// billionths off the iso-line across its range (trj4's face 404: a vertex on such an edge took the
// normal of the row itself, 70 degrees off its neighbours' a hundred-thousandth of the face away,
// and a sliver beside it read as flipped on four levels at 0.01%).
#include <gtest/gtest.h>

#include <vector>

#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>

#include "surface_eval.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A bicubic sheet over [0, 1]^2 bulging up, its row v = 0 drawn together to a micron (its poles
// a micron apart along x).
Handle(Geom_BSplineSurface) sheetWithAMicronRow() {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  for (int i = 1; i <= 4; ++i) {
    for (int j = 1; j <= 4; ++j) {
      const double x = i - 2.5, z = (i == 2 || i == 3) && (j == 2 || j == 3) ? 1.0 : 0.0;
      poles(i, j) = j == 1 ? gp_Pnt(1e-6 * x, 0, 0) : gp_Pnt(x * (j - 1) / 3.0, j - 1.0, z);
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots(1) = 0, knots(2) = 1, mults(1) = mults(2) = 4;
  return new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
}

// The sheet's face over the UV quadrilateral from (0, 0) to (1, tilt), (1, 1) and (0, 1), its
// first edge flagged degenerated and stripped of its 3D curve, as a writer that took the row for a
// pole leaves it.
TopoDS_Face faceWithDegenerateRow(double tilt) {
  const TopoDS_Face face = test::uvPolygonFace(sheetWithAMicronRow(), {{0, 0}, {1, tilt}, {1, 1}, {0, 1}});
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull() || pcurve->Value(first).Y() > 1e-6 || pcurve->Value(last).Y() > 1e-6) continue;
    BRep_Builder builder;
    builder.UpdateEdge(edge, Handle(Geom_Curve)(), BRep_Tool::Tolerance(edge));
    builder.Degenerated(edge, Standard_True);
  }
  return face;
}

TEST(DegenerateRow, PointsOnTheEdgeHaveNoRegularNormal) {
  for (const double tilt : {0.0, 4e-9, 1e-7}) {
    SCOPED_TRACE(testing::Message() << "pcurve across the row by " << tilt);
    const SurfaceEval eval(faceWithDegenerateRow(tilt));
    for (const double u : {0.1, 0.5, 0.9}) {
      gp_Pnt p;
      gp_Dir n;
      EXPECT_FALSE(eval.pointNormal(u, tilt * u, p, n)) << "u " << u;
    }
    // A hundredth of the face inside, the normal is regular.
    gp_Pnt p;
    gp_Dir n;
    EXPECT_TRUE(eval.pointNormal(0.5, 0.01, p, n));
  }
}

}  // namespace
}  // namespace cetview::brep
