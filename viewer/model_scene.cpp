#include "model_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <glm/mat4x4.hpp>

namespace cetview {
namespace {
// The ids and index ranges below come from the model and the consumer's checks, so the Scene can
// only refuse them if a contract is broken: say so loudly rather than draw a wrong picture silently.
void expectOk(const engine::Status& status, const char* what) {
  if (!status)
    std::fprintf(stderr, "cetview: internal error: %s: %s\n", what, status.error().message.c_str());
}
}  // namespace

std::string checkDisplayable(const brep::Model& model) {
  const brep::Bounds b = model.bounds();
  double reach = 0;
  for (int i = 0; i < 3; ++i) reach = std::max({reach, std::abs(b.min[i]), std::abs(b.max[i])});
  if (reach <= kDisplayableExtent) return {};
  char text[160];
  std::snprintf(text, sizeof text,
                "coordinates reach %.3g model units, beyond what the renderer can show (%.0e); 'cetview export' "
                "still writes its mesh",
                reach, kDisplayableExtent);
  return text;
}

engine::Color8 toColor8(const brep::Color& c) {
  const auto encode = [](float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(s * 255.0f));
  };
  return engine::Color8{encode(c.r), encode(c.g), encode(c.b),
                        static_cast<std::uint8_t>(std::lround(std::clamp(c.a, 0.0f, 1.0f) * 255.0f))};
}

glm::mat4 ModelScene::instanceTransform(const brep::InstanceInfo& instance) {
  const auto& m = instance.transform;  // row-major 3x4 [R | t]
  glm::mat4 transform(1.0f);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) transform[c][r] = static_cast<float>(m[static_cast<std::size_t>(4 * r + c)]);
  }
  return transform;
}

ModelScene::ModelScene(const brep::Model& model, engine::Scene& scene) : scene_(scene) {
  const auto& faces = model.faces();
  faceIds_.resize(faces.size());
  shown_.resize(faces.size());
  edgeIds_.resize(model.edgeCount());
  std::vector<engine::PartId> partIds;
  for (const brep::PartInfo& part : model.parts()) {
    const engine::PartRange range =
        scene_.addPart(part.faceCount, part.edgeCount, toColor8(part.color), /*closedSolid=*/part.closed);
    partIds.push_back(range.part);
    for (std::uint32_t i = 0; i < part.faceCount; ++i) {
      const std::uint32_t f = part.firstFace + i;
      faceIds_[f] = range.face(i);
      // Faces with no colour of their own take the part's colour (already the part default).
      if (faces[f].hasOwnColor)
        expectOk(scene_.setFaceColor(range.face(i), toColor8(faces[f].color)), "face colour");
    }
    for (std::uint32_t i = 0; i < part.edgeCount; ++i) edgeIds_[part.firstEdge + i] = range.edge(i);
  }
  for (const brep::InstanceInfo& instance : model.instances()) {
    auto id = scene_.addInstance(partIds[instance.part], instanceTransform(instance));
    if (!id) continue;  // an unknown part cannot happen: parts were added above
    instanceIds_.push_back(*id);
    if (instance.hasColor)
      expectOk(scene_.setInstanceColor(*id, toColor8(instance.color)), "instance colour");
  }
  const brep::Bounds b = model.bounds();
  if (!b.empty()) {
    bounds_.add(
        glm::vec3(static_cast<float>(b.min[0]), static_cast<float>(b.min[1]), static_cast<float>(b.min[2])));
    bounds_.add(
        glm::vec3(static_cast<float>(b.max[0]), static_cast<float>(b.max[1]), static_cast<float>(b.max[2])));
  }
}

std::uint32_t ModelScene::appendVertices(const stream::StreamVertex* vertices, std::size_t count) {
  static_assert(sizeof(stream::StreamVertex) == sizeof(engine::MeshVertex), "the same 24-byte layout");
  std::vector<engine::MeshVertex> converted(count);
  std::memcpy(converted.data(), vertices, count * sizeof(engine::MeshVertex));
  return scene_.appendVertices(converted.data(), count);
}

void ModelScene::setFaceIndices(std::uint32_t face, const std::uint32_t* indices, std::size_t count) {
  expectOk(scene_.setFaceIndices(faceIds_[face], indices, count), "face triangles");
  shown_[face].assign(indices, indices + count);
}

void ModelScene::setEdgePolyline(std::uint32_t edge, const float* xyz, std::size_t pointCount) {
  expectOk(scene_.setEdgePolyline(edgeIds_[edge], xyz, pointCount), "edge polyline");
}

}  // namespace cetview
