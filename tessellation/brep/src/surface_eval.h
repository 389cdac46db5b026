// Evaluation of one face's exact surface: points and normals for new vertices, the UV scaling of
// DESIGN.md step 3, and local orthogonal projection (the deviation measure). One instance per
// thread: the adaptor caches B-spline spans.
#pragma once

#include <atomic>
#include <cmath>
#include <utility>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include "bspline_direct.h"
#include "cet/types.h"
#include "elementary_distance.h"
#include "ring_angles.h"
#include "uv_axis.h"

namespace cetview::brep {

// First derivatives at (u, v) on a face whose parameter box ends at uMax and vMax: at or past those
// sides, a B-spline's derivatives are those of the knot span inside the box. At an interior knot
// the evaluators take the span above it, and where the surface is only C0 there (a crease, or a
// sheet folding back) a face ending at the knot got the normals of the surface beyond it: a face on
// a fold had its vertices on that side facing away (1024 flipped triangles on a level) and its edge
// there halved to a tenth of the tolerance. `direct`: the face's direct evaluator, if any.
void faceSideD1(const BSplineDirect* direct, const Adaptor3d_Surface& surface, double uMin, double uMax, double vMin,
                double vMax, double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv);

// A surface's crease lines (SurfaceEval::onCrease), as a value: for users that outlive the
// evaluator (the edge table keeps each face's while its evaluator goes with the face's mesher).
struct CreaseLines {
  std::vector<double> u, v;         // parameters of the lines, increasing
  double uPeriod = 0, vPeriod = 0;  // 0 unless periodic: the lines repeat with it
  double uBand = 0, vBand = 0;      // a point this near a line is on it
  bool empty() const { return u.empty() && v.empty(); }
  bool on(double pu, double pv) const;
};

class SurfaceEval {
 public:
  // `chordal` and `angleRad` (the finest tolerances the face will be meshed to; 0: unknown) set how
  // far the scaled UV stretches a surface that bends more one way than the other (see scaled()).
  explicit SurfaceEval(const TopoDS_Face& face, double chordal = 0, double angleRad = 0);

  const BRepAdaptor_Surface& adaptor() const { return surface_; }
  // A B-spline face's direct evaluator (immutable: may be shared with other threads), or null.
  const std::shared_ptr<const BSplineDirect>& direct() const { return direct_; }
  // True when point(), projectOnce(), blend() and crossesCrease() may be called from several threads
  // at once: planes, cylinders, cones, spheres and tori (closed forms) and B-splines evaluated
  // directly. Other surfaces go through OpenCASCADE's adaptor and its mutable caches.
  bool concurrentSafe() const { return concurrentSafe_; }

  // Point and unit natural normal (Su x Sv) at (u, v). Returns false where the normal is not
  // defined by first derivatives (poles, apexes, and every point of a degenerate edge's iso-line);
  // the normal then comes from higher derivatives or the neighbourhood, and may still be a poor
  // choice for angle tests.
  bool pointNormal(double u, double v, gp_Pnt& p, gp_Dir& n) const;
  gp_Pnt point(double u, double v) const;

