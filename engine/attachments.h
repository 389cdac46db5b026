// The per-extent images a render pass needs besides its output: depth, the multisampled colour
// (with MSAA), and one framebuffer per output image (swapchain images, or the offscreen image).
// Shared by all frames in flight; the render pass's external dependency orders their reuse.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

#include "engine/context.h"
#include "engine/pipelines.h"
#include "engine/resources.h"

namespace cetview::engine {

struct Attachments {
  VkExtent2D extent{0, 0};
  Image color;  // multisampled colour; empty with one sample
  Image depth;
  std::vector<VkFramebuffer> framebuffers;  // one per output view, same order
};

// Errors: as createImage(), kVulkan.
Result<Attachments> createAttachments(const Device& device, VkRenderPass renderPass,
                                      const TargetFormat& format, VkExtent2D extent,
                                      const std::vector<VkImageView>& outputs);
void destroyAttachments(const Device& device, Attachments& attachments);

}  // namespace cetview::engine
