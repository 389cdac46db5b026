// The triangulator on small and degenerate inputs: every result is checked for valid topology,
// exact local Delaunay-ness and its constraints; counts and areas are known in closed form.
#include "cet/triangulator.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

#include "cet/poly_triangulation.h"
#include "cet/predicates.h"
#include "triangulation_checks.h"

namespace cet {
namespace {

using testing::coveredArea;
using testing::expectSegmentsPresent;
using testing::expectValidCdt;

constexpr double kPi = 3.14159265358979323846;

Triangulator triangulate(const std::vector<Point2>& points) {
  Triangulator tri;
  tri.addVertices(points.data(), points.size());
  tri.insertPending();
  tri.markDomain(DomainRule::kHullAndHolePoints);
  return tri;
}

TEST(Triangulator, SingleTriangle) {
  const Triangulator tri = triangulate({{0, 0}, {1, 0}, {0, 1}});
  EXPECT_EQ(tri.insideTriangleCount(), 1u);
  expectValidCdt(tri);
}

TEST(Triangulator, ClockwiseInputBecomesCounterClockwise) {
  const Triangulator tri = triangulate({{0, 0}, {0, 1}, {1, 0}});
  std::vector<VertexId> idx;
  tri.collectTriangles(idx);
  ASSERT_EQ(idx.size(), 3u);
  EXPECT_GT(testing::signedArea2(tri.point(idx[0]), tri.point(idx[1]), tri.point(idx[2])), 0);
}

TEST(Triangulator, AllCollinearGivesNoTriangleAndNoCrash) {
  std::vector<Point2> line;
  for (int i = 0; i < 100; ++i) line.push_back({i * 0.5, i * 0.25});
  Triangulator tri;
  tri.addVertices(line.data(), line.size());
  EXPECT_FALSE(tri.insertPending());
  EXPECT_FALSE(tri.hasTriangles());
  EXPECT_EQ(tri.insideTriangleCount(), 0u);
  EXPECT_EQ(tri.insertSegment(0, 5).code, Status::Code::kNoTriangulation);
  // A later batch that leaves the line makes the whole set triangulable.
  const Point2 off{1, 10};
  tri.addVertices(&off, 1);
  EXPECT_TRUE(tri.insertPending());
  EXPECT_EQ(tri.insideTriangleCount(), 99u);
  expectValidCdt(tri);
}

// A raised flag stops the bulk insertion within kCancelStride vertices: it returns false and says
// so (no collinearity); the same points insert whole without it.
TEST(Triangulator, BulkInsertionStopsAtARaisedFlag) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::vector<Point2> points(20 * Triangulator::kCancelStride);
  for (Point2& p : points) p = {coordinate(random), coordinate(random)};
  const std::atomic<bool> raised{true}, lowered{false};
  Triangulator stopped;
  stopped.addVertices(points.data(), points.size());
  EXPECT_FALSE(stopped.insertPending(false, &raised));
  EXPECT_TRUE(stopped.cancelled());
  std::size_t in = 0;
  for (VertexId v = 0; v < points.size(); ++v) in += stopped.mesh().incident(v) != kNoTriangle;
  EXPECT_LE(in, Triangulator::kCancelStride + 3);
  Triangulator whole;
  whole.addVertices(points.data(), points.size());
  EXPECT_TRUE(whole.insertPending(false, &lowered));
  EXPECT_FALSE(whole.cancelled());
  whole.markDomain(DomainRule::kHullAndHolePoints);
  expectValidCdt(whole);
}

TEST(Triangulator, TwoPointsAndDuplicatesOnly) {
  Triangulator tri;
  const std::vector<Point2> p = {{1, 1}, {1, 1}, {2, 2}, {1, 1}};
  tri.addVertices(p.data(), p.size());
  EXPECT_FALSE(tri.insertPending());
}

TEST(Triangulator, DuplicatesAreMerged) {
  std::vector<Point2> p = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 1}, {0.5, 0.5}, {0.5, 0.5}};
  const Triangulator tri = triangulate(p);
  EXPECT_EQ(tri.mergedCount(), 3u);
  EXPECT_EQ(tri.representative(4), 0u);
  EXPECT_EQ(tri.representative(5), 2u);
  EXPECT_EQ(tri.representative(7), tri.representative(6));
  EXPECT_EQ(tri.insideTriangleCount(), 4u);
  expectValidCdt(tri);
}

