#include "camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace cetview {
namespace {

constexpr float kOrbitRadiansPerPixel = 0.3f * 3.14159265f / 180.0f;
constexpr float kZoomPerStep = 0.85f;

// Smoothstep easing: starts and ends at rest.
float ease(float t) {
  return t * t * (3.0f - 2.0f * t);
}

// Rotation taking (direction, up) of `a` to those of `b`, interpolated by quaternion slerp.
glm::quat frameOf(const engine::Camera& c) {
  const glm::vec3 right = glm::normalize(glm::cross(c.direction, c.up));
  // Columns: right, up, -direction (a right-handed basis).
  return glm::quat_cast(glm::mat3(right, c.up, -c.direction));
}

}  // namespace

void CameraController::reset(const engine::Camera& camera, const engine::Bounds& bounds) {
  camera_ = camera;
  bounds_ = bounds;
  animating_ = false;
  finishMove();
}

void CameraController::setBounds(const engine::Bounds& bounds) {
  bounds_ = bounds;
  finishMove();
}

float CameraController::halfHeightAtTarget() const {
  if (camera_.projection == engine::Projection::kOrthographic) return camera_.orthoHeight * 0.5f;
  return camera_.distance * std::tan(camera_.fovY * 0.5f);
}

void CameraController::finishMove() {
  if (!bounds_.empty()) engine::updateClipPlanes(camera_, bounds_);
}

void CameraController::orbit(glm::vec2 pixels) {
  animating_ = false;
  const glm::vec3 worldUp(0.0f, 0.0f, 1.0f);
  // Horizontal drag: turn about world Z; dragging right turns the model right (the eye left).
  const glm::quat yaw = glm::angleAxis(-pixels.x * kOrbitRadiansPerPixel, worldUp);
  glm::vec3 dir = yaw * camera_.direction;
  glm::vec3 up = yaw * camera_.up;
  // Vertical drag: tilt about the screen's right axis.
  const glm::vec3 right = glm::normalize(glm::cross(dir, up));
  const glm::quat pitch = glm::angleAxis(-pixels.y * kOrbitRadiansPerPixel, right);
  dir = glm::normalize(pitch * dir);
  up = pitch * up;
  // Re-orthonormalise against drift.
  up = glm::normalize(up - dir * glm::dot(up, dir));
  camera_.direction = dir;
  camera_.up = up;
  finishMove();
}

void CameraController::pan(glm::vec2 pixels, glm::vec2 viewport) {
  if (viewport.y <= 0.0f) return;
  animating_ = false;
  const float worldPerPixel = 2.0f * halfHeightAtTarget() / viewport.y;
  const glm::vec3 right = glm::normalize(glm::cross(camera_.direction, camera_.up));
  camera_.target -= right * (pixels.x * worldPerPixel) - camera_.up * (pixels.y * worldPerPixel);
  finishMove();
}

void CameraController::zoom(float steps, glm::vec2 cursor, glm::vec2 viewport) {
  if (viewport.x <= 0.0f || viewport.y <= 0.0f || steps == 0.0f) return;
  animating_ = false;
  const float s = std::pow(kZoomPerStep, steps);
  const float halfH = halfHeightAtTarget();
  const float halfW = halfH * viewport.x / viewport.y;
  const glm::vec2 ndc = cursor / viewport * 2.0f - 1.0f;  // y down
  const glm::vec3 right = glm::normalize(glm::cross(camera_.direction, camera_.up));
  const glm::vec3 under = camera_.target + right * (ndc.x * halfW) - camera_.up * (ndc.y * halfH);
  // Scaling the view about `under` keeps it at the same screen position.
  camera_.target = under + (camera_.target - under) * s;
  if (camera_.projection == engine::Projection::kOrthographic) {
    camera_.orthoHeight *= s;
  } else {
    camera_.distance *= s;
  }
  finishMove();
}

