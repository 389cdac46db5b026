#include "engine/gpu_scene.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include <glm/matrix.hpp>

#include "engine/gpu_structs.h"
#include "engine/vk_check.h"

namespace cetview::engine {
namespace {

constexpr VkDeviceSize kFaceDrawSize = sizeof(VkDrawIndexedIndirectCommand);
constexpr VkDeviceSize kEdgeDrawSize = sizeof(VkDrawIndirectCommand);
constexpr VkDeviceSize kEdgePointSize = 3 * sizeof(float);
constexpr VkDeviceSize kMinTableEntries = 256;

}  // namespace

GpuScene::GpuScene(const Device& device, Scene& scene, const GpuSceneOptions& options)
    : device_(device), scene_(scene), options_(options) {
  // Not on CPU devices unless asked: there the one-by-one path's culling of clusters outside the
  // view or facing away (face_culling.h) spares lavapipe's front end, and issuing draws costs it
  // little. (Multi-part scenes once drew 40x slower on lavapipe with indirect draws, and 30-180x
  // slower on an NVIDIA H200: that was the wrap-round of the draw loop in recordFaceDraws().)
  const bool cpu = device.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  indirect_ = options.indirectDraws && (!cpu || options.indirectDrawsOnCpu) &&
              device.features.multiDrawIndirect && device.features.drawIndirectFirstInstance;
  multiDraw_ = !indirect_ && options.multiDraw && device.features.multiDraw;
}

Result<std::unique_ptr<GpuScene>> GpuScene::create(const Device& device, Scene& scene,
                                                   const GpuSceneOptions& options) {
  std::unique_ptr<GpuScene> result(new GpuScene(device, scene, options));
  CETVIEW_TRY(result->init());
  return result;
}

Status GpuScene::init() {
  constexpr VkBufferUsageFlags copy = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  buffers_[kVertices].usage = copy | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  buffers_[kIndices].usage = copy | VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
  buffers_[kEdgePoints].usage = copy | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  buffers_[kFaceDraws].usage = copy | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
  buffers_[kFaceColors].usage = copy | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  buffers_[kEdgeDraws].usage = copy | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
  const VkDeviceSize initial[kTargetCount] = {
      std::max<VkDeviceSize>(options_.initialVertexCapacity, 64) * sizeof(MeshVertex),
      std::max<VkDeviceSize>(options_.initialIndexCapacity, 192) * sizeof(std::uint32_t),
      std::max<VkDeviceSize>(options_.initialEdgePointCapacity, 64) * kEdgePointSize,
      kMinTableEntries * kFaceDrawSize,
      kMinTableEntries * sizeof(std::uint32_t),
      kMinTableEntries * kEdgeDrawSize,
  };
  for (int t = 0; t < kTargetCount; ++t) {
    auto buffer = createBuffer(device_, initial[t], buffers_[t].usage, MemoryUse::kDeviceLocal);
    CETVIEW_TRY(buffer);
    buffers_[t].buffer = *buffer;
  }
  indexSlots_ = RangeAllocator(buffers_[kIndices].buffer.size / sizeof(std::uint32_t));
  edgeSlots_ = RangeAllocator(buffers_[kEdgePoints].buffer.size / kEdgePointSize);
  generation_ = scene_.generation_;
  return {};
}

GpuScene::~GpuScene() {
  for (Growable& g : buffers_) destroyBuffer(device_, g.buffer);
}

void GpuScene::reset() {
  indexSlots_ = RangeAllocator(indexSlots_.capacity());
  edgeSlots_ = RangeAllocator(edgeSlots_.capacity());
  faces_.clear();
  edges_.clear();
  partDraws_.clear();
  committedIndices_ = 0;
  generation_ = scene_.generation_;
}

Status GpuScene::reserve(Target t, VkDeviceSize bytes, VkDeviceSize keepBytes) {
  Growable& g = buffers_[t];
  if (bytes <= g.buffer.size) return {};
  VkDeviceSize size = std::max<VkDeviceSize>(bytes, g.buffer.size * 2);
  size = (size + 255) / 256 * 256;
  auto buffer = createBuffer(device_, size, g.usage, MemoryUse::kDeviceLocal);
  CETVIEW_TRY(buffer);
  auto earlier =
      std::find_if(growths_.begin(), growths_.end(), [t](const Growth& x) { return x.target == t; });
  if (earlier != growths_.end()) {
    // Grown twice in one frame: copy straight from the original buffer; the intermediate one was
    // never referenced by a command and goes at once.
    destroyBuffer(device_, g.buffer);
  } else {
    growths_.push_back(Growth{t, g.buffer, std::min(keepBytes, g.buffer.size)});
  }
  g.buffer = *buffer;
  if (stats_) ++stats_->bufferGrowths;
  return {};
}

Status GpuScene::growTables() {
  auto faceCount = static_cast<std::uint32_t>(faces_.size());
  std::uint32_t sceneFaces = scene_.faceCount();
  if (sceneFaces > faceCount) {
    CETVIEW_TRY(reserve(kFaceDraws, sceneFaces * kFaceDrawSize, faceCount * kFaceDrawSize));
    CETVIEW_TRY(reserve(kFaceColors, sceneFaces * sizeof(std::uint32_t), faceCount * sizeof(std::uint32_t)));
    // New faces: no triangles (zero draw commands), their part's colour.
    fills_.push_back(
        Fill{kFaceDraws, faceCount * kFaceDrawSize, (sceneFaces - faceCount) * kFaceDrawSize, 0u});
    for (const Scene::Part& part : scene_.parts_) {
      std::uint32_t begin = std::max(part.firstFace, faceCount);
      std::uint32_t end = part.firstFace + part.faceCount;
      if (begin >= end) continue;
      fills_.push_back(
          Fill{kFaceColors, begin * VkDeviceSize{4}, (end - begin) * VkDeviceSize{4}, packColor(part.color)});
    }
    faces_.resize(sceneFaces);
  }
  auto edgeCount = static_cast<std::uint32_t>(edges_.size());
  std::uint32_t sceneEdges = scene_.edgeCount();
  if (sceneEdges > edgeCount) {
    CETVIEW_TRY(reserve(kEdgeDraws, sceneEdges * kEdgeDrawSize, edgeCount * kEdgeDrawSize));
    fills_.push_back(
        Fill{kEdgeDraws, edgeCount * kEdgeDrawSize, (sceneEdges - edgeCount) * kEdgeDrawSize, 0u});
    edges_.resize(sceneEdges);
  }
  return {};
}

bool GpuScene::stage(std::initializer_list<Piece> pieces, std::uint64_t* ringOffsets) {
  constexpr std::uint64_t kAlign = UploadRing::kAlignment;
  std::uint64_t total = 0;
  for (const Piece& p : pieces) total += (p.size + kAlign - 1) / kAlign * kAlign;
  if (total == 0) return true;
  if (total > remaining_ || ringFull_) return false;
  auto block = ring_->allocate(total);
  if (!block) {
    ringFull_ = true;
    return false;
  }
  remaining_ -= total;
  stats_->bytes += total;
  std::uint64_t offset = *block;
  std::size_t i = 0;
  for (const Piece& p : pieces) {
    if (ringOffsets) ringOffsets[i++] = offset;
    if (p.size == 0) continue;
    std::memcpy(ring_->data(offset), p.data, p.size);
    copies_[p.target].push_back(VkBufferCopy{offset, p.dstOffset, p.size});
    offset += (p.size + kAlign - 1) / kAlign * kAlign;
  }
  return true;
}

VkDrawIndexedIndirectCommand GpuScene::faceDraw(std::uint32_t face) const {
  const FaceSlot& slot = faces_[face];
  bool visible = scene_.faces_[face].visible && slot.count > 0;
  VkDrawIndexedIndirectCommand draw{};
  draw.indexCount = visible ? static_cast<std::uint32_t>(slot.count) : 0u;
  draw.instanceCount = visible ? 1u : 0u;
  draw.firstIndex = static_cast<std::uint32_t>(slot.offset);
  draw.vertexOffset = 0;
  draw.firstInstance = face;
  return draw;
}

bool GpuScene::writeFaceDraw(std::uint32_t face, const Piece* data) {
  VkDrawIndexedIndirectCommand draw = faceDraw(face);
  FaceSlot& slot = faces_[face];
  Piece command{kFaceDraws, face * kFaceDrawSize, &draw, sizeof(draw)};
  if (slot.drawWrittenFrame == frame_) {
    // Already staged this frame: two copies to one destination in one command would overlap, so
    // rewrite the bytes the recorded copy reads (it executes after submission).
    if (data && !stage({*data})) return false;
    std::memcpy(ring_->data(slot.drawRingOffset), &draw, sizeof(draw));
  } else {
    std::uint64_t offsets[2] = {0, 0};
    bool staged = data ? stage({command, *data}, offsets) : stage({command}, offsets);
    if (!staged) return false;
    slot.drawWrittenFrame = frame_;
    slot.drawRingOffset = offsets[0];
  }
  scene_.faceDrawsDirty_.unmark(face);
  return true;
}

void GpuScene::uploadFaceColors() {
  std::uint32_t id = 0;
  while (scene_.faceColorsDirty_.front(&id)) {
    std::uint32_t packed = packColor(scene_.faces_[id].color);
    if (!stage(kFaceColors, id * VkDeviceSize{4}, &packed, sizeof(packed))) return;
    scene_.faceColorsDirty_.popFront();
  }
}

void GpuScene::uploadFaceVisibility() {
  std::uint32_t id = 0;
  while (scene_.faceDrawsDirty_.front(&id)) {
    if (!writeFaceDraw(id)) return;  // writeFaceDraw() unmarks it
  }
}

Status GpuScene::uploadVertices() {
  std::uint64_t uploaded = scene_.uploadedVertices_;
  std::uint64_t total = scene_.vertices_.size();
  if (uploaded == total) return {};
  // Whole 16-byte units of budget, so the aligned charge never exceeds what is left.
  std::uint64_t count =
      std::min<std::uint64_t>(total - uploaded, (remaining_ & ~std::uint64_t{15}) / sizeof(MeshVertex));
  if (count == 0) return {};
  CETVIEW_TRY(reserve(kVertices, (uploaded + count) * sizeof(MeshVertex), uploaded * sizeof(MeshVertex)));
  if (!stage(kVertices, uploaded * sizeof(MeshVertex), &scene_.vertices_[uploaded],
             count * sizeof(MeshVertex))) {
    return {};
  }
  scene_.uploadedVertices_ = static_cast<std::uint32_t>(uploaded + count);
  stats_->vertices += static_cast<std::uint32_t>(count);
  return {};
}

namespace {

// Budget bytes a final piece of `bytes` plus a draw command of `drawBytes` costs.
std::uint64_t finalCost(std::uint64_t bytes, std::uint64_t drawBytes) {
  constexpr std::uint64_t kAlign = UploadRing::kAlignment;
  return (bytes + kAlign - 1) / kAlign * kAlign + (drawBytes + kAlign - 1) / kAlign * kAlign;
}

}  // namespace

Status GpuScene::uploadFaces() {
  constexpr std::uint64_t kIndexSize = sizeof(std::uint32_t);
  while (scene_.faceQueueHead_ < scene_.faceQueue_.size()) {
    std::uint32_t id = scene_.faceQueue_[scene_.faceQueueHead_];
    Scene::Face& face = scene_.faces_[id];
    FaceSlot& slot = faces_[id];
    // Indices may only reach the GPU after the vertices they use (queue order keeps this cheap).
    if (face.requiredVertices > scene_.uploadedVertices_) return {};
    std::uint64_t n = face.pending.size();

    if (!slot.uploading || slot.serial != face.serial) {
      if (slot.uploading && !slot.inPlace)
        indexSlots_.free(slot.newOffset, slot.newCapacity);  // replaced mid-upload
      // In place only when this frame can finish it: a committed slot is never left half new.
      slot.inPlace = n == 0 || (n <= slot.capacity && finalCost(n * kIndexSize, kFaceDrawSize) <= remaining_);
      if (slot.inPlace) {
        slot.newOffset = slot.offset;
        slot.newCapacity = slot.capacity;
      } else {
        auto offset = indexSlots_.allocate(n);
        if (!offset) {
          std::uint64_t capacity = indexSlots_.capacity();
          CETVIEW_TRY(
              reserve(kIndices, std::max(capacity * 2, capacity + n) * kIndexSize, capacity * kIndexSize));
          indexSlots_.grow(buffers_[kIndices].buffer.size / kIndexSize);
          offset = indexSlots_.allocate(n);
        }
        slot.newOffset = *offset;
        slot.newCapacity = n;
      }
      slot.uploading = true;
      slot.serial = face.serial;
      slot.done = 0;
    }

    std::uint64_t left = n - slot.done;
    if (!slot.inPlace && finalCost(left * kIndexSize, kFaceDrawSize) > remaining_) {
      // Cannot finish this frame: fill the new slot as far as the budget goes.
      std::uint64_t chunk = std::min(left, (remaining_ & ~std::uint64_t{15}) / kIndexSize);
      if (chunk > 0 && stage(kIndices, (slot.newOffset + slot.done) * kIndexSize,
                             face.pending.data() + slot.done, chunk * kIndexSize)) {
        slot.done += chunk;
      }
      return {};
    }

    // Finish: the last indices and the switched draw command go in one staged block.
    FaceSlot before = slot;
    slot.offset = slot.newOffset;
    slot.capacity = slot.newCapacity;
    slot.count = n;
    Piece last{kIndices, (slot.newOffset + slot.done) * kIndexSize, face.pending.data() + slot.done,
               left * kIndexSize};
    if (!writeFaceDraw(id, left > 0 ? &last : nullptr)) {
      slot = before;
      if (slot.inPlace) slot.uploading = false;  // nothing was written: decide afresh next frame
      return {};
    }
    if (!before.inPlace && before.capacity > 0) indexSlots_.free(before.offset, before.capacity);
    if (n == 0 && slot.capacity > 0) {
      indexSlots_.free(slot.offset, slot.capacity);  // an emptied face keeps no slot
      slot.offset = slot.capacity = 0;
    }
    committedIndices_ = committedIndices_ - before.count + n;
    // The culling bounds of what is drawn from now on (one-by-one draws only; see the top of gpu_scene.h).
    if (!indirect_) {
      slot.clusters.clear();
      for (std::uint64_t first = 0; first < n; first += 3 * kClusterTriangles) {
        slot.clusters.push_back(
            computeFaceCullBounds(scene_.vertices_.data(), face.pending.data() + first,
                                  std::min<std::uint64_t>(n - first, 3 * kClusterTriangles)));
      }
    }
    if (face.part < partDraws_.size()) partDraws_[face.part].facesDirty = true;
    slot.uploading = false;
    face.queued = false;
    scene_.pendingIndexBytes_ -= n * kIndexSize;
    std::vector<std::uint32_t>().swap(face.pending);
    ++stats_->facesCompleted;
    if (++scene_.faceQueueHead_ == scene_.faceQueue_.size()) {
      scene_.faceQueue_.clear();
      scene_.faceQueueHead_ = 0;
    }
  }
  return {};
}

Status GpuScene::uploadEdges() {
  while (scene_.edgeQueueHead_ < scene_.edgeQueue_.size()) {
    std::uint32_t id = scene_.edgeQueue_[scene_.edgeQueueHead_];
    Scene::Edge& edge = scene_.edges_[id];
    EdgeSlot& slot = edges_[id];
    std::uint64_t n = edge.pending.size() / 3;  // points

    if (!slot.uploading || slot.serial != edge.serial) {
      if (slot.uploading && !slot.inPlace) edgeSlots_.free(slot.newOffset, slot.newCapacity);
      slot.inPlace =
          n == 0 || (n <= slot.capacity && finalCost(n * kEdgePointSize, kEdgeDrawSize) <= remaining_);
      if (slot.inPlace) {
        slot.newOffset = slot.offset;
        slot.newCapacity = slot.capacity;
      } else {
        auto offset = edgeSlots_.allocate(n);
        if (!offset) {
          std::uint64_t capacity = edgeSlots_.capacity();
          CETVIEW_TRY(reserve(kEdgePoints, std::max(capacity * 2, capacity + n) * kEdgePointSize,
                              capacity * kEdgePointSize));
          edgeSlots_.grow(buffers_[kEdgePoints].buffer.size / kEdgePointSize);
          offset = edgeSlots_.allocate(n);
        }
        slot.newOffset = *offset;
        slot.newCapacity = n;
      }
      slot.uploading = true;
      slot.serial = edge.serial;
      slot.done = 0;
    }

    std::uint64_t left = n - slot.done;
    if (!slot.inPlace && finalCost(left * kEdgePointSize, kEdgeDrawSize) > remaining_) {
      std::uint64_t chunk = std::min(left, (remaining_ & ~std::uint64_t{15}) / kEdgePointSize);
      if (chunk > 0 && stage(kEdgePoints, (slot.newOffset + slot.done) * kEdgePointSize,
                             edge.pending.data() + 3 * slot.done, chunk * kEdgePointSize)) {
        slot.done += chunk;
      }
      return {};
    }

    VkDrawIndirectCommand draw{};
    draw.vertexCount = static_cast<std::uint32_t>(n);
    draw.instanceCount = n > 0 ? 1u : 0u;
    draw.firstVertex = static_cast<std::uint32_t>(slot.newOffset);
    draw.firstInstance = id;
    Piece command{kEdgeDraws, id * kEdgeDrawSize, &draw, sizeof(draw)};
    Piece last{kEdgePoints, (slot.newOffset + slot.done) * kEdgePointSize,
               edge.pending.data() + 3 * slot.done, left * kEdgePointSize};
    if (!stage({command, last})) {
      if (slot.inPlace) slot.uploading = false;
      return {};
    }
    if (!slot.inPlace && slot.capacity > 0) edgeSlots_.free(slot.offset, slot.capacity);
    slot.offset = slot.newOffset;
    slot.capacity = slot.newCapacity;
    slot.count = n;
    if (n == 0 && slot.capacity > 0) {
      edgeSlots_.free(slot.offset, slot.capacity);
      slot.offset = slot.capacity = 0;
    }
    if (edge.part < partDraws_.size()) partDraws_[edge.part].edgesDirty = true;
    slot.uploading = false;
    edge.queued = false;
    scene_.pendingEdgeBytes_ -= edge.pending.size() * sizeof(float);
    std::vector<float>().swap(edge.pending);
    ++stats_->edgesCompleted;
    if (++scene_.edgeQueueHead_ == scene_.edgeQueue_.size()) {
      scene_.edgeQueue_.clear();
      scene_.edgeQueueHead_ = 0;
    }
  }
  return {};
}

Status GpuScene::recordUploads(VkCommandBuffer cmd, UploadRing& ring, std::uint64_t budget,
                               std::vector<Buffer>& retired, UploadStats* stats) {
  UploadStats local;
  stats_ = stats ? stats : &local;
  *stats_ = UploadStats{};
  ring_ = &ring;
  remaining_ = budget;
  ringFull_ = false;
  ++frame_;
  if (generation_ != scene_.generation_) reset();

  Status status = growTables();
  // Small, interactive changes first so toggles stay responsive while geometry streams in.
  if (status) uploadFaceColors();
  if (status) uploadFaceVisibility();
  if (status) status = uploadVertices();
  if (status) status = uploadFaces();
  if (status) status = uploadEdges();
  // Whatever was staged before a failure is still recorded, so CPU and GPU state stay in step.
  emit(cmd, retired);
  stats_->workLeft = scene_.uploadsPending();
  stats_ = nullptr;
  ring_ = nullptr;
  return status;
}

void GpuScene::emit(VkCommandBuffer cmd, std::vector<Buffer>& retired) {
  bool anyCopy =
      std::any_of(std::begin(copies_), std::end(copies_), [](const auto& c) { return !c.empty(); });
  if (growths_.empty() && fills_.empty() && !anyCopy) return;

  // Earlier frames' reads and transfers finish before this frame's transfers touch the buffers.
  memoryBarrier(cmd,
                VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                    VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
  for (Growth& g : growths_) {
    if (g.keepBytes > 0) {
      VkBufferCopy region{0, 0, g.keepBytes};
      vkCmdCopyBuffer(cmd, g.old.buffer, buffers_[g.target].buffer.buffer, 1, &region);
    }
    retired.push_back(g.old);
  }
  for (const Fill& f : fills_) {
    if (f.size > 0) vkCmdFillBuffer(cmd, buffers_[f.target].buffer.buffer, f.offset, f.size, f.value);
  }
  if (!growths_.empty() || !fills_.empty()) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
  }
  for (int t = 0; t < kTargetCount; ++t) {
    if (copies_[t].empty()) continue;
    vkCmdCopyBuffer(cmd, ring_->buffer(), buffers_[t].buffer.buffer,
                    static_cast<std::uint32_t>(copies_[t].size()), copies_[t].data());
    copies_[t].clear();
  }
  memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_INDEX_READ_BIT |
                    VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_SHADER_READ_BIT);
  growths_.clear();
  fills_.clear();
}

