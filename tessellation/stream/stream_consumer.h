// The consumer side of progressive loading, on the render thread: drains the stream's rings within
// a byte budget (it never waits), keeps every face's completed levels, and hands the renderer what
// it should show through a MeshSink. It translates each face's local vertex ids into the sink's one
// growing vertex array, so the renderer sees only "append vertices" and "face F is now these
// triangles" (DESIGN.md "Data flow", step 7).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "stream/progressive_stream.h"
#include "stream/update_records.h"

namespace cetview::stream {

// What the renderer implements (the viewer wires it to engine::Scene).
class MeshSink {
 public:
  virtual ~MeshSink() = default;
  // Appends vertices to the one shared array; returns the index of the first.
  virtual std::uint32_t appendVertices(const StreamVertex* vertices, std::size_t count) = 0;
  // Face `face` (model face id) now shows these triangles (indices into the shared array).
  virtual void setFaceIndices(std::uint32_t face, const std::uint32_t* indices, std::size_t count) = 0;
  // B-rep edge `edge` (model edge id) is now this polyline (xyz floats, part coordinates).
  virtual void setEdgePolyline(std::uint32_t edge, const float* xyz, std::size_t pointCount) = 0;
};

struct LevelStat {
  int level = 0;
  double ms = 0;             // since the stream started, when the level completed
  std::uint64_t triangles = 0;
  double chordal = 0;
};

class StreamConsumer {
 public:
  StreamConsumer(ProgressiveStream& stream, std::size_t faceCount);

  // Reads records (up to about `byteBudget` bytes) and applies those of level <= showLevel() to the
  // sink; finer ones are kept and applied when showLevel() allows. Returns the bytes read.
  std::size_t poll(std::size_t byteBudget, MeshSink& sink);

  // The level to show: each face shows its finest stored level not above it. Lowering it takes
  // effect at once from stored levels; raising it shows what is stored and the rest as it arrives.
  void setShowLevel(int level, MeshSink& sink);
  int showLevel() const { return showLevel_; }

  // Highest level every face has reached and the consumer has applied (-1 before the first).
  int completeLevel() const { return static_cast<int>(levels_.size()) - 1; }
  const std::vector<LevelStat>& levelStats() const { return levels_; }
  // Triangles currently shown over all faces.
  std::uint64_t shownTriangles() const { return shownTriangles_; }
  // Faces' finest stored level (-1: nothing yet).
  int faceLevel(std::uint32_t face) const { return static_cast<int>(faces_[face].levels.size()) - 1; }

 private:
  struct Segment {
    std::uint32_t local, global;  // local ids [local, next segment's local) start at `global`
  };
  struct Face {
    std::vector<Segment> segments;
    std::uint32_t localCount = 0;
    std::vector<std::vector<std::uint32_t>> levels;  // global indices per completed level
    int shown = -1;
    std::vector<std::vector<std::uint8_t>> deferred;  // records read before an earlier level of this face
  };
  void apply(const std::uint8_t* data, std::size_t size, MeshSink& sink);
  void showEdges(MeshSink& sink);
  void show(std::uint32_t face, MeshSink& sink);
  bool drainedBelow(int level);

  ProgressiveStream& stream_;
  std::vector<Face> faces_;
  std::vector<RecordReader> readers_;
  RecordReader control_;
  std::vector<std::deque<std::vector<std::uint8_t>>> held_;  // per ring: records above showLevel_
  std::vector<int> ringLevel_;  // per ring: level of the last record read from it
  std::deque<LevelDoneHeader> levelDone_;  // read, waiting for their faces' records
  std::vector<LevelStat> levels_;
  std::vector<std::vector<std::uint8_t>> edgeLevels_;  // kEdgeLevel payloads by level
  int shownEdgeLevel_ = -1;
  int showLevel_;
  std::uint64_t shownTriangles_ = 0;
};

}  // namespace cetview::stream
