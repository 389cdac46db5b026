#include "poly_triangulation.h"

namespace cet {

bool triangulatePoly(const PolyData& data, Triangulator& tri, std::string& error) {
  tri.reserve(data.points.size());
  tri.addVertices(data.points.data(), data.points.size());
  if (!tri.insertPending()) return true;  // all points collinear (or fewer than 3): no triangle
  for (std::size_t s = 0; s < data.segments.size(); ++s) {
    const Status status = tri.insertSegment(data.segments[s][0], data.segments[s][1]);
    if (!status.ok()) {
      error = "segment " + std::to_string(s + static_cast<std::size_t>(data.base)) + ": " + status.message;
      return false;
    }
  }
  tri.markDomain(DomainRule::kHullAndHolePoints, data.holes.data(), data.holes.size());
  return true;
}

}  // namespace cet