namespace {

// The sphere around a part's bounds (culling bounds without a cone), or none for an empty part.
FaceCullBounds sphereAround(const Bounds& bounds) {
  FaceCullBounds sphere;
  if (!bounds.empty()) {
    sphere.center = bounds.center();
    sphere.radius = 0.5f * glm::length(bounds.size());
  }
  return sphere;
}

}  // namespace

GpuScene::PartDraws& GpuScene::partDraws(std::uint32_t part) {
  if (partDraws_.size() < scene_.parts_.size()) partDraws_.resize(scene_.parts_.size());
  PartDraws& draws = partDraws_[part];
  if (draws.facesDirty || draws.sceneVersion != scene_.parts_[part].drawVersion) {
    buildFaceDraws(part, draws);
    draws.facesDirty = false;
    draws.sceneVersion = scene_.parts_[part].drawVersion;
  }
  if (draws.edgesDirty) {
    buildEdgeRuns(part, draws);
    draws.edgesDirty = false;
  }
  return draws;
}

void GpuScene::buildFaceDraws(std::uint32_t part, PartDraws& draws) {
  const Scene::Part& p = scene_.parts_[part];
  // Only faces this GpuScene already knows (tables grow at the start of each upload).
  std::uint32_t end =
      std::min<std::uint32_t>(p.firstFace + p.faceCount, static_cast<std::uint32_t>(faces_.size()));
  std::vector<FaceDraw>& list = draws.faces;
  list.clear();
  for (std::uint32_t f = p.firstFace; f < end; ++f) {
    const FaceSlot& slot = faces_[f];
    const Scene::Face& face = scene_.faces_[f];
    if (slot.count == 0 || !face.visible) continue;
    list.push_back(FaceDraw{f, static_cast<std::uint32_t>(slot.offset),
                            static_cast<std::uint32_t>(slot.count), packColor(face.color),
                            linearColor(face.color)});
  }
  // Slot order, so adjacent slots merge into runs; with multi-draw grouped by colour first, so
  // each colour is one call (the depth test makes the order of opaque faces invisible).
  if (multiDraw_) {
    std::sort(list.begin(), list.end(), [](const FaceDraw& a, const FaceDraw& b) {
      return a.packed != b.packed ? a.packed < b.packed : a.firstIndex < b.firstIndex;
    });
  } else {
    std::sort(list.begin(), list.end(),
              [](const FaceDraw& a, const FaceDraw& b) { return a.firstIndex < b.firstIndex; });
  }
}

