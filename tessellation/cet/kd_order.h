// Insertion order from a kd-tree kept as a permutation (Yang & Choi 2010, section 3): no nodes are
// stored. For every range [lo, hi) of the recursion the median point along the range's longer axis
// sits at lo + (hi - lo) / 2, with the points before it on its lower side. Visiting the ranges
// breadth-first inserts coarse-to-fine over the whole domain, and each point's parent (the median of
// the enclosing range) is already inserted and nearby: its triangle is where the point's walk starts.
#pragma once

#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "types.h"

namespace cet {

// Rearranges ids[0, n) (indices into points) into the kd permutation. O(n log n), in place. If
// orderedPoints is given, it receives points[ids[i]] for each i, read from the partitioning's own
// copy (cheaper for the caller than gathering them through ids).
void kdPermutation(const Point2* points, std::uint32_t* ids, std::size_t n, Point2* orderedPoints = nullptr);

struct KdRange {
  std::uint32_t lo, hi;
  std::uint32_t parent;  // id of the parent median, or UINT32_MAX for the root
};

// Calls visit(id, parentId) for every id of a kd permutation, parents before children (parentId is
// UINT32_MAX for the root). The tree is walked breadth-first down to subtrees of about kLocalBlock
// points; those subtrees are then visited one after the other, each breadth-first. The first phase
// spreads points coarse-to-fine over the whole domain; the second keeps consecutive insertions in
// one small region, so the triangles they touch stay in cache. Either phase queues at most about
// n / kLocalBlock or kLocalBlock ranges. `queue` is scratch, reused.
inline constexpr std::uint32_t kLocalBlock = 2048;

template <class Visit>
void forEachBreadthFirst(const std::uint32_t* ids, std::size_t n, std::vector<KdRange>& queue, Visit&& visit) {
  queue.clear();
  if (n == 0) return;
  std::vector<KdRange> blocks;
  const auto run = [&](KdRange root, bool deferSmall) {
    queue.clear();
    queue.push_back(root);
    std::size_t head = 0;
    while (head < queue.size()) {
      const KdRange r = queue[head++];
      if (deferSmall && r.hi - r.lo <= kLocalBlock) {
        blocks.push_back(r);
        continue;
      }
      const std::uint32_t mid = r.lo + (r.hi - r.lo) / 2;
      visit(ids[mid], r.parent);
      if (mid > r.lo) queue.push_back(KdRange{r.lo, mid, ids[mid]});
      if (mid + 1 < r.hi) queue.push_back(KdRange{mid + 1, r.hi, ids[mid]});
    }
  };
  run(KdRange{0, static_cast<std::uint32_t>(n), UINT32_MAX}, n > kLocalBlock);
  // Blocks come out in tree order: neighbouring blocks are neighbouring regions.
  std::sort(blocks.begin(), blocks.end(), [](const KdRange& a, const KdRange& b) { return a.lo < b.lo; });
  for (const KdRange& b : blocks) run(b, false);
}

}  // namespace cet
