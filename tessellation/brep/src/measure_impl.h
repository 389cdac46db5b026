// Private: the deviation measure on raw arrays, used for CET meshes and BRepMesh's alike (the bench
// compares both with the same code).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "surface_eval.h"

namespace cetview::brep {

// Largest distance from the triangles to the surface. On planes, cylinders and spheres the exact
// largest distance of each triangle (SurfaceEval::triangleDeviation); on cones and tori 13 samples
// per triangle at their closed-form distances; elsewhere the 13 samples projected by Gauss-Newton
// from their interpolated (u, v), and a sample that would raise the maximum then by damped steps
// (Levenberg-Marquardt) down to a local minimum of its distance, and if it still would, again from
// the surface point nearest to it on a grid over the triangle's (u, v): never under the distance,
// and over it only where the nearest point lies beyond another local minimum from every start.
// A triangle without area in (u, v) seeds along its one line instead of a grid, and then searches
// that line around the nearest seed by golden sections (no derivatives: past a knot where the
// surface collapses onto a point, projections cannot move).
// positions xyz and uv per vertex; idx three per triangle.
// A sample still over `fineAbove` (the tolerance it is judged by) is also taken from a finer grid.
// Once the largest distance so far is over `stopAbove`, it is returned at once: a reading over
// stopAbove for exactly the triangles whose full reading is (the samples are read in the same
// order either way), for callers that only ask whether the triangles are within it.
double measureDeviation(const SurfaceEval& eval, const double* positions, const double* uv,
                        const std::uint32_t* idx, std::size_t triangles, double fineAbove = INFINITY,
                        double stopAbove = INFINITY);

// Largest angle (radians) between the exact surface normals at the two ends of a triangle edge:
// DESIGN.md's angular deflection. Edges shorter than `minLength` (the size below which neither
// mesher applies the angle), with an end where the normal is undefined (a pole, an apex), across a
// crease of the surface or a fold of its parametrisation (where the normal jumps: no refinement
// brings the two sides' normals together) are not counted. With the mesh's `normals` (xyz per
// vertex), a vertex that shares its (u, v) and point with another (a fold vertex and its twin, one
// per side of the fold: FaceMesher) has, along each edge, the normal that the surface has a small
// step along it and that vertex shows (the normal's limit on that side); without them, or none
// such, the normal at its (u, v) (at a fold, the middle of the turn).
double measureCornerAngle(const SurfaceEval& eval, const double* positions, const double* uv,
                          std::size_t vertices, const std::uint32_t* idx, std::size_t triangles,
                          double minLength, const float* normals = nullptr);

// How a triangle (corner: its three vertex indices) faces against its corners' unit surface normals
// (xyz per vertex): degenerate (no area: |cross| <= 1e-12 * longest edge squared), facing (along
// their sum), or flipped (against it); flipped across a fold when two corners' normals oppose (a
// negative dot product: the surface's parametrisation folds between them, and no flat triangle
// faces both ways). FaceQuality's degenerate, flipped and flippedAcrossFolds count these.
enum class TriangleFacing { kFacing, kDegenerate, kFlipped, kFlippedAcrossFold };
TriangleFacing triangleFacing(const double* positions, const float* normals, const std::uint32_t corner[3]);

}  // namespace cetview::brep
