// Property tests against CGAL's Constrained_Delaunay_triangulation_2: the same triangle count and
// covered area, every unconstrained edge locally Delaunay by the exact test, every segment present,
// on random, grid, circle, clustered, long-thin and polygon-with-holes inputs from 3 to 1M points.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <list>
#include <random>

#include "cet/poly_format.h"
#include "cet/poly_triangulation.h"
#include "poly_generators.h"
#include "triangulation_checks.h"

namespace cet {
namespace {

using namespace cet::generators;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;
};
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

struct Reference {
  std::size_t triangles = 0;
  double area = 0;
};

// CGAL's answer: with segments, faces at odd nesting depth from the infinite face (the standard
// polygon-with-holes marking, equal to Triangle's -p for properly nested loops); without, all.
Reference cgalReference(const PolyData& d) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(d.points.size());
  {
    std::vector<std::pair<K::Point_2, std::size_t>> pts;
    pts.reserve(d.points.size());
    for (std::size_t i = 0; i < d.points.size(); ++i) pts.emplace_back(K::Point_2(d.points[i].x, d.points[i].y), i);
    if (d.segments.empty()) {
      std::vector<K::Point_2> plain;
      plain.reserve(pts.size());
      for (auto& p : pts) plain.push_back(p.first);
      cdt.insert(plain.begin(), plain.end());
    } else {
      for (auto& p : pts) handles.push_back(cdt.insert(p.first));
    }
  }
  for (auto s : d.segments) cdt.insert_constraint(handles[s[0]], handles[s[1]]);
  Reference r;
  const auto area = [](Cdt::Face_handle f) {
    const auto& a = f->vertex(0)->point();
    const auto& b = f->vertex(1)->point();
    const auto& c = f->vertex(2)->point();
    return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
  };
  if (d.segments.empty()) {
    for (auto f : cdt.finite_face_handles()) {
      ++r.triangles;
      r.area += area(f);
    }
    return r;
  }
  // Flood by nesting level, crossing constrained edges increments it.
  std::list<Cdt::Edge> border;
  const auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info().nesting != -1) return;
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      Cdt::Face_handle f = queue.front();
      queue.pop_front();
      if (f->info().nesting != -1) continue;
      f->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          border.push_back(Cdt::Edge(f, i));
        } else {
          queue.push_back(n);
        }
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    Cdt::Edge e = border.front();
    border.pop_front();
    Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1);
  }
  for (auto f : cdt.finite_face_handles()) {
    if (f->info().nesting % 2 == 1) {
      ++r.triangles;
      r.area += area(f);
    }
  }
  return r;
}

void compareWithCgal(const PolyData& d, const char* what) {
  SCOPED_TRACE(what);
  PolyTriangulation result;
  std::string error;
  ASSERT_TRUE(triangulatePoly(d, result, error)) << error;
  const Triangulator& tri = result.tri;
  const Reference ref = cgalReference(d);
  EXPECT_EQ(tri.insideTriangleCount(), ref.triangles);
  const double area = testing::coveredArea(tri);
  EXPECT_NEAR(area, ref.area, 1e-9 * std::max(1.0, std::fabs(ref.area)));
  testing::expectValidCdt(tri);
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (auto s : d.segments) segments.push_back({result.internalOf[s[0]], result.internalOf[s[1]]});
  testing::expectSegmentsPresent(tri, segments);
}

TEST(CgalCompare, Random) {
  for (std::size_t n : {3u, 4u, 10u, 100u, 1000u, 10000u, 100000u}) {
    compareWithCgal(randomPoints(n, static_cast<unsigned>(n)), ("random " + std::to_string(n)).c_str());
  }
}

TEST(CgalCompare, RandomMillion) { compareWithCgal(randomPoints(1000000, 2026), "random 1M"); }

TEST(CgalCompare, Grid) {
  for (std::size_t side : {2u, 3u, 10u, 100u, 300u}) compareWithCgal(grid(side), ("grid " + std::to_string(side)).c_str());
}

TEST(CgalCompare, Circle) {
  for (std::size_t n : {3u, 5u, 64u, 1000u, 10000u}) {
    compareWithCgal(circle(n, false), "circle");
    compareWithCgal(circle(n, true), "circle with centre");
  }
}

TEST(CgalCompare, Clustered) {
  for (std::size_t n : {1000u, 50000u}) compareWithCgal(clustered(n, 5), ("clustered " + std::to_string(n)).c_str());
}

TEST(CgalCompare, LongThin) {
  for (std::size_t n : {100u, 10000u, 100000u}) compareWithCgal(longThin(n, 8), ("long thin " + std::to_string(n)).c_str());
}

TEST(CgalCompare, PolygonWithHoles) {
  compareWithCgal(polygonWithHoles(8, 1, 4, 0, 1), "octagon with one hole");
  compareWithCgal(polygonWithHoles(200, 16, 12, 500, 2), "16 holes");
  compareWithCgal(polygonWithHoles(2000, 400, 20, 20000, 3), "400 holes, 10k segments");
}

TEST(CgalCompare, ConstrainedGridAndDiagonals) {
  // Segments along grid lines and diagonals through many collinear vertices.
  PolyData d = grid(30);
  for (std::uint32_t i = 0; i + 1 < 30; ++i) {
    d.segments.push_back({i * 30, (i + 1) * 30});                   // along one side (split at every vertex)
    d.segments.push_back({i * 30 + i, (i + 1) * 30 + (i + 1)});     // main diagonal
  }
  d.segments.push_back({0, 29 * 30 + 29});  // the whole diagonal again, through 28 vertices
  d.segments.push_back({29, 29 * 30});      // the anti-diagonal crosses it exactly at a vertex? (29,0)-(0,29): no
  // Close a loop so the domain is a polygon: the grid's border.
  PolyTriangulation result;
  std::string error;
  const bool ok = triangulatePoly(d, result, error);
  // The anti-diagonal crosses the main diagonal between grid vertices (at (14.5, 14.5)): rejected.
  EXPECT_FALSE(ok);
  EXPECT_NE(error.find("crosses"), std::string::npos) << error;
  d.segments.pop_back();
  compareWithCgal(d, "constrained grid");
}

}  // namespace
}  // namespace cet
