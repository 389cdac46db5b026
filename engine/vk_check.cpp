#include "engine/vk_check.h"

#include <string>

namespace cetview::engine {

const char* vkResultName(VkResult result) {
  switch (result) {
#define CETVIEW_RESULT_NAME(name) \
  case name:                      \
    return #name;
    CETVIEW_RESULT_NAME(VK_SUCCESS)
    CETVIEW_RESULT_NAME(VK_NOT_READY)
    CETVIEW_RESULT_NAME(VK_TIMEOUT)
    CETVIEW_RESULT_NAME(VK_EVENT_SET)
    CETVIEW_RESULT_NAME(VK_EVENT_RESET)
    CETVIEW_RESULT_NAME(VK_INCOMPLETE)
    CETVIEW_RESULT_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
    CETVIEW_RESULT_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    CETVIEW_RESULT_NAME(VK_ERROR_INITIALIZATION_FAILED)
    CETVIEW_RESULT_NAME(VK_ERROR_DEVICE_LOST)
    CETVIEW_RESULT_NAME(VK_ERROR_MEMORY_MAP_FAILED)
    CETVIEW_RESULT_NAME(VK_ERROR_LAYER_NOT_PRESENT)
    CETVIEW_RESULT_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
    CETVIEW_RESULT_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
    CETVIEW_RESULT_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
    CETVIEW_RESULT_NAME(VK_ERROR_TOO_MANY_OBJECTS)
    CETVIEW_RESULT_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
    CETVIEW_RESULT_NAME(VK_ERROR_FRAGMENTED_POOL)
    CETVIEW_RESULT_NAME(VK_ERROR_UNKNOWN)
    CETVIEW_RESULT_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
    CETVIEW_RESULT_NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    CETVIEW_RESULT_NAME(VK_ERROR_FRAGMENTATION)
    CETVIEW_RESULT_NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    CETVIEW_RESULT_NAME(VK_ERROR_SURFACE_LOST_KHR)
    CETVIEW_RESULT_NAME(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    CETVIEW_RESULT_NAME(VK_SUBOPTIMAL_KHR)
    CETVIEW_RESULT_NAME(VK_ERROR_OUT_OF_DATE_KHR)
    CETVIEW_RESULT_NAME(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR)
    CETVIEW_RESULT_NAME(VK_ERROR_VALIDATION_FAILED_EXT)
#undef CETVIEW_RESULT_NAME
    default:
      break;
  }
  thread_local std::string unknown;
  unknown = "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  return unknown.c_str();
}

Error vkError(const char* call, VkResult result) {
  std::string name(call);
  auto paren = name.find('(');
  if (paren != std::string::npos) name.resize(paren);
  ErrorCode code = ErrorCode::kVulkan;
  switch (result) {
    case VK_ERROR_OUT_OF_HOST_MEMORY:
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
    case VK_ERROR_OUT_OF_POOL_MEMORY:
    case VK_ERROR_FRAGMENTED_POOL:
      code = ErrorCode::kOutOfMemory;
      break;
    case VK_ERROR_DEVICE_LOST:
      code = ErrorCode::kDeviceLost;
      break;
    case VK_ERROR_SURFACE_LOST_KHR:
      code = ErrorCode::kSurfaceLost;
      break;
    case VK_ERROR_INCOMPATIBLE_DRIVER:
      code = ErrorCode::kNoVulkan;
      break;
    default:
      break;
  }
  if (code == ErrorCode::kDeviceLost) {
    return Error{code, "the Vulkan device was lost (VK_ERROR_DEVICE_LOST in " + name +
                           "): the driver reset or crashed"};
  }
  return Error{code, name + " failed: " + vkResultName(result)};
}

}  // namespace cetview::engine
