// The CET operators one by one, each followed by the topology validator.
#include "cet/cet_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "cet/topology_check.h"
#include "cet/triangulator.h"

namespace cet {
namespace {

// A unit square split by its diagonal (0, 2), closed by four ghost triangles.
//   3 ---- 2
//   |    / |
//   |  /   |
//   0 ---- 1
struct Square {
  CetMesh m;
  TriangleId lower, upper;  // (0, 1, 2) and (0, 2, 3)
  TriangleId ghost[4];      // outside edges 0-1, 1-2, 2-3, 3-0
  Square() {
    for (Point2 p : {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{0, 1}}) m.addVertex(p);
    lower = m.addTriangle(0, 1, 2);
    upper = m.addTriangle(0, 2, 3);
    m.link(lower, 1, upper, 2);  // edge 2 -> 0 of lower, 0 -> 2 of upper
    // Ghost across the hull edge a -> b (counter-clockwise) is (b, a, inf).
    const VertexId hull[4] = {0, 1, 2, 3};
    for (int k = 0; k < 4; ++k) ghost[k] = m.addTriangle(hull[(k + 1) % 4], hull[k], kInfiniteVertex);
    m.link(lower, 2, ghost[0], 2);  // 0 -> 1
    m.link(lower, 0, ghost[1], 2);  // 1 -> 2
    m.link(upper, 0, ghost[2], 2);  // 2 -> 3
    m.link(upper, 1, ghost[3], 2);  // 3 -> 0
    // Ghost k = (h[k+1], h[k], inf): edge 0 is (h[k], inf), edge 1 is (inf, h[k+1]).
    for (int k = 0; k < 4; ++k) m.link(ghost[k], 1, ghost[(k + 1) % 4], 0);
  }
};

TEST(CetMesh, TriangleIsTwentyEightBytes) { EXPECT_EQ(sizeof(CetMesh::Triangle), 28u); }

TEST(CetMesh, SquareIsValid) {
  Square s;
  EXPECT_EQ(checkTopology(s.m), "");
  EXPECT_TRUE(s.m.isGhost(s.ghost[0]));
  EXPECT_FALSE(s.m.isGhost(s.lower));
  EXPECT_EQ(s.m.ghostIndex(s.ghost[2]), 2);
}

TEST(CetMesh, RetrievalOperators) {
  Square s;
  EXPECT_EQ(s.m.vertex(s.lower, 1), 1u);
  EXPECT_EQ(s.m.neighbor(s.lower, 1), s.upper);
  EXPECT_EQ(s.m.indexOf(s.upper, 3), 2);
  EXPECT_EQ(s.m.indexOf(s.upper, 1), -1);
  EXPECT_EQ(s.m.edgeTo(s.upper, s.lower), 2);
  const EdgeRef tw = s.m.twin(EdgeRef{s.lower, 1});
  EXPECT_EQ(tw.t, s.upper);
  EXPECT_EQ(tw.i, 2);
  EXPECT_EQ(s.m.edgeOrigin(EdgeRef{s.lower, 1}), 2u);
  EXPECT_EQ(s.m.edgeDestination(EdgeRef{s.lower, 1}), 0u);
  const EdgeRef e = s.m.findEdge(2, 0);
  EXPECT_EQ(e.t, s.lower);
  EXPECT_EQ(e.i, 1);
  EXPECT_EQ(s.m.findEdge(1, 3).t, kNoTriangle);
}

// findEdge turns around both ends at once (a segment through a fan looks its crossed edges up
// from the hub's far ends): every ordered pair of vertices of a fan of 64 spokes and of a random
// triangulation gets the directed edge between them, found from either end, or none.
TEST(CetMesh, FindEdgeAnswersEveryOrderedPairFromEitherEnd) {
  for (const bool fan : {true, false}) {
    SCOPED_TRACE(fan ? "fan" : "random");
    std::vector<Point2> points;
    if (fan) {
      points.push_back({0, 0});
      for (int i = 0; i < 64; ++i) points.push_back({std::cos(i * M_PI / 32), std::sin(i * M_PI / 32)});
    } else {
      unsigned state = 12345;
      for (int i = 0; i < 60; ++i) {
        state = state * 1103515245u + 12345u;
        const double x = (state >> 8) % 10007 / 10007.0;
        state = state * 1103515245u + 12345u;
        points.push_back({x, (state >> 8) % 10009 / 10009.0});
      }
    }
    Triangulator tri;
    tri.addVertices(points.data(), points.size());
    ASSERT_TRUE(tri.insertPending());
    const CetMesh& m = tri.mesh();
    // (origin, destination) of every edge between two vertices: a hull edge runs outwards in its
    // ghost triangle.
    std::set<std::pair<VertexId, VertexId>> directed;
    for (TriangleId t = 0; t < m.triangleCount(); ++t) {
      for (int i = 0; i < 3; ++i) {
        const VertexId a = m.edgeOrigin(EdgeRef{t, i}), b = m.edgeDestination(EdgeRef{t, i});
        if (a != kInfiniteVertex && b != kInfiniteVertex) directed.insert({a, b});
      }
    }
    if (fan) {  // the centre's 64 spokes, each way
      EXPECT_EQ(std::count_if(directed.begin(), directed.end(), [](auto e) { return e.first == 0; }), 64);
      EXPECT_EQ(std::count_if(directed.begin(), directed.end(), [](auto e) { return e.second == 0; }), 64);
    }
    const auto n = static_cast<VertexId>(points.size());
    for (VertexId a = 0; a < n; ++a) {
      for (VertexId b = 0; b < n; ++b) {
        if (a == b) continue;
        const EdgeRef e = m.findEdge(a, b);
        if (directed.count({a, b})) {
          ASSERT_NE(e.t, kNoTriangle) << a << " -> " << b;
          EXPECT_EQ(m.edgeOrigin(e), a);
          EXPECT_EQ(m.edgeDestination(e), b);
        } else {
          EXPECT_EQ(e.t, kNoTriangle) << a << " -> " << b;
        }
      }
    }
  }
}

TEST(CetMesh, TraversalAroundVertexVisitsItsStarInOrder) {
  Square s;
  // Around vertex 0: lower, upper, ghost(3-0), ghost(0-1), counter-clockwise, and back.
  std::vector<TriangleId> ccw;
  TriangleId t = s.lower;
  do {
    ccw.push_back(t);
    t = s.m.nextAround(t, 0);
  } while (t != s.lower && ccw.size() < 10);
  ASSERT_EQ(ccw.size(), 4u);
  EXPECT_EQ(ccw[1], s.upper);
  EXPECT_EQ(ccw[2], s.ghost[3]);
  EXPECT_EQ(ccw[3], s.ghost[0]);
  std::vector<TriangleId> cw;
  t = s.lower;
  do {
    cw.push_back(t);
    t = s.m.prevAround(t, 0);
  } while (t != s.lower && cw.size() < 10);
  std::reverse(cw.begin() + 1, cw.end());
  EXPECT_EQ(cw, ccw);
}

TEST(CetMesh, FlipReplacesTheDiagonal) {
  Square s;
  s.m.setFlag(s.lower, 2, kAlongLoop);  // 0 -> 1 is a constraint: the flag must travel with its edge
  s.m.flip(s.lower, 1);                 // diagonal 0-2 becomes 1-3
  EXPECT_EQ(checkTopology(s.m), "");
  EXPECT_EQ(s.m.findEdge(0, 2).t, kNoTriangle);
  const EdgeRef diag = s.m.findEdge(1, 3);
  ASSERT_NE(diag.t, kNoTriangle);
  const EdgeRef bottom = s.m.findEdge(0, 1);
  ASSERT_NE(bottom.t, kNoTriangle);
  EXPECT_EQ(s.m.flag(bottom.t, bottom.i), kAlongLoop);
  const EdgeRef bottomOutside = s.m.findEdge(1, 0);
  EXPECT_EQ(s.m.flag(bottomOutside.t, bottomOutside.i), kAgainstLoop);
  // The flipped triangles keep the vertex opposite the old diagonal as M0.
  EXPECT_EQ(s.m.vertex(s.lower, 0), 1u);
  EXPECT_EQ(s.m.vertex(s.upper, 0), 1u);
}

TEST(CetMesh, SplitTriangleMakesThreeAroundTheNewVertex) {
  Square s;
  s.m.setOutside(s.lower, true);
  s.m.setOutside(s.upper, true);
  const VertexId v = s.m.addVertex({0.75, 0.25});
  const SplitResult r = s.m.splitTriangle(s.lower, v);
  ASSERT_EQ(r.count, 3);
  EXPECT_EQ(checkTopology(s.m), "");
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(s.m.vertex(r.t[k], 0), v);
    EXPECT_TRUE(s.m.isOutside(r.t[k]));  // the outside bit is inherited
  }
  std::set<VertexId> around;
  TriangleId t = s.m.incident(v);
  for (int k = 0; k < 3; ++k, t = s.m.nextAround(t, v)) {
    around.insert(s.m.vertex(t, 1));
    around.insert(s.m.vertex(t, 2));
  }
  EXPECT_EQ(around, (std::set<VertexId>{0, 1, 2}));
}

TEST(CetMesh, SplitEdgeKeepsTheConstraintOnBothHalves) {
  Square s;
  s.m.setFlag(s.lower, 1, kAlongLoop);  // the diagonal 2 -> 0 as a constraint
  const VertexId v = s.m.addVertex({0.5, 0.5});
  const SplitResult r = s.m.splitEdge(s.lower, 1, v);
  ASSERT_EQ(r.count, 4);
  EXPECT_EQ(checkTopology(s.m), "");
  const EdgeRef half1 = s.m.findEdge(2, v), half2 = s.m.findEdge(v, 0);
  ASSERT_NE(half1.t, kNoTriangle);
  ASSERT_NE(half2.t, kNoTriangle);
  EXPECT_EQ(s.m.flag(half1.t, half1.i), kAlongLoop);
  EXPECT_EQ(s.m.flag(half2.t, half2.i), kAlongLoop);
  const EdgeRef back = s.m.findEdge(0, v);
  EXPECT_EQ(s.m.flag(back.t, back.i), kAgainstLoop);
  EXPECT_EQ(s.m.findEdge(0, 2).t, kNoTriangle);
}

TEST(CetMesh, SplitHullEdgeWithGhost) {
  Square s;
  const VertexId v = s.m.addVertex({0.5, 0.0});
  const SplitResult r = s.m.splitEdge(s.lower, 2, v);  // edge 0 -> 1 with the ghost beyond
  ASSERT_EQ(r.count, 4);
  EXPECT_EQ(checkTopology(s.m), "");
  int ghosts = 0;
  for (int k = 0; k < 4; ++k) ghosts += s.m.isGhost(r.t[k]) ? 1 : 0;
  EXPECT_EQ(ghosts, 2);
}

TEST(CetMesh, SetFlagIsTwinConsistentAndBothWaysStaysThree) {
  Square s;
  s.m.setFlag(s.lower, 1, kBothWays);
  EXPECT_EQ(s.m.flag(s.upper, 2), kBothWays);
  s.m.setFlag(s.upper, 2, kAlongLoop);
  EXPECT_EQ(s.m.flag(s.lower, 1), kAgainstLoop);
  EXPECT_EQ(checkTopology(s.m), "");
}

TEST(CetMesh, ValidatorCatchesBrokenArrays) {
  {
    Square s;
    s.m.link(s.lower, 1, s.ghost[0], 0);  // breaks the symmetry of two pairs
    EXPECT_NE(checkTopology(s.m), "");
  }
  {
    CetMesh m;
    for (Point2 p : {Point2{0, 0}, Point2{1, 0}, Point2{0, 1}}) m.addVertex(p);
    m.addTriangle(0, 2, 1);  // clockwise, and without neighbours
    EXPECT_NE(checkTopology(m), "");
  }
}

}  // namespace
}  // namespace cet
