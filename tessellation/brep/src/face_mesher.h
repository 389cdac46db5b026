// One face, coarse to fine, on its own CET triangulator (DESIGN.md "Data flow", steps 3-6).
//
// Level 0 builds the face domain: the loops of face_topology.h sampled at the shared edge points,
// scaled UV, segments recovered, outside flood-filled. Each later level replaces every boundary
// segment that its edge split by the chain of new points (Triangulator::replaceConstraint), splits
// the rows of degenerate edges (poles, apexes) to keep pace, then refines the interior until every
// triangle is within the level's tolerances. Vertices are appended to the FaceMesh as the
// triangulator creates them (output id = triangulator id + a base that only a rebuild moves), so
// nothing is ever rebuilt per level.
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "brep/tessellator.h"
#include "brepmesh_fallback.h"
#include "cet/triangulator.h"
#include "face_topology.h"
#include "surface_eval.h"
#include "ring_angles.h"
#include "torus_lattice.h"
#include "triangle_records.h"

namespace cetview::brep {

class EdgeTable;
class WorkSharing;

// Refinement (of edges and of triangles) aims below each tolerance by this factor: the samples see
// most, not all, of a segment's or triangle's deviation (a quadratic deviation peaks within ~15% of
// its largest sampled value).
constexpr double kDeviationMargin = 0.85;
// Where a triangle's deviation is computed exactly (planes, cylinders, spheres: see
// ElementaryDistance::triangleDeviation), or read at its peak from closed-form distances (cones and
// tori: deviation_peak.h), only rounding, the surface's terms beyond the quadratic and edge points a
// hair off the surface separate it from the measured one.
constexpr double kExactDeviationMargin = 0.98;

struct FaceMesherSettings {
  double finalChordal = 0;   // the fallback mesher's tolerance; UV gaps below a tenth of it close silently
  double finalAngle = 0;
  bool reversed = false;     // face orientation: normals and winding of the output flip
  // Vertices closer than this are one point (poles, singular rows of a B-spline, bridged UV gaps):
  // triangles with two of them have no area and are dropped from the output.
  double coincident = 0;
  // The run's idle workers, which a large refinement pass shares its measuring with (null: alone).
  // Meshes do not depend on it.
  WorkSharing* sharing = nullptr;
  bool trace = false;  // print the refinement's split decisions on stderr (traceFace)
  std::size_t maxRefinePoints = 0;  // MeshParams::maxPointsPerFaceLevel (0: refinePointBound's default)
};

// CETVIEW_DEBUG_REFINE=all traces every face's refinement, =N face N's alone (a debugging aid).
bool traceFace(FaceId face);

// The most points one level's refinement may add to a face that had `pointsBefore` points: the
// `requested` bound (MeshParams::maxPointsPerFaceLevel), or by default 256 times the points before,
// at least 250 thousand and at most a million.
std::size_t refinePointBound(std::size_t pointsBefore, std::size_t requested);

class FaceMesher {
 public:
  // `eval`: the face's surface evaluator if already made (null: the mesher makes its own).
  FaceMesher(FaceTopology topology, const FaceMesherSettings& settings, std::unique_ptr<SurfaceEval> eval = nullptr);

  // Advances to level k (the previous level is k-1, or none). Appends the new vertices to `mesh` and
  // pushes level k's index array. Returns kCancelled (nothing pushed) when cancel is raised.
  // A failure to build the domain on a coarse level (not `finalLevel`) defers CET to the next level.
  FaceStatus advance(int k, const Level& level, const EdgeTable& edges, FaceMesh& mesh, FaceReport& report,
                     const std::atomic<bool>* cancel, bool finalLevel);

  // In a face's reason: a coarse level showed the fallback mesh ("level 0 shows the fallback mesh: ...").
  static constexpr const char* kDeferredLevel = " shows the fallback mesh: ";
  // The same where the fallback failed as well ("level 0 shows no triangles: ...", "levels 0 to 4
  // show no triangles: ...").
  static constexpr const char* kEmptyLevel = " no triangles: ";

 private:
  struct Occurrence {
    std::size_t loop = 0, index = 0;  // position in topology_.loops
    // Triangulator ids of its points in increasing edge parameter (degenerate: pcurve order).
    std::vector<cet::VertexId> chain;
    bool forward = true;  // the loop runs along increasing parameter
  };

