#include "stream/progressive_stream.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace cetview::stream {

bool firstLevelIsCheap(const brep::Model& model) {
  if (model.faces().size() > 16 || model.edgeCount() > 64) return false;
  return std::all_of(model.faces().begin(), model.faces().end(), [](const brep::FaceInfo& f) {
    switch (f.kind) {
      case brep::SurfaceKind::kPlane:
      case brep::SurfaceKind::kCylinder:
      case brep::SurfaceKind::kCone:
      case brep::SurfaceKind::kSphere:
      case brep::SurfaceKind::kTorus:
        return true;
      default:
        return false;
    }
  });
}

ProgressiveStream::ProgressiveStream(brep::Tessellator& tessellator, int targetLevel, const StreamOptions& options)
    : tess_(tessellator), options_(options) {
  options_.threads = std::max(1u, options_.threads);
  const auto& faces = tess_.model().faces();
  order_.resize(faces.size());
  std::iota(order_.begin(), order_.end(), brep::FaceId{0});
  std::stable_sort(order_.begin(), order_.end(),
                   [&](brep::FaceId a, brep::FaceId b) { return faces[a].area > faces[b].area; });
  sent_.assign(faces.size(), 0);
  onKept_ = options_.kept && options_.kept->acquire();
  try {
    setUpRings();
  } catch (...) {
    if (onKept_) options_.kept->release();
    throw;
  }
  target_ = std::clamp(targetLevel, 0, tess_.lastLevel());
  start_ = std::chrono::steady_clock::now();
  if (options_.firstLevelOnCaller && firstLevelIsCheap(tess_.model())) makeFirstLevelHere();
  if (onKept_) {
    options_.kept->launch([this] { coordinate(); });
  } else {
    coordinator_ = std::thread([this] { coordinate(); });
  }
}

void ProgressiveStream::makeFirstLevelHere() {
  onCaller_ = true;
  inProgress_ = 0;
  if (runLevel(0, 1) && publishLevelDone(0)) {
    complete_ = 0;
    firstLevelByCaller_ = true;
  }
  inProgress_ = -1;
  cancel_ = false;
  onCaller_ = false;
}

void ProgressiveStream::setUpRings() {
  StreamThreads* kept = onKept_ ? options_.kept : nullptr;
  if (kept && kept->threads() == options_.threads && kept->ringBytes() == options_.ringBytes) {
    for (unsigned i = 0; i < options_.threads; ++i) rings_.push_back(&kept->workerRing(i));
    control_ = &kept->controlRing();
    for (SpscRing* ring : rings_) ring->reset();
    control_->reset();
    return;
  }
  for (unsigned i = 0; i < options_.threads; ++i) {
    ownRings_.push_back(std::make_unique<SpscRing>(options_.ringBytes));
    rings_.push_back(ownRings_.back().get());
  }
  ownRings_.push_back(std::make_unique<SpscRing>(kControlRingBytes));
  control_ = ownRings_.back().get();
}

ProgressiveStream::~ProgressiveStream() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  if (onKept_) {
    options_.kept->finish();
  } else {
    coordinator_.join();
  }
}

void ProgressiveStream::setTargetLevel(int level) {
  level = std::clamp(level, 0, tess_.lastLevel());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    target_ = level;
    if (inProgress_.load() > level) cancel_ = true;
  }
  wake_.notify_all();
}

StreamProgress ProgressiveStream::progress() const {
  StreamProgress p;
  p.levelInProgress = inProgress_.load();
  p.lastCompleteLevel = complete_.load();
  p.facesDoneInLevel = facesDone_.load();
  p.faceCount = static_cast<std::uint32_t>(order_.size());
  p.targetLevel = target_.load();
  return p;
}

bool ProgressiveStream::idle() const { return inProgress_.load() < 0 && complete_.load() >= target_.load(); }

void ProgressiveStream::waitForLevel(int level, std::chrono::microseconds timeout) const {
  std::unique_lock<std::mutex> lock(mutex_);
  publishedChanged_.wait_for(lock, timeout, [&] { return published_ >= level || stop_.load(); });
}

bool ProgressiveStream::waitForSpace() {
  if (onCaller_) cancel_ = true;  // nobody reads yet: leave the level to the coordinator
  if (cancel_.load(std::memory_order_relaxed)) return false;
  std::this_thread::sleep_for(std::chrono::microseconds(200));
  return !cancel_.load(std::memory_order_relaxed);
}

void ProgressiveStream::coordinate() {
  for (;;) {
    int level;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_.load() || complete_.load() < target_.load(); });
      if (stop_) return;
      cancel_ = false;
      level = complete_.load() + 1;
      inProgress_ = level;
      facesDone_ = 0;
    }
    const bool done = runLevel(level, options_.threads);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      inProgress_ = -1;
      if (done) complete_ = level;
    }
    if (done) publishLevelDone(level);
  }
}

