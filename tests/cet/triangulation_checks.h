// Shared checks for triangulator tests: validity, Delaunay, constraints present, covered area.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "cet/topology_check.h"
#include "cet/triangulator.h"

namespace cet::testing {

inline double signedArea2(Point2 a, Point2 b, Point2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Sum of the inside triangles' areas (plain doubles: a measurement, not a decision).
inline double coveredArea(const Triangulator& tri) {
  std::vector<VertexId> idx;
  tri.collectTriangles(idx);
  double area = 0;
  for (std::size_t k = 0; k < idx.size(); k += 3) {
    area += 0.5 * signedArea2(tri.point(idx[k]), tri.point(idx[k + 1]), tri.point(idx[k + 2]));
  }
  return area;
}

// Topology and the exact Delaunay test on every unconstrained edge.
inline void expectValidCdt(const Triangulator& tri) {
  EXPECT_EQ(checkTopology(tri.mesh()), "");
  EXPECT_EQ(checkDelaunay(tri.mesh()), "");
}

// Every segment is a chain of constraint edges (split only at vertices lying exactly on it).
inline void expectSegmentsPresent(const Triangulator& tri, const std::vector<std::array<std::uint32_t, 2>>& segments) {
  const CetMesh& m = tri.mesh();
  for (const auto& s : segments) {
    VertexId a = tri.representative(s[0]);
    const VertexId b = tri.representative(s[1]);
    int guard = 0;
    while (a != b && guard++ < 1000000) {
      // The next vertex along a -> b: a neighbour of a joined by a constraint edge, collinear and
      // strictly closer to b.
      VertexId next = kNoVertex;
      const TriangleId start = m.incident(a);
      TriangleId t = start;
      do {
        const int k = m.indexOf(t, a);
        const VertexId x = m.vertex(t, next3(k));
        if (x != kInfiniteVertex && m.isConstrained(t, prev3(k))) {
          const Point2 pa = m.point(a), pb = m.point(b), px = m.point(x);
          const bool collinear = signedArea2(pa, pb, px) == 0.0;
          const double along = (px.x - pa.x) * (pb.x - pa.x) + (px.y - pa.y) * (pb.y - pa.y);
          const double toB = (pb.x - pa.x) * (pb.x - pa.x) + (pb.y - pa.y) * (pb.y - pa.y);
          if (x == b || (collinear && along > 0 && along < toB)) {
            if (next == kNoVertex || x == b) next = x;
          }
        }
        t = m.nextAround(t, a);
      } while (t != start);
      ASSERT_NE(next, kNoVertex) << "segment " << s[0] << "-" << s[1] << " is missing after vertex " << a;
      a = next;
    }
  }
}

}  // namespace cet::testing
