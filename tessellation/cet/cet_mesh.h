// The CET arrays (constraints embedded triangles; Yang & Choi 2010, section 2) and their operators.
//
// Vertex  v = (p, L): p its UV point, L one triangle incident to it.
// Triangle t = (M0 M1 M2, N0 N1 N2, f0 f1 f2):
//
//                 M2
//                 /\    edge 0 = M1 -> M2, across it N0, flag f0
//                /  \   edge 1 = M2 -> M0, across it N1, flag f1
//       N1, f1  /    \  N0, f0
//              /  t   \ edge 2 = M0 -> M1, across it N2, flag f2
//             /        \ (all counter-clockwise)
//           M0 -------- M1
//                N2, f2
//
//   Mi are counter-clockwise. Edge i is the edge opposite Mi: it runs M[i+1] -> M[i+2] (indices mod 3),
//   Ni is the triangle across it and fi its constraint flag:
//     0 not a constraint; 1 constraint running the same way as its boundary loop (M[i+1] -> M[i+2]
//     is the loop's direction); 2 constraint running the other way; 3 both (two loops, or both
//     directions given). Seen from the neighbour the same edge has flag 1 <-> 2 swapped, 0 and 3 kept.
//   The three flags pack into one byte with an `outside` bit (triangle not in the domain).
//
// There is no edge array: an edge is (triangle, local index). These operators are the only code that
// reads or writes the arrays. Ghost triangles (one vertex is kInfiniteVertex) close the triangulation
// outside the convex hull, so every edge has two triangles.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "types.h"

namespace cet {

enum EdgeFlag : std::uint8_t {
  kUnconstrained = 0,
  kAlongLoop = 1,    // constraint, same direction as its loop
  kAgainstLoop = 2,  // constraint, opposite direction
  kBothWays = 3,
};

// The same constraint seen from the other triangle.
inline EdgeFlag twinFlag(EdgeFlag f) {
  return f == kAlongLoop ? kAgainstLoop : f == kAgainstLoop ? kAlongLoop : f;
}

inline constexpr int kNext3[3] = {1, 2, 0};
inline constexpr int kPrev3[3] = {2, 0, 1};
inline int next3(int i) { return kNext3[i]; }
inline int prev3(int i) { return kPrev3[i]; }

// An edge as (triangle, local index of the opposite vertex).
struct EdgeRef {
  TriangleId t = kNoTriangle;
  int i = 0;
};

// The triangles a splitting operator produced; the new vertex is M0 of each and edge 0 of each is
// one of the edges around the old cavity (the ones Lawson's flips must check next).
struct SplitResult {
  TriangleId t[4] = {kNoTriangle, kNoTriangle, kNoTriangle, kNoTriangle};
  int count = 0;
};

class CetMesh {
 public:
  struct Triangle {
    VertexId M[3];
    TriangleId N[3];
    std::uint8_t bits;  // f0 in bits 0-1, f1 in 2-3, f2 in 4-5, bit 6: outside the domain
  };
  static_assert(sizeof(Triangle) == 28, "a triangle is 28 bytes: 3 vertex ids, 3 neighbours, 1 flag byte");

  void reserve(std::size_t vertices, std::size_t triangles);

