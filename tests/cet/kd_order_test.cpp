#include "cet/kd_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace cet {
namespace {

// Checks the kd property recursively: in every range the median splits its points on one axis.
void expectKdRange(const std::vector<Point2>& p, const std::vector<std::uint32_t>& ids, std::size_t lo, std::size_t hi,
                   int depth) {
  if (hi - lo < 2 || depth > 64) return;
  const std::size_t mid = lo + (hi - lo) / 2;
  const Point2 m = p[ids[mid]];
  const bool xSplit = std::all_of(ids.begin() + static_cast<long>(lo), ids.begin() + static_cast<long>(mid),
                                  [&](std::uint32_t i) { return p[i].x <= m.x; }) &&
                      std::all_of(ids.begin() + static_cast<long>(mid) + 1, ids.begin() + static_cast<long>(hi),
                                  [&](std::uint32_t i) { return p[i].x >= m.x; });
  const bool ySplit = std::all_of(ids.begin() + static_cast<long>(lo), ids.begin() + static_cast<long>(mid),
                                  [&](std::uint32_t i) { return p[i].y <= m.y; }) &&
                      std::all_of(ids.begin() + static_cast<long>(mid) + 1, ids.begin() + static_cast<long>(hi),
                                  [&](std::uint32_t i) { return p[i].y >= m.y; });
  ASSERT_TRUE(xSplit || ySplit) << "range [" << lo << ", " << hi << ")";
  expectKdRange(p, ids, lo, mid, depth + 1);
  expectKdRange(p, ids, mid + 1, hi, depth + 1);
}

TEST(KdOrder, PermutationIsAKdTree) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> p(5000);
  for (auto& q : p) q = {u(rng) * 10.0, u(rng)};  // long and thin: splits mostly on x
  std::vector<std::uint32_t> ids(p.size());
  std::iota(ids.begin(), ids.end(), 0u);
  kdPermutation(p.data(), ids.data(), ids.size());
  std::vector<std::uint32_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  expectKdRange(p, ids, 0, ids.size(), 0);
}

TEST(KdOrder, BreadthFirstVisitsEveryIdOnceAfterItsParent) {
  std::vector<Point2> p(1000);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {static_cast<double>(i % 37), static_cast<double>(i / 37)};
  std::vector<std::uint32_t> ids(p.size());
  std::iota(ids.begin(), ids.end(), 0u);
  kdPermutation(p.data(), ids.data(), ids.size());
  std::vector<int> seen(p.size(), 0);
  std::vector<KdRange> queue;
  std::size_t count = 0;
  forEachBreadthFirst(ids.data(), ids.size(), queue, [&](std::uint32_t id, std::uint32_t parent) {
    if (count == 0) {
      EXPECT_EQ(parent, UINT32_MAX);
    } else {
      ASSERT_LT(parent, p.size());
      EXPECT_EQ(seen[parent], 1) << "parent must be visited first";
    }
    ++seen[id];
    ++count;
  });
  EXPECT_EQ(count, p.size());
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
}

}  // namespace
}  // namespace cet
