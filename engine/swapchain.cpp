#include "engine/swapchain.h"

#include <algorithm>

#include "engine/pipelines.h"
#include "engine/vk_check.h"

namespace cetview::engine {

Result<VkSurfaceFormatKHR> chooseSurfaceFormat(const Device& device, VkSurfaceKHR surface,
                                               VkSampleCountFlagBits samples) {
  std::uint32_t count = 0;
  CETVIEW_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physicalDevice, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  CETVIEW_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physicalDevice, surface, &count, formats.data()));
  if (count == 0) return makeError(ErrorCode::kUnsupported, "the window surface offers no pixel format");
  const bool srgbFirst = preferSrgbTarget(device, samples);
  for (VkFormat wanted : {srgbFirst ? VK_FORMAT_B8G8R8A8_SRGB : VK_FORMAT_B8G8R8A8_UNORM,
                          srgbFirst ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                          srgbFirst ? VK_FORMAT_B8G8R8A8_UNORM : VK_FORMAT_B8G8R8A8_SRGB,
                          srgbFirst ? VK_FORMAT_R8G8B8A8_UNORM : VK_FORMAT_R8G8B8A8_SRGB}) {
    for (const VkSurfaceFormatKHR& f : formats) {
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    }
  }
  return formats[0];
}

Result<VkExtent2D> surfaceExtent(const Device& device, VkSurfaceKHR surface, VkExtent2D framebuffer) {
  VkSurfaceCapabilitiesKHR caps;
  CETVIEW_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device.physicalDevice, surface, &caps));
  if (caps.currentExtent.width != UINT32_MAX) return caps.currentExtent;
  VkExtent2D extent;
  extent.width = std::clamp(framebuffer.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent.height = std::clamp(framebuffer.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  if (framebuffer.width == 0 || framebuffer.height == 0) extent = {0, 0};
  return extent;
}

namespace {

Result<VkPresentModeKHR> choosePresentMode(const Device& device, VkSurfaceKHR surface, bool vsync) {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always supported
  std::uint32_t count = 0;
  CETVIEW_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(device.physicalDevice, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  CETVIEW_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(device.physicalDevice, surface, &count, modes.data()));
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR}) {
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  }
  return VK_PRESENT_MODE_FIFO_KHR;
}

Status createAll(const Device& device, VkSurfaceKHR surface, VkSurfaceFormatKHR format, VkExtent2D extent,
                 bool vsync, VkSwapchainKHR old, Swapchain& s) {
  VkSurfaceCapabilitiesKHR caps;
  CETVIEW_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device.physicalDevice, surface, &caps));
  auto mode = choosePresentMode(device, surface, vsync);
  CETVIEW_TRY(mode);

  // One image more than the minimum, so acquiring never waits on the presentation engine.
  std::uint32_t imageCount = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);
  VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & alpha)) {
    alpha = static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                     -caps.supportedCompositeAlpha);
  }

  auto info = vkInit<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
  info.surface = surface;
  info.minImageCount = imageCount;
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  // Screenshots of the window copy the presented image; surfaces that cannot skip them.
  s.transferSrc = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  if (s.transferSrc) info.imageUsage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                          ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                          : caps.currentTransform;
  info.compositeAlpha = alpha;
  info.presentMode = *mode;
  info.clipped = VK_TRUE;
  info.oldSwapchain = old;
  CETVIEW_VK(vkCreateSwapchainKHR(device.device, &info, nullptr, &s.swapchain));
  s.format = format;
  s.extent = extent;

  std::uint32_t count = 0;
  CETVIEW_VK(vkGetSwapchainImagesKHR(device.device, s.swapchain, &count, nullptr));
  s.images.resize(count);
  CETVIEW_VK(vkGetSwapchainImagesKHR(device.device, s.swapchain, &count, s.images.data()));
  for (VkImage image : s.images) {
    auto view = vkInit<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format.format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView v = VK_NULL_HANDLE;
    CETVIEW_VK(vkCreateImageView(device.device, &view, nullptr, &v));
    s.views.push_back(v);
  }
  return {};
}

}  // namespace

Result<Swapchain> createSwapchain(const Device& device, VkSurfaceKHR surface, VkSurfaceFormatKHR format,
                                  VkExtent2D extent, bool vsync, VkSwapchainKHR old) {
  if (extent.width == 0 || extent.height == 0) {
    return makeError(ErrorCode::kInvalidArgument, "a swapchain needs a non-zero extent");
  }
  Swapchain s;
  Status status = createAll(device, surface, format, extent, vsync, old, s);
  if (!status) {
    destroySwapchain(device, s);
    return status.error();
  }
  return s;
}

void destroySwapchain(const Device& device, Swapchain& s) {
  for (VkImageView view : s.views) vkDestroyImageView(device.device, view, nullptr);
  if (s.swapchain != VK_NULL_HANDLE) vkDestroySwapchainKHR(device.device, s.swapchain, nullptr);
  s = Swapchain{};
}

}  // namespace cetview::engine
