// Checks on triangle meshes, shared by the tests and the bench: plain arrays in, counts out.
// Watertightness (open edges after welding), degenerate triangles, and self-intersection by bucket
// subdivision plus triangle-triangle tests (Jung, Shin & Choi, "Self-intersection removal in
// triangular mesh offsetting", section 3.2; the triangle test is Moeller's interval overlap).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cetview::brep {

class Tessellator;

struct TriangleSoup {
  std::vector<double> positions;       // x, y, z per vertex
  std::vector<std::uint32_t> indices;  // three per triangle
  std::vector<std::uint32_t> faceOf;   // the face id of each triangle (optional: empty means one face)
  std::size_t triangleCount() const { return indices.size() / 3; }
};

// One part's mesh at level k (the final level for -1, a face's last level where it has fewer):
// every face's vertices and triangles, in part coordinates.
TriangleSoup partSoup(const Tessellator& t, std::uint32_t part, int level = -1);

// Maps each vertex to a representative: vertices closer than `tolerance` (per axis) are merged.
std::vector<std::uint32_t> weldVertices(const std::vector<double>& positions, double tolerance);

// Edges used by exactly one triangle after welding (the cracks and free boundaries of the mesh).
// Edges used by three or more triangles are counted in `nonManifold` if given.
std::size_t countOpenEdges(const TriangleSoup& soup, double weldTolerance, std::size_t* nonManifold = nullptr);

// Triangles with (numerically) zero area: |cross product| <= 1e-12 * longest edge squared.
std::size_t countDegenerate(const TriangleSoup& soup);

// Pairs of triangles that properly intersect. Pairs sharing a (welded) vertex are not tested;
// contacts closer than `tolerance` do not count. A pair from two different faces counts only when
// one triangle pierces the other's plane deeper than `otherFaceDepth`: faces that touch (solids in
// contact, coplanar faces) or meet tangentially cross by up to the deflection in any mesh, while a
// fold or a real overlap goes deeper. Up to maxPairs pairs are returned in `pairs`.
std::size_t countSelfIntersections(const TriangleSoup& soup, double weldTolerance, double tolerance,
                                   std::vector<std::pair<std::uint32_t, std::uint32_t>>* pairs = nullptr,
                                   std::size_t maxPairs = 16, double otherFaceDepth = 0);

}  // namespace cetview::brep
