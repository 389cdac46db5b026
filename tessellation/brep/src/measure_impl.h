// Private: the deviation measure on raw arrays, used for CET meshes and BRepMesh's alike (the bench
// compares both with the same code).
#pragma once

#include <cstddef>
#include <cstdint>

#include "surface_eval.h"

namespace cetview::brep {

// Largest distance from the triangles to the surface: 13 samples per triangle projected by Newton
// from their interpolated (u, v), and on planes, cylinders and spheres also the exact largest
// distance of each triangle (SurfaceEval::triangleDeviation). positions xyz and uv per vertex; idx
// three per triangle.
double measureDeviation(const SurfaceEval& eval, const double* positions, const double* uv, const std::uint32_t* idx,
                        std::size_t triangles);

// Largest angle (radians) between the exact surface normals at the two ends of a triangle edge:
// DESIGN.md's angular deflection. Edges shorter than `minLength` (the size below which neither
// mesher applies the angle), with an end where the normal is undefined (a pole, an apex) or across a
// crease of the surface (where no refinement brings the normals together) are not counted.
double measureCornerAngle(const SurfaceEval& eval, const double* positions, const double* uv, std::size_t vertices,
                          const std::uint32_t* idx, std::size_t triangles, double minLength);

}  // namespace cetview::brep
