#include "engine/camera.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

namespace cetview::engine {
namespace {

// The box to fit: a zero-size box becomes a unit box around its point.
Bounds fitBox(const Bounds& bounds) {
  Bounds box = bounds;
  if (box.radius() <= 0.0f) {
    box.add(bounds.min - glm::vec3(0.5f));
    box.add(bounds.min + glm::vec3(0.5f));
  }
  return box;
}

std::array<glm::vec3, 8> corners(const Bounds& b) {
  std::array<glm::vec3, 8> c;
  for (int i = 0; i < 8; ++i) {
    c[i] = glm::vec3((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
  }
  return c;
}

}  // namespace

glm::vec3 viewDirection(StandardView view) {
  switch (view) {
    case StandardView::kIso:
      return glm::normalize(glm::vec3(-1.0f, 1.0f, -1.0f));  // from +x, -y, +z
    case StandardView::kFront:
      return {0.0f, 1.0f, 0.0f};
    case StandardView::kBack:
      return {0.0f, -1.0f, 0.0f};
    case StandardView::kLeft:
      return {1.0f, 0.0f, 0.0f};
    case StandardView::kRight:
      return {-1.0f, 0.0f, 0.0f};
    case StandardView::kTop:
      return {0.0f, 0.0f, -1.0f};
    case StandardView::kBottom:
      return {0.0f, 0.0f, 1.0f};
  }
  return {0.0f, 1.0f, 0.0f};
}

glm::vec3 viewUp(StandardView view) {
  switch (view) {
    case StandardView::kTop:
      return {0.0f, 1.0f, 0.0f};
    case StandardView::kBottom:
      return {0.0f, -1.0f, 0.0f};
    case StandardView::kIso: {
      // World Z with its component along the view direction removed.
      glm::vec3 d = viewDirection(view);
      glm::vec3 z(0.0f, 0.0f, 1.0f);
      return glm::normalize(z - d * glm::dot(z, d));
    }
    default:
      return {0.0f, 0.0f, 1.0f};
  }
}

const char* viewName(StandardView view) {
  switch (view) {
    case StandardView::kIso:
      return "iso";
    case StandardView::kFront:
      return "front";
    case StandardView::kBack:
      return "back";
    case StandardView::kLeft:
      return "left";
    case StandardView::kRight:
      return "right";
    case StandardView::kTop:
      return "top";
    case StandardView::kBottom:
      return "bottom";
  }
  return "iso";
}

std::optional<StandardView> parseStandardView(std::string_view name) {
  for (StandardView v : {StandardView::kIso, StandardView::kFront, StandardView::kBack, StandardView::kLeft,
                         StandardView::kRight, StandardView::kTop, StandardView::kBottom}) {
    if (name == viewName(v)) return v;
  }
  return std::nullopt;
}

Camera standardView(StandardView view, const Bounds& bounds, float aspect, Projection projection) {
  Camera camera;
  camera.direction = viewDirection(view);
  camera.up = viewUp(view);
  camera.projection = projection;
  fitToBounds(camera, bounds, aspect);
  return camera;
}

void fitToBounds(Camera& camera, const Bounds& bounds, float aspect, float margin) {
  if (bounds.empty()) return;
  Bounds box = fitBox(bounds);
  glm::vec3 f = glm::normalize(camera.direction);
  glm::vec3 u = glm::normalize(camera.up - f * glm::dot(camera.up, f));
  glm::vec3 r = glm::cross(f, u);
  camera.direction = f;
  camera.up = u;
  camera.target = box.center();

  float tanY = std::tan(0.5f * camera.fovY);
  float tanX = tanY * aspect;
  float needed = 0.0f;      // perspective: smallest distance that shows every corner
  float halfHeight = 0.0f;  // orthographic: half of the visible height
  float closest = 0.0f;     // most negative depth offset of a corner (towards the eye)
  for (const glm::vec3& c : corners(box)) {
    glm::vec3 p = c - camera.target;
    float x = std::abs(glm::dot(p, r)) * margin;
    float y = std::abs(glm::dot(p, u)) * margin;
    float z = glm::dot(p, f);  // > 0: farther from the eye than the target
    // Visible when |x| <= (d + z) tanX and |y| <= (d + z) tanY.
    needed = std::max({needed, x / tanX - z, y / tanY - z});
    halfHeight = std::max({halfHeight, y, x / aspect});
    closest = std::min(closest, z);
  }
  if (camera.projection == Projection::kPerspective) {
    camera.distance = std::max(needed, -closest * 1.01f + 1e-6f);
  } else {
    camera.orthoHeight = 2.0f * halfHeight;
    camera.distance = 2.0f * box.radius();  // outside the box, so near stays in front of the eye
  }
  updateClipPlanes(camera, box);
}

void updateClipPlanes(Camera& camera, const Bounds& bounds) {
  if (bounds.empty()) return;
  Bounds box = fitBox(bounds);
  float radius = box.radius() * 1.01f;
  float centerDepth = glm::dot(box.center() - camera.eye(), glm::normalize(camera.direction));
  float farPlane = std::max(centerDepth + radius, radius * 1e-3f);
  float nearPlane = centerDepth - radius;
  if (camera.projection == Projection::kPerspective) nearPlane = std::max(nearPlane, farPlane * 1e-5f);
  camera.nearPlane = nearPlane;
  camera.farPlane = farPlane;
}

glm::mat4 viewMatrix(const Camera& camera) {
  return glm::lookAtRH(camera.eye(), camera.target, camera.up);
}

glm::mat4 projectionMatrix(const Camera& camera, float aspect) {
  glm::mat4 p;
  if (camera.projection == Projection::kPerspective) {
    p = glm::perspectiveRH_ZO(camera.fovY, aspect, camera.nearPlane, camera.farPlane);
  } else {
    float h = 0.5f * camera.orthoHeight;
    float w = h * aspect;
    p = glm::orthoRH_ZO(-w, w, -h, h, camera.nearPlane, camera.farPlane);
  }
  p[1][1] = -p[1][1];  // Vulkan clip space: y points down
  return p;
}

}  // namespace cetview::engine
