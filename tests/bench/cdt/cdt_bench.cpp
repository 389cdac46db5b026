// CET triangulator against CGAL's Constrained_Delaunay_triangulation_2, side by side in one run:
// time ratio per case, time per point across sizes, bytes per triangle and per vertex.
//   cdt_bench [--max N] [--repeat R] [--case random|grid|trimmed|fan]
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cet/poly_triangulation.h"
#include "poly_generators.h"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;
using Clock = std::chrono::steady_clock;

double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

struct CetRun {
  double ms;
  std::size_t triangles;
  double bytesPerTriangle, bytesPerVertex;
};

CetRun runCet(const cet::PolyData& d) {
  const auto start = Clock::now();
  cet::PolyTriangulation result;  // what `cetview cdt` runs
  std::string error;
  if (!cet::triangulatePoly(d, result, error)) std::fprintf(stderr, "cdt_bench: %s\n", error.c_str());
  const auto end = Clock::now();
  const cet::Triangulator& tri = result.tri;
  const cet::CetMesh& m = tri.mesh();
  return CetRun{ms(start, end), tri.insideTriangleCount(),
                static_cast<double>(m.bytesTriangles()) / static_cast<double>(m.triangleCount()),
                static_cast<double>(m.bytesVertices()) / static_cast<double>(m.vertexCount())};
}

double runCgal(const cet::PolyData& d, std::size_t& faces) {
  std::vector<K::Point_2> pts;
  pts.reserve(d.points.size());
  for (auto p : d.points) pts.emplace_back(p.x, p.y);
  std::vector<std::pair<std::size_t, std::size_t>> segs;
  segs.reserve(d.segments.size());
  for (auto s : d.segments) segs.emplace_back(s[0], s[1]);
  const auto start = Clock::now();
  Cdt cdt;
  if (segs.empty()) {
    cdt.insert(pts.begin(), pts.end());  // spatially sorted insertion
  } else {
    cdt.insert_constraints(pts.begin(), pts.end(), segs.begin(), segs.end());
  }
  const auto end = Clock::now();
  faces = cdt.number_of_faces();
  return ms(start, end);
}

// n points on a unit circle and its centre: the Delaunay triangulation is the fan from the centre.
// One constraint, a chord a quarter of the circle long, crosses n / 4 of its spokes: each crossed
// edge is looked up while the spokes are flipped away (a fuzzed face's boundary crossed 18486).
cet::PolyData fanCrossedByAChord(std::size_t n) {
  cet::PolyData d;
  d.points.push_back({0.0, 0.0});
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    d.points.push_back({std::cos(a), std::sin(a)});
  }
  d.segments.push_back({static_cast<std::uint32_t>(1 + n / 4 + 1), 1u});
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t maxPoints = 4000000;
  int repeat = 3;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--max")) maxPoints = std::strtoull(argv[i + 1], nullptr, 10);
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--case")) only = argv[i + 1];
  }
  std::printf("%-9s %9s %8s %10s %10s %8s %10s %10s %9s %9s\n", "case", "points", "segments", "cet ms", "cgal ms",
              "speedup", "cet ns/pt", "cgal ns/pt", "B/tri", "B/vertex");
  for (const char* kind : {"random", "grid", "trimmed", "fan"}) {
    if (!only.empty() && only != kind) continue;
    for (std::size_t n : {10000u, 100000u, 1000000u, 4000000u}) {
      if (n > maxPoints) continue;
      cet::PolyData d;
      if (!std::strcmp(kind, "random")) {
        d = cet::generators::randomPoints(n, 1);
      } else if (!std::strcmp(kind, "grid")) {
        d = cet::generators::grid(static_cast<std::size_t>(std::sqrt(static_cast<double>(n))));
      } else if (!std::strcmp(kind, "fan")) {
        if (n > 100000) continue;
        d = fanCrossedByAChord(n);
      } else {
        if (n < 100000) continue;  // ~80k constraint segments need at least that many points
        // 8000-vertex outer loop and 3600 holes of 20 segments: 80k segments, rest interior points.
        d = cet::generators::polygonWithHoles(8000, 3600, 20, n - 8000 - 3600 * 20, 4);
      }
      const int reps = n >= 1000000 ? 1 : repeat;
      CetRun best{1e300, 0, 0, 0};
      double cgalBest = 1e300;
      std::size_t cgalFaces = 0;
      for (int r = 0; r < reps; ++r) {
        const CetRun c = runCet(d);
        if (c.ms < best.ms) best = c;
        cgalBest = std::min(cgalBest, runCgal(d, cgalFaces));
      }
      const double pts = static_cast<double>(d.points.size());
      std::printf("%-9s %9zu %8zu %10.1f %10.1f %7.2fx %10.1f %10.1f %9.1f %9.1f\n", kind, d.points.size(),
                  d.segments.size(), best.ms, cgalBest, cgalBest / best.ms, best.ms * 1e6 / pts, cgalBest * 1e6 / pts,
                  best.bytesPerTriangle, best.bytesPerVertex);
      std::fflush(stdout);
    }
  }
  return 0;
}
