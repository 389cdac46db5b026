// Sequential constrained Delaunay triangulation on the CET arrays (Yang & Choi 2010, section 3).
//
// Use, in this order:
//   1. addVertices()          append points to the vertex array (ids are given in order);
//   2. insertPending()        insert every appended vertex, in kd-tree (permutation) order;
//   3. insertSegment(a, b)    recover constraint edges, a -> b in the direction of their boundary loop;
//   4. markDomain()           flood-fill the outside and the holes (stops at constraint edges);
//   5. insertPoints()         refinement: more points, batch by batch, each batch in its own kd order.
// Every decision about orientation or in-circle goes through the exact predicates (predicates.h).
//
// The full triangulation of the convex hull is kept (with ghost triangles outside the hull); triangles
// outside the domain are only flagged, so ids stay stable and refinement walks can cross holes.
#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "cet_mesh.h"
#include "types.h"

namespace cet {

// How markDomain() decides which triangles are outside.
enum class DomainRule {
  // Triangle's -p: with at least one segment, everything reachable from the convex hull without
  // crossing a segment is outside; with no segment the whole convex hull is kept. Hole points too.
  kHullAndHolePoints,
  // B-rep faces: loops are oriented (outer counter-clockwise, inner clockwise), so the side of a
  // constraint edge whose flag is 2 (edge runs against the loop) is outside. The hull and hole
  // points are outside as well.
  kLoopOrientation,
};

struct Status {
  enum class Code { kOk, kCrossingSegments, kBadVertex, kNoTriangulation };
  Code code = Code::kOk;
  std::string message;  // one line, empty when ok
  // kCrossingSegments: the constraint edge the new segment crosses (its endpoints' vertex ids).
  VertexId crossed[2] = {kInfiniteVertex, kInfiniteVertex};
  bool ok() const { return code == Code::kOk; }
};

// What happened to one point given to insertPoints() / insertPoint().
enum class InsertOutcome : std::uint8_t {
  kInserted,      // a new vertex
  kMerged,        // equal to an existing vertex; its id is returned
  kOnConstraint,  // exactly on a constraint edge: rejected (refinement never splits a boundary)
  kOutside,       // outside the domain (after markDomain) or outside the convex hull: rejected
};

class Triangulator {
 public:
  Triangulator() = default;

  // Reserve room for about this many vertices (triangles follow, about 2 per vertex).
  void reserve(std::size_t vertices);

  // Appends points to the vertex array without inserting them; returns the id of the first one.
  // Ids are consecutive, in the given order. Coordinates must satisfy supportedCoordinate() (types.h).
  VertexId addVertices(const Point2* points, std::size_t count);

  // Inserts every vertex appended since the last call, ordered by a kd-tree permutation (recursive
  // median split); each walk starts from the triangle of the vertex's parent in that tree.
  // A vertex equal to an earlier one is merged into it (see representative()). While all vertices
  // seen so far are collinear there is no triangle; they stay pending and the call returns false.
  // With alreadyKdOrdered, the caller promises the pending vertices are stored as a kd permutation
  // (kdPermutation() of them is the identity), which saves the partitioning.
  // `cancel`, looked at every kCancelStride vertices: once raised, the rest are skipped, the call
  // returns false and cancelled() is true; the triangulation is then incomplete, to be discarded.
  bool insertPending(bool alreadyKdOrdered = false, const std::atomic<bool>* cancel = nullptr);
  bool cancelled() const { return cancelled_; }
  static constexpr std::size_t kCancelStride = 1024;

  // Recovers the segment a -> b as an edge (both already inserted), flags it (1 on the side where
  // the triangle runs the same way, 2 on the other, 3 where both directions were given) and
  // restores the constrained Delaunay property. A segment through an existing vertex is split
  // there. A segment that properly crosses an earlier constraint edge is rejected with
  // kCrossingSegments: no Steiner point is invented; pieces before the crossing stay inserted.
  // A zero-length segment (a and b the same after merging) is ignored.
  Status insertSegment(VertexId a, VertexId b);

