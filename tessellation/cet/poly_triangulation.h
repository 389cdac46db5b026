// The whole .poly pipeline on the CET triangulator: vertices in kd order, segments recovered, then
// the domain carved as Triangle's -p does (concavities and holes removed; with no segments, the
// convex hull).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "poly_format.h"
#include "triangulator.h"

namespace cet {

// The triangulator stores the input vertices in kd-permutation order (as Yang & Choi rearrange the
// vertex array), so that consecutive insertions read neighbouring memory; the two maps translate
// between the file's vertex numbers and the triangulator's ids.
struct PolyTriangulation {
  Triangulator tri;
  std::vector<std::uint32_t> inputOf;     // triangulator vertex id -> input vertex index
  std::vector<std::uint32_t> internalOf;  // input vertex index -> triangulator vertex id

  // Inside triangles, counter-clockwise, as 0-based input vertex indices (duplicates map to the
  // input vertex they were merged into).
  void collectInputTriangles(std::vector<std::uint32_t>& indices) const;
};

// Triangulates `data` into `out`. Returns false with a one-line `error` when the input cannot be
// triangulated as given (crossing segments). All-collinear input is not an error: no triangles.
bool triangulatePoly(const PolyData& data, PolyTriangulation& out, std::string& error);

}  // namespace cet
