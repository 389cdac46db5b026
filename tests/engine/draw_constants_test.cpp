// Per-draw constants without a GPU: part-space normals turn into view space (where the lights are
// constants) as world normals would, and the colour mode follows style and instance.
#include <gtest/gtest.h>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "engine/draw_constants.h"

namespace cetview::test {
namespace {

using namespace engine;

glm::vec3 normalToView(const DrawConstants& c, glm::vec3 local) {
  return glm::mat3(glm::vec3(c.normalToView0), glm::vec3(c.normalToView1), glm::vec3(c.normalToView2)) *
         local;
}

TEST(DrawConstantsTest, NormalsTurnIntoViewSpaceWithUnitLength) {
  Bounds b;
  b.add(glm::vec3(-1.0f));
  b.add(glm::vec3(1.0f));
  Camera camera = standardView(StandardView::kIso, b, 1.5f);
  FrameView view = makeFrameView(camera, 1.5f, ViewStyle{});
  glm::mat4 rigid =
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(3, -2, 5)), 0.7f, glm::vec3(1, 2, 3));
  glm::mat4 mirror(1.0f);
  mirror[1][1] = -1.0f;
  // Uniform scales keep angles; a mirror turns normals like positions.
  for (glm::mat4 model :
       {glm::scale(rigid, glm::vec3(2.5f)), glm::scale(rigid, glm::vec3(1e-3f)), rigid * mirror}) {
    DrawConstants c = drawConstants(view, model, std::nullopt);
    for (glm::vec3 local : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, -1, 2))}) {
      // The world normal (inverse transpose), then the camera's rotation.
      glm::vec3 world = glm::normalize(glm::mat3(glm::transpose(glm::inverse(model))) * local);
      glm::vec3 expected = glm::mat3(viewMatrix(camera)) * world;
      glm::vec3 actual = normalToView(c, local);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f);
    }
  }

  // Model-view-projection is the frame's view-projection after the instance transform.
  glm::mat4 model = glm::scale(rigid, glm::vec3(2.5f));
  DrawConstants c = drawConstants(view, model, std::nullopt);
  glm::vec4 p(0.3f, -0.2f, 0.9f, 1.0f);
  glm::vec4 expected = view.viewProj * (model * p);
  glm::vec4 actual = c.modelViewProj * p;
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-4f);
}

TEST(DrawConstantsTest, ViewSpaceFacesTheEyeAlongZAndTheKeyLightComesFromTheUpperLeft) {
  Camera camera;
  camera.direction = glm::vec3(0, 1, 0);  // front view: screen right is +x, screen up is +z
  camera.up = glm::vec3(0, 0, 1);
  FrameView view = makeFrameView(camera, 1.0f, ViewStyle{});
  DrawConstants c = drawConstants(view, glm::mat4(1.0f), std::nullopt);
  // A normal towards the eye is view-space +z (the headlight), screen-up is +y (the sky).
  EXPECT_NEAR(normalToView(c, glm::vec3(0, -1, 0)).z, 1.0f, 1e-6f);
  EXPECT_NEAR(normalToView(c, glm::vec3(0, 0, 1)).y, 1.0f, 1e-6f);
  EXPECT_NEAR(normalToView(c, glm::vec3(1, 0, 0)).x, 1.0f, 1e-6f);
  glm::vec3 key = keyLightInView();
  EXPECT_NEAR(glm::length(key), 1.0f, 1e-5f);
  EXPECT_LT(key.x, 0.0f);  // left
  EXPECT_GT(key.y, 0.0f);  // up
  EXPECT_GT(key.z, 0.0f);  // in front of the model, towards the eye
}

TEST(DrawConstantsTest, ColourModes) {
  Camera camera;
  ViewStyle style;
  FrameView view = makeFrameView(camera, 1.0f, style);
  EXPECT_LT(drawConstants(view, glm::mat4(1.0f), std::nullopt).color.a, 0.0f);  // per-face colours
  glm::vec4 red = drawConstants(view, glm::mat4(1.0f), Color8{255, 0, 0, 255}).color;
  EXPECT_NEAR(red.r, 1.0f, 1e-6f);
  EXPECT_NEAR(red.g, 0.0f, 1e-6f);
  style.fileColors = false;
  style.defaultFaceColor = Color8{188, 188, 188, 255};  // sRGB 188 is about linear 0.5
  FrameView plain = makeFrameView(camera, 1.0f, style);
  glm::vec4 grey = drawConstants(plain, glm::mat4(1.0f), Color8{255, 0, 0, 255}).color;
  EXPECT_NEAR(grey.r, 0.5f, 0.01f);
  EXPECT_NEAR(grey.g, 0.5f, 0.01f);
}

}  // namespace
}  // namespace cetview::test