void GpuScene::buildEdgeRuns(std::uint32_t part, PartDraws& draws) {
  const Scene::Part& p = scene_.parts_[part];
  std::uint32_t end =
      std::min<std::uint32_t>(p.firstEdge + p.edgeCount, static_cast<std::uint32_t>(edges_.size()));
  std::vector<EdgeRun>& runs = draws.edges;
  runs.clear();
  for (std::uint32_t e = p.firstEdge; e < end; ++e) {
    const EdgeSlot& slot = edges_[e];
    if (slot.count > 0) {
      runs.push_back(
          EdgeRun{static_cast<std::uint32_t>(slot.offset), static_cast<std::uint32_t>(slot.count)});
    }
  }
  std::sort(runs.begin(), runs.end(),
            [](const EdgeRun& a, const EdgeRun& b) { return a.firstPoint < b.firstPoint; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (out > 0 && runs[out - 1].firstPoint + runs[out - 1].pointCount == runs[i].firstPoint) {
      runs[out - 1].pointCount += runs[i].pointCount;
    } else {
      runs[out++] = runs[i];
    }
  }
  runs.resize(out);
}

void GpuScene::recordFaceDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const FrameView& view,
                               VkPipeline twoSided, VkPipeline culled) {
  faceDrawCalls_ = 0;
  clustersCulled_ = 0;
  edgeDrawCalls_ = 0;  // until recordEdgeDraws() (not called without edges)
  if (committedIndices_ == 0) return;
  VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &buffers_[kVertices].buffer.buffer, &zero);
  vkCmdBindIndexBuffer(cmd, buffers_[kIndices].buffer.buffer, 0, VK_INDEX_TYPE_UINT32);
  // At least 1: the loops below step by the count drawn.
  const std::uint32_t maxDraws = std::max(1u, device_.properties.limits.maxDrawIndirectCount);
  constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  VkPipeline bound = VK_NULL_HANDLE;
  for (const Scene::Instance& instance : scene_.instances_) {
    if (!instance.visible) continue;
    const Scene::Part& part = scene_.parts_[instance.part];
    // Only faces this GpuScene already knows (tables grow at the start of each upload).
    std::uint32_t end =
        std::min<std::uint32_t>(part.firstFace + part.faceCount, static_cast<std::uint32_t>(faces_.size()));
    if (part.firstFace >= end) continue;
    // A mirroring transform turns counter-clockwise triangles clockwise: no culling then.
    bool cull = part.closedSolid && glm::determinant(glm::mat3(instance.transform)) > 0.0f;
    VkPipeline pipeline = cull ? culled : twoSided;
    if (pipeline != bound) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      bound = pipeline;
    }
    DrawConstants constants = drawConstants(view, instance.transform, instance.color);
    const CullView cullView =
        makeCullView(constants.modelViewProj, glm::inverse(instance.transform) * view.eye);
    if (outsideFrustum(cullView, sphereAround(part.bounds))) continue;  // the whole instance is out of view
    if (indirect_) {
      vkCmdPushConstants(cmd, layout, kStages, 0, sizeof(constants), &constants);
      // Step by the count drawn, not by the limit: GPUs report a limit of 2^32 - 1, and adding
      // that wraps `first` round to below the part, drawing other parts' faces in this transform.
      for (std::uint32_t first = part.firstFace, count = 0; first < end; first += count) {
        count = std::min(end - first, maxDraws);
        vkCmdDrawIndexedIndirect(cmd, buffers_[kFaceDraws].buffer.buffer, first * kFaceDrawSize, count,
                                 static_cast<std::uint32_t>(kFaceDrawSize));
        ++faceDrawCalls_;
      }
      continue;
    }
    // One by one: runs of adjacent slots (of one colour unless the instance has its own), leaving
    // out the faces that cannot show. The runs of one colour wait in indexRanges_ and go in as few
    // calls as the device allows (multi-draw: one per colour change).
    const PartDraws& draws = partDraws(instance.part);
    const bool ownColors = constants.color.a < 0.0f;
    vkCmdPushConstants(cmd, layout, kStages, 0, sizeof(constants), &constants);
    // Whole faces facing away only where the pipeline culls back faces (not in wireframe).
    const bool backFaces = cull && culled != twoSided;
    bool colorPushed = false;
    std::uint32_t pushed = 0;
    std::uint32_t runFirst = 0, runCount = 0;
    const FaceDraw* runFace = nullptr;  // the run's first face (its colour)
    auto flush = [&] {
      if (runCount == 0) return;
      if (ownColors && (!colorPushed || runFace->packed != pushed)) {
        drawIndexRanges(cmd);  // the previous colour's runs
        vkCmdPushConstants(cmd, layout, kStages, offsetof(DrawConstants, color), sizeof(runFace->color),
                           &runFace->color);
        colorPushed = true;
        pushed = runFace->packed;
      }
      indexRanges_.push_back({runFirst, runCount, 0});
      runCount = 0;
    };
    for (const FaceDraw& face : draws.faces) {
      const std::vector<FaceCullBounds>& clusters = faces_[face.face].clusters;
      for (std::size_t k = 0; k < clusters.size(); ++k) {
        if (outsideFrustum(cullView, clusters[k]) || (backFaces && backFacing(cullView, clusters[k]))) {
          ++clustersCulled_;
          continue;
        }
        const std::uint32_t first = face.firstIndex + static_cast<std::uint32_t>(k) * 3 * kClusterTriangles;
        const std::uint32_t count =
            std::min(face.indexCount - (first - face.firstIndex), 3 * kClusterTriangles);
        if (runCount > 0 && runFirst + runCount == first && (!ownColors || runFace->packed == face.packed)) {
          runCount += count;
          continue;
        }
        flush();
        runFirst = first;
        runCount = count;
        runFace = &face;
      }
    }
    flush();
    drawIndexRanges(cmd);
  }
}

