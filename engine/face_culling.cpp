#include "engine/face_culling.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace cetview::engine {
namespace {

// Extra half angle of every cone (radians): the rasteriser decides facing from rounded clip
// coordinates, so a face seen almost edge-on is left to it.
constexpr float kConeMargin = 0.01f;

glm::vec3 position(const MeshVertex& v) {
  return glm::vec3(v.position[0], v.position[1], v.position[2]);
}

}  // namespace

FaceCullBounds computeFaceCullBounds(const MeshVertex* vertices, const std::uint32_t* indices,
                                     std::size_t count) {
  FaceCullBounds result;
  if (count < 3) return result;
  // One pass for the box and the triangles' normals (area-weighted: their sum is the axis), one
  // over the normals for the widest angle to the axis, without a square root per triangle. Run
  // once per cluster as its triangles are committed, inside an upload frame: kept cheap.
  const std::size_t triangles = count / 3;
  thread_local std::vector<glm::vec3> normals;
  normals.resize(triangles);
  glm::vec3 lo(vertices[indices[0]].position[0], vertices[indices[0]].position[1],
               vertices[indices[0]].position[2]);
  glm::vec3 hi = lo;
  glm::vec3 sum(0.0f);
  for (std::size_t t = 0; t < triangles; ++t) {
    glm::vec3 a = position(vertices[indices[3 * t]]);
    glm::vec3 b = position(vertices[indices[3 * t + 1]]);
    glm::vec3 c = position(vertices[indices[3 * t + 2]]);
    lo = glm::min(lo, glm::min(a, glm::min(b, c)));
    hi = glm::max(hi, glm::max(a, glm::max(b, c)));
    normals[t] = glm::cross(b - a, c - a);
    sum += normals[t];
  }
  result.center = 0.5f * (lo + hi);
  result.radius = 0.5f * glm::length(hi - lo);
  float sumLength = glm::length(sum);
  if (!(sumLength > 0.0f) || !std::isfinite(sumLength)) return result;  // no area, or not finite
  const glm::vec3 axis = sum / sumLength;
  // The smallest cos(angle to the axis) as a signed square, cos * |cos| = d * |d| / |n|^2.
  float minSignedCos2 = 1.0f;
  for (const glm::vec3& n : normals) {
    float length2 = glm::dot(n, n);
    if (!(length2 > 0.0f)) continue;  // a triangle without area draws nothing
    float d = glm::dot(axis, n);
    minSignedCos2 = std::min(minSignedCos2, d * std::abs(d) / length2);
  }
  if (!(minSignedCos2 > 0.0f)) return result;  // normals spread over a half space or more
  double angle = std::acos(std::min(1.0, std::sqrt(double(minSignedCos2)))) + kConeMargin;
  if (angle >= 0.5 * 3.14159265358979) return result;
  result.axis = axis;
  result.cosAngle = static_cast<float>(std::cos(angle));
  return result;
}

CullView makeCullView(const glm::mat4& m, const glm::vec4& eyeInPart) {
  CullView view;
  view.eye = eyeInPart;
  // Rows of the matrix (GLM is column-major); Vulkan clip space: -w <= x, y <= w, 0 <= z <= w.
  auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
  const glm::vec4 x = row(0), y = row(1), z = row(2), w = row(3);
  const glm::vec4 planes[6] = {w + x, w - x, w + y, w - y, z, w - z};
  for (int i = 0; i < 6; ++i) {
    float length = glm::length(glm::vec3(planes[i]));
    // A degenerate plane (a singular matrix) culls nothing.
    view.planes[i] = length > 0.0f && std::isfinite(length) ? planes[i] / length : glm::vec4(0, 0, 0, 1);
  }
  return view;
}

bool outsideFrustum(const CullView& view, const FaceCullBounds& bounds) {
  if (bounds.radius < 0.0f) return false;
  for (const glm::vec4& plane : view.planes) {
    if (glm::dot(glm::vec3(plane), bounds.center) + plane.w < -bounds.radius) return true;
  }
  return false;
}

bool backFacing(const CullView& view, const FaceCullBounds& bounds) {
  if (bounds.cosAngle <= 0.0f || bounds.radius < 0.0f) return false;
  // A triangle with unit normal n through a point p within the sphere (c, r) faces away when
  // dot(n, eye - p) < 0; dot(n, eye - p) <= dot(n, eye - c) + r. With the cone (axis a, half angle
  // t) and the angle f between a and eye - c, dot(n, eye - c) <= d cos(f - t) for d = |eye - c|,
  // so every triangle faces away when f > 90 deg + t + asin(r / d).
  const float cosT = bounds.cosAngle;
  const float sinT = std::sqrt(std::max(0.0f, 1.0f - cosT * cosT));
  if (view.eye.w == 0.0f) {
    // Orthographic: the eye is at infinity in direction u; every ray is parallel to it.
    float length = glm::length(glm::vec3(view.eye));
    if (!(length > 0.0f)) return false;
    return glm::dot(bounds.axis, glm::vec3(view.eye) / length) < -sinT;
  }
  const glm::vec3 v = glm::vec3(view.eye) / view.eye.w - bounds.center;
  const float d2 = glm::dot(v, v);
  const float r = bounds.radius;
  if (!(d2 > r * r)) return false;  // the eye is inside the sphere
  const float d = std::sqrt(d2);
  const float sinB = r / d;
  const float cosB = std::sqrt(std::max(0.0f, 1.0f - sinB * sinB));
  if (cosT * cosB - sinT * sinB <= 0.0f) return false;  // t + asin(r / d) >= 90 deg: never
  return glm::dot(bounds.axis, v) < -d * (sinT * cosB + cosT * sinB);
}

}  // namespace cetview::engine
