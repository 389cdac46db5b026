// One failing face never takes the model down: a face whose mesher throws (injected here, as a bug
// would) is isolated with its reason, gets the fallback mesh, and every other face is exactly what a
// clean run gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include "brepmesh_fallback.h"
#include "edge_table.h"
#include "face_mesher.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

void expectSameFace(const Tessellator& a, const Tessellator& b, FaceId f) {
  const FaceMesh& x = a.faceMesh(f);
  const FaceMesh& y = b.faceMesh(f);
  EXPECT_EQ(x.positions, y.positions) << "face " << f;
  EXPECT_EQ(x.levels, y.levels) << "face " << f;
  EXPECT_EQ(a.report(f).status, b.report(f).status) << "face " << f;
}

void expectWellFormed(const Tessellator& t, FaceId f) {
  const FaceMesh& m = t.faceMesh(f);
  ASSERT_EQ(m.levels.size(), static_cast<std::size_t>(t.lastLevel() + 1));
  ASSERT_EQ(m.levelVertexEnd.size(), m.levels.size());
  for (const auto& level : m.levels) {
    EXPECT_EQ(level.size() % 3, 0u);
    for (std::uint32_t i : level) ASSERT_LT(i, m.vertexCount());
  }
}

TEST(Isolation, ThrowingFaceFallsBackAndTheRestIsUntouched) {
  auto m = test::loadDemo();
  auto clean = Tessellator::create(*m, test::relative(0.001)).tessellator;
  auto faulty = Tessellator::create(*m, test::relative(0.001)).tessellator;
  ASSERT_TRUE(clean && faulty);
  const FaceId bad = 3;
  faulty->failFaceForTesting(bad);
  ASSERT_TRUE(clean->run(2));
  ASSERT_TRUE(faulty->run(2));

  const FaceReport r = faulty->report(bad);
  EXPECT_EQ(r.status, FaceStatus::kFallback) << r.reason;
  EXPECT_NE(r.reason.find("failure injected for testing"), std::string::npos) << r.reason;
  EXPECT_EQ(r.reason.find('\n'), std::string::npos);
  expectWellFormed(*faulty, bad);
  EXPECT_FALSE(faulty->faceMesh(bad).levels.back().empty()) << "the fallback mesh shows the face";
  for (FaceId f = 0; f < m->faces().size(); ++f) {
    if (f != bad) expectSameFace(*clean, *faulty, f);
  }
}

TEST(Isolation, FailureAfterSomeLevelsKeepsTheCompletedOnes) {
  auto m = test::loadDemo();
  auto clean = Tessellator::create(*m, test::relative(0.001)).tessellator;
  auto faulty = Tessellator::create(*m, test::relative(0.001)).tessellator;
  ASSERT_TRUE(clean && faulty);
  ASSERT_GE(clean->lastLevel(), 3);
  ASSERT_TRUE(clean->run(1));
  const FaceId bad = 0;
  for (int k = 0; k <= faulty->lastLevel(); ++k) {
    ASSERT_TRUE(faulty->discretiseEdges(k));
    if (k == 2) faulty->failFaceForTesting(bad);
    for (FaceId f = 0; f < m->faces().size(); ++f) faulty->advanceFace(f, k);
  }
  EXPECT_EQ(faulty->report(bad).status, FaceStatus::kFallback) << faulty->report(bad).reason;
  expectWellFormed(*faulty, bad);
  const FaceMesh& x = faulty->faceMesh(bad);
  const FaceMesh& y = clean->faceMesh(bad);
  EXPECT_EQ(x.levels[0], y.levels[0]);
  EXPECT_EQ(x.levels[1], y.levels[1]);
  EXPECT_NE(x.levels[2], y.levels[2]) << "from level 2 on, the face shows the fallback mesh";
  EXPECT_EQ(x.levels[2], x.levels.back());
  for (FaceId f = 0; f < m->faces().size(); ++f) {
    if (f != bad) expectSameFace(*clean, *faulty, f);
  }
}

