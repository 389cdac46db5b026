// The windowed path on a real swapchain without a display: the test starts its own Xvfb server,
// opens an X window through xcb and hands the renderer a VkSurfaceKHR for it, as the viewer will
// with GLFW. Covers first swapchain creation, resize, minimise (0x0) and an out-of-date swapchain
// (window resized behind the renderer's back). Skipped when Xvfb is not installed.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <utility>

// vulkan_xcb.h needs xcb.h first: separate blocks keep clang-format from reordering them.
#include <xcb/xcb.h>

#include <vulkan/vulkan.h>
#include <vulkan/vulkan_xcb.h>

#include "engine/render_to_png.h"
#include "engine/vk_check.h"
#include "render_fixture.h"
#include "support/on_path.h"
#include "test_meshes.h"

extern char** environ;

namespace cetview::test {
namespace {

using namespace engine;

// An Xvfb server on a free display, stopped when this goes away.
class XvfbServer {
 public:
  bool start() {
    int fds[2];
    if (pipe(fds) != 0) return false;
    std::string fd = std::to_string(fds[1]);
    const char* argv[] = {"Xvfb",       "-displayfd", fd.c_str(), "-screen", "0",
                          "640x480x24", "-nolisten",  "tcp",      nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, const_cast<char**>(argv), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (rc != 0) {
      pid_ = -1;
      close(fds[0]);
      return false;
    }
    // Xvfb writes the display number once it accepts connections.
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    while (poll(&p, 1, 10000) > 0) {
      char c;
      if (read(fds[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    close(fds[0]);
    display_ = number.empty() ? "" : ":" + number;
    return !display_.empty();
  }
  ~XvfbServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

class WindowTest : public VulkanTest {
 protected:
  void SetUp() override {
    if (!cetview::test::onPath("Xvfb")) GTEST_SKIP() << "Xvfb is not installed (Debian: xvfb)";
    instanceExtensions_ = {VK_KHR_SURFACE_EXTENSION_NAME, VK_KHR_XCB_SURFACE_EXTENSION_NAME};
    VulkanTest::SetUp();
  }
  // The renderer on the test window's surface, following framebuffer_ as the window system's size.
  void createRenderer() {
    ASSERT_NE(surface_, VK_NULL_HANDLE);
    auto created = Renderer::createWindowed(device_, surface_, [this] { return framebuffer_; });
    ASSERT_TRUE(created.ok()) << created.error().message;
    renderer_ = std::move(*created);
  }

  void TearDown() override {
    VulkanTest::TearDown();
    if (connection_) xcb_disconnect(connection_);
  }

  VkSurfaceKHR createSurface() override {
    if (!server_.start()) {
      ADD_FAILURE() << "Xvfb did not start";
      return VK_NULL_HANDLE;
    }
    connection_ = xcb_connect(server_.display().c_str(), nullptr);
    if (xcb_connection_has_error(connection_)) {
      ADD_FAILURE() << "cannot connect to Xvfb on " << server_.display();
      return VK_NULL_HANDLE;
    }
    xcb_screen_t* screen = xcb_setup_roots_iterator(xcb_get_setup(connection_)).data;
    window_ = xcb_generate_id(connection_);
    xcb_create_window(connection_, XCB_COPY_FROM_PARENT, window_, screen->root, 0, 0, 320, 240, 0,
                      XCB_WINDOW_CLASS_INPUT_OUTPUT, screen->root_visual, 0, nullptr);
    xcb_map_window(connection_, window_);
    sync();

    auto info = vkInit<VkXcbSurfaceCreateInfoKHR>(VK_STRUCTURE_TYPE_XCB_SURFACE_CREATE_INFO_KHR);
    info.connection = connection_;
    info.window = window_;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkResult r = vkCreateXcbSurfaceKHR(instance_.instance, &info, nullptr, &surface);
    if (r != VK_SUCCESS) ADD_FAILURE() << vkError("vkCreateXcbSurfaceKHR", r).message;
    return surface;
  }

  // Resizes the X window and waits until the server has done it.
  void resizeWindow(std::uint32_t width, std::uint32_t height) {
    const std::uint32_t values[] = {width, height};
    xcb_configure_window(connection_, window_, XCB_CONFIG_WINDOW_WIDTH | XCB_CONFIG_WINDOW_HEIGHT, values);
    sync();
  }
  void sync() { free(xcb_get_input_focus_reply(connection_, xcb_get_input_focus(connection_), nullptr)); }

  // Draws until a frame is rendered (a resize may skip one while the swapchain is recreated).
  void drawUntilRendered(Renderer& r, const Camera& camera) {
    for (int attempt = 0; attempt < 5; ++attempt) {
      auto status = r.drawFrame(camera);
      ASSERT_TRUE(status.ok()) << status.error().message;
      if (*status == FrameStatus::kRendered) return;
    }
    FAIL() << "no frame rendered in 5 attempts";
  }

  XvfbServer server_;
  xcb_connection_t* connection_ = nullptr;
  xcb_window_t window_ = 0;
  VkExtent2D framebuffer_{320, 240};  // what the "window system" reports to the renderer
};

TEST_F(WindowTest, ResizeMinimiseAndOutOfDateSwapchains) {
  ASSERT_NO_FATAL_FAILURE(createRenderer());
  Renderer& r = *renderer_;
  ASSERT_TRUE(addMesh(r.scene(), cube()).ok());
  Camera camera = standardView(StandardView::kIso, r.scene().bounds(), 320.0f / 240.0f);

  for (int i = 0; i < 3; ++i) drawUntilRendered(r, camera);
  EXPECT_EQ(r.extent().width, 320u);
  EXPECT_EQ(r.extent().height, 240u);
  EXPECT_EQ(r.swapchainRecreations(), 1u);  // the first swapchain

  // Resize, reported by the window system.
  resizeWindow(200, 150);
  framebuffer_ = {200, 150};
  drawUntilRendered(r, camera);
  drawUntilRendered(r, camera);
  EXPECT_EQ(r.extent().width, 200u);
  EXPECT_EQ(r.extent().height, 150u);
  EXPECT_GE(r.swapchainRecreations(), 2u);

  // Minimised: a 0x0 framebuffer draws nothing and is no error, but uploads go on.
  framebuffer_ = {0, 0};
  ASSERT_TRUE(addMesh(r.scene(), sphere(0.5f, 12, glm::vec3(0.0f, 0.0f, 1.5f))).ok());
  for (int i = 0; i < 3; ++i) {
    auto status = r.drawFrame(camera);
    ASSERT_TRUE(status.ok()) << status.error().message;
    EXPECT_EQ(*status, FrameStatus::kSkipped);
  }
  EXPECT_FALSE(r.scene().uploadsPending());
  framebuffer_ = {200, 150};
  drawUntilRendered(r, camera);

  // Resized behind the renderer's back: the surface reports the swapchain out of date or
  // suboptimal, and the renderer follows the surface's size.
  std::uint32_t before = r.swapchainRecreations();
  resizeWindow(260, 180);
  for (int i = 0; i < 4; ++i) {
    auto status = r.drawFrame(camera);
    ASSERT_TRUE(status.ok()) << status.error().message;
  }
  EXPECT_GT(r.swapchainRecreations(), before);
  EXPECT_EQ(r.extent().width, 260u);
  EXPECT_EQ(r.extent().height, 180u);
  ASSERT_TRUE(r.waitIdle().ok());
}

// A device lost in the middle of the frame loop (simulated: lavapipe never loses it): the frame
// returns kDeviceLost, every later call the same error, and the swapchain, its semaphores and the
// overlay's frames are torn down cleanly (validation layer on).
TEST_F(WindowTest, DeviceLossMidLoopEndsWithAnErrorAndCleanTeardown) {
  ASSERT_NO_FATAL_FAILURE(createRenderer());
  Renderer& r = *renderer_;
  ASSERT_TRUE(addMesh(r.scene(), cube()).ok());
  Camera camera = standardView(StandardView::kIso, r.scene().bounds(), 320.0f / 240.0f);
  int overlayCalls = 0;
  r.setOverlay([&overlayCalls](VkCommandBuffer) { ++overlayCalls; });
  for (int i = 0; i < 3; ++i) drawUntilRendered(r, camera);
  EXPECT_GE(overlayCalls, 3);

  r.simulateDeviceLossForTesting();
  auto lost = r.drawFrame(camera);
  ASSERT_FALSE(lost.ok());
  EXPECT_EQ(lost.error().code, ErrorCode::kDeviceLost) << lost.error().message;
  EXPECT_NE(lost.error().message.find("the Vulkan device was lost"), std::string::npos)
      << lost.error().message;
  EXPECT_TRUE(r.deviceLost());
  const int callsAtLoss = overlayCalls;
  for (int i = 0; i < 3; ++i) {
    auto again = r.drawFrame(camera);
    ASSERT_FALSE(again.ok());
    EXPECT_EQ(again.error().message, lost.error().message);
  }
  auto image = r.capture(camera);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.error().code, ErrorCode::kDeviceLost);
  EXPECT_FALSE(r.waitIdle().ok());
  EXPECT_EQ(overlayCalls, callsAtLoss);  // nothing more was recorded
}

// The overlay hook records inside the frame's render pass after the model (the viewer's ImGui
// panels), and capture() of a window reads back the presented image, overlay included.
TEST_F(WindowTest, OverlayIsDrawnOverTheModelAndCaptured) {
  ASSERT_NO_FATAL_FAILURE(createRenderer());
  Renderer& r = *renderer_;
  EXPECT_NE(r.renderPass(), VK_NULL_HANDLE);
  EXPECT_GE(r.framesInFlight(), 1u);
  ASSERT_TRUE(addMesh(r.scene(), cube()).ok());
  ASSERT_TRUE(r.finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, r.scene().bounds(), 320.0f / 240.0f);

  int overlayCalls = 0;
  r.setOverlay([&overlayCalls](VkCommandBuffer cmd) {
    ++overlayCalls;
    VkClearAttachment clear{};
    clear.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    clear.colorAttachment = 0;
    clear.clearValue.color = {{1.0f, 0.0f, 0.0f, 1.0f}};
    VkClearRect rect{{{0, 0}, {40, 30}}, 0, 1};  // top-left corner, over the background
    vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
    rect.rect = {{140, 100}, {40, 40}};  // window centre, over the cube
    vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
  });
  Result<RgbaImage> image = makeError(ErrorCode::kUnsupported, "not tried");
  for (int attempt = 0; attempt < 5; ++attempt) {
    image = r.capture(camera);
    if (image.ok() || image.error().code != ErrorCode::kUnsupported) break;
  }
  ASSERT_TRUE(image.ok()) << image.error().message;
  ASSERT_EQ(image->width, 320u);
  ASSERT_EQ(image->height, 240u);
  EXPECT_GE(overlayCalls, 1);
  auto px = [&](std::uint32_t x, std::uint32_t y) { return &image->pixels[(std::size_t{y} * image->width + x) * 4]; };
  for (auto [x, y] : {std::pair{10u, 10u}, std::pair{160u, 120u}}) {
    const std::uint8_t* p = px(x, y);
    EXPECT_GT(p[0], 240) << x << "," << y;
    EXPECT_LT(p[1], 16) << x << "," << y;
    EXPECT_LT(p[2], 16) << x << "," << y;
  }
  const std::uint8_t* bg = px(300, 10);  // the background gradient (bluish grey), no overlay
  EXPECT_GT(bg[2], bg[0]);
  EXPECT_GT(bg[1], 100);

  r.setOverlay({});
  auto plain = r.capture(camera);
  for (int attempt = 0; attempt < 5 && !plain.ok(); ++attempt) plain = r.capture(camera);
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  EXPECT_GT(plain->pixels[(10u * plain->width + 10u) * 4 + 1], 100);  // no red square any more
  ASSERT_TRUE(r.waitIdle().ok());
}

}  // namespace
}  // namespace cetview::test
