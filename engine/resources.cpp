#include "engine/resources.h"

#include "engine/vk_check.h"

namespace cetview::engine {
namespace {

// Index of a memory type allowed by `typeBits` that has `required` flags, preferring one that also
// has `preferred`; UINT32_MAX when none has `required`.
std::uint32_t findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t typeBits,
                             VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  std::uint32_t fallback = UINT32_MAX;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) == 0) continue;
    VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback == UINT32_MAX) fallback = i;
  }
  return fallback;
}

Result<VkDeviceMemory> allocate(const Device& device, const VkMemoryRequirements& req,
                                VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred,
                                VkMemoryPropertyFlags* chosenFlags) {
  std::uint32_t type = findMemoryType(device.memory, req.memoryTypeBits, required, preferred);
  if (type == UINT32_MAX) {
    return makeError(ErrorCode::kUnsupported, "no Vulkan memory type has the properties a resource needs");
  }
  *chosenFlags = device.memory.memoryTypes[type].propertyFlags;
  auto info = vkInit<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  info.allocationSize = req.size;
  info.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  CETVIEW_VK(vkAllocateMemory(device.device, &info, nullptr, &memory));
  return memory;
}

}  // namespace

Result<Buffer> createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                            MemoryUse use) {
  Buffer result;
  result.size = size;
  auto info = vkInit<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  CETVIEW_VK(vkCreateBuffer(device.device, &info, nullptr, &result.buffer));

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device.device, result.buffer, &req);
  VkMemoryPropertyFlags required = 0;
  VkMemoryPropertyFlags preferred = 0;
  switch (use) {
    case MemoryUse::kDeviceLocal:
      preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
      break;
    case MemoryUse::kUpload:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case MemoryUse::kReadback:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
      preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  VkMemoryPropertyFlags flags = 0;
  auto memory = allocate(device, req, required, preferred, &flags);
  if (!memory) {
    destroyBuffer(device, result);
    return memory.error();
  }
  result.memory = *memory;
  result.coherent = (flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
  VkResult r = vkBindBufferMemory(device.device, result.buffer, result.memory, 0);
  if (r == VK_SUCCESS && use != MemoryUse::kDeviceLocal) {
    r = vkMapMemory(device.device, result.memory, 0, VK_WHOLE_SIZE, 0, &result.mapped);
  }
  if (r != VK_SUCCESS) {
    destroyBuffer(device, result);
    return vkError("vkBindBufferMemory/vkMapMemory", r);
  }
  return result;
}

void destroyBuffer(const Device& device, Buffer& buffer) {
  if (buffer.buffer != VK_NULL_HANDLE) vkDestroyBuffer(device.device, buffer.buffer, nullptr);
  if (buffer.memory != VK_NULL_HANDLE) vkFreeMemory(device.device, buffer.memory, nullptr);  // unmaps too
  buffer = Buffer{};
}

Status invalidateForHost(const Device& device, const Buffer& buffer) {
  if (buffer.coherent) return {};
  auto range = vkInit<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
  range.memory = buffer.memory;
  range.offset = 0;
  range.size = VK_WHOLE_SIZE;
  CETVIEW_VK(vkInvalidateMappedMemoryRanges(device.device, 1, &range));
  return {};
}

Result<Image> createImage(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                          VkSampleCountFlagBits samples, VkImageAspectFlags aspect) {
  Image result;
  result.format = format;
  result.extent = extent;
  auto info = vkInit<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  CETVIEW_VK(vkCreateImage(device.device, &info, nullptr, &result.image));

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device.device, result.image, &req);
  bool transient = (usage & VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT) != 0;
  VkMemoryPropertyFlags preferred =
      transient ? VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  VkMemoryPropertyFlags flags = 0;
  auto memory = allocate(device, req, 0, preferred, &flags);
  if (!memory) {
    destroyImage(device, result);
    return memory.error();
  }
  result.memory = *memory;
  VkResult r = vkBindImageMemory(device.device, result.image, result.memory, 0);
  if (r != VK_SUCCESS) {
    destroyImage(device, result);
    return vkError("vkBindImageMemory", r);
  }

  auto view = vkInit<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view.image = result.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {aspect, 0, 1, 0, 1};
  r = vkCreateImageView(device.device, &view, nullptr, &result.view);
  if (r != VK_SUCCESS) {
    destroyImage(device, result);
    return vkError("vkCreateImageView", r);
  }
  return result;
}

void destroyImage(const Device& device, Image& image) {
  if (image.view != VK_NULL_HANDLE) vkDestroyImageView(device.device, image.view, nullptr);
  if (image.image != VK_NULL_HANDLE) vkDestroyImage(device.device, image.image, nullptr);
  if (image.memory != VK_NULL_HANDLE) vkFreeMemory(device.device, image.memory, nullptr);
  image = Image{};
}

Result<VkShaderModule> createShaderModule(const Device& device, const std::uint32_t* words,
                                          std::size_t sizeBytes) {
  auto info = vkInit<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  info.codeSize = sizeBytes;
  info.pCode = words;
  VkShaderModule module = VK_NULL_HANDLE;
  CETVIEW_VK(vkCreateShaderModule(device.device, &info, nullptr, &module));
  return module;
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStages, VkAccessFlags dstAccess) {
  auto barrier = vkInit<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  vkCmdPipelineBarrier(cmd, srcStages, dstStages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace cetview::engine
