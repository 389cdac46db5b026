#include "engine/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "engine/gpu_structs.h"
#include "engine/vk_check.h"

namespace cetview::engine {
namespace {

// A colour format for the offscreen image that can be rendered to and copied from, in the window's
// order of preference (preferSrgbTarget()), so headless frames match the window's.
Result<VkFormat> chooseOffscreenFormat(const Device& device, VkSampleCountFlagBits samples) {
  constexpr VkFormatFeatureFlags kNeeded =
      VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
  const bool srgbFirst = preferSrgbTarget(device, samples);
  for (VkFormat format : {srgbFirst ? VK_FORMAT_B8G8R8A8_SRGB : VK_FORMAT_B8G8R8A8_UNORM,
                          srgbFirst ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                          srgbFirst ? VK_FORMAT_B8G8R8A8_UNORM : VK_FORMAT_B8G8R8A8_SRGB,
                          srgbFirst ? VK_FORMAT_R8G8B8A8_UNORM : VK_FORMAT_R8G8B8A8_SRGB}) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(device.physicalDevice, format, &props);
    if ((props.optimalTilingFeatures & kNeeded) == kNeeded) return format;
  }
  return makeError(ErrorCode::kUnsupported, "the device cannot render to any 8-bit RGBA format");
}

bool isBgr(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_B8G8R8A8_UNORM;
}

// Acquiring a swapchain image waits at most this long; then the frame is skipped (the presentation
// engine may hold every image for a while, e.g. a hidden window's FIFO; that is no lost device).
constexpr std::uint64_t kAcquireTimeoutNs = 1'000'000'000ull;

}  // namespace

Renderer::Renderer(const Device& device, const RendererOptions& options)
    : device_(device), options_(options) {
  options_.framesInFlight = std::clamp<std::uint32_t>(options_.framesInFlight, 1, 4);
  options_.uploadBudgetBytes = std::clamp<std::uint64_t>(options_.uploadBudgetBytes, 64u << 10, 512u << 20);
  if (options_.msaaSamples == 0) {
    options_.msaaSamples = device.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1 : 4;
  }
}

Result<std::unique_ptr<Renderer>> Renderer::createHeadless(const Device& device, VkExtent2D extent,
                                                           const RendererOptions& options) {
  if (extent.width == 0 || extent.height == 0) {
    return makeError(ErrorCode::kInvalidArgument, "headless image size must be at least 1x1");
  }
  std::unique_ptr<Renderer> r(new Renderer(device, options));
  auto color = chooseOffscreenFormat(device, chooseSampleCount(device, r->options_.msaaSamples));
  CETVIEW_TRY(color);
  r->format_.color = *color;
  r->format_.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  CETVIEW_TRY(r->createCommon());
  CETVIEW_TRY(r->createHeadlessTarget(extent));
  return r;
}

Result<std::unique_ptr<Renderer>> Renderer::createWindowed(const Device& device, VkSurfaceKHR surface,
                                                           FramebufferSizeFn framebufferSize,
                                                           const RendererOptions& options) {
  if (surface == VK_NULL_HANDLE || !framebufferSize) {
    return makeError(ErrorCode::kInvalidArgument, "a windowed renderer needs a surface and a size callback");
  }
  if (!device.swapchainExtension) {
    return makeError(ErrorCode::kMissingExtension, "device '" + device.name + "' has no VK_KHR_swapchain");
  }
  std::unique_ptr<Renderer> r(new Renderer(device, options));
  r->surface_ = surface;
  r->framebufferSize_ = std::move(framebufferSize);
  auto format = chooseSurfaceFormat(device, surface, chooseSampleCount(device, r->options_.msaaSamples));
  CETVIEW_TRY(format);
  r->swapchain_.format = *format;
  r->format_.color = format->format;
  r->format_.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  CETVIEW_TRY(r->createCommon());
  return r;
}

