// Coarse-to-fine B-rep tessellation with the CET triangulator (DESIGN.md "Data flow", steps 2-6).
//
// Use (what a progressive worker does):
//   auto t = Tessellator::create(model, params);              // resolves the deflection, plans levels
//   for (k = 0; k < t->schedule().size(); ++k) {
//     t->discretiseEdges(k);                                  // every edge once, shared by its faces
//     for each face f (any threads, one thread per face at a time):
//       t->advanceFace(f, k);                                 // appends vertices, publishes level k
//       const FaceMesh& m = t->faceMesh(f);                   // new vertices [levelVertexBegin(k), end)
//   }                                                         // and m.levels[k], the whole index array
// Or run() does all of it with N threads.
//
// Contracts:
// - discretiseEdges(k) must return before any advanceFace(., k) starts (the caller synchronises).
//   It may run while faces still advance to k-1: levels live in separate arrays.
// - advanceFace() for distinct faces may run concurrently; a face's FaceMesh must not be read while
//   that face advances.
// - A face's vertices are appended and never moved; each completed level's index array is kept, so
//   showing a coarser level is instant. Every completed level k of every face is within
//   schedule()[k].chordal of the exact surface, and shares its boundary vertices (same positions)
//   with the faces across its edges: each completed level is watertight where the B-rep is closed.
//   Exceptions, reported per face: a fallback face (meshed by BRepMesh, with its own boundary
//   points), and a face whose coarse boundary polygon crosses itself in UV, which shows the
//   fallback mesh on those coarse levels and is CET-meshed (watertight) from the first level where
//   its boundary is valid.
// - One bad face never stops the model: it is repaired or gets a fallback mesh, and report() says why.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "brep/model.h"
#include "brep/tolerance.h"
#include "brep/worker_pool.h"

namespace cetview::brep {

struct Level {
  double chordal = 0.0;   // absolute chordal tolerance of this level (model units)
  double angleRad = 0.0;  // angular tolerance of this level
};

enum class FaceStatus : std::uint8_t {
  kPending,    // no level completed yet
  kOk,         // meshed by CET from its exact boundary
  kRepaired,   // meshed by CET after a sound repair of its wires (gap closed, loop reversed, ...)
  kFallback,   // CET could not mesh it (crossing or missing pcurves, ...); OpenCASCADE's mesher did
  kEmpty,      // nothing could mesh it (the face has no area or no usable geometry)
  kCancelled,  // the cancellation flag was raised while it advanced
};
const char* faceStatusName(FaceStatus status);

struct FaceReport {
  FaceStatus status = FaceStatus::kPending;
  std::string reason;  // one line for kRepaired / kFallback / kEmpty
};

// One face's mesh. Vertex i has positions[3i..3i+2], normals[3i..], uv[2i..].
struct FaceMesh {
  std::vector<double> positions;  // part coordinates
  std::vector<float> normals;     // unit exact surface normal, on the face's outer side (orientation applied)
  std::vector<double> uv;         // the surface's own parameters
  // Completed levels: levels[k] holds index triples, counter-clockwise seen from the normals' side.
  std::vector<std::vector<std::uint32_t>> levels;
  std::vector<std::uint32_t> levelVertexEnd;  // vertex count when level k completed

  std::size_t vertexCount() const { return positions.size() / 3; }
  std::uint32_t levelVertexBegin(std::size_t k) const { return k == 0 ? 0u : levelVertexEnd[k - 1]; }
};

// Called with (completed steps, total steps) from the thread that called run().
using ProgressFn = std::function<void(std::size_t done, std::size_t total)>;

class TessellatorImpl;

class Tessellator {
 public:
  struct CreateResult {
    std::unique_ptr<Tessellator> tessellator;  // null on error
    std::string error;
  };
  // Resolves params against the model's bounding box and plans the levels. Fails (one line) for a
  // deflection absurd for this model. Parallel sections run on `pool` when given (shared with
  // other tessellators: one whose run finds it busy works alone), else on a pool of its own.
  static CreateResult create(const Model& model, const MeshParams& params,
                             std::shared_ptr<WorkerPool> pool = nullptr);
  ~Tessellator();

  const Model& model() const;
  double chordal() const;  // the final absolute chordal deflection
  double angleRad() const;
  // Decreasing chordal tolerances, the last one equal to chordal().
  const std::vector<Level>& schedule() const;
  int lastLevel() const { return static_cast<int>(schedule().size()) - 1; }

  // Step 2 of level k (k == edgeLevel() + 1). Returns false when cancelled (the level is then not
  // discretised and may be asked for again).
  bool discretiseEdges(int level, unsigned threads = 1, const std::atomic<bool>* cancel = nullptr);
  int edgeLevel() const;

  // Steps 3-6 for one face, through every level up to `level` (edges discretised that far).
  FaceStatus advanceFace(FaceId face, int level, const std::atomic<bool>* cancel = nullptr);
  int faceLevel(FaceId face) const;  // last completed level, -1 for none
  const FaceMesh& faceMesh(FaceId face) const;
  FaceReport report(FaceId face) const;

  // Runs work(worker) for every worker in [0, threads) on that many threads (worker 0 is the
  // calling thread) and returns when all have returned; for callers that hand faces to workers
  // themselves (advanceFace inside `work`). A worker whose call has returned helps the others: a
  // large face's refinement passes are shared out among idle workers. Meshes are the same for any
  // number of threads. Not reentrant.
  void runWorkers(unsigned threads, const std::function<void(unsigned worker)>& work);

  // All levels up to lastLevel (-1: the final one) for all faces with `threads` threads. Returns
  // false when cancelled.
  bool run(unsigned threads, const ProgressFn& progress = {}, const std::atomic<bool>* cancel = nullptr,
           int lastLevel = -1);

  // Triangles of level k over all faces (parts counted once, not per instance).
  std::size_t triangleCount(int level) const;

  // Edge `edge`'s polyline at level k (discretiseEdges(k) has returned), xyz floats in part
  // coordinates, for drawing B-rep edges; empty for degenerate edges. Safe while faces advance:
  // a discretised level never changes.
  void edgePolyline(EdgeId edge, int level, std::vector<float>& xyz) const;

  // Test hook: the next advanceFace() of `face` throws inside its mesher, as a bug would, so tests
  // can check that the face is isolated (FaceReport says why) and the rest of the model goes on.
  void failFaceForTesting(FaceId face);

  TessellatorImpl& impl() const { return *impl_; }

 private:
  explicit Tessellator(std::unique_ptr<TessellatorImpl> impl);
  std::unique_ptr<TessellatorImpl> impl_;
};

}  // namespace cetview::brep
