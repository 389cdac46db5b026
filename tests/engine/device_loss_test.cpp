// A lost Vulkan device on a headless renderer: the call that meets the loss returns kDeviceLost
// with a one-line message, every later call returns that same error without touching the device,
// and destruction is clean (validation layer, ASan). lavapipe never loses its device, so the loss
// is injected with Renderer::simulateDeviceLossForTesting(): the renderer's next submission or
// wait reports VK_ERROR_DEVICE_LOST while the real device goes on, so the cleanup is real.
#include <gtest/gtest.h>

#include <string>

#include "engine/render_to_png.h"
#include "engine/vk_check.h"
#include "render_fixture.h"
#include "test_meshes.h"

namespace cetview::test {
namespace {

using namespace engine;

// The error every call of a lost renderer returns: the first one's code and message.
void expectSameLoss(const Error& error, const Error& first) {
  EXPECT_EQ(error.code, ErrorCode::kDeviceLost) << error.message;
  EXPECT_EQ(error.message, first.message);
}

TEST(DeviceLossMessage, NamesTheCallAndSaysWhatHappened) {
  const Error e = vkError("vkQueueSubmit(queue, 1, &submit, fence)", VK_ERROR_DEVICE_LOST);
  EXPECT_EQ(e.code, ErrorCode::kDeviceLost);
  EXPECT_EQ(
      e.message,
      "the Vulkan device was lost (VK_ERROR_DEVICE_LOST in vkQueueSubmit): the driver reset or crashed");
  // Other results keep the short form.
  EXPECT_EQ(vkError("vkCreateBuffer(...)", VK_ERROR_OUT_OF_DEVICE_MEMORY).message,
            "vkCreateBuffer failed: VK_ERROR_OUT_OF_DEVICE_MEMORY");
}

class DeviceLossTest : public VulkanTest {
 protected:
  Renderer* loadCube() {
    Renderer* r = makeHeadless(64, 64);
    if (r == nullptr) return nullptr;
    EXPECT_TRUE(addMesh(r->scene(), cube()).ok());
    return r;
  }
};

TEST_F(DeviceLossTest, LossInDrawFrameIsFinalAndCleanedUp) {
  Renderer* r = loadCube();
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->finishUploads().ok());
  const Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  for (int i = 0; i < 3; ++i) {
    auto frame = r->drawFrame(camera);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
  }
  ASSERT_TRUE(r->capture(camera).ok());
  EXPECT_FALSE(r->deviceLost());

  r->simulateDeviceLossForTesting();
  auto lost = r->drawFrame(camera);
  ASSERT_FALSE(lost.ok());
  const Error first = lost.error();
  EXPECT_EQ(first.code, ErrorCode::kDeviceLost);
  EXPECT_NE(first.message.find("the Vulkan device was lost (VK_ERROR_DEVICE_LOST in vk"), std::string::npos)
      << first.message;
  EXPECT_EQ(first.message.find('\n'), std::string::npos);
  EXPECT_TRUE(r->deviceLost());

  // Everything after returns the same error at once.
  auto again = r->drawFrame(camera);
  ASSERT_FALSE(again.ok());
  expectSameLoss(again.error(), first);
  auto image = r->capture(camera);
  ASSERT_FALSE(image.ok());
  expectSameLoss(image.error(), first);
  Status finished = r->finishUploads();
  ASSERT_FALSE(finished.ok());
  expectSameLoss(finished.error(), first);
  Status idle = r->waitIdle();
  ASSERT_FALSE(idle.ok());
  expectSameLoss(idle.error(), first);

  // The Scene is the CPU's: it still takes changes, which are never uploaded.
  ASSERT_TRUE(addMesh(r->scene(), sphere(0.5f, 12, glm::vec3(0.0f, 0.0f, 2.0f))).ok());
  EXPECT_TRUE(r->scene().uploadsPending());
  auto afterUpdate = r->drawFrame(camera);
  ASSERT_FALSE(afterUpdate.ok());
  expectSameLoss(afterUpdate.error(), first);
  finished = r->finishUploads();
  ASSERT_FALSE(finished.ok());
  expectSameLoss(finished.error(), first);
  EXPECT_TRUE(r->scene().uploadsPending());
  EXPECT_TRUE(r->deviceLost());
  // TearDown destroys the renderer and the device with the validation layer watching.
}

TEST_F(DeviceLossTest, LossWhileUploading) {
  Renderer* r = loadCube();
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->scene().uploadsPending());
  r->simulateDeviceLossForTesting();
  Status finished = r->finishUploads();
  ASSERT_FALSE(finished.ok());
  EXPECT_EQ(finished.error().code, ErrorCode::kDeviceLost) << finished.error().message;
  EXPECT_TRUE(r->deviceLost());
  const Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  auto image = r->capture(camera);
  ASSERT_FALSE(image.ok());
  expectSameLoss(image.error(), finished.error());
}

TEST_F(DeviceLossTest, LossInCaptureAfterUploadsInFlight) {
  Renderer* r = makeHeadless(64, 64, [] {
    RendererOptions o;
    o.uploadBudgetBytes = 64u << 10;  // the sphere takes several frames
    return o;
  }());
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(addMesh(r->scene(), sphere(1.0f, 48)).ok());
  const Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  auto frame = r->drawFrame(camera);  // leaves a frame (and its uploads) in flight
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  ASSERT_TRUE(r->scene().uploadsPending());

  r->simulateDeviceLossForTesting();
  auto image = r->capture(camera);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.error().code, ErrorCode::kDeviceLost) << image.error().message;
  Status finished = r->finishUploads();
  ASSERT_FALSE(finished.ok());
  expectSameLoss(finished.error(), image.error());
}

// Before any frame nothing is in flight: the first submission meets the loss.
TEST_F(DeviceLossTest, LossInTheFirstSubmission) {
  Renderer* r = makeHeadless(32, 32);
  ASSERT_NE(r, nullptr);
  r->simulateDeviceLossForTesting();
  auto frame = r->drawFrame(Camera{});
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(
      frame.error().message,
      "the Vulkan device was lost (VK_ERROR_DEVICE_LOST in vkQueueSubmit): the driver reset or crashed");
  Status idle = r->waitIdle();
  ASSERT_FALSE(idle.ok());
  expectSameLoss(idle.error(), frame.error());
}

TEST_F(DeviceLossTest, LossInWaitIdle) {
  Renderer* r = loadCube();
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->finishUploads().ok());
  r->simulateDeviceLossForTesting();
  Status idle = r->waitIdle();
  ASSERT_FALSE(idle.ok());
  EXPECT_EQ(idle.error().code, ErrorCode::kDeviceLost) << idle.error().message;
  auto image = r->capture(standardView(StandardView::kIso, r->scene().bounds(), r->aspect()));
  ASSERT_FALSE(image.ok());
  expectSameLoss(image.error(), idle.error());
}

}  // namespace
}  // namespace cetview::test
