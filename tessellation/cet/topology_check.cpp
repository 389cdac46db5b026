#include "topology_check.h"

#include "mesh_predicates.h"
#include "predicates.h"

namespace cet {

namespace {
std::string edgeName(const CetMesh& mesh, TriangleId t, int i) {
  const auto name = [](VertexId v) { return v == kInfiniteVertex ? std::string("inf") : std::to_string(v); };
  return "triangle " + std::to_string(t) + " edge " + std::to_string(i) + " (" +
         name(mesh.vertex(t, next3(i))) + "-" + name(mesh.vertex(t, prev3(i))) + ")";
}
}  // namespace

std::string checkTopology(const CetMesh& mesh) {
  const auto m = static_cast<TriangleId>(mesh.triangleCount());
  const auto n = static_cast<VertexId>(mesh.vertexCount());
  for (TriangleId t = 0; t < m; ++t) {
    int infinite = 0;
    for (int i = 0; i < 3; ++i) {
      const VertexId v = mesh.vertex(t, i);
      if (v == kInfiniteVertex) {
        ++infinite;
      } else if (v >= n) {
        return "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) + " out of range";
      }
    }
    if (infinite > 1) return "triangle " + std::to_string(t) + " has more than one infinite vertex";
    if (infinite == 0) {
      const double o = orient2d(mesh.point(mesh.vertex(t, 0)), mesh.point(mesh.vertex(t, 1)),
                                mesh.point(mesh.vertex(t, 2)));
      if (!(o > 0.0)) return "triangle " + std::to_string(t) + " is not counter-clockwise";
    }
    for (int i = 0; i < 3; ++i) {
      const TriangleId u = mesh.neighbor(t, i);
      if (u >= m) return edgeName(mesh, t, i) + " has no neighbour";
      const VertexId a = mesh.vertex(t, next3(i)), b = mesh.vertex(t, prev3(i));
      int j = -1;
      for (int k = 0; k < 3; ++k) {
        if (mesh.neighbor(u, k) == t && mesh.vertex(u, next3(k)) == b && mesh.vertex(u, prev3(k)) == a) j = k;
      }
      if (j < 0) return edgeName(mesh, t, i) + ": neighbour " + std::to_string(u) + " does not share it back";
      if (mesh.flag(u, j) != twinFlag(mesh.flag(t, i))) return edgeName(mesh, t, i) + ": flags disagree across it";
      if (!mesh.isConstrained(t, i) && infinite == 0 && !mesh.isGhost(u) && mesh.isOutside(t) != mesh.isOutside(u)) {
        return edgeName(mesh, t, i) + ": domain changes across an unconstrained edge";
      }
    }
  }
  for (VertexId v = 0; v < n; ++v) {
    const TriangleId t = mesh.incident(v);
    if (t == kNoTriangle) continue;
    if (t >= m || mesh.indexOf(t, v) < 0) return "vertex " + std::to_string(v) + ": L does not contain it";
  }
  return {};
}

std::string checkDelaunay(const CetMesh& mesh) {
  const auto m = static_cast<TriangleId>(mesh.triangleCount());
  for (TriangleId t = 0; t < m; ++t) {
    for (int i = 0; i < 3; ++i) {
      if (mesh.isConstrained(t, i)) continue;
      const EdgeRef across = mesh.twin(EdgeRef{t, i});
      if (inCircumcircle(mesh, t, mesh.vertex(across.t, across.i))) {
        return edgeName(mesh, t, i) + " is not locally Delaunay";
      }
    }
  }
  return {};
}

}  // namespace cet
