#include "engine/range_allocator.h"

#include <cassert>
#include <iterator>

namespace cetview::engine {

void RangeAllocator::insertFree(std::uint64_t offset, std::uint64_t count) {
  byOffset_.emplace(offset, count);
  bySize_.emplace(count, offset);
  free_ += count;
}

void RangeAllocator::eraseFree(std::map<std::uint64_t, std::uint64_t>::iterator it) {
  auto range = bySize_.equal_range(it->second);
  for (auto s = range.first; s != range.second; ++s) {
    if (s->second == it->first) {
      bySize_.erase(s);
      break;
    }
  }
  free_ -= it->second;
  byOffset_.erase(it);
}

std::optional<std::uint64_t> RangeAllocator::allocate(std::uint64_t count) {
  assert(count > 0);
  auto best = bySize_.lower_bound(count);
  if (best == bySize_.end()) return std::nullopt;
  std::uint64_t offset = best->second;
  std::uint64_t size = best->first;
  eraseFree(byOffset_.find(offset));
  if (size > count) insertFree(offset + count, size - count);
  return offset;
}

void RangeAllocator::free(std::uint64_t offset, std::uint64_t count) {
  if (count == 0) return;
  assert(offset + count <= capacity_);
  auto next = byOffset_.lower_bound(offset);
  assert(next == byOffset_.end() || next->first >= offset + count);  // not already free
  if (next != byOffset_.end() && next->first == offset + count) {
    count += next->second;
    auto after = std::next(next);
    eraseFree(next);
    next = after;
  }
  if (next != byOffset_.begin()) {
    auto prev = std::prev(next);
    assert(prev->first + prev->second <= offset);  // not already free
    if (prev->first + prev->second == offset) {
      offset = prev->first;
      count += prev->second;
      eraseFree(prev);
    }
  }
  insertFree(offset, count);
}

void RangeAllocator::grow(std::uint64_t newCapacity) {
  assert(newCapacity >= capacity_);
  if (newCapacity == capacity_) return;
  std::uint64_t old = capacity_;
  capacity_ = newCapacity;
  free(old, newCapacity - old);
}

}  // namespace cetview::engine
