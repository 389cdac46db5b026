// Where a flat triangle's deviation from a surface that bends one way peaks inside it.
//
// Over a small triangle whose corners lie on the surface the distance to it is nearly quadratic,
// zero at the corners: q(b) = 4 (m0 b1 b2 + m1 b2 b0 + m2 b0 b1) in barycentric coordinates b, m_i
// its value at the middle of edge i (opposite corner i). Where the surface is a saddle or bends
// one way only (a cone), q peaks on an edge, at its middle; where it bends both ways alike (a
// sphere, a torus's outside: the distances keep one sign) it may peak inside, where the centroid
// and the edges' middles, the refinement's samples, read down to 0.94 of it (an acute triangle
// whose circumcentre, in the metric of the surface's second fundamental form, lies between them).
// The middles' readings give q, and a sample at its peak reads the deviation all but exactly.
#pragma once

namespace cetview::brep {

// The barycentric weights b of q's maximum when it lies strictly inside the triangle (q concave
// there: all m_i > 0 and the peak not on an edge); false otherwise (the maximum is then on an
// edge, at its middle).
bool quadraticDeviationPeak(const double middle[3], double b[3]);

}  // namespace cetview::brep
