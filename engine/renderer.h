// The renderer: owns a Scene and its GPU copy, the upload ring, the pipelines and the frame loop,
// drawing either into a window's swapchain or into an offscreen image that capture() reads back.
// Both targets use the same render pass shape and the same pipelines.
//
// Frame loop: each drawFrame() waits only for the frame `framesInFlight` frames ago, uploads up to
// `uploadBudgetBytes` of the Scene's changes (the rest waits for later frames; a face keeps showing
// its previous triangles until its new ones are complete), records background, faces and edges,
// and submits (and presents, in a window). Not thread-safe: one thread drives a Renderer.
//
// A lost device (VK_ERROR_DEVICE_LOST from any call, or a frame the device has not finished after
// kHangTimeoutNs) is final: the call that meets it returns a kDeviceLost error, and every later
// drawFrame(), capture(), finishUploads() and waitIdle() returns that same error at once without
// touching the device. Only destroying the Renderer (and the Device) is left to do.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/attachments.h"
#include "engine/camera.h"
#include "engine/context.h"
#include "engine/gpu_scene.h"
#include "engine/image.h"
#include "engine/pipelines.h"
#include "engine/resources.h"
#include "engine/result.h"
#include "engine/scene.h"
#include "engine/swapchain.h"
#include "engine/types.h"
#include "engine/upload_ring.h"
#include "engine/view_style.h"

namespace cetview::engine {

struct RendererOptions {
  // Samples per pixel, clamped to what the device supports; 1 disables MSAA. 0 (auto): 4 on GPUs,
  // 1 on CPU devices (lavapipe), where 4x MSAA costs about three times the frame time.
  std::uint32_t msaaSamples = 0;
  // Bytes uploaded per frame at most (64 KiB .. 512 MiB); bigger changes spread over frames.
  std::uint64_t uploadBudgetBytes = 16u << 20;
  std::uint32_t framesInFlight = 2;  // 1..4
  bool vsync = true;                 // window: FIFO; false: MAILBOX/IMMEDIATE when offered
  GpuSceneOptions scene;             // initial buffer sizes, indirect draws
};

enum class FrameStatus {
  kRendered,
  kSkipped,  // window minimised (0x0), the swapchain was out of date (recreated next frame), or the
             // presentation engine gave no image within a second
};

class Renderer {
 public:
  // Reports the window's framebuffer size in pixels (0x0 while minimised); called every frame.
  using FramebufferSizeFn = std::function<VkExtent2D()>;

  // Offscreen rendering into a `extent`-sized image; capture() reads frames back.
  // Errors: kInvalidArgument (zero extent), kUnsupported (no usable colour/depth format), kVulkan...
  static Result<std::unique_ptr<Renderer>> createHeadless(const Device& device, VkExtent2D extent,
                                                          const RendererOptions& options = {});
  // Rendering into `surface` (owned by the caller; keep it alive until the Renderer is gone). The
  // Device must have been created with this surface as DeviceOptions::presentSurface.
  // Errors: kMissingExtension (no VK_KHR_swapchain), kUnsupported, kVulkan...
  static Result<std::unique_ptr<Renderer>> createWindowed(const Device& device, VkSurfaceKHR surface,
                                                          FramebufferSizeFn framebufferSize,
                                                          const RendererOptions& options = {});
  // Waits for the device to finish (a lost device returns at once), then frees everything.
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }

  // Uploads (within the budget) and draws one frame. A skipped frame (minimised, swapchain out of
  // date) still uploads, so streaming goes on. Errors: kUnsupported (wireframe without
  // fillModeNonSolid), kDeviceLost (for good: see the top of this file), kSurfaceLost,
  // kOutOfMemory, kVulkan.
  Result<FrameStatus> drawFrame(const Camera& camera, const ViewStyle& style = {});

  // Draws one frame and returns its pixels (waits for it); call finishUploads() first for a
  // picture of the whole scene. In a window the frame is also presented, overlay included.
  // Errors: kUnsupported (the surface's images cannot be copied from, or the frame was skipped:
  // minimised, out of date or no image in time; try again next frame), and drawFrame()'s.
  Result<RgbaImage> capture(const Camera& camera, const ViewStyle& style = {});

  // Extra commands recorded inside each frame's render pass (its only subpass), after the model:
  // the viewer's ImGui overlay. Called with the frame's command buffer; the pipelines it binds
  // must be made for renderPass() and samples(). An empty function removes the overlay.
  using OverlayFn = std::function<void(VkCommandBuffer)>;
  void setOverlay(OverlayFn overlay) { overlay_ = std::move(overlay); }
  // The render pass every frame uses (stable for the renderer's life unless the window's surface
  // format changes, which recreates the pipelines).
  VkRenderPass renderPass() const { return pipelines_.renderPass; }
  std::uint32_t framesInFlight() const { return options_.framesInFlight; }

  // Submits upload-only frames (same budget each) until the Scene has nothing pending, then waits.
  Status finishUploads();

  // Waits until every submitted frame has finished (at most kHangTimeoutNs per wait). Errors:
  // kDeviceLost.
  Status waitIdle();

  // Whether the device was lost (see the top of this file); the renderer only draws errors then.
  bool deviceLost() const { return lost_.has_value(); }
  // A wait for the device that lasts this long (60 s) means the device is hung: treated as lost.
  static constexpr std::uint64_t kHangTimeoutNs = 60'000'000'000ull;

  // TEST ONLY (fault injection; lavapipe never loses its device): the next queue submission, fence
  // wait or device wait the renderer checks reports VK_ERROR_DEVICE_LOST instead of its real
  // result, and the renderer is lost from then on as after a real loss. The call itself still
  // runs, so the real device stays usable and destruction is a real cleanup.
  void simulateDeviceLossForTesting() { simulateLoss_ = true; }