  // Distance from m to the surface, by Gauss-Newton from (u, v) (updated to the foot point). Each
  // iterate is a surface point, so the result never underestimates the distance to the nearest
  // point found. maxIter bounds the derivative evaluations.
  // `start` (if given) receives |S(u, v) - m| at the starting (u, v): the corresponding-point distance.
  double project(const gp_Pnt& m, double& u, double& v, int maxIter, double* start = nullptr) const;
  // The same by Levenberg-Marquardt: each step is damped until it brings the point closer, so the
  // iterates descend to a local minimum of the distance even where Gauss-Newton overshoots (across a
  // pole or a fold of the parametrisation, where Su or Sv vanishes). Slower: for the measure only.
  // With a `box` (u0, u1, v0, v1), steps stop at it in every direction, periodic ones included, and
  // only there: beside a seam the surface turns sharply across, steps that crossed it ran into the
  // far side's spans and no damping brought them back; on a face reaching past its surface's
  // knots, steps stopped at the knots could not reach the extrapolated part (see measureDeviation).
  double projectDamped(const gp_Pnt& m, double& u, double& v, int maxIter, const double* box = nullptr) const;
  // The box around a triangle (corner parameters cu, cv) for projectDamped: in a periodic direction
  // the face's parameter box, in another the surface's bounds, each widened to the triangle's
  // corners (a face may reach past its surface's knots, where the surface is extrapolated; a foot
  // found further out would be on no part of the face).
  void triangleBox(const double cu[3], const double cv[3], double box[4]) const;
  // The refinement's estimate of the same: on planes, cylinders, cones, spheres and tori the exact
  // distance to the surface in closed form; otherwise Gauss-Newton that stops once a step moves the
  // foot by less than a tenth of the distance (usually one D1 and one D0 evaluation; more near poles).
  // A start point within `enough` of m ends it there: |S(u, v) - m| bounds the distance from above.
  double projectOnce(const gp_Pnt& m, double u, double v, double* start, double enough = 0) const;
  // Planes, cylinders, cones, spheres and tori: projectOnce() is the distance in closed form.
  bool closedFormDistance() const { return elementary_.valid(); }
  // Planes, cylinders and spheres: the largest distance from the flat triangle to the surface in
  // closed form (ElementaryDistance::triangleDeviation), not from samples.
  bool exactTriangleDeviation() const { return elementary_.hasTriangleDeviation(); }
  double triangleDeviation(const gp_Pnt& a, const gp_Pnt& b, const gp_Pnt& c, int& where) const {
    return elementary_.triangleDeviation(a.XYZ(), b.XYZ(), c.XYZ(), where);
  }

