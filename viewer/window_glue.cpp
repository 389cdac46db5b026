#include "window_glue.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <vector>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

namespace cetview {
namespace {

// Window events (input, resize, exposure) counted for inputEvents(). One window per process. The
// callbacks are set before ImGui's backend, which installs its own and calls these from them.
std::atomic<std::uint64_t> gEvents{0};
void countEvent() { gEvents.fetch_add(1, std::memory_order_relaxed); }
void installEventCounters(GLFWwindow* w) {
  glfwSetCursorPosCallback(w, [](GLFWwindow*, double, double) { countEvent(); });
  glfwSetMouseButtonCallback(w, [](GLFWwindow*, int, int, int) { countEvent(); });
  glfwSetScrollCallback(w, [](GLFWwindow*, double, double) { countEvent(); });
  glfwSetKeyCallback(w, [](GLFWwindow*, int, int, int, int) { countEvent(); });
  glfwSetCharCallback(w, [](GLFWwindow*, unsigned int) { countEvent(); });
  glfwSetWindowFocusCallback(w, [](GLFWwindow*, int) { countEvent(); });
  glfwSetCursorEnterCallback(w, [](GLFWwindow*, int) { countEvent(); });
  glfwSetFramebufferSizeCallback(w, [](GLFWwindow*, int, int) { countEvent(); });
  glfwSetWindowRefreshCallback(w, [](GLFWwindow*) { countEvent(); });
  glfwSetWindowIconifyCallback(w, [](GLFWwindow*, int) { countEvent(); });
}

void checkImGuiVk(VkResult r) {
  if (r != VK_SUCCESS)
    std::fprintf(stderr, "cetview: ImGui Vulkan backend: VkResult %d\n", static_cast<int>(r));
}

bool isSrgb(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB ||
         format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

std::string vkFailed(const char* what, VkResult r) {
  return std::string(what) + " failed (VkResult " + std::to_string(static_cast<int>(r)) + ")";
}

}  // namespace

WindowGlue::CreateResult WindowGlue::create(const WindowOptions& options) {
  CreateResult out;
  std::unique_ptr<WindowGlue> glue(new WindowGlue());
  out.error = glue->init(options);
  if (out.error.empty()) out.glue = std::move(glue);
  return out;
}

std::string WindowGlue::init(const WindowOptions& options) {
  if (!glfwInit()) {
    const char* description = nullptr;
    glfwGetError(&description);
    return std::string("cannot open a window: ") + (description ? description : "GLFW could not initialise") +
           " (no display? try xvfb-run, or 'cetview render' for headless pictures)";
  }
  glfwReady_ = true;
  if (!glfwVulkanSupported()) return "GLFW finds no Vulkan loader";

  engine::InstanceOptions instanceOptions;
  instanceOptions.validation = options.validate;
  std::uint32_t count = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&count);
  if (!extensions) return "the window system offers no Vulkan surface extensions";
  for (std::uint32_t i = 0; i < count; ++i) instanceOptions.extensions.emplace_back(extensions[i]);
  auto instance = engine::createInstance(instanceOptions);
  if (!instance) return instance.error().message;
  instance_ = std::move(*instance);

  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!window_) return "glfwCreateWindow failed";
  if (VkResult r = glfwCreateWindowSurface(instance_.instance, window_, nullptr, &surface_);
      r != VK_SUCCESS) {
    return vkFailed("glfwCreateWindowSurface", r);
  }

  engine::DeviceOptions deviceOptions;
  deviceOptions.name = options.device;
  deviceOptions.presentSurface = surface_;
  auto device = engine::createDevice(instance_, deviceOptions);
  if (!device) return device.error().message;
  device_ = *device;

  engine::RendererOptions rendererOptions;
  rendererOptions.vsync = options.vsync;
  GLFWwindow* w = window_;
  auto renderer = engine::Renderer::createWindowed(
      device_, surface_,
      [w] {
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(w, &fw, &fh);
        return VkExtent2D{static_cast<std::uint32_t>(std::max(0, fw)),
                          static_cast<std::uint32_t>(std::max(0, fh))};
      },
      rendererOptions);
  if (!renderer) return renderer.error().message;
  renderer_ = std::move(*renderer);

