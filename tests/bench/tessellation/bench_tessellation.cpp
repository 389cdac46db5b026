// bench_tessellation [--deflection D] [--angle A] [--threads N] [MODEL...]
// With no MODEL: the demo part and every occt-misc sample with faces. One JSON line per model
// (brep::benchJson), then a summary: geometric means of cetview/BRepMesh time and triangle ratios,
// and the worst measured deviation of each, in multiples of the deflection.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "brep/bench.h"

int main(int argc, char** argv) {
  using namespace cetview::brep;
  BenchOptions options;
  std::vector<std::string> models;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    std::string error;
    if (arg == "--deflection" && i + 1 < argc) {
      error = parseDeflection(argv[++i], options.params.chordal);
    } else if (arg == "--angle" && i + 1 < argc) {
      error = parseAngle(argv[++i], options.params.angleDeg);
    } else if (arg == "--threads" && i + 1 < argc) {
      options.threads = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else {
      models.push_back(arg);
    }
    if (!error.empty()) {
      std::fprintf(stderr, "bench_tessellation: %s\n", error.c_str());
      return 2;
    }
  }
  if (models.empty()) {
    models.push_back("demo");
    std::error_code ec;
    for (const char* dir : {"occ", "step", "iges"})
      for (const auto& e : std::filesystem::directory_iterator(std::string(CETVIEW_OCCT_DATA) + "/" + dir, ec)) {
        const std::string ext = e.path().extension().string();
        if (ext == ".brep" || ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs") models.push_back(e.path().string());
      }
  }
  double logTime = 0, logTris = 0, worstCet = 0, worstBm = 0;
  int n = 0;
  for (const std::string& m : models) {
    const BenchResult r = benchModel(m, options);
    std::printf("%s\n", benchJson(r).c_str());
    std::fflush(stdout);
    if (!r.error.empty() || r.brepmesh_ms <= 0 || r.brepmesh_triangles == 0) continue;
    logTime += std::log(r.cetview_ms / r.brepmesh_ms);
    logTris += std::log(static_cast<double>(r.cetview_triangles) / static_cast<double>(r.brepmesh_triangles));
    worstCet = std::max(worstCet, r.cetview_max_dev / r.deflection);
    worstBm = std::max(worstBm, r.brepmesh_max_dev / r.deflection);
    ++n;
  }
  if (n > 0) {
    std::printf("summary: %d models; geometric mean cetview/BRepMesh time %.2f, triangles %.2f; worst deviation "
                "cetview %.2fx, BRepMesh %.2fx the deflection\n",
                n, std::exp(logTime / n), std::exp(logTris / n), worstCet, worstBm);
  }
  return 0;
}
