// Interactive camera: orbit, pan, zoom towards the cursor, fit, standard views, projection switch,
// and smooth transitions between cameras. Pure math on engine::Camera (no window, no Vulkan), so
// the viewer's mouse handling is tested without a display.
//
// Screen conventions: pixel (0,0) is the top-left corner, y grows downwards; `viewport` is the
// framebuffer size in pixels.
#pragma once

#include <glm/vec2.hpp>

#include "engine/camera.h"
#include "engine/types.h"

namespace cetview {

class CameraController {
 public:
  // Starts at `camera`; `bounds` (world) keeps the clip planes around the model.
  void reset(const engine::Camera& camera, const engine::Bounds& bounds);
  void setBounds(const engine::Bounds& bounds);

  const engine::Camera& camera() const { return camera_; }
  // Air around the model when fitting (1.1 = 10% on the tighter axis); the window leaves room for panels.
  void setFitMargin(float margin) { margin_ = margin; }

  // Turntable orbit about the target: horizontal drag turns about world Z (CAD up), vertical drag
  // tilts about the screen's right axis. 0.3 degrees per pixel.
  void orbit(glm::vec2 pixels);
  // Moves the camera so that the point under the cursor follows it (exact on the target plane).
  void pan(glm::vec2 pixels, glm::vec2 viewport);
  // Wheel `steps` (positive: closer) scale the distance (or ortho height) by 0.85 per step,
  // keeping the target-plane point under `cursor` fixed on screen.
  void zoom(float steps, glm::vec2 cursor, glm::vec2 viewport);

  // Smooth transitions (seconds = 0 jumps): to a standard view fitted to the bounds, to "fit all"
  // along the current direction, and between perspective and orthographic (same framing).
  void animateTo(const engine::Camera& target, float seconds);
  void viewStandard(engine::StandardView view, float aspect, float seconds);
  void fitAll(float aspect, float seconds);
  void setProjection(engine::Projection projection);

  // Advances a running transition by `dt` seconds.
  void update(float dt);
  bool animating() const { return animating_; }

  // Whether the ray through pixel `cursor` hits the bounds box (false: "empty space").
  bool rayHitsBounds(glm::vec2 cursor, glm::vec2 viewport) const;

 private:
  float halfHeightAtTarget() const;
  void finishMove();

  engine::Camera camera_;
  engine::Bounds bounds_;
  float margin_ = 1.1f;
  engine::Camera from_, to_;
  float elapsed_ = 0, duration_ = 0;
  bool animating_ = false;
};

}  // namespace cetview