TEST(Triangulator, GridIsCoCircularEverywhere) {
  std::vector<Point2> p;
  const int n = 60;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) p.push_back({static_cast<double>(i), static_cast<double>(j)});
  const Triangulator tri = triangulate(p);
  EXPECT_EQ(tri.insideTriangleCount(), static_cast<std::size_t>(2 * (n - 1) * (n - 1)));
  EXPECT_DOUBLE_EQ(coveredArea(tri), (n - 1.0) * (n - 1.0));
  expectValidCdt(tri);
}

TEST(Triangulator, CircleWithCentre) {
  std::vector<Point2> p;
  const int n = 200;
  for (int i = 0; i < n; ++i) p.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
  p.push_back({0, 0});
  const Triangulator tri = triangulate(p);
  EXPECT_EQ(tri.insideTriangleCount(), static_cast<std::size_t>(n));
  expectValidCdt(tri);
}

TEST(Triangulator, CircleWithoutCentreHasNMinusTwoTriangles) {
  std::vector<Point2> p;
  const int n = 257;
  for (int i = 0; i < n; ++i) p.push_back({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)});
  const Triangulator tri = triangulate(p);
  EXPECT_EQ(tri.insideTriangleCount(), static_cast<std::size_t>(n - 2));
  expectValidCdt(tri);
}

TEST(Triangulator, ClusteredAndTinyScales) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  for (double scale : {1e-12, 1.0, 1e12}) {
    std::vector<Point2> p;
    for (int c = 0; c < 5; ++c) {
      const Point2 centre{g(rng) * scale, g(rng) * scale};
      for (int i = 0; i < 400; ++i) p.push_back({centre.x + g(rng) * scale * 1e-6, centre.y + g(rng) * scale * 1e-6});
    }
    const Triangulator tri = triangulate(p);
    EXPECT_GT(tri.insideTriangleCount(), 1900u);
    expectValidCdt(tri);
  }
}

TEST(Triangulator, PointsOnHullLineExtendTheHull) {
  // Collinear points along the bottom edge inserted after the first triangle exist: they land on
  // the hull line beyond and between the hull vertices.
  const Triangulator tri = triangulate({{0, 0}, {4, 0}, {2, 3}, {1, 0}, {6, 0}, {-3, 0}, {5, 0}, {2, 0}});
  EXPECT_EQ(tri.insideTriangleCount(), 6u);
  EXPECT_DOUBLE_EQ(coveredArea(tri), 0.5 * 9 * 3);
  expectValidCdt(tri);
}

TEST(Triangulator, SegmentIsRecoveredAndFlagged) {
  // A long segment across a fan of points that Delaunay would never connect.
  std::vector<Point2> p = {{0, 0}, {10, 0}};
  for (int i = 1; i < 10; ++i) {
    p.push_back({static_cast<double>(i), 0.3});
    p.push_back({static_cast<double>(i), -0.3});
  }
  Triangulator tri;
  tri.addVertices(p.data(), p.size());
  ASSERT_TRUE(tri.insertPending());
  ASSERT_TRUE(tri.insertSegment(0, 1).ok());
  const EdgeRef e = tri.mesh().findEdge(0, 1);
  ASSERT_NE(e.t, kNoTriangle);
  EXPECT_EQ(tri.mesh().flag(e.t, e.i), kAlongLoop);
  const EdgeRef back = tri.mesh().findEdge(1, 0);
  EXPECT_EQ(tri.mesh().flag(back.t, back.i), kAgainstLoop);
  // Inserting it again the other way makes it a both-ways constraint.
  ASSERT_TRUE(tri.insertSegment(1, 0).ok());
  EXPECT_EQ(tri.mesh().flag(e.t, e.i), kBothWays);
  expectValidCdt(tri);
}

