#include "brepmesh_fallback.h"

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <system_error>
#include <thread>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_Add3dCurve.hxx>
#include <BndLib_AddSurface.hxx>
#include <Bnd_Box.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "surface_eval.h"

namespace cetview::brep {
namespace {

// The job threads of CancellableFallback. When the program exits (this object is destroyed before
// OpenCASCADE's own statics, having been made later), every BRepMesh still running on one is told
// to stop at its next check, and the exit waits for them.
class JobThreads {
 public:
  static JobThreads& instance() {
    static JobThreads threads;
    return threads;
  }
  JobThreads(const JobThreads&) = delete;
  JobThreads& operator=(const JobThreads&) = delete;
  ~JobThreads() {
    stopping_.store(true);
    std::unique_lock<std::mutex> lock(mutex_);
    ended_.wait(lock, [this] { return running_ == 0; });
  }
  void started() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++running_;
  }
  void ended() {
    std::lock_guard<std::mutex> lock(mutex_);
    --running_;
    ended_.notify_all();
  }
  bool stopping() const { return stopping_.load(std::memory_order_relaxed); }

 private:
  JobThreads() = default;
  std::mutex mutex_;
  std::condition_variable ended_;
  int running_ = 0;
  std::atomic<bool> stopping_{false};
};

// BRepMesh asks its progress indicator whether to stop: when the job is abandoned, or at exit.
class StopIndicator : public Message_ProgressIndicator {
 public:
  explicit StopIndicator(const std::atomic<bool>& abandoned) : abandoned_(abandoned) {}
  Standard_Boolean UserBreak() override {
    return abandoned_.load(std::memory_order_relaxed) || JobThreads::instance().stopping();
  }

 protected:
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

 private:
  const std::atomic<bool>& abandoned_;
};

std::string failureOf(const Standard_Failure& e) {
  return std::string("BRepMesh failed: ") + e.GetMessageString();
}

// A copy: BRepMesh stores polygons on the edges it meshes, and the originals are shared with faces
// other threads are meshing. The geometry is copied too, so the copy outlives the model.
TopoDS_Face privateCopy(const TopoDS_Face& face) {
  BRepBuilderAPI_Copy copier(face, Standard_True, Standard_False);
  return TopoDS::Face(copier.Shape());
}

// An edge whose 3D curve strays far from its face, or "" when none does. BRepMesh discretises each
// edge's 3D curve and then works its points against the surface; on a fuzzed face whose degree-14
// edge curve spans a box 1.2e7 across beside a surface 458 across, its model healer (which reads no
// progress indicator, so no cancel reaches it) allocated without end: 24 GB and the process killed.
// A valid edge lies within its tolerance of the surface; beyond kStrayFactor times the surface's
// extent it is not an edge of this face at all, and BRepMesh is not run on it.
std::string strayingEdge(const TopoDS_Face& face) {
  constexpr double kStrayFactor = 10;
  Bnd_Box surfaceBox;
  BndLib_AddSurface::Add(BRepAdaptor_Surface(face), 0.0, surfaceBox);
  if (surfaceBox.IsVoid() || surfaceBox.IsOpen()) return "";
  const double extent = std::sqrt(surfaceBox.SquareExtent());
  int index = 0;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next(), ++index) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (BRep_Tool::Degenerated(edge) || !BRep_Tool::IsGeometric(edge)) continue;
    Bnd_Box curveBox;
    BndLib_Add3dCurve::Add(BRepAdaptor_Curve(edge), 0.0, curveBox);
    if (curveBox.IsVoid()) continue;
    const double curveExtent = curveBox.IsOpen() ? HUGE_VAL : std::sqrt(curveBox.SquareExtent());
    if (curveExtent > kStrayFactor * extent + BRep_Tool::Tolerance(edge)) {
      char line[160];
      std::snprintf(line, sizeof line,
                    "edge %d's 3D curve spans %.3g, far beyond its surface (%.3g): not given to BRepMesh",
                    index, curveExtent, extent);
      return line;
    }
  }
  return "";
}

void runBRepMesh(const TopoDS_Face& face, double chordal, double angle, const Message_ProgressRange& range) {
  IMeshTools_Parameters parameters;
  parameters.Deflection = chordal;
  parameters.Angle = angle;
  parameters.Relative = Standard_False;
  parameters.InParallel = Standard_False;
  BRepMesh_IncrementalMesh mesher(face, parameters, range);
}

