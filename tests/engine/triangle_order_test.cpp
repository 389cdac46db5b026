// Triangle reordering for vertex reuse without a GPU: the same triangles with the same windings
// come out, far fewer vertex shader runs are needed for a shuffled face, and a face that is already
// compact keeps its order.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "engine/triangle_order.h"

namespace cetview::test {
namespace {

using namespace engine;
using Triangle = std::array<std::uint32_t, 3>;

// A grid of n x n quads, row by row (a compact order), vertex ids from `first` times `stride`.
std::vector<std::uint32_t> grid(std::uint32_t n, std::uint32_t first = 0, std::uint32_t stride = 1) {
  std::vector<std::uint32_t> indices;
  auto id = [&](std::uint32_t i, std::uint32_t j) { return (first + j * (n + 1) + i) * stride; };
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      indices.insert(indices.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      indices.insert(indices.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return indices;
}

std::vector<std::uint32_t> shuffled(std::vector<std::uint32_t> indices, unsigned seed) {
  std::mt19937 rng(seed);
  std::size_t triangles = indices.size() / 3;
  for (std::size_t i = triangles - 1; i > 0; --i) {
    std::size_t j = std::uniform_int_distribution<std::size_t>(0, i)(rng);
    for (int c = 0; c < 3; ++c) std::swap(indices[3 * i + c], indices[3 * j + c]);
  }
  return indices;
}

// The triangles as a sorted list, each rotated to start at its smallest vertex (winding kept).
std::vector<Triangle> triangles(const std::vector<std::uint32_t>& indices) {
  std::vector<Triangle> result;
  for (std::size_t k = 0; k + 2 < indices.size(); k += 3) {
    Triangle t{indices[k], indices[k + 1], indices[k + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    result.push_back(t);
  }
  std::sort(result.begin(), result.end());
  return result;
}

double fetchesPerTriangle(const std::vector<std::uint32_t>& indices) {
  return double(lavapipeVertexFetches(indices.data(), indices.size())) / double(indices.size() / 3);
}

TEST(TriangleOrderTest, SmallFacesKeepTheirOrder) {
  std::vector<std::uint32_t> small = shuffled(grid(11), 1);  // 242 triangles
  ASSERT_LT(small.size() / 3, kReorderMinTriangles);
  std::vector<std::uint32_t> copy = small;
  reorderForVertexReuse(copy);
  EXPECT_EQ(copy, small);
}

TEST(TriangleOrderTest, ShuffledFacesGetCompactAgainWithTheSameTriangles) {
  for (std::uint32_t stride : {1u, 1000u}) {  // dense ids, and ids spread far apart
    std::vector<std::uint32_t> compact = grid(60, 5000, stride);
    std::vector<std::uint32_t> mixed = shuffled(compact, 2);
    std::vector<std::uint32_t> reordered = mixed;
    reorderForVertexReuse(reordered);
    EXPECT_EQ(triangles(reordered), triangles(compact)) << "stride " << stride;
    EXPECT_GT(fetchesPerTriangle(mixed), 2.0) << "stride " << stride;
    EXPECT_LT(fetchesPerTriangle(reordered), 0.8) << "stride " << stride;
  }
}

TEST(TriangleOrderTest, CompactFacesKeepTheirOrder) {
  std::vector<std::uint32_t> compact = grid(25);
  ASSERT_LE(fetchesPerTriangle(compact), kCompactFetchesPerTriangle);
  std::vector<std::uint32_t> copy = compact;
  reorderForVertexReuse(copy);
  EXPECT_EQ(copy, compact);
}

}  // namespace
}  // namespace cetview::test