TEST(Triangulator, SegmentThroughVerticesIsSplitThere) {
  std::vector<Point2> p = {{0, 0}, {6, 6}, {2, 2}, {4, 4}, {0, 6}, {6, 0}, {1, 3}, {3, 1}};
  Triangulator tri;
  tri.addVertices(p.data(), p.size());
  ASSERT_TRUE(tri.insertPending());
  ASSERT_TRUE(tri.insertSegment(0, 1).ok());
  for (auto [a, b] : {std::pair<VertexId, VertexId>{0, 2}, {2, 3}, {3, 1}}) {
    const EdgeRef e = tri.mesh().findEdge(a, b);
    ASSERT_NE(e.t, kNoTriangle) << a << "-" << b;
    EXPECT_EQ(tri.mesh().flag(e.t, e.i), kAlongLoop);
  }
  expectValidCdt(tri);
}

TEST(Triangulator, CrossingSegmentsAreRejectedWithAClearMessage) {
  std::vector<Point2> p = {{0, 0}, {2, 2}, {0, 2}, {2, 0}, {1, 3}};
  Triangulator tri;
  tri.addVertices(p.data(), p.size());
  ASSERT_TRUE(tri.insertPending());
  ASSERT_TRUE(tri.insertSegment(0, 1).ok());
  const Status s = tri.insertSegment(2, 3);
  EXPECT_EQ(s.code, Status::Code::kCrossingSegments);
  EXPECT_NE(s.message.find("crosses"), std::string::npos) << s.message;
  expectValidCdt(tri);  // still a valid triangulation with the first segment
  expectSegmentsPresent(tri, {{0, 1}});
}

TEST(Triangulator, SegmentsTouchingAtEndpointsAreNotCrossing) {
  std::vector<Point2> p = {{0, 0}, {2, 0}, {1, 1}, {1, 3}};
  Triangulator tri;
  tri.addVertices(p.data(), p.size());
  ASSERT_TRUE(tri.insertPending());
  EXPECT_TRUE(tri.insertSegment(0, 2).ok());
  EXPECT_TRUE(tri.insertSegment(2, 1).ok());
  EXPECT_TRUE(tri.insertSegment(2, 3).ok());
  expectValidCdt(tri);
}

std::vector<Point2> square(Point2 c, double h, bool clockwise) {
  std::vector<Point2> s = {{c.x - h, c.y - h}, {c.x + h, c.y - h}, {c.x + h, c.y + h}, {c.x - h, c.y + h}};
  if (clockwise) std::swap(s[1], s[3]);
  return s;
}

TEST(Triangulator, HoleByHolePointAndByLoopOrientationAgree) {
  std::vector<Point2> p = square({0, 0}, 10, false);
  const std::vector<Point2> inner = square({0, 0}, 3, true);
  p.insert(p.end(), inner.begin(), inner.end());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-9.5, 9.5);
  for (int i = 0; i < 300; ++i) p.push_back({u(rng), u(rng)});
  std::vector<std::array<std::uint32_t, 2>> seg;
  for (std::uint32_t k = 0; k < 4; ++k) seg.push_back({k, (k + 1) % 4});
  for (std::uint32_t k = 0; k < 4; ++k) seg.push_back({4 + k, 4 + (k + 1) % 4});

  auto build = [&](DomainRule rule) {
    Triangulator tri;
    tri.addVertices(p.data(), p.size());
    tri.insertPending();
    for (auto s : seg) EXPECT_TRUE(tri.insertSegment(s[0], s[1]).ok());
    const Point2 hole{0, 0};
    tri.markDomain(rule, rule == DomainRule::kHullAndHolePoints ? &hole : nullptr,
                   rule == DomainRule::kHullAndHolePoints ? 1 : 0);
    return tri;
  };
  const Triangulator byPoint = build(DomainRule::kHullAndHolePoints);
  const Triangulator byOrientation = build(DomainRule::kLoopOrientation);
  EXPECT_NEAR(coveredArea(byPoint), 400.0 - 36.0, 1e-9);
  EXPECT_NEAR(coveredArea(byOrientation), 400.0 - 36.0, 1e-9);
  EXPECT_EQ(byPoint.insideTriangleCount(), byOrientation.insideTriangleCount());
  expectValidCdt(byPoint);
  expectSegmentsPresent(byPoint, seg);
}

