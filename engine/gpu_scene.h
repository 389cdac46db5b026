// The GPU copy of a Scene: growable device-local buffers and the per-frame upload of what changed.
//
// Buffers (all device-local, filled only by copies from the upload ring):
//   vertices    MeshVertex[], append-only, as Scene's array
//   indices     uint32[]; each face owns a slot (RangeAllocator) holding its current triangles
//   edgePoints  float3[]; each edge owns a slot holding its line list
//   faceDraws   VkDrawIndexedIndirectCommand per face, firstInstance = face id
//   faceColors  packed sRGB RGBA8 per face (storage buffer, indexed by gl_InstanceIndex)
//   edgeDraws   VkDrawIndirectCommand per edge
// Instances are not uploaded: each draw's push constants carry its transform (draw_constants.h).
//
// Without multi-draw indirect (lavapipe), draws are issued one by one, and there each costs about
// 5-10 us of the single-threaded front end (llvmpipe flushes and copies its 33 KB fragment state
// per draw: at 1M triangles the 1200 edge and 800 face draws of the benchmark were a fifth of it).
// So each part's edges whose slots follow each other in the edge buffer are drawn as one
// line list, and its faces as runs of adjacent slots of one colour (the colour goes in the push
// constants, so no per-face colour reaches the shaders). With VK_EXT_multi_draw (lavapipe has it)
// the faces are ordered by colour and all runs of one colour go in one call, as do a part's edge
// runs: a few calls per instance instead of hundreds (about 600 -> 3 in the 1M-triangle benchmark).
// Clusters of kClusterTriangles consecutive triangles of a face that lie outside the view frustum,
// or wholly face away from the eye on a culled closed solid, are left out as each frame is recorded
// (face_culling.h): about a quarter of a curved closed model's triangles then never reach
// lavapipe's front end. On every device, instances whose part's bounding sphere lies outside the
// view frustum are not drawn. Each part's drawable faces are kept in order, rebuilt only when a
// slot, a face colour or a visibility changed.
//
// A face's new index array goes in place when it fits its slot and the whole array fits this
// frame's budget; otherwise into a fresh slot, over as many frames as the budget needs, and the
// face's draw command switches to it in the frame whose copies complete it. The draw command is
// rewritten in that same frame, so a freed slot is never drawn from after it is reused. All copies
// of a frame are recorded before its render pass, between global barriers (previous frames' reads
// -> transfer, transfer -> this frame's reads), so in-place overwrites and slot reuse are safe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/vec4.hpp>

#include "engine/context.h"
#include "engine/draw_constants.h"
#include "engine/face_culling.h"
#include "engine/range_allocator.h"
#include "engine/resources.h"
#include "engine/scene.h"
#include "engine/upload_ring.h"

namespace cetview::engine {

// Triangles per culling cluster of a face (one-by-one draws): small enough for the clusters of a
// curved surface to face one way, large enough that the extra draw calls cost less than they save.
inline constexpr std::uint32_t kClusterTriangles = 128;

struct GpuSceneOptions {
  std::uint64_t initialVertexCapacity = 1u << 16;     // vertices (buffers double when full)
  std::uint64_t initialIndexCapacity = 1u << 18;      // uint32 indices
  std::uint64_t initialEdgePointCapacity = 1u << 14;  // edge points
  bool indirectDraws = true;  // multi-draw indirect where the device allows; false: one by one, per run
  // Also on CPU devices (lavapipe), where it is off by default: there the one-by-one path's
  // culling of clusters that cannot show spares the front end (see the constructor).
  bool indirectDrawsOnCpu = false;
  // Draws one by one: the ranges of one colour in one call where the device has VK_EXT_multi_draw;
  // false: one call per range.
  bool multiDraw = true;
};

// What one frame's upload did.
struct UploadStats {
  std::uint64_t bytes = 0;           // copied through the upload ring
  std::uint32_t vertices = 0;        // appended vertices uploaded
  std::uint32_t facesCompleted = 0;  // faces whose new index array is drawn from this frame on
  std::uint32_t edgesCompleted = 0;
  std::uint32_t bufferGrowths = 0;  // device buffers replaced by larger ones
  bool workLeft = false;            // the budget (or ring) ran out with changes still waiting
};

class GpuScene {
 public:
  // Errors: as createBuffer().
  static Result<std::unique_ptr<GpuScene>> create(const Device& device, Scene& scene,
                                                  const GpuSceneOptions& options);
  // The device must be idle (nothing in flight reads these buffers).
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  // Records, into `cmd` outside a render pass, the copies of up to `budget` bytes of the Scene's
  // pending changes, staged in `ring`. Buffers replaced by larger ones are appended to `retired`;
  // destroy them once this command buffer has finished executing.
  Status recordUploads(VkCommandBuffer cmd, UploadRing& ring, std::uint64_t budget,
                       std::vector<Buffer>& retired, UploadStats* stats);

