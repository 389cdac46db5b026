#include "kd_order.h"

#include <algorithm>

namespace cet {

namespace {
struct Box {
  double minX, minY, maxX, maxY;
};
struct Pending {
  std::uint32_t lo, hi;
  Box box;
};
// The points are copied next to their ids while partitioning, so nth_element compares contiguous
// memory instead of chasing ids into the vertex array (several times faster on large inputs).
struct Item {
  double x, y;
  std::uint32_t id;
};
}  // namespace

void kdPermutation(const Point2* points, std::uint32_t* ids, std::size_t n) {
  if (n < 2) return;
  std::vector<Item> items(n);
  Box all{points[ids[0]].x, points[ids[0]].y, points[ids[0]].x, points[ids[0]].y};
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 p = points[ids[i]];
    items[i] = Item{p.x, p.y, ids[i]};
    all.minX = std::min(all.minX, p.x), all.maxX = std::max(all.maxX, p.x);
    all.minY = std::min(all.minY, p.y), all.maxY = std::max(all.maxY, p.y);
  }
  // Depth-first with an explicit stack (depth about log2 n); the child boxes are the parent's box
  // cut at the median, which is enough to choose the longer axis without rescanning points.
  std::vector<Pending> stack;
  stack.push_back(Pending{0, static_cast<std::uint32_t>(n), all});
  Item* const it = items.data();
  while (!stack.empty()) {
    const Pending r = stack.back();
    stack.pop_back();
    if (r.hi - r.lo < 2) continue;
    const std::uint32_t mid = r.lo + (r.hi - r.lo) / 2;
    const bool splitX = (r.box.maxX - r.box.minX) >= (r.box.maxY - r.box.minY);
    if (splitX) {
      std::nth_element(it + r.lo, it + mid, it + r.hi,
                       [](const Item& a, const Item& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    } else {
      std::nth_element(it + r.lo, it + mid, it + r.hi,
                       [](const Item& a, const Item& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); });
    }
    const Item m = it[mid];
    Box lower = r.box, upper = r.box;
    if (splitX) {
      lower.maxX = m.x, upper.minX = m.x;
    } else {
      lower.maxY = m.y, upper.minY = m.y;
    }
    stack.push_back(Pending{r.lo, mid, lower});
    stack.push_back(Pending{mid + 1, r.hi, upper});
  }
  for (std::size_t i = 0; i < n; ++i) ids[i] = items[i].id;
}

}  // namespace cet
