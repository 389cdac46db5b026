#include "engine/triangle_order.h"

#include <algorithm>
#include <cstring>

#include <meshoptimizer.h>

namespace cetview::engine {

void reorderForVertexReuse(std::vector<std::uint32_t>& indices) {
  const std::size_t count = indices.size() / 3 * 3;
  if (count / 3 < kReorderMinTriangles) return;
  if (double(lavapipeVertexFetches(indices.data(), count)) <= kCompactFetchesPerTriangle * double(count / 3))
    return;
  auto [lo, hi] = std::minmax_element(indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(count));
  const std::uint32_t base = *lo;
  const std::size_t range = std::size_t{*hi} - base + 1;
  std::vector<std::uint32_t> local(count), reordered(count);
  std::vector<std::uint32_t> used;  // the distinct vertices, sorted, when the index range is sparse
  if (range <= 2 * count) {
    for (std::size_t i = 0; i < count; ++i) local[i] = indices[i] - base;
  } else {
    used.assign(indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(count));
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    for (std::size_t i = 0; i < count; ++i) {
      local[i] =
          static_cast<std::uint32_t>(std::lower_bound(used.begin(), used.end(), indices[i]) - used.begin());
    }
  }
  meshopt_optimizeVertexCache(reordered.data(), local.data(), count, used.empty() ? range : used.size());
  for (std::size_t i = 0; i < count; ++i)
    indices[i] = used.empty() ? reordered[i] + base : used[reordered[i]];
}

std::size_t lavapipeVertexFetches(const std::uint32_t* indices, std::size_t count) {
  constexpr std::size_t kSegment = 1023;  // 1024 rounded down to whole triangles
  std::size_t fetches = 0;
  for (std::size_t start = 0; start < count; start += kSegment) {
    std::uint32_t cache[256];
    std::memset(cache, 0xff, sizeof cache);
    for (std::size_t i = start; i < std::min(count, start + kSegment); ++i) {
      std::uint32_t v = indices[i];
      if (cache[v % 256] != v) {
        cache[v % 256] = v;
        ++fetches;
      }
    }
  }
  return fetches;
}

}  // namespace cetview::engine