  // ---- Retrieval ----
  std::size_t vertexCount() const { return points_.size(); }
  std::size_t triangleCount() const { return triangles_.size(); }  // including ghosts and outside ones
  bool empty() const { return triangles_.empty(); }
  Point2 point(VertexId v) const { return points_[v]; }
  const Point2* points() const { return points_.data(); }
  TriangleId incident(VertexId v) const { return L_[v]; }  // L; kNoTriangle if not inserted
  VertexId vertex(TriangleId t, int i) const { return triangles_[t].M[i]; }
  TriangleId neighbor(TriangleId t, int i) const { return triangles_[t].N[i]; }
  EdgeFlag flag(TriangleId t, int i) const {
    return static_cast<EdgeFlag>((triangles_[t].bits >> (2 * i)) & 3u);
  }
  bool isConstrained(TriangleId t, int i) const { return flag(t, i) != kUnconstrained; }
  bool isOutside(TriangleId t) const { return (triangles_[t].bits & kOutsideBit) != 0; }
  // Local index (0..2) of the infinite vertex, or -1 for a finite triangle.
  int ghostIndex(TriangleId t) const { return indexOf(t, kInfiniteVertex); }
  bool isGhost(TriangleId t) const { return ghostIndex(t) >= 0; }
  // Local index of v in t, or -1.
  int indexOf(TriangleId t, VertexId v) const { return slotOrNone(triangles_[t].M, v); }
  // Local index of the edge of t shared with neighbour n, or -1.
  int edgeTo(TriangleId t, TriangleId n) const { return slotOrNone(triangles_[t].N, n); }
  // The same edge seen from the neighbouring triangle.
  EdgeRef twin(EdgeRef e) const;
  // Edge e's endpoints in t's counter-clockwise direction.
  VertexId edgeOrigin(EdgeRef e) const { return vertex(e.t, next3(e.i)); }
  VertexId edgeDestination(EdgeRef e) const { return vertex(e.t, prev3(e.i)); }
  // Traversal around a vertex: the triangle that follows t counter-clockwise (resp. clockwise) around
  // v, sharing an edge incident to v. v must be a vertex of t.
  TriangleId nextAround(TriangleId t, VertexId v) const;
  TriangleId prevAround(TriangleId t, VertexId v) const;
  // The edge from a to b, as the triangle in which it runs a -> b counter-clockwise; found by
  // turning around a and b at once. kNoTriangle if a and b are not adjacent.
  EdgeRef findEdge(VertexId a, VertexId b) const;

  // ---- Modification ----
  VertexId addVertex(Point2 p);
  TriangleId addTriangle(VertexId a, VertexId b, VertexId c);  // counter-clockwise, no neighbours yet
  void link(TriangleId t, int i, TriangleId u, int j);         // make (t, i) and (u, j) neighbours
  void setIncident(VertexId v, TriangleId t) { L_[v] = t; }
  // Sets the flag of edge (t, i) and the twin flag on the neighbour's side.
  void setFlag(TriangleId t, int i, EdgeFlag f);
  void setOutside(TriangleId t, bool outside);
  // Replaces the diagonal of the quadrilateral formed by t and its neighbour across edge i. With
  // t = (a, b, c), a = M[i], and d opposite in the neighbour, afterwards t = (a, b, d) and the
  // neighbour = (a, d, c): a is M0 of both, and edge 0 of each is an old outer edge. The quad must be
  // strictly convex and edge i unconstrained. Flags and outside bits travel with their edges.
  void flip(TriangleId t, int i);
  // The same when the caller already knows the neighbour's local index j of the shared edge.
  void flip(TriangleId t, int i, int j);
  // Splits t by vertex v strictly inside it into three triangles (t is reused).
  SplitResult splitTriangle(TriangleId t, VertexId v);
  // Splits edge i of t (and the neighbour's side) by vertex v strictly inside the edge into four
  // triangles. Each half of a constraint keeps its flag.
  SplitResult splitEdge(TriangleId t, int i, VertexId v);

  // Memory held by the two arrays (capacity, not size): for benchmarks.
  std::size_t bytesVertices() const;
  std::size_t bytesTriangles() const;

 private:
  static constexpr std::uint8_t kOutsideBit = 1u << 6;
  // Which of the three slots holds x, which must be there exactly once. Computed without branches:
  // the slot is as good as random, so a chain of comparisons mispredicts about once per call, and
  // the hot paths (splits, flips, the Lawson loop) make several such lookups per inserted point.
  static int slotOf(const std::uint32_t (&slots)[3], std::uint32_t x) {
    assert(!(slots[1] == x && slots[2] == x));
    return static_cast<int>(slots[1] == x) | (static_cast<int>(slots[2] == x) << 1);
  }
  static int slotOrNone(const std::uint32_t (&slots)[3], std::uint32_t x) {
    const int k = slotOf(slots, x);
    return slots[k] == x ? k : -1;
  }
  void setFlagOneSide(TriangleId t, int i, EdgeFlag f);
  void replaceNeighbor(TriangleId t, TriangleId from, TriangleId to) {
    TriangleId(&n)[3] = triangles_[t].N;
    const int k = slotOf(n, from);
    assert(n[k] == from);
    n[k] = to;
  }
  void touchVertices(TriangleId t);  // points each finite vertex's L at t

  std::vector<Point2> points_;      // p of each vertex
  std::vector<TriangleId> L_;       // L of each vertex
  std::vector<Triangle> triangles_;
};

}  // namespace cet