void CameraController::animateTo(const engine::Camera& target, float seconds) {
  if (seconds <= 0.0f) {
    camera_ = target;
    animating_ = false;
    finishMove();
    return;
  }
  from_ = camera_;
  to_ = target;
  elapsed_ = 0.0f;
  duration_ = seconds;
  animating_ = true;
}

void CameraController::viewStandard(engine::StandardView view, float aspect, float seconds) {
  engine::Camera target = engine::standardView(view, bounds_, aspect, camera_.projection);
  target.fovY = camera_.fovY;
  if (!bounds_.empty()) engine::fitToBounds(target, bounds_, aspect, margin_);
  animateTo(target, seconds);
}

void CameraController::fitAll(float aspect, float seconds) {
  engine::Camera target = animating_ ? to_ : camera_;
  engine::fitToBounds(target, bounds_, aspect, margin_);
  animateTo(target, seconds);
}

void CameraController::setProjection(engine::Projection projection) {
  if (camera_.projection == projection) return;
  const float tanHalf = std::tan(camera_.fovY * 0.5f);
  if (projection == engine::Projection::kOrthographic) {
    camera_.orthoHeight = 2.0f * camera_.distance * tanHalf;
  } else {
    camera_.distance = camera_.orthoHeight * 0.5f / tanHalf;
  }
  camera_.projection = projection;
  if (animating_) {
    // Keep the running transition's end in the new projection too.
    if (projection == engine::Projection::kOrthographic) {
      to_.orthoHeight = 2.0f * to_.distance * tanHalf;
    } else {
      to_.distance = to_.orthoHeight * 0.5f / tanHalf;
    }
    to_.projection = projection;
    from_ = camera_;
    elapsed_ = 0.0f;
  }
  finishMove();
}

void CameraController::update(float dt) {
  if (!animating_) return;
  elapsed_ += std::max(0.0f, dt);
  const float t = std::min(1.0f, elapsed_ / duration_);
  if (t >= 1.0f) {
    camera_ = to_;
    animating_ = false;
    finishMove();
    return;
  }
  const float e = ease(t);
  const glm::mat3 frame = glm::mat3_cast(glm::slerp(frameOf(from_), frameOf(to_), e));
  camera_ = to_;
  camera_.up = glm::normalize(frame[1]);
  camera_.direction = glm::normalize(-frame[2]);
  camera_.target = glm::mix(from_.target, to_.target, e);
  // Distances and heights interpolate geometrically, so zooming feels uniform.
  camera_.distance = from_.distance * std::pow(to_.distance / from_.distance, e);
  camera_.orthoHeight = from_.orthoHeight * std::pow(to_.orthoHeight / from_.orthoHeight, e);
  finishMove();
}

bool CameraController::rayHitsBounds(glm::vec2 cursor, glm::vec2 viewport) const {
  if (bounds_.empty() || viewport.x <= 0.0f || viewport.y <= 0.0f) return false;
  const float halfH = halfHeightAtTarget();
  const float halfW = halfH * viewport.x / viewport.y;
  const glm::vec2 ndc = cursor / viewport * 2.0f - 1.0f;
  const glm::vec3 right = glm::normalize(glm::cross(camera_.direction, camera_.up));
  const glm::vec3 onPlane = camera_.target + right * (ndc.x * halfW) - camera_.up * (ndc.y * halfH);
  glm::vec3 origin, dir;
  if (camera_.projection == engine::Projection::kOrthographic) {
    dir = camera_.direction;
    origin = onPlane - dir * (bounds_.radius() * 4.0f + camera_.distance);
  } else {
    origin = camera_.eye();
    dir = glm::normalize(onPlane - origin);
  }
  // Slab test.
  float t0 = -1e30f, t1 = 1e30f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-12f) {
      if (origin[a] < bounds_.min[a] || origin[a] > bounds_.max[a]) return false;
      continue;
    }
    float ta = (bounds_.min[a] - origin[a]) / dir[a];
    float tb = (bounds_.max[a] - origin[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t1 >= std::max(t0, 0.0f);
}

}  // namespace cetview
