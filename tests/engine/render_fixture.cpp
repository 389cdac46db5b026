#include "render_fixture.h"

#include <cstdlib>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#endif

namespace cetview::test {
namespace {

// LeakSanitizer reports at exit, after the Vulkan loader has unloaded the validation layer and
// the driver; their leak stacks then name no module, and no suppression can match them. Pinning
// both libraries (RTLD_NODELETE) keeps the stacks readable, so tests/engine/lsan.supp can name
// exactly those two libraries and nothing of ours.
void pinVulkanLibrariesForLeakReports() {
#if defined(__SANITIZE_ADDRESS__)
  static const bool pinned = [] {
    for (const char* library : {"libVkLayer_khronos_validation.so", "libvulkan_lvp.so"}) {
      dlopen(library, RTLD_NOW | RTLD_NODELETE);  // absent on some machines: nothing to pin then
    }
    return true;
  }();
  (void)pinned;
#endif
}

}  // namespace

const char* testDeviceName() {
  const char* name = std::getenv("CETVIEW_TEST_DEVICE");
  return name != nullptr && *name != '\0' ? name : "llvmpipe";
}

void VulkanTest::SetUp() {
  pinVulkanLibrariesForLeakReports();
  engine::InstanceOptions options;
  options.validation = true;
  options.synchronizationValidation = synchronizationValidation_;
  options.extensions = instanceExtensions_;
  auto instance = engine::createInstance(options);
  ASSERT_TRUE(instance.ok()) << instance.error().message;
  instance_ = std::move(*instance);

  surface_ = createSurface();
  if (HasFatalFailure() || IsSkipped()) return;
  engine::DeviceOptions deviceOptions;
  deviceOptions.presentSurface = surface_;
  deviceOptions.name = testDeviceName();
  auto device = engine::createDevice(instance_, deviceOptions);
  ASSERT_TRUE(device.ok()) << device.error().message;
  device_ = *device;
}

void VulkanTest::TearDown() {
  renderer_.reset();
  engine::destroyDevice(device_);
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_.instance, surface_, nullptr);
  surface_ = VK_NULL_HANDLE;
  engine::destroyInstance(instance_);
  if (instance_.log) {
    EXPECT_EQ(instance_.log->count(), 0u) << "the validation layer reported problems (printed above)";
  }
}

engine::Renderer* VulkanTest::makeHeadless(std::uint32_t width, std::uint32_t height,
                                           engine::RendererOptions options) {
  renderer_.reset();
  auto renderer = engine::Renderer::createHeadless(device_, {width, height}, options);
  if (!renderer.ok()) {
    ADD_FAILURE() << renderer.error().message;
    return nullptr;
  }
  renderer_ = std::move(*renderer);
  return renderer_.get();
}

}  // namespace cetview::test
