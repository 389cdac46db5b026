#include "engine/scene.h"

#include <string>

#include <glm/vec4.hpp>

#include "engine/triangle_order.h"

namespace cetview::engine {
namespace {

Error badId(const char* what, std::uint32_t id, std::size_t count) {
  return makeError(ErrorCode::kInvalidArgument, std::string(what) + " " + std::to_string(id) +
                                                    " out of range (" + std::to_string(count) + " exist)");
}

}  // namespace

PartRange Scene::addPart(std::uint32_t faceCount, std::uint32_t edgeCount, Color8 color, bool closedSolid) {
  Part part;
  part.firstFace = this->faceCount();
  part.faceCount = faceCount;
  part.firstEdge = this->edgeCount();
  part.edgeCount = edgeCount;
  part.color = color;
  part.closedSolid = closedSolid;
  auto id = static_cast<std::uint32_t>(parts_.size());
  parts_.push_back(part);

  Face face;
  face.part = id;
  face.color = color;
  faces_.resize(faces_.size() + faceCount, face);
  Edge edge;
  edge.part = id;
  edges_.resize(edges_.size() + edgeCount, edge);
  return PartRange{PartId{id}, FaceId{part.firstFace}, faceCount, EdgeId{part.firstEdge}, edgeCount};
}

Result<InstanceId> Scene::addInstance(PartId part, const glm::mat4& transform) {
  if (toIndex(part) >= parts_.size()) return badId("part", toIndex(part), parts_.size());
  Instance instance;
  instance.part = toIndex(part);
  instance.transform = transform;
  auto id = static_cast<std::uint32_t>(instances_.size());
  instances_.push_back(instance);
  return InstanceId{id};
}

Status Scene::checkInstance(InstanceId instance) const {
  if (toIndex(instance) >= instances_.size()) return badId("instance", toIndex(instance), instances_.size());
  return {};
}

Status Scene::checkFace(FaceId face) const {
  if (toIndex(face) >= faces_.size()) return badId("face", toIndex(face), faces_.size());
  return {};
}

Status Scene::setInstanceTransform(InstanceId instance, const glm::mat4& transform) {
  CETVIEW_TRY(checkInstance(instance));
  instances_[toIndex(instance)].transform = transform;
  return {};
}

Status Scene::setInstanceColor(InstanceId instance, std::optional<Color8> color) {
  CETVIEW_TRY(checkInstance(instance));
  instances_[toIndex(instance)].color = color;
  return {};
}

Status Scene::setInstanceVisible(InstanceId instance, bool visible) {
  CETVIEW_TRY(checkInstance(instance));
  instances_[toIndex(instance)].visible = visible;
  return {};
}

std::uint32_t Scene::appendVertices(const MeshVertex* vertices, std::size_t count) {
  auto first = static_cast<std::uint32_t>(vertices_.size());
  vertices_.insert(vertices_.end(), vertices, vertices + count);
  return first;
}

Status Scene::setFaceIndices(FaceId face, const std::uint32_t* indices, std::size_t count) {
  CETVIEW_TRY(checkFace(face));
  if (count % 3 != 0) {
    return makeError(ErrorCode::kInvalidArgument, "face " + std::to_string(toIndex(face)) + ": " +
                                                      std::to_string(count) +
                                                      " indices is not whole triangles");
  }
  Face& f = faces_[toIndex(face)];
  Part& part = parts_[f.part];
  std::uint32_t limit = vertexCount();
  std::uint32_t required = 0;
  Bounds box;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint32_t v = indices[i];
    if (v >= limit) {
      return makeError(ErrorCode::kInvalidArgument, "face " + std::to_string(toIndex(face)) + ": index " +
                                                        std::to_string(v) + " >= vertex count " +
                                                        std::to_string(limit));
    }
    if (v >= required) required = v + 1;
    const float* p = vertices_[v].position;
    box.add(glm::vec3(p[0], p[1], p[2]));
  }
  part.bounds.add(box);

  if (f.queued) pendingIndexBytes_ -= f.pending.size() * sizeof(std::uint32_t);
  f.pending.assign(indices, indices + count);
  reorderForVertexReuse(f.pending);
  pendingIndexBytes_ += count * sizeof(std::uint32_t);
  f.requiredVertices = required;
  ++f.serial;
  if (!f.queued) {
    f.queued = true;
    faceQueue_.push_back(toIndex(face));
  }
  return {};
}

Status Scene::setEdgePolyline(EdgeId edge, const float* xyz, std::size_t pointCount) {
  if (toIndex(edge) >= edges_.size()) return badId("edge", toIndex(edge), edges_.size());
  Edge& e = edges_[toIndex(edge)];
  Part& part = parts_[e.part];
  if (e.queued) pendingEdgeBytes_ -= e.pending.size() * sizeof(float);
  e.pending.clear();
  // A line list (each inner point twice) draws every edge of every part in one indirect call.
  for (std::size_t i = 0; i + 1 < pointCount; ++i) {
    e.pending.insert(e.pending.end(), xyz + 3 * i, xyz + 3 * i + 6);
  }
  for (std::size_t i = 0; i < pointCount; ++i)
    part.bounds.add(glm::vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
  pendingEdgeBytes_ += e.pending.size() * sizeof(float);
  ++e.serial;
  if (!e.queued) {
    e.queued = true;
    edgeQueue_.push_back(toIndex(edge));
  }
  return {};
}

Status Scene::setFaceColor(FaceId face, Color8 color) {
  CETVIEW_TRY(checkFace(face));
  Face& f = faces_[toIndex(face)];
  if (f.color != color) ++parts_[f.part].drawVersion;
  f.color = color;
  faceColorsDirty_.mark(toIndex(face));
  return {};
}

Status Scene::setFaceVisible(FaceId face, bool visible) {
  CETVIEW_TRY(checkFace(face));
  Face& f = faces_[toIndex(face)];
  if (f.visible == visible) return {};
  f.visible = visible;
  ++parts_[f.part].drawVersion;
  faceDrawsDirty_.mark(toIndex(face));
  return {};
}

Bounds Scene::bounds() const {
  Bounds world;
  for (const Instance& instance : instances_) {
    if (!instance.visible) continue;
    const Bounds& b = parts_[instance.part].bounds;
    if (b.empty()) continue;
    for (int i = 0; i < 8; ++i) {
      glm::vec4 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z,
                       1.0f);
      world.add(glm::vec3(instance.transform * corner));
    }
  }
  return world;
}

std::uint64_t Scene::pendingBytes() const {
  return (vertices_.size() - uploadedVertices_) * sizeof(MeshVertex) + pendingIndexBytes_ + pendingEdgeBytes_;
}

bool Scene::uploadsPending() const {
  return pendingBytes() > 0 || faceQueueHead_ < faceQueue_.size() || edgeQueueHead_ < edgeQueue_.size() ||
         !faceColorsDirty_.empty() || !faceDrawsDirty_.empty();
}

void Scene::clear() {
  std::uint64_t generation = generation_ + 1;
  *this = Scene();
  generation_ = generation;
}

}  // namespace cetview::engine
