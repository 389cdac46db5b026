// Measured quality of a tessellation against the exact surfaces: the numbers the deviation promise
// (DESIGN.md "Tolerance semantics") and the bench are about.
#pragma once

#include <cstddef>
#include <vector>

namespace cetview::brep {

class Tessellator;

struct FaceQuality {
  double maxDeviation = 0;    // largest distance from the mesh to the exact surface
  std::size_t triangles = 0;
  std::size_t degenerate = 0; // zero-area triangles (|cross| <= 1e-12 * longest edge squared)
  std::size_t flipped = 0;    // triangles facing against their corners' surface normals
  // Largest angle (radians) between the exact surface normals at the ends of a triangle edge, over
  // edges of at least a tenth of the final chordal tolerance, off poles and creases.
  double maxCornerAngle = 0;
};

// Measures level `level` of every face (each face's last level for -1). The deviation is sampled at
// 13 points of every triangle (the centroid and a barycentric grid of step 1/4 without the corners),
// each projected onto the exact surface by Newton iteration from its interpolated (u, v); on planes,
// cylinders and spheres it is also computed exactly per triangle (the largest distance in closed form).
std::vector<FaceQuality> measureFaces(const Tessellator& t, int level = -1, unsigned threads = 1);

// Flipped triangles (as FaceQuality::flipped) over every face of level `level` (each face's last
// level for -1), without the surface measures: cheap enough for every level of a bench run.
std::size_t countFlipped(const Tessellator& t, int level);

// The same measure per triangle (the viewer's deviation heat map): out[f][i] is the deviation of
// triangle i of face f's level `level` (each face's last level for -1), in the order of
// faceMesh(f).levels; INFINITY where the surface cannot be evaluated.
std::vector<std::vector<float>> measureTriangles(const Tessellator& t, int level = -1, unsigned threads = 1);

}  // namespace cetview::brep
