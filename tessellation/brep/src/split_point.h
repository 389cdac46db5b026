// Where the face mesher splits a triangle that lies too far from an analytic surface (plane,
// cylinder, cone, sphere, torus) inside it, in the face's scaled UV plane.
#pragma once

#include "cet/types.h"

namespace cetview::brep {

// The barycentric weights b of the split point of triangle p (its corners in scaled UV; chord[i]:
// whether edge i, opposite corner i, is a boundary chord, which no point may split): its
// circumcentre where that lies strictly inside it, as Delaunay refinement does; else (an obtuse or
// right corner) the middle of its longest edge unless that is a boundary chord (Rivara's
// bisection); else its centroid. The deviation of such a triangle grows with its size, and the
// first two leave the new triangles better shaped than the centroid would: fewer points for the
// same tolerance (with circles on spheres in equal segments: CylinderHead 1172 -> 1140 triangles,
// fuse 996 -> 908, Pump_TopCover 5014 -> 4910 at 0.1%).
void analyticSplitWeights(const cet::Point2 p[3], const bool chord[3], double b[3]);

}  // namespace cetview::brep
