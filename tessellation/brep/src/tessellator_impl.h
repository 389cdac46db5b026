// Private: the state behind a Tessellator (shared edges, per-face meshers and meshes).
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "brep/tessellator.h"
#include "brepmesh_fallback.h"
#include "edge_table.h"
#include "face_mesher.h"
#include "work_sharing.h"

namespace cetview::brep {

class TessellatorImpl {
 public:
  TessellatorImpl(const Model& model, double chordal, double angle, std::vector<Level> schedule,
                  std::shared_ptr<WorkerPool> pool);

  struct FaceState {
    std::unique_ptr<SurfaceEval> eval;   // made with the edges' first level, handed to the mesher
    std::unique_ptr<FaceMesher> mesher;  // alive between levels, freed after the last one
    FaceMesh mesh;
    FaceReport report;
    int level = -1;
    bool failed = false;         // an exception escaped its mesher: isolated (see isolateFailedFace)
    bool injectFailure = false;  // failFaceForTesting()
    std::string isolation;       // why it failed, while its fallback mesh is not made yet
    std::unique_ptr<CancellableFallback> fallback;  // that mesh's BRepMesh, while cancelled
  };

  const Model& model;
  double chordal;
  double angle;
  std::vector<Level> schedule;
  std::size_t maxPointsPerFaceLevel = 0;  // MeshParams' work bound
  EdgeTable edges;
  std::atomic<int> edgeLevel{-1};
  std::vector<FaceState> faces;
  bool surfacesReady = false;  // prepareSurfaces() has completed
  // Threads for every parallel section (runWorkers(), the edges, the surfaces): the caller's pool
  // or one of the tessellator's own.
  std::shared_ptr<WorkerPool> poolHolder;
  WorkerPool& pool;
  WorkSharing sharing{pool};  // runWorkers()' idle workers, lent to the faces' refinement passes

  // Every face's SurfaceEval, with `threads` threads, and the edges' face scales from them: the
  // first level's edges need the scales, its faces the evaluators. Returns false when cancelled
  // (faces done so far keep theirs; a later call completes the rest).
  bool prepareSurfaces(unsigned threads, const std::atomic<bool>* cancel);

  // A face whose meshing threw (a bug or exhausted memory, never a property of the input that the
  // mesher knows how to report): its mesher is dropped, BRepMesh meshes it if it can (kFallback), else
  // it stays without triangles (kEmpty); either way with the reason, and levels up to `level` exist,
  // so the rest of the model goes on.
  FaceStatus isolateFailedFace(FaceId face, int level, const std::string& what,
                               const std::atomic<bool>* cancel);
  // The failed face's fallback mesh, on every level up to `level`; kCancelled (to be called again)
  // when the flag stops BRepMesh.
  FaceStatus finishIsolation(FaceId face, int level, const std::atomic<bool>* cancel);
};

// Plans the levels: tolerances halving from about 1% of the diagonal down to `chordal` (faster than
// halving when that would take more than 8 levels), angles coarsening with the square root of the
// tolerance ratio (a circle's sagitta grows with the square of its angle).
std::vector<Level> planLevels(double chordal, double angle, double diagonal, bool progressive);

}  // namespace cetview::brep