// The triangulation BRepMesh left on `face`, appended with exact normals.
FallbackResult appendTriangulation(const TopoDS_Face& face, bool reversed, FaceMesh& mesh,
                                   std::vector<std::uint32_t>& indices, std::string& failure) {
  try {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || tri->NbTriangles() == 0) {
      failure = "BRepMesh produced no triangles";
      return FallbackResult::kFailed;
    }
    const gp_Trsf trsf = loc.Transformation();
    SurfaceEval eval(face);
    const auto base = static_cast<std::uint32_t>(mesh.vertexCount());
    const double sign = reversed ? -1.0 : 1.0;
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(trsf);
      double u = 0, v = 0;
      if (tri->HasUVNodes()) {
        const gp_Pnt2d uv = tri->UVNode(i);
        u = uv.X(), v = uv.Y();
      } else {
        u = 0.5 * (eval.uMin + eval.uMax), v = 0.5 * (eval.vMin + eval.vMax);
        eval.project(p, u, v, 20);
      }
      gp_Pnt s;
      gp_Dir n;
      eval.pointNormal(u, v, s, n);
      mesh.positions.insert(mesh.positions.end(), {p.X(), p.Y(), p.Z()});
      mesh.normals.insert(mesh.normals.end(), {static_cast<float>(sign * n.X()), static_cast<float>(sign * n.Y()),
                                               static_cast<float>(sign * n.Z())});
      mesh.uv.insert(mesh.uv.end(), {u, v});
    }
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a, b, c;
      tri->Triangle(i).Get(a, b, c);  // natural orientation of the surface (the face is FORWARD)
      const std::uint32_t A = base + static_cast<std::uint32_t>(a - 1), B = base + static_cast<std::uint32_t>(b - 1),
                          C = base + static_cast<std::uint32_t>(c - 1);
      if (reversed) {
        indices.insert(indices.end(), {A, C, B});
      } else {
        indices.insert(indices.end(), {A, B, C});
      }
    }
    return FallbackResult::kMeshed;
  } catch (const Standard_Failure& e) {
    failure = failureOf(e);
    return FallbackResult::kFailed;
  }
}

}  // namespace

FallbackResult meshFaceWithBRepMesh(const TopoDS_Face& forwardFace, bool reversed, double chordal,
                                    double angle, FaceMesh& mesh, std::vector<std::uint32_t>& indices,
                                    std::string& failure) {
  try {
    failure = strayingEdge(forwardFace);
    if (!failure.empty()) return FallbackResult::kFailed;
    const TopoDS_Face face = privateCopy(forwardFace);
    runBRepMesh(face, chordal, angle, Message_ProgressRange());
    return appendTriangulation(face, reversed, mesh, indices, failure);
  } catch (const Standard_Failure& e) {
    failure = failureOf(e);
    return FallbackResult::kFailed;
  }
}

struct CancellableFallback::Job {
  TopoDS_Face face;  // the private copy BRepMesh meshes
  std::atomic<bool> abandoned{false};
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;    // under mutex
  std::string failure;  // BRepMesh threw (written before done)
};

CancellableFallback::~CancellableFallback() {
  if (job_) job_->abandoned.store(true);
}

FallbackResult CancellableFallback::run(const TopoDS_Face& forwardFace, bool reversed, double chordal,
                                        double angle, FaceMesh& mesh, std::vector<std::uint32_t>& indices,
                                        std::string& failure, const std::atomic<bool>* cancel) {
  if (cancel == nullptr)
    return meshFaceWithBRepMesh(forwardFace, reversed, chordal, angle, mesh, indices, failure);
  if (!job_) {
    auto job = std::make_shared<Job>();
    try {
      failure = strayingEdge(forwardFace);
      if (!failure.empty()) return FallbackResult::kFailed;
      job->face = privateCopy(forwardFace);
    } catch (const Standard_Failure& e) {
      failure = failureOf(e);
      return FallbackResult::kFailed;
    }
    JobThreads& threads = JobThreads::instance();
    threads.started();
    try {
      std::thread([job, &threads, chordal, angle]() mutable {
        std::string thrown;
        try {
          Handle(StopIndicator) indicator = new StopIndicator(job->abandoned);
          runBRepMesh(job->face, chordal, angle, indicator->Start());
        } catch (const Standard_Failure& e) {
          thrown = failureOf(e);
        } catch (...) {
          thrown = "BRepMesh failed";
        }
        {
          std::lock_guard<std::mutex> lock(job->mutex);
          job->failure = thrown;
          job->done = true;
        }
        job->finished.notify_all();
        job.reset();  // the face's copy goes here or with its last owner, before ended()
        threads.ended();
      }).detach();
    } catch (const std::system_error&) {  // no thread to be had: BRepMesh here, to the end
      threads.ended();
      return meshFaceWithBRepMesh(forwardFace, reversed, chordal, angle, mesh, indices, failure);
    }
    job_ = std::move(job);
  }
  // Raised already: back at once, whether or not the job has finished (a later call takes it up).
  if (cancel->load(std::memory_order_relaxed)) return FallbackResult::kCancelled;
  {
    std::unique_lock<std::mutex> lock(job_->mutex);
    while (!job_->done) {
      if (cancel->load(std::memory_order_relaxed)) return FallbackResult::kCancelled;
      job_->finished.wait_for(lock, std::chrono::milliseconds(2));
    }
  }
  const std::shared_ptr<Job> job = std::move(job_);
  if (!job->failure.empty()) {
    failure = job->failure;
    return FallbackResult::kFailed;
  }
  return appendTriangulation(job->face, reversed, mesh, indices, failure);
}

}  // namespace cetview::brep
