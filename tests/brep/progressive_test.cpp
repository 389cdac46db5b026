// The progressive API contract: decreasing levels, vertices appended never moved, earlier levels
// kept, faces advanced from several threads, cancellation.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "test_support.h"

namespace cetview::brep {
namespace {

TEST(Progressive, ScheduleDecreasesToTheRequestedDeflection) {
  auto m = test::loadDemo();
  auto t = Tessellator::create(*m, test::relative(0.0005)).tessellator;
  ASSERT_TRUE(t);
  const auto& s = t->schedule();
  ASSERT_GE(s.size(), 3u);
  for (std::size_t k = 1; k < s.size(); ++k) {
    EXPECT_LT(s[k].chordal, s[k - 1].chordal);
    EXPECT_LE(s[k].angleRad, s[k - 1].angleRad);
  }
  EXPECT_DOUBLE_EQ(s.back().chordal, t->chordal());
  EXPECT_NEAR(t->chordal(), 0.0005 * m->bounds().diagonal(), 1e-12);
  MeshParams direct = test::relative(0.0005);
  direct.progressive = false;
  EXPECT_EQ(Tessellator::create(*m, direct).tessellator->schedule().size(), 1u);
}

TEST(Progressive, VerticesAreAppendedAndLevelsKept) {
  auto m = test::loadDemo();
  auto t = Tessellator::create(*m, test::relative(0.001)).tessellator;
  ASSERT_TRUE(t);
  const std::size_t faces = m->faces().size();
  std::vector<FaceMesh> snapshots(faces);
  for (int k = 0; k <= t->lastLevel(); ++k) {
    ASSERT_TRUE(t->discretiseEdges(k));
    for (FaceId f = 0; f < faces; ++f) {
      const FaceStatus s = t->advanceFace(f, k);
      ASSERT_EQ(s, FaceStatus::kOk) << t->report(f).reason;
      ASSERT_EQ(t->faceLevel(f), k);
      const FaceMesh& now = t->faceMesh(f);
      const FaceMesh& before = snapshots[f];
      ASSERT_EQ(now.levels.size(), static_cast<std::size_t>(k + 1));
      // Appended, never moved: the previous arrays are a prefix of the new ones.
      ASSERT_GE(now.positions.size(), before.positions.size());
      EXPECT_TRUE(std::equal(before.positions.begin(), before.positions.end(), now.positions.begin()));
      EXPECT_TRUE(std::equal(before.normals.begin(), before.normals.end(), now.normals.begin()));
      EXPECT_TRUE(std::equal(before.uv.begin(), before.uv.end(), now.uv.begin()));
      for (int j = 0; j < k; ++j) EXPECT_EQ(now.levels[static_cast<std::size_t>(j)], before.levels[static_cast<std::size_t>(j)]);
      EXPECT_EQ(now.levelVertexEnd.back(), now.vertexCount());
      for (std::uint32_t i : now.levels.back()) ASSERT_LT(i, now.vertexCount());
      snapshots[f] = now;
    }
  }
}

TEST(Progressive, ThreadsGiveTheSameMesh) {
  auto m = test::loadDemo();
  auto one = Tessellator::create(*m, test::relative(0.001)).tessellator;
  auto four = Tessellator::create(*m, test::relative(0.001)).tessellator;
  ASSERT_TRUE(one->run(1));
  ASSERT_TRUE(four->run(4));
  for (FaceId f = 0; f < m->faces().size(); ++f) {
    EXPECT_EQ(one->faceMesh(f).levels, four->faceMesh(f).levels) << "face " << f;
    EXPECT_EQ(one->faceMesh(f).positions, four->faceMesh(f).positions) << "face " << f;
  }
}

TEST(Progressive, CancellationStopsTheRun) {
  auto m = test::loadDemo();
  auto t = Tessellator::create(*m, test::relative(0.0001)).tessellator;
  std::atomic<bool> cancel{true};
  EXPECT_FALSE(t->run(2, {}, &cancel));
  std::size_t completed = 0;
  for (FaceId f = 0; f < m->faces().size(); ++f) completed += t->faceLevel(f) == t->lastLevel();
  EXPECT_EQ(completed, 0u);
  // A cancelled face resumes where it stopped.
  cancel = false;
  EXPECT_TRUE(t->run(2, {}, &cancel));
  for (FaceId f = 0; f < m->faces().size(); ++f) EXPECT_EQ(t->faceLevel(f), t->lastLevel());
}

// The flag is read inside a refinement pass and inside an edge's subdivision, not only between
// them (a fuzzed face's pass took 0.65 s to notice it), and a run cancelled anywhere resumes to the
// mesh an uninterrupted run makes: cancelled after 1 to 60 ms (inside passes of the demo's finest
// levels, and of its edges), then run again, every face's levels and vertices match.
TEST(Progressive, CancelledAnywhereResumesToTheSameMesh) {
  auto m = test::loadDemo();
  const MeshParams params = test::relative(0.0002);
  auto clean = Tessellator::create(*m, params).tessellator;
  ASSERT_TRUE(clean->run(1));
  for (const double ms : {1.0, 2.0, 3.5, 5.0, 8.0, 13.0, 21.0, 34.0, 60.0}) {
    auto t = Tessellator::create(*m, params).tessellator;
    std::atomic<bool> cancel{false};
    std::thread raise([&] {
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(ms));
      cancel = true;
    });
    const bool finished = t->run(1, {}, &cancel);
    raise.join();
    cancel = false;
    if (!finished) {
      ASSERT_TRUE(t->run(1, {}, &cancel));
    }
    for (FaceId f = 0; f < m->faces().size(); ++f) {
      ASSERT_EQ(t->faceMesh(f).levels, clean->faceMesh(f).levels) << "cancelled after " << ms << " ms, face " << f;
      ASSERT_EQ(t->faceMesh(f).positions, clean->faceMesh(f).positions) << "cancelled after " << ms << " ms, face " << f;
    }
  }
}

TEST(Progressive, ProgressReachesTheTotal) {
  auto m = test::loadDemo();
  auto t = Tessellator::create(*m, test::relative(0.01)).tessellator;
  std::size_t lastDone = 0, lastTotal = 0;
  ASSERT_TRUE(t->run(2, [&](std::size_t done, std::size_t total) {
    EXPECT_GE(done, lastDone);
    lastDone = done, lastTotal = total;
  }));
  EXPECT_EQ(lastDone, lastTotal);
  EXPECT_EQ(lastTotal, m->faces().size());
}

}  // namespace
}  // namespace cetview::brep
