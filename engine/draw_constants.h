// Per-draw constants: each instance's transform into clip space and its normals' rotation into
// view space, where the lights are constant, and the colour mode (shaders/shared.h, DrawConstants).
// Pure math, so it is tested without a GPU.
#pragma once

#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/camera.h"
#include "engine/gpu_structs.h"
#include "engine/view_style.h"

namespace cetview::engine {

// World-space view of one frame, computed once and shared by every draw.
struct FrameView {
  glm::mat4 viewProj{1.0f};
  glm::mat3 viewRotation{1.0f};           // world -> view space for directions
  glm::vec3 towardsEye{0.0f};             // unit, opposite the view direction
  glm::vec4 eye{0.0f, 0.0f, 0.0f, 1.0f};  // perspective: (eye, 1); orthographic: (towardsEye, 0)
  std::optional<glm::vec4> forcedColor;   // linear; set when file colours are off
};

// The key light, in view space: from the upper left, in front of the model (shared.h's rig).
glm::vec3 keyLightInView();

FrameView makeFrameView(const Camera& camera, float aspect, const ViewStyle& style);

// Constants for drawing one instance placed by `model` (part -> world: rigid, uniformly scaled,
// possibly mirrored), with its colour override.
DrawConstants drawConstants(const FrameView& view, const glm::mat4& model,
                            const std::optional<Color8>& color);

}  // namespace cetview::engine
