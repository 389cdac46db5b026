// The window's swapchain. The Renderer recreates it when the framebuffer size changes or the
// surface reports it out of date or suboptimal; while minimised (0x0) it draws nothing.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

#include "engine/context.h"
#include "engine/result.h"

namespace cetview::engine {

struct Swapchain {
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VkSurfaceFormatKHR format{};
  VkExtent2D extent{0, 0};
  std::vector<VkImage> images;
  std::vector<VkImageView> views;
  bool transferSrc = false;  // images can be copied from (Renderer::capture() of a window)
};

// A B8G8R8A8 or R8G8B8A8 format in the sRGB colour space when offered (*_SRGB first where
// preferSrgbTarget(device, samples), else *_UNORM first: the shaders encode then), else the first.
Result<VkSurfaceFormatKHR> chooseSurfaceFormat(const Device& device, VkSurfaceKHR surface,
                                               VkSampleCountFlagBits samples);

// The extent a swapchain created now would get: the surface's current extent, or `framebuffer`
// clamped to the surface's limits where the surface leaves the size to the application. A zero
// width or height means minimised: create no swapchain then.
Result<VkExtent2D> surfaceExtent(const Device& device, VkSurfaceKHR surface, VkExtent2D framebuffer);

// `extent` must be non-zero. `vsync` selects FIFO; otherwise MAILBOX, then IMMEDIATE, then FIFO.
// `old` (may be null) is handed to the driver for reuse; the caller destroys it afterwards.
Result<Swapchain> createSwapchain(const Device& device, VkSurfaceKHR surface, VkSurfaceFormatKHR format,
                                  VkExtent2D extent, bool vsync, VkSwapchainKHR old);
void destroySwapchain(const Device& device, Swapchain& swapchain);

}  // namespace cetview::engine
