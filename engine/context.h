// Vulkan instance and device setup (vk-bootstrap's shape: options in, a Result out).
//
// Order of use: createInstance(); the caller may then create a VkSurfaceKHR with the instance (the
// viewer does, through GLFW); createDevice() with that surface, or without one for headless work.
// Destroy in reverse. Structs are plain handles: copying one does not copy the objects behind it.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/result.h"

namespace cetview::engine {

// Validation-layer output gathered by the debug-utils messenger. Thread-safe: layers may report from
// any thread. Tests fail on any counted message.
class ValidationLog {
 public:
  // Counted messages: every warning or error of the validation or performance kind, and every
  // error of any kind. General warnings (loader chatter) are kept in messages() but not counted.
  std::uint32_t count() const;
  std::vector<std::string> messages() const;  // the first 64, each "SEVERITY: text"
  void clear();

  void add(bool counted, std::string message);
  bool echoToStderr = true;  // print each message as it arrives

 private:
  mutable std::mutex mutex_;
  std::uint32_t count_ = 0;
  std::vector<std::string> messages_;
};

struct InstanceOptions {
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation; a missing layer is kMissingLayer
  bool synchronizationValidation = false;  // also enable the layer's synchronisation checks (slower)
  bool echoMessages = true;                // print validation messages to stderr as they arrive
  std::vector<std::string> extensions;     // e.g. the window system's surface extensions
};

struct Instance {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  bool validation = false;
  std::unique_ptr<ValidationLog> log;  // never null after createInstance()
};

// Errors: kNoVulkan (no loader-visible driver), kMissingLayer, kMissingExtension, kVulkan.
Result<Instance> createInstance(const InstanceOptions& options);
void destroyInstance(Instance& instance);

// Optional features the engine uses when the device has them.
struct DeviceFeatures {
  bool multiDrawIndirect = false;          // one indirect call draws every face of a part
  bool drawIndirectFirstInstance = false;  // indirect draws carry the face id in firstInstance
  bool fillModeNonSolid = false;           // wireframe display mode (polygon mode LINE)
  bool wideLines = false;
  // VK_EXT_multi_draw: one call draws several index ranges. Where draws go one by one (lavapipe),
  // each call costs the driver some microseconds however few triangles it has.
  bool multiDraw = false;
  std::uint32_t maxMultiDrawCount = 0;  // ranges per call
};

struct DeviceOptions {
  std::string name;                              // substring of the device name; empty: best device
  VkSurfaceKHR presentSurface = VK_NULL_HANDLE;  // when set, the device must present to it
};

struct Device {
  VkInstance instance = VK_NULL_HANDLE;  // not owned
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;  // graphics + transfer (+ present when a surface was given)
  std::uint32_t queueFamily = 0;
  std::string name;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  DeviceFeatures features;
  bool swapchainExtension = false;  // VK_KHR_swapchain enabled (only with DeviceOptions::presentSurface)
  // Entry points of VK_EXT_multi_draw; null unless features.multiDraw.
  PFN_vkCmdDrawMultiIndexedEXT cmdDrawMultiIndexed = nullptr;
  PFN_vkCmdDrawMultiEXT cmdDrawMulti = nullptr;
  ValidationLog* log = nullptr;  // the instance's log; not owned
};

// Errors: kNoDevice, kDeviceNotFound (message lists the device names), kMissingExtension, kVulkan.
Result<Device> createDevice(const Instance& instance, const DeviceOptions& options);
void destroyDevice(Device& device);

// "llvmpipe (LLVM 15.0.6, 256 bits), CPU, Vulkan 1.3": one line for logs and --device listings.
std::string describeDevice(const Device& device);

// Names of every physical device, in enumeration order.
Result<std::vector<std::string>> listDeviceNames(const Instance& instance);

}  // namespace cetview::engine
