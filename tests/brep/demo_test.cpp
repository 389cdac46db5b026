// The demo part at relative and absolute deflections: the deviation promise, watertightness, no
// degenerate, flipped or intersecting triangles, on every level.
#include <gtest/gtest.h>

#include "test_support.h"

namespace cetview::brep {
namespace {

const Model& demo() {
  static std::unique_ptr<Model> model = [] {
    LoadResult r = loadModel("demo");
    EXPECT_TRUE(r) << r.error;
    return std::move(r.model);
  }();
  return *model;
}

TEST(Demo, OnePercent) { test::tessellateAndCheck(demo(), test::relative(0.01)); }
TEST(Demo, OneTenthPercent) { test::tessellateAndCheck(demo(), test::relative(0.001)); }
TEST(Demo, OneHundredthPercent) { test::tessellateAndCheck(demo(), test::relative(0.0001), test::finalLevelOnly()); }
TEST(Demo, Absolute) { test::tessellateAndCheck(demo(), test::absolute(0.05)); }
TEST(Demo, CoarseAngle) { test::tessellateAndCheck(demo(), test::relative(0.002, 45)); }

TEST(Demo, EveryFaceMeshedByCet) {
  auto t = test::tessellateAndCheck(demo(), test::relative(0.001));
  ASSERT_TRUE(t);
  for (FaceId f = 0; f < demo().faces().size(); ++f)
    EXPECT_EQ(t->report(f).status, FaceStatus::kOk) << "face " << f << ": " << t->report(f).reason;
}

}  // namespace
}  // namespace cetview::brep
