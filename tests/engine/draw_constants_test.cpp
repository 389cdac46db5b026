// Per-draw constants without a GPU: lighting vectors land in part space so that dot products with
// part-space normals equal the world-space ones, and the colour mode follows style and instance.
#include <gtest/gtest.h>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "engine/draw_constants.h"

namespace cetview::test {
namespace {

using namespace engine;

TEST(DrawConstantsTest, LightingVectorsMoveIntoPartSpace) {
  Bounds b;
  b.add(glm::vec3(-1.0f));
  b.add(glm::vec3(1.0f));
  Camera camera = standardView(StandardView::kIso, b, 1.5f);
  FrameView view = makeFrameView(camera, 1.5f, ViewStyle{});
  glm::mat4 model =
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(3, -2, 5)), 0.7f, glm::vec3(1, 2, 3));
  model = glm::scale(model, glm::vec3(2.5f));  // uniform scale keeps angles
  DrawConstants c = drawConstants(view, model, std::nullopt, true);

  // A part-space normal and its world image give the same cosines with the light vectors.
  for (glm::vec3 local : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, -1, 2))}) {
    glm::vec3 world = glm::normalize(glm::mat3(glm::transpose(glm::inverse(model))) * local);
    EXPECT_NEAR(glm::dot(local, glm::vec3(c.toEye)), glm::dot(world, view.towardsEye), 1e-5f);
    EXPECT_NEAR(glm::dot(local, glm::vec3(c.keyLight)), glm::dot(world, view.keyLight), 1e-5f);
    EXPECT_NEAR(glm::dot(local, glm::vec3(c.up)), glm::dot(world, view.up), 1e-5f);
  }
  EXPECT_FLOAT_EQ(c.toEye.w, 1.0f);
  EXPECT_FLOAT_EQ(drawConstants(view, model, std::nullopt, false).toEye.w, 0.0f);

  // Model-view-projection is the frame's view-projection after the instance transform.
  glm::vec4 p(0.3f, -0.2f, 0.9f, 1.0f);
  glm::vec4 expected = view.viewProj * (model * p);
  glm::vec4 actual = c.modelViewProj * p;
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-4f);
}

TEST(DrawConstantsTest, KeyLightComesFromTheUpperLeftOfTheScreen) {
  Camera camera;
  camera.direction = glm::vec3(0, 1, 0);  // front view: screen right is +x, screen up is +z
  camera.up = glm::vec3(0, 0, 1);
  FrameView view = makeFrameView(camera, 1.0f, ViewStyle{});
  EXPECT_LT(view.keyLight.x, 0.0f);  // left
  EXPECT_GT(view.keyLight.z, 0.0f);  // up
  EXPECT_LT(view.keyLight.y, 0.0f);  // in front of the model, towards the eye
  EXPECT_NEAR(view.up.z, 1.0f, 1e-6f);
  EXPECT_NEAR(view.towardsEye.y, -1.0f, 1e-6f);
}

TEST(DrawConstantsTest, ColourModes) {
  Camera camera;
  ViewStyle style;
  FrameView view = makeFrameView(camera, 1.0f, style);
  EXPECT_LT(drawConstants(view, glm::mat4(1.0f), std::nullopt, true).color.a, 0.0f);  // per-face colours
  glm::vec4 red = drawConstants(view, glm::mat4(1.0f), Color8{255, 0, 0, 255}, true).color;
  EXPECT_NEAR(red.r, 1.0f, 1e-6f);
  EXPECT_NEAR(red.g, 0.0f, 1e-6f);
  style.fileColors = false;
  style.defaultFaceColor = Color8{188, 188, 188, 255};  // sRGB 188 is about linear 0.5
  FrameView plain = makeFrameView(camera, 1.0f, style);
  glm::vec4 grey = drawConstants(plain, glm::mat4(1.0f), Color8{255, 0, 0, 255}, true).color;
  EXPECT_NEAR(grey.r, 0.5f, 0.01f);
  EXPECT_NEAR(grey.g, 0.5f, 0.01f);
}

}  // namespace
}  // namespace cetview::test