// A face whose mesher throws is meshed by the fallback, cancellable like any other: with the flag
// raised, advanceFace() returns kCancelled at once and the face has no level; the next call makes
// what an uninterrupted run makes.
TEST(Isolation, AThrowingFaceWhoseFallbackIsCancelledResumesToTheSameMesh) {
  auto m = test::loadDemo();
  auto clean = Tessellator::create(*m, test::relative(0.001)).tessellator;
  auto t = Tessellator::create(*m, test::relative(0.001)).tessellator;
  ASSERT_TRUE(clean && t);
  const FaceId bad = 3;
  clean->failFaceForTesting(bad);
  t->failFaceForTesting(bad);
  ASSERT_TRUE(clean->run(2));
  for (int k = 0; k <= t->lastLevel(); ++k) ASSERT_TRUE(t->discretiseEdges(k));
  std::atomic<bool> cancel{true};
  EXPECT_EQ(t->advanceFace(bad, t->lastLevel(), &cancel), FaceStatus::kCancelled);
  EXPECT_TRUE(t->faceMesh(bad).levels.empty());
  cancel = false;
  ASSERT_TRUE(t->run(2, {}, &cancel));
  EXPECT_EQ(t->report(bad).status, FaceStatus::kFallback);
  for (FaceId f = 0; f < m->faces().size(); ++f) {
    expectSameFace(*clean, *t, f);
    EXPECT_EQ(t->report(f).reason, clean->report(f).reason) << "face " << f;
  }
}