  // Scaled UV (DESIGN.md step 3): x = (u - u0) * su, y = (v - v0) * sv, where su, sv are the mean
  // 3D lengths of a unit step in u and v over the face, so the Delaunay criterion in (x, y) judges
  // shapes about as in 3D; on a surface that bends one way more than the other, the direction that
  // bends less is then shrunk by the ratio of the steps the tolerances allow each way. On a
  // B-spline surface whose knot spans run at very different 3D speeds (a span 1e-4 as long as its
  // neighbours carrying as much of the surface, say) one scale cannot serve them all: each span then
  // gets its own (x is piecewise linear in u, continuous, monotone). On a sphere y is piecewise
  // linear in v too, and the map conformal (buildConformalSphereAxes).
  // On a flat free-form face (flat()) the scaled plane is the face's own plane instead.
  cet::Point2 scaled(double u, double v) const {
    if (flat_) return flatScaled(u, v);
    return {uAxis_.map(u), vAxis_.map(v)};
  }
  void unscaled(const cet::Point2& q, double& u, double& v) const {
    if (flat_) return flatUnscaled(q, u, v);
    u = uAxis_.inverse(q.x), v = vAxis_.inverse(q.y);
  }
  double u0 = 0, v0 = 0, su = 1, sv = 1;  // the one scale (the mean over the face) in each direction
  // One scale per direction: straight lines in UV are straight in the scaled plane.
  bool linear() const { return !flat_ && uAxis_.slope.size() == 1 && vAxis_.slope.size() == 1; }
  // A B-spline face whose poles lie within kFlatThickness of the final chordal tolerance of one plane
  // (with positive weights the surface lies in their convex hull: it is that plane, for the
  // tolerance), within one period where periodic, whose parametrisation keeps its orientation over
  // the face's box (Su x Sv on one side of the plane, never of no area, at the points of a grid; a
  // pole row on the box's side excepted) and is uneven there (|Su| or |Sv| more than
  // kFlatSpeedSpread apart, as by a pole row): its scaled plane is the plane itself, x and y
  // the coordinates of S(u, v) in an orthonormal frame there, and unscaled() inverts that by Newton
  // steps. The triangulation is then one of the face's own outline: flat in 3D as it is in the
  // scaled plane, whatever the parametrisation does. Separate scales per direction cannot follow a
  // parametrisation squeezed unevenly by its weights (speeds 1e4 apart across a flat fuzzed sheet):
  // triangles well shaped in the scaled plane overlapped in 3D, and refining them made more (a
  // sheet flat within 2e-9 of its size: 375788 triangles on its first level, 53756 of them
  // flipped). The edge table keeps uAxis() and vAxis(): chords it separates in that plane may
  // cross in this one, and the mesher then builds that level in the scaled UV plane instead
  // (FaceMesher::buildDomainFlatOrScaled, useFlat()).
  bool flat() const { return flat_; }
  // A free-form face that is a torus or a sphere in disguise, parametrized one angle per parameter
  // (ring_angles.h): scaled as the torus or the sphere it is, and meshed on its lattice.
  const std::optional<RingAngles>& ringAngles() const { return ringAngles_; }
  double flatThickness() const { return flatThickness_; }  // the poles' largest distance from the plane
  // Makes the face flat() if it is, for that chordal tolerance (the constructor calls it with its
  // own). The measure calls it too: on a flat face the triangles are straight in the plane, where
  // their points' parameters are the start from which projections find the foot (from the UV
  // interpolation, on such a parametrisation, neither they nor grids over the triangle's UV did).
  void detectFlat(double chordal);
  // A mesher whose domain failed in the flat plane meshes that level in the scaled UV plane
  // (useFlat(false)) and tries the plane again on its next (useFlat(true): flat again if the face
  // was). The creases, bends and sharp knots stay cleared: the surface is a plane for the
  // tolerance, it turns nowhere, and the edge table was told so.
  void useFlat(bool on) { flat_ = on && flatFound_; }
  // Tests only: with it off no face is flat(). The tests of the scaled UV plane's handling of
  // fuzzed flat sheets fanning from a pole (meshed in their plane since) keep it that way.
  static void enableFlatFaces(bool on) { flatFacesEnabled_.store(on, std::memory_order_relaxed); }
  static constexpr double kFlatThickness = 0.01;
  static constexpr double kFlatSpeedSpread = 4;  // |Su| or |Sv| over the grid: the slowest to the fastest
  static constexpr int kFlatGrid = 16;  // cells each way of the orientation check and Newton's start points
  // The two directions' scalings (the edge discretisation works in their plane, also on a flat()
  // face, whose mesher works in the face's own).
  const UvAxis& uAxis() const { return uAxis_; }
  const UvAxis& vAxis() const { return vAxis_; }
  // The UV of the point with weights w[0..n) of the corners (u[i], v[i]) in the scaled plane, where
  // the triangulation's edges are straight (in UV too when linear()).
  void blend(int n, const double* w, const double* u, const double* v, double& ou, double& ov) const {
    ou = 0, ov = 0;
    if (linear()) {
      for (int i = 0; i < n; ++i) ou += w[i] * u[i], ov += w[i] * v[i];
      return;
    }
    cet::Point2 q;
    for (int i = 0; i < n; ++i) {
      const cet::Point2 p = scaled(u[i], v[i]);
      q.x += w[i] * p.x, q.y += w[i] * p.y;
    }
    if (flat_) return flatUnscaled(q, ou, ov, u, v, w, n);
    unscaled(q, ou, ov);
  }

