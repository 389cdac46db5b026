// Edges flagged degenerated that are not (BRepCheck's InvalidDegeneratedFlag): a closed iso row of a
// periodic surface written as a pole. Loading makes them regular edges and reports the repair; true
// poles and apexes stay degenerate.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <Precision.hxx>
#include <gp_Ax3.hxx>

#include "test_support.h"

namespace cetview::brep {
namespace {

constexpr double kHeight = 20;

// A tube of radius 5 and height kHeight on `surface` (u around, v along the axis), natural bounds.
TopoDS_Face tube(const Handle(Geom_Surface)& surface) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  surface->Bounds(u0, u1, v0, v1);
  if (Precision::IsInfinite(u1)) u0 = 0, u1 = 2 * M_PI;
  return BRepBuilderAPI_MakeFace(surface, u0, u1, 0, kHeight, 1e-7).Face();
}

// `face` with its edge along v = `v` flagged degenerated and stripped of its 3D curve, as a writer
// that took the row for a pole leaves it.
TopoDS_Face withRowFlaggedDegenerate(const TopoDS_Face& face, double v) {
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (BRep_Tool::IsClosed(edge, face)) continue;  // a seam
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull() || std::abs(pcurve->Value(first).Y() - v) > 1e-9 || std::abs(pcurve->Value(last).Y() - v) > 1e-9)
      continue;
    BRep_Builder builder;
    builder.UpdateEdge(edge, Handle(Geom_Curve)(), BRep_Tool::Tolerance(edge));
    builder.Degenerated(edge, Standard_True);
  }
  return face;
}

std::size_t finalTriangles(const Tessellator& t) { return t.triangleCount(t.lastLevel()); }

void checkRimIsMeshedAlongTheSurface(const Handle(Geom_Surface)& surface, const std::string& name) {
  const MeshParams params = test::relative(0.001);
  auto clean = test::loadShape(tube(surface), name + "_clean");
  ASSERT_TRUE(clean);
  auto reference = test::tessellateAndCheck(*clean, params);
  ASSERT_TRUE(reference);

  auto flagged = test::loadShape(withRowFlaggedDegenerate(tube(surface), kHeight), name + "_flagged");
  ASSERT_TRUE(flagged);
  // The promise on every level: meshed as a pole, the rim's row sat on one point and the face was
  // nowhere near its surface (a fuzzed B-spline strip: 279x the deflection, 2.3M triangles).
  auto t = test::tessellateAndCheck(*flagged, params);
  ASSERT_TRUE(t);
  const FaceReport report = t->report(0);
  EXPECT_EQ(report.status, FaceStatus::kRepaired) << report.reason;
  EXPECT_NE(report.reason.find("flagged degenerated but spanning 10 on the surface"), std::string::npos) << report.reason;
  // Rebuilt as the surface's own iso curve (model_finalize.cpp: here a circle), the rim is meshed
  // as the clean tube's is. BRepLib::BuildCurve3d's approximation of it was halved where the circle
  // takes equal segments: the cylinder's tube took 88 triangles against 80.
  EXPECT_EQ(finalTriangles(*t), finalTriangles(*reference));
}

TEST(FalseDegenerateEdges, CylinderRimFlaggedAsAPoleIsMeshedAlongTheSurface) {
  checkRimIsMeshedAlongTheSurface(new Geom_CylindricalSurface(gp_Ax3(), 5), "cylinder_rim");
}

TEST(FalseDegenerateEdges, PeriodicBSplineRimFlaggedAsAPoleIsMeshedAlongTheSurface) {
  const Handle(Geom_BSplineSurface) bspline = GeomConvert::SurfaceToBSplineSurface(
      new Geom_RectangularTrimmedSurface(new Geom_CylindricalSurface(gp_Ax3(), 5), 0, 2 * M_PI, 0, kHeight));
  ASSERT_FALSE(bspline.IsNull());
  if (!bspline->IsUPeriodic()) bspline->SetUPeriodic();
  ASSERT_TRUE(bspline->IsUPeriodic());
  checkRimIsMeshedAlongTheSurface(bspline, "bspline_rim");
}

// A three-sided B-spline patch whose v = 0 row of poles lies within 2e-5 of one point (as CAD
// exports write them; the part is 10 across), flagged degenerated with the default tolerance of
// 1e-7: a pole still, though the row spreads beyond ten times its tolerance.
TEST(FalseDegenerateEdges, AMicronWideCollapsedRowStaysAPole) {
  const int n = 4;
  TColgp_Array2OfPnt poles(1, n, 1, n);
  for (int i = 1; i <= n; ++i) {
    const double theta = (i - 1) / double(n - 1);
    poles.SetValue(i, 1, gp_Pnt(2e-5 * std::cos(3.0 * i), 2e-5 * std::sin(3.0 * i), 0));
    for (int j = 2; j <= n; ++j) {
      const double r = 10.0 * (j - 1) / (n - 1);
      poles.SetValue(i, j, gp_Pnt(r * std::cos(theta), r * std::sin(theta), 0.3 * r + 0.5 * std::sin(1.0 * i * j)));
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots(1) = 0, knots(2) = 1, mults(1) = mults(2) = n;
  const Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, n - 1, n - 1);
  const TopoDS_Face face = withRowFlaggedDegenerate(BRepBuilderAPI_MakeFace(surface, 1e-7).Face(), 0);
  int degenerate = 0;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) degenerate += BRep_Tool::Degenerated(TopoDS::Edge(e.Current()));
  ASSERT_EQ(degenerate, 1);
  auto model = test::loadShape(face, "micron_row");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->report(0).reason.find("flagged degenerated"), std::string::npos) << t->report(0).reason;
}

TEST(FalseDegenerateEdges, TruePolesAndApexesStayDegenerate) {
  const std::pair<TopoDS_Shape, const char*> shapes[] = {
      {BRepPrimAPI_MakeSphere(10).Shape(), "sphere"},
      {BRepPrimAPI_MakeCone(5, 0, 10).Shape(), "cone_apex"},
  };
  for (const auto& [shape, name] : shapes) {
    SCOPED_TRACE(name);
    auto model = test::loadShape(shape, name);
    ASSERT_TRUE(model);
    auto t = test::tessellateAndCheck(*model, test::relative(0.001));
    ASSERT_TRUE(t);
    for (FaceId f = 0; f < model->faces().size(); ++f) {
      EXPECT_EQ(t->report(f).status, FaceStatus::kOk) << f << ": " << t->report(f).reason;
    }
  }
}

}  // namespace
}  // namespace cetview::brep
