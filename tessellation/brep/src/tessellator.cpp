// The Tessellator: levels, shared edges, per-face advance, and the all-in-one run().
#include "brep/tessellator.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include <Standard_Failure.hxx>
#include <TopoDS.hxx>

#include "brepmesh_fallback.h"
#include "disguised_surface.h"

#include "model_impl.h"
#include "tessellator_impl.h"

namespace cetview::brep {

const char* faceStatusName(FaceStatus status) {
  switch (status) {
    case FaceStatus::kPending: return "pending";
    case FaceStatus::kOk: return "ok";
    case FaceStatus::kRepaired: return "repaired";
    case FaceStatus::kFallback: return "fallback";
    case FaceStatus::kEmpty: return "empty";
    case FaceStatus::kCancelled: return "cancelled";
  }
  return "unknown";
}

std::vector<Level> planLevels(double chordal, double angle, double diagonal, bool progressive) {
  std::vector<Level> levels;
  const double coarse = 0.01 * diagonal;
  int count = 1;
  double factor = 2.0;
  if (progressive && coarse > chordal) {
    count = static_cast<int>(std::ceil(std::log2(coarse / chordal))) + 1;
    if (count > 8) {
      count = 8;
      factor = std::pow(coarse / chordal, 1.0 / 7.0);
    }
  }
  // A level's angle grows with the square root of its chordal ratio (a circle's sagitta grows with
  // the square of its arc), up to 80 degrees: the coarsest levels exist to show the whole model at
  // once, and on a rough free-form face (occ/terrain.brep) a tighter angle made nearly all of level
  // 0's points (4069 of 4094 at 60 degrees).
  const double maxAngle = std::max(angle, 4 * M_PI / 9);
  for (int k = 0; k < count; ++k) {
    const double ratio = std::pow(factor, count - 1 - k);
    levels.push_back({chordal * ratio, std::min(angle * std::sqrt(ratio), maxAngle)});
  }
  return levels;
}

// The edges' tolerances: below each level's by the same margin as the faces' triangles.
static std::vector<Level> edgeTolerances(std::vector<Level> schedule) {
  for (Level& level : schedule) level.chordal *= kDeviationMargin;
  return schedule;
}

TessellatorImpl::TessellatorImpl(const Model& m, double c, double a, std::vector<Level> s,
                                 std::shared_ptr<WorkerPool> p)
    : model(m),
      chordal(c),
      angle(a),
      schedule(std::move(s)),
      edges(m.impl(), edgeTolerances(schedule)),
      faces(m.faces().size()),
      poolHolder(p ? std::move(p) : std::make_shared<WorkerPool>()),
      pool(*poolHolder) {}

Tessellator::Tessellator(std::unique_ptr<TessellatorImpl> impl) : impl_(std::move(impl)) {}
Tessellator::~Tessellator() = default;

Tessellator::CreateResult Tessellator::create(const Model& model, const MeshParams& params,
                                              std::shared_ptr<WorkerPool> pool) {
  CreateResult result;
  double chordal = 0;
  result.error = resolveDeflection(params.chordal, model.bounds().diagonal(), chordal);
  if (!result.error.empty()) return result;
  if (!(params.angleDeg > 0) || params.angleDeg > 90) {
    result.error = "angle must be in (0, 90] degrees";
    return result;
  }
  const double angle = params.angleDeg * M_PI / 180.0;
  auto impl = std::make_unique<TessellatorImpl>(
      model, chordal, angle, planLevels(chordal, angle, model.bounds().diagonal(), params.progressive),
      std::move(pool));
  impl->maxPointsPerFaceLevel = params.maxPointsPerFaceLevel;
  result.tessellator.reset(new Tessellator(std::move(impl)));
  return result;
}

const Model& Tessellator::model() const { return impl_->model; }
double Tessellator::chordal() const { return impl_->chordal; }
double Tessellator::angleRad() const { return impl_->angle; }
const std::vector<Level>& Tessellator::schedule() const { return impl_->schedule; }
int Tessellator::edgeLevel() const { return impl_->edgeLevel.load(); }
int Tessellator::faceLevel(FaceId face) const { return impl_->faces[face].level; }
const FaceMesh& Tessellator::faceMesh(FaceId face) const { return impl_->faces[face].mesh; }
FaceReport Tessellator::report(FaceId face) const { return impl_->faces[face].report; }

bool Tessellator::discretiseEdges(int level, unsigned threads, const std::atomic<bool>* cancel) {
  if (level != impl_->edgeLevel.load() + 1 || level > lastLevel()) return level <= impl_->edgeLevel.load();
  // The edge table holds each level's edge tolerance (edgeTolerances(): the faces' margin applied).
  if (!impl_->surfacesReady && !impl_->prepareSurfaces(threads, cancel)) return false;
  if (!impl_->edges.discretise(level, impl_->pool, threads, cancel)) return false;
  impl_->edgeLevel.store(level);
  return true;
}

bool TessellatorImpl::prepareSurfaces(unsigned threads, const std::atomic<bool>* cancel) {
  std::atomic<bool> cancelled{false};
  parallelFor(pool, faces.size(), threads, [&](std::size_t f) {
    if (cancelled.load(std::memory_order_relaxed) || faces[f].eval) return;
    if (cancel && cancel->load(std::memory_order_relaxed)) {
      cancelled = true;
      return;
    }
    EdgeTable::FaceScale scale;
    try {
      const TopoDS_Face face = TopoDS::Face(model.impl().faceShapes[f].Oriented(TopAbs_FORWARD));
      auto eval = std::make_unique<SurfaceEval>(face, kDeviationMargin * schedule.back().chordal,
                                                schedule.back().angleRad);
      scale.uAxis = eval->uAxis(), scale.vAxis = eval->vAxis();
      scale.uMin = eval->uMin, scale.uMax = eval->uMax, scale.vMin = eval->vMin, scale.vMax = eval->vMax;
      const GeomAbs_SurfaceType type = eval->adaptor().GetType();
      scale.direct = eval->direct();
      // Tori and free-form faces bend otherwise beside an edge than along it, unless the free-form
      // surface is a plane, a sphere or a cylinder written as one (disguised_surface.h).
      const bool freeForm = type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface;
      const bool disguised =
          freeForm && (scale.direct ? isPlaneSphereOrCylinder(
                                          [&scale](double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) {
                                            scale.direct->d1(u, v, p, du, dv);
                                          },
                                          scale.uMin, scale.uMax, scale.vMin, scale.vMax)
                                    : isPlaneSphereOrCylinder(eval->adaptor(), scale.uMin, scale.uMax, scale.vMin,
                                                              scale.vMax));
      scale.bendsBeside = type != GeomAbs_Plane && type != GeomAbs_Cylinder && type != GeomAbs_Cone &&
                          type != GeomAbs_Sphere && !disguised;
      scale.curved = type != GeomAbs_Plane;
      scale.creases = eval->creaseLines();
      scale.valid = true;
      faces[f].eval = std::move(eval);
    } catch (const Standard_Failure&) {
      // No usable surface: the face's mesher fails the same way and the face falls back.
    }
    edges.setFaceScale(static_cast<FaceId>(f), std::move(scale));
  });
  if (cancelled) return false;
  edges.scalesSet();
  surfacesReady = true;
  return true;
}

FaceStatus Tessellator::advanceFace(FaceId face, int level, const std::atomic<bool>* cancel) {
  TessellatorImpl& t = *impl_;
  TessellatorImpl::FaceState& s = t.faces[face];
  level = std::min(level, lastLevel());
  if (level > t.edgeLevel.load()) return s.report.status;  // contract: edges first
  if (!s.isolation.empty()) return t.finishIsolation(face, level, cancel);  // its fallback was cancelled
  try {
    for (int k = s.level + 1; k <= level; ++k) {
      if (s.failed) {  // an isolated face keeps what it has on every further level
        s.mesh.levels.push_back(s.mesh.levels.back());
        s.mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(s.mesh.vertexCount()));
        s.level = k;
        continue;
      }
      if (s.injectFailure) throw std::runtime_error("failure injected for testing");
      if (!s.mesher) {
        FaceMesherSettings settings;
        settings.finalChordal = t.chordal;
        settings.finalAngle = t.angle;
        settings.coincident = 1e-10 * t.model.bounds().diagonal();
        settings.reversed = t.model.faces()[face].reversed;
        settings.sharing = &t.sharing;
        settings.trace = traceFace(face);
        settings.maxRefinePoints = t.maxPointsPerFaceLevel;
        s.mesher = std::make_unique<FaceMesher>(buildFaceTopology(t.model.impl(), face), settings, std::move(s.eval));
      }
      const FaceStatus status = s.mesher->advance(k, t.schedule[static_cast<std::size_t>(k)], t.edges, s.mesh,
                                                  s.report, cancel, k == lastLevel());
      if (status == FaceStatus::kCancelled) return status;
      s.level = k;
    }
  } catch (const std::exception& e) {
    return t.isolateFailedFace(face, level, e.what(), cancel);
  } catch (const Standard_Failure& e) {
    return t.isolateFailedFace(face, level, std::string("OpenCASCADE: ") + e.GetMessageString(), cancel);
  } catch (...) {
    return t.isolateFailedFace(face, level, "unknown exception", cancel);
  }
  if (s.level == lastLevel()) s.mesher.reset();
  return s.report.status;
}