  // True when a crease (a parameter line where the surface is not C1: a B-spline knot of full
  // multiplicity, the seam of a periodic surface that is C0 there, a C0 swept curve) lies between
  // (ua, va) and (ub, vb), or one of them is on it and the other is not. Normals on either side of a
  // crease differ by its angle however close the points are: no refinement can bring them together.
  bool crossesCrease(double ua, double va, double ub, double vb) const {
    return crosses(uCreases_, uPeriod_, ua, ub) || crosses(vCreases_, vPeriod_, va, vb);
  }
  // True when (u, v) lies on a crease line (within 1e-9 of the face's parameter box across it). The
  // normal there is a limit from one side, the one of the knot span OpenCASCADE evaluates, which
  // need not be the side the face's triangles lie on (FaceMesher::showCreaseCorners).
  bool onCrease(double u, double v) const {
    return near(uCreases_, uPeriod_, u, 1e-9 * (uMax - uMin)) ||
           near(vCreases_, vPeriod_, v, 1e-9 * (vMax - vMin));
  }
  friend struct CreaseLines;
  bool hasCreases() const { return !uCreases_.empty() || !vCreases_.empty(); }
  CreaseLines creaseLines() const {
    return {uCreases_, vCreases_, uPeriod_, vPeriod_, 1e-9 * (uMax - uMin), 1e-9 * (vMax - vMin)};
  }
  // A sharp knot (findSharpKnots: a crease where the surface is smooth but turns within a band
  // narrower than any split) strictly between a and b (in u when uDir, else v; a < b), the one
  // nearest `near`; false when there is none.
  bool sharpKnotBetween(bool uDir, double a, double b, double near, double& knot) const;
  // A bend (a crease line found by keepTurningBreaks where the normal turns by at most 120 degrees
  // at every sample: a knot of full multiplicity, a C0 seam; not a sharp knot, a fold, or a line
  // kept for want of a normal along it) strictly between a and b (in u when uDir, else v; a < b;
  // off both by more than onCrease's band), in the period that holds a and b; false when none.
  bool bendBetween(bool uDir, double a, double b, double& line) const;
  // True when the unit normal jumps on the UV segment from (ua, va) to (ub, vb), whose ends' normals
  // na and nb oppose (a negative dot product): bisecting towards the half that turns further, the
  // turn stays above 90 degrees down to 2^-kJumpBisections of the segment. A parametrisation that
  // folds its sheet over (Su x Sv through zero and back: a wing tip closed flat, a blade tip pinched)
  // flips the normal so, and no refinement brings the two sides' normals together, as across a
  // crease; a surface that merely bends divides its turn between the halves within a few steps.
  // (A surface bending by 90 degrees within 2^-24 of an edge's length is taken for a jump too.)
  // False where a pole lies between. Thread-safe where concurrentSafe().
  bool normalJumps(double ua, double va, double ub, double vb, const gp_Dir& na, const gp_Dir& nb) const;
  static constexpr int kJumpBisections = 24;
  // Whether the normal reverses, on the UV segment from (ua, va) to (ub, vb) whose ends' normals na
  // and nb oppose, within an eighth of the segment (2^-kFoldReach) about one point where the
  // parametrisation folds: Su x Sv through zero, or near it (A319's wing tip turns over within 0.01
  // of its 3-unit triangles, Su and Sv 0.005 degrees from parallel there; Propeller's blade tips). `at` is
  // the middle of the turn (the segment's parameter, 0 at a), where the normal is as near to na as to nb;
  // `before` and `after` the normals either side of it between which the turn is complete, up to
  // angleRad. False where the turn spreads wider (the surface bends) or no such point is found.
  bool findFold(double ua, double va, double ub, double vb, const gp_Dir& na, const gp_Dir& nb,
                double angleRad, double& at, gp_Dir& before, gp_Dir& after) const;
  static constexpr int kFoldBisections = 30;
  static constexpr int kFoldProbe = 12;      // bisections before asking whether it is a fold (foldAt)
  static constexpr double kFoldSine = 0.1;   // a fold: Su and Sv within 6 degrees of parallel at the turn,
  static constexpr double kFoldArea = 0.05;  // or |Su x Sv| below this fraction of the larger of the ends'