  // The (u, v) of a boundary point: the pcurve's at edge parameter t, moved to the foot of the edge
  // point p on the surface where the pcurve strays from p.
  gp_Pnt2d boundaryUV(const LoopEdge& le, double t, const gp_Pnt& p) const;
  // Builds the domain from level k's edge points. `cancel` is looked at every few thousand points
  // and segments: once raised, it returns false with `cancelled` set, the build half done
  // (abandonBuild() discards it).
  bool buildDomain(int k, const EdgeTable& edges, FaceMesh& mesh, std::string& problem,
                   const std::atomic<bool>* cancel, bool& cancelled);
  // buildDomain(); on a flat face (SurfaceEval::flat) whose domain fails in its plane, again in the
  // scaled UV plane, and the next level rebuilds it (flatRetry_), in the plane if it works there.
  // Edges leaving a vertex close together in 3D may have chords crossing there, split apart in UV
  // (the edge table discretises them in the scaled UV plane): such a face meshed in that plane
  // before flat faces, and fell back to BRepMesh in its own; a finer level's chords may not cross.
  bool buildDomainFlatOrScaled(int k, const EdgeTable& edges, FaceMesh& mesh, std::string& problem,
                               const std::atomic<bool>* cancel, bool& cancelled);
  // Drops a cancelled build: its vertices (appended from base_) and its triangulation. The next
  // advance() builds the domain again, as an uninterrupted build would have.
  FaceStatus abandonBuild(FaceMesh& mesh);
  // Empties the arrays kept per triangulator vertex and the boundary occurrences with their
  // refinement's progress (a build starts them afresh; a cancelled one drops them).
  void clearVertexData();
  // Moves the boundary to level k's edge points (new points split the constraint segments). The
  // cancel flag is read before each segment: once raised, it returns false with `cancelled` set,
  // its progress kept (boundaryProgress_) for the next call with the same level.
  bool refineBoundary(int k, const EdgeTable& edges, FaceMesh& mesh, std::string& problem,
                      const std::atomic<bool>* cancel, bool& cancelled);
  bool splitSegment(const Occurrence& occ, std::size_t o, std::vector<gp_Pnt2d>& uvs, std::vector<const gp_Pnt*>& ps,
                    std::vector<cet::VertexId>& chain, FaceMesh& mesh, std::string& problem);
  bool refinePoles(FaceMesh& mesh, std::string& problem);
  static constexpr int kMaxPoleSegments = 1024;
  static int poleSegments(double length, double typical);
  // Interior refinement of level `levelIndex` to its tolerances; false when cancelled. Stops (and
  // sets refinementStopped_) past refinePointBound() new points.
  bool refine(int levelIndex, const Level& level, FaceMesh& mesh, const std::atomic<bool>* cancel);
  // On a torus or a sphere: moves the split (u, v) of triangle t to the nearest lattice point (torus_lattice.h)
  // that still splits it (inside its circumcircle, in it or in a neighbour across a free edge),
  // keeps half a lattice step from the corners about it and is clear of the chords (true); else
  // leaves it (false).
  bool snapToLattice(cet::TriangleId t, double& u, double& v);
  // At the first refinement: the face's lattice if it is a torus or a sphere, or a free-form one in
  // disguise parametrized one angle per parameter (ring_angles.h).
  void makeLattice();
  // A lattice point in the face's parameters, with its row's step and the step between rows as
  // spans of u and of v there.
  struct LatticeCandidate {
    double u, v, stepU, stepV;
  };
  void latticePointsNear(double u, double v);  // fills latticeNear_
  std::unique_ptr<TorusLattice> lattice_;  // null off tori and spheres
  const RingAngles* ringAngles_ = nullptr;  // a disguised one's angles (eval_'s; its lattice is laid out in them)
  bool latticeMade_ = false;
  std::vector<LatticePoint> latticeRaw_;                       // the lattice's points, in its angles
  std::vector<LatticeCandidate> latticeNear_;                  // snapToLattice's candidates
  std::vector<std::pair<double, std::size_t>> latticeOrder_;   // and their order
  bool flatRetry_ = false;          // this level's domain failed in the flat plane: the next tries it again
  bool refinementStopped_ = false;  // a level's refinement did not converge: later levels keep its interior
  int refineLevel_ = -1;            // the level refine() last ran, and its triangulator's points before it
  std::size_t refineStart_ = 0;
  // Level index array: inside triangles minus those collapsed on one 3D point, oriented.
  std::vector<std::uint32_t> snapshot(const FaceMesh& mesh) const;
  // The face is meshed by BRepMesh (brepmesh_fallback.h) from now on. Cancelled while BRepMesh
  // runs, it returns kCancelled and the next advance() goes straight back to it (pendingFallback_).
  FaceStatus useFallback(std::string why, FaceMesh& mesh, FaceReport& report,
                         const std::atomic<bool>* cancel);
  std::string pendingFallback_;      // why, when a fallback was cancelled
  CancellableFallback fallbackJob_;  // BRepMesh for useFallback() and deferLevel()
  // A face with nothing to show (its surface has no area): every level is empty (kEmpty).
  FaceStatus leaveEmpty(const std::string& why, FaceMesh& mesh, FaceReport& report);
  bool areaChecked_ = false;  // SurfaceEval::collapsed() asked (on the first level)
  FaceStatus deferLevel(int k, std::string why, FaceMesh& mesh, FaceReport& report,
                        const std::atomic<bool>* cancel);
  std::vector<std::uint32_t> deferredIndices_;  // the fallback mesh shown by deferred coarse levels
  std::string pendingDefer_;                    // why, when making deferredIndices_ was cancelled
  std::string deferredFailure_;                 // why BRepMesh made no deferredIndices_ (it failed)
  // Consecutive levels deferred without a fallback mesh share one line of repairs_ ("levels 0 to 4
  // show no triangles: <the first one's cause>"): its index, and the run's first and last level.
  std::size_t emptyLine_ = 0;
  int emptyFirst_ = -1, emptyLast_ = -1;

