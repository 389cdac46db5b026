// Basic types of the CET core: indices into the vertex and triangle arrays, and UV points.
#pragma once

#include <cstdint>

namespace cet {

// Index into the vertex array (V in Yang & Choi 2010).
using VertexId = std::uint32_t;
// Index into the triangle array (T in Yang & Choi 2010).
using TriangleId = std::uint32_t;

inline constexpr VertexId kNoVertex = 0xFFFFFFFFu;
// The symbolic vertex at infinity: each convex-hull edge has a ghost triangle (a, b, kInfiniteVertex)
// outside it, so every edge has two triangles and walks, flips and inserts need no special hull cases.
inline constexpr VertexId kInfiniteVertex = 0xFFFFFFFEu;
inline constexpr TriangleId kNoTriangle = 0xFFFFFFFFu;

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

// The exact predicates are exact while no product overflows or underflows: coordinates must be
// finite with magnitude in [kMinCoordinate, kMaxCoordinate], or zero. (1e-12 .. 1e12 is well inside.)
inline constexpr double kMaxCoordinate = 1e50;
inline constexpr double kMinCoordinate = 1e-50;
inline bool supportedCoordinate(double v) {
  const double m = v < 0 ? -v : v;
  return v == 0.0 || (m >= kMinCoordinate && m <= kMaxCoordinate);
}

inline bool operator==(Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Point2 a, Point2 b) { return !(a == b); }

}  // namespace cet
