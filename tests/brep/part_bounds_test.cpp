// A model's box is its geometry's (part_bounds.h), which relative deflections are fractions of and
// the window's Model panel shows: not OpenCASCADE's quick box, which bounds a B-spline by its
// control points and a torus face by more than the face (a NURBS torus 8 x 8 x 2 read
// 12 x 13.9 x 3.5; screw.step's diagonal 2.03x its own, shell1's 2.07x). Each case below checks
// that its premise holds, that the quick box is off, so that it fails where the loader takes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Trsf.hxx>

#include "brep/model.h"
#include "brep/tessellator.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

struct Box {
  double min[3], max[3];
};

Box quickBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box, Standard_False);
  Box b{};
  box.Get(b.min[0], b.min[1], b.min[2], b.max[0], b.max[1], b.max[2]);
  return b;
}

// The loaded model's box against `expected`, each side within `tolerance`; and the quick box off
// by more than `quickOff` on some side (the premise).
void expectBox(const TopoDS_Shape& shape, const std::string& name, const Box& expected, double tolerance,
               double quickOff) {
  auto model = test::loadShape(shape, name);
  ASSERT_TRUE(model);
  const Bounds b = model->bounds();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(b.min[i], expected.min[i], tolerance) << "axis " << i;
    EXPECT_NEAR(b.max[i], expected.max[i], tolerance) << "axis " << i;
  }
  const Box quick = quickBox(shape);
  double off = 0;
  for (int i = 0; i < 3; ++i)
    off = std::max({off, expected.min[i] - quick.min[i], quick.max[i] - expected.max[i]});
  EXPECT_GT(off, quickOff) << "the quick box is not off here: the case tests nothing";
}

// A torus of radii 3 and 1 written as a rational B-spline, as STEP and IGES files often carry it.
TEST(PartBounds, ANurbsTorusReadsItsOwnSize) {
  const TopoDS_Shape torus = BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeTorus(3, 1).Shape()).Shape();
  expectBox(torus, "nurbs_torus", Box{{-4, -4, -1}, {4, 4, 1}}, 1e-6, 1);
}

// A quarter of a torus (with its two caps): OpenCASCADE's quick box takes the torus face for more
// than the quarter.
TEST(PartBounds, AQuarterTorusReadsItsOwnSize) {
  const TopoDS_Shape quarter = BRepPrimAPI_MakeTorus(3, 1, M_PI / 2).Shape();
  expectBox(quarter, "quarter_torus", Box{{0, 0, -1}, {4, 4, 1}}, 1e-6, 0.25);
}

// A unit sphere written as a B-spline and turned off the axes: its extremes lie between the grid's
// samples (every 11.25 and 22.5 degrees; 2% short along an axis), where the search finds them.
TEST(PartBounds, ATurnedSphereReadsItsOwnSize) {
  gp_Trsf turn;
  turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 0.7);
  const TopoDS_Shape sphere =
      BRepBuilderAPI_NurbsConvert(BRepBuilderAPI_Transform(BRepPrimAPI_MakeSphere(1).Shape(), turn).Shape()).Shape();
  expectBox(sphere, "turned_sphere", Box{{-1, -1, -1}, {1, 1, 1}}, 1e-6, 0.05);
}

// A B-spline sheet of 16 x 16 spans, its inner knots at half-integers, with two bumps: a broad one
// (3 x 3 poles raised by 3) and a taller narrow one (one pole raised by 10) whose top lies between
// the samples of a 17 x 17 grid over the face, each of which reads lower than the broad bump's. The
// search from the best sample climbs the broad bump; with samples in every half span, the grid
// reaches the narrow one. Its top is found: as high as a 1001 x 1001 grid's highest sample, and
// not over it by more than that grid can miss.
TEST(PartBounds, ANarrowBumpBesideABroadOneReadsItsTop) {
  constexpr int kSpans = 16, kDegree = 3, kPoles = kSpans + kDegree;
  TColgp_Array2OfPnt poles(1, kPoles, 1, kPoles);
  for (int i = 1; i <= kPoles; ++i)
    for (int j = 1; j <= kPoles; ++j) {
      const bool broad = std::abs(i - 5) <= 1 && std::abs(j - 5) <= 1, narrow = i == 13 && j == 13;
      poles.SetValue(i, j, gp_Pnt(i, j, broad ? 3.0 : narrow ? 10.0 : 0.0));
    }
  TColStd_Array1OfReal knots(1, kSpans + 1);
  TColStd_Array1OfInteger mults(1, kSpans + 1);
  for (int k = 1; k <= kSpans + 1; ++k) {
    knots(k) = k == 1 ? 0.0 : k == kSpans + 1 ? double(kSpans) : k - 0.5;
    mults(k) = (k == 1 || k == kSpans + 1) ? kDegree + 1 : 1;
  }
  Handle(Geom_BSplineSurface) sheet = new Geom_BSplineSurface(poles, knots, knots, mults, mults, kDegree, kDegree);
  double top = 0;
  constexpr int kDense = 1000;
  for (int i = 0; i <= kDense; ++i)
    for (int j = 0; j <= kDense; ++j) top = std::max(top, sheet->Value(kSpans * double(i) / kDense, kSpans * double(j) / kDense).Z());
  auto model = test::loadShape(BRepBuilderAPI_MakeFace(sheet, 1e-7).Face(), "bumped_sheet");
  ASSERT_TRUE(model);
  EXPECT_GE(model->bounds().max[2], top - 1e-12 * top);
  EXPECT_LE(model->bounds().max[2], top + 1e-4 * top);
  // The premise: the narrow bump is the taller, and the coarse grid reads the broad one higher.
  double broadTop = 0, coarseAtNarrow = 0, coarseAtBroad = 0;
  for (int i = 0; i <= kSpans; ++i)
    for (int j = 0; j <= kSpans; ++j) {
      const double z = sheet->Value(i, j).Z();
      (i + j < kSpans ? coarseAtBroad : coarseAtNarrow) = std::max(i + j < kSpans ? coarseAtBroad : coarseAtNarrow, z);
    }
  for (int i = 0; i <= kDense / 2; ++i)
    for (int j = 0; j <= kDense / 2; ++j) broadTop = std::max(broadTop, sheet->Value(8.0 * i / (kDense / 2), 8.0 * j / (kDense / 2)).Z());
  EXPECT_GT(top, broadTop + 0.5);
  EXPECT_GT(coarseAtBroad, coarseAtNarrow);
}

// Relative deflections are fractions of that box's diagonal: 1% of the NURBS torus is 0.01 x
// sqrt(8^2 + 8^2 + 2^2).
TEST(PartBounds, RelativeDeflectionIsAFractionOfTheGeometrysDiagonal) {
  const TopoDS_Shape torus = BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeTorus(3, 1).Shape()).Shape();
  auto model = test::loadShape(torus, "nurbs_torus");
  ASSERT_TRUE(model);
  auto t = Tessellator::create(*model, test::relative(0.01)).tessellator;
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->chordal(), 0.01 * std::sqrt(132.0), 1e-8);
  // The premise: 1% of the quick box's diagonal is far from that.
  const Box quick = quickBox(torus);
  double square = 0;
  for (int i = 0; i < 3; ++i) square += (quick.max[i] - quick.min[i]) * (quick.max[i] - quick.min[i]);
  EXPECT_GT(0.01 * std::sqrt(square), 1.2 * 0.01 * std::sqrt(132.0)) << "the premise";
}

}  // namespace
}  // namespace cetview::brep
