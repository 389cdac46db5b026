// The upload ring: one persistently mapped, host-visible buffer that every host-to-device copy goes
// through. Each frame's blocks are released when that frame's fence has signalled (the Renderer
// passes RingAllocator marks around), so the CPU never overwrites bytes a copy still reads.
#pragma once

#include <cstdint>
#include <optional>

#include "engine/context.h"
#include "engine/resources.h"
#include "engine/ring_allocator.h"

namespace cetview::engine {

class UploadRing {
 public:
  // Alignment of every block: enough for any copy and for uint32/float data.
  static constexpr std::uint64_t kAlignment = 16;

  // Errors: as createBuffer(). `capacity` is rounded up to kAlignment.
  static Result<UploadRing> create(const Device& device, std::uint64_t capacity);
  void destroy(const Device& device);

  // Copies `size` bytes into the ring; their offset in buffer(), or nullopt when the ring is full.
  std::optional<std::uint64_t> push(const void* data, std::uint64_t size);
  // Room for `size` bytes to be written through data(offset); nullopt when the ring is full.
  std::optional<std::uint64_t> allocate(std::uint64_t size) { return allocator_.allocate(size, kAlignment); }
  void* data(std::uint64_t offset) { return static_cast<std::uint8_t*>(buffer_.mapped) + offset; }

  std::uint64_t mark() const { return allocator_.mark(); }
  void release(std::uint64_t mark) { allocator_.release(mark); }
  VkBuffer buffer() const { return buffer_.buffer; }
  std::uint64_t capacity() const { return allocator_.capacity(); }

 private:
  Buffer buffer_;
  RingAllocator allocator_;
};

}  // namespace cetview::engine
