// Insertion order from a kd-tree kept as a permutation (Yang & Choi 2010, section 3): no nodes are
// stored. For every range [lo, hi) of the recursion the median point along the range's longer axis
// sits at lo + (hi - lo) / 2, with the points before it on its lower side. Visiting the ranges
// breadth-first inserts coarse-to-fine over the whole domain, and each point's parent (the median of
// the enclosing range) is already inserted and nearby: its triangle is where the point's walk starts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "types.h"

namespace cet {

// Rearranges ids[0, n) (indices into points) into the kd permutation. O(n log n), in place.
void kdPermutation(const Point2* points, std::uint32_t* ids, std::size_t n);

struct KdRange {
  std::uint32_t lo, hi;
  std::uint32_t parent;  // id of the parent median, or UINT32_MAX for the root
};

// Calls visit(id, parentId) for every id of a kd permutation in breadth-first order of its tree
// (parentId is UINT32_MAX for the root). `queue` is scratch storage, reused between calls.
template <class Visit>
void forEachBreadthFirst(const std::uint32_t* ids, std::size_t n, std::vector<KdRange>& queue, Visit&& visit) {
  queue.clear();
  if (n == 0) return;
  queue.push_back(KdRange{0, static_cast<std::uint32_t>(n), UINT32_MAX});
  std::size_t head = 0;
  while (head < queue.size()) {
    const KdRange r = queue[head++];
    const std::uint32_t mid = r.lo + (r.hi - r.lo) / 2;
    visit(ids[mid], r.parent);
    if (mid > r.lo) queue.push_back(KdRange{r.lo, mid, ids[mid]});
    if (mid + 1 < r.hi) queue.push_back(KdRange{mid + 1, r.hi, ids[mid]});
    // Drop the consumed front now and then so the queue holds about one tree level, not all ranges.
    if (head > 4096 && head * 2 > queue.size()) {
      queue.erase(queue.begin(), queue.begin() + static_cast<std::ptrdiff_t>(head));
      head = 0;
    }
  }
}

}  // namespace cet
