// Validators for the CET arrays, run by the tests after operations (and available to any caller).
#pragma once

#include <string>

#include "cet_mesh.h"

namespace cet {

// Structural invariants: neighbour symmetry (N of the neighbour points back across the same two
// vertices), L of every inserted vertex names a triangle containing it, flags consistent across an
// edge (1 on one side is 2 on the other, 0 and 3 on both), every finite triangle strictly
// counter-clockwise (exact orient2d), exactly one infinite vertex per ghost, the outside bit equal on
// both sides of every unconstrained edge between finite
// triangles (ghosts are outside by definition). Returns an empty string when valid, else the first problem.
std::string checkTopology(const CetMesh& mesh);

// Every unconstrained edge is locally Delaunay by the exact in-circle test (ghost edges: the hull
// is convex). Returns an empty string when it holds, else the first offending edge.
std::string checkDelaunay(const CetMesh& mesh);

}  // namespace cet
