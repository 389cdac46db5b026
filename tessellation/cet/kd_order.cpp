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
}  // namespace

void kdPermutation(const Point2* points, std::uint32_t* ids, std::size_t n) {
  if (n < 2) return;
  Box all{points[ids[0]].x, points[ids[0]].y, points[ids[0]].x, points[ids[0]].y};
  for (std::size_t i = 1; i < n; ++i) {
    const Point2 p = points[ids[i]];
    all.minX = std::min(all.minX, p.x), all.maxX = std::max(all.maxX, p.x);
    all.minY = std::min(all.minY, p.y), all.maxY = std::max(all.maxY, p.y);
  }
  // Depth-first with an explicit stack (depth about log2 n); the child boxes are the parent's box
  // cut at the median, which is enough to choose the longer axis without rescanning points.
  std::vector<Pending> stack;
  stack.push_back(Pending{0, static_cast<std::uint32_t>(n), all});
  while (!stack.empty()) {
    const Pending r = stack.back();
    stack.pop_back();
    if (r.hi - r.lo < 2) continue;
    const std::uint32_t mid = r.lo + (r.hi - r.lo) / 2;
    const bool splitX = (r.box.maxX - r.box.minX) >= (r.box.maxY - r.box.minY);
    if (splitX) {
      std::nth_element(ids + r.lo, ids + mid, ids + r.hi, [points](std::uint32_t a, std::uint32_t b) {
        return points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
      });
    } else {
      std::nth_element(ids + r.lo, ids + mid, ids + r.hi, [points](std::uint32_t a, std::uint32_t b) {
        return points[a].y < points[b].y || (points[a].y == points[b].y && points[a].x < points[b].x);
      });
    }
    const Point2 m = points[ids[mid]];
    Box lower = r.box, upper = r.box;
    if (splitX) {
      lower.maxX = m.x, upper.minX = m.x;
    } else {
      lower.maxY = m.y, upper.minY = m.y;
    }
    stack.push_back(Pending{r.lo, mid, lower});
    stack.push_back(Pending{mid + 1, r.hi, upper});
  }
}

}  // namespace cet
