#include "mesh_predicates.h"

#include "predicates.h"

namespace cet {

bool strictlyBetween(Point2 a, Point2 b, Point2 p) {
  if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
  return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

bool inCircumcircle(const CetMesh& mesh, TriangleId t, VertexId d) {
  if (d == kInfiniteVertex) return false;
  const Point2 pd = mesh.point(d);
  const int g = mesh.ghostIndex(t);
  if (g < 0) {
    return incircle(mesh.point(mesh.vertex(t, 0)), mesh.point(mesh.vertex(t, 1)), mesh.point(mesh.vertex(t, 2)),
                    pd) > 0.0;
  }
  const Point2 x = mesh.point(mesh.vertex(t, next3(g)));
  const Point2 y = mesh.point(mesh.vertex(t, prev3(g)));
  const double o = orient2d(x, y, pd);
  if (o != 0.0) return o > 0.0;
  return strictlyBetween(x, y, pd);
}

}  // namespace cet