Status Renderer::createCommon() {
  auto depth = chooseDepthFormat(device_);
  CETVIEW_TRY(depth);
  format_.depth = *depth;
  format_.samples = chooseSampleCount(device_, options_.msaaSamples);
  auto gpuScene = GpuScene::create(device_, scene_, options_.scene);
  CETVIEW_TRY(gpuScene);
  gpuScene_ = std::move(*gpuScene);
  // One-by-one draws push each run's colour; indirect ones read the face table.
  auto pipelines = createPipelines(device_, format_, !gpuScene_->usesIndirectDraws());
  CETVIEW_TRY(pipelines);
  pipelines_ = *pipelines;

  // Every frame in flight holds at most a budget, and the one being recorded another; a block
  // that does not fit before the ring's end skips the rest of the lap, and in that rare case the
  // upload simply continues next frame.
  auto ring = UploadRing::create(device_, options_.uploadBudgetBytes * (options_.framesInFlight + 1));
  CETVIEW_TRY(ring);
  ring_ = *ring;
  return createFrames();
}

Status Renderer::createFrames() {
  std::uint32_t n = options_.framesInFlight;
  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, n},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n}};
  auto poolInfo = vkInit<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  poolInfo.maxSets = n;
  poolInfo.poolSizeCount = 2;
  poolInfo.pPoolSizes = sizes;
  CETVIEW_VK(vkCreateDescriptorPool(device_.device, &poolInfo, nullptr, &descriptorPool_));

  frames_.resize(n);
  for (Frame& f : frames_) {
    auto pool = vkInit<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = device_.queueFamily;
    CETVIEW_VK(vkCreateCommandPool(device_.device, &pool, nullptr, &f.pool));
    auto alloc = vkInit<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = f.pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    CETVIEW_VK(vkAllocateCommandBuffers(device_.device, &alloc, &f.cmd));
    auto fence = vkInit<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    CETVIEW_VK(vkCreateFence(device_.device, &fence, nullptr, &f.fence));
    auto semaphore = vkInit<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    CETVIEW_VK(vkCreateSemaphore(device_.device, &semaphore, nullptr, &f.acquired));
    auto globals =
        createBuffer(device_, sizeof(Globals), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::kUpload);
    CETVIEW_TRY(globals);
    f.globals = *globals;
    auto setInfo = vkInit<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    setInfo.descriptorPool = descriptorPool_;
    setInfo.descriptorSetCount = 1;
    setInfo.pSetLayouts = &pipelines_.setLayout;
    CETVIEW_VK(vkAllocateDescriptorSets(device_.device, &setInfo, &f.set));
  }
  return {};
}