FaceStatus TessellatorImpl::isolateFailedFace(FaceId face, int level, const std::string& what,
                                              const std::atomic<bool>* cancel) {
  FaceState& s = faces[face];
  s.mesher.reset();
  s.failed = true;
  s.isolation = "meshing failed (" + what + ")";
  return finishIsolation(face, level, cancel);
}

FaceStatus TessellatorImpl::finishIsolation(FaceId face, int level, const std::atomic<bool>* cancel) {
  FaceState& s = faces[face];
  level = std::max(level, s.level + 1);  // the level that failed, at least
  std::vector<std::uint32_t> indices;
  std::string failure;
  bool meshed = false;
  try {
    const TopoDS_Face forward = TopoDS::Face(model.impl().faceShapes[face].Oriented(TopAbs_FORWARD));
    if (!s.fallback) s.fallback = std::make_unique<CancellableFallback>();
    const FallbackResult result = s.fallback->run(forward, model.faces()[face].reversed, chordal, angle,
                                                  s.mesh, indices, failure, cancel);
    if (result == FallbackResult::kCancelled) return FaceStatus::kCancelled;  // s.isolation kept
    meshed = result == FallbackResult::kMeshed;
  } catch (const std::exception& e) {
    failure = e.what();
  } catch (const Standard_Failure& e) {
    failure = e.GetMessageString();
  } catch (...) {
    failure = "unknown exception";
  }
  s.fallback.reset();
  const std::string reason = std::move(s.isolation);
  s.isolation.clear();
  s.report.status = meshed ? FaceStatus::kFallback : FaceStatus::kEmpty;
  s.report.reason = meshed ? reason + "; meshed by the fallback" : reason + "; fallback failed too: " + failure;
  if (!meshed) indices.clear();
  // Levels before the failure keep their triangles; the failed level and the rest show `indices`.
  const std::size_t levels = static_cast<std::size_t>(level) + 1;
  s.mesh.levels.resize(std::min(s.mesh.levels.size(), static_cast<std::size_t>(s.level + 1)));
  s.mesh.levelVertexEnd.resize(s.mesh.levels.size());
  while (s.mesh.levels.size() < levels) {
    s.mesh.levels.push_back(indices);
    s.mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(s.mesh.vertexCount()));
  }
  s.level = level;
  return s.report.status;
}