  static constexpr int kFoldReach = 3;
  static constexpr double kSettledRad = 0.5 * M_PI / 180;
  // A segment shorter than this times its largest coordinate is not searched: its 2^-kFoldBisections
  // steps would come within a few units of rounding of the coordinates.
  static constexpr double kFoldResolution = 1e-6;
  // Whether the singular point (u, v) lies on a line of the parameters that collapses to one point
  // (a pinch: a pole's row, a ruled sheet whose rows cross) rather than on a fold. The line runs
  // along the kernel of the derivative (the (u, v) direction it maps to nothing) at a pinch and
  // across it at a fold: the area element (|Su x Sv|, signed by `side`) stays near zero a step along
  // the kernel and grows a step across it at a pinch, and the other way round at a fold. The step
  // is 1e-3 of (du, dv)'s length. And the line collapses: the derivative along the kernel is below
  // kCollapsed of the one across it (Propeller's blade tips fold along a line of the kernel, but
  // one that runs along the tip at 0.015 of the speed across: their fold points are apart). Fold
  // points on a pinch would all be one 3D point, no triangle between two of them with area (a
  // ruled sheet took 864 of them on its first level).
  bool pinches(double u, double v, double du, double dv, const gp_Vec& side) const;
  static constexpr double kPinch = 0.1;
  static constexpr double kCollapsed = 1e-4;

  double uMin = 0, uMax = 0, vMin = 0, vMax = 0;  // the face's parameter box (from its pcurves)

  // True when the surface has no area over the face's parameter box: it collapses onto a curve or a
  // point (every row of a B-spline's poles one point, say). The largest |Su x Sv| on a 17x17 grid
  // times the box's (u, v) area is then rounding noise against the square of the face's 3D extent
  // (a face L long and w wide reads about w / L), or makes the face narrower than kNoWidth (noise
  // in a derivative stretched over a long parameter range: a fuzzed patch extrapolated 53 units
  // below its knots read a width of 3e-12 over 0.017). Such a face has nothing to show, and its (u, v)
  // maps to 3D too poorly for any mesher to work in: refinement chases noise normals (a B-spline
  // collapsed onto a segment took 225k zero-area triangles in 3 s at 0.1%). False for a box
  // without area: the face's boundary encloses none, whatever the surface (the domain says so).
  bool collapsed() const;

 private:
  // Whether the parametrisation folds at (u, v), on the segment from (ua, va) to (ub, vb) across the
  // fold (findFold's test).
  bool foldAt(double u, double v, double ua, double va, double ub, double vb) const;
  // The unit (u, v) direction that the derivative at (u, v) maps nearest to zero (the smaller
  // eigenvector of the Gram matrix of Su and Sv), and the ratio of its image's length to the
  // largest image of a unit direction. False where the derivative vanishes.
  bool kernel(double u, double v, double& ku, double& kv, double* smallerOverLarger = nullptr) const;
  // pointNormal's first-derivative normal; false (n unset) where it is not defined.
  bool regularNormal(double u, double v, gp_Pnt& p, gp_Dir& n) const;
  double projectFrom(const gp_Pnt& m, double& u, double& v, int maxIter, double* start, bool& clamped,
                     double settle = 1e-3, double enough = 0) const;

  static bool crosses(const std::vector<double>& creases, double period, double a, double b);
  static bool near(const std::vector<double>& creases, double period, double x, double band);

  // The iso-lines of the face's degenerate edges (one 3D point each). A B-spline's degenerate row is
  // often not collapsed exactly: its points lie a micron apart, its first derivatives are small but
  // not noise, and the normal they give swings with the parameter along the row (measured: 80 to 150
  // degrees from the normals a hundredth of the face away). Nor is its pcurve always exactly an
  // iso-line: trj4's face 404 has one whose ends lie 4e-9 apart across it.
  struct DegenerateRow {
    bool uConstant = false;  // u = value (else v = value)
    double value = 0;
    double tolerance = 0;  // how far across it a point still lies on the row
  };
  void findDegenerateRows();
  bool onDegenerateRow(double u, double v) const;
  std::vector<DegenerateRow> degenerateRows_;

