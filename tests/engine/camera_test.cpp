// Camera math without a GPU: standard view directions, fit-to-bounds containment and tightness,
// clip planes and Vulkan's clip-space conventions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <ostream>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "engine/camera.h"

namespace cetview::test {
namespace {

using namespace engine;

const StandardView kAllViews[] = {StandardView::kIso,   StandardView::kFront, StandardView::kBack,
                                  StandardView::kLeft,  StandardView::kRight, StandardView::kTop,
                                  StandardView::kBottom};

Bounds box(glm::vec3 min, glm::vec3 max) {
  Bounds b;
  b.add(min);
  b.add(max);
  return b;
}

std::array<glm::vec3, 8> cornersOf(const Bounds& b) {
  std::array<glm::vec3, 8> c;
  for (int i = 0; i < 8; ++i) {
    c[i] = glm::vec3((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
  }
  return c;
}

glm::vec3 toNdc(const Camera& camera, float aspect, glm::vec3 p) {
  glm::vec4 clip = projectionMatrix(camera, aspect) * viewMatrix(camera) * glm::vec4(p, 1.0f);
  return glm::vec3(clip) / clip.w;
}

void expectNear(glm::vec3 a, glm::vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(CameraTest, StandardViewDirectionsFollowTheZUpConvention) {
  expectNear(viewDirection(StandardView::kFront), {0, 1, 0});
  expectNear(viewDirection(StandardView::kBack), {0, -1, 0});
  expectNear(viewDirection(StandardView::kLeft), {1, 0, 0});
  expectNear(viewDirection(StandardView::kRight), {-1, 0, 0});
  expectNear(viewDirection(StandardView::kTop), {0, 0, -1});
  expectNear(viewDirection(StandardView::kBottom), {0, 0, 1});
  expectNear(viewDirection(StandardView::kIso), glm::normalize(glm::vec3(-1, 1, -1)));
  for (StandardView v : kAllViews) {
    EXPECT_NEAR(glm::length(viewDirection(v)), 1.0f, 1e-6f) << viewName(v);
    EXPECT_NEAR(glm::length(viewUp(v)), 1.0f, 1e-6f) << viewName(v);
    EXPECT_NEAR(glm::dot(viewDirection(v), viewUp(v)), 0.0f, 1e-6f) << viewName(v);
  }
  // The iso view keeps world Z pointing up the screen.
  EXPECT_GT(viewUp(StandardView::kIso).z, 0.5f);
}

TEST(CameraTest, ViewNamesRoundTrip) {
  for (StandardView v : kAllViews) {
    auto parsed = parseStandardView(viewName(v));
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, v);
  }
  EXPECT_FALSE(parseStandardView("diagonal").has_value());
}

TEST(CameraTest, StandardViewLooksFromTheNamedSide) {
  Bounds b = box({-1, -2, -3}, {1, 2, 3});
  // Front: the eye is on the -Y side, and +Z projects upwards (Vulkan NDC y points down).
  Camera front = standardView(StandardView::kFront, b, 1.0f);
  EXPECT_LT(front.eye().y, b.min.y);
  EXPECT_LT(toNdc(front, 1.0f, {0, 0, 3}).y, toNdc(front, 1.0f, {0, 0, -3}).y);
  // Right: +X side, and -Y (the front) appears on the left.
  Camera right = standardView(StandardView::kRight, b, 1.0f);
  EXPECT_GT(right.eye().x, b.max.x);
  EXPECT_LT(toNdc(right, 1.0f, {0, -2, 0}).x, toNdc(right, 1.0f, {0, 2, 0}).x);
  // Top: above, with +Y up the screen and +X to the right.
  Camera top = standardView(StandardView::kTop, b, 1.0f);
  EXPECT_GT(top.eye().z, b.max.z);
  EXPECT_LT(toNdc(top, 1.0f, {0, 2, 0}).y, toNdc(top, 1.0f, {0, -2, 0}).y);
  EXPECT_LT(toNdc(top, 1.0f, {-1, 0, 0}).x, toNdc(top, 1.0f, {1, 0, 0}).x);
}

struct FitCase {
  Projection projection;
  float aspect;
};

void PrintTo(const FitCase& c, std::ostream* os) {
  *os << (c.projection == Projection::kPerspective ? "perspective" : "orthographic") << ", aspect "
      << c.aspect;
}

class CameraFitTest : public ::testing::TestWithParam<FitCase> {};

TEST_P(CameraFitTest, FitContainsTheBoxAndIsTight) {
  const FitCase& c = GetParam();
  const Bounds boxes[] = {box({-1, -1, -1}, {1, 1, 1}), box({10, 20, -5}, {14, 21, 30}),
                          box({-0.001f, -0.002f, 0}, {0.001f, 0.002f, 0.0005f}),
                          box({0, 0, 0}, {500, 20, 3})};
  for (const Bounds& b : boxes) {
    for (StandardView v : kAllViews) {
      Camera camera;
      camera.direction = viewDirection(v);
      camera.up = viewUp(v);
      camera.projection = c.projection;
      fitToBounds(camera, b, c.aspect, 1.1f);
      float extreme = 0.0f;  // largest |ndc| over the corners
      for (glm::vec3 p : cornersOf(b)) {
        glm::vec3 ndc = toNdc(camera, c.aspect, p);
        EXPECT_LE(std::abs(ndc.x), 1.0f + 1e-4f) << viewName(v);
        EXPECT_LE(std::abs(ndc.y), 1.0f + 1e-4f) << viewName(v);
        EXPECT_GE(ndc.z, -1e-5f) << viewName(v);  // Vulkan depth range [0, 1]
        EXPECT_LE(ndc.z, 1.0f + 1e-5f) << viewName(v);
        extreme = std::max({extreme, std::abs(ndc.x), std::abs(ndc.y)});
      }
      // Tight: with a 10% margin the farthest corner lands at 1/1.1 of the half-extent.
      EXPECT_NEAR(extreme, 1.0f / 1.1f, 2e-3f) << viewName(v);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Projections, CameraFitTest,
                         ::testing::Values(FitCase{Projection::kPerspective, 1.0f},
                                           FitCase{Projection::kPerspective, 16.0f / 9.0f},
                                           FitCase{Projection::kPerspective, 0.5f},
                                           FitCase{Projection::kOrthographic, 1.0f},
                                           FitCase{Projection::kOrthographic, 16.0f / 9.0f},
                                           FitCase{Projection::kOrthographic, 0.5f}),
                         [](const ::testing::TestParamInfo<FitCase>& param) {
                           const char* projection = param.param.projection == Projection::kPerspective
                                                        ? "Perspective"
                                                        : "Orthographic";
                           return std::string(projection) + "Aspect" +
                                  std::to_string(static_cast<int>(std::lround(param.param.aspect * 100.0f)));
                         });

TEST(CameraTest, FitKeepsDirectionAndCentresTheTarget) {
  Bounds b = box({2, 4, 6}, {4, 8, 12});
  Camera camera;
  camera.direction = glm::normalize(glm::vec3(1, 2, -0.5f));
  camera.up = glm::vec3(0, 0, 1);
  glm::vec3 before = camera.direction;
  fitToBounds(camera, b, 1.5f);
  expectNear(camera.direction, before);
  expectNear(camera.target, b.center());
  EXPECT_NEAR(glm::dot(camera.up, camera.direction), 0.0f, 1e-6f);
}

TEST(CameraTest, EmptyBoundsLeaveTheCameraAloneAndAPointGetsAUnitBox) {
  Camera camera;
  Camera copy = camera;
  fitToBounds(camera, Bounds{}, 1.0f);
  EXPECT_EQ(camera.distance, copy.distance);
  Bounds point;
  point.add(glm::vec3(5, 5, 5));
  fitToBounds(camera, point, 1.0f);
  expectNear(camera.target, glm::vec3(5, 5, 5));
  EXPECT_GT(camera.distance, 0.5f);
  EXPECT_GT(camera.nearPlane, 0.0f);
}

TEST(CameraTest, ClipPlanesFollowTheCameraAfterItMoves) {
  Bounds b = box({-1, -1, -1}, {1, 1, 1});
  Camera camera = standardView(StandardView::kIso, b, 1.0f);
  camera.distance *= 4.0f;  // zoomed out by the viewer
  updateClipPlanes(camera, b);
  for (glm::vec3 p : cornersOf(b)) {
    glm::vec3 ndc = toNdc(camera, 1.0f, p);
    EXPECT_GE(ndc.z, 0.0f);
    EXPECT_LE(ndc.z, 1.0f);
  }
  camera.distance = 0.1f;  // inside the box: near stays positive
  updateClipPlanes(camera, b);
  EXPECT_GT(camera.nearPlane, 0.0f);
  EXPECT_GT(camera.farPlane, camera.nearPlane);
}

}  // namespace
}  // namespace cetview::test