// tests/brep/data/crossing_boundary.brep, written by face_fuzz: at 0.1% face 1's boundary crosses
// itself in UV on every level, so its coarse levels show BRepMesh's mesh and the final level falls
// back to it. (At the 0.0112% face_fuzz chose, its finest boundary crosses no more since the
// extension past its surface's knots is scaled by its own speed.) The final level takes the mesh the
// coarse levels made (at the same final tolerances) instead of running BRepMesh again: on a fuzzed
// face where BRepMesh takes 10 s, that halved the face's time.
TEST(Isolation, AFaceDeferredOnEveryLevelMeshesItsFallbackOnce) {
  auto model = test::loadTestData("crossing_boundary.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::fuzzed("crossing_boundary.brep", 0.001, 10.625467307545586));
  ASSERT_TRUE(t);
  const FaceId crossing = 1;
  ASSERT_EQ(t->report(crossing).status, FaceStatus::kFallback) << t->report(crossing).reason;
  EXPECT_NE(t->report(crossing).reason.find("crosses itself"), std::string::npos) << t->report(crossing).reason;
  expectWellFormed(*t, crossing);
  const FaceMesh& m = t->faceMesh(crossing);
  ASSERT_GT(m.levels.size(), 1u);
  EXPECT_FALSE(m.levels.back().empty());
  for (std::size_t k = 1; k < m.levels.size(); ++k) EXPECT_EQ(m.levels[k], m.levels[0]) << "level " << k;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// A plane face whose one wire crosses itself at the centre.
std::unique_ptr<Model> bowTie() {
  const TopoDS_Wire wire =
      BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(10, 10, 0), gp_Pnt(10, 0, 0), gp_Pnt(0, 10, 0), true)
          .Wire();
  return test::loadShape(BRepBuilderAPI_MakeFace(gp_Pln(), wire).Face(), "bow_tie");
}

// A face's reason names each repair and failure once. A bow tie (its one wire crosses itself at
// the centre) fails in CET on every level and in BRepMesh too: its reason said "fallback failed
// too" twice (BRepMesh ran again for the final level after failing for the coarse ones).
// crossing_boundary.brep's face 1, rebuilt on every level, said "inner wire ran counter-clockwise
// in UV; reversed" 24 times.
TEST(Isolation, AFaceReasonNamesEachRepairAndFailureOnce) {
  auto model = bowTie();
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  const std::string& reason = t->report(0).reason;
  EXPECT_EQ(t->report(0).status, FaceStatus::kEmpty) << reason;
  EXPECT_EQ(occurrences(reason, "crosses itself"), 1u) << reason;
  EXPECT_EQ(occurrences(reason, "fallback failed too"), 1u) << reason;

  auto crossing = test::loadTestData("crossing_boundary.brep");
  ASSERT_TRUE(crossing);
  auto c = test::tessellate(*crossing, test::fuzzed("crossing_boundary.brep", 0.00011235273724638671, 10.625467307545586));
  ASSERT_TRUE(c);
  EXPECT_EQ(occurrences(c->report(1).reason, "inner wire ran counter-clockwise in UV; reversed"), 1u)
      << c->report(1).reason;
}

// The cancellable fallback: with the flag raised it returns at once and appends nothing; BRepMesh
// goes on on its own thread, and the next call takes up the same job. Without a flag it runs inline.
TEST(Isolation, TheFallbackReturnsAtOnceWhenCancelledAndTakesUpItsJobAgain) {
  const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(10).Shape();
  const TopoDS_Face face = TopoDS::Face(TopExp_Explorer(sphere, TopAbs_FACE).Current());
  FaceMesh inline_;
  std::vector<std::uint32_t> inlineIndices;
  std::string failure;
  ASSERT_EQ(meshFaceWithBRepMesh(face, false, 0.01, 0.3, inline_, inlineIndices, failure),
            FallbackResult::kMeshed)
      << failure;
  std::atomic<bool> cancel{true};
  FaceMesh mesh;
  std::vector<std::uint32_t> indices;
  CancellableFallback fallback;
  EXPECT_EQ(fallback.run(face, false, 0.01, 0.3, mesh, indices, failure, &cancel),
            FallbackResult::kCancelled);
  EXPECT_EQ(mesh.vertexCount(), 0u);
  EXPECT_TRUE(indices.empty());
  cancel = false;
  ASSERT_EQ(fallback.run(face, false, 0.01, 0.3, mesh, indices, failure, &cancel), FallbackResult::kMeshed)
      << failure;
  EXPECT_EQ(indices, inlineIndices);
  EXPECT_EQ(mesh.positions, inline_.positions);
  EXPECT_EQ(mesh.normals, inline_.normals);
  // Abandoned while BRepMesh runs: destroyed without waiting (the thread ends on its own).
  CancellableFallback abandoned;
  cancel = true;
  EXPECT_EQ(abandoned.run(face, false, 0.003, 0.2, mesh, indices, failure, &cancel),
            FallbackResult::kCancelled);
}

// A square face whose edge's 3D curve swings 10000 units out (its ends on the square's corners, its
// pcurve the square's side): BRepMesh builds a face's boundary from the 3D curves, so its mesh
// would hold triangles out to that swing, and on such a fuzzed face (seed 2626, input 209) its
// healer, which no cancel reaches, allocated until the process was killed (24 GB). The fallback
// refuses such a face at once, inline or on its thread, and says which edge and why.
TEST(Isolation, TheFallbackRefusesAFaceWhoseEdgeCurveLiesFarOffItsSurface) {
  TopoDS_Face face =
      BRepBuilderAPI_MakeFace(gp_Pln(), BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0),
                                                                   gp_Pnt(10, 10, 0), gp_Pnt(0, 10, 0), true)
                                            .Wire())
          .Face();
  const TopoDS_Edge side = TopoDS::Edge(TopExp_Explorer(face, TopAbs_EDGE).Current());
  double first = 0, last = 0;
  const Handle(Geom_Curve) line = BRep_Tool::Curve(side, first, last);
  TColgp_Array1OfPnt poles(1, 3);
  poles(1) = line->Value(first), poles(2) = gp_Pnt(5, -1e4, 0), poles(3) = line->Value(last);
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = first, knots(2) = last;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities(1) = multiplicities(2) = 3;
  // The pcurve stays the side (stored: on a plane OCCT would otherwise project the new curve).
  const gp_Pnt a = line->Value(first), b = line->Value(last);
  BRep_Builder builder;
  builder.UpdateEdge(side, new Geom2d_Line(gp_Pnt2d(a.X(), a.Y()), gp_Dir2d(b.X() - a.X(), b.Y() - a.Y())),
                     face, BRep_Tool::Tolerance(side));
  builder.UpdateEdge(side, new Geom_BSplineCurve(poles, knots, multiplicities, 2),
                     BRep_Tool::Tolerance(side));
  FaceMesh mesh;
  std::vector<std::uint32_t> indices;
  std::string failure;
  EXPECT_EQ(meshFaceWithBRepMesh(face, false, 0.01, 0.3, mesh, indices, failure), FallbackResult::kFailed);
  EXPECT_NE(failure.find("edge 0's 3D curve spans"), std::string::npos) << failure;
  EXPECT_NE(failure.find("far beyond its surface"), std::string::npos) << failure;
  EXPECT_EQ(mesh.vertexCount(), 0u);
  EXPECT_TRUE(indices.empty());
  std::atomic<bool> cancel{false};
  CancellableFallback fallback;
  failure.clear();
  EXPECT_EQ(fallback.run(face, false, 0.01, 0.3, mesh, indices, failure, &cancel), FallbackResult::kFailed);
  EXPECT_NE(failure.find("far beyond its surface"), std::string::npos) << failure;
}

