// `cetview bench MODEL... [--json]`: cetview against BRepMesh_IncrementalMesh, side by side in one
// process at the same deflection and angle (tessellation/brep/include/brep/bench.h).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "brep/bench.h"
#include "commands.h"

namespace cetview {
namespace {

struct BenchOptions {
  std::vector<std::string> models;
  std::string deflection = "0.1%";
  std::string angle = "20";
  unsigned threads = 0;
  bool json = false;
  bool noMeasure = false;
};

int runBench(const BenchOptions& o) {
  using namespace brep;
  brep::BenchOptions options;
  std::string error = parseDeflection(o.deflection, options.params.chordal);
  if (error.empty()) error = parseAngle(o.angle, options.params.angleDeg);
  if (!error.empty()) {
    std::fprintf(stderr, "cetview bench: %s\n", error.c_str());
    return 2;
  }
  options.threads = o.threads;
  options.measure = !o.noMeasure;
  if (!o.json) {
    // fin_ms: cetview's final level alone, one thread, against bm_ms (BRepMesh, one thread) in fin/bm;
    // cet_ms: every level coarse to fine, one thread; cet_thr: the same on --threads.
    std::printf("%-34s %6s %9s %9s %9s %9s %7s %9s %9s %9s %8s %8s %7s %7s %6s %6s\n", "model", "faces", "load_ms",
                "fin_ms", "bm_ms", "fin/bm", "cet_ms", "cet_thr", "cet_tris", "bm_tris", "cet_dev", "bm_dev", "cet_ang",
                "bm_ang", "cet_cr", "bm_cr");
  }
  int status = 0;
  for (const std::string& model : o.models) {
    const BenchResult r = benchModel(model, options);
    if (!r.error.empty()) {
      std::fprintf(stderr, "cetview bench: %s\n", r.error.c_str());
      status = 2;
      if (o.json) std::printf("%s\n", benchJson(r).c_str());
      continue;
    }
    if (o.json) {
      std::printf("%s\n", benchJson(r).c_str());
    } else {
      const std::string name = model.size() > 34 ? "..." + model.substr(model.size() - 31) : model;
      // Deviations as multiples of the deflection: above 1.00 breaks the promise.
      // Angles in degrees: the largest between the exact normals at a triangle edge's ends.
      std::printf("%-34s %6zu %9.1f %9.1f %9.1f %9.2f %7.1f %9.1f %9zu %9zu %8.2f %8.2f %7.1f %7.1f %6zu %6zu\n",
                  name.c_str(), r.faces, r.load_ms, r.cetview_direct_ms, r.brepmesh_ms,
                  r.brepmesh_ms > 0 ? r.cetview_direct_ms / r.brepmesh_ms : 0.0, r.cetview_ms, r.cetview_ms_threads,
                  r.cetview_triangles, r.brepmesh_triangles, r.cetview_max_dev / r.deflection,
                  r.brepmesh_max_dev / r.deflection, r.cetview_max_angle_deg, r.brepmesh_max_angle_deg, r.cetview_cracks,
                  r.brepmesh_cracks);
    }
    std::fflush(stdout);
  }
  return status;
}

}  // namespace

Command benchCommand() {
  auto options = std::make_shared<BenchOptions>();
  Command cmd{"bench", "cetview against BRepMesh_IncrementalMesh, side by side"};
  cmd.required("models", &options->models, "STEP, IGES or .brep files, or 'demo'")
      .option("--deflection", &options->deflection, "Chordal deflection: absolute (0.05) or relative (0.1%)")
      .option("--angle", &options->angle, "Angular deflection in degrees")
      .option("--threads", &options->threads, "Threads of the parallel runs (0: all cores)")
      .option("--json", &options->json, "One JSON object per model per line")
      .option("--no-measure", &options->noMeasure, "Skip deviation, crack and degeneracy measurements");
  cmd.run = [options] { return runBench(*options); };
  return cmd;
}

}  // namespace cetview
