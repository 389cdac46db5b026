// Edge discretisation by recursive subdivision with the two criteria of Laug & Borouchaki (2016,
// "Discrete CAD model for visualization and meshing", section 2.1): proximity (chordal distance of
// the curve to each segment, sampled at every eighth, and for a rational curve with uneven weights
// bounded by its control points: curve_hull.h) and regularity (turn angle between the
// tangents at a segment's ends, and between each tangent and the chord), plus the turn of the surface
// normals of each face along the segment. Level k subdivides the
// segments of level k-1 that fail the tolerances of level k, so levels are nested.
#include "edge_table.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>
#include <utility>

#include <BRepAdaptor_Curve.hxx>
#include <gp_Pnt2d.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "circular_arc.h"
#include "curve_hull.h"
#include "curve_poles.h"
#include "facet_rules.h"
#include "model_impl.h"
#include "ring_angles.h"
#include "surface_eval.h"

namespace cetview::brep {
namespace {

double distanceToSegment(const gp_Pnt& p, const gp_Pnt& a, const gp_Pnt& b) {
  const gp_Vec ab(a, b), ap(a, p);
  const double len2 = ab.SquareMagnitude();
  if (len2 <= 0) return ap.Magnitude();
  const double s = std::clamp(ap.Dot(ab) / len2, 0.0, 1.0);
  return gp_Vec(a.XYZ() + s * ab.XYZ(), p.XYZ()).Magnitude();
}

double angleBetween(const gp_Vec& a, const gp_Vec& b) {
  const double ma = a.Magnitude(), mb = b.Magnitude();
  if (ma <= 1e-300 || mb <= 1e-300) return 0.0;  // no tangent at a singular point: no angular claim
  return std::acos(std::clamp(a.Dot(b) / (ma * mb), -1.0, 1.0));
}

constexpr int kMaxDepth = 24;  // 2^24 segments per coarse segment: beyond any sane tolerance

// Height over length of the triangle that must stand on each segment within the tolerances: a
// right isosceles one (half its base high, angles 45-90-45), not an equilateral one (0.866). Where
// a face bends across an edge the refinement puts its first row of points closer to the boundary
// than the segments are long, with well-shaped triangles still; asking room for equilateral ones
// split such edges up to 4 times finer than the face needed (Propeller 12136 -> 7968 triangles,
// 2.5% fewer over the bench's models; 0.35 and 0.65 both did worse).
constexpr double kStandingHeight = 0.5;
// The lowest of the triangles standing on a segment whose normals are checked too (heights halve
// from kStandingHeight): 4 times as long as high. Down to 1/16 split edges beside fillets and gave
// 7% more triangles over the bench.
constexpr double kLowestStanding = 0.25;
// Where the tall standing triangle may miss the angle (see standing() in discretiseEdge): by at
// most this factor, by at most this angle (radians, 45 degrees), and where the surface under the
// segment's UV chord lies within this fraction of its length from the 3D chord (hugsChord).
constexpr double kSlenderSpread = 1.5;
constexpr double kSlenderMaxAngle = M_PI / 4;
constexpr double kSlenderBulge = kLowestStanding / 4;
// How far behind a segment's chord (a fraction of its length, in the plane of its mean normal) the
// face may reach before the segment is halved (curlsBehind in discretiseEdge): past rounding noise
// on flat strips (1e-15) and CrankArm's pinched B-spline corner (0.002), below the curled corner
// blends of Top and trj4 (0.037).
constexpr double kCurlBehind = 1.0 / 64;

// The fewest equal segments of a circular arc (radius r, angle theta) that meet a level's criteria
// in discretiseEdge(): the sagitta within the chordal tolerance (and within maxSag: see
// arcSagBeside()) and the tangent turn within the angle, which is not asked of chords shorter than
// the angle criteria's minimum size.
std::uint32_t fewestArcSegments(double r, double theta, const Level& tol, double maxSag) {
  constexpr double kBelow = 1 - 1e-9;  // rounding must not leave a segment a hair over
  const double bySag = 2 * std::acos(std::clamp(1 - std::min(tol.chordal, maxSag) / r, -1.0, 1.0)) * kBelow;
  double n = std::ceil(theta / std::max(bySag, 1e-9));
  const double byAngle = tol.angleRad * kBelow;
  // More segments than this have chords shorter than the minimum size (0.1 of the chordal).
  const double minChord = 2 * std::asin(std::min(1.0, 0.1 * tol.chordal / (2 * r)));
  const double shortest = minChord > 0 ? std::floor(theta / minChord) : HUGE_VAL;
  n = std::max(n, std::min(std::ceil(theta / byAngle), shortest));
  return static_cast<std::uint32_t>(std::min(n, 1e7));
}

// m 2^j with m at most 7: the counts level-by-level halving reaches from a small first count.
bool halvingCount(std::uint32_t n) {
  while (n % 2 == 0) n /= 2;
  return n <= 7;
}

// Equal segments of a circular arc per level, from the fewest each level needs: the last level has
// at most about 14% more segments than it needs (the next count of the form m 2^j, m <= 7), and
// each coarser level has half of the next one's where that is still enough for it, else as many,
// so each level's points are among the next one's. Halving the segments level by level from two
// or three instead ends anywhere between the fewest and twice as many (a circle that needs 77 got
// 96). Empty when the arc would need absurdly many.
std::vector<std::uint32_t> arcSegments(const std::vector<std::uint32_t>& need) {
  if (need.empty() || need.back() > 1000000) return {};
  std::vector<std::uint32_t> out(need.size());
  std::uint32_t n = need.back();
  while (!halvingCount(n)) ++n;
  out.back() = n;
  for (std::size_t k = need.size() - 1; k-- > 0;) {
    const std::uint32_t next = out[k + 1];
    out[k] = next % 2 == 0 && next / 2 >= need[k] ? next / 2 : next;
  }
  return out;
}

// The fewest segments of each level for an arc of radius r and angle theta (a closed edge must be
// a polygon: at least 3; maxSag: see arcSagBeside()); empty if not a usable arc.
std::vector<std::uint32_t> arcNeeds(double r, double theta, bool closed, double maxSag,
                                    const std::vector<Level>& tolerances) {
  if (!(r > 0) || !(theta > 0)) return {};
  const std::uint32_t least = closed ? 3 : 2;
  std::vector<std::uint32_t> need(tolerances.size());
  for (std::size_t k = 0; k < tolerances.size(); ++k)
    need[k] = std::max(least, fewestArcSegments(r, theta, tolerances[k], maxSag));
  return need;
}

// The points of `previous` (increasing, from first to last; may be empty) and those dividing an
// arc into n equal segments, in increasing order: point i at parameterAt(i), about `step` apart
// in parameter; one within a quarter step of a previous one is left out (the previous ones must
// stay: nested levels).
template <class ParameterAt>
std::vector<double> withEqualSegments(const std::vector<double>& previous, std::uint32_t n, double step,
                                      ParameterAt parameterAt) {
  std::vector<double> out;
  out.reserve(previous.size() + n + 1);
  std::size_t j = 0;
  for (std::uint32_t i = 0; i <= n; ++i) {
    const double t = parameterAt(i);
    while (j < previous.size() && previous[j] < t - 0.25 * step) out.push_back(previous[j++]);
    if (j < previous.size() && previous[j] <= t + 0.25 * step) continue;  // the previous point stands in
    out.push_back(t);
  }
  while (j < previous.size()) out.push_back(previous[j++]);
  return out;
}

// A line, or a B-spline or Bezier curve whose poles all lie on the chord between the edge's ends
// (the curve stays within their hull): a natural-bounds B-spline face's straight sides, which
// OpenCASCADE writes as degree-1 B-splines.
bool isStraight(const BRepAdaptor_Curve& curve, double first, double last) {
  if (curve.GetType() == GeomAbs_Line) return true;
  std::vector<gp_Pnt> poles;
  if (!hullPoints(curve, first, last, poles)) return false;
  const gp_Pnt a = curve.Value(first), b = curve.Value(last);
  const gp_Vec chord(a, b);
  const double length = chord.Magnitude();
  if (!(length > 0)) return false;
  const double tolerance = 1e-9 * length;
  for (const gp_Pnt& p : poles) {
    const gp_Vec ap(a, p);
    const double along = ap.Dot(chord) / length;
    if (along < -tolerance || along > length + tolerance) return false;
    if (ap.Crossed(chord).Magnitude() / length > tolerance) return false;
  }
  return true;
}

}  // namespace

EdgeTable::EdgeTable(const ModelImpl& model, std::vector<Level> tolerances)
    : model_(model), tolerances_(std::move(tolerances)) {
  const std::size_t levelCount = tolerances_.size();
  const std::size_t n = model.edgeShapes.size();
  info_.resize(n);
  levels_.resize(n);
  faceScales_.resize(model.faceShapes.size());
  tubeRadius_.assign(model.faceShapes.size(), std::nan(""));
  for (FaceId f = 0; f < model.faceShapes.size(); ++f) {
    const TopoDS_Face face = TopoDS::Face(model.faceShapes[f].Oriented(TopAbs_FORWARD));
    const PartId part = model.faces[f].part;
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
      const EdgeId e = model.edgeId(part, it.Current());
      if (e == UINT32_MAX) continue;
      // In a FORWARD face the material lies left of each pcurve in the edge's direction of use.
      const int side = it.Current().Orientation() == TopAbs_REVERSED ? -1 : 1;
      bool known = false;
      for (FaceUse& use : info_[e].faces) {
        if (!use.face.IsSame(face)) continue;
        known = true;
        if (use.side != side) use.side = 0;  // both orientations: a seam
      }
      if (known || info_[e].faces.size() >= 2) continue;
      FaceUse use;
      use.face = face;
      use.id = f;
      use.side = side;
      use.pcurve = Pcurve(
          BRep_Tool::CurveOnSurface(TopoDS::Edge(it.Current().Oriented(TopAbs_FORWARD)), face, use.first, use.last));
      if (!use.pcurve.isNull()) info_[e].faces.push_back(use);
    }
  }
  std::map<std::pair<const void*, const void*>, std::size_t> edgeByEnds;
  for (std::size_t e = 0; e < n; ++e) {
    levels_[e].resize(levelCount);
    const TopoDS_Edge edge = TopoDS::Edge(model.edgeShapes[e].Oriented(TopAbs_FORWARD));
    Info& info = info_[e];
    info.degenerated = BRep_Tool::Degenerated(edge);
    BRep_Tool::Range(edge, info.first, info.last);
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edge, v0, v1);
    if (!v0.IsNull()) info.p0 = BRep_Tool::Pnt(v0);
    if (!v1.IsNull()) info.p1 = BRep_Tool::Pnt(v1);
    info.closed = !v0.IsNull() && v0.IsSame(v1);
    if (!info.degenerated && !info.closed && !v0.IsNull() && !v1.IsNull()) {
      const void* a = v0.TShape().get();
      const void* b = v1.TShape().get();
      if (std::less<const void*>()(b, a)) std::swap(a, b);
      const auto [it, added] = edgeByEnds.emplace(std::make_pair(a, b), e);
      if (!added) info.sharesEnds = info_[it->second].sharesEnds = true;
    }
    if (info.degenerated) continue;
    try {
      BRepAdaptor_Curve curve(edge);
      info.straight = isStraight(curve, info.first, info.last);
      if (curve.GetType() == GeomAbs_Circle && !info.faces.empty()) {
        info.arcAngle = info.last - info.first;
        info.arcNeeds = arcNeeds(curve.Circle().Radius(), info.arcAngle, info.closed, arcSagBeside(info.faces), tolerances_);
      } else if ((curve.GetType() == GeomAbs_BSplineCurve || curve.GetType() == GeomAbs_BezierCurve) &&
                 !info.faces.empty()) {
        info.splineArc = circularArcOf(curve, info.first, info.last, info.closed);
        if (info.splineArc) {
          info.arcAngle = info.splineArc->angle;
          info.arcNeeds = arcNeeds(info.splineArc->radius, info.arcAngle, info.closed, arcSagBeside(info.faces), tolerances_);
        }
      }
      if (v0.IsNull()) info.p0 = curve.Value(info.first);
      if (v1.IsNull()) info.p1 = curve.Value(info.last);
      info.spline = splineOf(curve);
    } catch (const Standard_Failure&) {
      info.broken = true;
    }
  }
  shareArcCountsOnCones();
  for (Info& info : info_) info.arcSegments = arcSegments(info.arcNeeds);
}