  // ImGui: its own descriptor pool (the font texture), backends on this window and render pass.
  VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 4;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &poolSize;
  if (VkResult r = vkCreateDescriptorPool(device_.device, &poolInfo, nullptr, &imguiPool_); r != VK_SUCCESS) {
    return vkFailed("vkCreateDescriptorPool", r);
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  imguiContext_ = true;
  ImGui::GetIO().IniFilename = nullptr;  // the same layout every start (tests rely on it)
  ImGui::StyleColorsDark();
  if (isSrgb(renderer_->colorFormat())) {
    // ImGui's colours are meant as sRGB values written as they are; an sRGB swapchain would encode
    // them again and wash them out, so hand it their linear equivalents.
    for (ImVec4& c : ImGui::GetStyle().Colors) {
      c.x = std::pow(c.x, 2.2f);
      c.y = std::pow(c.y, 2.2f);
      c.z = std::pow(c.z, 2.2f);
    }
  }
  installEventCounters(window_);
  if (!ImGui_ImplGlfw_InitForVulkan(window_, true)) return "ImGui's GLFW backend did not initialise";
  imguiGlfw_ = true;

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = instance_.instance;
  info.PhysicalDevice = device_.physicalDevice;
  info.Device = device_.device;
  info.QueueFamily = device_.queueFamily;
  info.Queue = device_.queue;
  info.DescriptorPool = imguiPool_;
  info.Subpass = 0;
  // ImGui rotates its vertex buffers over ImageCount frames: one more than the renderer keeps in
  // flight, so a buffer is never rewritten while a frame still reads it.
  info.MinImageCount = std::max(2u, renderer_->framesInFlight());
  info.ImageCount = info.MinImageCount + 1;
  info.MSAASamples = renderer_->samples();
  info.CheckVkResultFn = checkImGuiVk;
  if (!ImGui_ImplVulkan_Init(&info, renderer_->renderPass()))
    return "ImGui's Vulkan backend did not initialise";
  imguiVulkan_ = true;

  // Font atlas upload: one command buffer, submitted and waited here, before the first frame.
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandPoolCreateInfo poolCreate{};
  poolCreate.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  poolCreate.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolCreate.queueFamilyIndex = device_.queueFamily;
  if (VkResult r = vkCreateCommandPool(device_.device, &poolCreate, nullptr, &pool); r != VK_SUCCESS) {
    return vkFailed("vkCreateCommandPool", r);
  }
  std::string error;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkCommandBufferAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  if (VkResult r = vkAllocateCommandBuffers(device_.device, &alloc, &cmd); r != VK_SUCCESS) {
    error = vkFailed("vkAllocateCommandBuffers", r);
  } else if (r = vkBeginCommandBuffer(cmd, &begin); r != VK_SUCCESS) {
    error = vkFailed("vkBeginCommandBuffer", r);
  } else if (!ImGui_ImplVulkan_CreateFontsTexture(cmd)) {
    error = "ImGui could not record its font upload";
  } else if (r = vkEndCommandBuffer(cmd); r != VK_SUCCESS) {
    error = vkFailed("vkEndCommandBuffer", r);
  } else if (r = vkQueueSubmit(device_.queue, 1, &submit, VK_NULL_HANDLE); r != VK_SUCCESS) {
    error = vkFailed("vkQueueSubmit", r);
  } else if (r = vkQueueWaitIdle(device_.queue); r != VK_SUCCESS) {
    error = vkFailed("vkQueueWaitIdle", r);
  }
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  vkDestroyCommandPool(device_.device, pool, nullptr);
  if (!error.empty()) return error;

  ImGui::GetIO().DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  renderer_->setOverlay([](VkCommandBuffer commands) {
    if (ImDrawData* data = ImGui::GetDrawData()) ImGui_ImplVulkan_RenderDrawData(data, commands);
  });
  return {};
}

WindowGlue::~WindowGlue() {
  // The last frames may still read ImGui's buffers: wait for them before ImGui frees them. Not with
  // Renderer::waitIdle(), which returns at once once the device is lost (and the loss may be
  // simulated, the real device still busy); a really lost device ends this wait at once, and its
  // result does not matter here.
  if (device_.device) (void)vkDeviceWaitIdle(device_.device);
  if (renderer_) renderer_->setOverlay({});
  if (imguiVulkan_) ImGui_ImplVulkan_Shutdown();
  if (imguiGlfw_) ImGui_ImplGlfw_Shutdown();
  if (imguiContext_) ImGui::DestroyContext();
  if (imguiPool_ != VK_NULL_HANDLE) vkDestroyDescriptorPool(device_.device, imguiPool_, nullptr);
  renderer_.reset();
  if (device_.device) engine::destroyDevice(device_);
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_.instance, surface_, nullptr);
  if (instance_.instance) engine::destroyInstance(instance_);
  if (window_) glfwDestroyWindow(window_);
  if (glfwReady_) glfwTerminate();
}

void WindowGlue::newImGuiFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void WindowGlue::finishImGuiFrame() {
  ImGui::Render();
}

std::uint64_t WindowGlue::inputEvents() const { return gEvents.load(std::memory_order_relaxed); }

}  // namespace cetview
