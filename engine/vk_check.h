// Checking of Vulkan results: every call's VkResult becomes an Error naming the call and the result.
#pragma once

#include <vulkan/vulkan.h>

#include "engine/result.h"

namespace cetview::engine {

// A zero-initialised Vulkan struct with its sType set (brace-initialising only sType trips
// -Wmissing-field-initializers).
template <typename T>
T vkInit(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" etc.; "VkResult(<n>)" for values this build does not know.
const char* vkResultName(VkResult result);

// An Error for a failed call: "vkCreateBuffer failed: VK_ERROR_OUT_OF_DEVICE_MEMORY". `call` may be
// the whole call expression; it is cut at the first '('. The code follows the result (memory, lost
// device, lost surface, else kVulkan). A lost device reads "the Vulkan device was lost
// (VK_ERROR_DEVICE_LOST in vkQueueSubmit): the driver reset or crashed".
Error vkError(const char* call, VkResult result);

}  // namespace cetview::engine

// Evaluates a Vulkan call and returns vkError() from the enclosing function unless it gave VK_SUCCESS.
#define CETVIEW_VK(call)                                                                                \
  do {                                                                                                  \
    VkResult cetview_vk_result_ = (call);                                                               \
    if (cetview_vk_result_ != VK_SUCCESS) return ::cetview::engine::vkError(#call, cetview_vk_result_); \
  } while (0)