  bool headless() const { return surface_ == VK_NULL_HANDLE; }
  VkExtent2D extent() const { return extent_; }  // of the last frame's target (window: swapchain)
  float aspect() const;
  VkSampleCountFlagBits samples() const { return format_.samples; }
  VkFormat colorFormat() const { return format_.color; }
  const UploadStats& lastUploadStats() const { return lastUpload_; }
  // Triangles the GPU draws per instance of every part (whole faces only: a face being replaced
  // counts its previous array until the new one is complete).
  std::uint64_t committedTriangles() const { return gpuScene_->committedTriangles(); }
  std::uint32_t swapchainRecreations() const { return recreations_; }
  // Whether faces are drawn with multi-draw indirect (see GpuSceneOptions) or one call per run of
  // faces (gpu_scene.h).
  bool usesIndirectDraws() const { return gpuScene_->usesIndirectDraws(); }
  // One by one: whether the runs of one colour go in one VK_EXT_multi_draw call (gpu_scene.h).
  bool usesMultiDraw() const { return gpuScene_->usesMultiDraw(); }
  // Draw calls the last rendered frame issued for faces and for edges (one by one: one per run of
  // adjacent slots, or with multi-draw one per colour, see gpu_scene.h; indirect: one per
  // multi-draw indirect call).
  std::uint32_t lastFaceDrawCalls() const { return gpuScene_->lastFaceDrawCalls(); }
  std::uint32_t lastEdgeDrawCalls() const { return gpuScene_->lastEdgeDrawCalls(); }
  // Clusters of up to kClusterTriangles triangles of a face (per instance) the last rendered frame
  // did not draw: outside the view, or wholly back-facing on a culled closed solid (one-by-one
  // draws only; see gpu_scene.h and face_culling.h). A face of fewer triangles is one cluster.
  std::uint32_t lastClustersCulled() const { return gpuScene_->lastClustersCulled(); }
  const Device& device() const { return device_; }

  // Images in the swapchain (window; 0 before the first frame), e.g. for ImGui's Vulkan backend.
  std::uint32_t swapchainImageCount() const { return static_cast<std::uint32_t>(swapchain_.images.size()); }

 private:
  struct Frame {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    VkSemaphore acquired = VK_NULL_HANDLE;  // window: the swapchain image is ready
    Buffer globals;                         // gpu::Globals, host-visible
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkBuffer boundFaces = VK_NULL_HANDLE;  // the face colour buffer the set points at
    std::uint64_t serial = 0;              // of the last submission that used this frame
    std::uint64_t ringMark = 0;            // upload ring position after that submission
    bool inFlight = false;                 // submitted, its fence not yet waited for
  };

  Renderer(const Device& device, const RendererOptions& options);
  Status createCommon();
  Status createFrames();
  Status createHeadlessTarget(VkExtent2D extent);
  // Window: makes the swapchain match the framebuffer; false while minimised.
  Result<bool> prepareSwapchain();
  Status recreateSwapchain(VkExtent2D framebuffer, bool* minimised);
  void destroySwapchainResources();
  // The result of a submission or wait as the renderer sees it: `real`, or VK_ERROR_DEVICE_LOST
  // once after simulateDeviceLossForTesting().
  VkResult deviceResult(VkResult real);
  // Waits for `fences` (all of them) for at most kHangTimeoutNs; a timeout is a kDeviceLost error.
  Status waitFences(const VkFence* fences, std::uint32_t count);
  Status waitDeviceIdle();  // every frame's fence, then vkDeviceWaitIdle
  // Remembers a kDeviceLost error: the renderer is lost from now on.
  void noteLoss(const Error& error);
  Status waitForFrame(Frame& frame);
  // One frame: with `camera` null, uploads only; with `capture`, also copies the image to readback_.
  Result<FrameStatus> runFrame(const Camera* camera, const ViewStyle* style, bool capture);
  Result<RgbaImage> captureFrame(const Camera& camera, const ViewStyle& style);  // capture() itself
  void writeGlobals(Frame& frame, const ViewStyle& style);
  void updateDescriptors(Frame& frame);
  void recordRenderPass(Frame& frame, VkFramebuffer framebuffer, const Camera& camera,
                        const ViewStyle& style);

  const Device& device_;
  RendererOptions options_;
  Scene scene_;
  std::unique_ptr<GpuScene> gpuScene_;
  UploadRing ring_;
  TargetFormat format_;
  Pipelines pipelines_;
  Attachments attachments_;
  VkExtent2D extent_{0, 0};
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  std::vector<Frame> frames_;
  std::uint64_t frameIndex_ = 0;
  std::uint64_t serial_ = 0;
  std::deque<std::pair<std::uint64_t, Buffer>> retired_;  // (serial of the last frame using it, buffer)
  UploadStats lastUpload_;
  OverlayFn overlay_;

  // Headless target.
  Image offscreen_;
  Buffer readback_;  // headless: made with the target; window: made by the first capture

  // Window target.
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  FramebufferSizeFn framebufferSize_;
  Swapchain swapchain_;
  VkExtent2D swapchainFramebuffer_{0, 0};  // framebufferSize_() when the swapchain was made
  std::vector<VkSemaphore> renderDone_;    // one per swapchain image
  bool needRecreate_ = true;
  std::uint32_t recreations_ = 0;

  std::optional<Error> lost_;  // the error that lost the device; returned by every later call
  bool simulateLoss_ = false;  // simulateDeviceLossForTesting() is pending
};

}  // namespace cetview::engine
