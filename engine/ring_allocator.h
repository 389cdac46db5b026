// Offsets in a ring of bytes, handed out in order and released in order by frame marks. Pure
// bookkeeping (no Vulkan), so it is unit-tested alone; UploadRing puts a mapped buffer behind it.
//
//   tail_                 head_
//    |<-- in flight ------>|<------ free ------>|   positions grow without bound;
//                                                   offset = position % capacity
#pragma once

#include <cstdint>
#include <optional>

namespace cetview::engine {

class RingAllocator {
 public:
  // `capacity` must be a multiple of every alignment later passed to allocate().
  explicit RingAllocator(std::uint64_t capacity = 0) : capacity_(capacity) {}

  // Offset in [0, capacity) of `size` contiguous bytes aligned to `alignment` (a power of two), or
  // nullopt when the ring lacks room until older marks are released. A block never wraps: when it
  // does not fit before the end, the rest of the lap is skipped.
  std::optional<std::uint64_t> allocate(std::uint64_t size, std::uint64_t alignment);

  // Position after the latest allocation. Hand it to release() once the GPU work that reads every
  // block allocated so far has finished (the frame's fence).
  std::uint64_t mark() const { return head_; }

  // Everything allocated before `mark` may be reused. Marks must be released in order.
  void release(std::uint64_t mark);

  std::uint64_t capacity() const { return capacity_; }
  std::uint64_t used() const { return head_ - tail_; }

 private:
  std::uint64_t capacity_ = 0;
  std::uint64_t head_ = 0;  // next free position
  std::uint64_t tail_ = 0;  // oldest position still in flight
};

}  // namespace cetview::engine
