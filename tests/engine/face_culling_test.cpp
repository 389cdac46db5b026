// Whole-face culling without a GPU: a face is only ever reported back-facing or out of view when
// every one of its triangles really is (checked against the exact per-triangle tests for random
// patches and cameras), and the obvious cases are caught.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "engine/camera.h"
#include "engine/face_culling.h"

namespace cetview::test {
namespace {

using namespace engine;

struct Patch {
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;
};

MeshVertex vertex(glm::vec3 p) {
  return MeshVertex{{p.x, p.y, p.z}, {0.0f, 0.0f, 1.0f}};
}

// An n x n grid on the unit square in the z = 0 plane, counter-clockwise seen from +z.
Patch square(std::uint32_t n) {
  Patch patch;
  for (std::uint32_t j = 0; j <= n; ++j) {
    for (std::uint32_t i = 0; i <= n; ++i) {
      patch.vertices.push_back(vertex(glm::vec3(float(i) / float(n), float(j) / float(n), 0.0f)));
    }
  }
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      std::uint32_t a = j * (n + 1) + i;
      patch.indices.insert(patch.indices.end(), {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1});
    }
  }
  return patch;
}

// A piece of a sphere around `center` (outward counter-clockwise) spanning `spread` radians.
Patch spherePatch(glm::vec3 center, float radius, float lon0, float lat0, float spread, std::uint32_t n) {
  Patch patch;
  for (std::uint32_t j = 0; j <= n; ++j) {
    for (std::uint32_t i = 0; i <= n; ++i) {
      float lon = lon0 + spread * float(i) / float(n);
      float lat = lat0 + spread * float(j) / float(n);
      glm::vec3 d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
      patch.vertices.push_back(vertex(center + radius * d));
    }
  }
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      std::uint32_t a = j * (n + 1) + i;
      patch.indices.insert(patch.indices.end(), {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1});
    }
  }
  return patch;
}

FaceCullBounds boundsOf(const Patch& p) {
  return computeFaceCullBounds(p.vertices.data(), p.indices.data(), p.indices.size());
}

glm::vec3 at(const Patch& p, std::size_t k) {
  const MeshVertex& v = p.vertices[p.indices[k]];
  return glm::vec3(v.position[0], v.position[1], v.position[2]);
}

// The exact test: does any triangle face the eye (homogeneous: w = 1 a point, w = 0 a direction)?
bool anyTriangleFaces(const Patch& p, glm::vec4 eye) {
  for (std::size_t k = 0; k + 2 < p.indices.size(); k += 3) {
    glm::vec3 a = at(p, k), b = at(p, k + 1), c = at(p, k + 2);
    glm::vec3 n = glm::cross(b - a, c - a);
    glm::vec3 toEye = eye.w != 0.0f ? glm::vec3(eye) / eye.w - a : glm::vec3(eye);
    if (glm::dot(n, toEye) >= 0.0f) return true;
  }
  return false;
}

