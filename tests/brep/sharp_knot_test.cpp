// A B-spline whose last knot span is a millionth as wide as the one before: the surface is C2 at
// the knot, but its speed across it jumps a million times, and the normal turns by the bend within a
// band far narrower than any split the mesher makes (SurfaceEval::findSharpKnots). Such a knot is a
// crease to the mesher: its refinement leaves the normals' turn across it to the chordal test, as
// across a knot of full multiplicity. The measure (built without tolerances) does not: its angle
// reads the turn across such a knot with the rest (the fuzzed band's largest: 152 degrees), and
// these tests assert no angle.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Dir.hxx>

#include "brep/measure.h"
#include "surface_eval.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

constexpr double kKnot = 1, kLastSpan = 1e-6;

// A sheet 10 wide (u, straight) whose profile (v, cubic) runs 30 along x and then, within its last
// span (from kKnot, lastSpan wide), bends up to z = 10; with a last span of 1e-6, the bend's first
// 90 degrees are packed within about 1e-6 of the knot in 3D.
TopoDS_Face bentSheet(double lastSpan = kLastSpan) {
  const double x[5] = {0, 10, 20, 30, 30}, z[5] = {0, 0, 0, 0, 10};
  TColgp_Array2OfPnt poles(1, 2, 1, 5);
  for (int i = 1; i <= 2; ++i)
    for (int j = 1; j <= 5; ++j) poles.SetValue(i, j, gp_Pnt(x[j - 1], 10.0 * (i - 1), z[j - 1]));
  TColStd_Array1OfReal uKnots(1, 2), vKnots(1, 3);
  TColStd_Array1OfInteger uMults(1, 2), vMults(1, 3);
  uKnots(1) = 0, uKnots(2) = 1, uMults(1) = uMults(2) = 2;
  vKnots(1) = 0, vKnots(2) = kKnot, vKnots(3) = kKnot + lastSpan;
  vMults(1) = 4, vMults(2) = 1, vMults(3) = 4;
  Handle(Geom_BSplineSurface) sheet = new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 1, 3);
  return BRepBuilderAPI_MakeFace(sheet, 1e-7).Face();
}

TEST(SharpKnot, IsACreaseToTheMesherAtTheTolerancesItCannotResolve) {
  const TopoDS_Face face = bentSheet();
  const double angle = 20 * M_PI / 180;
  const SurfaceEval meshing(face, 0.03, angle);
  EXPECT_TRUE(meshing.crossesCrease(0.5, kKnot - 0.1, 0.5, kKnot + 0.5 * kLastSpan));
  EXPECT_FALSE(meshing.crossesCrease(0.5, 0.1, 0.5, 0.9));
  // Without tolerances it is no crease, nor where the bend takes a whole span as wide as the others.
  EXPECT_FALSE(SurfaceEval(face).crossesCrease(0.5, kKnot - 0.1, 0.5, kKnot + 0.5 * kLastSpan));
  EXPECT_FALSE(SurfaceEval(bentSheet(1), 0.03, angle).crossesCrease(0.5, kKnot - 0.1, 0.5, kKnot + 0.5));
}

// At 0.1%: every level within its tolerance, no degenerate or flipped triangle, and 4273 triangles
// (the 90 degree crease needs its points). Without the knot taken for a crease, angle splits crept
// towards it from both sides down to the minimum size: 25485 triangles. (A fuzzed band with such a
// knot, at 0.35% and 14 degrees: 96k triangles and 7516 flipped slivers along it; now 58k and 328.)
TEST(SharpKnot, IsMeshedWithoutCreepingTowardsIt) {
  auto model = test::loadShape(bentSheet(), "bent_sheet");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  for (const FaceQuality& q : test::expectEveryLevelWithinTolerance(*t, 0)) {
    EXPECT_EQ(q.degenerate, 0u);
    EXPECT_EQ(q.flipped, 0u);
  }
  EXPECT_LE(t->triangleCount(t->lastLevel()), 8000u) << "25485 when the knot is not taken for a crease";
}

// tests/brep/data/sharp_knot_band.brep, written by face_fuzz: a band 5400 x 1500 on a bicubic
// B-spline whose last v span is 2e-9 wide against 0.002 for the one before; the normal turns 35 to
// 85 degrees within 1e-12 of v (1e-5 in 3D) past the knot. At 0.35% and 14.4 degrees, angle splits
// crept towards the knot from both sides and left slivers along it: 96435 triangles, 7516 flipped.
// With the knot a crease, 57573 triangles and 328 flipped (94 across folds); the rest were slivers
// left by points split beside the knot for the deviation, where the mesh must follow the bend. Put
// on the knot's line, those points make it an edge of the mesh: 53085 triangles, 29 flipped (23 across
// folds: triangles with a corner on the knot, whose normal is the slow side's).
TEST(SharpKnot, DeviationSplitsBesideItGoOntoItsLine) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("sharp_knot_band.brep", test::fuzzed("sharp_knot_band.brep", 0.0035128744065219275, 14.355077439536126));
  ASSERT_FALSE(levels.empty());
  const FaceQuality& last = levels.back();
  EXPECT_EQ(last.degenerate, 0u);
  EXPECT_LE(last.flipped - last.flippedAcrossFolds, 20u) << "234 with the split points beside the knot";
  EXPECT_LE(last.triangles, 60000u);
}

}  // namespace
}  // namespace cetview::brep
