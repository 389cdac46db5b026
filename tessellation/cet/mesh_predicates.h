// The exact predicates lifted to CET triangles, with the vertex at infinity handled symbolically.
#pragma once

#include "cet_mesh.h"
#include "types.h"

namespace cet {

// p lies on the open segment (a, b); a, b, p must be collinear. Exact (coordinate comparisons).
bool strictlyBetween(Point2 a, Point2 b, Point2 p);

// Whether vertex d lies strictly inside the circumcircle of triangle t, the test Lawson's flips use.
// For a ghost triangle (x, y, infinity) the "circle" is the open half-plane left of x -> y (outside
// the hull) plus the open segment (x, y); the infinite vertex is inside no circle. With this
// convention the flips keep the hull convex and the whole triangulation Delaunay.
bool inCircumcircle(const CetMesh& mesh, TriangleId t, VertexId d);

}  // namespace cet
