// Device choice without a GPU: the ranking, the name filter and the errors.
#include <gtest/gtest.h>

#include "engine/device_select.h"

namespace cetview::test {
namespace {

using namespace engine;

DeviceCandidate candidate(const char* name, VkPhysicalDeviceType type,
                          std::uint32_t api = VK_API_VERSION_1_3) {
  DeviceCandidate c;
  c.name = name;
  c.type = type;
  c.apiVersion = api;
  c.hasGraphicsQueue = true;
  c.canPresent = true;
  return c;
}

const std::vector<DeviceCandidate> kMachine = {
    candidate("llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU),
    candidate("Intel(R) UHD Graphics 630", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
    candidate("NVIDIA GeForce RTX 3070", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
};

TEST(DeviceSelectTest, PrefersDiscreteThenIntegratedThenCpu) {
  EXPECT_EQ(*pickDevice(kMachine, "", false), 2u);
  std::vector<DeviceCandidate> noDiscrete(kMachine.begin(), kMachine.begin() + 2);
  EXPECT_EQ(*pickDevice(noDiscrete, "", false), 1u);
  std::vector<DeviceCandidate> onlyLavapipe(kMachine.begin(), kMachine.begin() + 1);
  EXPECT_EQ(*pickDevice(onlyLavapipe, "", false), 0u);
}

TEST(DeviceSelectTest, NameFilterIsACaseInsensitiveSubstring) {
  EXPECT_EQ(*pickDevice(kMachine, "LLVMPIPE", false), 0u);
  EXPECT_EQ(*pickDevice(kMachine, "uhd", false), 1u);
  EXPECT_EQ(*pickDevice(kMachine, "RTX", false), 2u);
}

TEST(DeviceSelectTest, UnknownNameListsTheAvailableDevices) {
  auto r = pickDevice(kMachine, "radeon", false);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kDeviceNotFound);
  EXPECT_NE(r.error().message.find("radeon"), std::string::npos);
  EXPECT_NE(r.error().message.find("llvmpipe"), std::string::npos);
  EXPECT_NE(r.error().message.find("RTX 3070"), std::string::npos);
  EXPECT_EQ(r.error().message.find('\n'), std::string::npos);  // one line
}

TEST(DeviceSelectTest, NoDeviceAtAllIsOneClearError) {
  auto r = pickDevice({}, "", false);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kNoDevice);
  EXPECT_NE(r.error().message.find("no Vulkan device"), std::string::npos);
}

TEST(DeviceSelectTest, SkipsDevicesThatCannotServe) {
  std::vector<DeviceCandidate> devices = kMachine;
  devices[2].apiVersion = VK_API_VERSION_1_0;  // too old
  devices[1].canPresent = false;               // not for this window
  EXPECT_EQ(*pickDevice(devices, "", true), 0u);
  EXPECT_EQ(*pickDevice(devices, "", false), 1u);  // headless: presenting does not matter
  auto r = pickDevice(devices, "RTX", false);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kNoDevice);
  EXPECT_NE(r.error().message.find("needs Vulkan 1.1"), std::string::npos);
}

}  // namespace
}  // namespace cetview::test