  using Axis = UvAxis;
  // Per-span scales of a B-spline direction where its spans' 3D speeds differ by more than 4x.
  // A face reaching past the surface's knots (its pcurves leave the surface's range) lies there on
  // OCCT's extension of the end span, which may run at any speed: a rational patch whose first v
  // span is 1e-6 long extends as a curve (the extension's |Sv| falls from 2.6e4 to 1e-8 within
  // 0.02 of v), while the end span's scale carried on made the face's 0.24 of v past the knots
  // 100000 times as tall in the scaled plane as the rest of it. Past the knots, bands halving towards
  // the end knot (kReachBands at most) each take the 3D length their chords cover.
  static constexpr int kReachBands = 40;
  // Past the knots by less than this share of the end span, the extension runs at the span's own
  // speed (and rounding in the pcurves' boxes reaches 1e-9 past them on sample models).
  static constexpr double kReachMargin = 0.01;
  // Spans whose speed differs by more than kUnevenSpanSpread between its samples (at a sixth, the
  // middle and five sixths) and, just inside an end, falls kSlowEndRatio below the span's mean,
  // to within kUnevenSpanSpread of the mean speed of the covered span across that end's knot, and
  // there varies by no more than kUnevenSpanSpread across the face, go to `uneven` for
  // divideUnevenSpans(); so do those whose speed rises far above the mean by an end (kFastEndRatio).
  void buildAxis(bool uDir, Axis& axis, std::vector<std::pair<double, double>>& uneven) const;
  // One scale per span is too coarse where the speed changes by orders of magnitude inside a span: a
  // fuzzed B-spline's last v span, 2.6e-6 wide after one 0.56 wide, joins it C2, its |Sv| rising
  // from 2.5e4 at the knot to 5.1e9 at the end; at its mean scale, triangles shaped well in the
  // scaled plane lay flat in 3D along the knot (728 flipped on the last level). Such spans are
  // halved (kUnevenSpanDepth times at most) until the speed at a sixth, the middle and five sixths
  // of each piece is within kEvenPieceSpread, each piece scaled by its mean 3D chord (past
  // kMaxPiecesPerSpan pieces the span keeps its scale). Not beside a
  // sharp knot, which the mesher takes as a crease (dividing the fast span there, and spans whose
  // speed varies less, left more flipped triangles on the fuzzed faces the tests keep). After
  // findSharpKnots(), which compares the spans' own means.
  static constexpr double kUnevenSpanSpread = 4;
  static constexpr double kSlowEndRatio = 100;
  // A span whose speed just inside an end is more than kFastEndRatio times its mean goes to
  // `uneven` whatever the span across the knot: at the span's mean scale the surface by that end is
  // squeezed into a sliver of the scaled plane (a fuzzed rational patch, weights 0.001 to 38, whose
  // first u span's speed rises from 4e-4 to 1000 within its last thousandth: most of the face in 3D
  // within 0.002 of its u, where triangles well shaped in the scaled plane lie flipped in 3D,
  // 171319 triangles, 43841 flipped on level 0). Only where the end's speed, s times faster along
  // the fastest of the five lines across the face than along the slowest, is more than s^2 times
  // the span's mean: the pieces' scales, the five lines' mean, are then nearer every line's speed
  // than the span's one scale is (a flat sheet squeezed 70x unevenly across its fast end keeps it).
  static constexpr double kFastEndRatio = 100;
  static constexpr double kEvenPieceSpread = 2;
  static constexpr int kUnevenSpanDepth = 16;
  static constexpr std::size_t kMaxPiecesPerSpan = 64;
  // |Su| at (t, w) (uDir) or |Sv| at (w, t); and its mean over five lines w across the face's box
  // (`spread`, if given: the fastest of the five over the slowest).
  double speedAlong(bool uDir, double t, double w) const;
  double meanSpeedAcross(bool uDir, double t, double* spread = nullptr) const;
  void divideUnevenSpans(bool uDir, const std::vector<std::pair<double, double>>& uneven,
                         const std::vector<double>& sharpKnots, Axis& axis) const;
  // Knots of a B-spline direction (scaled by `axis`) that act as creases although the surface is C1
  // or smoother there: beside a span kSharpKnotSpeedRatio times faster than its neighbour, the
  // normal turns by more than angleRad within `reach` (3D) of the knot line. The turn is real, but
  // packed into a band narrower than any split the mesher makes (a fuzzed band whose last v span is
  // 2e-9 wide against 0.002 for the one before: the normal turns 35 degrees within 1e-12 in v, 1e-5
  // in 3D); angle splits crept towards such a knot and left slivers along it, flipped (6.8k on one
  // face). Knots that are creases already (not C1) are left out. Appended to `out`; the mesher also
  // puts its deviation splits beside such a knot onto its line (FaceMesher::ontoCreaseLine).
  static constexpr double kSharpKnotSpeedRatio = 100;
  // Of a direction's C1 breaks (`breaks`, increasing), keeps those where the normal turns across
  // the line by more than kCreaseTurnRad somewhere over the face's box (its limits from either
  // side, at samples along the line); a line with no normal at any sample, or where the speed
  // across it jumps as beside a sharp knot, stays a crease too. A break of the parametrisation
  // alone (a knot of full multiplicity where the surface is tangent-continuous: the STEP and IGES
  // B-splines pieced from Bezier patches) is no crease: the normal is continuous there, and the
  // angle test must hold across it (taken for creases, such lines on hammer, linkrods and r0901
  // were exempt from it, and edges across them turned by up to 94 degrees). Fills uBends_, vBends_.
  static constexpr double kCreaseTurnRad = 0.5 * M_PI / 180;
  static constexpr int kCreaseSamples = 17;
  static constexpr std::size_t kCreaseSampleBudget = 20000;
  static constexpr double kNoNormalSine = 1e-6;      // |Su x Sv| below this share of |Su| |Sv|: no normal
  static constexpr double kFoldingCreaseCos = -0.5;  // a turn past 120 degrees: the sheet folds back
  void keepTurningBreaks(bool uDir, std::vector<double>& breaks);
  void findSharpKnots(bool uDir, const Axis& axis, double reach, double angleRad, std::vector<double>& out) const;
  // A sphere's scaled UV is conformal: x = r u and y = r ln tan(pi/4 + v/2) (Mercator), piecewise
  // linear in spans of latitude across the face (the scale changing by kConformalSpanChange at most
  // in each, at most kConformalSpanRad long: 441 spans from pole to pole) and capped
  // kConformalCapRad from the equator (the pole rows would run off to infinity). The Delaunay
  // criterion in (x, y) then judges shapes as on the sphere at every latitude; with one scale each
  // way (the mean over the face) triangles near the poles were squeezed across the meridians and
  // near the equator stretched along them: a whole sphere of radius 10 at 0.1% took 2984 triangles
  // (BRepMesh 2836), now 2602, and CylinderHead's hemispherical pocket 1140 -> 996. su and sv
  // keep the mean 3D speeds (the edge table's estimate of the face's extent).
  static constexpr double kConformalSpanChange = 0.02;
  static constexpr double kConformalSpanRad = 5 * M_PI / 180;
  static constexpr double kConformalCapRad = 88 * M_PI / 180;
  void buildConformalSphereAxes();
  // The same for a sphere in disguise, through its angles: x along the ring r times the angle
  // round the axis, y the conformal map of the latitude, each piecewise linear over its table.
  void buildConformalDisguisedSphereAxes();
  std::optional<RingAngles> ringAngles_;
  Axis uAxis_, vAxis_;