void EdgeTable::scalesSet() {
  for (Info& info : info_) {
    // A face without a usable surface falls back anyway; it does not guide its edges.
    info.faces.erase(std::remove_if(info.faces.begin(), info.faces.end(),
                                    [&](const FaceUse& use) { return !faceScales_[use.id].valid; }),
                     info.faces.end());
    for (FaceUse& use : info.faces) use.scale = &faceScales_[use.id];
  }
  faceUses_.assign(faceScales_.size(), {});
  for (EdgeId e = 0; e < info_.size(); ++e)
    for (std::uint32_t k = 0; k < info_[e].faces.size(); ++k) faceUses_[info_[e].faces[k].id].push_back({e, k});
}

bool EdgeTable::discretise(int level, WorkerPool& pool, unsigned threads, const std::atomic<bool>* cancel) {
  const Level& tolerance = tolerances_[static_cast<std::size_t>(level)];
  std::atomic<bool> cancelled{false};
  parallelFor(pool, info_.size(), threads, [&](std::size_t e) {
    if (cancelled.load(std::memory_order_relaxed)) return;
    if (cancel && cancel->load(std::memory_order_relaxed)) {
      cancelled = true;
      return;
    }
    if (!discretiseEdge(static_cast<EdgeId>(e), level, tolerance, cancel)) cancelled = true;
  });
  if (cancelled) return false;
  return separateCrossings(level, pool, threads, cancel);
}

// How far an arc's chords may sag for the faces beside it, whatever the tolerance: a quarter of the
// tube's radius beside a torus. A circle along a narrow tube (Axis_of_bearing's quarter tubes, 0.5
// in radius, on circles of 11 at 1%, where the deflection is 1.42) sagging 0.135 left the tube's
// first row of points inside the chord's sag (0.118 in), and the triangle between them flipped;
// halving's 24 segments (0.094) had left room, and so does a quarter of the radius (24 again).
// Equal segments elsewhere kept every face of the sample models clean; they had been kept to
// planes, cylinders, cones and spheres since this flip, and beside tori and free-form faces
// halving's counts took 2% more triangles at 0.01% (Pump_Nut 6350 against 5282).
// A torus written as a B-spline is a torus here too (a NURBS sink's quarter tubes of radius 0.4 on
// rings of 9.4 at 0.1%: with the angle's 5 chords a side, the tube's angle splits beside them all
// fell within their clearance, and an edge from the face's corner turned 21.8 degrees).
double EdgeTable::arcSagBeside(const std::vector<FaceUse>& uses) {
  double maxSag = HUGE_VAL;
  for (const FaceUse& use : uses) {
    const double r = tubeRadius(use);
    if (r > 0) maxSag = std::min(maxSag, 0.25 * r);
  }
  return maxSag;
}

double EdgeTable::tubeRadius(const FaceUse& use) {
  double& r = tubeRadius_[use.id];
  if (!std::isnan(r)) return r;
  r = 0;
  const BRepAdaptor_Surface surface(use.face, Standard_False);
  if (surface.GetType() == GeomAbs_Torus) {
    r = surface.Torus().MinorRadius();
  } else if (mayBeRing(surface.GetType())) {
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(use.face, u0, u1, v0, v1);
    const std::optional<RingAngles> ring = ringAngles(surface, u0, u1, v0, v1);
    if (ring && ring->major > 0) r = ring->minor;
  }
  return r;
}