Status Renderer::createHeadlessTarget(VkExtent2D extent) {
  auto image = createImage(device_, extent, format_.color,
                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
  CETVIEW_TRY(image);
  offscreen_ = *image;
  auto readback = createBuffer(device_, VkDeviceSize{extent.width} * extent.height * 4,
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kReadback);
  CETVIEW_TRY(readback);
  readback_ = *readback;
  auto attachments = createAttachments(device_, pipelines_.renderPass, format_, extent, {offscreen_.view});
  CETVIEW_TRY(attachments);
  attachments_ = *attachments;
  extent_ = extent;
  return {};
}

Renderer::~Renderer() {
  // Its result does not matter: a lost device returns at once, and everything is freed either way.
  if (device_.device != VK_NULL_HANDLE) (void)vkDeviceWaitIdle(device_.device);
  gpuScene_.reset();
  for (auto& r : retired_) destroyBuffer(device_, r.second);
  for (Frame& f : frames_) {
    if (f.pool) vkDestroyCommandPool(device_.device, f.pool, nullptr);
    if (f.fence) vkDestroyFence(device_.device, f.fence, nullptr);
    if (f.acquired) vkDestroySemaphore(device_.device, f.acquired, nullptr);
    destroyBuffer(device_, f.globals);
  }
  if (descriptorPool_) vkDestroyDescriptorPool(device_.device, descriptorPool_, nullptr);
  destroySwapchainResources();
  destroySwapchain(device_, swapchain_);
  destroyAttachments(device_, attachments_);
  destroyImage(device_, offscreen_);
  destroyBuffer(device_, readback_);
  ring_.destroy(device_);
  destroyPipelines(device_, pipelines_);
}

float Renderer::aspect() const {
  if (extent_.width == 0 || extent_.height == 0) return 1.0f;
  return static_cast<float>(extent_.width) / static_cast<float>(extent_.height);
}

Status Renderer::waitIdle() {
  if (lost_) return *lost_;
  Status status = waitDeviceIdle();
  if (!status) noteLoss(status.error());
  return status;
}

Status Renderer::waitDeviceIdle() {
  // Every submission signals its frame's fence: wait for them with a time limit first, so a hung
  // device becomes an error instead of blocking vkDeviceWaitIdle forever.
  std::vector<VkFence> fences;
  for (const Frame& f : frames_) {
    if (f.inFlight) fences.push_back(f.fence);
  }
  if (!fences.empty()) CETVIEW_TRY(waitFences(fences.data(), static_cast<std::uint32_t>(fences.size())));
  for (Frame& f : frames_) f.inFlight = false;
  if (VkResult r = deviceResult(vkDeviceWaitIdle(device_.device)); r != VK_SUCCESS) {
    return vkError("vkDeviceWaitIdle", r);
  }
  return {};
}

VkResult Renderer::deviceResult(VkResult real) {
  if (!simulateLoss_) return real;
  simulateLoss_ = false;
  return VK_ERROR_DEVICE_LOST;
}

Status Renderer::waitFences(const VkFence* fences, std::uint32_t count) {
  VkResult r = deviceResult(vkWaitForFences(device_.device, count, fences, VK_TRUE, kHangTimeoutNs));
  if (r == VK_TIMEOUT) {
    return makeError(ErrorCode::kDeviceLost,
                     "the Vulkan device was lost (no frame finished in " +
                         std::to_string(kHangTimeoutNs / 1'000'000'000ull) +
                         " s: VK_TIMEOUT in vkWaitForFences): the device or its driver hung");
  }
  if (r != VK_SUCCESS) return vkError("vkWaitForFences", r);
  return {};
}

void Renderer::noteLoss(const Error& error) {
  if (error.code == ErrorCode::kDeviceLost && !lost_) lost_ = error;
}

void Renderer::destroySwapchainResources() {
  for (VkSemaphore s : renderDone_) vkDestroySemaphore(device_.device, s, nullptr);
  renderDone_.clear();
  if (surface_ != VK_NULL_HANDLE) destroyAttachments(device_, attachments_);
}

Status Renderer::recreateSwapchain(VkExtent2D framebuffer, bool* minimised) {
  *minimised = false;
  CETVIEW_TRY(waitDeviceIdle());
  auto extent = surfaceExtent(device_, surface_, framebuffer);
  CETVIEW_TRY(extent);
  if (extent->width == 0 || extent->height == 0) {
    *minimised = true;
    return {};
  }
  auto format = chooseSurfaceFormat(device_, surface_, format_.samples);
  CETVIEW_TRY(format);
  auto fresh = createSwapchain(device_, surface_, *format, *extent, options_.vsync, swapchain_.swapchain);
  CETVIEW_TRY(fresh);
  destroySwapchainResources();
  destroySwapchain(device_, swapchain_);
  swapchain_ = std::move(*fresh);
  ++recreations_;

  if (format->format != format_.color) {
    // The pipelines are compiled against the render pass's format. After a failure the format is
    // left unknown, so the next recreation tries again instead of drawing with no pipelines.
    format_.color = format->format;
    Status pipelines = recreatePipelines(device_, format_, pipelines_);
    if (!pipelines) {
      format_.color = VK_FORMAT_UNDEFINED;
      return pipelines.error();
    }
  }
  auto attachments =
      createAttachments(device_, pipelines_.renderPass, format_, swapchain_.extent, swapchain_.views);
  CETVIEW_TRY(attachments);
  attachments_ = *attachments;
  for (std::size_t i = 0; i < swapchain_.images.size(); ++i) {
    auto info = vkInit<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    VkSemaphore s = VK_NULL_HANDLE;
    CETVIEW_VK(vkCreateSemaphore(device_.device, &info, nullptr, &s));
    renderDone_.push_back(s);
  }
  swapchainFramebuffer_ = framebuffer;
  extent_ = swapchain_.extent;
  needRecreate_ = false;
  return {};
}

Result<bool> Renderer::prepareSwapchain() {
  VkExtent2D framebuffer = framebufferSize_();
  if (framebuffer.width == 0 || framebuffer.height == 0) return false;  // minimised
  bool resized =
      framebuffer.width != swapchainFramebuffer_.width || framebuffer.height != swapchainFramebuffer_.height;
  if (!needRecreate_ && !resized && swapchain_.swapchain != VK_NULL_HANDLE) return true;
  bool minimised = false;
  CETVIEW_TRY(recreateSwapchain(framebuffer, &minimised));
  return !minimised;
}

Status Renderer::waitForFrame(Frame& frame) {
  // A frame whose submission failed (or never happened) has no fence to wait for: waiting on its
  // reset fence would only time out.
  if (frame.inFlight) CETVIEW_TRY(waitFences(&frame.fence, 1));
  frame.inFlight = false;
  // Frames are waited in submission order, so every serial up to this one has finished.
  ring_.release(frame.ringMark);
  while (!retired_.empty() && retired_.front().first <= frame.serial) {
    destroyBuffer(device_, retired_.front().second);
    retired_.pop_front();
  }
  return {};
}

void Renderer::writeGlobals(Frame& frame, const ViewStyle& style) {
  Globals g{};
  g.backgroundTop = linearColor(style.backgroundTop);
  g.backgroundBottom = linearColor(style.backgroundBottom);
  g.edgeColor = linearColor(style.edgeColor);
  std::memcpy(frame.globals.mapped, &g, sizeof(g));
}

void Renderer::updateDescriptors(Frame& frame) {
  VkBuffer faces = gpuScene_->faceColorBuffer();
  if (frame.boundFaces == faces) return;
  VkDescriptorBufferInfo infos[2] = {{frame.globals.buffer, 0, sizeof(Globals)}, {faces, 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[2];
  for (int i = 0; i < 2; ++i) {
    writes[i] = vkInit<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[i].dstSet = frame.set;
    writes[i].dstBinding = i == 0 ? CETVIEW_BINDING_GLOBALS : CETVIEW_BINDING_FACES;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(device_.device, 2, writes, 0, nullptr);
  frame.boundFaces = faces;
}

void Renderer::recordRenderPass(Frame& frame, VkFramebuffer framebuffer, const Camera& camera,
                                const ViewStyle& style) {
  VkCommandBuffer cmd = frame.cmd;
  VkClearValue clears[3]{};
  clears[1].depthStencil = {1.0f, 0};
  auto begin = vkInit<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
  begin.renderPass = pipelines_.renderPass;
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent_};
  begin.clearValueCount = format_.samples != VK_SAMPLE_COUNT_1_BIT ? 3u : 2u;
  begin.pClearValues = clears;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);

  VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent_.width), static_cast<float>(extent_.height),
                      0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, extent_};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.layout, 0, 1, &frame.set, 0,
                          nullptr);

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.background);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  FrameView view = makeFrameView(camera, aspect(), style);
  if (style.mode == DisplayMode::kWireframe) {
    gpuScene_->recordFaceDraws(cmd, pipelines_.layout, view, pipelines_.wireframe, pipelines_.wireframe);
  } else {
    gpuScene_->recordFaceDraws(cmd, pipelines_.layout, view, pipelines_.shaded, pipelines_.shadedCulled);
    if (style.mode == DisplayMode::kShadedWithEdges) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.edges);
      gpuScene_->recordEdgeDraws(cmd, pipelines_.layout, view);
    }
  }
  if (overlay_) overlay_(cmd);
  vkCmdEndRenderPass(cmd);
}