  // The flat face's plane (flat()).
  void findFlatPlane(double chordal);
  cet::Point2 flatScaled(double u, double v) const {
    const gp_XYZ d = point(u, v).XYZ() - flatOrigin_;
    // Rounding noise next to the origin (1e-52 at a point across from it) is zero: the
    // triangulator takes no coordinates that small.
    auto coordinate = [this](double c) { return std::abs(c) > 1e-30 * flatSize_ ? c : 0.0; };
    return {coordinate(d.Dot(flatX_)), coordinate(d.Dot(flatY_))};
  }
  // (u, v) with flatScaled(u, v) = q, by damped Newton steps: from the UV blend of corners (bu, bv)
  // with weights bw when given (n of them), then from each of those corners; else from the scaled
  // axes' inverse; and where those fall short, from the nearest grid point. The closest found.
  void flatUnscaled(const cet::Point2& q, double& u, double& v, const double* bu = nullptr,
                    const double* bv = nullptr, const double* bw = nullptr, int n = 0) const;
  // Newton steps from (u, v) towards flatScaled(u, v) = q, each halved until it brings the point
  // closer; (u, v) is left at the closest, and the distance left returned.
  double flatNewton(const cet::Point2& q, double& u, double& v) const;
  static constexpr int kFlatNewtonSteps = 50;
  bool flat_ = false;
  bool flatFound_ = false;  // the plane was found (flat_ is whether it is in use)
  static inline std::atomic<bool> flatFacesEnabled_{true};
  gp_XYZ flatOrigin_, flatX_, flatY_;
  double flatSize_ = 0;                // the face's extent in the plane
  double flatThickness_ = 0;
  std::vector<cet::Point2> flatGrid_;  // flatScaled at (kFlatGrid + 1)^2 points of the face's box

