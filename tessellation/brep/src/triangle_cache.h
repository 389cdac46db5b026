// What the refinement measured on a triangle, keyed by its three vertex ids (order-free). A triangle
// is evaluated once in its life: later passes and later levels look the result up. Open addressing
// with linear probing; no per-entry allocation.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cetview::brep {

struct TriangleRecord {
  std::uint32_t a = UINT32_MAX, b = 0, c = 0;  // sorted vertex ids; a == UINT32_MAX marks an empty slot
  float deviation = 0;   // largest sampled distance to the surface
  float normalAngle = 0; // largest angle between corner normals (radians)
  float longest = 0;     // longest 3D edge
  float facetCos = 1;    // cosine between the facet normal and its corners' mean surface normal
  std::uint8_t worstSample = 0;  // 0 centroid, 1 + i the midpoint of edge i (opposite corner i)
  std::uint8_t angleEdge = 0;    // edge whose ends' normals differ most
  std::uint8_t longestFreeEdge = 3;  // longest unconstrained edge (3: none)
  std::uint8_t flags = 0;        // kFlipped | kCollapsed
  static constexpr std::uint8_t kFlipped = 1;    // no area, or no usable corner normal to compare
  static constexpr std::uint8_t kCollapsed = 2;  // two corners share a 3D point (pole, gap): dropped
  static constexpr std::uint8_t kStuck = 4;      // no safe split point (see FaceMesher::safeSplit)
};

class TriangleCache {
 public:
  // The record for (a, b, c), or null.
  const TriangleRecord* find(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    if (slots_.empty()) return nullptr;
    sort3(a, b, c);
    for (std::size_t i = hash(a, b, c) & mask_;; i = (i + 1) & mask_) {
      const TriangleRecord& r = slots_[i];
      if (r.a == UINT32_MAX) return nullptr;
      if (r.a == a && r.b == b && r.c == c) return &r;
    }
  }

  void insert(TriangleRecord record) {
    if ((size_ + 1) * 2 > slots_.size()) grow();
    sort3(record.a, record.b, record.c);
    for (std::size_t i = hash(record.a, record.b, record.c) & mask_;; i = (i + 1) & mask_) {
      TriangleRecord& r = slots_[i];
      if (r.a == UINT32_MAX) {
        r = record;
        ++size_;
        return;
      }
      if (r.a == record.a && r.b == record.b && r.c == record.c) {
        r = record;
        return;
      }
    }
  }

  void clear() {
    slots_.clear();
    size_ = 0;
    mask_ = 0;
  }
  std::size_t size() const { return size_; }

 private:
  static void sort3(std::uint32_t& a, std::uint32_t& b, std::uint32_t& c) {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
  }
  static std::size_t hash(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint64_t h = a * 0x9E3779B97F4A7C15ull;
    h ^= (b + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
    h ^= (c + 0x85EBCA77C2B2AE63ull) * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
  void grow() {
    std::vector<TriangleRecord> old;
    old.swap(slots_);
    slots_.assign(std::max<std::size_t>(1024, old.size() * 2), TriangleRecord{});
    mask_ = slots_.size() - 1;
    size_ = 0;
    for (const TriangleRecord& r : old)
      if (r.a != UINT32_MAX) insert(r);
  }

  std::vector<TriangleRecord> slots_;
  std::size_t size_ = 0;
  std::size_t mask_ = 0;
};

}  // namespace cetview::brep