// A coarse level whose boundary crosses itself shows BRepMesh's mesh; where BRepMesh fails too, that
// level shows no triangles and says why, and the next level builds the face afresh (a finer boundary
// need not cross itself: on a fuzzed face, seed 2626 input 209, BRepMesh was refused on level 0).
// A failed fallback on a coarse level gave up the whole face there. The bow tie crosses itself on
// every level and BRepMesh fails on it: after level 0 it is empty for now, its reason saying why;
// at the end it is empty, its reason naming the crossing and the failure once.
TEST(Isolation, ACoarseLevelWithoutAFallbackMeshLeavesTheNextLevelToCet) {
  auto model = bowTie();
  ASSERT_TRUE(model);
  auto t = Tessellator::create(*model, test::relative(0.001)).tessellator;
  ASSERT_TRUE(t);
  ASSERT_GT(t->lastLevel(), 0);
  ASSERT_TRUE(t->run(1, {}, nullptr, 0));
  const FaceReport level0 = t->report(0);
  EXPECT_EQ(level0.status, FaceStatus::kEmpty) << level0.reason;
  EXPECT_NE(
      level0.reason.find(std::string("level 0 shows") + FaceMesher::kEmptyLevel + "boundary crosses itself"),
      std::string::npos)
      << level0.reason;
  EXPECT_NE(level0.reason.find("fallback failed too"), std::string::npos) << level0.reason;
  EXPECT_TRUE(t->faceMesh(0).levels.at(0).empty());
  // The next levels are built afresh, cross again, and join level 0's line.
  ASSERT_TRUE(t->run(1, {}, nullptr, 2));
  const FaceReport level2 = t->report(0);
  EXPECT_NE(level2.reason.find(std::string("levels 0 to 2 show") + FaceMesher::kEmptyLevel +
                               "boundary crosses itself"),
            std::string::npos)
      << level2.reason;
  EXPECT_EQ(occurrences(level2.reason, "fallback failed too"), 1u) << level2.reason;
  ASSERT_TRUE(t->run(1));
  const FaceReport& end = t->report(0);
  EXPECT_EQ(end.status, FaceStatus::kEmpty) << end.reason;
  EXPECT_EQ(occurrences(end.reason, "crosses itself"), 1u) << end.reason;
  EXPECT_EQ(occurrences(end.reason, "fallback failed too"), 1u) << end.reason;
  expectWellFormed(*t, 0);
}

// A run of level 0 cancelled while crossing_boundary.brep's face 1 makes its fallback mesh
// (BRepMesh, from about 15 ms into the run to 100-180 ms) returns without waiting for it: that face
// has no level yet (it had level 0 when the run waited for BRepMesh). Resumed, the run makes what an
// uninterrupted one makes: the same meshes, statuses and reasons (the domain is not rebuilt, the
// reason not repeated).
TEST(Isolation, AFallbackCancelledAnywhereResumesToTheSameMesh) {
  auto model = test::loadTestData("crossing_boundary.brep");
  ASSERT_TRUE(model);
  const MeshParams params = test::fuzzed("crossing_boundary.brep", 0.00011235273724638671, 10.625467307545586);
  auto clean = test::tessellate(*model, params);
  ASSERT_TRUE(clean);
  auto cleanLevel0 = Tessellator::create(*model, params).tessellator;  // its reports after level 0
  ASSERT_TRUE(cleanLevel0 && cleanLevel0->run(1, {}, nullptr, 0));
  int cancelled = 0;
  for (const double ms : {5.0, 30.0, 60.0}) {
    auto t = Tessellator::create(*model, params).tessellator;
    ASSERT_TRUE(t);
    std::atomic<bool> cancel{false};
    std::thread raise([&] {
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(ms));
      cancel = true;
    });
    const bool finished = t->run(1, {}, &cancel, 0);  // level 0: face 1 calls BRepMesh at once
    raise.join();
    cancel = false;
    if (!finished) {
      ++cancelled;
      EXPECT_TRUE(t->faceMesh(1).levels.empty()) << "cancelled after " << ms << " ms";
    }
    ASSERT_TRUE(t->run(1, {}, &cancel, 0));
    EXPECT_EQ(t->report(1).reason, cleanLevel0->report(1).reason) << "cancelled after " << ms << " ms";
    ASSERT_TRUE(t->run(1, {}, &cancel));
    for (FaceId f = 0; f < model->faces().size(); ++f) {
      expectSameFace(*clean, *t, f);
      EXPECT_EQ(t->report(f).reason, clean->report(f).reason)
          << "cancelled after " << ms << " ms, face " << f;
    }
  }
  EXPECT_GE(cancelled, 2) << "level 0 ran to its end before the flag";
}

