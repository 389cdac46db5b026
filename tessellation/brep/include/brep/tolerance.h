// Tolerance semantics (DESIGN.md): chordal deflection absolute (model units) or relative to the
// model's bounding-box diagonal ("0.1%"); angular deflection in degrees. Parsing returns a one-line
// error for anything a user could type wrong; resolve() rejects values absurd for the given model.
#pragma once

#include <cstddef>

#include <string>

namespace cetview::brep {

struct Deflection {
  double value = 0.001;  // a fraction of the diagonal when relative, model units otherwise
  bool relative = true;
};

struct MeshParams {
  Deflection chordal;     // default 0.1% of the bounding-box diagonal
  double angleDeg = 20.0; // largest angle between corner normals of a triangle / tangents of an edge
  // Coarse-to-fine levels (DESIGN.md step 5); false makes the final level the only one.
  bool progressive = true;
  // Work bound: the most points one level's refinement may add to one face; beyond it the face
  // keeps what it has, and its report says the level's tolerances were not reached there. 0: the
  // default, 256 times the face's points before the level, at least 250 thousand and at most a
  // million (no face of the sample models comes near it; faces whose refinement does not converge
  // ran to millions).
  std::size_t maxPointsPerFaceLevel = 0;
};

// "0.1%" -> {0.001, relative}; "0.05" or "5e-2" -> {0.05, absolute}. Returns an empty string on
// success, else the error. Rejects empty, non-numeric, trailing garbage, NaN, infinity, zero,
// negative, and relative values above 50%.
std::string parseDeflection(const std::string& text, Deflection& out);

// Degrees in (0, 90]. Returns an empty string on success, else the error.
std::string parseAngle(const std::string& text, double& degrees);

// The absolute chordal deflection for a model with this bounding-box diagonal. Returns an empty
// string on success; rejects deflections below 1e-6 of the diagonal (the mesh would not fit in
// memory) or above half of it, and models without extent.
std::string resolveDeflection(const Deflection& d, double diagonal, double& absolute);

}  // namespace cetview::brep
