// Live tessellation behind the window's sliders, against a CPU-side engine Scene (no GPU): every
// slider position maps to one schedule's level; coarser shows stored levels at once, finer refines;
// an angle change restarts coarse; the heat map's measured deviations stay within tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include <cmath>

#include "brep/measure.h"
#include "live_tessellation.h"

namespace cetview::test {
namespace {

// Polls until the target level is complete (or 60 s pass).
// The demo part streaming into `scene` with two threads, as the window starts it; null (and a test
// failure) when it cannot start.
std::unique_ptr<LiveTessellation> startDemo(engine::Scene& scene) {
  brep::LoadResult loaded = brep::loadModel("demo");
  EXPECT_TRUE(loaded) << loaded.error;
  if (!loaded) return nullptr;
  LiveOptions options;
  options.threads = 2;
  auto created = LiveTessellation::create(std::move(loaded.model), scene, options);
  EXPECT_TRUE(created.live) << created.error;
  return std::move(created.live);
}

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
  engine::Scene scene;
  std::unique_ptr<LiveTessellation> started = startDemo(scene);
  ASSERT_TRUE(started);
  LiveTessellation& live = *started;

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

  // The heat map: every shown triangle measured against the exact surface, within the level's
  // tolerance, drawn by extra heat parts while the model's own instance is hidden.
  const std::uint32_t instancesBefore = scene.instanceCount();
  double worst = -1;
  ASSERT_TRUE(live.showHeatMap(2, &worst));
  EXPECT_TRUE(live.heatMapShown());
  EXPECT_GT(worst, 0.0);
  EXPECT_LE(worst, 1.0);
  EXPECT_EQ(scene.instanceCount(), 2 * instancesBefore);
  const std::vector<std::vector<float>> perTriangle =
      brep::measureTriangles(live.tessellator(), live.targetLevel(), 2);
  std::size_t measured = 0;
  double largest = 0;
  for (std::uint32_t f = 0; f < perTriangle.size(); ++f) {
    EXPECT_EQ(perTriangle[f].size() * 3, live.modelScene().shownIndices(f).size()) << "face " << f;
    measured += perTriangle[f].size();
    for (float d : perTriangle[f]) largest = std::max(largest, static_cast<double>(d));
  }
  EXPECT_EQ(measured, live.consumer().shownTriangles());
  EXPECT_NEAR(largest / live.levelTolerance(live.targetLevel()), worst, 1e-6);
  // The per-triangle maximum is the per-face measure's.
  const std::vector<brep::FaceQuality> perFace =
      brep::measureFaces(live.tessellator(), live.targetLevel(), 2);
  for (std::uint32_t f = 0; f < perFace.size(); ++f) {
    double faceMax = 0;
    for (float d : perTriangle[f]) faceMax = std::max(faceMax, static_cast<double>(d));
    EXPECT_NEAR(faceMax, perFace[f].maxDeviation, 1e-6 * live.diagonal()) << "face " << f;
  }
  live.hideHeatMap();
  EXPECT_FALSE(live.heatMapShown());
  ASSERT_TRUE(live.showHeatMap(2));  // again: reuses the heat parts
  EXPECT_EQ(scene.instanceCount(), 2 * instancesBefore);
  live.hideHeatMap();

  // A new angle re-plans: the scene restarts and the same deflection is reached again.
  const double requested = live.requestedDeflection();
  ASSERT_EQ(live.setAngle(8.0), "");
  EXPECT_DOUBLE_EQ(live.angleDeg(), 8.0);
  EXPECT_DOUBLE_EQ(live.requestedDeflection(), requested);
  EXPECT_EQ(live.consumer().completeLevel(), -1);
  ASSERT_TRUE(settle(live));
  EXPECT_GT(live.consumer().shownTriangles(), 0u);
}

TEST(LiveTessellation, HeatBinsAndColoursRunFromGreenToRed) {
  EXPECT_EQ(LiveTessellation::heatBin(0.0), 0u);
  EXPECT_EQ(LiveTessellation::heatBin(0.999), LiveTessellation::kHeatBins - 2);
  EXPECT_EQ(LiveTessellation::heatBin(1.0), LiveTessellation::kHeatBins - 1);
  EXPECT_EQ(LiveTessellation::heatBin(INFINITY), LiveTessellation::kHeatBins - 1);
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

namespace cetview::test {
namespace {

// After "finer", once the target level is complete, every face shows it.
TEST(LiveTessellation, FinerTargetShowsTheWholeLevel) {
  for (int round = 0; round < 10; ++round) {
    engine::Scene scene;
    std::unique_ptr<LiveTessellation> started = startDemo(scene);
    ASSERT_TRUE(started);
    LiveTessellation& live = *started;
    // As the window does: move the slider as soon as the level shows, the stream maybe not idle yet.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (live.consumer().completeLevel() < live.targetLevel() &&
           std::chrono::steady_clock::now() < deadline) {
      live.poll(std::size_t{32} << 20);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const int finer = live.setDeflection(live.levelTolerance(live.targetLevel() + 1));
    ASSERT_TRUE(settle(live));
    const auto& stats = live.consumer().levelStats();
    ASSERT_GT(static_cast<int>(stats.size()), finer);
    EXPECT_EQ(live.consumer().shownTriangles(), stats[static_cast<std::size_t>(finer)].triangles)
        << "round " << round;
  }
}

// While another file loads, the window holds the current model's finer levels: the stream stops
// at the level shown when the hold began (the level in progress is cancelled) and stays there;
// released, it goes on to the target.
TEST(LiveTessellation, HeldFinerLevelsWaitAndReleasedGoOn) {
  engine::Scene scene;
  std::unique_ptr<LiveTessellation> started = startDemo(scene);
  ASSERT_TRUE(started);
  LiveTessellation& live = *started;
  live.setDeflection(live.finestAbsolute());  // the last level: far more work than level 0
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (live.consumer().completeLevel() < 0 && std::chrono::steady_clock::now() < deadline) {
    live.poll(std::size_t{64} << 20);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ASSERT_GE(live.consumer().completeLevel(), 0);
  live.holdFinerLevels(true);
  EXPECT_TRUE(live.holdingFinerLevels());
  while (!live.idle() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(live.idle()) << "the held stream did not stop";
  live.poll(std::size_t{64} << 20);
  const int held = live.consumer().completeLevel();
  EXPECT_LT(held, live.targetLevel());
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  live.poll(std::size_t{64} << 20);
  EXPECT_EQ(live.consumer().completeLevel(), held) << "a held stream went on";
  live.holdFinerLevels(false);
  ASSERT_TRUE(settle(live));
  EXPECT_EQ(live.consumer().completeLevel(), live.targetLevel());
}

}  // namespace
}  // namespace cetview::test
