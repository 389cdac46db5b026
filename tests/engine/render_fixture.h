// Fixture of every test that touches Vulkan: an instance with VK_LAYER_KHRONOS_validation (a
// missing layer fails the test, it never passes silently), the device (lavapipe in CI, or the
// one named by CETVIEW_TEST_DEVICE), and a check after each test that the validation layer
// reported nothing.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/context.h"
#include "engine/renderer.h"

namespace cetview::test {

// The device the render tests run on: CETVIEW_TEST_DEVICE (a name substring, as --device), else
// lavapipe, whose pictures the goldens are (a GPU draws lines and MSAA edges a little differently).
const char* testDeviceName();

class VulkanTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Window tests: called between instance and device creation; the surface (if any) is destroyed
  // after the device. Instance extensions it needs go in instanceExtensions_ before SetUp().
  virtual VkSurfaceKHR createSurface() { return VK_NULL_HANDLE; }

  // A headless renderer on device_, released before the device in TearDown(); null (and the test
  // failed) when it cannot be created.
  engine::Renderer* makeHeadless(std::uint32_t width, std::uint32_t height,
                                 engine::RendererOptions options = {});

  engine::Instance instance_;
  engine::Device device_;
  std::unique_ptr<engine::Renderer> renderer_;
  std::vector<std::string> instanceExtensions_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  bool synchronizationValidation_ = true;  // subclasses may turn the (slow) sync checks off
};

}  // namespace cetview::test
