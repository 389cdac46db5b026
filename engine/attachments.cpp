#include "engine/attachments.h"

#include "engine/vk_check.h"

namespace cetview::engine {
namespace {

Status createAll(const Device& device, VkRenderPass renderPass, const TargetFormat& format, VkExtent2D extent,
                 const std::vector<VkImageView>& outputs, Attachments& a) {
  a.extent = extent;
  bool msaa = format.samples != VK_SAMPLE_COUNT_1_BIT;
  if (msaa) {
    auto color = createImage(device, extent, format.color,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                             format.samples, VK_IMAGE_ASPECT_COLOR_BIT);
    CETVIEW_TRY(color);
    a.color = *color;
  }
  auto depth =
      createImage(device, extent, format.depth,
                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                  format.samples, VK_IMAGE_ASPECT_DEPTH_BIT);
  CETVIEW_TRY(depth);
  a.depth = *depth;

  for (VkImageView output : outputs) {
    VkImageView views[3] = {msaa ? a.color.view : output, a.depth.view, output};
    auto info = vkInit<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    info.renderPass = renderPass;
    info.attachmentCount = msaa ? 3u : 2u;
    info.pAttachments = views;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    CETVIEW_VK(vkCreateFramebuffer(device.device, &info, nullptr, &framebuffer));
    a.framebuffers.push_back(framebuffer);
  }
  return {};
}

}  // namespace

Result<Attachments> createAttachments(const Device& device, VkRenderPass renderPass,
                                      const TargetFormat& format, VkExtent2D extent,
                                      const std::vector<VkImageView>& outputs) {
  Attachments a;
  Status status = createAll(device, renderPass, format, extent, outputs, a);
  if (!status) {
    destroyAttachments(device, a);
    return status.error();
  }
  return a;
}

void destroyAttachments(const Device& device, Attachments& a) {
  for (VkFramebuffer framebuffer : a.framebuffers) vkDestroyFramebuffer(device.device, framebuffer, nullptr);
  destroyImage(device, a.color);
  destroyImage(device, a.depth);
  a = Attachments{};
}

}  // namespace cetview::engine
