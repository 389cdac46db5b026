// The viewer's window glue: the one place where GLFW, ImGui's GLFW and Vulkan backends and the
// engine's Vulkan handles meet (DESIGN.md allows this glue in viewer/). It opens a GLFW window,
// makes the engine's instance, device and windowed renderer for its surface, and draws ImGui's
// frame through the renderer's overlay hook. Everything else in the viewer sees only the engine's
// API and ImGui's plain calls.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "engine/context.h"
#include "engine/renderer.h"

struct GLFWwindow;

namespace cetview {

struct WindowOptions {
  int width = 1280, height = 800;
  std::string title = "cetview";
  std::string device;     // substring of the Vulkan device name
  bool validate = false;  // VK_LAYER_KHRONOS_validation; its reports are counted in validationCount()
  bool vsync = true;
};

class WindowGlue {
 public:
  struct CreateResult {
    std::unique_ptr<WindowGlue> glue;  // null on error
    std::string error;
  };
  // Initialises GLFW (no display: an error), the window, Vulkan and ImGui (context, style, both
  // backends, font upload).
  static CreateResult create(const WindowOptions& options);
  ~WindowGlue();
  WindowGlue(const WindowGlue&) = delete;
  WindowGlue& operator=(const WindowGlue&) = delete;

  GLFWwindow* window() const { return window_; }
  engine::Renderer& renderer() { return *renderer_; }
  const engine::Device& device() const { return device_; }
  std::uint32_t validationCount() const { return instance_.log ? instance_.log->count() : 0; }

  // Window events so far (mouse, keys, scroll, focus, resize, exposure, minimise): a change means
  // the next frame is worth drawing.
  std::uint64_t inputEvents() const;

  // Starts an ImGui frame (both backends, then ImGui::NewFrame()).
  void newImGuiFrame();
  // ImGui::Render(), and the renderer's next frame draws that ImGui frame over the model.
  void finishImGuiFrame();

 private:
  WindowGlue() = default;
  std::string init(const WindowOptions& options);

  GLFWwindow* window_ = nullptr;
  bool glfwReady_ = false;
  engine::Instance instance_;
  engine::Device device_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  std::unique_ptr<engine::Renderer> renderer_;
  VkDescriptorPool imguiPool_ = VK_NULL_HANDLE;
  bool imguiContext_ = false, imguiGlfw_ = false, imguiVulkan_ = false;
};

}  // namespace cetview
