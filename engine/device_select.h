// Choice of the physical device: pure ranking over plain descriptions, so it is testable without a GPU.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/result.h"

namespace cetview::engine {

// What device selection needs to know about one VkPhysicalDevice.
struct DeviceCandidate {
  std::string name;  // VkPhysicalDeviceProperties::deviceName
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t apiVersion = 0;   // VkPhysicalDeviceProperties::apiVersion
  bool hasGraphicsQueue = false;  // a queue family with VK_QUEUE_GRAPHICS_BIT
  bool canPresent = false;        // that family can present to the caller's surface (ignored without one)
};

// Lower is preferred: discrete, integrated, virtual, other, then CPU (lavapipe, the fallback).
int deviceTypeRank(VkPhysicalDeviceType type);

// Index into `candidates` of the device to use: the best-ranked usable device whose name contains
// `nameFilter` (case-insensitive; empty matches every device), ties broken by enumeration order.
// Usable: Vulkan 1.1 or newer, a graphics queue, and present support when `needPresent`.
// Errors: kNoDevice (empty list, or nothing usable), kDeviceNotFound (no name matches; the message
// lists the available names).
Result<std::size_t> pickDevice(const std::vector<DeviceCandidate>& candidates, std::string_view nameFilter,
                               bool needPresent);

}  // namespace cetview::engine