TEST(Triangulator, ConcavityIsRemovedLikeTrianglesDashP) {
  // An L-shaped polygon: its convex hull minus the notch.
  const std::vector<Point2> p = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  PolyData data;
  data.points = p;
  for (std::uint32_t k = 0; k < 6; ++k) data.segments.push_back({k, (k + 1) % 6});
  PolyTriangulation result;
  std::string error;
  ASSERT_TRUE(triangulatePoly(data, result, error)) << error;
  EXPECT_EQ(result.tri.insideTriangleCount(), 4u);
  EXPECT_DOUBLE_EQ(coveredArea(result.tri), 12.0);
  expectValidCdt(result.tri);
  std::vector<std::uint32_t> input;
  result.collectInputTriangles(input);
  for (std::size_t k = 0; k < input.size(); k += 3) {
    EXPECT_GT(testing::signedArea2(p[input[k]], p[input[k + 1]], p[input[k + 2]]), 0) << "input numbering, CCW";
  }
}

// The square [-1, 1]^2 as a counter-clockwise loop (vertices 0..3), its domain marked.
void constrainedUnitSquare(Triangulator& tri) {
  const std::vector<Point2> p = square({0, 0}, 1, false);
  tri.addVertices(p.data(), p.size());
  tri.insertPending();
  for (std::uint32_t k = 0; k < 4; ++k) ASSERT_TRUE(tri.insertSegment(k, (k + 1) % 4).ok());
  tri.markDomain(DomainRule::kLoopOrientation);
}

TEST(Triangulator, RefinementBatchesInsertWithoutRebuild) {
  Triangulator tri;
  ASSERT_NO_FATAL_FAILURE(constrainedUnitSquare(tri));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.999, 0.999);
  std::size_t expectedVertices = 4;
  for (int level = 0; level < 4; ++level) {
    std::vector<Point2> batch(100u << level);
    for (auto& q : batch) q = {u(rng), u(rng)};
    batch.push_back({0.5, 0.5});
    batch.push_back({0.5, 0.5});     // duplicate inside the batch
    batch.push_back({1.0, 0.0});     // on the boundary constraint: rejected
    batch.push_back({3.0, 3.0});     // outside: rejected
    std::vector<VertexId> ids(batch.size());
    std::vector<InsertOutcome> outcomes(batch.size());
    tri.insertPoints(batch.data(), batch.size(), ids.data(), outcomes.data());
    const std::size_t n = batch.size();
    EXPECT_EQ(outcomes[n - 2], InsertOutcome::kOnConstraint);
    EXPECT_EQ(ids[n - 2], kNoVertex);
    EXPECT_EQ(outcomes[n - 1], InsertOutcome::kOutside);
    EXPECT_EQ(ids[n - 3], ids[n - 4]);
    for (auto o : outcomes) expectedVertices += o == InsertOutcome::kInserted ? 1 : 0;
    EXPECT_EQ(tri.vertexCount(), expectedVertices);
    EXPECT_NEAR(coveredArea(tri), 4.0, 1e-12);
    expectValidCdt(tri);
  }
}

TEST(Triangulator, ReplaceConstraintMovesTheBoundary) {
  // A square whose bottom edge is refined outward into a bulge: the domain grows.
  Triangulator tri;
  ASSERT_NO_FATAL_FAILURE(constrainedUnitSquare(tri));
  std::vector<Point2> interior = {{0, 0}, {0.5, -0.9}, {-0.5, -0.9}};
  std::vector<VertexId> ids(interior.size());
  tri.insertPoints(interior.data(), interior.size(), ids.data());
  const std::vector<Point2> bulge = {{-0.5, -1.5}, {0.0, -1.7}, {0.5, -1.5}};
  std::vector<VertexId> bulgeIds(bulge.size());
  ASSERT_TRUE(tri.replaceConstraint(0, 1, bulge.data(), bulge.size(), bulgeIds.data()).ok());
  tri.markDomain(DomainRule::kLoopOrientation);
  expectValidCdt(tri);
  // Area of the square plus the polygon (-1,-1) (-0.5,-1.5) (0,-1.7) (0.5,-1.5) (1,-1).
  const double bulgeArea = 0.5 * 0.5 * 0.5 * 2 + 0.5 * (0.5 + 0.7) * 0.5 * 2;
  EXPECT_NEAR(coveredArea(tri), 4.0 + bulgeArea, 1e-12);
  const EdgeRef old = tri.mesh().findEdge(0, 1);
  EXPECT_TRUE(old.t == kNoTriangle || !tri.mesh().isConstrained(old.t, old.i)) << "the replaced edge is no constraint";
  expectSegmentsPresent(tri, {{0, bulgeIds[0]}, {bulgeIds[0], bulgeIds[1]}, {bulgeIds[1], bulgeIds[2]}, {bulgeIds[2], 1}});
}

