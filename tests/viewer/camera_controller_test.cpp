// The viewer's camera controller: pure math, checked against the engine's projection.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "camera_controller.h"

namespace cetview::test {
namespace {

using engine::Camera;
using engine::Projection;

engine::Bounds unitBox() {
  engine::Bounds b;
  b.add(glm::vec3(-1.0f));
  b.add(glm::vec3(1.0f));
  return b;
}

// Pixel position of world point p (top-left origin, y down).
glm::vec2 project(const Camera& c, glm::vec3 p, glm::vec2 viewport) {
  const glm::vec4 clip =
      engine::projectionMatrix(c, viewport.x / viewport.y) * engine::viewMatrix(c) * glm::vec4(p, 1.0f);
  const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
  return (ndc * 0.5f + 0.5f) * viewport;
}

class CameraControllerTest : public ::testing::TestWithParam<Projection> {
 protected:
  void SetUp() override {
    controller.reset(engine::standardView(engine::StandardView::kIso, unitBox(), vp.x / vp.y, GetParam()),
                     unitBox());
  }
  CameraController controller;
  glm::vec2 vp{960.0f, 600.0f};
};

TEST_P(CameraControllerTest, ZoomKeepsThePointUnderTheCursor) {
  const Camera& c = controller.camera();
  const glm::vec2 cursor(700.0f, 150.0f);
  // The point on the target plane under the cursor.
  const glm::vec3 right = glm::normalize(glm::cross(c.direction, c.up));
  const float halfH =
      c.projection == Projection::kOrthographic ? c.orthoHeight * 0.5f : c.distance * std::tan(c.fovY * 0.5f);
  const glm::vec2 ndc = cursor / vp * 2.0f - 1.0f;
  const glm::vec3 p = c.target + right * (ndc.x * halfH * vp.x / vp.y) - c.up * (ndc.y * halfH);
  ASSERT_NEAR(glm::distance(project(c, p, vp), cursor), 0.0f, 0.05f);
  const float before = c.projection == Projection::kOrthographic ? c.orthoHeight : c.distance;
  controller.zoom(2.0f, cursor, vp);
  const float after = controller.camera().projection == Projection::kOrthographic
                          ? controller.camera().orthoHeight
                          : controller.camera().distance;
  EXPECT_LT(after, before * 0.75f);  // closer
  EXPECT_NEAR(glm::distance(project(controller.camera(), p, vp), cursor), 0.0f, 0.05f);
}

TEST_P(CameraControllerTest, PanMovesTheTargetPlaneWithTheCursor) {
  const glm::vec3 p = controller.camera().target;
  const glm::vec2 before = project(controller.camera(), p, vp);
  controller.pan(glm::vec2(50.0f, -20.0f), vp);
  const glm::vec2 after = project(controller.camera(), p, vp);
  EXPECT_NEAR(after.x - before.x, 50.0f, 0.05f);
  EXPECT_NEAR(after.y - before.y, -20.0f, 0.05f);
}

TEST_P(CameraControllerTest, OrbitTurnsAboutTheTargetAndKeepsAnOrthonormalFrame) {
  const Camera start = controller.camera();
  for (int i = 0; i < 100; ++i) controller.orbit(glm::vec2(13.0f, -7.0f));
  const Camera& c = controller.camera();
  EXPECT_NEAR(glm::length(c.direction), 1.0f, 1e-4f);
  EXPECT_NEAR(glm::length(c.up), 1.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(c.direction, c.up), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::distance(c.target, start.target), 0.0f, 1e-5f);
  EXPECT_NEAR(c.distance, start.distance, 1e-5f);
  // Horizontal drag alone turns about world Z: the direction's Z component is kept.
  controller.reset(start, unitBox());
  controller.orbit(glm::vec2(200.0f, 0.0f));
  EXPECT_NEAR(controller.camera().direction.z, start.direction.z, 1e-5f);
  EXPECT_GT(glm::distance(controller.camera().direction, start.direction), 0.5f);
}

TEST_P(CameraControllerTest, TransitionsAreSmoothAndEndExactly) {
  controller.viewStandard(engine::StandardView::kTop, vp.x / vp.y, 0.4f);
  EXPECT_TRUE(controller.animating());
  glm::vec3 previous = controller.camera().direction;
  float largestStep = 0.0f;
  for (int i = 0; i < 40; ++i) {
    controller.update(0.0125f);
    largestStep = std::max(largestStep, glm::distance(previous, controller.camera().direction));
    previous = controller.camera().direction;
  }
  EXPECT_FALSE(controller.animating());
  EXPECT_LT(largestStep, 0.15f);  // no jump
  EXPECT_NEAR(glm::distance(controller.camera().direction, engine::viewDirection(engine::StandardView::kTop)),
              0.0f, 1e-5f);
  // Fit all after a zoom brings the whole box back in view.
  controller.zoom(10.0f, vp * 0.5f, vp);
  controller.fitAll(vp.x / vp.y, 0.0f);
  const engine::Bounds b = unitBox();
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                           (i & 4) ? b.max.z : b.min.z);
    const glm::vec2 px = project(controller.camera(), corner, vp);
    EXPECT_GE(px.x, 0.0f);
    EXPECT_LE(px.x, vp.x);
    EXPECT_GE(px.y, 0.0f);
    EXPECT_LE(px.y, vp.y);
  }
}

TEST_P(CameraControllerTest, RayHitsTheBoxOnlyWhereItIs) {
  EXPECT_TRUE(controller.rayHitsBounds(vp * 0.5f, vp));
  EXPECT_FALSE(controller.rayHitsBounds(glm::vec2(2.0f, 2.0f), vp));
}

INSTANTIATE_TEST_SUITE_P(Projections, CameraControllerTest,
                         ::testing::Values(Projection::kPerspective, Projection::kOrthographic),
                         [](const ::testing::TestParamInfo<Projection>& param) {
                           return param.param == Projection::kPerspective ? "Perspective" : "Orthographic";
                         });

TEST(CameraController, ProjectionSwitchKeepsTheFraming) {
  CameraController controller;
  controller.reset(engine::standardView(engine::StandardView::kFront, unitBox(), 1.6f), unitBox());
  const Camera persp = controller.camera();
  controller.setProjection(Projection::kOrthographic);
  EXPECT_NEAR(controller.camera().orthoHeight, 2.0f * persp.distance * std::tan(persp.fovY * 0.5f), 1e-4f);
  controller.setProjection(Projection::kPerspective);
  EXPECT_NEAR(controller.camera().distance, persp.distance, 1e-4f);
}

}  // namespace
}  // namespace cetview::test