// The circles of one cone (a chamfer's two rims) are cut for the largest of their needs on each
// level, all alike: with counts of their own (5 and 3 segments on a half turn) a coarse chord of
// one rim faces a point of the other between its ends, and on a narrow cone the triangle they make
// stands flipped (the chord's sagitta exceeds the cone's width). Chained cones share too; arcs of
// different angles keep their own.
void EdgeTable::shareArcCountsOnCones() {
  std::vector<EdgeId> group(info_.size());
  for (EdgeId e = 0; e < group.size(); ++e) group[e] = e;
  const std::function<EdgeId(EdgeId)> root = [&](EdgeId e) { return group[e] == e ? e : group[e] = root(group[e]); };
  std::unordered_map<FaceId, EdgeId> firstCircleOfCone;
  for (EdgeId e = 0; e < info_.size(); ++e) {
    if (info_[e].arcNeeds.empty()) continue;
    for (const FaceUse& use : info_[e].faces) {
      if (BRepAdaptor_Surface(use.face, Standard_False).GetType() != GeomAbs_Cone) continue;
      const auto [it, added] = firstCircleOfCone.emplace(use.id, e);
      if (!added) group[root(e)] = root(it->second);
    }
  }
  std::unordered_map<EdgeId, std::vector<EdgeId>> members;
  for (EdgeId e = 0; e < info_.size(); ++e)
    if (!info_[e].arcNeeds.empty() && root(e) != e) members[root(e)].push_back(e);
  for (auto& [r, list] : members) {
    list.push_back(r);
    const double span = info_[r].arcAngle;
    std::vector<std::uint32_t> need = info_[r].arcNeeds;
    bool sameAngle = true;
    for (const EdgeId e : list) {
      sameAngle = sameAngle && std::abs(info_[e].arcAngle - span) <= 1e-9 * span;
      for (std::size_t k = 0; k < need.size(); ++k) need[k] = std::max(need[k], info_[e].arcNeeds[k]);
    }
    if (!sameAngle) continue;
    for (const EdgeId e : list) info_[e].arcNeeds = need;
  }
}

double EdgeTable::pcurveParameter(const Info& info, const FaceUse& use, double t) {
  return info.last == info.first ? use.first : use.first + (t - info.first) / (info.last - info.first) * (use.last - use.first);
}

// Coarse chords of two loops (or two parts of one loop) that run close together can cross in the
// plane the face is triangulated in (its scaled UV, SurfaceEval::scaled) where the curves do not: the
// face could not be meshed from that level's boundary. Both crossing segments are halved, for every
// face that uses their edges, until no face's segments cross (or a few rounds have passed: pcurves
// that really cross are the mesher's to report). That plane is scaled per knot span where spans
// differ, so a chord straight there is not straight in (u, v): the crossings are sought between the
// ends' scaled points, as the mesher joins them.
bool EdgeTable::separateCrossings(int level, WorkerPool& pool, unsigned threads,
                                  const std::atomic<bool>* cancel) {
  constexpr int kRounds = 8;
  const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  for (int round = 0; round < kRounds; ++round) {
    std::vector<std::vector<SegmentId>> found(faceUses_.size());
    parallelFor(pool, faceUses_.size(), threads,
                [&](std::size_t f) { findCrossings(static_cast<FaceId>(f), level, found[f], cancel); });
    if (cancelled()) return false;
    std::vector<SegmentId> split;
    for (const auto& list : found) split.insert(split.end(), list.begin(), list.end());
    if (split.empty()) return true;
    std::sort(split.begin(), split.end());
    split.erase(std::unique(split.begin(), split.end()), split.end());
    std::vector<std::size_t> starts;
    for (std::size_t i = 0; i < split.size(); ++i)
      if (i == 0 || split[i].edge != split[i - 1].edge) starts.push_back(i);
    starts.push_back(split.size());
    // Per edge, one pass that halves its listed segments (inserting them one by one moved the
    // points after each: on a fuzzed face whose rounds halved tens of thousands of segments of long
    // edges, that alone took seconds).
    parallelFor(pool, starts.size() - 1, threads, [&](std::size_t g) {
      const EdgeId e = split[starts[g]].edge;
      EdgePoints& points = levels_[e][static_cast<std::size_t>(level)];
      if (points.t.size() + (starts[g + 1] - starts[g]) > kMaxPoints) {
        points.capped = true;
        return;
      }
      try {
        BRepAdaptor_Curve curve(TopoDS::Edge(model_.edgeShapes[e].Oriented(TopAbs_FORWARD)));
        EdgePoints halved;
        halved.t.reserve(points.t.size() + (starts[g + 1] - starts[g]));
        halved.p.reserve(halved.t.capacity());
        std::size_t next = starts[g];
        for (std::uint32_t j = 0; j < points.t.size(); ++j) {
          halved.t.push_back(points.t[j]);
          halved.p.push_back(points.p[j]);
          if (next == starts[g + 1] || split[next].segment != j) continue;
          ++next;
          const double tm = 0.5 * (points.t[j] + points.t[j + 1]);
          if (!(tm > points.t[j] && tm < points.t[j + 1])) continue;
          halved.t.push_back(tm);
          halved.p.push_back(curve.Value(tm));
        }
        points = std::move(halved);
      } catch (const Standard_Failure&) {
        // Left as it is: the face mesher reports the crossing.
      }
    });
  }
  return true;
}

void EdgeTable::findCrossings(FaceId face, int level, std::vector<SegmentId>& out,
                              const std::atomic<bool>* cancel) const {
  struct Segment {
    double x0, y0, x1, y1;
    SegmentId id;
  };
  std::vector<Segment> segments;
  const FaceScale& scale = faceScales_[face];
  for (const auto& [e, k] : faceUses_[face]) {
    const Info& info = info_[e];
    const FaceUse& use = info.faces[k];
    const EdgePoints& points = levels_[e][static_cast<std::size_t>(level)];
    double px = 0, py = 0;
    for (std::size_t j = 0; j < points.t.size(); ++j) {
      const gp_Pnt2d uv = use.pcurve.value(pcurveParameter(info, use, points.t[j]));
      const double x = scale.uAxis.map(uv.X()), y = scale.vAxis.map(uv.Y());
      if (j > 0) segments.push_back({px, py, x, y, {e, static_cast<std::uint32_t>(j - 1)}});
      px = x, py = y;
    }
  }
  if (segments.size() < 3) return;
  auto orient = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  std::sort(segments.begin(), segments.end(), [](const Segment& a, const Segment& b) { return std::min(a.x0, a.x1) < std::min(b.x0, b.x1); });
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (i % 1024 == 0 && cancel && cancel->load(std::memory_order_relaxed)) return;
    const Segment& a = segments[i];
    const double aRight = std::max(a.x0, a.x1), aLow = std::min(a.y0, a.y1), aHigh = std::max(a.y0, a.y1);
    for (std::size_t j = i + 1; j < segments.size() && std::min(segments[j].x0, segments[j].x1) <= aRight; ++j) {
      const Segment& b = segments[j];
      if (std::max(b.y0, b.y1) < aLow || std::min(b.y0, b.y1) > aHigh) continue;
      const double d1 = orient(a.x0, a.y0, a.x1, a.y1, b.x0, b.y0), d2 = orient(a.x0, a.y0, a.x1, a.y1, b.x1, b.y1);
      const double d3 = orient(b.x0, b.y0, b.x1, b.y1, a.x0, a.y0), d4 = orient(b.x0, b.y0, b.x1, b.y1, a.x1, a.y1);
      if (!((d1 < 0 && d2 > 0) || (d1 > 0 && d2 < 0)) || !((d3 < 0 && d4 > 0) || (d3 > 0 && d4 < 0))) continue;
      // Segments meeting at a corner touch there without crossing; where edges meet, their pcurves
      // agree only to within the edge tolerance, so they may overlap by a hair: only a crossing
      // inside both segments counts.
      const double along = d3 / (d3 - d4), alongB = d1 / (d1 - d2);
      if (along > 1e-3 && along < 1 - 1e-3 && alongB > 1e-3 && alongB < 1 - 1e-3) {
        out.push_back(a.id);
        out.push_back(b.id);
      }
    }
  }
}

