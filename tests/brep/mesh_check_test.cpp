// The checks themselves must be able to fail: known cracks, degenerate and intersecting triangles.
#include <gtest/gtest.h>

#include "brep/mesh_check.h"

namespace cetview::brep {
namespace {

// A closed tetrahedron.
TriangleSoup tetrahedron() {
  TriangleSoup s;
  s.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  s.indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  s.faceOf = {0, 0, 0, 0};
  return s;
}

TEST(MeshCheck, ClosedMeshHasNoOpenEdge) { EXPECT_EQ(countOpenEdges(tetrahedron(), 1e-12), 0u); }

TEST(MeshCheck, DuplicatedVerticesWeldAndCracksShow) {
  TriangleSoup s = tetrahedron();
  // Give the last triangle its own copies of its corners: welded, still closed.
  s.positions.insert(s.positions.end(), {0, 0, 0, 0, 0, 1, 0, 1, 0});
  s.indices[9] = 4, s.indices[10] = 5, s.indices[11] = 6;
  EXPECT_EQ(countOpenEdges(s, 1e-12), 0u);
  // Move one copy: a crack of three open edges... and three more on the other side.
  s.positions[12] = 1e-3;
  EXPECT_EQ(countOpenEdges(s, 1e-9), 4u);
}

TEST(MeshCheck, Degenerate) {
  TriangleSoup s = tetrahedron();
  EXPECT_EQ(countDegenerate(s), 0u);
  s.positions.insert(s.positions.end(), {2, 0, 0});
  s.indices.insert(s.indices.end(), {0, 1, 4});  // collinear
  EXPECT_EQ(countDegenerate(s), 1u);
}

TEST(MeshCheck, SelfIntersection) {
  TriangleSoup s = tetrahedron();
  EXPECT_EQ(countSelfIntersections(s, 1e-12, 1e-12), 0u);
  // A triangle piercing the tetrahedron's face x + y + z = 1 and the base z = 0.
  s.positions.insert(s.positions.end(), {0.2, 0.2, -0.5, 0.3, 0.2, 2, 0.2, 0.3, 2});
  s.indices.insert(s.indices.end(), {4, 5, 6});
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  EXPECT_EQ(countSelfIntersections(s, 1e-12, 1e-12, &pairs), 2u);
  ASSERT_FALSE(pairs.empty());
  EXPECT_EQ(pairs[0].second, 4u);
}

TEST(MeshCheck, SelfIntersectionScalesWithBuckets) {
  // Two parallel grids 1e-3 apart never touch; one crossing triangle is found among 20000.
  TriangleSoup s;
  const int n = 50;
  for (int layer = 0; layer < 2; ++layer)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) s.positions.insert(s.positions.end(), {double(i), double(j), layer * 1e-3});
  auto id = [&](int layer, int i, int j) { return static_cast<std::uint32_t>(layer * (n + 1) * (n + 1) + i * (n + 1) + j); };
  for (int layer = 0; layer < 2; ++layer)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        s.indices.insert(s.indices.end(), {id(layer, i, j), id(layer, i + 1, j), id(layer, i + 1, j + 1)});
        s.indices.insert(s.indices.end(), {id(layer, i, j), id(layer, i + 1, j + 1), id(layer, i, j + 1)});
      }
  EXPECT_EQ(countSelfIntersections(s, 1e-9, 1e-9), 0u);
  const auto base = static_cast<std::uint32_t>(s.positions.size() / 3);
  s.positions.insert(s.positions.end(), {10.3, 10.3, -1, 10.6, 10.4, 1, 10.4, 10.6, 1});
  s.indices.insert(s.indices.end(), {base, base + 1, base + 2});
  EXPECT_GE(countSelfIntersections(s, 1e-9, 1e-9), 2u);  // through both layers
}

}  // namespace
}  // namespace cetview::brep
