// What the refinement measured on a triangle, kept per triangle id of the face's triangulator. A
// triangle is evaluated once in its life: later passes and later levels find its record as long as
// the triangle at that id still has the same corners (an operator that changes a triangle changes
// its corners, and the record no longer matches). The samples on each edge are kept too: the
// neighbour across the edge, evaluated later, takes them instead of projecting the same points again.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "cet/types.h"

namespace cetview::brep {

struct TriangleRecord {
  cet::VertexId v[3] = {cet::kNoVertex, cet::kNoVertex, cet::kNoVertex};  // corners when evaluated
  float deviation = 0;  // largest sampled distance to the surface
  float normalCos = 1;  // cosine of the largest angle between corner normals
  float longest = 0;    // longest 3D edge
  float facetCos = 1;   // cosine between the facet normal and its corners' mean surface normal
  // Samples on edge i (opposite corner i): largest projected and corresponding-point distances;
  // negative when the edge was not sampled (a constrained edge, a collapsed triangle).
  float edgeDeviation[3] = {-1, -1, -1};
  float edgeCorresponding[3] = {-1, -1, -1};
  std::uint8_t worstSample = 0;                // 0 centroid, 1 + i the midpoint of edge i (opposite corner i)
  std::uint8_t angleEdge = 0;                  // edge whose ends' normals differ most
  std::uint8_t longestFreeEdge = 3;            // longest unconstrained edge (3: none)
  // kFlipped | kCollapsed | kUnmeasured | kPoleCorner | kInLine | kMeasureChordal | kAcrossFold |
  // kAcrossCrease
  std::uint8_t flags = 0;
  static constexpr std::uint8_t kFlipped = 1;  // no area, or no usable corner normal to compare
  static constexpr std::uint8_t kCollapsed = 2;   // two corners share a 3D point (pole, gap): dropped
  static constexpr std::uint8_t kUnmeasured = 4;  // the angle split it: no chordal samples taken
  static constexpr std::uint8_t kPoleCorner = 8;  // a corner without a first-derivative normal (pole, apex)
  static constexpr std::uint8_t kInLine = 16;     // flipped as corners in line through a pole (its facet is noise)
  static constexpr std::uint8_t kMeasureChordal =
      32;  // unmeasured, but its angle split was dropped: measure it
  // A free edge between regular corners crosses a fold of the parametrisation (FaceMesher::foldPoint).
  static constexpr std::uint8_t kAcrossFold = 64;
  // A free edge between regular corners crosses a bend of the surface (SurfaceEval::bendBetween) and
  // its ends' normals differ by more than the angle: the triangle bridges it (FaceMesher::creasePoint).
  static constexpr std::uint8_t kAcrossCrease = 128;

  bool matches(cet::VertexId a, cet::VertexId b, cet::VertexId c) const {
    return v[0] == a && v[1] == b && v[2] == c;
  }
};

// The regularity rule of a level: a triangle whose corner normals differ by more than the angle is
// split, unless it is already smaller than the level's minimum size.
struct AngleSplit {
  float minCos = -1;  // cosine of the angle tolerance
  float minSize = 0;
  bool splits(const TriangleRecord& r) const { return r.normalCos < minCos && r.longest > minSize; }
};

// Records in blocks that never move: growing the store touches each new record's memory once,
// where a vector copied every record into fresh memory at each growth and held both copies
// meanwhile (on occ/terrain.brep, 41% of the export's page faults were its growth). The first
// blocks ramp up from kFirst records (64, 64, 128, 256, 512: ids 0-1023), then every block holds
// kBlock: most faces have a few dozen triangles, and a first block of kBlock (56 KB, every record
// written when made) cost each of them 14 page faults, on these virtual machines about 0.14 ms.
class TriangleRecords {
 public:
  // The record of triangle t if it was evaluated with corners (a, b, c) in this order, else null.
  const TriangleRecord* find(cet::TriangleId t, cet::VertexId a, cet::VertexId b, cet::VertexId c) const {
    if (t >= capacity_) return nullptr;
    const TriangleRecord& r = record(t);
    return r.matches(a, b, c) ? &r : nullptr;
  }
  // Makes room for triangle ids below `triangles`, so that at() on them moves nothing (threads
  // may then fill distinct records at once).
  void reserve(std::size_t triangles) {
    while (capacity_ < triangles) {
      const std::size_t size = blockSize(blocks_.size());
      blocks_.push_back(std::make_unique<TriangleRecord[]>(size));
      capacity_ += size;
    }
  }
  TriangleRecord& at(cet::TriangleId t) { return const_cast<TriangleRecord&>(record(t)); }
  void clear() {
    std::vector<std::unique_ptr<TriangleRecord[]>>().swap(blocks_);
    capacity_ = 0;
  }
  std::size_t capacity() const { return capacity_; }

 private:
  static constexpr unsigned kFirstShift = 6, kBlockShift = 10;
  static constexpr std::size_t kFirst = std::size_t{1} << kFirstShift;       // 3.5 KB
  static constexpr std::size_t kBlock = std::size_t{1} << kBlockShift;       // 56 KB
  static constexpr std::size_t kRampBlocks = 1 + kBlockShift - kFirstShift;  // blocks below id kBlock
  static std::size_t blockSize(std::size_t b) {
    if (b == 0) return kFirst;
    return b < kRampBlocks ? std::size_t{1} << (kFirstShift + b - 1) : kBlock;
  }
  const TriangleRecord& record(cet::TriangleId t) const {
    if (t < kFirst) return blocks_[0][t];
    if (t >= kBlock) return blocks_[kRampBlocks - 1 + t / kBlock][t % kBlock];
    // Ids [2^h, 2^(h+1)) of the ramp share block h - kFirstShift + 1.
    unsigned h = kFirstShift;
    while ((t >> (h + 1)) != 0) ++h;
    return blocks_[h - kFirstShift + 1][t - (cet::TriangleId{1} << h)];
  }
  std::size_t capacity_ = 0;
  std::vector<std::unique_ptr<TriangleRecord[]>> blocks_;
};

}  // namespace cetview::brep