  // Evaluation: B-spline faces go to the direct evaluator (bspline_direct.h) for every point; it
  // keeps no state, so one SurfaceEval of such a face serves several threads at once (see
  // concurrentSafe()), and a point's value does not depend on which points came before it.
  void d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const;
  std::shared_ptr<const BSplineDirect> direct_;

  BRepAdaptor_Surface surface_;
  ElementaryDistance elementary_;  // planes, cylinders, cones, spheres, tori
  TopoDS_Face face_;
  mutable Handle(Geom_Surface) geom_;  // with the face's location applied, made when first needed (normals at poles)
  bool uPeriodic_ = false, vPeriodic_ = false;
  bool concurrentSafe_ = false;
  double su0_ = 0, su1_ = 0, sv0_ = 0, sv1_ = 0;  // the surface's own parameter bounds
  // How far the face's pcurves reach in (u, v), not cut to the surface's range as uMin... are.
  double reachU0_ = 0, reachU1_ = 0, reachV0_ = 0, reachV1_ = 0;
  double meanLu_ = 0, meanLv_ = 0;                 // mean |Su|, |Sv| over the face
  // The largest |Su x Sv| times the box's (u, v) area against the face's 3D extent squared, below
  // which the surface has no area; and that ratio on the constructor's 5x5 grid (collapsed() looks
  // closer only when it is small).
  static constexpr double kNoArea = 1e-10;
  static constexpr double kNoWidth = 1e-9;  // model units: a hundredth of Precision::Confusion()
  double gridArea_ = 0;
  std::vector<double> uCreases_, vCreases_;        // parameters of the crease lines, increasing
  std::vector<double> uSharpKnots_, vSharpKnots_;  // those of them that are sharp knots, increasing
  std::vector<double> uBends_, vBends_;            // those of them that are bends (bendBetween), increasing
  double uPeriod_ = 0, vPeriod_ = 0;               // 0 unless periodic: creases repeat with it
};

}  // namespace cetview::brep
