// A free-form curve that is a circular arc in disguise: STEP and IGES files often write circles as
// rational B-splines (the strips of as1-oc-214-mat are bounded by such half circles). Found from
// samples of the curve, it takes equal segments as an exact circle does (edge_table.cpp), at the
// parameters where it has turned by equal angles, which on a rational curve are not equally spaced.
#pragma once

#include <optional>

#include <Adaptor3d_Curve.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

namespace cetview::brep {

struct CircularArc {
  gp_Pnt center;
  gp_Dir axis;   // the arc turns counter-clockwise about it from start to end
  gp_Dir start;  // from the center towards the arc's start
  double radius = 0;
  double angle = 0;  // how far it turns, in (0, 2 pi]

  // The angle of p about the axis from the start, in [0, 2 pi).
  double angleOf(const gp_Pnt& p) const;
  // The parameter in [first, last] where the curve has turned by phi (0 <= phi <= angle): Newton's
  // steps on the turn, kept inside a shrinking bracket (halving it where a step would leave it).
  double parameterAt(const Adaptor3d_Curve& curve, double first, double last, double phi) const;
};

// The circle a rational curve runs on between first and last (a closed edge: once round), if every
// one of 32 samples lies on it within 1e-9 of its radius and they turn steadily one way, by more
// than a thousandth of a radian in all; else none.
std::optional<CircularArc> circularArcOf(const Adaptor3d_Curve& curve, double first, double last, bool closed);

}  // namespace cetview::brep
