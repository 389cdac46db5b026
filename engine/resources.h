// Buffers and images with their own memory (niagara's resources.h shape: plain structs, free
// create/destroy functions). One allocation per resource: the engine holds few, large resources
// (growable geometry buffers, the upload ring, attachments), far below maxMemoryAllocationCount.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "engine/context.h"
#include "engine/result.h"

namespace cetview::engine {

enum class MemoryUse {
  kDeviceLocal,  // GPU-only: geometry, tables, attachments
  kUpload,       // host-visible and coherent, persistently mapped: the upload ring, per-frame uniforms
  kReadback,     // host-visible, cached when the device offers it, persistently mapped: captures
};

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;  // non-null for kUpload and kReadback
  bool coherent = true;    // false: call invalidateForHost() before reading `mapped`
};

// Errors: kOutOfMemory, kUnsupported (no memory type fits), kVulkan.
Result<Buffer> createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);
void destroyBuffer(const Device& device, Buffer& buffer);

// Makes device writes visible to the host for non-coherent readback memory (no-op when coherent).
Status invalidateForHost(const Device& device, const Buffer& buffer);

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{0, 0};
};

// A 2D single-mip image with a view. Transient attachments (TRANSIENT_ATTACHMENT usage) prefer
// lazily allocated memory, which tilers never back with real memory.
Result<Image> createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                          VkSampleCountFlagBits samples, VkImageAspectFlags aspect);
void destroyImage(const Device& device, Image& image);

Result<VkShaderModule> createShaderModule(const Device& device, const std::uint32_t* words,
                                          std::size_t sizeBytes);

// One global memory barrier (the engine's uploads touch whole buffers, so per-buffer barriers buy
// nothing on any device it targets).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);

}  // namespace cetview::engine
