#include "engine/draw_constants.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace cetview::engine {

glm::vec3 keyLightInView() {
  return glm::normalize(glm::vec3(-0.45f, 0.65f, 0.62f));
}

FrameView makeFrameView(const Camera& camera, float aspect, const ViewStyle& style) {
  FrameView v;
  glm::mat4 view = viewMatrix(camera);
  v.viewProj = projectionMatrix(camera, aspect) * view;
  v.towardsEye = -glm::normalize(camera.direction);
  v.eye = camera.projection == Projection::kPerspective ? glm::vec4(camera.eye(), 1.0f)
                                                        : glm::vec4(v.towardsEye, 0.0f);
  // View space -> world for directions: the transpose of the view matrix's rotation.
  glm::mat3 toWorld = glm::transpose(glm::mat3(view));
  v.keyLight = glm::normalize(toWorld * keyLightInView());
  v.up = glm::normalize(toWorld * glm::vec3(0.0f, 1.0f, 0.0f));
  if (!style.fileColors) v.forcedColor = linearColor(style.defaultFaceColor);
  return v;
}

DrawConstants drawConstants(const FrameView& view, const glm::mat4& model, const std::optional<Color8>& color,
                            bool twoSided) {
  DrawConstants c{};
  c.modelViewProj = view.viewProj * model;
  // Directions go into part space through the inverse of the linear part; for rigid and
  // uniformly scaled transforms that keeps every angle, so lighting there is exact.
  glm::mat4 inverse = glm::inverse(model);
  glm::mat3 directions(inverse);
  auto direction = [&](glm::vec3 d) { return glm::vec4(glm::normalize(directions * d), 0.0f); };
  c.toEye = direction(view.towardsEye);
  c.toEye.w = twoSided ? 1.0f : 0.0f;
  c.keyLight = direction(view.keyLight);
  c.up = direction(view.up);
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
