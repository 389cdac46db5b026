// The progressive API contract: decreasing levels, vertices appended never moved, earlier levels
// kept, faces advanced from several threads, cancellation.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <thread>
#include <utility>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Face.hxx>

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

// A flat disc of radius 100 whose rim (a periodic cubic B-spline, 8000 poles alternately 0.05 in
// and out) ripples 4000 times by about 0.02: at 0.04%, levels 0 to 3 see a circle (64 points on
// level 3), and level 4, the first whose tolerance is below the ripples, places 7552 more on the
// rim at once (a knurled rim). The disc needs no interior point on any level.
TopoDS_Face knurledDisc() {
  constexpr int kPoles = 8000;
  TColgp_Array1OfPnt poles(1, kPoles);
  for (int i = 1; i <= kPoles; ++i) {
    const double angle = 2 * M_PI * i / kPoles, r = 100 + (i % 2 ? 0.05 : -0.05);
    poles(i) = gp_Pnt(r * std::cos(angle), r * std::sin(angle), 0);
  }
  TColStd_Array1OfReal knots(1, kPoles + 1);
  TColStd_Array1OfInteger mults(1, kPoles + 1);
  for (int i = 1; i <= kPoles + 1; ++i) knots(i) = i - 1, mults(i) = 1;
  Handle(Geom_BSplineCurve) rim = new Geom_BSplineCurve(poles, knots, mults, 3, true);
  return BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(rim).Edge()).Wire(), true)
      .Face();
}

// Vertices on the mesh's border (edges of one triangle): the rim's points.
std::size_t borderVertices(const std::vector<std::uint32_t>& triangles) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t i = 0; i < triangles.size(); i += 3)
    for (int j = 0; j < 3; ++j) {
      const std::uint32_t a = triangles[i + j], b = triangles[i + (j + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  std::map<std::uint32_t, int> border;
  for (const auto& [edge, count] : edges)
    if (count == 1) ++border[edge.first], ++border[edge.second];
  return border.size();
}

// Levels 0 to k - 1 of every face, uncancelled.
void advanceBelow(Tessellator& t, int k) {
  for (int level = 0; level < k; ++level) {
    ASSERT_TRUE(t.discretiseEdges(level));
    for (FaceId f = 0; f < t.model().faces().size(); ++f)
      ASSERT_NE(t.advanceFace(f, level), FaceStatus::kCancelled);
  }
}

// The flag is read inside the boundary's refinement too, segment by segment: level 4 of the
// knurled disc splits the rim's 64 segments into 7616, and a call cancelled part way keeps the
// rim's new points placed so far (more than level 3's vertices, fewer than level 4's rim) and goes
// on from there to the mesh of an uninterrupted run. Before, the boundary was refined whole once
// begun (on a rim refined from 128 points to 52800 in one level, half a second).
TEST(Progressive, CancelledInsideTheBoundarysRefinementGoesOnFromThere) {
  auto m = test::loadShape(knurledDisc(), "knurled_disc");
  ASSERT_TRUE(m);
  const MeshParams params = test::relative(0.0004);
  constexpr int k = 4;
  auto clean = Tessellator::create(*m, params).tessellator;
  ASSERT_TRUE(clean);
  ASSERT_GT(clean->lastLevel(), k);
  advanceBelow(*clean, k + 1);
  const FaceMesh& full = clean->faceMesh(0);
  const std::size_t before = full.levelVertexEnd[k - 1], after = full.levelVertexEnd[k];
  ASSERT_EQ(borderVertices(full.levels[k]), after) << "every vertex of the disc is on its rim";
  ASSERT_GT(after, 20 * before) << "level " << k << " refines the rim at once";

  bool stoppedInside = false;
  for (const double ms : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) {
    auto t = Tessellator::create(*m, params).tessellator;
    advanceBelow(*t, k);
    ASSERT_TRUE(t->discretiseEdges(k));
    std::atomic<bool> cancel{false};
    std::thread raise([&] {
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(ms));
      cancel = true;
    });
    const FaceStatus status = t->advanceFace(0, k, &cancel);
    raise.join();
    if (status == FaceStatus::kCancelled) {
      const std::size_t placed = t->faceMesh(0).vertexCount();
      stoppedInside = stoppedInside || (placed > before && placed < after);
      ASSERT_NE(t->advanceFace(0, k), FaceStatus::kCancelled);
    }
    ASSERT_EQ(t->faceMesh(0).levels, full.levels) << "cancelled after " << ms << " ms";
    ASSERT_EQ(t->faceMesh(0).positions, full.positions) << "cancelled after " << ms << " ms";
  }
  EXPECT_TRUE(stoppedInside) << "no call stopped inside the rim's refinement";
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