  // Output bookkeeping: vertices the triangulator created since the last sync get their data.
  // Appends the output data of the next triangulator vertex: at (u, v), position p (an edge point)
  // or, when p is null, the surface point.
  void appendVertex(FaceMesh& mesh, double u, double v, const gp_Pnt* p);
  cet::Point2 scaled(double u, double v) const { return eval_.scaled(u, v); }
  // Measuring a pass's triangles. Each new triangle of a pass (in `measured_`, stamped in
  // measuredStamp_) is measured into its record, in parallel; an edge shared with a lower triangle of
  // the same pass takes that triangle's samples afterwards (finishTriangle), so records are exactly
  // those of measuring one triangle after the other in id order, on any number of threads.
  struct Corners {
    cet::VertexId v[3];
    gp_Pnt p[3];
    double u[3], w[3];
    bool collapsed = false;  // two corners on one 3D point
    // Two of them half a period or more apart in a periodic direction, with no boundary chord
    // between them: the triangle spans the seam, and the band it stands for is not covered.
    bool wraps = false;
    // Every pair of corners on one 3D point is a pair of pole vertices (singular_): the triangle
    // stands on a pole's row, and the sector behind it is the pole's fan (sample()).
    bool onPoleRow = true;
    // Such a triangle's regular corner's normal (evaluateTriangle sets it; sample() reads it).
    const gp_Dir* fanNormal = nullptr;
  };
  struct Pending {            // what evaluateTriangle leaves for finishTriangle
    double worst = -1, corresponding = -1;  // the interior samples' largest distances
    double edgeWorst[3] = {-1, -1, -1}, edgeCorresponding[3] = {-1, -1, -1};  // -1: constrained, or deferred
    double longest = 0;
    std::uint8_t deferred = 0;  // bit i: edge i waits for the lower triangle across it
  };
  Corners corners(cet::TriangleId t, const FaceMesh& mesh) const;
  gp_Pnt position(const FaceMesh& mesh, cet::VertexId v) const;  // triangulator vertex v's 3D point
  // Distance from the point of the flat triangle at barycentric b to the surface (and the
  // corresponding-point distance |S(uv) - M|; on elementary surfaces at the centroid only, else 0).
  double sample(const Corners& c, const double b[3], double& corresponding, bool centroid) const;
  // Worst samples of edge i: its midpoint (and quarter points on free-form surfaces).
  void sampleEdge(const Corners& c, int i, double& worst, double& corresponding) const;
  // Measures triangle t into r; chordal samples are skipped when angleSplit splits it anyway.
  void evaluateTriangle(cet::TriangleId t, const FaceMesh& mesh, const AngleSplit& angleSplit, int stamp,
                        TriangleRecord& r, Pending& pending) const;
  void finishTriangle(cet::TriangleId t, const FaceMesh& mesh, TriangleRecord& r, Pending& pending) const;
  // The record's deviation and worst sample from its samples (interior ones in `pending`); with
  // `c`, on cones and tori, also from a sample where the quadratic through its edges' middles peaks
  // (deviation_peak.h).
  void conclude(TriangleRecord& r, const Pending& pending, bool collapsed, const Corners* c) const;
  // The samples of edge i of t as the triangle across it measured them, if its record is current.
  bool edgeSamplesFromNeighbour(cet::TriangleId t, int i, float& deviation, float& corresponding) const;
  bool onChord(cet::TriangleId t) const;  // t has a constrained (boundary) edge
  // How the flat triangle (a, b, c) faces against its corners' surface normals: the cosine of its
  // normal with their sum (the smaller of those with the first-derivative normals and with the
  // output's normals, which poles have too); -2 where it has no area, no corner with a normal, or
  // an edge across a crease or fold of the surface (no one side to face).
  double facing(cet::VertexId a, cet::VertexId b, cet::VertexId c, const FaceMesh& mesh) const;
  // An edge of flipped triangle t whose flip (Triangulator::flipEdge) leaves both triangles of the
  // quadrilateral facing the surface's way (facing() at least kFoldCos), with no two of its corners'
  // normals opposed (a fold, where no flat triangle faces both ways), or -1. Such a flip puts the
  // orientation right without a point: where the surface's map from the scaled plane is far from
  // linear over the triangles (a sheet fanning from a pole corner), the Delaunay diagonal of a
  // quadrilateral may face away on the surface while the other diagonal faces right, and splits of
  // the flipped triangle made more such quadrilaterals beside it (a fuzzed plane's fan: 57893
  // triangles, 12334 flipped, within 5e-5 of the tolerance; now 83, none flipped). refine() asks
  // it for flipped triangles longer than the level's tolerance only, those split whatever the
  // chords' clearance: for smaller ones the changed meshes left more triangles flipped across folds
  // on A319's wing tips (14 on the final level instead of 10) and one on trj4.
  // Nor does it flip a quadrilateral that this level has flipped kMaxQuadFlips times already: where
  // the triangles' rules disagree (a triangle with a pole corner in line with the others is flipped
  // to refine() but not to facing()), two flips undid each other pass after pass and kept the splits
  // beside them waiting to the pass bound (a fuzzed face: 3700 passes of the same two flips, the
  // level left 6.2x over). Measured against the seven fuzz seeds and single faces: refusing to
  // restore any diagonal once flipped away left flipped triangles to split instead (38% more
  // degenerate triangles over the seeds; 4.9% with this bound), and making facing() agree with
  // refine() took one fuzzed face from 136k triangles to 501k.
  int repairingFlip(cet::TriangleId t, const FaceMesh& mesh) const;
  static constexpr int kMaxQuadFlips = 4;
  struct QuadKeyHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const {
      return std::hash<std::uint64_t>()(k.first * 0x9E3779B97F4A7C15ull ^ k.second);
    }
  };
  // Flips of each quadrilateral this level, keyed by its two diagonals (vertex pairs, in order).
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, int, QuadKeyHash> quadFlips_;
  // Flips this level that kept each edge (a, b) of the flipped triangle (a, b, c) (pairKey): a
  // triangle with a corner on a pole and its corners in line through it stays flipped (its facet
  // is noise) whatever its third corner, and its repairing flips, keeping the pole and one other
  // corner, walked a new quadrilateral each pass until the pass bound (a fuzzed face: 3800 passes
  // on a level). At most kMaxPivotFlips per edge: with 8,
  // flips refused elsewhere left their triangles to splits that cascaded (a fuzzed face's last
  // level: 76.9k triangles -> 501k, to the point bound).
  static constexpr int kMaxPivotFlips = 64;
  std::unordered_map<std::uint64_t, int> pivotFlips_;
  // And at most kMaxVertexPivotFlips this level with one vertex kept (the walk goes on with a new
  // second corner after each edge's bound: a fuzzed sheet's level walked 4000 flips around one
  // pole-row vertex, one a pass, to the pass bound).
  static constexpr int kMaxVertexPivotFlips = 512;
  std::unordered_map<cet::VertexId, int> vertexPivotFlips_;
  // Triangles (keyed by their vertices) whose split point this level merged with a vertex or was
  // rejected by the triangulation: not asked again. Asked again, such a split marked its corners
  // touched on every pass, so a neighbour waiting for its turn never had it, and the level ended
  // when no point went in: a fuzzed face kept a triangle 2.04x its level's tolerance so.
  std::unordered_set<std::pair<std::uint64_t, std::uint64_t>, QuadKeyHash> failedSplits_;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> splitKeys_;  // of splitTriangles_
  static std::pair<std::uint64_t, std::uint64_t> triangleKey(cet::VertexId a, cet::VertexId b,
                                                             cet::VertexId c) {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {std::uint64_t{a} << 32 | b, c};
  }
  static std::uint64_t pairKey(cet::VertexId a, cet::VertexId b) {
    return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
  }
  static std::pair<std::uint64_t, std::uint64_t> quadKey(cet::VertexId a0, cet::VertexId a1, cet::VertexId b0,
                                                         cet::VertexId b1) {
    const std::uint64_t x = pairKey(a0, a1), y = pairKey(b0, b1);
    return x < y ? std::make_pair(x, y) : std::make_pair(y, x);
  }
  // Whether t, with one corner at a pole, has each other corner at the far end of a boundary chord
  // from that pole or beside it where the side bulges out beyond the chord, no further in from the
  // chord than the side is out at the same fraction of it (or itself beyond). A triangle on the
  // chord from a point in the bulge is flipped, and a split of it (sliding along the edge it
  // bisects, standing on the chord as a facet that faces the surface's way) only put another point
  // in the bulge, nearer the side: a cascade along it (a fuzzed sheet: 13022 triangles, 4526
  // flipped). refine() does not split such a triangle as flipped, unless an edge flip puts it
  // right (repairingFlip).
  bool huggingPoleChord(cet::TriangleId t, const TriangleRecord& r, const FaceMesh& mesh) const;
  // Whether t's corners all lie, in scaled UV, within a band along one boundary chord's line (no
  // corner further from it than kAlongChordBand of t's longest edge, each projecting onto the chord),
  // each an end of the chord or off the boundary (a thin strip's triangles, their far corners on its
  // other side, lie in such a band too, and splits put them right: held back, 161 flipped
  // triangles on nist_ctc_04's coarse levels and 9 on Block's).
  // Such a sliver follows the boundary curve's bend, not the surface's: its facet faces either way
  // whatever the surface does, and bisecting a free edge only puts another point in the band, nearer
  // the line. A fuzzed sheet (a zigzag fanning from a pole, 885-long chord from it) took 24675
  // points on level 0 so, 25k of them within 1e-8 of that chord's line in UV, one split a pass
  // to the pass bound, and showed the stopped level's mesh on the finer ones (8.8x). refine() does
  // not split such a triangle as flipped.
  bool alongChord(cet::TriangleId t) const;
  // Whether t, its corners in line through a pole (TriangleRecord::kInLine), stands on a boundary
  // chord with an end at a pole or apex. Bisecting such a triangle only makes another on the same
  // chord with its apex nearer to it, in line again: no split puts it right (a fuzzed fan onto a
  // straight side took 66168 triangles, 23578 of no area, splitting them as flipped).
  bool inLineOnChordIntoPole(cet::TriangleId t, const TriangleRecord& r) const;
  // No corner of t has a first-derivative normal: the surface has no area there (collapsed onto a
  // curve or a point), and its triangles no orientation that a split could put right.
  bool allSingular(cet::TriangleId t) const;
  // Whether triangle t, with a corner at a pole and read too far from the surface (r), is within
  // `reachable` by the deviation measure itself (measure_impl.h).
  bool withinByTheMeasure(cet::TriangleId t, const FaceMesh& mesh, const TriangleRecord& r, double reachable) const;
  // Whether triangle t is within `bound` of the surface by the deviation measure (measure_impl.h);
  // false where the measure does not apply (a triangle wrapping around a periodic direction). The
  // reading stops at the first sample confirmed over the bound: a sample over it is read from two
  // grids over the triangle (2298 surface points), and reading all 13 made these calls a fifth of
  // Propeller's final level (18 of them, every one over).
  bool measuredWithin(cet::TriangleId t, const FaceMesh& mesh, double bound) const;
  // measuredWithin's surface, as measureFaces makes it (made on first use, by refine()'s one thread).
  mutable std::unique_ptr<SurfaceEval> judge_;
  // Whether a bend of the surface (a crease line, SurfaceEval::bendBetween) lies strictly between
  // (ua, va) and (ub, vb), in u or in v.
  bool bendBetween(double ua, double va, double ub, double vb) const;
  // Where the longest free edge of triangle t between regular corners crosses a bend: (u, v)
  // exactly on the line. False where no edge does. Not on a fold (a sheet turning back by more than
  // 120 degrees): there the points on the line and the splits of flipped triangles beside them
  // cascaded (a fuzzed sheet folded at two knots, seed 101 input 223: 165k -> 443k triangles).
  bool creasePoint(cet::TriangleId t, const FaceMesh& mesh, double& u, double& v) const;
  // Moves a split point (u, v) of triangle t onto a sharp knot's line (SurfaceEval::findSharpKnots)
  // or a bend's (SurfaceEval::bendBetween) that the triangle spans, where that line crosses t (see
  // refine()).
  void ontoCreaseLine(cet::TriangleId t, const FaceMesh& mesh, double& u, double& v) const;
  // Keeps a split point of triangle t off the boundary chords near it: the surface under a chord's UV
  // segment bulges away from the 3D chord within the tangent plane, and a point inside that bulge
  // lands on the wrong side of the chord in 3D: a flipped triangle nothing can repair. Moves (u, v)
  // towards the opposite corner when needed; false when no safe point was found. A split for the
  // angle (forAngle; angleEdge the edge to split, -1 for none) or of a flipped triangle (anyPoint;
  // angleEdge the edge it is bisected on) may also slide along that edge, and there come closer to a
  // chord (see clearOfChords).
  bool safeSplit(cet::TriangleId t, double& u, double& v, const FaceMesh& mesh, bool anyPoint, bool forAngle,
                 int angleEdge) const;
  void buildChords(const FaceMesh& mesh);
  // Whether vertex v is an end of a boundary chord (a constrained edge in its star).
  bool touchesChord(cet::VertexId v) const;
  // An angle split (u, v) of triangle t's edge `edge` that lands past the angle (minCos) from an
  // end on a boundary chord, where no point between them keeps the chords' clearance: that part of
  // the edge could never be split again. Moves (u, v) towards that end until it keeps the angle, if
  // the point there is clear. A narrow fillet under a long chord that sags below it (a torus tube
  // of 0.15 on a ring of 20 at 0.4): the first row came 20.1 and 22 degrees across from the chord's
  // ends, and every point between lay behind the chord's line in 3D or faced away from the surface
  // (21.03 degrees kept).
  void keepRowWithinAngleOfChord(cet::TriangleId t, int edge, const FaceMesh& mesh, double minCos, double& u,
                                 double& v) const;
  // Whether (u, v) keeps every nearby chord's clearance. mayStand: within a clearance, also a point
  // whose facet on the chord would face the surface's way (the clearance is cautious: it guards
  // points that split for the chordal tolerance or a fold, which come back until they find room).
  bool clearOfChords(double u, double v, bool mayStand) const;

