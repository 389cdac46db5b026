#include "engine/context.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "engine/cpu_allocator.h"
#include "engine/device_select.h"
#include "engine/vk_check.h"

namespace cetview::engine {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr std::size_t kMaxKeptMessages = 64;

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT types,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* log = static_cast<ValidationLog*>(user);
  bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  bool checked = (types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT)) != 0;
  std::string text = error ? "ERROR: " : "WARNING: ";
  text += (data && data->pMessage) ? data->pMessage : "(no message)";
  log->add(error || checked, std::move(text));
  return VK_FALSE;  // never abort the call: the engine wants to see the result it would have had
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
  auto info =
      vkInit<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onDebugMessage;
  info.pUserData = log;
  return info;
}

bool hasLayer(const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.end(),
                     [&](const VkLayerProperties& p) { return std::strcmp(p.layerName, name) == 0; });
}

// Instance extensions from the loader and drivers, plus those of `layer` when given.
Result<std::vector<std::string>> instanceExtensions(const char* layer) {
  std::vector<std::string> names;
  auto query = [&names](const char* source) -> Status {
    std::uint32_t count = 0;
    VkResult r = vkEnumerateInstanceExtensionProperties(source, &count, nullptr);
    // A loader without any driver can fail here: the clearest place to name the cause.
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED) {
      return makeError(ErrorCode::kNoVulkan, "no Vulkan driver found (install mesa-vulkan-drivers)");
    }
    CETVIEW_VK(r);
    std::vector<VkExtensionProperties> props(count);
    CETVIEW_VK(vkEnumerateInstanceExtensionProperties(source, &count, props.data()));
    for (std::uint32_t i = 0; i < count; ++i) names.emplace_back(props[i].extensionName);
    return {};
  };
  CETVIEW_TRY(query(nullptr));
  if (layer != nullptr) CETVIEW_TRY(query(layer));
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other";
  }
}

Result<std::vector<VkPhysicalDevice>> physicalDevices(VkInstance instance) {
  std::uint32_t count = 0;
  CETVIEW_VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  if (count > 0) CETVIEW_VK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  devices.resize(count);
  return devices;
}

// The first queue family with graphics (and present support when a surface is given), or UINT32_MAX.
Result<std::uint32_t> graphicsFamily(VkPhysicalDevice device, VkSurfaceKHR surface, bool* hasGraphics) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  *hasGraphics = false;
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) == 0) continue;
    *hasGraphics = true;
    if (surface == VK_NULL_HANDLE) return i;
    VkBool32 present = VK_FALSE;
    CETVIEW_VK(vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present));
    if (present) return i;
  }
  return UINT32_MAX;
}

Result<std::vector<std::string>> deviceExtensions(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  CETVIEW_VK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> props(count);
  CETVIEW_VK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, props.data()));
  std::vector<std::string> names;
  for (std::uint32_t i = 0; i < count; ++i) names.emplace_back(props[i].extensionName);
  return names;
}

}  // namespace

std::uint32_t ValidationLog::count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return count_;
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return messages_;
}

void ValidationLog::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  count_ = 0;
  messages_.clear();
}

void ValidationLog::add(bool counted, std::string message) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (echoToStderr) std::fprintf(stderr, "vulkan: %s\n", message.c_str());
  if (counted) ++count_;
  if (messages_.size() < kMaxKeptMessages) messages_.push_back(std::move(message));
}

