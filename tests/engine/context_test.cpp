// Instance and device setup on the real loader: the validation layer is found and active, and the
// failure modes (layer missing, no driver, unknown device name) are returned errors, not crashes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "engine/context.h"
#include "engine/vk_check.h"
#include "render_fixture.h"

namespace cetview::test {
namespace {

using namespace engine;

// Sets an environment variable for one scope (the loader reads its variables at each call).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_) {
      setenv(name_.c_str(), old_->c_str(), 1);
    } else {
      unsetenv(name_.c_str());
    }
  }

 private:
  std::string name_;
  std::optional<std::string> old_;
};

using ContextTest = VulkanTest;

TEST_F(ContextTest, ValidationLayerIsLoadedAndReports) {
  // A zero-sized buffer breaks VUID-VkBufferCreateInfo-size-00912: the layer must say so.
  instance_.log->echoToStderr = false;
  auto info = vkInit<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkResult r = vkCreateBuffer(device_.device, &info, nullptr, &buffer);
  if (r == VK_SUCCESS && buffer != VK_NULL_HANDLE) vkDestroyBuffer(device_.device, buffer, nullptr);
  EXPECT_GE(instance_.log->count(), 1u) << "validation is requested but reported nothing";
  instance_.log->clear();
}

TEST_F(ContextTest, DescribesTheChosenDevice) {
  std::string description = describeDevice(device_);
  EXPECT_NE(description.find(device_.name), std::string::npos);
  EXPECT_NE(description.find("Vulkan 1."), std::string::npos);
  auto names = listDeviceNames(instance_);
  ASSERT_TRUE(names.ok());
  EXPECT_FALSE(names->empty());
}

TEST_F(ContextTest, PicksADeviceByNameSubstring) {
  auto names = listDeviceNames(instance_);
  ASSERT_TRUE(names.ok() && !names->empty());
  std::string name = names->front();
  DeviceOptions options;
  options.name = name.substr(0, std::min<std::size_t>(name.size(), 4));
  auto device = createDevice(instance_, options);
  ASSERT_TRUE(device.ok()) << device.error().message;
  EXPECT_NE(device->name.find(options.name), std::string::npos);
  destroyDevice(*device);
}

TEST_F(ContextTest, UnknownDeviceNameIsAnError) {
  DeviceOptions options;
  options.name = "no-such-gpu-9000";
  auto device = createDevice(instance_, options);
  ASSERT_FALSE(device.ok());
  EXPECT_EQ(device.error().code, ErrorCode::kDeviceNotFound);
  EXPECT_NE(device.error().message.find(device_.name), std::string::npos) << device.error().message;
}

TEST(ContextSetupTest, MissingValidationLayerIsAnErrorNotASilentPass) {
  // Point the loader's explicit-layer search at an empty place: validation must then fail.
  ScopedEnv layerPath("VK_LAYER_PATH", "/nonexistent-cetview-layers");
  InstanceOptions options;
  options.validation = true;
  auto instance = createInstance(options);
  ASSERT_FALSE(instance.ok());
  EXPECT_EQ(instance.error().code, ErrorCode::kMissingLayer);
  EXPECT_NE(instance.error().message.find("VK_LAYER_KHRONOS_validation"), std::string::npos);
}

TEST(ContextSetupTest, NoVulkanDriverIsOneClearError) {
  ScopedEnv icd("VK_ICD_FILENAMES", "/nonexistent-cetview-icd.json");
  ScopedEnv driverFiles("VK_DRIVER_FILES", "/nonexistent-cetview-icd.json");
  InstanceOptions options;
  auto instance = createInstance(options);
  if (instance.ok()) {
    // Some loaders create the instance and fail at enumeration instead.
    auto device = createDevice(*instance, DeviceOptions{});
    ASSERT_FALSE(device.ok());
    EXPECT_EQ(device.error().code, ErrorCode::kNoDevice);
    destroyInstance(*instance);
    return;
  }
  EXPECT_EQ(instance.error().code, ErrorCode::kNoVulkan) << instance.error().message;
  EXPECT_NE(instance.error().message.find("driver"), std::string::npos);
}

}  // namespace
}  // namespace cetview::test
