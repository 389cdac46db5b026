// The render pass and the pipelines every target (window or offscreen) draws with: background
// gradient, shaded faces (two-sided, and culled for closed solids), wireframe (triangle edges) and
// B-rep edge lines. They share one pipeline layout: descriptor set 0 (globals, face colours) and
// DrawConstants push constants.
#pragma once

#include <vulkan/vulkan.h>

#include "engine/context.h"
#include "engine/result.h"

namespace cetview::engine {

// What the render pass writes. With samples > 1 the multisampled colour attachment is resolved
// into the output image; with 1 the output image is the colour attachment.
struct TargetFormat {
  VkFormat color = VK_FORMAT_UNDEFINED;  // the output image's format (swapchain or offscreen)
  VkFormat depth = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkImageLayout finalLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // PRESENT_SRC_KHR or TRANSFER_SRC_OPTIMAL
};

struct Pipelines {
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline background = VK_NULL_HANDLE;
  VkPipeline shaded = VK_NULL_HANDLE;        // two-sided
  VkPipeline shadedCulled = VK_NULL_HANDLE;  // back faces culled: closed solids only
  VkPipeline wireframe = VK_NULL_HANDLE;     // VK_NULL_HANDLE without DeviceFeatures::fillModeNonSolid
  VkPipeline edges = VK_NULL_HANDLE;
  bool colorPushed = false;  // the face pipelines use the *_pushed shaders
};

// `colorPushed`: the face pipelines take the face colour from DrawConstants::color alone, with
// shaders that have no colour varying (for GpuScene's one-by-one draws, see shaders/mesh.vert).
// Errors: kVulkan, kOutOfMemory.
Result<Pipelines> createPipelines(const Device& device, const TargetFormat& format, bool colorPushed);
// For a new target format: a new render pass and pipelines; the descriptor set layout and the
// pipeline layout stay, so descriptor sets allocated with them stay valid and updatable.
Status recreatePipelines(const Device& device, const TargetFormat& format, Pipelines& pipelines);
void destroyPipelines(const Device& device, Pipelines& pipelines);

// Depth formats in order of preference that the device can attach: D32, D24S8, D16.
Result<VkFormat> chooseDepthFormat(const Device& device);
// The largest supported count <= `requested` (rounded down to a power of two) for colour and depth.
VkSampleCountFlagBits chooseSampleCount(const Device& device, std::uint32_t requested);
// True for *_SRGB formats: the hardware encodes; otherwise shaders must (CETVIEW_SPEC_ENCODE_SRGB).
bool isSrgbFormat(VkFormat format);
// Whether targets (window and offscreen) drawn with `samples` should be *_SRGB formats: on GPUs,
// where encoding is free, and with MSAA, whose resolve must average linear values. Not on CPU
// devices without MSAA (their default): llvmpipe's sRGB store cost lavapipe about 6% of a
// 1M-triangle frame, more than the shaders' own encoding into a UNORM target (toTarget() in
// shaders/common.glsl).
bool preferSrgbTarget(const Device& device, VkSampleCountFlagBits samples);

}  // namespace cetview::engine
