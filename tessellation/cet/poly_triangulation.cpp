#include "poly_triangulation.h"

#include <algorithm>
#include <numeric>

#include "kd_order.h"
#include "predicates.h"

namespace cet {

namespace {

// The failure in the file's own numbering: which input segment the new one crosses (the crossed
// edge is a piece of an earlier segment, split where it passed through vertices).
std::string describeFailedSegment(const PolyData& data, const PolyTriangulation& out, std::size_t s,
                                  const Status& status) {
  const auto base = static_cast<std::size_t>(data.base);
  const auto name = [&](std::size_t segment) {
    return "segment " + std::to_string(segment + base) + " (" + std::to_string(data.segments[segment][0] + base) +
           "-" + std::to_string(data.segments[segment][1] + base) + ")";
  };
  if (status.code != Status::Code::kCrossingSegments || status.crossed[0] == kInfiniteVertex)
    return name(s) + ": " + status.message;
  const Point2& a = data.points[out.inputOf[status.crossed[0]]];
  const Point2& b = data.points[out.inputOf[status.crossed[1]]];
  const auto within = [](const Point2& p, const Point2& q, const Point2& x) {
    return orient2d(p, q, x) == 0.0 && std::min(p.x, q.x) <= x.x && x.x <= std::max(p.x, q.x) &&
           std::min(p.y, q.y) <= x.y && x.y <= std::max(p.y, q.y);
  };
  for (std::size_t earlier = 0; earlier < s; ++earlier) {
    const Point2& p = data.points[data.segments[earlier][0]];
    const Point2& q = data.points[data.segments[earlier][1]];
    if (within(p, q, a) && within(p, q, b)) return name(s) + " crosses " + name(earlier);
  }
  return name(s) + " crosses the constraint edge " + std::to_string(out.inputOf[status.crossed[0]] + base) + "-" +
         std::to_string(out.inputOf[status.crossed[1]] + base);
}

}  // namespace

bool triangulatePoly(const PolyData& data, PolyTriangulation& out, std::string& error) {
  const std::size_t n = data.points.size();
  out.inputOf.resize(n);
  std::iota(out.inputOf.begin(), out.inputOf.end(), 0u);
  std::vector<Point2> ordered(n);
  kdPermutation(data.points.data(), out.inputOf.data(), n, ordered.data());
  out.internalOf.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.internalOf[out.inputOf[i]] = static_cast<std::uint32_t>(i);
  Triangulator& tri = out.tri;
  tri.reserve(n);
  tri.addVertices(ordered.data(), n);
  ordered = std::vector<Point2>();
  if (!tri.insertPending(/*alreadyKdOrdered=*/true)) return true;  // all points collinear (or fewer than 3): no triangle
  for (std::size_t s = 0; s < data.segments.size(); ++s) {
    const Status status = tri.insertSegment(out.internalOf[data.segments[s][0]], out.internalOf[data.segments[s][1]]);
    if (!status.ok()) {
      error = describeFailedSegment(data, out, s, status);
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
