// The wires of one face as ordered edge occurrences with their pcurves (DESIGN.md step 3): outer and
// inner loops, seam edges (two occurrences, two pcurves), degenerate edges (poles, apexes), and the
// period shifts that make each loop continuous in UV on periodic surfaces.
#pragma once

#include <string>
#include <vector>

#include <Geom2d_Curve.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec2d.hxx>

#include "brep/model.h"

namespace cetview::brep {

class ModelImpl;

struct LoopEdge {
  EdgeId edge = 0;
  bool reversed = false;     // traversed from the edge's last parameter to its first
  bool degenerated = false;  // a pole or apex: one 3D point
  Handle(Geom2d_Curve) pcurve;
  double pcurveFirst = 0, pcurveLast = 0;  // pcurve range matching the edge's [first, last]
  double edgeFirst = 0, edgeLast = 0;
  gp_Vec2d shift;            // added to every pcurve point (a multiple of the surface periods)
  gp_Pnt pole;               // degenerated: the 3D point

  // The pcurve parameter for the edge parameter t (linear when the ranges differ: not same-parameter).
  double pcurveParameter(double t) const {
    if (edgeLast == edgeFirst) return pcurveFirst;
    return pcurveFirst + (t - edgeFirst) / (edgeLast - edgeFirst) * (pcurveLast - pcurveFirst);
  }
};

struct FaceTopology {
  TopoDS_Face face;  // FORWARD-oriented: outer loops run counter-clockwise in UV, holes clockwise
  std::vector<std::vector<LoopEdge>> loops;
  std::string failure;               // non-empty: the face cannot be meshed from its wires (why)
  std::vector<std::string> repairs;  // sound repairs applied while building
};

// Builds the loops of face f. Never throws: problems land in failure.
FaceTopology buildFaceTopology(const ModelImpl& model, FaceId f);

}  // namespace cetview::brep