Result<Instance> createInstance(const InstanceOptions& options) {
  Instance result;
  result.log = std::make_unique<ValidationLog>();
  result.log->echoToStderr = options.echoMessages;
  result.validation = options.validation;

  std::uint32_t loaderVersion = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS || loaderVersion < VK_API_VERSION_1_1) {
    return makeError(ErrorCode::kNoVulkan, "the Vulkan loader is older than 1.1");
  }
  if (options.validation && !hasLayer(kValidationLayer)) {
    return makeError(ErrorCode::kMissingLayer, std::string("validation requested but ") + kValidationLayer +
                                                   " is not installed (Debian: vulkan-validationlayers)");
  }
  auto available = instanceExtensions(options.validation ? kValidationLayer : nullptr);
  CETVIEW_TRY(available);

  std::vector<const char*> extensions;
  for (const std::string& name : options.extensions) {
    if (!contains(*available, name)) {
      return makeError(ErrorCode::kMissingExtension, "instance extension " + name + " is not available");
    }
    extensions.push_back(name.c_str());
  }
  bool debugUtils = options.validation && contains(*available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (options.validation && !debugUtils) {
    return makeError(ErrorCode::kMissingExtension,
                     "validation requested but " VK_EXT_DEBUG_UTILS_EXTENSION_NAME " is not available");
  }
  if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  auto app = vkInit<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "cetview";
  app.pEngineName = "cetview";
  app.apiVersion = VK_API_VERSION_1_1;

  const char* layers[] = {kValidationLayer};
  auto info = vkInit<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (options.validation) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
  }
  // Chained so that messages from vkCreateInstance/vkDestroyInstance themselves are caught too.
  VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(result.log.get());
  VkValidationFeatureEnableEXT syncFeature = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  auto features = vkInit<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
  if (debugUtils) {
    info.pNext = &debugInfo;
    if (options.synchronizationValidation) {
      features.enabledValidationFeatureCount = 1;
      features.pEnabledValidationFeatures = &syncFeature;
      debugInfo.pNext = &features;
    }
  }
  VkResult r = vkCreateInstance(&info, nullptr, &result.instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER) {
    return makeError(ErrorCode::kNoVulkan, "no Vulkan driver found (install mesa-vulkan-drivers)");
  }
  if (r == VK_ERROR_LAYER_NOT_PRESENT) {
    return makeError(ErrorCode::kMissingLayer, std::string(kValidationLayer) + " failed to load");
  }
  CETVIEW_VK(r);

  if (debugUtils) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(result.instance, "vkCreateDebugUtilsMessengerEXT"));
    VkDebugUtilsMessengerCreateInfoEXT messenger = messengerInfo(result.log.get());
    r = create ? create(result.instance, &messenger, nullptr, &result.messenger)
               : VK_ERROR_EXTENSION_NOT_PRESENT;
    if (r != VK_SUCCESS) {
      destroyInstance(result);
      return vkError("vkCreateDebugUtilsMessengerEXT", r);
    }
  }
  return result;
}

void destroyInstance(Instance& instance) {
  if (instance.messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance.instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance.instance, instance.messenger, nullptr);
    instance.messenger = VK_NULL_HANDLE;
  }
  if (instance.instance != VK_NULL_HANDLE) vkDestroyInstance(instance.instance, nullptr);
  instance.instance = VK_NULL_HANDLE;
}

