// A surface without area over part of its domain: tests/brep/data/collapsed_half.brep, written by
// face_fuzz, is a B-spline whose poles over the last half of its u span all lie on one point. Its
// triangles there have no area and corners without a first-derivative normal: no orientation a
// split could put right. Split as flipped triangles, they ran on to the minimum size everywhere in
// the collapsed half: 4.7 million triangles in 31 s at 0.1% (BRepMesh: 1552).
#include <gtest/gtest.h>

#include <string>

#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

TEST(CollapsedSurface, HalfCollapsedToAPointIsNotRefinedThere) {
  LoadResult loaded = loadModel(std::string(CETVIEW_BREP_TEST_DATA) + "/collapsed_half.brep");
  ASSERT_TRUE(loaded.model) << loaded.error;
  auto created = Tessellator::create(*loaded.model, test::relative(0.001));
  ASSERT_TRUE(created.tessellator) << created.error;
  Tessellator& t = *created.tessellator;
  ASSERT_TRUE(t.run(1));
  for (int k = 0; k <= t.lastLevel(); ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const FaceQuality q = measureFaces(t, k).at(0);
    EXPECT_LE(q.maxDeviation, t.schedule()[std::size_t(k)].chordal);
    EXPECT_LE(q.triangles, 20000u);
  }
}

}  // namespace
}  // namespace cetview::brep
