// Flat free-form faces (SurfaceEval::flat()): a B-spline whose poles lie in one plane, within a
// hundredth of the tolerance, and whose parametrisation keeps its orientation over the face but is
// uneven there (speeds 4x apart), is meshed in that plane: its scaled plane is the plane itself, so
// the triangulation is one of the face's outline in 3D, whatever its weights do to the
// parametrisation.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "brep/measure.h"
#include "surface_eval.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A rational bicubic patch over [0, 1]^2 on the plane z = 0, its 4 x 4 poles at x from `columns`
// and y = 0..3, weights from 0.1 to 10 (all 1 when not `weighted`); `lift` raises one inner pole
// off the plane.
TopoDS_Face weightedSheet(const double columns[4], double lift = 0, bool weighted = true) {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  TColStd_Array2OfReal weights(1, 4, 1, 4);
  const double w[4][4] = {{1, 10, 0.1, 2}, {0.2, 5, 8, 0.1}, {3, 0.1, 0.5, 10}, {1, 4, 0.3, 1}};
  for (int i = 1; i <= 4; ++i) {
    for (int j = 1; j <= 4; ++j) {
      poles(i, j) = gp_Pnt(columns[i - 1], j - 1.0, i == 2 && j == 3 ? lift : 0.0);
      weights(i, j) = weighted ? w[i - 1][j - 1] : 1.0;
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots(1) = 0, knots(2) = 1, mults(1) = mults(2) = 4;
  const Handle(Geom_BSplineSurface) sheet = new Geom_BSplineSurface(poles, weights, knots, knots, mults, mults, 3, 3);
  return BRepBuilderAPI_MakeFace(sheet, 1e-7).Face();
}

constexpr double kColumns[4] = {0, 1, 2, 3};
constexpr double kChordal = 1e-3;  // the patch is about 4.2 across

// Flat: the scaled plane is the plane (distances there are 3D distances) and unscaled() inverts it.
TEST(FlatFreeForm, ARationalSheetInAPlaneIsMeshedInThatPlane) {
  const SurfaceEval eval(weightedSheet(kColumns), kChordal, 0.3);
  ASSERT_TRUE(eval.flat());
  std::vector<std::pair<double, double>> at;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) at.emplace_back(0.05 + 0.15 * i, 0.05 + 0.15 * j);
  for (std::size_t k = 0; k < at.size(); ++k) {
    const auto [u, v] = at[k];
    const cet::Point2 q = eval.scaled(u, v);
    double bu = -1, bv = -1;
    eval.unscaled(q, bu, bv);
    EXPECT_NEAR(bu, u, 1e-8) << "at " << u << ", " << v;
    EXPECT_NEAR(bv, v, 1e-8) << "at " << u << ", " << v;
    const auto [u2, v2] = at[(k * 7 + 3) % at.size()];
    const cet::Point2 q2 = eval.scaled(u2, v2);
    EXPECT_NEAR(std::hypot(q.x - q2.x, q.y - q2.y), eval.point(u, v).Distance(eval.point(u2, v2)), 1e-9);
  }
}

// Not flat: poles off the plane by more than a hundredth of the tolerance, a sheet folding over
// itself (its columns out of order), no tolerance to judge by, or a parametrisation close to
// uniform (the same grid without weights: it meshes as well, and cheaper, in the scaled UV plane).
TEST(FlatFreeForm, OnlyASheetFlatForTheToleranceAndUnfoldedIsFlat) {
  EXPECT_TRUE(SurfaceEval(weightedSheet(kColumns, 0.005 * kChordal), kChordal, 0.3).flat());
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns, 0.02 * kChordal), kChordal, 0.3).flat());
  const double folded[4] = {0, 3, -1, 2};
  EXPECT_FALSE(SurfaceEval(weightedSheet(folded), kChordal, 0.3).flat());
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns)).flat());
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns, 0, false), kChordal, 0.3).flat());
}

// The whole patch, meshed: its outline's four iso-lines are straight, so each level is two
// triangles, within the tolerance and facing the surface's way.
TEST(FlatFreeForm, AWeightedFlatPatchTakesItsOutlineOnly) {
  auto model = test::loadShape(weightedSheet(kColumns), "weighted sheet");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  const std::vector<FaceQuality> levels = test::expectEveryLevelWithinTolerance(*t, 0);
  for (const FaceQuality& q : levels) {
    EXPECT_EQ(q.flipped, 0u);
    EXPECT_EQ(q.degenerate, 0u);
    EXPECT_LE(q.triangles, 8u);
  }
}

// flat_sheet_with_extreme_weights.brep (face_fuzz seed 101, input 79): a degree 1 x 2 sheet 73000
// long, flat within 1.7e-4, its weights from 1e-3 to 712 (a step of 1e-6 in u moves a point by 115
// near one side). Meshed in the scaled UV plane its first level (0.24%, 35.4 degrees) took 375788
// triangles, 53756 of them flipped, in 57 s: triangles well shaped there overlapped in 3D, and
// their splits made more. In its plane: two triangles a level, within 1e-6 of the tolerance.
TEST(FlatFreeForm, AFlatSheetWithExtremeWeightsIsMeshedAsItsOutline) {
  const std::vector<FaceQuality> levels = test::testDataEveryLevel(
      "flat_sheet_with_extreme_weights.brep", test::relative(0.0024064050719198024, 35.363088426031894));
  ASSERT_FALSE(levels.empty());
  for (const FaceQuality& q : levels) {
    EXPECT_EQ(q.flipped, 0u);
    EXPECT_EQ(q.degenerate, 0u);
    EXPECT_LE(q.triangles, 8u);
  }
}

}  // namespace
}  // namespace cetview::brep
