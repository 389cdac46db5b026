// Step 2 of DESIGN.md "Data flow": every edge of the model discretised once per level, shared by
// the faces that use it (so each completed level is watertight). Nested levels: the parameters of
// level k contain those of level k-1, so a face refines its boundary by splitting old segments.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Geom2d_Curve.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include "brep/tessellator.h"
#include "brep/worker_pool.h"
#include "bspline_direct.h"
#include "circular_arc.h"
#include "pcurve.h"
#include "spline_curve.h"
#include "surface_eval.h"
#include "uv_axis.h"

namespace cetview::brep {

class ModelImpl;

struct EdgePoints {
  std::vector<double> t;   // increasing curve parameters, first and last are the edge's ends
  std::vector<gp_Pnt> p;   // 3D points in part coordinates; the ends are the edge's vertices
  bool capped = false;     // stopped at the point bound: chords may miss the level's tolerances
};

class EdgeTable {
 public:
  // Points of one edge on one level, at most. The 62 sample models take up to 1039 at 0.1%
  // (terrain's); an edge that wants 250 times that is off its face (a fuzzed edge 1.08e6 long on a
  // face 2.9 across took 2.2 million points on its second level, and the face's boundary, built
  // from them without a look at the cancellation flag, held a cancelled run for 7.5 s).
  static constexpr std::size_t kMaxPoints = std::size_t{1} << 18;

  // Gathers the edges and the faces using them; cheap (no surface is evaluated). `tolerances`: the
  // edges' tolerance at each level, coarsest first.
  EdgeTable(const ModelImpl& model, std::vector<Level> tolerances);
  EdgeTable(const EdgeTable&) = delete;  // its edges' face uses point into faceScales_
  EdgeTable& operator=(const EdgeTable&) = delete;

  // What the discretisation needs of a face's surface (SurfaceEval's scaling and parameter box).
  struct FaceScale {
    bool valid = false;          // false: the face has no usable surface and does not guide its edges
    UvAxis uAxis, vAxis;         // its scaled UV plane, per knot span where spans differ (SurfaceEval)
    double uMin = 0, uMax = 0, vMin = 0, vMax = 0;
    // Tori and free-form surfaces (B-spline, Bezier, offset, swept): beside an edge the surface can
    // bend another way than along it.
    bool bendsBeside = false;
    // Not a plane: a narrow face folds under coarse chords that sag across it (foldsAcross).
    bool curved = false;
    std::shared_ptr<const BSplineDirect> direct;  // a B-spline face's direct evaluator (immutable, shared)
    CreaseLines creases;                          // the surface's crease lines (SurfaceEval::creaseLines)
  };
  // Before the first discretise(): every face's scale (from any thread, one call per face), then
  // scalesSet() once, from one thread.
  void setFaceScale(FaceId face, FaceScale scale) { faceScales_[face] = std::move(scale); }
  void scalesSet();

  // Discretises every non-degenerate edge for level k (after level k-1). Returns false if cancelled.
  bool discretise(int level, WorkerPool& pool, unsigned threads, const std::atomic<bool>* cancel);

  bool degenerated(EdgeId e) const { return info_[e].degenerated; }
  // The points of edge e at level k (discretise(k) has returned). Degenerate edges have none.
  const EdgePoints& points(EdgeId e, int level) const { return levels_[e][static_cast<std::size_t>(level)]; }
  double first(EdgeId e) const { return info_[e].first; }
  double last(EdgeId e) const { return info_[e].last; }
  const gp_Pnt& firstPoint(EdgeId e) const { return info_[e].p0; }
  const gp_Pnt& lastPoint(EdgeId e) const { return info_[e].p1; }

 private:
  // A face that uses the edge: its pcurve lets the discretisation keep the surface normals along each
  // segment within the angular tolerance (no interior point can fix a boundary segment whose ends'
  // normals differ too much).
  // The face also bounds how long a segment may be: a well-shaped triangle standing on it inside the
  // face must be within the tolerances, or the interior refinement can only add slivers along it.
  struct FaceUse {
    TopoDS_Face face;  // FORWARD
    FaceId id = 0;
    Pcurve pcurve;
    double first = 0, last = 0;  // pcurve range
    int side = 1;                // the face lies left (+1) or right (-1) of the pcurve, or both (0: seam)
    const FaceScale* scale = nullptr;  // faceScales_[id], set by scalesSet()
  };
  struct Info {
    double first = 0, last = 0;
    gp_Pnt p0, p1;  // vertex positions at first and last
    bool degenerated = false;
    bool straight = false;  // a line: one segment is exact
    bool closed = false;    // both ends are the same vertex
    bool sharesEnds = false;  // another edge joins the same two vertices
    bool broken = false;    // no usable curve: the chord between its vertices stands in for it
    std::vector<FaceUse> faces;  // at most two
    // A circular arc: the fewest segments each level needs (arcNeeds(), shared on a cone), and its
    // equal segments per level (arcSegments()), each level's a divisor of the next one's; empty
    // for other curves.
    std::vector<std::uint32_t> arcNeeds, arcSegments;
    double arcAngle = 0;  // how far the arc turns
    // A B-spline or Bezier curve that is a circular arc (circular_arc.h): its circle.
    std::optional<CircularArc> splineArc;
    // A non-periodic B-spline 3D curve, placed, evaluated directly (spline_curve.h); else null and
    // the discretisation asks OpenCASCADE's adaptor.
    std::shared_ptr<const SplineCurve<3>> spline;
  };
  // Fills levels_[e][level]; false, with the points half made, when `cancel` was raised meanwhile.
  bool discretiseEdge(EdgeId e, int level, const Level& tolerance, const std::atomic<bool>* cancel);
  static double pcurveParameter(const Info& info, const FaceUse& use, double t);
  double arcSagBeside(const std::vector<FaceUse>& uses);  // the most an arc's chords may sag
  // The tube radius of the used face if it is a torus or one in disguise (ring_angles.h), else 0;
  // found once per face (tubeRadius_, NaN until then; the constructor alone asks).
  double tubeRadius(const FaceUse& use);
  std::vector<double> tubeRadius_;
  void shareArcCountsOnCones();

  // Segment j of edge e (between its points j and j + 1) at the level at hand.
  struct SegmentId {
    EdgeId edge;
    std::uint32_t segment;
    bool operator<(const SegmentId& o) const { return edge != o.edge ? edge < o.edge : segment < o.segment; }
    bool operator==(const SegmentId& o) const { return edge == o.edge && segment == o.segment; }
  };
  // False when cancelled (the level's points are then half separated: discretise() runs again).
  bool separateCrossings(int level, WorkerPool& pool, unsigned threads, const std::atomic<bool>* cancel);
  void findCrossings(FaceId face, int level, std::vector<SegmentId>& out,
                     const std::atomic<bool>* cancel) const;

  const ModelImpl& model_;
  std::vector<Level> tolerances_;  // [level]
  std::vector<Info> info_;
  std::vector<std::vector<EdgePoints>> levels_;  // [edge][level], sized up front (no reallocation)
  std::vector<FaceScale> faceScales_;             // [face]
  std::vector<std::vector<std::pair<EdgeId, std::uint32_t>>> faceUses_;  // [face]: (edge, index in its faces)
};

}  // namespace cetview::brep
