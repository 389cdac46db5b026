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
  // Of those, the ones across a fold: two corners' normals oppose (a negative dot product), as
  // where a surface's parametrisation folds a sheet flat (a wing tip closed to zero thickness).
  // No flat triangle faces both ways there; the rest are orientation errors.
  std::size_t flippedAcrossFolds = 0;
  // Largest angle (radians) between the exact surface normals at the ends of a triangle edge, over
  // edges of at least a tenth of the final chordal tolerance, off poles, creases and folds (where the
  // normal jumps).
  double maxCornerAngle = 0;
};

// Measures level `level` of every face (each face's last level for -1). The deviation is sampled at
// 13 points of every triangle (the centroid and a barycentric grid of step 1/4 without the corners),
// each projected onto the exact surface by Gauss-Newton iteration from its interpolated (u, v), then
// by damped steps where that would raise the maximum, and from the nearest point of a grid over the
// triangle's (u, v) where it still would (measure_impl.h). On elementary surfaces it is
// exact: on planes, cylinders and spheres the largest distance over the triangle in closed form, on
// cones and tori the samples' distances in closed form.
std::vector<FaceQuality> measureFaces(const Tessellator& t, int level = -1, unsigned threads = 1);

// Flipped triangles (as FaceQuality::flipped) over every face of level `level` (each face's last
// level for -1), without the surface measures: cheap enough for every level of a bench run. Those
// across folds (FaceQuality::flippedAcrossFolds) also go to `acrossFolds` when given.
std::size_t countFlipped(const Tessellator& t, int level, std::size_t* acrossFolds = nullptr);

// The same measure per triangle (the viewer's deviation heat map): out[f][i] is the deviation of
// triangle i of face f's level `level` (each face's last level for -1), in the order of
// faceMesh(f).levels; INFINITY where the surface cannot be evaluated.
std::vector<std::vector<float>> measureTriangles(const Tessellator& t, int level = -1, unsigned threads = 1);

}  // namespace cetview::brep
