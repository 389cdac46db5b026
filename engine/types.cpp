#include "engine/types.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace cetview::engine {

Color8 colorFromFloat(float r, float g, float b, float a) {
  auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return Color8{byte(r), byte(g), byte(b), byte(a)};
}

glm::vec4 linearColor(Color8 c) {
  auto channel = [](std::uint8_t v) {
    float x = static_cast<float>(v) / 255.0f;
    return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
  };
  return glm::vec4(channel(c.r), channel(c.g), channel(c.b), static_cast<float>(c.a) / 255.0f);
}

void Bounds::add(const glm::vec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

void Bounds::add(const Bounds& b) {
  if (b.empty()) return;
  add(b.min);
  add(b.max);
}

float Bounds::radius() const {
  return empty() ? 0.0f : 0.5f * glm::length(max - min);
}

}  // namespace cetview::engine