Result<FrameStatus> Renderer::runFrame(const Camera* camera, const ViewStyle* style, bool capture) {
  if (style && style->mode == DisplayMode::kWireframe && pipelines_.wireframe == VK_NULL_HANDLE) {
    return makeError(ErrorCode::kUnsupported,
                     "wireframe needs fillModeNonSolid, which '" + device_.name + "' lacks");
  }
  Frame& frame = frames_[frameIndex_ % frames_.size()];
  CETVIEW_TRY(waitForFrame(frame));

  bool present = camera != nullptr && !headless();
  std::uint32_t imageIndex = 0;
  if (present) {
    // Nothing to draw into (minimised, or the swapchain is out of date): the frame still uploads,
    // so streaming continues and the progressive loader is not held back.
    auto ready = prepareSwapchain();
    CETVIEW_TRY(ready);
    VkResult r = VK_ERROR_OUT_OF_DATE_KHR;
    if (*ready) {
      r = vkAcquireNextImageKHR(device_.device, swapchain_.swapchain, kAcquireTimeoutNs, frame.acquired,
                                VK_NULL_HANDLE, &imageIndex);
      if (r == VK_ERROR_OUT_OF_DATE_KHR) needRecreate_ = true;
    }
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_TIMEOUT || r == VK_NOT_READY) {
      present = false;
      camera = nullptr;
    } else if (r == VK_SUBOPTIMAL_KHR) {
      needRecreate_ = true;  // still usable: draw and present it, recreate next frame
    } else if (r != VK_SUCCESS) {
      return vkError("vkAcquireNextImageKHR", r);
    }
  }
  if (capture && present) {
    if (!swapchain_.transferSrc) {
      return makeError(ErrorCode::kUnsupported,
                       "this window surface's images cannot be copied (no screenshot)");
    }
    // Frames in flight never read back (capture waits for its own frame), so the old buffer is free.
    const VkDeviceSize bytes = VkDeviceSize{extent_.width} * extent_.height * 4;
    if (readback_.size != bytes) {
      destroyBuffer(device_, readback_);
      auto readback = createBuffer(device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kReadback);
      CETVIEW_TRY(readback);
      readback_ = *readback;
    }
  }

  CETVIEW_VK(vkResetFences(device_.device, 1, &frame.fence));
  CETVIEW_VK(vkResetCommandPool(device_.device, frame.pool, 0));
  auto begin = vkInit<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  CETVIEW_VK(vkBeginCommandBuffer(frame.cmd, &begin));

  std::uint64_t serial = ++serial_;
  std::vector<Buffer> retired;
  Status uploaded =
      gpuScene_->recordUploads(frame.cmd, ring_, options_.uploadBudgetBytes, retired, &lastUpload_);
  for (Buffer& b : retired) retired_.emplace_back(serial, b);
  frame.serial = serial;
  frame.ringMark = ring_.mark();

  // After a failed upload the frame still submits what was staged (GpuScene's bookkeeping counts
  // it as done), but draws nothing; the error is returned once the submission is out.
  bool render = camera != nullptr && uploaded.ok();
  if (render) {
    writeGlobals(frame, *style);
    updateDescriptors(frame);
    VkFramebuffer framebuffer = attachments_.framebuffers[present ? imageIndex : 0];
    recordRenderPass(frame, framebuffer, *camera, *style);
    if (capture && present) {
      // The presented image: PRESENT_SRC -> TRANSFER_SRC, copy, and back for the presentation.
      VkImage image = swapchain_.images[imageIndex];
      auto toCopy = vkInit<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
      toCopy.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
      toCopy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      toCopy.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
      toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      toCopy.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      toCopy.image = image;
      toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &toCopy);
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {extent_.width, extent_.height, 1};
      vkCmdCopyImageToBuffer(frame.cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1,
                             &region);
      auto toPresent = toCopy;
      toPresent.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      toPresent.dstAccessMask = 0;
      toPresent.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      toPresent.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
      vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0,
                           0, nullptr, 0, nullptr, 1, &toPresent);
      memoryBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    } else if (capture) {
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {extent_.width, extent_.height, 1};
      vkCmdCopyImageToBuffer(frame.cmd, offscreen_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             readback_.buffer, 1, &region);
      memoryBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    }
  }
  CETVIEW_VK(vkEndCommandBuffer(frame.cmd));

  VkPipelineStageFlags waitStage =
      present && render ? VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT : VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
  auto submit = vkInit<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &frame.cmd;
  if (present) {
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &frame.acquired;
    submit.pWaitDstStageMask = &waitStage;
  }
  if (present && render) {
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderDone_[imageIndex];
  }
  if (VkResult r = deviceResult(vkQueueSubmit(device_.queue, 1, &submit, frame.fence)); r != VK_SUCCESS) {
    return vkError("vkQueueSubmit", r);
  }
  frame.inFlight = true;
  ++frameIndex_;
  if (!uploaded) {
    if (present) needRecreate_ = true;  // the acquired image was not drawn: start from a fresh swapchain
    return uploaded.error();
  }

  if (present) {
    auto info = vkInit<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &renderDone_[imageIndex];
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_.swapchain;
    info.pImageIndices = &imageIndex;
    VkResult r = vkQueuePresentKHR(device_.queue, &info);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
      needRecreate_ = true;
    } else if (r != VK_SUCCESS) {
      return vkError("vkQueuePresentKHR", r);
    }
  }
  return camera != nullptr ? FrameStatus::kRendered : FrameStatus::kSkipped;
}