// The work bound (MeshParams::maxPointsPerFaceLevel): a face whose refinement would add more points
// on one level stops there, keeps what it has on that level and the later ones, and says so. (By
// default the bound is far above any sample model's needs; fuzzed faces whose refinement does not
// converge ran to millions of points and gigabytes on one level.)
TEST(Isolation, AFaceStopsAtTheWorkBoundAndSaysSo) {
  auto model = test::loadShape(BRepPrimAPI_MakeSphere(10).Shape(), "sphere");
  ASSERT_TRUE(model);
  MeshParams params = test::relative(0.0001);
  auto free = test::tessellate(*model, params);
  params.maxPointsPerFaceLevel = 500;
  auto bound = test::tessellate(*model, params);
  ASSERT_TRUE(free && bound);
  ASSERT_EQ(model->faces().size(), 1u);
  EXPECT_EQ(free->report(0).status, FaceStatus::kOk);
  const FaceReport r = bound->report(0);
  EXPECT_EQ(r.status, FaceStatus::kRepaired);
  EXPECT_NE(r.reason.find("refinement stopped on level"), std::string::npos) << r.reason;
  expectWellFormed(*bound, 0);
  const FaceMesh& m = bound->faceMesh(0);
  int stopped = -1;
  for (int k = 0; k <= bound->lastLevel(); ++k) {
    EXPECT_FALSE(m.levels[std::size_t(k)].empty()) << "level " << k;
    if (stopped < 0 && bound->triangleCount(k) < free->triangleCount(k)) stopped = k;
  }
  ASSERT_GE(stopped, 0) << "the bound stopped no level";
  // The level it stopped on added at most the bound and one pass beyond; the next levels refine
  // only their boundary.
  EXPECT_LE(bound->triangleCount(bound->lastLevel()), free->triangleCount(bound->lastLevel()) / 2);
}

// edge_far_off_its_face.brep (face_fuzz seed 303, input 11) is a B-spline face 2.9 across whose
// edge 12 runs 1.08e6 units through space: on level 1 its discretisation took 2.2 million points (6
// s), and the face's boundary built from them (10 s more) held a cancelled run 7.5 s past the flag.
// Each edge now stops at EdgeTable::kMaxPoints on a level, and its faces say so.
TEST(Isolation, AnEdgeStopsAtItsPointBoundAndItsFaceSaysSo) {
  auto model = test::loadTestData("edge_far_off_its_face.brep");
  ASSERT_TRUE(model);
  auto tessellated = test::tessellate(*model, test::fuzzed("edge_far_off_its_face.brep", 0.00053658762185832064, 39.178301670862901), 1);
  ASSERT_TRUE(tessellated);
  const Tessellator& t = *tessellated;
  std::size_t most = 0;
  for (EdgeId e = 0; e < model->edgeCount(); ++e) {
    std::vector<float> xyz;
    t.edgePolyline(e, 1, xyz);
    most = std::max(most, xyz.size() / 3);
  }
  EXPECT_EQ(most, EdgeTable::kMaxPoints) << "2.2 million without the bound";
  EXPECT_NE(t.report(0).reason.find("discretisation stopped at"), std::string::npos) << t.report(0).reason;
}

