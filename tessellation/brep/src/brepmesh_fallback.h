// The fallback for a face CET cannot mesh from its wires (crossing or missing pcurves, a domain
// without area): OpenCASCADE's BRepMesh on a private copy of the face, so the model has no hole
// there. Its boundary points are its own, so that face may not be watertight with its neighbours.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>

#include "brep/tessellator.h"

namespace cetview::brep {

enum class FallbackResult { kMeshed, kFailed, kCancelled };

// Appends the vertices to mesh and the triangles (oriented for `reversed`) to indices; kFailed,
// with the reason, when BRepMesh produces nothing or is not run (an edge's 3D curve far off the
// face's surface: strayingEdge() in the .cpp). Runs on the calling thread, to the end.
FallbackResult meshFaceWithBRepMesh(const TopoDS_Face& forwardFace, bool reversed, double chordal,
                                    double angle, FaceMesh& mesh, std::vector<std::uint32_t>& indices,
                                    std::string& failure);

// The same, cancellable at once. BRepMesh reads its progress indicator only between its phases,
// and a face's first phase (the surface's grid of points) can run for seconds without a check, so
// BRepMesh runs on a thread of its own while the caller waits and watches the cancel flag.
// Cancelled, run() returns kCancelled within milliseconds, having appended nothing; BRepMesh goes
// on, and the next run() (same face and tolerances) takes up the same job. Destroyed while the
// job runs, it tells BRepMesh to stop at its next check and leaves the thread to end on its own
// (the program waits for such threads when it exits).
class CancellableFallback {
 public:
  CancellableFallback() = default;
  CancellableFallback(const CancellableFallback&) = delete;
  CancellableFallback& operator=(const CancellableFallback&) = delete;
  ~CancellableFallback();

  FallbackResult run(const TopoDS_Face& forwardFace, bool reversed, double chordal, double angle,
                     FaceMesh& mesh, std::vector<std::uint32_t>& indices, std::string& failure,
                     const std::atomic<bool>* cancel);

 private:
  struct Job;
  std::shared_ptr<Job> job_;
};

}  // namespace cetview::brep