Result<Device> createDevice(const Instance& instance, const DeviceOptions& options) {
  auto devices = physicalDevices(instance.instance);
  CETVIEW_TRY(devices);
  bool needPresent = options.presentSurface != VK_NULL_HANDLE;

  std::vector<DeviceCandidate> candidates;
  std::vector<std::uint32_t> families;
  for (VkPhysicalDevice pd : *devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(pd, &props);
    DeviceCandidate c;
    c.name = props.deviceName;
    c.type = props.deviceType;
    c.apiVersion = props.apiVersion;
    auto family = graphicsFamily(pd, options.presentSurface, &c.hasGraphicsQueue);
    CETVIEW_TRY(family);
    c.canPresent = *family != UINT32_MAX;
    if (!needPresent) c.canPresent = true;
    if (needPresent && c.canPresent) {
      auto extensions = deviceExtensions(pd);
      CETVIEW_TRY(extensions);
      c.canPresent = contains(*extensions, VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }
    candidates.push_back(std::move(c));
    families.push_back(*family);
  }
  auto chosen = pickDevice(candidates, options.name, needPresent);
  CETVIEW_TRY(chosen);

  Device result;
  result.instance = instance.instance;
  result.physicalDevice = (*devices)[*chosen];
  result.queueFamily = families[*chosen];
  result.log = instance.log.get();
  vkGetPhysicalDeviceProperties(result.physicalDevice, &result.properties);
  vkGetPhysicalDeviceMemoryProperties(result.physicalDevice, &result.memory);
  result.name = result.properties.deviceName;
  if (result.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) keepFreedMemoryForCpuRendering();

  auto extensions = deviceExtensions(result.physicalDevice);
  CETVIEW_TRY(extensions);
  const bool hasMultiDraw = contains(*extensions, VK_EXT_MULTI_DRAW_EXTENSION_NAME);
  auto multiDrawSupported =
      vkInit<VkPhysicalDeviceMultiDrawFeaturesEXT>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTI_DRAW_FEATURES_EXT);
  auto supported2 = vkInit<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  if (hasMultiDraw) supported2.pNext = &multiDrawSupported;
  vkGetPhysicalDeviceFeatures2(result.physicalDevice, &supported2);
  const VkPhysicalDeviceFeatures& supported = supported2.features;
  auto enabled2 = vkInit<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  VkPhysicalDeviceFeatures& enabled = enabled2.features;
  enabled.multiDrawIndirect = supported.multiDrawIndirect;
  enabled.drawIndirectFirstInstance = supported.drawIndirectFirstInstance;
  enabled.fillModeNonSolid = supported.fillModeNonSolid;
  enabled.wideLines = supported.wideLines;
  result.features.multiDrawIndirect = supported.multiDrawIndirect == VK_TRUE;
  result.features.drawIndirectFirstInstance = supported.drawIndirectFirstInstance == VK_TRUE;
  result.features.fillModeNonSolid = supported.fillModeNonSolid == VK_TRUE;
  result.features.wideLines = supported.wideLines == VK_TRUE;

  std::vector<const char*> enabledExtensions;
  auto multiDrawEnabled =
      vkInit<VkPhysicalDeviceMultiDrawFeaturesEXT>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTI_DRAW_FEATURES_EXT);
  if (hasMultiDraw && multiDrawSupported.multiDraw == VK_TRUE) {
    auto multiDrawLimits = vkInit<VkPhysicalDeviceMultiDrawPropertiesEXT>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTI_DRAW_PROPERTIES_EXT);
    auto properties2 = vkInit<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
    properties2.pNext = &multiDrawLimits;
    vkGetPhysicalDeviceProperties2(result.physicalDevice, &properties2);
    if (multiDrawLimits.maxMultiDrawCount > 0) {
      multiDrawEnabled.multiDraw = VK_TRUE;
      enabled2.pNext = &multiDrawEnabled;
      enabledExtensions.push_back(VK_EXT_MULTI_DRAW_EXTENSION_NAME);
      result.features.multiDraw = true;
      result.features.maxMultiDrawCount = multiDrawLimits.maxMultiDrawCount;
    }
  }
  // Only with a surface: VK_KHR_swapchain needs the instance's VK_KHR_surface, which headless
  // instances do not enable.
  result.swapchainExtension = needPresent && contains(*extensions, VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  if (result.swapchainExtension) enabledExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  float priority = 1.0f;
  auto queueInfo = vkInit<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queueInfo.queueFamilyIndex = result.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  auto info = vkInit<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<std::uint32_t>(enabledExtensions.size());
  info.ppEnabledExtensionNames = enabledExtensions.data();
  info.pNext = &enabled2;
  CETVIEW_VK(vkCreateDevice(result.physicalDevice, &info, nullptr, &result.device));
  vkGetDeviceQueue(result.device, result.queueFamily, 0, &result.queue);
  if (result.features.multiDraw) {
    result.cmdDrawMultiIndexed = reinterpret_cast<PFN_vkCmdDrawMultiIndexedEXT>(
        vkGetDeviceProcAddr(result.device, "vkCmdDrawMultiIndexedEXT"));
    result.cmdDrawMulti =
        reinterpret_cast<PFN_vkCmdDrawMultiEXT>(vkGetDeviceProcAddr(result.device, "vkCmdDrawMultiEXT"));
    if (result.cmdDrawMultiIndexed == nullptr || result.cmdDrawMulti == nullptr) {
      result.features.multiDraw = false;  // enabled but unused: harmless
      result.cmdDrawMultiIndexed = nullptr;
      result.cmdDrawMulti = nullptr;
    }
  }
  return result;
}

void destroyDevice(Device& device) {
  if (device.device != VK_NULL_HANDLE) vkDestroyDevice(device.device, nullptr);
  device.device = VK_NULL_HANDLE;
  device.queue = VK_NULL_HANDLE;
}

std::string describeDevice(const Device& device) {
  std::uint32_t v = device.properties.apiVersion;
  return device.name + ", " + typeName(device.properties.deviceType) + ", Vulkan " +
         std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v));
}

Result<std::vector<std::string>> listDeviceNames(const Instance& instance) {
  auto devices = physicalDevices(instance.instance);
  CETVIEW_TRY(devices);
  std::vector<std::string> names;
  for (VkPhysicalDevice pd : *devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(pd, &props);
    names.emplace_back(props.deviceName);
  }
  return names;
}

}  // namespace cetview::engine
