// A surface without area over part of its domain: tests/brep/data/collapsed_half.brep, written by
// face_fuzz, is a B-spline whose poles over the last half of its u span all lie on one point. Its
// triangles there have no area and corners without a first-derivative normal: no orientation a
// split could put right. Split as flipped triangles, they ran on to the minimum size everywhere in
// the collapsed half: 4.7 million triangles in 31 s at 0.1% (BRepMesh: 1552).
#include <gtest/gtest.h>

#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

TEST(CollapsedSurface, HalfCollapsedToAPointIsNotRefinedThere) {
  auto model = test::loadTestData("collapsed_half.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  for (const FaceQuality& q : test::expectEveryLevelWithinTolerance(*t, 0)) EXPECT_LE(q.triangles, 20000u);
}

}  // namespace
}  // namespace cetview::brep
