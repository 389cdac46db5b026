// `cetview cdt IN.poly -o OUT [--json]`: the CET triangulator alone, on Triangle's formats.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cet/poly_format.h"
#include "cet/poly_triangulation.h"
#include "commands.h"

namespace cetview {
namespace {

struct CdtOptions {
  std::string input;
  std::string output;
  bool json = false;
};

int runCdt(const CdtOptions& options) {
  cet::PolyData data;
  std::string error;
  if (!cet::readPoly(options.input, data, error)) {
    std::fprintf(stderr, "cetview cdt: %s\n", error.c_str());
    return 2;
  }
  cet::PolyTriangulation result;
  const auto start = std::chrono::steady_clock::now();
  const bool ok = cet::triangulatePoly(data, result, error);
  std::vector<cet::VertexId> triangles;
  if (ok) result.collectInputTriangles(triangles);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!ok) {
    std::fprintf(stderr, "cetview cdt: %s: %s\n", options.input.c_str(), error.c_str());
    return 2;
  }
  if (!cet::writeNodeEle(options.output, data, triangles, error)) {
    std::fprintf(stderr, "cetview cdt: %s\n", error.c_str());
    return 1;
  }
  const std::size_t count = triangles.size() / 3;
  if (options.json) {
    std::printf(
        "{\"input\":\"%s\",\"points\":%zu,\"segments\":%zu,\"holes\":%zu,\"merged\":%zu,\"triangles\":%zu,\"ms\":%.3f,"
        "\"node\":\"%s.node\",\"ele\":\"%s.ele\"}\n",
        options.input.c_str(), data.points.size(), data.segments.size(), data.holes.size(), result.tri.mergedCount(), count,
        ms, options.output.c_str(), options.output.c_str());
  } else {
    std::printf("cdt: %zu points, %zu segments, %zu holes -> %zu triangles in %.3f ms (%s.node, %s.ele)\n",
                data.points.size(), data.segments.size(), data.holes.size(), count, ms, options.output.c_str(),
                options.output.c_str());
  }
  return 0;
}

}  // namespace

Command cdtCommand() {
  auto options = std::make_shared<CdtOptions>();
  Command cmd{"cdt", "Constrained Delaunay triangulation of a Triangle .poly file"};
  cmd.required("input", &options->input, "Input .poly file")
      .required("-o,--output", &options->output, "Output base name: writes OUT.node and OUT.ele")
      .option("--json", &options->json, "Print one JSON object instead of the summary line");
  cmd.run = [options] { return runCdt(*options); };
  return cmd;
}

}  // namespace cetview
