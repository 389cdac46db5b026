#include "stream/stream_consumer.h"

#include <algorithm>
#include <cstring>

namespace cetview::stream {

StreamConsumer::StreamConsumer(ProgressiveStream& stream, std::size_t faceCount)
    : stream_(stream), faces_(faceCount), control_(stream.controlRing()), showLevel_(stream.targetLevel()) {
  for (std::size_t i = 0; i < stream.workerRingCount(); ++i) readers_.emplace_back(stream.workerRing(i));
  held_.resize(stream.workerRingCount());
  ringLevel_.assign(stream.workerRingCount(), -1);
}

std::size_t StreamConsumer::poll(std::size_t byteBudget, MeshSink& sink) {
  std::size_t read = 0;
  // Level-done records first, so that rings found empty below prove their levels complete.
  RecordReader::Record r;
  while (control_.next(r)) {
    if (r.tag == kEdgeLevel && r.size >= sizeof(EdgeLevelHeader)) {
      EdgeLevelHeader h;
      std::memcpy(&h, r.data, sizeof h);
      if (edgeLevels_.size() <= h.level) edgeLevels_.resize(h.level + 1);
      edgeLevels_[h.level].assign(r.data, r.data + r.size);
      showEdges(sink);
      continue;
    }
    if (r.tag != kLevelDone || r.size < sizeof(LevelDoneHeader)) continue;
    LevelDoneHeader h;
    std::memcpy(&h, r.data, sizeof h);
    levelDone_.push_back(h);
  }
  bool progress = true;
  while (progress && read < byteBudget) {
    progress = false;
    for (std::size_t i = 0; i < readers_.size() && read < byteBudget; ++i) {
      if (!readers_[i].next(r)) continue;
      progress = true;
      read += r.size;
      if (r.tag != kFaceLevel || r.size < sizeof(FaceLevelHeader)) continue;
      FaceLevelHeader h;
      std::memcpy(&h, r.data, sizeof h);
      ringLevel_[i] = static_cast<int>(h.level);
      if (static_cast<int>(h.level) > showLevel_ || !held_[i].empty()) {
        held_[i].emplace_back(r.data, r.data + r.size);
      } else {
        apply(r.data, r.size, sink);
      }
    }
  }
  while (!levelDone_.empty() && drainedBelow(static_cast<int>(levelDone_.front().level))) {
    const LevelDoneHeader& h = levelDone_.front();
    if (static_cast<int>(h.level) == completeLevel() + 1) {
      levels_.push_back(LevelStat{static_cast<int>(h.level), h.ms, h.triangles, h.chordal});
    }
    levelDone_.pop_front();
  }
  return read;
}

bool StreamConsumer::drainedBelow(int level) {
  for (std::size_t i = 0; i < readers_.size(); ++i) {
    if (ringLevel_[i] > level) continue;  // records come level by level in each ring
    if (stream_.workerRing(i).usedBytes() != 0) return false;
  }
  return true;
}

void StreamConsumer::setShowLevel(int level, MeshSink& sink) {
  showLevel_ = level;
  // Held records now allowed, coarsest first so each face's vertices stay in order across rings.
  for (;;) {
    std::size_t best = held_.size();
    std::uint32_t bestLevel = 0;
    for (std::size_t i = 0; i < held_.size(); ++i) {
      if (held_[i].empty()) continue;
      FaceLevelHeader h;
      std::memcpy(&h, held_[i].front().data(), sizeof h);
      if (static_cast<int>(h.level) > level) continue;
      if (best == held_.size() || h.level < bestLevel) best = i, bestLevel = h.level;
    }
    if (best == held_.size()) break;
    apply(held_[best].front().data(), held_[best].front().size(), sink);
    held_[best].pop_front();
  }
  for (std::uint32_t f = 0; f < faces_.size(); ++f) show(f, sink);
  showEdges(sink);
}

void StreamConsumer::showEdges(MeshSink& sink) {
  int want = std::min(showLevel_, static_cast<int>(edgeLevels_.size()) - 1);
  while (want >= 0 && edgeLevels_[static_cast<std::size_t>(want)].empty()) --want;
  if (want < 0 || want == shownEdgeLevel_) return;
  shownEdgeLevel_ = want;
  const std::vector<std::uint8_t>& data = edgeLevels_[static_cast<std::size_t>(want)];
  EdgeLevelHeader h;
  std::memcpy(&h, data.data(), sizeof h);
  std::size_t at = sizeof h;
  std::vector<float> xyz;
  for (std::uint32_t i = 0; i < h.edgeCount && at + 8 <= data.size(); ++i) {
    std::uint32_t entry[2];
    std::memcpy(entry, data.data() + at, sizeof entry);
    at += sizeof entry;
    const std::size_t bytes = std::size_t{entry[1]} * 3 * sizeof(float);
    if (at + bytes > data.size()) return;  // corrupt: stop rather than read past the record
    xyz.resize(std::size_t{entry[1]} * 3);
    if (bytes > 0) std::memcpy(xyz.data(), data.data() + at, bytes);
    at += bytes;
    sink.setEdgePolyline(entry[0], xyz.data(), entry[1]);
  }
}

void StreamConsumer::apply(const std::uint8_t* data, std::size_t size, MeshSink& sink) {
  FaceLevelHeader h;
  std::memcpy(&h, data, sizeof h);
  const std::size_t need = sizeof h + std::size_t{h.vertexCount} * sizeof(StreamVertex) +
                           std::size_t{h.indexCount} * sizeof(std::uint32_t);
  if (h.face >= faces_.size() || size < need) return;
  Face& face = faces_[h.face];
  if (h.firstVertex > face.localCount) {
    // A face's levels can be published by different workers, so its level k+1 record may be read
    // before its level k record still waiting in another ring: keep it until that one is applied
    // (dropping it left the face stuck at level k, and every later level with it).
    face.deferred.emplace_back(data, data + size);
    return;
  }
  // New vertices only: a level published again after a cancellation repeats some.
  const std::uint32_t skip = face.localCount - h.firstVertex;
  if (h.vertexCount > skip) {
    const auto* v = reinterpret_cast<const StreamVertex*>(data + sizeof h) + skip;
    const std::uint32_t count = h.vertexCount - skip;
    const std::uint32_t global = sink.appendVertices(v, count);
    face.segments.push_back(Segment{face.localCount, global});
    face.localCount += count;
  }
  std::vector<std::uint32_t> indices(h.indexCount);
  if (!indices.empty()) {
    std::memcpy(indices.data(), data + sizeof h + std::size_t{h.vertexCount} * sizeof(StreamVertex),
                indices.size() * sizeof(std::uint32_t));
  }
  for (std::uint32_t& i : indices) {
    if (i >= face.localCount) return;  // corrupt record: never index outside the shared array
    const auto it = std::upper_bound(face.segments.begin(), face.segments.end(), i,
                                     [](std::uint32_t v, const Segment& s) { return v < s.local; });
    i = (it - 1)->global + (i - (it - 1)->local);
  }
  if (face.levels.size() <= h.level) face.levels.resize(h.level + 1);
  if (face.shown == static_cast<int>(h.level)) {  // replaced while shown: send it again
    shownTriangles_ -= face.levels[h.level].size() / 3;
    face.shown = -1;
  }
  face.levels[h.level] = std::move(indices);
  show(h.face, sink);
  // Deferred records this one makes applicable, lowest vertex offset first.
  while (!face.deferred.empty()) {
    std::size_t best = face.deferred.size();
    std::uint32_t bestFirst = 0;
    for (std::size_t i = 0; i < face.deferred.size(); ++i) {
      FaceLevelHeader d;
      std::memcpy(&d, face.deferred[i].data(), sizeof d);
      if (d.firstVertex <= face.localCount && (best == face.deferred.size() || d.firstVertex < bestFirst)) {
        best = i, bestFirst = d.firstVertex;
      }
    }
    if (best == face.deferred.size()) break;
    std::vector<std::uint8_t> record = std::move(face.deferred[best]);
    face.deferred.erase(face.deferred.begin() + static_cast<std::ptrdiff_t>(best));
    apply(record.data(), record.size(), sink);  // may apply further deferred records itself
    break;
  }
}

void StreamConsumer::show(std::uint32_t f, MeshSink& sink) {
  Face& face = faces_[f];
  int want = std::min(showLevel_, static_cast<int>(face.levels.size()) - 1);
  while (want >= 0 && face.levels[static_cast<std::size_t>(want)].empty()) --want;
  if (want == face.shown) return;
  if (face.shown >= 0) shownTriangles_ -= face.levels[static_cast<std::size_t>(face.shown)].size() / 3;
  face.shown = want;
  if (want < 0) {
    sink.setFaceIndices(f, nullptr, 0);
    return;
  }
  const auto& idx = face.levels[static_cast<std::size_t>(want)];
  shownTriangles_ += idx.size() / 3;
  sink.setFaceIndices(f, idx.data(), idx.size());
}

}  // namespace cetview::stream
