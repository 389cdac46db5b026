#include "poly_triangulation.h"

#include <numeric>

#include "kd_order.h"

namespace cet {

bool triangulatePoly(const PolyData& data, PolyTriangulation& out, std::string& error) {
  const std::size_t n = data.points.size();
  out.inputOf.resize(n);
  std::iota(out.inputOf.begin(), out.inputOf.end(), 0u);
  kdPermutation(data.points.data(), out.inputOf.data(), n);
  out.internalOf.resize(n);
  std::vector<Point2> ordered(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.internalOf[out.inputOf[i]] = static_cast<std::uint32_t>(i);
    ordered[i] = data.points[out.inputOf[i]];
  }
  Triangulator& tri = out.tri;
  tri.reserve(n);
  tri.addVertices(ordered.data(), n);
  ordered = std::vector<Point2>();
  if (!tri.insertPending(/*alreadyKdOrdered=*/true)) return true;  // all points collinear (or fewer than 3): no triangle
  for (std::size_t s = 0; s < data.segments.size(); ++s) {
    const Status status = tri.insertSegment(out.internalOf[data.segments[s][0]], out.internalOf[data.segments[s][1]]);
    if (!status.ok()) {
      error = "segment " + std::to_string(s + static_cast<std::size_t>(data.base)) + ": " + status.message;
      return false;
    }
  }
  tri.markDomain(DomainRule::kHullAndHolePoints, data.holes.data(), data.holes.size());
  return true;
}

void PolyTriangulation::collectInputTriangles(std::vector<std::uint32_t>& indices) const {
  tri.collectTriangles(indices);
  for (std::uint32_t& v : indices) v = inputOf[v];
}

}  // namespace cet