  // Inside a render pass: every visible face of every visible instance, with `culled` for
  // instances of closed solids that are not mirrored and `twoSided` for the rest (both mesh.vert
  // pipelines; they may be the same). Binds the pipelines itself.
  void recordFaceDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const FrameView& view,
                       VkPipeline twoSided, VkPipeline culled);
  // Inside a render pass with the edge pipeline bound: every edge of every visible instance.
  void recordEdgeDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const FrameView& view);

  VkBuffer faceColorBuffer() const { return buffers_[kFaceColors].buffer.buffer; }
  bool usesIndirectDraws() const { return indirect_; }
  bool usesMultiDraw() const { return multiDraw_; }
  // Draw calls the last recordFaceDraws() / recordEdgeDraws() issued (indirect: one per call).
  std::uint32_t lastFaceDrawCalls() const { return faceDrawCalls_; }
  std::uint32_t lastEdgeDrawCalls() const { return edgeDrawCalls_; }
  // Clusters of faces (per instance) the last recordFaceDraws() left out as invisible.
  std::uint32_t lastClustersCulled() const { return clustersCulled_; }
  std::uint64_t committedTriangles() const { return committedIndices_ / 3; }  // per instance of each part
  std::uint32_t uploadedVertices() const { return scene_.uploadedVertices_; }

 private:
  enum Target { kVertices, kIndices, kEdgePoints, kFaceDraws, kFaceColors, kEdgeDraws, kTargetCount };

  struct Growable {
    Buffer buffer;
    VkBufferUsageFlags usage = 0;
  };
  struct Growth {
    Target target;
    Buffer old;
    VkDeviceSize keepBytes;  // [0, keepBytes) of `old` moves to the new buffer
  };
  struct Fill {
    Target target;
    VkDeviceSize offset, size;
    std::uint32_t value;
  };
  // GPU-side state of one face: its committed slot and an upload in progress.
  struct FaceSlot {
    std::uint64_t offset = 0, capacity = 0, count = 0;  // committed: drawn from
    bool uploading = false;
    bool inPlace = false;      // the upload overwrites the committed slot
    std::uint64_t serial = 0;  // Scene::Face::serial being uploaded
    std::uint64_t newOffset = 0, newCapacity = 0, done = 0;
    std::uint64_t drawWrittenFrame = 0;  // frame whose copies already hold its draw
    std::uint64_t drawRingOffset = 0;
    // Culling bounds of the committed triangles in clusters of kClusterTriangles, in their order
    // (only without indirect draws).
    std::vector<FaceCullBounds> clusters;
  };
  struct EdgeSlot {
    std::uint64_t offset = 0, capacity = 0, count = 0;
    bool uploading = false;
    bool inPlace = false;
    std::uint64_t serial = 0;
    std::uint64_t newOffset = 0, newCapacity = 0, done = 0;
  };

  // Without indirect draws (see the top of this file): a part's drawable faces in slot order, merged
  // into runs as each frame is recorded, and its edges merged once.
  struct FaceDraw {
    std::uint32_t face = 0;
    std::uint32_t firstIndex = 0, indexCount = 0;
    std::uint32_t packed = 0;  // packColor() of the face's colour
    glm::vec4 color{0.0f};     // the same, linear
  };
  // Laid out as VkMultiDrawInfoEXT, so a part's runs go to vkCmdDrawMultiEXT as they are.
  struct EdgeRun {
    std::uint32_t firstPoint = 0, pointCount = 0;
  };
  static_assert(sizeof(EdgeRun) == sizeof(VkMultiDrawInfoEXT) &&
                offsetof(EdgeRun, firstPoint) == offsetof(VkMultiDrawInfoEXT, firstVertex) &&
                offsetof(EdgeRun, pointCount) == offsetof(VkMultiDrawInfoEXT, vertexCount));
  struct PartDraws {
    bool facesDirty = true, edgesDirty = true;
    std::uint64_t sceneVersion = ~std::uint64_t{0};  // Scene::Part::drawVersion `faces` matches
    std::vector<FaceDraw> faces;                     // visible, non-empty, by firstIndex
    std::vector<EdgeRun> edges;                      // adjacent slots merged, by firstPoint
  };

  GpuScene(const Device& device, Scene& scene, const GpuSceneOptions& options);
  PartDraws& partDraws(std::uint32_t part);
  void buildFaceDraws(std::uint32_t part, PartDraws& draws);
  void buildEdgeRuns(std::uint32_t part, PartDraws& draws);
  // Draws and empties indexRanges_ (one by one, with the push constants as they are).
  void drawIndexRanges(VkCommandBuffer cmd);
  Status init();
  void reset();
  // Makes buffers_[t] at least `bytes` large, keeping [0, keepBytes) of its content.
  Status reserve(Target t, VkDeviceSize bytes, VkDeviceSize keepBytes);
  Status growTables();
  // One copy to stage: `size` bytes from `data` to `target` at `dstOffset`.
  struct Piece {
    Target target;
    VkDeviceSize dstOffset;
    const void* data;
    std::uint64_t size;
  };
  // Stages every piece or none, in one ring block charged (16-byte aligned) to the budget; false
  // when the budget or the ring is out. `ringOffsets`, when given, receives each piece's offset.
  bool stage(std::initializer_list<Piece> pieces, std::uint64_t* ringOffsets = nullptr);
  bool stage(Target target, VkDeviceSize dstOffset, const void* data, std::uint64_t size) {
    return stage({Piece{target, dstOffset, data, size}});
  }
  VkDrawIndexedIndirectCommand faceDraw(std::uint32_t face) const;
  // Stages face `face`'s draw command (from its committed slot), together with `data` when given.
  bool writeFaceDraw(std::uint32_t face, const Piece* data = nullptr);
  Status uploadVertices();
  Status uploadFaces();
  Status uploadEdges();
  void uploadFaceColors();
  void uploadFaceVisibility();
  void emit(VkCommandBuffer cmd, std::vector<Buffer>& retired);

  const Device& device_;
  Scene& scene_;
  GpuSceneOptions options_;
  bool indirect_ = false;
  bool multiDraw_ = false;  // one-by-one draws through VK_EXT_multi_draw
  std::uint64_t generation_ = 0;
  Growable buffers_[kTargetCount];
  RangeAllocator indexSlots_;
  RangeAllocator edgeSlots_;
  std::vector<FaceSlot> faces_;
  std::vector<EdgeSlot> edges_;
  std::uint64_t committedIndices_ = 0;
  std::vector<PartDraws> partDraws_;
  std::uint32_t faceDrawCalls_ = 0, edgeDrawCalls_ = 0, clustersCulled_ = 0;
  std::vector<VkMultiDrawIndexedInfoEXT> indexRanges_;  // recordFaceDraws(): runs of one colour

  // Per-frame recording state.
  UploadRing* ring_ = nullptr;
  std::uint64_t remaining_ = 0;
  std::uint64_t frame_ = 0;
  UploadStats* stats_ = nullptr;
  bool ringFull_ = false;
  std::vector<VkBufferCopy> copies_[kTargetCount];
  std::vector<Growth> growths_;
  std::vector<Fill> fills_;
};

}  // namespace cetview::engine
