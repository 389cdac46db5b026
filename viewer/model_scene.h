// Wires a loaded B-rep model and its progressive stream to the engine's Scene: parts, instances and
// colours become engine parts and instances; the stream's face levels and edge polylines arrive
// through the MeshSink interface. Shared by `cetview render` and the window viewer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "brep/model.h"
#include "engine/camera.h"
#include "engine/scene.h"
#include "stream/stream_consumer.h"

namespace cetview {

// The renderer works in 32-bit floats: a model whose coordinates reach beyond kDisplayableExtent
// (squared distances would overflow) cannot be shown. Returns the one-line reason, empty when it can.
constexpr double kDisplayableExtent = 1e15;
std::string checkDisplayable(const brep::Model& model);

// linear RGB (brep, XCAF) -> sRGB-encoded 8-bit (engine).
engine::Color8 toColor8(const brep::Color& c);

class ModelScene : public stream::MeshSink {
 public:
  // Adds every part (its faces and edges, reserved empty) and every instance of `model` to `scene`.
  ModelScene(const brep::Model& model, engine::Scene& scene);

  std::uint32_t appendVertices(const stream::StreamVertex* vertices, std::size_t count) override;
  void setFaceIndices(std::uint32_t face, const std::uint32_t* indices, std::size_t count) override;
  void setEdgePolyline(std::uint32_t edge, const float* xyz, std::size_t pointCount) override;

  // The model's world box (exact, from the B-rep), for fitting the camera before any triangle exists.
  engine::Bounds bounds() const { return bounds_; }
  engine::FaceId engineFace(std::uint32_t face) const { return faceIds_[face]; }
  engine::InstanceId engineInstance(std::uint32_t instance) const { return instanceIds_[instance]; }
  // The triangles face `face` shows now (indices into the Scene's vertex array), as last set.
  const std::vector<std::uint32_t>& shownIndices(std::uint32_t face) const { return shown_[face]; }
  // An instance's part -> world transform, as given to the Scene.
  static glm::mat4 instanceTransform(const brep::InstanceInfo& instance);

 private:
  engine::Scene& scene_;
  std::vector<engine::FaceId> faceIds_;
  std::vector<engine::EdgeId> edgeIds_;
  std::vector<engine::InstanceId> instanceIds_;
  std::vector<std::vector<std::uint32_t>> shown_;  // per model face
  engine::Bounds bounds_;
};

}  // namespace cetview