bool ProgressiveStream::publishLevelDone(int level) {
  LevelDoneHeader h{};
  h.level = static_cast<std::uint32_t>(level);
  h.faces = static_cast<std::uint32_t>(order_.size());
  h.triangles = tess_.triangleCount(level);
  h.chordal = tess_.schedule()[static_cast<std::size_t>(level)].chordal;
  h.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  RecordWriter writer(*control_);
  const bool written = writer.write(&h, sizeof h, kLevelDone, [this] {
    if (onCaller_) return false;
    std::this_thread::yield();
    return !stop_.load();
  });
  if (!written) return false;
  if (options_.onLevelPublished) options_.onLevelPublished();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    published_ = std::max(published_, level);
  }
  publishedChanged_.notify_all();
  return true;
}

bool ProgressiveStream::runLevel(int level, unsigned threads) {
  if (!tess_.discretiseEdges(level, threads, &cancel_)) return false;
  if (edgesPublished_ < level) {
    if (!publishEdges(level)) return false;
    edgesPublished_ = level;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> cancelled{false};
  const auto work = [&](unsigned worker) {
    RecordWriter writer(*rings_[worker]);
    std::vector<std::uint8_t> buffer;
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= order_.size()) return;
      const brep::FaceId face = order_[i];
      if (tess_.faceLevel(face) < level) {
        const brep::FaceStatus status = tess_.advanceFace(face, level, &cancel_);
        if (status == brep::FaceStatus::kCancelled || tess_.faceLevel(face) < level) {
          cancelled = true;
          return;
        }
      }
      // Each face is published once per level it reaches; sent_[face] is only touched by the worker
      // that holds the face during this level.
      publishFace(writer, buffer, face, level, tess_.report(face).status, sent_[face]);
      if (cancel_.load()) {
        cancelled = true;
        return;
      }
      ++facesDone_;
    }
  };
  // Workers out of faces help the others' large faces (the end of every level; all of a model of
  // one big face).
  tess_.runWorkers(threads, work);
  return !cancelled.load();
}

bool ProgressiveStream::publishEdges(int level) {
  const auto edges = static_cast<brep::EdgeId>(tess_.model().edgeCount());
  std::vector<std::uint8_t> buffer(sizeof(EdgeLevelHeader));
  std::vector<float> xyz;
  std::uint32_t count = 0;
  for (brep::EdgeId e = 0; e < edges; ++e) {
    tess_.edgePolyline(e, level, xyz);
    if (xyz.empty()) continue;
    const std::uint32_t entry[2] = {e, static_cast<std::uint32_t>(xyz.size() / 3)};
    const auto* a = reinterpret_cast<const std::uint8_t*>(entry);
    const auto* b = reinterpret_cast<const std::uint8_t*>(xyz.data());
    buffer.insert(buffer.end(), a, a + sizeof entry);
    buffer.insert(buffer.end(), b, b + xyz.size() * sizeof(float));
    ++count;
  }
  const EdgeLevelHeader h{static_cast<std::uint32_t>(level), count};
  std::memcpy(buffer.data(), &h, sizeof h);
  RecordWriter writer(*control_);
  return writer.write(buffer.data(), buffer.size(), kEdgeLevel, [this] {
    if (onCaller_) return false;
    std::this_thread::yield();
    return !stop_.load();
  });
}

void ProgressiveStream::publishFace(RecordWriter& writer, std::vector<std::uint8_t>& buffer, brep::FaceId face,
                                    int level, brep::FaceStatus status, std::uint32_t& sentVertices) {
  const brep::FaceMesh& mesh = tess_.faceMesh(face);
  const auto& indices = mesh.levels[static_cast<std::size_t>(level)];
  const std::uint32_t end = mesh.levelVertexEnd[static_cast<std::size_t>(level)];
  const std::uint32_t first = sentVertices;
  FaceLevelHeader h{};
  h.face = face;
  h.level = static_cast<std::uint32_t>(level);
  h.firstVertex = first;
  h.vertexCount = end - first;
  h.indexCount = static_cast<std::uint32_t>(indices.size());
  h.status = static_cast<std::uint32_t>(status);
  buffer.resize(sizeof h + h.vertexCount * sizeof(StreamVertex) + indices.size() * sizeof(std::uint32_t));
  std::memcpy(buffer.data(), &h, sizeof h);
  auto* v = reinterpret_cast<StreamVertex*>(buffer.data() + sizeof h);
  for (std::uint32_t i = first; i < end; ++i, ++v) {
    for (int c = 0; c < 3; ++c) {
      v->position[c] = static_cast<float>(mesh.positions[3 * i + static_cast<std::uint32_t>(c)]);
      v->normal[c] = mesh.normals[3 * i + static_cast<std::uint32_t>(c)];
    }
  }
  if (!indices.empty()) {  // an empty face (nothing could mesh it) has no index array at all
    std::memcpy(buffer.data() + sizeof h + h.vertexCount * sizeof(StreamVertex), indices.data(),
                indices.size() * sizeof(std::uint32_t));
  }
  if (writer.write(buffer.data(), buffer.size(), kFaceLevel, [this] { return waitForSpace(); })) {
    sentVertices = end;
  }
}

}  // namespace cetview::stream