bool EdgeTable::discretiseEdge(EdgeId e, int level, const Level& tol, const std::atomic<bool>* cancel) {
  const Info& info = info_[e];
  EdgePoints& out = levels_[e][static_cast<std::size_t>(level)];
  out.t.clear();
  out.p.clear();
  out.capped = false;
  if (info.degenerated) return true;
  if (info.broken) {
    out.t = {info.first, info.last};
    out.p = {info.p0, info.p1};
    return true;
  }
  const TopoDS_Edge edge = TopoDS::Edge(model_.edgeShapes[e].Oriented(TopAbs_FORWARD));
  std::vector<double> seedT;
  if (level > 0) {
    seedT = levels_[e][static_cast<std::size_t>(level - 1)].t;
  }
  if (!info.arcSegments.empty() && !info.splineArc) {
    const std::uint32_t n = info.arcSegments[static_cast<std::size_t>(level)];
    const double step = (info.last - info.first) / n;
    seedT = withEqualSegments(seedT, n, step, [&](std::uint32_t i) { return i == n ? info.last : info.first + step * i; });
  }
  try {
    BRepAdaptor_Curve curve(edge);
    if (!info.arcSegments.empty() && info.splineArc) {
      // Equal angles, at the parameters where the curve has turned by them.
      const CircularArc& arc = *info.splineArc;
      const std::uint32_t n = info.arcSegments[static_cast<std::size_t>(level)];
      seedT = withEqualSegments(seedT, n, (info.last - info.first) / n, [&](std::uint32_t i) {
        if (i == 0 || i == n) return i == 0 ? info.first : info.last;
        return arc.parameterAt(curve, info.first, info.last, arc.angle * i / n);
      });
    }
    // The 3D curve's samples and tangents: from its poles where it is a B-spline (Info::spline),
    // else the adaptor's. At the edge's ends the adaptor's too: where an end is a knot of the curve
    // the adaptor takes the derivative of the span inside the edge, the poles' that of the span
    // starting there (a fuzzed straight edge ending on a knot where its curve turns 60 degrees read
    // the turn at its end and was split). The points that become the edge's vertices are the
    // adaptor's: the faces' meshes follow their last bits (from the poles, the sample models' meshes
    // changed both ways at 0.01%: bearing 51083 -> 51153 triangles, hammer 8670 -> 8652).
    const auto fromPoles = [&](double t) { return info.spline && t != info.first && t != info.last; };
    auto curveValue = [&](double t) {
      if (!fromPoles(t)) return curve.Value(t);
      double p[3];
      info.spline->evaluate(t, p, nullptr);
      return gp_Pnt(p[0], p[1], p[2]);
    };
    auto curveD1 = [&](double t, gp_Pnt& p, gp_Vec& d) {
      if (!fromPoles(t)) return curve.D1(t, p, d);
      double a[3], b[3];
      info.spline->evaluate(t, a, b);
      p.SetCoord(a[0], a[1], a[2]);
      d.SetCoord(b[0], b[1], b[2]);
    };
    // Surface normals of the faces along the edge (their parameter maps linearly onto the edge's).
    std::vector<BRepAdaptor_Surface> surfaces;
    for (const FaceUse& use : info.faces) surfaces.emplace_back(use.face, Standard_False);
    const std::size_t uses = surfaces.size();
    // Points along an edge fall in a new knot span of a B-spline face nearly every time: evaluated
    // directly rather than through OpenCASCADE's per-span cache (bspline_direct.h).
    auto d1 = [&](std::size_t k, double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) {
      const FaceScale& scale = *info.faces[k].scale;
      faceSideD1(scale.direct.get(), surfaces[k], scale.uMin, scale.uMax, scale.vMin, scale.vMax, u, v, p, du, dv);
    };
    auto pointOn = [&](std::size_t k, double u, double v) {
      if (const BSplineDirect* direct = info.faces[k].scale->direct.get()) return direct->value(u, v);
      return surfaces[k].Value(u, v);
    };
    // Su x Sv, or none (zero) where the surface has no area there: Su parallel to Sv (a pole, or a
    // patch collapsed onto a segment), where the direction of their cross product is rounding noise.
    auto crossOrNone = [](const gp_Vec& du, const gp_Vec& dv) {
      const gp_Vec n = du.Crossed(dv);
      return n.Magnitude() <= 1e-10 * du.Magnitude() * dv.Magnitude() ? gp_Vec(0, 0, 0) : n;
    };
    // On a crease of face k's surface (SurfaceEval::onCrease: a C0 knot line, or a sharp knot's,
    // where the two limits nearly agree) the evaluators give the normal of one side, the knot span
    // OpenCASCADE picks, which need not be the side a segment leaving uv along `along` (UV) lies
    // on, with the face on `side` of it. Sets n to the normal just off the crease that way (and a
    // tenth as far into the face, for a segment running along the crease); false (n untouched)
    // where uv is not on a crease. An edge along the bend of a bracket (90 degrees) took the far
    // plate's normals at its ends: every apex standing on it failed the angle, and it was halved
    // level after level (4098 points at 0.1% for a side 5 long); an edge ending on the crease was
    // halved towards that end down to the minimum size.
    auto creaseSide = [&](std::size_t k, const gp_Pnt2d& uv, gp_Vec2d along, int side, gp_Vec& n) {
      const FaceScale& scale = *info.faces[k].scale;
      if (scale.creases.empty() || !scale.creases.on(uv.X(), uv.Y()) || !(along.Magnitude() > 0))
        return false;
      along.Normalize();
      const gp_Vec2d off = (along + gp_Vec2d(-along.Y(), along.X()) * (0.1 * side)) * 1e-7;
      gp_Pnt p;
      gp_Vec du, dv;
      d1(k, uv.X() + off.X() * (scale.uMax - scale.uMin), uv.Y() + off.Y() * (scale.vMax - scale.vMin), p, du,
         dv);
      n = crossOrNone(du, dv);
      return true;
    };
    // The faces' normals at t: below, the limit coming from smaller t (a segment ending at t);
    // above, from larger t (a segment starting there). They differ only on creases (creaseSide).
    auto normalsAt = [&](double t, gp_Vec* below, gp_Vec* above) {
      for (std::size_t k = 0; k < uses; ++k) {
        const FaceUse& use = info.faces[k];
        const double s = pcurveParameter(info, use, t);
        const gp_Pnt2d uv = use.pcurve.value(s);
        gp_Pnt p;
        gp_Vec du, dv;
        d1(k, uv.X(), uv.Y(), p, du, dv);
        // At a pole one derivative is rounding noise: no normal to compare.
        below[k] = above[k] =
            du.Magnitude() < 1e-12 || dv.Magnitude() < 1e-12 ? gp_Vec(0, 0, 0) : crossOrNone(du, dv);
        if (use.scale->creases.empty() || below[k].Magnitude() == 0) continue;
        gp_Pnt2d onCurve;
        gp_Vec2d tangent;  // along increasing t
        use.pcurve.d1(s, onCurve, tangent);
        if (use.last < use.first) tangent.Reverse();
        if (creaseSide(k, uv, tangent, use.side, above[k])) creaseSide(k, uv, -tangent, -use.side, below[k]);
      }
    };
    // The segment's chord in face k's UV: its ends, the same in the face's scaled UV (the face
    // mesher's plane, where lengths approximate 3D ones: SurfaceEval::scaled), the chord's
    // direction there (dx, dy) and its length. The scaling is per knot span where a B-spline's
    // spans run at different speeds: with one scale for the whole face, triangles stood on a chord
    // along a span 4e-7 wide reached far past it, onto a side of the surface turned 90 degrees
    // away, and a fuzzed face's edge there was halved to the minimum size (66517 points at 0.01%).
    struct UvChord {
      gp_Pnt2d a, b;
      double ax = 0, ay = 0, dx = 0, dy = 0, len = 0;
    };
    auto uvChord = [&](std::size_t k, double ta, double tb) {
      const FaceUse& use = info.faces[k];
      UvChord c;
      c.a = use.pcurve.value(pcurveParameter(info, use, ta));
      c.b = use.pcurve.value(pcurveParameter(info, use, tb));
      c.ax = use.scale->uAxis.map(c.a.X()), c.ay = use.scale->vAxis.map(c.a.Y());
      c.dx = use.scale->uAxis.map(c.b.X()) - c.ax, c.dy = use.scale->vAxis.map(c.b.Y()) - c.ay;
      c.len = std::hypot(c.dx, c.dy);
      return c;
    };
    // The UV of the point at fraction f of the chord and `height` (scaled units) off it on `side`.
    auto offChord = [&](std::size_t k, const UvChord& c, double f, double height, int side, double& u,
                        double& v) {
      const FaceScale& scale = *info.faces[k].scale;
      const double h = height * side / c.len;
      u = scale.uAxis.inverse(c.ax + f * c.dx - h * c.dy);
      v = scale.vAxis.inverse(c.ay + f * c.dy + h * c.dx);
    };
    // Face k's normal (not unit) at (u, v); none (zero) where the surface has no area there, as in
    // normalsAt (a fuzzed face's straight edge beside a patch collapsed onto a segment was halved
    // down to a tenth of the tolerance for the noise: 3973 points on one edge, 4041 triangles of no
    // area).
    auto normalAt = [&](std::size_t k, double u, double v, gp_Pnt& p) {
      gp_Vec du, dv;
      d1(k, u, v, p, du, dv);
      return crossOrNone(du, dv);
    };
    // A facet on the chord (pa, pb) with apex `apex` nearly edge-on to the surface (the face
    // mesher's fold rule), or flipped, against its corners' normals; not decided where one has none.
    auto folds = [&](const gp_Pnt& pa, const gp_Pnt& pb, const gp_Pnt& apex, const gp_Vec& na, const gp_Vec& nb,
                     const gp_Vec& nApex, int side) {
      const double ma = na.Magnitude(), mb = nb.Magnitude(), mApex = nApex.Magnitude();
      if (!(ma > 0 && mb > 0 && mApex > 0)) return false;
      const gp_Vec facet = gp_Vec(pa, pb).Crossed(gp_Vec(pa, apex)) * side;
      const gp_Vec nSum = na / ma + nb / mb + nApex / mApex;
      return facet.Dot(nSum) <= kFoldCos * facet.Magnitude() * nSum.Magnitude();
    };
    // The perpendicular from the middle of face k's UV chord into the face (side: which way; the
    // domain on the left of the chord times side), in the face's scaled UV: h the largest height
    // inside the face's parameter box up to the tall standing triangle's, and (u, v) the point
    // reached. Not inside where the chord lies on the box's side (a seam, whose far side is the
    // face's other end) or its middle is off the box.
    struct Reach {
      double u, v, h, tall;  // the point reached (UV), how far (scaled) and the tall triangle's height
      bool inside;
    };
    auto reachInto = [&](std::size_t k, const UvChord& c, int side, double f = 0.5) {
      const FaceScale& scale = *info.faces[k].scale;
      Reach r;
      const double mx = c.ax + f * c.dx, my = c.ay + f * c.dy;
      const double rx = -side * c.dy / c.len, ry = side * c.dx / c.len;
      r.tall = r.h = kStandingHeight * c.len;
      auto limit = [&r](double m, double d, double lo, double hi) {
        if (d > 0) r.h = std::min(r.h, (hi - m) / d);
        if (d < 0) r.h = std::min(r.h, (lo - m) / d);
      };
      limit(mx, rx, scale.uAxis.map(scale.uMin), scale.uAxis.map(scale.uMax));
      limit(my, ry, scale.vAxis.map(scale.vMin), scale.vAxis.map(scale.vMax));
      r.inside = r.h > 1e-9 * (std::abs(mx) + std::abs(my) + c.len);
      offChord(k, c, f, r.h, side, r.u, r.v);
      return r;
    };
    // Whether every curved face on the segment stays near its chord (the slender triangles'
    // condition in standing()): the surface under each face's UV chord lies within kSlenderBulge of
    // the chord's length from the 3D chord, and where the face is narrower than half the chord,
    // within twice that of its width there (3D distance from the chord's middle to the far side of
    // the face's parameter box). A narrow fillet along a long chord turns across its width within
    // the chord's sag: Top.brep's tori of radius 1 on arcs of radius 92 (chords of 20 sagging 0.56
    // at 1%) kept 23 degrees, every point across them inside the chord's clearance.
    auto hugsChord = [&](double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb) {
      const gp_Pnt mid(0.5 * (pa.XYZ() + pb.XYZ()));
      for (std::size_t k = 0; k < uses; ++k) {
        if (!info.faces[k].scale->curved) continue;
        const UvChord c = uvChord(k, ta, tb);
        if (!(c.len > 0)) continue;
        double room = 0.5 * pa.Distance(pb);  // in 3D (the scaled UV may stretch one way 1000:1)
        for (int side : {-1, 1}) {
          if (info.faces[k].side != 0 && info.faces[k].side != side) continue;
          const Reach r = reachInto(k, c, side);
          if (!r.inside) continue;
          gp_Pnt across;
          normalAt(k, r.u, r.v, across);
          room = std::min(room, mid.Distance(across));
        }
        gp_Pnt under;
        double mu = 0, mv = 0;
        offChord(k, c, 0.5, 0, 1, mu, mv);
        normalAt(k, mu, mv, under);
        if (!(under.Distance(mid) < kSlenderBulge * 2 * room)) return false;
      }
      return true;
    };
    // Whether face k's surface has a pole at uv: one of its derivatives vanishes beside the other.
    auto atPole = [&](std::size_t k, const gp_Pnt2d& uv) {
      gp_Pnt p;
      gp_Vec du, dv;
      d1(k, uv.X(), uv.Y(), p, du, dv);
      return std::min(du.Magnitude(), dv.Magnitude()) <= 1e-9 * std::max(du.Magnitude(), dv.Magnitude());
    };
    // A face narrower than the tall standing triangle (its far side nearer the chord than half the
    // chord's length) that turns across its width beyond the angle: the face mesher's first row of
    // points must stand within the angle of the chord (the turn taken as even across the face),
    // where its splits put it, and a point there must make a facet with the chord that faces the
    // surface's way (FaceMesher::clearOfChords: inside a chord's clearance, within
    // kStandingFacetCos). Where the chord sags more than the face rises over that row, none can:
    // returns how far the far side misses the angle, else 0. r0901's fillet (90 degrees over 0.7
    // in width) along a chord 4.6 long sagging 0.15 at 0.1%: every point splitting an edge of 20.5
    // degrees lay inside the chord's clearance. (Tested where the normal has turned by the angle,
    // 1/spread across, Bottom's face 69 at 1%, a fillet turning 85 degrees, kept 20.35 degrees.)
    auto narrowMiss = [&](std::size_t k, const UvChord& c, const gp_Pnt& pa, const gp_Pnt& pb, int side,
                          const gp_Vec& na, const gp_Vec& nb, auto&& spreadAt) {
      // Not on a chord to a pole: the face narrows to nothing there, where a fan stands on the
      // pole rather than rows on the chord, and the normal at the pole is rounding noise (CrankArm's
      // corner blends, pinched to a point: their edges were halved towards it, and a sliver by the
      // pole flipped on two coarse levels).
      if (atPole(k, c.a) || atPole(k, c.b)) return 0.0;
      const Reach r = reachInto(k, c, side);
      if (!r.inside) return 0.0;
      gp_Pnt across, row;
      const double spread = spreadAt(r.u, r.v, across);
      if (spread <= 1.0) return 0.0;
      // The refinement halves the edges across the face, sliding a split up to 0.8 of the way
      // along one that has no clear point at its middle (FaceMesher::safeSplit): its first row
      // lies at most 0.8 of the way to the row before it, 2^-(n-1) across for n halvings, and no
      // farther than where the normal has turned by the angle from both of the chord's ends: its
      // points lie anywhere along the chord, and an edge runs from each end to the row points
      // beside the other as well (a fillet on a ring of 10, turning 15 degrees along each chord,
      // kept 20.09 degrees on such edges with the row tested under the middle alone). Where no row
      // does, however near, the chord is halved.
      const double halvings = std::ceil(std::log2(spread));
      double far = std::min(1 / spread, 1.6 / std::exp2(halvings)), near = 0;
      double u = 0, v = 0;
      const FaceScale& scale = *info.faces[k].scale;
      auto rowMissesAngle = [&](double depth) {
        for (double f : {0.0, 0.5, 1.0}) {
          offChord(k, c, f, r.h * depth, side, u, v);
          if (u < scale.uMin || u > scale.uMax || v < scale.vMin || v > scale.vMax) continue;
          if (spreadAt(u, v, row) > 1.0) return true;
        }
        return false;
      };
      if (rowMissesAngle(far)) {
        for (int i = 0; i < 12; ++i) {
          const double mid = 0.5 * (near + far);
          (rowMissesAngle(mid) ? far : near) = mid;
        }
        if (near == 0) return spread;
        far = near;
      }
      offChord(k, c, 0.5, r.h * far, side, u, v);
      const gp_Vec nRow = normalAt(k, u, v, row);
      const double ma = na.Magnitude(), mb = nb.Magnitude(), mRow = nRow.Magnitude();
      if (!(ma > 0 && mb > 0 && mRow > 0)) return 0.0;
      const gp_Vec nChord = na / ma + nb / mb;
      if (!(nChord.Magnitude() > 0)) return 0.0;
      const gp_Vec facet = gp_Vec(pa, pb).Crossed(gp_Vec(pa, row)) * side;
      const gp_Vec nSum = 2 * nChord.Normalized() + nRow / mRow;
      return facet.Dot(nSum) > kStandingFacetCos * facet.Magnitude() * nSum.Magnitude() ? 0.0 : spread;
    };
    // The apex of a triangle standing on face k's UV chord c: above the point at fraction f of the
    // chord, height times its length away (side: which way), in the face's scaled UV. False
    // outside the face's parameter box.
    auto apexAt = [&](std::size_t k, const UvChord& c, double f, double height, int side, double& au,
                      double& av) {
      const FaceScale& scale = *info.faces[k].scale;
      offChord(k, c, f, height * c.len, side, au, av);
      return au >= scale.uMin && au <= scale.uMax && av >= scale.vMin && av <= scale.vMax;
    };
    // How far triangles standing on the segment's UV chord miss the tolerances: the tallest (apex
    // kStandingHeight of the chord's length away, in the face's scaled UV) by the larger of its
    // centroid's sag over the chordal tolerance and its corners' normal spread over the angular
    // one, or twice over if it folds; lower ones (apexes on the same median, down to
    // kLowestStanding) by their spread alone. A face may bend sharply in a strip beside
    // its boundary (terrain's rim turns 70-120 degrees within 20 units of a side 8000 long): the
    // tall triangle's apex lies past the strip and passes, but every point the face mesher can
    // put there fails the angle against the chord's ends, so its refinement crept towards the
    // chord and left slivers a hair inside the boundary. Apexes stay inside the face's parameter box.
    //
    // The tall triangle may miss the angle a little (kSlenderSpread) where the low ones keep it: a
    // face turning steadily across its edge (a fillet beside it) then gets slender triangles along
    // the edge rather than the edge halved until the tall one stands (Ball's cylinder took 128
    // segments for the B-spline fillet beside it; bearing.iges 13184 -> 12240 triangles against
    // BRepMesh's 12285). The face mesher must be able to put its points that near: only where every
    // curved face hugs the chord (hugsChord), so that the clearance the mesher keeps from it
    // (FaceMesher::buildChords) stays below the low apexes. Without that bound Propeller's blade
    // tips folded at 1/4 (1582 flipped triangles on a level); without the absolute bound, a level-0
    // strip of MAT.brep turning 90 degrees folded.
    auto standing = [&](std::size_t k, double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, int side, const Level& crit) {
      const UvChord c = uvChord(k, ta, tb);
      if (!(c.len > 0)) return 0.0;
      gp_Pnt tmp;
      gp_Vec na = normalAt(k, c.a.X(), c.a.Y(), tmp), nb = normalAt(k, c.b.X(), c.b.Y(), tmp);
      // A chord on a crease or fold line of the surface inside the face's box (a C0 knot line of a
      // B-spline where the sheet folds back) may take its normals from the far side (d1 takes the
      // inside span on the box's sides only): where they point more than 90 degrees from the face's
      // own side, that side's are used (1e-7 of the chord towards the apexes). Every apex fails
      // the angle against the far side's normals, and the edge was halved down to a tenth of the
      // tolerance.
      auto faceSide = [&](double f, gp_Vec& n) {
        double au = 0, av = 0;
        if (!apexAt(k, c, f, 1e-7, side, au, av)) return;
        const gp_Vec inside = normalAt(k, au, av, tmp);
        if (inside.Dot(n) < 0) n = inside;
      };
      // On a crease line: the limit along the chord, on the face's side (creaseSide).
      const gp_Vec2d ab(c.a, c.b);
      if (!creaseSide(k, c.a, ab, side, na)) faceSide(0, na);
      if (!creaseSide(k, c.b, -ab, -side, nb)) faceSide(1, nb);
      gp_Vec nApex;
      auto spreadAt = [&](double au, double av, gp_Pnt& apex) {
        nApex = normalAt(k, au, av, apex);
        return std::max(angleBetween(na, nApex), angleBetween(nb, nApex)) / crit.angleRad;
      };
      double worst = 0, tallSpread = 0;
      bool lowest = false;  // whether the lowest triangle was checked (its apex inside the box)
      for (double height = kStandingHeight; height >= kLowestStanding; height *= 0.5) {
        double au = 0, av = 0;
        // Outside the face's parameter box the face is narrower than the triangle: its width, not
        // this segment, limits the triangles there (the lower ones too: a narrow fillet turns
        // steadily across, and the edges on its far side set its rows), as long as its first row
        // can stand on the chord (narrowMiss).
        if (!apexAt(k, c, 0.5, height, side, au, av)) {
          if (height == kStandingHeight) return narrowMiss(k, c, pa, pb, side, na, nb, spreadAt);
          break;
        }
        gp_Pnt apex;
        const double spread = spreadAt(au, av, apex);
        if (height == kStandingHeight) {
          gp_Pnt centroid;
          double cu = 0, cv = 0;  // the centroid: a third of the apex's height over the chord's middle
          offChord(k, c, 0.5, height * c.len / 3, side, cu, cv);
          const gp_Vec nc = normalAt(k, cu, cv, centroid);
          if (nc.Magnitude() > 0) {
            const gp_XYZ flat = (pa.XYZ() + pb.XYZ() + apex.XYZ()) / 3;
            worst = std::max(worst, std::abs(gp_Vec(flat, centroid.XYZ()).Dot(nc / nc.Magnitude())) / crit.chordal);
          }
          // Folded: the chord sags beside the segment as far as the apex reaches, so no point can
          // stand on it. (Asked of the tall triangle only: a low one on a curved chord always
          // tilts, and the face mesher is free to stand a taller one there.)
          if (folds(pa, pb, apex, na, nb, nApex, side)) return 2.0;
          if (worst > 1.0) break;
          tallSpread = spread;
          continue;
        }
        worst = std::max(worst, spread);
        lowest = height * 0.5 < kLowestStanding;
        if (worst > 1.0) break;
      }
      if (tallSpread <= 1.0 || worst > 1.0) return std::max(worst, tallSpread);
      // The tall triangle misses the angle: slender ones instead, where the surface turns steadily
      // beside the whole chord: the low triangles keep the angle over its quarters as well as its
      // middle, and at half their height (MAT.brep's terrain twists 50 degrees within 5 units of
      // a chord 20 long, near its end: slivers there kept 36 degrees), and every curved face on
      // the segment hugs its chord.
      if (!lowest || tallSpread > kSlenderSpread || tallSpread * crit.angleRad > kSlenderMaxAngle) return tallSpread;
      for (const double height : {kLowestStanding, 0.5 * kLowestStanding}) {
        for (const double f : {0.25, 0.5, 0.75}) {
          double au = 0, av = 0;
          gp_Pnt apex;
          if (height == kLowestStanding && f == 0.5) continue;  // checked above
          if (apexAt(k, c, f, height, side, au, av) && spreadAt(au, av, apex) > 1.0) return tallSpread;
        }
      }
      return hugsChord(ta, tb, pa, pb) ? worst : tallSpread;
    };
    // Whether the triangle that reaches across a narrow face from the segment folds: where the face
    // is narrower (in its parameter box) than the tall standing triangle, the apex lands on its far
    // side, and a chord whose sagitta exceeds the face's width there stands edge-on or flipped
    // (bug33398's chamfer cones: a rim 20 in radius, 0.6 wide, chords of 35 degrees; the bottle's
    // neck at coarse levels). Only where the face is clearly narrower (the apex clamped below 3/4
    // of the tall height): a B-spline half tube whose far end the tall apex nearly reaches folds
    // the same way under its single coarse triangle, and its interior points mend that (hammer's
    // handle faces took 14 times the triangles when its edges were halved for it).
    auto foldsAcross = [&](std::size_t k, double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, int side) {
      const UvChord c = uvChord(k, ta, tb);
      if (!(c.len > 0)) return false;
      const Reach r = reachInto(k, c, side);
      // Wide enough here; or the chord lies on the box's side (a seam, whose far side is the face's
      // other end) or its middle is off the box.
      if (r.h >= 0.75 * r.tall || !r.inside) return false;
      gp_Pnt apex, tmp;
      const gp_Vec nApex = normalAt(k, r.u, r.v, apex);
      const gp_Vec na = normalAt(k, c.a.X(), c.a.Y(), tmp), nb = normalAt(k, c.b.X(), c.b.Y(), tmp);
      return folds(pa, pb, apex, na, nb, nApex, side);
    };
    // Whether face k curls back behind the segment across its width: the point reaching into it
    // from a quarter, the middle or three quarters of the chord (as far as the tall standing
    // triangle's apex, or the far side of the face's parameter box) lies behind the 3D chord, more
    // than kCurlBehind of its length, in the plane of the chord's mean normal. No point of such a
    // face can stand on the chord clear of it (FaceMesher::buildChords): Top's and trj4's corner
    // blends, B-spline patches pinched to a side 0.47 long and 2.8 wide at level 0, kept a flipped
    // triangle fanning from the pinched corner, every split point of it behind a chord 3.1 long.
    // na, nb: the surface normals at the segment's ends.
    auto curlsBehind = [&](std::size_t k, double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, const gp_Vec& na,
                           const gp_Vec& nb, int side) {
      const double ma = na.Magnitude(), mb = nb.Magnitude();
      if (!(ma > 0 && mb > 0)) return false;
      const gp_Vec n = na / ma + nb / mb;
      const UvChord c = uvChord(k, ta, tb);
      if (!(c.len > 0) || !(n.Magnitude() > 0)) return false;
      const gp_Vec ab(pa, pb);
      for (double f : {0.25, 0.5, 0.75}) {
        const Reach r = reachInto(k, c, side, f);
        if (!r.inside) continue;
        const gp_Pnt across = pointOn(k, r.u, r.v);
        if (ab.Crossed(gp_Vec(pa, across)).Dot(n) * side < -kCurlBehind * ab.SquareMagnitude() * n.Magnitude()) return true;
      }
      return false;
    };
    // The standing triangles not on planes, cylinders, cones and spheres: they bend the same way
    // next to the boundary as along it, which the normal criterion above already covers. A torus
    // does not: beside a circle on its top, the tube turns down. The narrow-face fold on every
    // curved face.
    auto standingFails = [&](double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, const gp_Vec* na, const gp_Vec* nb,
                             const Level& crit) {
      for (std::size_t k = 0; k < uses; ++k) {
        const FaceScale& scale = *info.faces[k].scale;
        if (!scale.curved) continue;
        for (int side : {-1, 1}) {
          if (info.faces[k].side != 0 && info.faces[k].side != side) continue;
          if (scale.bendsBeside && standing(k, ta, tb, pa, pb, side, crit) > 1.0) return true;
          if (foldsAcross(k, ta, tb, pa, pb, side)) return true;
          if (scale.bendsBeside && curlsBehind(k, ta, tb, pa, pb, na[k], nb[k], side)) return true;
        }
      }
      return false;
    };
    // Where the samples below may miss the curve, its control points decide as well.
    std::optional<CurveHull> hull;
    if (!info.straight && CurveHull::samplesMayMiss(curve)) hull.emplace(curve);
    // The interior knots of a B-spline 3D curve: each span is one polynomial piece, and a segment's
    // samples (fractions of its parameter range) miss a span much shorter than the segment (a
    // fuzzed edge's last span, 2.6e-6 of its range of 1.64, carried thousands of units of its
    // length: its chord ran 1.08x the tolerance from the face on level 1).
    std::vector<double> knots;
    if (curve.GetType() == GeomAbs_BSplineCurve) {
      const Handle(Geom_BSplineCurve) bspline = curve.BSpline();
      for (int i = 1; i <= bspline->NbKnots(); ++i)
        if (bspline->Knot(i) > info.first && bspline->Knot(i) < info.last) knots.push_back(bspline->Knot(i));
    }
    // Whether the curve leaves the chord (pa, pb) by more than `chordal` at a knot inside (ta, tb) or
    // in the middle of a span there (the first and last cut by the segment's ends too).
    auto offChordAtKnots = [&](double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, double chordal) {
      auto k = std::upper_bound(knots.begin(), knots.end(), ta);
      if (k == knots.end() || *k >= tb) return false;
      double previous = ta;
      for (int checked = 0; checked < 256 && previous < tb; ++checked) {
        const double next = k != knots.end() && *k < tb ? *k : tb;
        if (distanceToSegment(curveValue(0.5 * (previous + next)), pa, pb) > chordal) return true;
        if (next < tb && distanceToSegment(curveValue(next), pa, pb) > chordal) return true;
        previous = next;
        if (k != knots.end()) ++k;
      }
      return false;
    };
    struct Item {
      double ta, tb;
      gp_Pnt pa, pb;
      gp_Vec da, db;
      gp_Vec na[2], nb[2];
      int depth;
    };
    // How far `off` (from the surface point at (u, v) of face k, derivatives du, dv) leads out of the
    // surface where (u, v) lies on a bound of its parameters that is not periodic: its part along
    // the surface's tangent plane, across the bound's iso-line, outwards; 0 inside or off a bound.
    // Past such a bound there is no surface to come nearer to (the measure's feet stop at it).
    auto beyondBound = [&](std::size_t k, double u, double v, const gp_Vec& du, const gp_Vec& dv,
                           const gp_Vec& off) {
      const BRepAdaptor_Surface& s = surfaces[k];
      auto at = [](double x, double bound, double first, double last) {
        return std::abs(x - bound) <= 1e-9 * std::max(1.0, std::abs(last - first));
      };
      gp_Vec inward, along;
      if (!s.IsVPeriodic() && at(v, s.FirstVParameter(), s.FirstVParameter(), s.LastVParameter())) {
        inward = dv, along = du;
      } else if (!s.IsVPeriodic() && at(v, s.LastVParameter(), s.FirstVParameter(), s.LastVParameter())) {
        inward = -dv, along = du;
      } else if (!s.IsUPeriodic() && at(u, s.FirstUParameter(), s.FirstUParameter(), s.LastUParameter())) {
        inward = du, along = dv;
      } else if (!s.IsUPeriodic() && at(u, s.LastUParameter(), s.FirstUParameter(), s.LastUParameter())) {
        inward = -du, along = dv;
      } else {
        return 0.0;
      }
      const double ma = along.Magnitude();
      if (!(ma > 0)) return 0.0;
      const gp_Vec t = along / ma;
      const gp_Vec across = inward - t * inward.Dot(t);
      const double mc = across.Magnitude();
      if (!(mc > 0)) return 0.0;
      return std::max(0.0, -off.Dot(across) / mc);
    };
    // Whether a face's surface along the chord (pa, pb) lies farther than `chordal` from it, across
    // the surface (along its normal), where halving can bring it nearer: the face mesher's
    // boundary is the chord's straight line in the face's scaled UV, and the triangles on it sample
    // the surface there. An edge's 3D curve may stray from the surface within its own tolerance
    // (linkrods.step: 4.1e-4 from a B-spline face, its deflection at 0.01% 5.7e-4): its chords
    // sagging towards the same side as the gap missed the surface by 1.3x the deflection, and the
    // refinement marched points into the chord's corner, each a third as far as the one before,
    // leaving a pile of flipped slivers. The gap itself (the curve against the surface at the
    // same parameter) halving cannot close: only while it is within `chordal` and the chord's own
    // part (the rest) is over a tenth of it. Along a bound of the surface's parameters, the parts
    // out of the surface's side count too, in the chord's distance and in the gap
    // (iges/bearing.iges at 0.01%: chords sagging 0.8 of the deflection out of a B-spline's side,
    // 0.22 of it above, made face 77 1.002x; counted in the chord's distance alone, a curve lying
    // out of the side by more than the deflection was halved to the point cap).
    auto surfaceLeavesChord = [&](double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, double chordal) {
      for (std::size_t k = 0; k < uses; ++k) {
        const UvChord c = uvChord(k, ta, tb);
        if (!(c.len > 0)) continue;
        for (double f : {0.5, 0.25, 0.75}) {
          double u = 0, v = 0;
          offChord(k, c, f, 0, 1, u, v);
          gp_Pnt under;
          gp_Vec du, dv;
          d1(k, u, v, under, du, dv);
          const gp_Vec n = crossOrNone(du, dv);
          const double m = n.Magnitude();
          if (!(m > 0)) continue;
          const gp_Vec off(under, pa.XYZ() + f * (pb.XYZ() - pa.XYZ()));
          const double across = std::hypot(off.Dot(n) / m, beyondBound(k, u, v, du, dv, off));
          if (!(across > chordal)) continue;
          const double t = ta + f * (tb - ta);
          const gp_Pnt2d uv = info.faces[k].pcurve.value(pcurveParameter(info, info.faces[k], t));
          gp_Pnt onSurface;
          gp_Vec su, sv;
          d1(k, uv.X(), uv.Y(), onSurface, su, sv);
          const gp_Vec ns = crossOrNone(su, sv);
          if (!(ns.Magnitude() > 0)) continue;
          const gp_Vec stray(onSurface, curveValue(t));
          const double gap =
              std::hypot(stray.Dot(ns) / ns.Magnitude(), beyondBound(k, uv.X(), uv.Y(), su, sv, stray));
          if (gap < chordal && across - gap > 0.1 * chordal) return true;
        }
      }
      return false;
    };
    // Whether segment s misses the criteria of tolerance `crit` and must be halved.
    auto misses = [&](const Item& s, const Level& crit) {
      if (!(s.tb - s.ta > 1e-12 * std::max(1.0, std::abs(s.tb)))) return false;
      // Past kMaxDepth only a knot inside a segment still halves it: a span can be far shorter than
      // 2^-24 of its edge (a fuzzed polyline's vertex 2e-6 from its end on an edge 2.77 long kept a
      // chord skipping it, 1.85x the deflection from it).
      if (s.depth >= kMaxDepth) return !info.straight && offChordAtKnots(s.ta, s.tb, s.pa, s.pb, crit.chordal);
      const double minSize = 0.1 * crit.chordal;  // below it the angle criteria are not applied (as BRepMesh's MinSize)
      const double chord = s.pa.Distance(s.pb);
      if (!info.straight) {
        for (double f : {0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875})
          if (distanceToSegment(curveValue(s.ta + f * (s.tb - s.ta)), s.pa, s.pb) > crit.chordal) return true;
        if (offChordAtKnots(s.ta, s.tb, s.pa, s.pb, crit.chordal)) return true;
        if (hull && hull->leaves(s.ta, s.tb, s.pa, s.pb, crit.chordal)) return true;
        if (chord > minSize) {
          const gp_Vec chordDir(s.pa, s.pb);
          if (angleBetween(s.da, s.db) > crit.angleRad || angleBetween(s.da, chordDir) > crit.angleRad ||
              angleBetween(chordDir, s.db) > crit.angleRad)
            return true;
        }
      }
      if (surfaceLeavesChord(s.ta, s.tb, s.pa, s.pb, crit.chordal)) return true;
      if (!(chord > minSize)) return false;
      for (std::size_t k = 0; k < uses; ++k)
        if (angleBetween(s.na[k], s.nb[k]) > crit.angleRad) return true;
      return standingFails(s.ta, s.tb, s.pa, s.pb, s.na, s.nb, crit);
    };
    auto itemAt = [&](double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb) {
      Item s{ta, tb, pa, pb, {}, {}, {}, {}, 0};
      gp_Pnt tmp;
      curveD1(ta, tmp, s.da);
      curveD1(tb, tmp, s.db);
      gp_Vec unused[2];
      normalsAt(ta, unused, s.na);
      normalsAt(tb, s.nb, unused);
      return s;
    };
    if (seedT.empty()) {
      // Coarsest: one segment for a line, three for a closed edge (a loop of its own must be a
      // polygon), and for a curve one where that chord alone meets the final level's criteria (a
      // slight arc: it then stays one segment on every level), else two. Beside a torus or a
      // free-form face with a quarter of the chordal tolerance: a chord sagging nearly the whole
      // tolerance there keeps the face's points away (its clearance) where two chords, sagging a
      // quarter as much, let them in (Bottom's face 50 at 1% kept 60-degree edges). Not where
      // another edge joins the same two vertices: two single chords between them would close a
      // loop of no area.
      int segments = info.closed ? 3 : (info.straight ? 1 : 2);
      Level slight = tolerances_.back();
      for (const FaceUse& use : info.faces)
        if (use.scale->bendsBeside) slight.chordal = 0.25 * tolerances_.back().chordal;
      if (segments == 2 && !info.sharesEnds && !misses(itemAt(info.first, info.last, info.p0, info.p1), slight))
        segments = 1;
      for (int i = 0; i <= segments; ++i) seedT.push_back(info.first + (info.last - info.first) * i / segments);
    }
    auto pointAt = [&](std::size_t i, double t) {
      if (i == 0) return info.p0;
      if (i + 1 == seedT.size()) return info.p1;
      return curve.Value(t);  // a vertex of the mesh: the adaptor's point (see curveValue)
    };
    std::vector<Item> stack;
    std::size_t examined = 0;
    gp_Pnt pPrev = pointAt(0, seedT[0]);
    gp_Pnt tmp;
    gp_Vec dPrev, nPrev[2], nUnused[2];
    curveD1(seedT[0], tmp, dPrev);
    normalsAt(seedT[0], nUnused, nPrev);
    out.t.push_back(seedT[0]);
    out.p.push_back(pPrev);
    for (std::size_t i = 1; i < seedT.size(); ++i) {
      const gp_Pnt pNext = pointAt(i, seedT[i]);
      gp_Vec dNext, nNext[2], nNextAbove[2];  // the limits coming from this segment and from the next
      curveD1(seedT[i], tmp, dNext);
      normalsAt(seedT[i], nNext, nNextAbove);
      // Depth-first, right half pushed first, so points come out in increasing t.
      stack.push_back({seedT[i - 1], seedT[i], pPrev, pNext, dPrev, dNext, {nPrev[0], nPrev[1]}, {nNext[0], nNext[1]}, 0});
      while (!stack.empty()) {
        // An edge far off its surface can take tens of milliseconds and thousands of points.
        if (++examined % 64 == 0 && cancel && cancel->load(std::memory_order_relaxed)) return false;
        Item s = stack.back();
        stack.pop_back();
        const bool full = out.t.size() + stack.size() + (seedT.size() - i) >= kMaxPoints;
        out.capped = out.capped || full;
        if (full || !misses(s, tol)) {
          out.t.push_back(s.tb);
          out.p.push_back(s.pb);
          continue;
        }
        const double tm = 0.5 * (s.ta + s.tb);
        gp_Pnt pm;
        gp_Vec dm, nmBelow[2], nmAbove[2];
        curve.D1(tm, pm, dm);  // a vertex of the mesh: the adaptor's point (see curveValue)
        normalsAt(tm, nmBelow, nmAbove);
        stack.push_back(
            {tm, s.tb, pm, s.pb, dm, s.db, {nmAbove[0], nmAbove[1]}, {s.nb[0], s.nb[1]}, s.depth + 1});
        stack.push_back(
            {s.ta, tm, s.pa, pm, s.da, dm, {s.na[0], s.na[1]}, {nmBelow[0], nmBelow[1]}, s.depth + 1});
      }
      pPrev = pNext;
      dPrev = dNext;
      nPrev[0] = nNextAbove[0], nPrev[1] = nNextAbove[1];
    }
  } catch (const Standard_Failure&) {
    out.t = {info.first, info.last};
    out.p = {info.p0, info.p1};
    out.capped = false;
  }
  return true;
}

}  // namespace cetview::brep