  // Boundary refinement between levels: the constraint a -> b (an existing constraint edge) becomes
  // the chain a -> points[0] -> ... -> points[count-1] -> b. The new points are inserted wherever
  // they fall (inside or outside the current domain; they need not lie on the old edge), ids[i]
  // receives each one's vertex id. Call markDomain() again afterwards: the domain changes shape.
  Status replaceConstraint(VertexId a, VertexId b, const Point2* points, std::size_t count, VertexId* ids);

  // Flags triangles outside the domain (see DomainRule); holes[] are points inside holes.
  // May be called again after more segments; refinement keeps the flags.
  void markDomain(DomainRule rule, const Point2* holes = nullptr, std::size_t holeCount = 0);

  // Refinement: inserts points sequentially, ordered by their own kd permutation. For each input i,
  // ids[i] is the vertex id (new or merged) or kNoVertex when rejected, and outcomes[i] (if not
  // null) says why. Only accepted points are appended to the vertex array. hints[i] (if not null)
  // is a triangle at or near points[i] where its walk starts (a refiner knows the triangle it splits).
  void insertPoints(const Point2* points, std::size_t count, VertexId* ids, InsertOutcome* outcomes = nullptr,
                    const TriangleId* hints = nullptr);

  // One point, walking from `hint` (any triangle, or kNoTriangle for the last one touched).
  InsertOutcome insertPoint(Point2 p, VertexId* id, TriangleId hint = kNoTriangle);

  // Replaces the diagonal of the quadrilateral that t and its neighbour across edge i form, where
  // that edge is unconstrained, neither triangle is a ghost and the quadrilateral is strictly
  // convex; returns whether it did. Unlike Lawson's flips it asks no in-circle test: the
  // triangulation may stop being Delaunay there, for a refiner that trades that for what the plane
  // does not see (the orientation of the triangles on a surface). Later insertions keep it a valid
  // constrained triangulation. Afterwards t = (a, b, d) and the neighbour = (a, d, c) (CetMesh::flip).
  bool flipEdge(TriangleId t, int i);

  // --- results ---
  bool hasTriangles() const { return !mesh_.empty(); }
  // Vertex ids, three per inside triangle, counter-clockwise, in triangle-array order.
  void collectTriangles(std::vector<VertexId>& indices) const;
  std::size_t insideTriangleCount() const;
  std::size_t vertexCount() const { return mesh_.vertexCount(); }
  Point2 point(VertexId v) const { return mesh_.point(v); }
  // The vertex a merged duplicate was folded into (itself for any other vertex).
  VertexId representative(VertexId v) const;
  std::size_t mergedCount() const { return merged_.size(); }

  const CetMesh& mesh() const { return mesh_; }

 private:
  struct Location;
  Location locate(Point2 p, TriangleId start) const;
  int chooseEdge(int mask) const;
  bool buildFirstTriangle();
  InsertOutcome insertLocated(VertexId v, const Location& loc);
  void legalizeEdges(std::vector<std::pair<VertexId, VertexId>>& stack);
  Status insertSegmentPiece(VertexId a, VertexId b, VertexId* reached);
  void setConstraintFlags(VertexId a, VertexId b);

  CetMesh mesh_;
  VertexId firstPending_ = 0;  // vertices [firstPending_, vertexCount) are not inserted yet
  bool domainMarked_ = false;
  bool cancelled_ = false;        // insertPending() stopped at a raised flag: the triangulation is incomplete
  std::size_t segmentCount_ = 0;  // segments inserted so far (markDomain floods the hull only if > 0)
  TriangleId lastTouched_ = kNoTriangle;
  std::unordered_map<VertexId, VertexId> merged_;
  // Reused scratch arrays (hot paths do not allocate per point).
  std::vector<TriangleId> flipStack_;
  std::vector<VertexId> order_;
  mutable std::uint32_t walkSeed_ = 0x9E3779B9u;
};

}  // namespace cet
