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
  auto t = test::tessellate(*model, test::relative(0.0020188504213594685, 28.634012359807738));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->report(0).reason.find("refinement stopped"), std::string::npos) << t->report(0).reason;
  const std::vector<FaceQuality> levels = test::expectEveryLevelWithinTolerance(*t, 0);
  ASSERT_FALSE(levels.empty());
  EXPECT_LT(levels.back().flipped, 100u);
}

}  // namespace
}  // namespace cetview::brep
