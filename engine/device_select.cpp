#include "engine/device_select.h"

#include <algorithm>
#include <cctype>

namespace cetview::engine {
namespace {

bool containsIgnoringCase(std::string_view haystack, std::string_view needle) {
  auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  auto it = std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end(),
                        [&](char a, char b) { return lower(a) == lower(b); });
  return it != haystack.end();
}

std::string versionString(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v));
}

// Empty when usable, else why not.
std::string unusableReason(const DeviceCandidate& c, bool needPresent) {
  if (c.apiVersion < VK_API_VERSION_1_1) return "needs Vulkan 1.1, has " + versionString(c.apiVersion);
  if (!c.hasGraphicsQueue) return "has no graphics queue";
  if (needPresent && !c.canPresent) return "cannot present to the window surface";
  return {};
}

}  // namespace

int deviceTypeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 4;
    default:
      return 3;
  }
}

Result<std::size_t> pickDevice(const std::vector<DeviceCandidate>& candidates, std::string_view nameFilter,
                               bool needPresent) {
  if (candidates.empty()) {
    return makeError(ErrorCode::kNoDevice,
                     "no Vulkan device found (install mesa-vulkan-drivers for the lavapipe CPU device)");
  }
  std::size_t best = candidates.size();
  std::size_t matches = 0;
  std::string firstReason;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const DeviceCandidate& c = candidates[i];
    if (!containsIgnoringCase(c.name, nameFilter)) continue;
    ++matches;
    std::string reason = unusableReason(c, needPresent);
    if (!reason.empty()) {
      if (firstReason.empty()) firstReason = "'" + c.name + "' " + reason;
      continue;
    }
    if (best == candidates.size() || deviceTypeRank(c.type) < deviceTypeRank(candidates[best].type)) best = i;
  }
  if (matches == 0) {
    std::string names;
    for (const DeviceCandidate& c : candidates) names += (names.empty() ? "'" : ", '") + c.name + "'";
    return makeError(ErrorCode::kDeviceNotFound,
                     "no Vulkan device name contains '" + std::string(nameFilter) + "'; available: " + names);
  }
  if (best == candidates.size()) {
    return makeError(ErrorCode::kNoDevice, "no usable Vulkan device: " + firstReason);
  }
  return best;
}

}  // namespace cetview::engine
