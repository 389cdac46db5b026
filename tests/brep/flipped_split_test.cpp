// Splits of flipped triangles where the usual split point is not clear of a boundary chord
// (FaceMesher::safeSplit's fallbacks), on inputs face_fuzz wrote (tests/brep/data).
#include <gtest/gtest.h>

#include <memory>

#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// needle_beside_crowded_knots.brep (face_fuzz seed 2323, input 38): a bicubic B-spline 1 wide in
// u and 0.001 in v whose last two knot spans in u are 8.4e-7 wide, its poles swinging hundreds
// across: within 3e-10 of its u = 1 side the surface runs half a unit in 3D. On the last level a
// flipped needle there (two corners 0.004 apart, the third on the side 0.9 away) could not be
// split on its long edges (their points fell in the side's chord clearance) and was split on its
// short edge instead, whose midpoint all but repeated a corner: the same needle again, pass after
// pass, 964 flipped triangles where 50 are left now. A split point on an edge less than a tenth
// of the triangle's longest is no longer taken.
TEST(FlippedSplit, ANeedleIsNotSplitOnItsShortEdge) {
  auto model = test::loadTestData("needle_beside_crowded_knots.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::fuzzed("needle_beside_crowded_knots.brep", 0.0020188504213594685, 28.634012359807738));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->report(0).reason.find("refinement stopped"), std::string::npos) << t->report(0).reason;
  const std::vector<FaceQuality> levels = test::expectEveryLevelWithinTolerance(*t, 0);
  ASSERT_FALSE(levels.empty());
  EXPECT_LT(levels.back().flipped, 100u);
}

// flat_periodic_sheets_folding_into_a_pole_row.brep (face_fuzz seed 404, input 51): two faces on
// one bicubic sheet that lies in a plane, periodic in u, its v = vmin row collapsed onto one point
// and its parametrisation folding over within the plane. At 0.0114% and 20.9 degrees face 0 has 52
// triangles on level 6; on level 7, whose minimum size let them through, splits of flipped
// triangles crept towards the pole row, each leaving flipped ones beside it: 81396 triangles
// (11208 flipped, 240 across folds) after 40678 such splits. A face splits at most
// kMaxFlippedSplits flipped triangles a level: 506 triangles, 85 flipped.
TEST(FlippedSplit, SplitsOfFlippedTrianglesAreBoundedPerLevel) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("flat_periodic_sheets_folding_into_a_pole_row.brep",
                               test::fuzzed("flat_periodic_sheets_folding_into_a_pole_row.brep", 0.00011448062065530057, 20.948195620660719));
  ASSERT_EQ(levels.size(), 8u);
  EXPECT_LE(levels.back().triangles, 2000u) << "81396 with only the splits below the minimum size bounded";
  EXPECT_LE(levels.back().flipped, 200u) << "11208 with only the splits below the minimum size bounded";
}

}  // namespace
}  // namespace cetview::brep
