// Live tessellation behind the window's sliders, against a CPU-side engine Scene (no GPU): every
// slider position maps to one schedule's level; coarser shows stored levels at once, finer refines;
// an angle change restarts coarse; the heat map's measured deviations stay within tolerance.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "live_tessellation.h"

namespace cetview::test {
namespace {

// Polls until the target level is complete (or 60 s pass).
bool settle(LiveTessellation& live) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (live.consumer().completeLevel() < live.targetLevel() || !live.idle()) {
    live.poll(std::size_t{64} << 20);
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  live.poll(std::size_t{64} << 20);
  return true;
}

TEST(LiveTessellation, SlidersRetargetOneScheduleAndAnglesRestart) {
  brep::LoadResult loaded = brep::loadModel("demo");
  ASSERT_TRUE(loaded) << loaded.error;
  engine::Scene scene;
  LiveOptions options;
  options.threads = 2;
  auto created = LiveTessellation::create(std::move(loaded.model), scene, options);
  ASSERT_TRUE(created.live) << created.error;
  LiveTessellation& live = *created.live;

  // The schedule runs from the coarse start down to 0.01% of the diagonal; 0.1% maps to the
  // coarsest level within it.
  const double diag = live.diagonal();
  EXPECT_NEAR(live.finestAbsolute(), 1e-4 * diag, 1e-9 * diag);
  EXPECT_NEAR(live.levelTolerance(live.lastLevel()), live.finestAbsolute(), 1e-9 * diag);
  const int fine = live.targetLevel();
  EXPECT_LE(live.levelTolerance(fine), 1e-3 * diag * (1 + 1e-9));
  if (fine > 0) {
    EXPECT_GT(live.levelTolerance(fine - 1), 1e-3 * diag);
  }
  EXPECT_LT(fine, live.lastLevel());
  ASSERT_TRUE(settle(live));
  const std::uint64_t fineTriangles = live.consumer().shownTriangles();
  EXPECT_GT(fineTriangles, 0u);
  EXPECT_GT(scene.vertexCount(), 0u);

  // Coarser: stored levels show at once, with no polling.
  const int coarse = live.setDeflection(live.coarsestAbsolute());
  EXPECT_EQ(coarse, 0);
  EXPECT_LT(live.consumer().shownTriangles(), fineTriangles);
  EXPECT_EQ(live.consumer().showLevel(), 0);

  // Finer than before: refinement continues past the old target.
  const int finer = live.setDeflection(live.levelTolerance(fine + 1));
  EXPECT_EQ(finer, fine + 1);
  ASSERT_TRUE(settle(live));
  EXPECT_GT(live.consumer().shownTriangles(), fineTriangles);

  // The heat map's numbers: measured deviation against the level's tolerance, within it.
  const std::vector<double> ratios = live.measureDeviationRatios(2);
  ASSERT_EQ(ratios.size(), live.model().faces().size());
  for (double r : ratios) {
    EXPECT_GE(r, 0.0);
    EXPECT_LE(r, 1.0);
  }
  live.applyHeatColors(ratios);
  EXPECT_EQ(scene.faceColor(live.modelScene().engineFace(0)).r, LiveTessellation::heatColor(ratios[0]).r);
  live.restoreFaceColors();
  EXPECT_EQ(scene.faceColor(live.modelScene().engineFace(0)).r, toColor8(live.model().faces()[0].color).r);

  // A new angle re-plans: the scene restarts and the same deflection is reached again.
  const double requested = live.requestedDeflection();
  ASSERT_EQ(live.setAngle(8.0), "");
  EXPECT_DOUBLE_EQ(live.angleDeg(), 8.0);
  EXPECT_DOUBLE_EQ(live.requestedDeflection(), requested);
  EXPECT_EQ(live.consumer().completeLevel(), -1);
  ASSERT_TRUE(settle(live));
  EXPECT_GT(live.consumer().shownTriangles(), 0u);
}

TEST(LiveTessellation, HeatColoursRunFromGreenToRed) {
  const engine::Color8 ok = LiveTessellation::heatColor(0.0);
  const engine::Color8 bad = LiveTessellation::heatColor(1.0);
  const engine::Color8 worse = LiveTessellation::heatColor(3.0);
  EXPECT_GT(ok.g, ok.r);
  EXPECT_GT(bad.r, bad.g);
  EXPECT_EQ(bad.r, worse.r);
  EXPECT_EQ(bad.g, worse.g);
}

}  // namespace
}  // namespace cetview::test
