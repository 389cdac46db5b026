#include "engine/ring_allocator.h"

#include <algorithm>
#include <cassert>

namespace cetview::engine {

std::optional<std::uint64_t> RingAllocator::allocate(std::uint64_t size, std::uint64_t alignment) {
  assert(alignment > 0 && (alignment & (alignment - 1)) == 0);
  assert(capacity_ % alignment == 0);
  if (size == 0 || size > capacity_) return std::nullopt;
  std::uint64_t position = (head_ + alignment - 1) & ~(alignment - 1);
  if (position % capacity_ + size > capacity_) position += capacity_ - position % capacity_;
  if (position + size - tail_ > capacity_) return std::nullopt;
  head_ = position + size;
  return position % capacity_;
}

void RingAllocator::release(std::uint64_t mark) {
  assert(mark <= head_);
  tail_ = std::max(tail_, mark);
}

}  // namespace cetview::engine
