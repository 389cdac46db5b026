#include "engine/draw_constants.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace cetview::engine {

glm::vec3 keyLightInView() {
  return glm::vec3(CETVIEW_KEY_LIGHT_X, CETVIEW_KEY_LIGHT_Y, CETVIEW_KEY_LIGHT_Z);
}

FrameView makeFrameView(const Camera& camera, float aspect, const ViewStyle& style) {
  FrameView v;
  glm::mat4 view = viewMatrix(camera);
  v.viewProj = projectionMatrix(camera, aspect) * view;
  v.towardsEye = -glm::normalize(camera.direction);
  v.eye = camera.projection == Projection::kPerspective ? glm::vec4(camera.eye(), 1.0f)
                                                        : glm::vec4(v.towardsEye, 0.0f);
  v.viewRotation = glm::mat3(view);
  if (!style.fileColors) v.forcedColor = linearColor(style.defaultFaceColor);
  return v;
}

DrawConstants drawConstants(const FrameView& view, const glm::mat4& model,
                            const std::optional<Color8>& color) {
  DrawConstants c{};
  c.modelViewProj = view.viewProj * model;
  // Normals turn with the linear part of rigid and uniformly scaled transforms (a mirror
  // included: its inverse transpose is itself); the scale is divided out.
  glm::mat3 toView = view.viewRotation * glm::mat3(model);
  const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(model))));
  if (scale > 0.0f) toView /= scale;
  c.normalToView0 = glm::vec4(toView[0], 0.0f);
  c.normalToView1 = glm::vec4(toView[1], 0.0f);
  c.normalToView2 = glm::vec4(toView[2], 0.0f);
  if (view.forcedColor) {
    c.color = *view.forcedColor;
  } else if (color) {
    c.color = linearColor(*color);
  } else {
    c.color = glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);  // the faces' own colours
  }
  return c;
}

}  // namespace cetview::engine
