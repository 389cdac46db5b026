// The model the renderer draws, in the shape the tessellation stream produces it (DESIGN.md, data
// flow 6-7): one shared vertex array that only grows by appending; parts made of faces and edges;
// instances of parts. A face is a colour plus its current index array (uint32 triangles into the
// shared vertex array), replaced wholesale whenever a finer level arrives. An edge is a polyline.
//
// Scene is CPU state only. Every change is recorded here and the Renderer uploads it later, within
// its per-frame byte budget: until a face's new index array is on the GPU the previous one is drawn,
// so a frame never shows a half-replaced face. Only the latest array of a face is uploaded even if
// it was replaced several times in between. Scene keeps a CPU copy of the vertex array (24 bytes
// a vertex: bounds and staging) but drops each index array once it is uploaded. Not thread-safe:
// call from the render thread (the stream's worker hands its snapshots over through its ring).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>

#include "engine/dirty_set.h"
#include "engine/result.h"
#include "engine/types.h"

namespace cetview::engine {

class GpuScene;

// Faces without a colour of their own (the viewer's "file colours off" uses ViewStyle instead).
inline constexpr Color8 kDefaultFaceColor{190, 192, 196, 255};

// The ids addPart() reserved: faces firstFace .. firstFace + faceCount - 1, edges likewise.
struct PartRange {
  PartId part{};
  FaceId firstFace{};
  std::uint32_t faceCount = 0;
  EdgeId firstEdge{};
  std::uint32_t edgeCount = 0;

  FaceId face(std::uint32_t i) const { return FaceId{toIndex(firstFace) + i}; }
  EdgeId edge(std::uint32_t i) const { return EdgeId{toIndex(firstEdge) + i}; }
};

class Scene {
 public:
  // --- Structure -------------------------------------------------------------------------------
  // Reserves `faceCount` faces (all of colour `color`, no triangles yet) and `edgeCount` edges (no
  // points yet). A part is drawn once per visible instance: add at least one.
  // `closedSolid`: the part is a closed shell whose triangles wind counter-clockwise seen from the
  // side its normals point to (outside), so its back faces can never be seen: it is drawn with
  // back-face culling (about a third less work on software rasterisers). Leave false for open
  // shells, or when winding is not guaranteed.
  PartRange addPart(std::uint32_t faceCount, std::uint32_t edgeCount, Color8 color = kDefaultFaceColor,
                    bool closedSolid = false);
  // `transform`: part space -> world, rigid or uniformly scaled (lighting assumes so; a mirror is
  // fine). Instances cost nothing to upload: they are read when each frame is recorded.
  // Errors: kInvalidArgument for an unknown part.
  Result<InstanceId> addInstance(PartId part, const glm::mat4& transform = glm::mat4(1.0f));
  Status setInstanceTransform(InstanceId instance, const glm::mat4& transform);
  // A colour for every face of this instance (nullopt: the faces' own colours).
  Status setInstanceColor(InstanceId instance, std::optional<Color8> color);
  Status setInstanceVisible(InstanceId instance, bool visible);

  // --- Geometry (the progressive stream's two operations) --------------------------------------
  // Appends `count` vertices; returns the index of the first. Indices given to setFaceIndices()
  // are into this one array, across all parts.
  std::uint32_t appendVertices(const MeshVertex* vertices, std::size_t count);

  // Face `face`'s triangles are now `indices` (count a multiple of 3, each < vertexCount()),
  // replacing the previous array (any length; 0 empties the face). Copies the indices; a face of
  // 256 triangles or more whose order reuses vertices poorly has its triangles reordered
  // (triangle_order.h; each keeps its winding).
  // Errors: kInvalidArgument (unknown face, count not a multiple of 3, index out of range).
  Status setFaceIndices(FaceId face, const std::uint32_t* indices, std::size_t count);

  // Edge `edge` is now the polyline through `pointCount` points (xyz floats, in part space),
  // replacing the previous one. Fewer than 2 points empties the edge. Copies the points.
  // Errors: kInvalidArgument (unknown edge).
  Status setEdgePolyline(EdgeId edge, const float* xyz, std::size_t pointCount);

  // --- Per-face state (the viewer's toggles) ---------------------------------------------------
  Status setFaceColor(FaceId face, Color8 color);
  Status setFaceVisible(FaceId face, bool visible);

  // --- Queries ---------------------------------------------------------------------------------
  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>(vertices_.size()); }
  std::uint32_t faceCount() const { return static_cast<std::uint32_t>(faces_.size()); }
  std::uint32_t edgeCount() const { return static_cast<std::uint32_t>(edges_.size()); }
  std::uint32_t partCount() const { return static_cast<std::uint32_t>(parts_.size()); }
  std::uint32_t instanceCount() const { return static_cast<std::uint32_t>(instances_.size()); }
  Color8 faceColor(FaceId face) const { return faces_[toIndex(face)].color; }
  bool faceVisible(FaceId face) const { return faces_[toIndex(face)].visible; }

  // World-space box of every visible instance's part bounds. Part bounds grow with every array set
  // and never shrink (replacements refine the same surface), so this is conservative.
  Bounds bounds() const;
  Bounds partBounds(PartId part) const { return parts_[toIndex(part)].bounds; }

  // Bytes recorded but not yet uploaded (vertices, index arrays, edge points).
  std::uint64_t pendingBytes() const;
  // True while anything (geometry, colours, visibility, instances) still waits for upload.
  bool uploadsPending() const;

  // Forgets everything (ids restart at 0); the renderer drops its GPU copy at the next frame.
  void clear();

 private:
  friend class GpuScene;

  struct Part {
    std::uint32_t firstFace = 0, faceCount = 0, firstEdge = 0, edgeCount = 0;
    Color8 color;
    bool closedSolid = false;
    Bounds bounds;
    std::uint64_t drawVersion = 0;  // bumped when a face's colour or visibility changes
  };
  struct Instance {
    std::uint32_t part = 0;
    glm::mat4 transform{1.0f};
    std::optional<Color8> color;
    bool visible = true;
  };
  struct Face {
    std::uint32_t part = 0;
    Color8 color;
    bool visible = true;
    bool queued = false;                 // in faceQueue_, `pending` holds the array to upload
    std::uint32_t requiredVertices = 0;  // `pending` uses vertices below this
    std::uint64_t serial = 0;            // bumped by every setFaceIndices()
    std::vector<std::uint32_t> pending;
  };
  struct Edge {
    std::uint32_t part = 0;
    bool queued = false;
    std::uint64_t serial = 0;
    std::vector<float> pending;  // line list: xyz per point, 2 points per segment
  };

  Status checkFace(FaceId face) const;
  Status checkInstance(InstanceId instance) const;

  std::vector<MeshVertex> vertices_;  // all vertices; [uploadedVertices_, size) still to upload
  std::uint32_t uploadedVertices_ = 0;
  std::vector<Part> parts_;
  std::vector<Instance> instances_;
  std::vector<Face> faces_;
  std::vector<Edge> edges_;
  std::vector<std::uint32_t> faceQueue_;  // faces with new index arrays, oldest first
  std::size_t faceQueueHead_ = 0;
  std::vector<std::uint32_t> edgeQueue_;
  std::size_t edgeQueueHead_ = 0;
  std::uint64_t pendingIndexBytes_ = 0;
  std::uint64_t pendingEdgeBytes_ = 0;
  DirtySet faceColorsDirty_;
  DirtySet faceDrawsDirty_;       // visibility changed: the draw command must be rewritten
  std::uint64_t generation_ = 0;  // bumped by clear()
};

}  // namespace cetview::engine
