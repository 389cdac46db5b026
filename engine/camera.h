// Camera: perspective or orthographic, standard views and fit-to-bounds. Pure math (GLM), no Vulkan
// calls, so it is tested without a GPU.
//
// World convention (CAD, as OpenCASCADE's V3d): Z up. The front view looks along +Y, the right view
// along -X, the top view down -Z with +Y up the screen. Matrices follow Vulkan: right-handed view
// space looking down -z, clip-space y pointing down, depth in [0, 1].
#pragma once

#include <optional>
#include <string_view>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "engine/types.h"

namespace cetview::engine {

enum class Projection { kPerspective, kOrthographic };

enum class StandardView { kIso, kFront, kBack, kLeft, kRight, kTop, kBottom };

struct Camera {
  glm::vec3 target{0.0f};                 // the point looked at (and orbited about)
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit vector from the eye towards the target
  glm::vec3 up{0.0f, 0.0f, 1.0f};         // unit, perpendicular to direction
  float distance = 10.0f;                 // eye = target - direction * distance
  Projection projection = Projection::kPerspective;
  float fovY = 0.5235988f;    // perspective: vertical field of view in radians (30 degrees)
  float orthoHeight = 10.0f;  // orthographic: visible height in world units
  float nearPlane = 0.1f;     // > 0 for perspective
  float farPlane = 100.0f;

  glm::vec3 eye() const { return target - direction * distance; }
};

// The direction from the eye to the target and the screen-up vector of a standard view.
glm::vec3 viewDirection(StandardView view);
glm::vec3 viewUp(StandardView view);

// "iso", "front", "back", "left", "right", "top", "bottom" (the viewer's --view values).
const char* viewName(StandardView view);
std::optional<StandardView> parseStandardView(std::string_view name);

// Aims the camera along a standard view and fits `bounds` (see fitToBounds).
Camera standardView(StandardView view, const Bounds& bounds, float aspect,
                    Projection projection = Projection::kPerspective);

// Keeps the direction, up and projection; moves the target to the box centre and sets the distance
// (perspective) or orthoHeight (orthographic) so that all eight corners of `bounds` project inside
// the viewport with `margin` (1.1 = 10% air on the tighter axis). Also calls updateClipPlanes().
// An empty box leaves the camera unchanged; a box of zero size is treated as a unit box.
void fitToBounds(Camera& camera, const Bounds& bounds, float aspect, float margin = 1.1f);

// Near and far planes that enclose the sphere around `bounds` from the current eye, with near
// kept positive for perspective (a depth range of at most 1e5). Call after moving the camera.
void updateClipPlanes(Camera& camera, const Bounds& bounds);

glm::mat4 viewMatrix(const Camera& camera);
glm::mat4 projectionMatrix(const Camera& camera, float aspect);

}  // namespace cetview::engine
