// How far a facet may turn from the surface it stands for, shared by the edge discretisation and
// the face refinement.
#pragma once

namespace cetview::brep {

// A facet more than 70 degrees off its corners' surface normals is nearly edge-on: a fold, a flip
// waiting to happen. (A smaller angle would catch the long thin triangles of a curved surface,
// which tilt by less and are sound; splitting them would only make more.) cos(70 degrees).
constexpr double kFoldCos = 0.3420201433256687;

// A new point may stand on a boundary chord closer than the chord's clearance if the facet it makes
// with it is within 60 degrees of the normals: the fold rule with a margin. cos(60 degrees).
constexpr double kStandingFacetCos = 0.5;

}  // namespace cetview::brep
