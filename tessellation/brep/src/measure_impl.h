// Private: the deviation measure on raw arrays, used for CET meshes and BRepMesh's alike (the bench
// compares both with the same code).
#pragma once

#include <cstddef>
#include <cstdint>

#include "surface_eval.h"

namespace cetview::brep {

// Largest distance from the triangles to the surface: 13 samples per triangle projected by Newton
// from their interpolated (u, v). positions xyz and uv per vertex; idx three per triangle.
double measureDeviation(const SurfaceEval& eval, const double* positions, const double* uv, const std::uint32_t* idx,
                        std::size_t triangles);

}  // namespace cetview::brep