void Tessellator::failFaceForTesting(FaceId face) { impl_->faces[face].injectFailure = true; }

void Tessellator::runWorkers(unsigned threads, const std::function<void(unsigned)>& work) {
  impl_->sharing.run(threads, work);
}

bool Tessellator::run(unsigned threads, const ProgressFn& progress, const std::atomic<bool>* cancel, int lastLevelWanted) {
  const int last = lastLevelWanted < 0 ? lastLevel() : std::min(lastLevelWanted, lastLevel());
  for (int k = edgeLevel() + 1; k <= last; ++k)
    if (!discretiseEdges(k, threads, cancel)) return false;
  const std::size_t total = impl_->faces.size();
  std::atomic<std::size_t> done{0};
  std::atomic<bool> cancelled{false};
  // Faces are independent once the edges are there: each runs through all its levels at once.
  std::atomic<std::size_t> next{0};
  runWorkers(threads, [&](unsigned worker) {
    for (std::size_t i = next++; i < total; i = next++) {
      if (advanceFace(static_cast<FaceId>(i), last, cancel) == FaceStatus::kCancelled) cancelled = true;
      const std::size_t d = ++done;
      if (worker == 0 && progress) progress(d, total);
    }
  });
  if (progress && !cancelled) progress(total, total);
  return !cancelled && !(cancel && cancel->load());
}

std::size_t Tessellator::triangleCount(int level) const {
  std::size_t n = 0;
  for (const auto& s : impl_->faces) {
    if (s.mesh.levels.empty()) continue;
    const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(level), s.mesh.levels.size() - 1);
    n += s.mesh.levels[k].size() / 3;
  }
  return n;
}

void Tessellator::edgePolyline(EdgeId edge, int level, std::vector<float>& xyz) const {
  xyz.clear();
  if (level < 0 || level > impl_->edgeLevel.load() || impl_->edges.degenerated(edge)) return;
  const EdgePoints& points = impl_->edges.points(edge, level);
  xyz.reserve(points.p.size() * 3);
  for (const gp_Pnt& p : points.p) {
    xyz.push_back(static_cast<float>(p.X()));
    xyz.push_back(static_cast<float>(p.Y()));
    xyz.push_back(static_cast<float>(p.Z()));
  }
}

}  // namespace cetview::brep
