// `cetview export MODEL -o OUT.{brep,glb,gltf,obj,stl} [--deflection D] [--angle A] [--threads N]`:
// the final tessellation of a model, written through OpenCASCADE's writers (tessellation/brep).

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "brep/export.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "commands.h"
#include "face_problems.h"
#include "progress_bar.h"
#include "terminal_load.h"

namespace cetview {
namespace {

struct ExportOptions {
  std::string model;
  std::string output;
  std::string deflection = "0.1%";
  std::string angle = "20";
  unsigned threads = 0;
};

int runExport(const ExportOptions& o) {
  using namespace brep;
  MeshParams params;
  std::string error = parseDeflection(o.deflection, params.chordal);
  if (error.empty()) error = parseAngle(o.angle, params.angleDeg);
  if (error.empty() && !exportFormatSupported(o.output))
    error = o.output + ": unknown output format (use .brep, .glb, .gltf, .obj or .stl)";
  if (!error.empty()) {
    std::fprintf(stderr, "cetview export: %s\n", error.c_str());
    return 2;
  }
  params.progressive = false;  // only the final level is written
  const auto start = std::chrono::steady_clock::now();
  LoadResult loaded = loadWithProgressBar(o.model, "export");
  if (!loaded) {
    std::fprintf(stderr, "cetview export: %s\n", loaded.error.c_str());
    return 2;
  }
  auto created = Tessellator::create(*loaded.model, params);
  if (!created.tessellator) {
    std::fprintf(stderr, "cetview export: %s: %s\n", o.model.c_str(), created.error.c_str());
    return 2;
  }
  Tessellator& t = *created.tessellator;
  const unsigned threads = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  {
    ProgressBar bar("export " + o.model);  // on a terminal only
    t.run(threads, [&](std::size_t done, std::size_t total) {
      bar.update(done, total, std::to_string(done) + "/" + std::to_string(total) + " faces");
    });
  }
  printFaceProblems(stderr, "cetview export", *loaded.model, collectFaceProblems(t));
  error = exportModel(t, o.output);
  if (!error.empty()) {
    std::fprintf(stderr, "cetview export: %s\n", error.c_str());
    return 1;
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("export: %s: %zu faces, %zu triangles, deflection %g, angle %g -> %s in %.0f ms\n", o.model.c_str(),
              loaded.model->faces().size(), t.triangleCount(t.lastLevel()), t.chordal(), params.angleDeg,
              o.output.c_str(), ms);
  return 0;
}

}  // namespace

Command exportCommand() {
  auto options = std::make_shared<ExportOptions>();
  Command cmd{"export", "Tessellate a model and write the final mesh"};
  cmd.required("model", &options->model, "STEP, IGES or .brep file, or 'demo'")
      .required("-o,--output", &options->output, "Output file: .brep, .glb, .gltf, .obj or .stl")
      .option("--deflection", &options->deflection, "Chordal deflection: absolute (0.05) or relative (0.1%)")
      .option("--angle", &options->angle, "Angular deflection in degrees")
      .option("--threads", &options->threads, "Worker threads (0: all cores)");
  cmd.run = [options] { return runExport(*options); };
  return cmd;
}

}  // namespace cetview
