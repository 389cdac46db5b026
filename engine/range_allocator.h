// Sub-ranges of a growable array (in elements): each face's index slot in the index buffer, each
// edge's slot in the edge buffer. Best fit over a free list that coalesces neighbours; O(log n) per
// call. Pure bookkeeping (no Vulkan), unit-tested alone.
#pragma once

#include <cstdint>
#include <map>
#include <optional>

namespace cetview::engine {

class RangeAllocator {
 public:
  explicit RangeAllocator(std::uint64_t capacity = 0) { grow(capacity); }

  // Start of `count` (> 0) free elements, or nullopt when no free range is large enough: grow() and
  // try again.
  std::optional<std::uint64_t> allocate(std::uint64_t count);

  // Returns [offset, offset + count), which allocate() gave out, to the free list.
  void free(std::uint64_t offset, std::uint64_t count);

  // Adds [capacity(), newCapacity) to the free list; shrinking is not supported.
  void grow(std::uint64_t newCapacity);

  std::uint64_t capacity() const { return capacity_; }
  std::uint64_t freeCount() const { return free_; }
  std::uint64_t largestFree() const { return bySize_.empty() ? 0 : bySize_.rbegin()->first; }
  std::uint64_t freeRangeCount() const { return byOffset_.size(); }

 private:
  void insertFree(std::uint64_t offset, std::uint64_t count);
  void eraseFree(std::map<std::uint64_t, std::uint64_t>::iterator it);

  std::uint64_t capacity_ = 0;
  std::uint64_t free_ = 0;
  std::map<std::uint64_t, std::uint64_t> byOffset_;     // free ranges: offset -> count
  std::multimap<std::uint64_t, std::uint64_t> bySize_;  // the same ranges: count -> offset
};

}  // namespace cetview::engine
