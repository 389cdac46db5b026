#include "engine/upload_ring.h"

#include <cstring>

namespace cetview::engine {

Result<UploadRing> UploadRing::create(const Device& device, std::uint64_t capacity) {
  capacity = (capacity + kAlignment - 1) / kAlignment * kAlignment;
  auto buffer = createBuffer(device, capacity, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::kUpload);
  CETVIEW_TRY(buffer);
  UploadRing ring;
  ring.buffer_ = *buffer;
  ring.allocator_ = RingAllocator(capacity);
  return ring;
}

void UploadRing::destroy(const Device& device) {
  destroyBuffer(device, buffer_);
}

std::optional<std::uint64_t> UploadRing::push(const void* data, std::uint64_t size) {
  auto offset = allocate(size);
  if (offset) std::memcpy(this->data(*offset), data, size);
  return offset;
}

}  // namespace cetview::engine
