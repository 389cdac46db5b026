// Idle workers helping busy ones (work_sharing.h): every chunk of a section runs exactly once,
// helpers do take chunks, errors reach the section's owner; and a model of one large face, whose
// refinement passes are shared out, gets the same mesh on 1, 2 and 4 threads.
#include "work_sharing.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "tessellator_impl.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

TEST(WorkSharing, OutsideARunASectionRunsOnTheCallerAlone) {
  WorkerPool pool;
  WorkSharing sharing{pool};
  std::vector<int> hits(1000, 0);
  const auto caller = std::this_thread::get_id();
  bool elsewhere = false;
  sharing.forEach(hits.size(), 7, [&](std::size_t begin, std::size_t end) {
    EXPECT_LE(end - begin, 7u);
    if (std::this_thread::get_id() != caller) elsewhere = true;
    for (std::size_t i = begin; i < end; ++i) ++hits[i];
  });
  EXPECT_FALSE(elsewhere);
  for (int h : hits) ASSERT_EQ(h, 1);
  EXPECT_EQ(sharing.helpedChunks(), 0u);
}

TEST(WorkSharing, IdleWorkersTakeChunksAndEachRunsOnce) {
  WorkerPool pool;
  WorkSharing sharing{pool};
  constexpr std::size_t kItems = 400;
  std::vector<std::atomic<int>> hits(kItems);
  std::mutex mutex;
  std::set<std::thread::id> threads;
  sharing.run(4, [&](unsigned worker) {
    if (worker != 0) return;  // the others are idle at once
    for (int section = 0; section < 3; ++section) {
      sharing.forEach(kItems, 4, [&](std::size_t begin, std::size_t end) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          threads.insert(std::this_thread::get_id());
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        for (std::size_t i = begin; i < end; ++i) hits[i].fetch_add(1);
      });
    }
  });
  for (const auto& h : hits) ASSERT_EQ(h.load(), 3);
  EXPECT_GT(threads.size(), 1u);
  EXPECT_GT(sharing.helpedChunks(), 0u);
}

TEST(WorkSharing, AnExceptionInAHelpedChunkReachesTheRun) {
  WorkerPool pool;
  WorkSharing sharing{pool};
  EXPECT_THROW(sharing.run(3,
                           [&](unsigned worker) {
                             if (worker != 0) return;
                             sharing.forEach(200, 1, [&](std::size_t begin, std::size_t) {
                               std::this_thread::sleep_for(std::chrono::microseconds(100));
                               if (begin == 150) throw std::runtime_error("chunk 150");
                             });
                           }),
               std::runtime_error);
  // Usable again afterwards: every worker that is called (the caller, and the helper if it woke
  // in time) covers the whole section once.
  std::atomic<int> sum{0}, calls{0};
  sharing.run(2, [&](unsigned) {
    ++calls;
    sharing.forEach(100, 3, [&](std::size_t b, std::size_t e) { sum += static_cast<int>(e - b); });
  });
  EXPECT_GE(calls.load(), 1);
  EXPECT_EQ(sum.load(), 100 * calls.load());
}

// One wavy B-spline face of 12 x 12 bicubic spans: nearly all of the work is one face's refinement.
TopoDS_Face wavySheet() {
  const int n = 15;
  TColgp_Array2OfPnt poles(1, n, 1, n);
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= n; ++j) poles.SetValue(i, j, gp_Pnt(10.0 * i, 10.0 * j, 6 * std::sin(0.9 * i) * std::cos(0.7 * j)));
  TColStd_Array1OfReal knots(1, n - 2);
  TColStd_Array1OfInteger mults(1, n - 2);
  for (int k = 1; k <= n - 2; ++k) knots(k) = k - 1, mults(k) = (k == 1 || k == n - 2) ? 4 : 1;
  Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
  return BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
}

TEST(WorkSharing, OneLargeFaceMeshesTheSameOnAnyNumberOfThreads) {
  auto model = test::loadShape(wavySheet(), "wavy_sheet");
  ASSERT_TRUE(model);
  ASSERT_EQ(model->faces().size(), 1u);
  std::vector<std::unique_ptr<Tessellator>> runs;
  for (unsigned threads : {1u, 2u, 4u}) {
    auto t = Tessellator::create(*model, test::relative(0.0001)).tessellator;
    ASSERT_TRUE(t);
    ASSERT_TRUE(t->run(threads));
    if (threads == 1) {
      EXPECT_EQ(t->impl().sharing.helpedChunks(), 0u);
    } else {
      EXPECT_GT(t->impl().sharing.helpedChunks(), 0u) << threads << " threads: no pass was shared";
    }
    runs.push_back(std::move(t));
  }
  ASSERT_GT(runs[0]->triangleCount(runs[0]->lastLevel()), 10000u);
  for (std::size_t r = 1; r < runs.size(); ++r) {
    EXPECT_EQ(runs[r]->faceMesh(0).levels, runs[0]->faceMesh(0).levels) << "run " << r;
    EXPECT_EQ(runs[r]->faceMesh(0).positions, runs[0]->faceMesh(0).positions) << "run " << r;
    EXPECT_EQ(runs[r]->faceMesh(0).normals, runs[0]->faceMesh(0).normals) << "run " << r;
  }
}

}  // namespace
}  // namespace cetview::brep