void GpuScene::drawIndexRanges(VkCommandBuffer cmd) {
  if (indexRanges_.empty()) return;
  if (multiDraw_) {
    const std::int32_t vertexOffset = 0;  // the same for every range
    const auto count = static_cast<std::uint32_t>(indexRanges_.size());
    for (std::uint32_t first = 0; first < count; first += device_.features.maxMultiDrawCount) {
      const std::uint32_t n = std::min(count - first, device_.features.maxMultiDrawCount);
      device_.cmdDrawMultiIndexed(cmd, n, indexRanges_.data() + first, 1, 0,
                                  sizeof(VkMultiDrawIndexedInfoEXT), &vertexOffset);
      ++faceDrawCalls_;
    }
  } else {
    for (const VkMultiDrawIndexedInfoEXT& range : indexRanges_) {
      vkCmdDrawIndexed(cmd, range.indexCount, 1, range.firstIndex, 0, 0);
      ++faceDrawCalls_;
    }
  }
  indexRanges_.clear();
}

void GpuScene::recordEdgeDraws(VkCommandBuffer cmd, VkPipelineLayout layout, const FrameView& view) {
  edgeDrawCalls_ = 0;
  VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &buffers_[kEdgePoints].buffer.buffer, &zero);
  // At least 1: the loops below step by the count drawn.
  const std::uint32_t maxDraws = std::max(1u, device_.properties.limits.maxDrawIndirectCount);
  for (const Scene::Instance& instance : scene_.instances_) {
    if (!instance.visible) continue;
    const Scene::Part& part = scene_.parts_[instance.part];
    std::uint32_t end =
        std::min<std::uint32_t>(part.firstEdge + part.edgeCount, static_cast<std::uint32_t>(edges_.size()));
    if (part.firstEdge >= end) continue;
    DrawConstants constants = drawConstants(view, instance.transform, instance.color);
    if (outsideFrustum(makeCullView(constants.modelViewProj, view.eye), sphereAround(part.bounds))) continue;
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(constants), &constants);
    if (indirect_) {
      for (std::uint32_t first = part.firstEdge, count = 0; first < end; first += count) {  // as for faces
        count = std::min(end - first, maxDraws);
        vkCmdDrawIndirect(cmd, buffers_[kEdgeDraws].buffer.buffer, first * kEdgeDrawSize, count,
                          static_cast<std::uint32_t>(kEdgeDrawSize));
        ++edgeDrawCalls_;
      }
    } else if (multiDraw_) {
      const std::vector<EdgeRun>& runs = partDraws(instance.part).edges;
      const auto count = static_cast<std::uint32_t>(runs.size());
      for (std::uint32_t first = 0; first < count; first += device_.features.maxMultiDrawCount) {
        const std::uint32_t n = std::min(count - first, device_.features.maxMultiDrawCount);
        device_.cmdDrawMulti(cmd, n, reinterpret_cast<const VkMultiDrawInfoEXT*>(runs.data() + first), 1, 0,
                             sizeof(EdgeRun));
        ++edgeDrawCalls_;
      }
    } else {
      for (const EdgeRun& run : partDraws(instance.part).edges) {
        vkCmdDraw(cmd, run.pointCount, 1, run.firstPoint, 0);
        ++edgeDrawCalls_;
      }
    }
  }
}

}  // namespace cetview::engine