Result<FrameStatus> Renderer::drawFrame(const Camera& camera, const ViewStyle& style) {
  if (lost_) return *lost_;
  auto status = runFrame(&camera, &style, false);
  if (!status) noteLoss(status.error());
  return status;
}

Result<RgbaImage> Renderer::capture(const Camera& camera, const ViewStyle& style) {
  if (lost_) return *lost_;
  auto image = captureFrame(camera, style);
  if (!image) noteLoss(image.error());
  return image;
}

Result<RgbaImage> Renderer::captureFrame(const Camera& camera, const ViewStyle& style) {
  Frame& frame = frames_[frameIndex_ % frames_.size()];
  auto status = runFrame(&camera, &style, true);
  CETVIEW_TRY(status);
  if (*status == FrameStatus::kSkipped) {
    return makeError(ErrorCode::kUnsupported,
                     "the window frame was skipped (minimised, out of date, or no image in time)");
  }
  CETVIEW_TRY(waitFences(&frame.fence, 1));
  frame.inFlight = false;
  CETVIEW_TRY(invalidateForHost(device_, readback_));

  RgbaImage image;
  image.width = extent_.width;
  image.height = extent_.height;
  image.pixels.resize(std::size_t{extent_.width} * extent_.height * 4);
  const auto* src = static_cast<const std::uint8_t*>(readback_.mapped);
  std::memcpy(image.pixels.data(), src, image.pixels.size());
  if (isBgr(format_.color)) {
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) std::swap(image.pixels[i], image.pixels[i + 2]);
  }
  return image;
}

Status Renderer::finishUploads() {
  if (lost_) return *lost_;
  while (scene_.uploadsPending()) {
    auto status = runFrame(nullptr, nullptr, false);
    if (!status) noteLoss(status.error());
    CETVIEW_TRY(status);
    if (lastUpload_.bytes == 0 && lastUpload_.facesCompleted == 0 && lastUpload_.edgesCompleted == 0 &&
        scene_.uploadsPending()) {
      return makeError(ErrorCode::kVulkan, "upload made no progress (ring smaller than one item?)");
    }
  }
  return waitIdle();
}

}  // namespace cetview::engine
