// Fuzz target for the .poly reader and the triangulator with random constraints.
// Built two ways: as a libFuzzer target (clang, -DCETVIEW_LIBFUZZER=ON) and as a seeded driver
// (poly_fuzz_driver.cpp) that CI runs for a short, reproducible while. Any broken invariant aborts.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cet/poly_format.h"
#include "cet/poly_triangulation.h"
#include "cet/topology_check.h"

namespace {

void require(const std::string& problem, const char* where) {
  if (problem.empty()) return;
  std::fprintf(stderr, "fuzz: %s: %s\n", where, problem.c_str());
  std::abort();
}

void checkTriangulation(const cet::Triangulator& tri) {
  require(cet::checkTopology(tri.mesh()), "topology");
  require(cet::checkDelaunay(tri.mesh()), "delaunay");
}

// Mode 0: the bytes are .poly text.
void fuzzText(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  cet::PolyData poly;
  std::string error;
  if (!cet::parsePoly(text, "fuzz.poly", poly, error)) {
    if (error.empty() || error.find('\n') != std::string::npos) require("bad error message: " + error, "parse");
    return;
  }
  if (poly.points.size() > 5000) return;
  cet::PolyTriangulation result;
  cet::triangulatePoly(poly, result, error);
  checkTriangulation(result.tri);
}

// Mode 1: the bytes are small-integer points (many collinear and co-circular) and segments.
void fuzzStructured(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return;
  const std::size_t pointCount = 3 + data[0] % 60;
  std::size_t k = 1;
  std::vector<cet::Point2> points;
  const double scale = (data[k] & 1) ? 1e-9 : (data[k] & 2) ? 1e9 : 1.0;
  ++k;
  for (std::size_t i = 0; i < pointCount && k + 1 < size; ++i, k += 2) {
    points.push_back({(data[k] % 16) * scale, (data[k + 1] % 16) * scale});
  }
  if (points.size() < 3) return;
  cet::Triangulator tri;
  tri.addVertices(points.data(), points.size());
  if (!tri.insertPending()) return;
  const auto n = static_cast<std::uint32_t>(points.size());
  for (; k + 1 < size; k += 2) {
    const cet::Status s = tri.insertSegment(data[k] % n, data[k + 1] % n);
    if (!s.ok() && s.code != cet::Status::Code::kCrossingSegments) require(s.message, "segment");
    require(cet::checkTopology(tri.mesh()), "topology after segment");
  }
  tri.markDomain((data[0] & 0x80) ? cet::DomainRule::kLoopOrientation : cet::DomainRule::kHullAndHolePoints);
  checkTriangulation(tri);
  // Refinement batch on top of the constrained result.
  std::vector<cet::Point2> extra;
  for (std::size_t i = 1; i + 1 < size && extra.size() < 64; i += 3) {
    extra.push_back({(data[i] % 31) * scale * 0.5, (data[i + 1] % 31) * scale * 0.5});
  }
  std::vector<cet::VertexId> ids(extra.size());
  tri.insertPoints(extra.data(), extra.size(), ids.data());
  checkTriangulation(tri);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  if (data[0] % 2 == 0) {
    fuzzText(data + 1, size - 1);
  } else {
    fuzzStructured(data + 1, size - 1);
  }
  return 0;
}