// The same face's boundary on level 1 (262144 points of the capped edge, half a second or more to
// build) reads the flag as it goes: a flag raised 20 or 150 ms into the build stops it there, with
// nothing left of it (the vertices it appended dropped), where the build ran to its end before the
// flag was seen. Resumed, the face makes what an uninterrupted run makes.
TEST(Isolation, ABoundaryBuildStopsAtTheFlagAndIsBuiltAgainWhole) {
  auto model = test::loadTestData("edge_far_off_its_face.brep");
  ASSERT_TRUE(model);
  const MeshParams params = test::fuzzed("edge_far_off_its_face.brep", 0.00053658762185832064, 39.178301670862901);
  auto clean = test::tessellate(*model, params, 1);
  ASSERT_TRUE(clean);
  int stoppedInBuild = 0;
  for (const double ms : {20.0, 150.0}) {
    auto t = Tessellator::create(*model, params).tessellator;
    ASSERT_TRUE(t);
    ASSERT_TRUE(t->run(1, {}, nullptr, 0));
    ASSERT_TRUE(t->discretiseEdges(1));
    const std::size_t before = t->faceMesh(0).vertexCount();
    std::atomic<bool> cancel{false};
    std::thread raise([&] {
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(ms));
      cancel = true;
    });
    const FaceStatus status = t->advanceFace(0, 1, &cancel);
    raise.join();
    if (status == FaceStatus::kCancelled && t->faceMesh(0).vertexCount() == before) ++stoppedInBuild;
    cancel = false;
    ASSERT_NE(t->advanceFace(0, 1, &cancel), FaceStatus::kCancelled);
    expectSameFace(*clean, *t, 0);
    EXPECT_EQ(t->report(0).reason, clean->report(0).reason) << "cancelled after " << ms << " ms";
  }
  EXPECT_GE(stoppedInBuild, 1) << "every build ran to its end before the flag was seen";
}

// On its last level the same face falls back (its capped chords cross each other in UV), and BRepMesh
// is not run on it: its edges' 3D curves span up to 5.5e5 beside a surface 2.9 across, and
// BRepMesh's mesh of it reached 16 across (spikes out to the curves). Its reason gives the cause,
// the cap that led to it (it gave the cause alone), and why there is no fallback mesh.
TEST(Isolation, AFaceThatFallsBackAfterAnEdgeStoppedSaysBoth) {
  auto model = test::loadTestData("edge_far_off_its_face.brep");
  ASSERT_TRUE(model);
  auto tessellated = test::tessellate(*model, test::fuzzed("edge_far_off_its_face.brep", 0.00053658762185832064, 39.178301670862901));
  ASSERT_TRUE(tessellated);
  const FaceReport& r = tessellated->report(0);
  EXPECT_EQ(r.status, FaceStatus::kEmpty) << r.reason;
  EXPECT_NE(r.reason.find("discretisation stopped at"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("far beyond its surface"), std::string::npos) << r.reason;
  EXPECT_EQ(r.reason.find(FaceMesher::kDeferredLevel), std::string::npos) << r.reason;
  EXPECT_EQ(r.reason.find(FaceMesher::kEmptyLevel), std::string::npos) << r.reason;
}

// The default bound grows with the face (256 times its points before the level, at least 250k) up
// to a million points: a fuzzed face starting from 19889 boundary points (an edge 222 units off its
// surface) and refining for ever by a pole was allowed 5.1 million, minutes and gigabytes on level
// 0; it now stops after 1.0 million points, in 16 s and 0.46 GB (cetview export, two threads). No
// face of the 62 sample models comes near it; terrain at 0.001% has 617k points in all.
TEST(Isolation, TheDefaultWorkBoundGrowsWithTheFaceUpToAMillionPoints) {
  EXPECT_EQ(refinePointBound(100, 0), 250000u);
  EXPECT_EQ(refinePointBound(2000, 0), 512000u);
  EXPECT_EQ(refinePointBound(19889, 0), 1000000u) << "5.1 million before";
  EXPECT_EQ(refinePointBound(19889, 500), 500u) << "MeshParams::maxPointsPerFaceLevel";
}

}  // namespace
}  // namespace cetview::brep
