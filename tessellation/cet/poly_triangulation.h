// The whole .poly pipeline on the CET triangulator: vertices in kd order, segments recovered, then
// the domain carved as Triangle's -p does (concavities and holes removed; with no segments, the
// convex hull).
#pragma once

#include <string>
#include <vector>

#include "poly_format.h"
#include "triangulator.h"

namespace cet {

// Triangulates `data` into `tri`. Returns false with a one-line `error` when the input cannot be
// triangulated as given (crossing segments). All-collinear input is not an error: no triangles.
bool triangulatePoly(const PolyData& data, Triangulator& tri, std::string& error);

}  // namespace cet