CullView viewFrom(glm::vec3 eye, glm::vec3 target, bool orthographic) {
  glm::mat4 view = glm::lookAt(
      eye, target, std::abs(glm::normalize(target - eye).z) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
  glm::mat4 projection = orthographic ? glm::orthoRH_ZO(-3.0f, 3.0f, -3.0f, 3.0f, 0.1f, 100.0f)
                                      : glm::perspectiveRH_ZO(0.8f, 1.0f, 0.1f, 100.0f);
  glm::vec4 eyeH = orthographic ? glm::vec4(glm::normalize(eye - target), 0.0f) : glm::vec4(eye, 1.0f);
  return makeCullView(projection * view, eyeH);
}

TEST(FaceCullingTest, PlanarFaceIsBackFacingOnlyFromBehind) {
  Patch p = square(4);
  FaceCullBounds b = boundsOf(p);
  EXPECT_NEAR(b.axis.z, 1.0f, 1e-6f);
  EXPECT_GT(b.cosAngle, 0.99f);
  EXPECT_NEAR(b.radius, std::sqrt(0.5f), 1e-6f);
  for (bool ortho : {false, true}) {
    EXPECT_FALSE(backFacing(viewFrom(glm::vec3(0.5f, 0.5f, 5.0f), glm::vec3(0.5f, 0.5f, 0.0f), ortho), b));
    EXPECT_TRUE(backFacing(viewFrom(glm::vec3(0.5f, 0.5f, -5.0f), glm::vec3(0.5f, 0.5f, 0.0f), ortho), b));
    // Edge-on, and just below the plane but close enough to see the near edge at a grazing angle.
    EXPECT_FALSE(backFacing(viewFrom(glm::vec3(5.0f, 0.5f, 0.0f), glm::vec3(0.5f, 0.5f, 0.0f), ortho), b));
  }
  EXPECT_FALSE(backFacing(viewFrom(glm::vec3(5.0f, 0.5f, -0.01f), glm::vec3(0.5f, 0.5f, 0.0f), false), b));
  // Below the plane but inside the bounding sphere: left to the rasteriser.
  EXPECT_FALSE(backFacing(viewFrom(glm::vec3(0.5f, 0.5f, -0.2f), glm::vec3(0.5f, 0.5f, -1.0f), false), b));
}

TEST(FaceCullingTest, WideOrEmptyFacesAreNeverBackFacing) {
  // A hemisphere's normals spread over 180 degrees: no cone.
  Patch hemisphere = spherePatch(glm::vec3(0.0f), 1.0f, 0.0f, 0.0f, 3.14159f, 8);
  FaceCullBounds b = boundsOf(hemisphere);
  EXPECT_LE(b.cosAngle, 0.0f);
  EXPECT_FALSE(backFacing(viewFrom(glm::vec3(0, 0, -50), glm::vec3(0.0f), false), b));

  FaceCullBounds empty = computeFaceCullBounds(nullptr, nullptr, 0);
  EXPECT_LT(empty.radius, 0.0f);
  EXPECT_FALSE(backFacing(viewFrom(glm::vec3(0, 0, 5), glm::vec3(0.0f), false), empty));
  EXPECT_FALSE(outsideFrustum(viewFrom(glm::vec3(0, 0, 5), glm::vec3(0.0f), false), empty));

  // Only degenerate triangles: a sphere, but no cone.
  Patch line;
  for (int i = 0; i < 3; ++i) line.vertices.push_back(vertex(glm::vec3(float(i), 0.0f, 0.0f)));
  line.indices = {0, 1, 2};
  FaceCullBounds flat = boundsOf(line);
  EXPECT_GE(flat.radius, 0.0f);
  EXPECT_LE(flat.cosAngle, 0.0f);
}

TEST(FaceCullingTest, CulledFacesHaveNoTriangleFacingTheEye) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int culled = 0, kept = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    glm::vec3 center(4.0f * unit(rng) - 2.0f, 4.0f * unit(rng) - 2.0f, 4.0f * unit(rng) - 2.0f);
    Patch p = spherePatch(center, 0.2f + unit(rng), 6.3f * unit(rng), 3.0f * unit(rng) - 1.5f,
                          0.05f + 1.2f * unit(rng), 1 + trial % 6);
    FaceCullBounds b = boundsOf(p);
    glm::vec3 eye(12.0f * unit(rng) - 6.0f, 12.0f * unit(rng) - 6.0f, 12.0f * unit(rng) - 6.0f);
    bool ortho = trial % 4 == 0;
    CullView view = viewFrom(eye, glm::vec3(0.0f), ortho);
    if (backFacing(view, b)) {
      ++culled;
      EXPECT_FALSE(anyTriangleFaces(p, view.eye)) << "trial " << trial;
    } else {
      ++kept;
    }
  }
  // The test means something only if both outcomes occur often.
  EXPECT_GT(culled, 300);
  EXPECT_GT(kept, 300);
}

TEST(FaceCullingTest, FacesOutsideTheFrustumHaveNoVertexInside) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int outside = 0, inside = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    glm::vec3 center(20.0f * unit(rng) - 10.0f, 20.0f * unit(rng) - 10.0f, 20.0f * unit(rng) - 10.0f);
    Patch p = spherePatch(center, 0.1f + 2.0f * unit(rng), 6.3f * unit(rng), 0.0f, 1.0f, 3);
    FaceCullBounds b = boundsOf(p);
    bool ortho = trial % 3 == 0;
    glm::vec3 eye(0.0f, -8.0f, 2.0f);
    glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 0, 1));
    glm::mat4 projection = ortho ? glm::orthoRH_ZO(-3.0f, 3.0f, -3.0f, 3.0f, 0.5f, 15.0f)
                                 : glm::perspectiveRH_ZO(0.8f, 1.3f, 0.5f, 15.0f);
    glm::mat4 m = projection * view;
    CullView cull = makeCullView(m, ortho ? glm::vec4(glm::normalize(eye), 0.0f) : glm::vec4(eye, 1.0f));
    if (!outsideFrustum(cull, b)) {
      ++inside;
      continue;
    }
    ++outside;
    // Every vertex lies beyond one and the same clip plane.
    auto beyond = [&](int plane) {
      for (const MeshVertex& v : p.vertices) {
        glm::vec4 c = m * glm::vec4(v.position[0], v.position[1], v.position[2], 1.0f);
        float d[6] = {c.w + c.x, c.w - c.x, c.w + c.y, c.w - c.y, c.z, c.w - c.z};
        if (d[plane] >= 0.0f) return false;
      }
      return true;
    };
    bool any = false;
    for (int plane = 0; plane < 6; ++plane) any = any || beyond(plane);
    EXPECT_TRUE(any) << "trial " << trial;
  }
  EXPECT_GT(outside, 300);
  EXPECT_GT(inside, 300);
}

}  // namespace
}  // namespace cetview::test
