// Plain types of the engine's API: the vertex layout, colours, ids, bounds and display modes.
#pragma once

#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace cetview::engine {

// One vertex of the shared, append-only vertex array: the GPU vertex buffer's exact layout.
struct MeshVertex {
  float position[3];
  float normal[3];  // the exact surface normal (unit length), not a triangle normal
};
static_assert(sizeof(MeshVertex) == 24, "MeshVertex is the vertex buffer layout");

// An sRGB-encoded colour with straight alpha (what STEP/XCAF colours become).
struct Color8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

inline bool operator==(Color8 x, Color8 y) {
  return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
}
inline bool operator!=(Color8 x, Color8 y) {
  return !(x == y);
}

// Colour from sRGB-encoded floats in [0, 1] (clamped, rounded to nearest).
Color8 colorFromFloat(float r, float g, float b, float a = 1.0f);

// Linear-light RGBA (alpha unchanged) of an sRGB colour: what the shaders light with.
glm::vec4 linearColor(Color8 c);

// The GPU face table's packing: R in the low byte (GLSL unpackUnorm4x8 order).
constexpr std::uint32_t packColor(Color8 c) {
  return std::uint32_t{c.r} | (std::uint32_t{c.g} << 8) | (std::uint32_t{c.b} << 16) |
         (std::uint32_t{c.a} << 24);
}

// Distinct id types: a face id passed where an edge id belongs does not compile.
enum class FaceId : std::uint32_t {};
enum class EdgeId : std::uint32_t {};
enum class PartId : std::uint32_t {};
enum class InstanceId : std::uint32_t {};

constexpr std::uint32_t toIndex(FaceId id) {
  return static_cast<std::uint32_t>(id);
}
constexpr std::uint32_t toIndex(EdgeId id) {
  return static_cast<std::uint32_t>(id);
}
constexpr std::uint32_t toIndex(PartId id) {
  return static_cast<std::uint32_t>(id);
}
constexpr std::uint32_t toIndex(InstanceId id) {
  return static_cast<std::uint32_t>(id);
}

// Axis-aligned box; empty (min > max) until something is added.
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void add(const glm::vec3& p);
  void add(const Bounds& b);
  glm::vec3 center() const { return (min + max) * 0.5f; }
  glm::vec3 size() const { return max - min; }
  float radius() const;  // half the diagonal: the radius of a sphere around the box
};

enum class DisplayMode {
  kShaded,           // lit faces
  kShadedWithEdges,  // lit faces and the B-rep edge lines over them
  kWireframe,        // triangle edges only (needs DeviceFeatures::fillModeNonSolid)
};

}  // namespace cetview::engine