TEST(Triangulator, RandomSegmentsNeverCorruptTheMesh) {
  // Random segments, some crossing: every accepted one is present, rejected ones leave a valid CDT.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int round = 0; round < 20; ++round) {
    std::vector<Point2> p(200);
    for (auto& q : p) q = {std::floor(u(rng) * 64) / 8, std::floor(u(rng) * 64) / 8};  // many collinear
    Triangulator tri;
    tri.addVertices(p.data(), p.size());
    ASSERT_TRUE(tri.insertPending());
    std::vector<std::array<std::uint32_t, 2>> accepted;
    std::uniform_int_distribution<std::uint32_t> pick(0, 199);
    for (int s = 0; s < 40; ++s) {
      const std::array<std::uint32_t, 2> seg = {pick(rng), pick(rng)};
      const Status st = tri.insertSegment(seg[0], seg[1]);
      if (st.ok()) accepted.push_back(seg);
      ASSERT_EQ(checkTopology(tri.mesh()), "") << "round " << round << " segment " << s;
    }
    tri.markDomain(DomainRule::kHullAndHolePoints);
    expectValidCdt(tri);
    expectSegmentsPresent(tri, accepted);
  }
}

TEST(Triangulator, FlipEdgeTakesTheOtherDiagonalWhereTheQuadIsConvexAndInsertionGoesOn) {
  // A refiner may flip an edge against the in-circle test (for the triangles' facing on a surface):
  // only unconstrained edges between finite triangles whose quadrilateral is strictly convex, and
  // later insertions still make a valid constrained triangulation of the same domain.
  Triangulator tri;
  ASSERT_NO_FATAL_FAILURE(constrainedUnitSquare(tri));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.999, 0.999);
  std::vector<Point2> batch(300);
  for (auto& q : batch) q = {u(rng), u(rng)};
  std::vector<VertexId> ids(batch.size());
  tri.insertPoints(batch.data(), batch.size(), ids.data());
  const CetMesh& m = tri.mesh();
  int flipped = 0, refusedConstrained = 0, refusedConcave = 0;
  for (TriangleId t = 0; t < m.triangleCount(); ++t) {
    if (m.isGhost(t) || m.isOutside(t)) continue;
    const int i = static_cast<int>(t % 3);
    const EdgeRef across = m.twin(EdgeRef{t, i});
    const bool constrained = m.isConstrained(t, i);
    const Point2 pa = m.point(m.vertex(t, i)), pb = m.point(m.vertex(t, next3(i))), pc = m.point(m.vertex(t, prev3(i)));
    const bool convex = !constrained && !m.isGhost(across.t) &&
                        orient2d(pa, pb, m.point(m.vertex(across.t, across.i))) > 0 &&
                        orient2d(pa, m.point(m.vertex(across.t, across.i)), pc) > 0;
    const VertexId a = m.vertex(t, i), d = constrained ? kNoVertex : m.vertex(across.t, across.i);
    const bool done = tri.flipEdge(t, i);
    EXPECT_EQ(done, convex) << "triangle " << t << " edge " << i;
    refusedConstrained += constrained;
    refusedConcave += !constrained && !convex;
    if (!done) continue;
    ++flipped;
    EXPECT_NE(m.findEdge(a, d).t, kNoTriangle) << "the new diagonal joins the two opposite corners";
    ASSERT_EQ(checkTopology(m), "") << "after flipping triangle " << t << " edge " << i;
  }
  EXPECT_GT(flipped, 100);
  EXPECT_GT(refusedConstrained, 0);
  EXPECT_GT(refusedConcave, 0);
  EXPECT_NE(checkDelaunay(m), "") << "the flips break the in-circle test somewhere";
  EXPECT_NEAR(coveredArea(tri), 4.0, 1e-12);
  for (auto& q : batch) q = {u(rng), u(rng)};
  tri.insertPoints(batch.data(), batch.size(), ids.data());
  EXPECT_EQ(checkTopology(m), "");
  EXPECT_NEAR(coveredArea(tri), 4.0, 1e-12);
  expectSegmentsPresent(tri, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
}

}  // namespace
}  // namespace cet
