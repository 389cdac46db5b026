// cetview against BRepMesh_IncrementalMesh on one model: same deflection, same angle, same process,
// same measuring code.
#include "brep/bench.h"

#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <thread>

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>

#include "brep/measure.h"
#include "brep/mesh_check.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "measure_impl.h"
#include "model_impl.h"
#include "parallel.h"

namespace cetview::brep {
namespace {

constexpr int kTimedRounds = 5;
constexpr double kRoundBudgetMs = 1500;

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Samples the heap in use every millisecond while alive: the peak growth over the start.
class HeapPeak {
 public:
  HeapPeak() : base_(inUse()), peak_(base_) {
    thread_ = std::thread([this] {
      while (!stop_.load()) {
        peak_ = std::max(peak_.load(), inUse());
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    });
  }
  double stopMb() {
    stop_ = true;
    thread_.join();
    peak_ = std::max(peak_.load(), inUse());
    return static_cast<double>(peak_.load() - std::min(base_, peak_.load())) / (1024.0 * 1024.0);
  }

 private:
  static std::size_t inUse() {
    const struct mallinfo2 mi = mallinfo2();
    return mi.uordblks + mi.hblkhd;
  }
  std::size_t base_;
  std::atomic<std::size_t> peak_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

void cleanMeshes(const ModelImpl& m) {
  for (const TopoDS_Shape& s : m.partShapes) BRepTools::Clean(s);
}

double runBRepMesh(const ModelImpl& m, double deflection, double angle, bool parallel) {
  cleanMeshes(m);
  IMeshTools_Parameters p;
  p.Deflection = deflection;
  p.Angle = angle;
  p.Relative = Standard_False;
  p.InParallel = parallel;
  const auto t0 = std::chrono::steady_clock::now();
  for (const TopoDS_Shape& s : m.partShapes) BRepMesh_IncrementalMesh mesher(s, p);
  return msSince(t0);
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    o += c;
  }
  return o;
}

}  // namespace

BenchResult benchModel(const std::string& path, const BenchOptions& options) {
  BenchResult r;
  r.model = path;
  r.threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  r.angleDeg = options.params.angleDeg;
  auto t0 = std::chrono::steady_clock::now();
  LoadResult loaded = loadModel(path);
  r.load_ms = msSince(t0);
  if (!loaded) {
    r.error = loaded.error;
    return r;
  }
  const Model& model = *loaded.model;
  const ModelImpl& m = model.impl();
  r.faces = model.faces().size();
  try {
    MeshParams direct = options.params;
    direct.progressive = false;
    {
      auto created = Tessellator::create(model, direct);
      if (!created.tessellator) {
        r.error = created.error;
        return r;
      }
      r.deflection = created.tessellator->chordal();
    }
    const double angleRad = options.params.angleDeg * M_PI / 180.0;
    r.brepmesh_ms_threads = runBRepMesh(m, r.deflection, angleRad, true);

    // The two single-thread final meshes the goal compares, cetview's final level alone ("direct")
    // and BRepMesh, alternate round by round so both see the same machine and both run warm after
    // the first round; each keeps its best round. Rounds stop after kTimedRounds or once the rounds
    // so far took kRoundBudgetMs (terrain: one round, BRepMesh alone takes 20-45 s).
    r.cetview_direct_ms = r.brepmesh_ms = INFINITY;
    const auto rounds0 = std::chrono::steady_clock::now();
    for (int round = 0; round < kTimedRounds && (round == 0 || msSince(rounds0) < kRoundBudgetMs); ++round) {
      {
        auto tess = Tessellator::create(model, direct).tessellator;
        t0 = std::chrono::steady_clock::now();
        tess->run(1);
        r.cetview_direct_ms = std::min(r.cetview_direct_ms, msSince(t0));
      }
      std::optional<HeapPeak> bheap;
      if (round == 0) bheap.emplace();
      r.brepmesh_ms = std::min(r.brepmesh_ms, runBRepMesh(m, r.deflection, angleRad, false));
      if (bheap) r.brepmesh_peak_mb = bheap->stopMb();
    }

    // The progressive runs, on N threads and on one, alternate the same way. (One run each, the
    // threaded one first, had the threaded run pay the process's first progressive run: bearing.iges
    // read 61.5 ms on two threads against 53.2 on one, where best of rounds gives 24 and 46.)
    MeshParams progressive = options.params;
    progressive.progressive = true;
    r.cetview_ms_threads = r.cetview_ms = INFINITY;
    std::unique_ptr<Tessellator> tess;
    // The threaded rounds share one pool, started before them, as BRepMesh's rounds share
    // OpenCASCADE's default thread pool (and the viewer keeps its threads across models).
    auto pool = std::make_shared<WorkerPool>();
    pool->start(r.threads);
    const auto rounds1 = std::chrono::steady_clock::now();
    for (int round = 0; round < kTimedRounds && (round == 0 || msSince(rounds1) < kRoundBudgetMs); ++round) {
      {
        auto threaded = Tessellator::create(model, progressive, pool).tessellator;
        t0 = std::chrono::steady_clock::now();
        threaded->run(r.threads);
        r.cetview_ms_threads = std::min(r.cetview_ms_threads, msSince(t0));
      }
      tess.reset();
      std::optional<HeapPeak> heap;
      if (round == 0) heap.emplace();
      tess = Tessellator::create(model, progressive).tessellator;
      t0 = std::chrono::steady_clock::now();
      tess->run(1);
      r.cetview_ms = std::min(r.cetview_ms, msSince(t0));
      if (heap) r.cetview_peak_mb = heap->stopMb();
    }
    r.levels = tess->schedule().size();
    r.cetview_triangles = tess->triangleCount(tess->lastLevel());
    for (FaceId f = 0; f < r.faces; ++f) {
      const FaceStatus s = tess->report(f).status;
      r.repaired_faces += s == FaceStatus::kRepaired;
      r.fallback_faces += s == FaceStatus::kFallback;
      r.empty_faces += s == FaceStatus::kEmpty;
    }

    // The last round's BRepMesh meshes are still on the faces: they are measured below.
    for (const TopoDS_Face& face : m.faceShapes) {
      TopLoc_Location loc;
      const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
      if (!tri.IsNull()) r.brepmesh_triangles += static_cast<std::size_t>(tri->NbTriangles());
    }
    if (options.measure) {
      const double angleLimit = tess->angleRad() * (1 + 1e-6);
      const double weld = 1e-7 * model.bounds().diagonal();
      const std::vector<FaceQuality> q = measureFaces(*tess, -1, r.threads);
      for (const FaceQuality& fq : q) {
        r.cetview_max_dev = std::max(r.cetview_max_dev, fq.maxDeviation);
        r.cetview_faces_over += fq.maxDeviation > r.deflection;
        r.cetview_max_angle_deg = std::max(r.cetview_max_angle_deg, fq.maxCornerAngle * 180 / M_PI);
        r.cetview_faces_over_angle += fq.maxCornerAngle > angleLimit;
        r.cetview_degenerate += fq.degenerate;
        r.cetview_flipped += fq.flipped;
        r.cetview_flipped_across_folds += fq.flippedAcrossFolds;
      }
      for (int k = 0; k < tess->lastLevel(); ++k) {
        r.cetview_flipped_coarse += countFlipped(*tess, k, &r.cetview_flipped_coarse_across_folds);
      }
      for (PartId p = 0; p < model.parts().size(); ++p) {
        if (model.parts()[p].closed) r.cetview_cracks += countOpenEdges(partSoup(*tess, p), weld);
      }
      // BRepMesh's triangulations, as soups in part coordinates with their UV nodes.
      std::vector<double> devs(m.faceShapes.size(), 0.0), angles(m.faceShapes.size(), 0.0);
      std::vector<std::size_t> degenerate(m.faceShapes.size(), 0);
      std::vector<TriangleSoup> faceSoups(m.faceShapes.size());
      parallelFor(m.faceShapes.size(), r.threads, [&](std::size_t f, unsigned) {
        const TopoDS_Face face = TopoDS::Face(m.faceShapes[f].Oriented(TopAbs_FORWARD));
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
        if (tri.IsNull()) return;
        TriangleSoup& soup = faceSoups[f];
        std::vector<double> uv;
        const gp_Trsf trsf = loc.Transformation();
        for (int i = 1; i <= tri->NbNodes(); ++i) {
          const gp_Pnt p = tri->Node(i).Transformed(trsf);
          soup.positions.insert(soup.positions.end(), {p.X(), p.Y(), p.Z()});
          const gp_Pnt2d t = tri->HasUVNodes() ? tri->UVNode(i) : gp_Pnt2d(0, 0);
          uv.insert(uv.end(), {t.X(), t.Y()});
        }
        for (int i = 1; i <= tri->NbTriangles(); ++i) {
          int a, b, c;
          tri->Triangle(i).Get(a, b, c);
          soup.indices.insert(soup.indices.end(), {static_cast<std::uint32_t>(a - 1), static_cast<std::uint32_t>(b - 1),
                                                   static_cast<std::uint32_t>(c - 1)});
        }
        degenerate[f] = countDegenerate(soup);
        try {
          SurfaceEval eval(face);
          eval.detectFlat(r.deflection);  // as cetview's mesh is measured (measureFaces)
          devs[f] = tri->HasUVNodes()
                        ? measureDeviation(eval, soup.positions.data(), uv.data(), soup.indices.data(),
                                           soup.triangleCount(), r.deflection)
                        : INFINITY;
          angles[f] = tri->HasUVNodes() ? measureCornerAngle(eval, soup.positions.data(), uv.data(), uv.size() / 2,
                                                              soup.indices.data(), soup.triangleCount(), 0.1 * r.deflection)
                                        : INFINITY;
        } catch (const Standard_Failure&) {
          devs[f] = INFINITY;
          angles[f] = INFINITY;
        }
      });
      for (std::size_t f = 0; f < devs.size(); ++f) {
        r.brepmesh_max_dev = std::max(r.brepmesh_max_dev, devs[f]);
        r.brepmesh_faces_over += devs[f] > r.deflection;
        r.brepmesh_max_angle_deg = std::max(r.brepmesh_max_angle_deg, angles[f] * 180 / M_PI);
        r.brepmesh_faces_over_angle += angles[f] > angleLimit;
        r.brepmesh_degenerate += degenerate[f];
        if (devs[f] <= r.deflection && angles[f] <= angleLimit) {
          r.brepmesh_triangles_kept += faceSoups[f].triangleCount();
          r.cetview_triangles_kept += q[f].triangles;
        }
      }
      for (PartId p = 0; p < model.parts().size(); ++p) {
        if (!model.parts()[p].closed) continue;
        TriangleSoup part;
        const PartInfo& info = model.parts()[p];
        for (FaceId f = info.firstFace; f < info.firstFace + info.faceCount; ++f) {
          const auto base = static_cast<std::uint32_t>(part.positions.size() / 3);
          part.positions.insert(part.positions.end(), faceSoups[f].positions.begin(), faceSoups[f].positions.end());
          for (std::uint32_t i : faceSoups[f].indices) part.indices.push_back(base + i);
        }
        r.brepmesh_cracks += countOpenEdges(part, weld);
      }
    }
    cleanMeshes(m);
  } catch (const Standard_Failure& e) {
    r.error = std::string("OpenCASCADE failure: ") + e.GetMessageString();
  }
  return r;
}

std::string benchJson(const BenchResult& r) {
  std::ostringstream o;
  o.precision(6);
  o << "{\"model\":\"" << escape(r.model) << "\"";
  if (!r.error.empty()) o << ",\"error\":\"" << escape(r.error) << "\"";
  auto num = [&](const char* k, double v) {
    o << ",\"" << k << "\":";
    if (std::isfinite(v)) o << v; else o << "null";
  };
  num("faces", static_cast<double>(r.faces));
  num("deflection", r.deflection);
  num("angle", r.angleDeg);
  num("threads", r.threads);
  num("levels", static_cast<double>(r.levels));
  num("load_ms", r.load_ms);
  num("cetview_ms", r.cetview_ms);
  num("cetview_ms_threads", r.cetview_ms_threads);
  num("cetview_direct_ms", r.cetview_direct_ms);
  num("brepmesh_ms", r.brepmesh_ms);
  num("brepmesh_ms_threads", r.brepmesh_ms_threads);
  num("cetview_triangles", static_cast<double>(r.cetview_triangles));
  num("brepmesh_triangles", static_cast<double>(r.brepmesh_triangles));
  num("cetview_max_dev", r.cetview_max_dev);
  num("brepmesh_max_dev", r.brepmesh_max_dev);
  num("cetview_max_angle_deg", r.cetview_max_angle_deg);
  num("brepmesh_max_angle_deg", r.brepmesh_max_angle_deg);
  num("cetview_faces_over_angle", static_cast<double>(r.cetview_faces_over_angle));
  num("brepmesh_faces_over_angle", static_cast<double>(r.brepmesh_faces_over_angle));
  num("cetview_faces_over", static_cast<double>(r.cetview_faces_over));
  num("brepmesh_faces_over", static_cast<double>(r.brepmesh_faces_over));
  num("cetview_cracks", static_cast<double>(r.cetview_cracks));
  num("brepmesh_cracks", static_cast<double>(r.brepmesh_cracks));
  num("cetview_degenerate", static_cast<double>(r.cetview_degenerate));
  num("cetview_flipped", static_cast<double>(r.cetview_flipped));
  num("cetview_flipped_coarse", static_cast<double>(r.cetview_flipped_coarse));
  num("cetview_flipped_across_folds", static_cast<double>(r.cetview_flipped_across_folds));
  num("cetview_flipped_coarse_across_folds", static_cast<double>(r.cetview_flipped_coarse_across_folds));
  num("cetview_triangles_kept", static_cast<double>(r.cetview_triangles_kept));
  num("brepmesh_triangles_kept", static_cast<double>(r.brepmesh_triangles_kept));
  num("brepmesh_degenerate", static_cast<double>(r.brepmesh_degenerate));
  num("cetview_peak_mb", r.cetview_peak_mb);
  num("brepmesh_peak_mb", r.brepmesh_peak_mb);
  num("repaired_faces", static_cast<double>(r.repaired_faces));
  num("fallback_faces", static_cast<double>(r.fallback_faces));
  num("empty_faces", static_cast<double>(r.empty_faces));
  o << "}";
  return o.str();
}

}  // namespace cetview::brep