  // A boundary chord (a constrained edge, domain on its left) and the clearance points must keep.
  struct Chord {
    gp_Pnt a;
    gp_Vec ab, n;
    cet::Point2 pa, pb;  // scaled UV
    double clearance = 0;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // guarded zone in scaled UV
    double near = 0;  // within this of the chord's ends' box the whole clearance is kept; beyond, its side
    std::int8_t pole = -1;  // which end is a pole or apex (0: a, 1: b), if one is
  };
  std::vector<Chord> chords_;
  std::vector<std::uint32_t> poleChords_;  // those with an end at a pole or apex
  // Chords by cell of a uniform scaled-UV grid: cell c's are gridChords_[gridStart_[c] ..
  // gridStart_[c + 1]); gridFill_ is buildChords' scratch.
  std::vector<std::uint32_t> gridStart_, gridChords_, gridFill_;
  double gridX0_ = 0, gridY0_ = 0, gridCellX_ = 1, gridCellY_ = 1;
  int gridNx_ = 0, gridNy_ = 0;

  FaceTopology topology_;
  FaceMesherSettings settings_;
  std::unique_ptr<SurfaceEval> ownEval_;
  const SurfaceEval& eval_;
  std::unique_ptr<cet::Triangulator> cdt_;
  std::uint32_t base_ = 0;  // output id of triangulator vertex 0
  // Fold vertices: points refine() puts on a fold of the surface's parametrisation, a line where
  // Su x Sv passes through zero and the normal reverses, or a turn as sharp (SurfaceEval::findFold). No one
  // normal is right there: each has two output vertices at the one point, out(v) with normal_[v] (the
  // normal's limit on one side) and `twin` with `other` (its limit on the other side), and each
  // triangle shows the one of its own side (sideNormal; snapshot).
  struct FoldVertex {
    gp_Dir other;
    std::uint32_t twin = 0;
  };
  std::unordered_map<cet::VertexId, FoldVertex> folds_;
  bool isFold(cet::VertexId v) const { return !folds_.empty() && folds_.count(v) != 0; }
  // Fold vertex v's normal (else normal_[v]) on the side of `side`: the limit nearer to it.
  const gp_Dir& sideNormal(cet::VertexId v, const gp_Vec& side) const;
  // The output vertex that corner v of a triangle whose surface normal is `side` shows.
  std::uint32_t shownVertex(cet::VertexId v, const gp_Vec& side) const;
  // The side whose normals a triangle's fold and crease corners show: its other corners' mean normal where
  // they agree (|sum| of at least half a unit), else the facet's normal (in the surface's natural
  // orientation).
  gp_Vec triangleSide(const cet::VertexId v[3], const gp_Pnt P[3]) const;
  // A twin is appended after the vertices so far, so the output ids of the triangulator vertices
  // appended later move on by one: from outShift_[i].first on, by outShift_[i].second.
  std::vector<std::pair<cet::VertexId, std::uint32_t>> outShift_;
  std::uint32_t out(cet::VertexId v) const {
    if (outShift_.empty() || v < outShift_.front().first) return base_ + v;
    const auto after = std::upper_bound(
        outShift_.begin(), outShift_.end(), v,
        [](cet::VertexId x, const std::pair<cet::VertexId, std::uint32_t>& e) { return x < e.first; });
    return base_ + v + std::prev(after)->second;
  }
  // Makes triangulator vertex v a fold vertex showing `before` itself, with a twin showing `after`.
  void appendFoldTwin(FaceMesh& mesh, cet::VertexId v, const gp_Dir& before, const gp_Dir& after);
  // Appends a twin of triangulator vertex v showing `other` (at the end of the mesh: the triangulator
  // vertices not appended yet come after it); returns its output id.
  std::uint32_t appendTwin(FaceMesh& mesh, cet::VertexId v, const gp_Dir& other);
  // Vertices without a first-derivative normal on a fold (a boundary point where the edge turns
  // back with the sheet): where a triangle's side faces away from one's normal, it gets a twin
  // showing the normal on that side (the surface's an eighth of the way to the triangle's centroid,
  // else the first regular one nearer),
  // which the triangles on that side show. For the output alone: the refinement treats the vertex
  // as before (made a fold vertex, poles' rules no longer held for it, and fuzzed faces with
  // singular boundary points cascaded: 369 -> 42419 triangles). Run before each snapshot.
  void twinSingularCorners(FaceMesh& mesh);
  std::unordered_map<cet::VertexId, FoldVertex> singularTwins_;
  // Vertices on a crease line (SurfaceEval::onCrease: a C0 knot, a seam where the surface is C0, a
  // fold of a periodic degree-1 surface): their normal is the limit from the knot span OpenCASCADE
  // evaluates, not necessarily from the side of the triangles that use them (a face bounded by a
  // crease showed the far side's normal all along that side: 1532 of a fuzzed face's 1623 triangles
  // faced against their corners' normals). For each triangle on one side of the creases through its
  // corners, the normal just inside it (on the way to its centroid, off the crease) is the one its
  // crease corners show: the vertex's own output normal where the vertex is new on this level and
  // no triangle has shown it yet, else a twin (a crease through the face: the triangles on each
  // side show their own). For the output, as singularTwins_ (the refinement leaves edges from a
  // crease to the chordal test); the side a triangle's fold corners take (triangleSide) leaves such
  // corners out too, on the levels after. Run before each snapshot.
  void showCreaseCorners(FaceMesh& mesh);
  struct CreaseCorner {
    gp_Dir shown;  // the normal out(v) shows
    std::uint32_t twin = kNoTwin;
    gp_Dir other;  // the twin's
  };
  static constexpr std::uint32_t kNoTwin = ~std::uint32_t{0};
  std::unordered_map<cet::VertexId, CreaseCorner> creaseCorners_;
  bool isCreaseCorner(cet::VertexId v) const {
    return !creaseCorners_.empty() && creaseCorners_.count(v) != 0;
  }
  // Where triangle t's free edge between regular corners crosses a fold (SurfaceEval::findFold; the
  // longest such edge): the fold point's (u, v) and the normals either side. False where none does.
  bool foldPoint(cet::TriangleId t, const FaceMesh& mesh, double angleRad, double& u, double& v,
                 gp_Dir& before, gp_Dir& after);
  // Directed edges (a << 32 | b) findFold found no fold on during this level (its answer depends
  // only on the ends, their normals and the level's angle): not asked again. A triangle left
  // unsplit beside terrain's rim asked about the same edges pass after pass (3572 searches of
  // 792 edges on its level 0, about a sixth of the level's time).
  std::unordered_set<std::uint64_t> noFold_;
  // The fold point near the middle of the edge between fold vertices a and b: on a segment across
  // the edge through its middle, as long as the edge (SurfaceEval::findFold). Splitting such an edge
  // at its middle, for the angle along the fold, made a plain vertex there whose normal is the
  // turn's middle, and the angle rule then halved edges towards it down to the minimum size.
  bool foldBetween(cet::VertexId a, cet::VertexId b, const FaceMesh& mesh, double angleRad, double& u,
                   double& v, gp_Dir& before, gp_Dir& after) const;
  // Fold points requested by a refinement pass (FoldSplit::point indexes points_).
  struct FoldSplit {
    std::size_t point = 0;
    gp_Dir before, after;
  };
  std::vector<FoldSplit> foldSplits_;
  bool foldsFailed_ = false;  // fold points left triangles beside them facing away: no more on this face
  // Fold points made on this face (since its domain was built), at most kFoldPointFloor and one in
  // kFoldPointShare of its points: a fold that one clean line of points settles takes a few (A319's
  // wing tips 4, Propeller's blade tips 1 or 2 per face). A bound on folds that do not settle: a
  // fuzzed sheet folded flat at a knot line, where each fold point made new edges across the fold
  // beside it, took 37320 triangles (226 without fold points), 7002 with this bound; what ended it
  // was the parameters' resolution (SurfaceEval::kFoldResolution).
  int foldPointCount_ = 0;
  static constexpr int kFoldPointFloor = 8;
  static constexpr std::size_t kFoldPointShare = 64;
  bool foldRoom() const {
    return foldPointCount_ < kFoldPointFloor + static_cast<int>(cdt_->vertexCount() / kFoldPointShare);
  }
  std::vector<gp_Dir> normal_;          // natural unit normal per triangulator vertex
  double uPeriod_ = 0, vPeriod_ = 0;  // the surface's periods (0: not periodic that way)
  std::vector<std::uint8_t> singular_;  // normal not defined by first derivatives (pole, apex)
  std::vector<float> offset_;  // distance from the surface (edge points of an edge that strays from it)
  bool strayReported_ = false;  // edges straying beyond the final deflection found (a repair note)
  std::vector<Occurrence> occurrences_;
  TriangleRecords records_;
  bool repaired_ = false;
  std::vector<std::string> repairs_;
  void noteCappedEdges(int k, const EdgeTable& edges);
  // repairs_ joined, each once; without the lines of levels deferred to the fallback on request.
  std::string repairsReason(bool withDeferredLevels = true) const;
  bool fallback_ = false;
  bool freeform_ = false;  // doubly curved (sphere, torus, B-spline, ...): sampled more densely
  bool exactDeviation_ = false;  // triangles' deviations in closed form, not sampled
  bool peakSampled_ = false;     // cones and tori: closed-form distances, and a sample at the peak
  double deviationMargin() const { return exactDeviation_ || peakSampled_ ? kExactDeviationMargin : kDeviationMargin; }
  FaceStatus fallbackStatus_ = FaceStatus::kFallback;
  int boundaryLevel_ = -1;  // the level whose edge points the triangulator's boundary holds
  // How far refineBoundary() got towards level `target` when the cancel flag stopped it: the next
  // call goes on from there, placing the same points in the same order as an uninterrupted call.
  struct BoundaryProgress {
    int target = -1;                   // the level being refined to (-1: none under way)
    std::size_t occurrence = 0;        // occurrences_ before it hold the target level's points
    std::size_t segment = 0;           // segments of that occurrence already split
    std::size_t next = 0;              // its first target-level edge point not yet placed
    std::vector<cet::VertexId> chain;  // its refined chain so far
  };
  BoundaryProgress boundaryProgress_;
  // Scratch.
  std::vector<cet::Point2> points_;
  std::vector<cet::VertexId> ids_;
  std::vector<cet::Point2> segmentPoints_;  // a boundary segment's new points (splitSegment)
  std::vector<cet::TriangleId> splitTriangles_;  // the triangle each point of points_ splits
  std::vector<std::pair<cet::TriangleId, int>> flips_;  // a pass's repairing flips (repairingFlip)
  std::vector<cet::TriangleId> work_, nextWork_;   // triangles a refinement pass looks at (after the first)
  std::vector<std::uint64_t> workBits_;            // work_ as a set, one bit per triangle
  std::vector<cet::InsertOutcome> outcomes_;
  std::vector<int> touched_;  // the refinement pass (stamp) that last split a triangle at this vertex
  std::vector<cet::TriangleId> visit_;     // a pass's triangles, in id order
  std::vector<cet::TriangleId> measured_;  // those of them without a current record
  std::vector<Pending> pending_;           // per measured_ entry
  std::vector<int> measuredStamp_;         // per triangle: the pass that measures it
  int passStamp_ = 0;         // counts passes over all levels
};

}  // namespace cetview::brep
