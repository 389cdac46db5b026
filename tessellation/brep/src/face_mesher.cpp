// Coarse-to-fine meshing of one face on the CET triangulator.
//
// Sources: Yang & Choi (2010) for the CET arrays and the sequential constrained Delaunay insertion;
// Eryar, "Delaunay surface visualization", for faces as constrained triangulations of their trimming
// loops in UV with holes removed by orientation; Laug & Borouchaki (2016) for the proximity and
// regularity criteria, applied here to triangles. A triangle is split
//  - where the exact surface deviates from it by more than the level's chordal tolerance: samples
//    of the flat triangle (centroid and free-edge midpoints; a barycentric grid on doubly curved
//    surfaces) projected onto the surface; the corresponding-point distance |S(uv) - M| guards
//    coverage (a triangle whose UV region maps far from it, across a seam or a pole, is split too);
//  - where the surface normals at its corners differ by more than the angular tolerance;
//  - where it is flipped or nearly edge-on against its corners' normals (split on its longest edge).
// Points go in batches, one per neighbourhood per pass (an independent set), and never closer to a
// boundary chord than the surface bulges under it (see buildChords): Delaunay keeps the closest apex
// on a constrained edge, so a point there would leave a flipped triangle for good.
#include "face_mesher.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>

#include <BRepAdaptor_Surface.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <Standard_Failure.hxx>
#include <gp_Torus.hxx>

#include "cet/predicates.h"
#include "deviation_peak.h"
#include "edge_table.h"
#include "facet_rules.h"
#include "measure_impl.h"
#include "split_point.h"
#include "work_sharing.h"

namespace cetview::brep {
namespace {

// Passes of batch insertion per level. A pass splits an independent set of the offending triangles
// (at least one), so this bounds a level's refinement depth, not its work (the point bound does
// that). At 400 a fuzzed face's last level ended there silently, 6.2x over its tolerance and
// reported ok (seed 404 input 240: 625k triangles, 112 of them over); a level that ends here is
// reported as the point bound's are.
constexpr int kMaxPasses = 4096;
// Splits of flipped triangles per face and level, of any size. A few end an orientation error
// (Propeller's blade tips took 4; over the sample models at 1%, 0.1% and 0.01% no face splits more
// than 511 on a level: terrain's level 0, and A319's one level when meshed without coarser ones at
// 0.01%, the most); where a fold of the surface's
// parametrisation meets a pole, every split made another flipped sliver beside it, down to a
// thousandth of the tolerance below the minimum size (a fuzzed folded sheet: 2.1 million
// triangles in 13 s), and above it on flat and folded sheets (fuzzed faces: a plane's last level,
// 52 triangles before it, took 81396, 11208 flipped, its splits creeping towards a pole row; with
// the bound 506 and 85).
constexpr int kMaxFlippedSplits = 1024;
// Fold points (FaceMesher::foldPoint): edges across a fold are split on it down to this fraction of
// the level's tolerance.
constexpr double kFoldFloor = 1e-3;
constexpr int kFoldTrouble = 16;  // see refine()
// FaceMesher::alongChord: a flipped triangle no wider across a boundary chord's line than this
// fraction of its longest edge is not split. At a thousandth, the fuzzed zigzag sheet's cascade
// stopped by the chord and began again beside the slivers it left (119k triangles on level 0).
constexpr double kAlongChordBand = 1e-2;
// Points one level's refinement of a face may add: the most of this floor and this many times the
// points the face had before, up to the ceiling. Over the 62 bench models a level adds at most 127k
// (terrain's level 0) and 36 times its points before; terrain at 0.001% has 617k points in all.
// Fuzzed faces whose refinement does not converge (rational patches with wild weights by a pole,
// chasing corresponding-point distances) ran to millions of points and gigabytes in minutes on one
// level, and a face that starts from 19k boundary points (an edge far off its surface) was allowed
// 5.1 million. A face so stopped is reported, shows what it has, and is not refined further on
// later levels.
constexpr std::size_t kRefineFloor = 250000;
constexpr std::size_t kRefineGrowth = 256;
constexpr std::size_t kRefineCeiling = 1000000;
// Triangles per chunk when a pass's measuring is shared out (a triangle takes a few microseconds).
constexpr std::size_t kMeasureGrain = 64;
// Triangles measured or decided between two reads of the cancel flag.
constexpr std::size_t kCancelGrain = 16;

double signedArea(const std::vector<cet::Point2>& pts, const std::vector<cet::VertexId>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const cet::Point2 p = pts[loop[i]], q = pts[loop[(i + 1) % loop.size()]];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * a;
}

// The triangulator's predicates are exact only for coordinates in its range (cet/types.h): zero or
// magnitudes in [1e-50, 1e50]. Outside it an orientation test can contradict another, and a point
// location walk can cycle for ever.
bool supported(const cet::Point2& p) { return cet::supportedCoordinate(p.x) && cet::supportedCoordinate(p.y); }

// A flipped or folded triangle below the level's minimum size is still split (down to a thousandth
// of the tolerance) where one point inside it ends the fault:
// - a corner is a pole: a triangle fanning from a pole's row onto a straight edge out of the pole
//   has its corners on one line in 3D (edge-on), however small;
// - it faces away from its corners' normals while they agree (normalCos >= 0: no free edge between
//   regular corners turns them by 90 degrees or more): a real orientation error, which coarse
//   levels left on Propeller's thin blade tips (a triangle 0.98 long at a level whose minimum size
//   is 1.09). Where the corners' normals oppose, the surface's own parametrisation folds between
//   them (A319's wing tip, a sheet folded flat): no triangle across the fold faces both ways, and
//   splitting there only makes more of them (1853 flipped on A319's level 4).
bool splitsBelowMinSize(const TriangleRecord& r) {
  if (r.flags & TriangleRecord::kPoleCorner) return true;
  const bool flipped = (r.flags & TriangleRecord::kFlipped) || r.facetCos < 0;
  return flipped && r.normalCos >= 0;
}

}  // namespace

std::size_t refinePointBound(std::size_t pointsBefore, std::size_t requested) {
  if (requested > 0) return requested;
  return std::clamp(kRefineGrowth * pointsBefore, kRefineFloor, kRefineCeiling);
}

bool traceFace(FaceId face) {
  static const char* const which = std::getenv("CETVIEW_DEBUG_REFINE");
  if (!which) return false;
  char* end = nullptr;
  const unsigned long n = std::strtoul(which, &end, 10);
  return end == which || *end != '\0' || n == face;
}

FaceMesher::FaceMesher(FaceTopology topology, const FaceMesherSettings& settings, std::unique_ptr<SurfaceEval> eval)
    : topology_(std::move(topology)),
      settings_(settings),
      ownEval_(eval ? std::move(eval)
                    : std::make_unique<SurfaceEval>(topology_.face, kDeviationMargin * settings.finalChordal, settings.finalAngle)),
      eval_(*ownEval_) {
  const GeomAbs_SurfaceType type = eval_.adaptor().GetType();
  // Ruled surfaces (planes, cylinders, cones) deviate from a triangle as a quadratic whose maximum
  // the centroid and edge midpoints catch; doubly curved ones can peak elsewhere in big triangles.
  freeform_ = type != GeomAbs_Plane && type != GeomAbs_Cylinder && type != GeomAbs_Cone;
  exactDeviation_ = eval_.exactTriangleDeviation();
  peakSampled_ = !exactDeviation_ && eval_.closedFormDistance();
  if (eval_.adaptor().IsUPeriodic()) uPeriod_ = eval_.adaptor().UPeriod();
  if (eval_.adaptor().IsVPeriodic()) vPeriod_ = eval_.adaptor().VPeriod();
  for (const std::string& r : topology_.repairs) repairs_.push_back(r);
  repaired_ = !repairs_.empty();
}

void FaceMesher::appendVertex(FaceMesh& mesh, double u, double v, const gp_Pnt* p) {
  gp_Pnt s;
  gp_Dir n;
  const bool regular = eval_.pointNormal(u, v, s, n);
  const gp_Pnt& q = p ? *p : s;
  mesh.positions.insert(mesh.positions.end(), {q.X(), q.Y(), q.Z()});
  const double sign = settings_.reversed ? -1.0 : 1.0;
  mesh.normals.insert(mesh.normals.end(), {static_cast<float>(sign * n.X()), static_cast<float>(sign * n.Y()),
                                           static_cast<float>(sign * n.Z())});
  mesh.uv.insert(mesh.uv.end(), {u, v});
  normal_.push_back(n);
  singular_.push_back(regular ? 0 : 1);
  offset_.push_back(p ? static_cast<float>(p->Distance(s)) : 0.0f);
}

void FaceMesher::appendFoldTwin(FaceMesh& mesh, cet::VertexId v, const gp_Dir& before, const gp_Dir& after) {
  const std::size_t o = out(v);
  const double sign = settings_.reversed ? -1.0 : 1.0;
  normal_[v] = before;
  for (int i = 0; i < 3; ++i) mesh.normals[3 * o + i] = static_cast<float>(sign * before.Coord(i + 1));
  singular_[v] = 0;  // its normals are the limits, each regular on its side
  folds_[v] = FoldVertex{after, appendTwin(mesh, v, after)};
}

std::uint32_t FaceMesher::appendTwin(FaceMesh& mesh, cet::VertexId v, const gp_Dir& other) {
  const std::size_t o = out(v);
  const double sign = settings_.reversed ? -1.0 : 1.0;
  const auto twin = static_cast<std::uint32_t>(mesh.vertexCount());
  const double p[3] = {mesh.positions[3 * o], mesh.positions[3 * o + 1], mesh.positions[3 * o + 2]};
  const double uv[2] = {mesh.uv[2 * o], mesh.uv[2 * o + 1]};
  mesh.positions.insert(mesh.positions.end(), p, p + 3);
  mesh.uv.insert(mesh.uv.end(), uv, uv + 2);
  mesh.normals.insert(mesh.normals.end(),
                      {static_cast<float>(sign * other.X()), static_cast<float>(sign * other.Y()),
                       static_cast<float>(sign * other.Z())});
  // The triangulator vertices not appended yet come after the twin.
  outShift_.emplace_back(static_cast<cet::VertexId>(normal_.size()),
                         (outShift_.empty() ? 0 : outShift_.back().second) + 1);
  return twin;
}

const gp_Dir& FaceMesher::sideNormal(cet::VertexId v, const gp_Vec& side) const {
  if (folds_.empty()) return normal_[v];
  const auto it = folds_.find(v);
  if (it == folds_.end()) return normal_[v];
  return gp_Vec(it->second.other).Dot(side) > gp_Vec(normal_[v]).Dot(side) ? it->second.other : normal_[v];
}

std::uint32_t FaceMesher::shownVertex(cet::VertexId v, const gp_Vec& side) const {
  for (const auto* twins : {&folds_, &singularTwins_}) {
    if (twins->empty()) continue;
    const auto it = twins->find(v);
    if (it != twins->end() && gp_Vec(it->second.other).Dot(side) > gp_Vec(normal_[v]).Dot(side))
      return it->second.twin;
  }
  if (!creaseCorners_.empty()) {
    const auto it = creaseCorners_.find(v);
    if (it != creaseCorners_.end() && it->second.twin != kNoTwin &&
        gp_Vec(it->second.other).Dot(side) > gp_Vec(it->second.shown).Dot(side))
      return it->second.twin;
  }
  return out(v);
}

gp_Vec FaceMesher::triangleSide(const cet::VertexId v[3], const gp_Pnt P[3]) const {
  gp_Vec side(0, 0, 0);
  for (int i = 0; i < 3; ++i)
    if (!singular_[v[i]] && !isFold(v[i]) && !isCreaseCorner(v[i])) side += gp_Vec(normal_[v[i]]);
  if (side.Magnitude() >= 0.5) return side;
  return gp_Vec(P[0], P[1]).Crossed(gp_Vec(P[0], P[2]));
}

bool FaceMesher::foldPoint(cet::TriangleId t, const FaceMesh& mesh, double angleRad, double& u, double& v,
                           gp_Dir& before, gp_Dir& after) {
  const cet::CetMesh& m = cdt_->mesh();
  double longest = -1;
  for (int i = 0; i < 3; ++i) {
    if (m.isConstrained(t, i)) continue;
    const cet::VertexId a = m.vertex(t, (i + 1) % 3), b = m.vertex(t, (i + 2) % 3);
    if (singular_[a] || singular_[b] || isFold(a) || isFold(b) || normal_[a].Dot(normal_[b]) >= 0) continue;
    const std::size_t oa = out(a), ob = out(b);
    const double ua = mesh.uv[2 * oa], va = mesh.uv[2 * oa + 1], ub = mesh.uv[2 * ob],
                 vb = mesh.uv[2 * ob + 1];
    if (eval_.crossesCrease(ua, va, ub, vb)) continue;
    const double length = position(mesh, a).Distance(position(mesh, b));
    if (length <= longest) continue;
    const std::uint64_t key = (std::uint64_t{a} << 32) | b;
    if (noFold_.count(key)) continue;
    double at = 0;
    gp_Dir n0, n1;
    if (!eval_.findFold(ua, va, ub, vb, normal_[a], normal_[b], angleRad, at, n0, n1)) {
      noFold_.insert(key);
      continue;
    }
    longest = length;
    u = ua + at * (ub - ua), v = va + at * (vb - va);
    before = n0, after = n1;
  }
  return longest >= 0;
}

bool FaceMesher::foldBetween(cet::VertexId a, cet::VertexId b, const FaceMesh& mesh, double angleRad,
                             double& u, double& v, gp_Dir& before, gp_Dir& after) const {
  const std::size_t oa = out(a), ob = out(b);
  const double mu = 0.5 * (mesh.uv[2 * oa] + mesh.uv[2 * ob]),
               mv = 0.5 * (mesh.uv[2 * oa + 1] + mesh.uv[2 * ob + 1]);
  const double pu = -0.5 * (mesh.uv[2 * ob + 1] - mesh.uv[2 * oa + 1]),
               pv = 0.5 * (mesh.uv[2 * ob] - mesh.uv[2 * oa]);
  gp_Pnt p;
  gp_Dir n0, n1;
  if (!eval_.pointNormal(mu - pu, mv - pv, p, n0) || !eval_.pointNormal(mu + pu, mv + pv, p, n1))
    return false;
  double at = 0;
  if (!eval_.findFold(mu - pu, mv - pv, mu + pu, mv + pv, n0, n1, angleRad, at, before, after)) return false;
  u = mu - pu + 2 * at * pu, v = mv - pv + 2 * at * pv;
  return true;
}

// Where an edge's pcurve and its 3D curve disagree (an edge of large tolerance, common in IGES),
// the pcurve's (u, v) maps to a surface point away from the shared 3D edge point, and the
// triangles between such boundary points and interior points (which sit at their own (u, v)) fold
// over the gap. The (u, v) of the edge point's foot on the surface keeps the two consistent. From
// gaps of 1% of the tolerance: a thin triangle flips over less (a 4.5% gap left one flipped on a
// cylinder of occt/trj4).
gp_Pnt2d FaceMesher::boundaryUV(const LoopEdge& le, double t, const gp_Pnt& p) const {
  gp_Pnt2d uv = le.pcurve->Value(le.pcurveParameter(t)).Translated(le.shift);
  const double gap = eval_.point(uv.X(), uv.Y()).Distance(p);
  if (!(gap > 0.01 * settings_.finalChordal)) return uv;
  double u = uv.X(), v = uv.Y();
  const double foot = eval_.project(p, u, v, 8);
  // Only a foot clearly closer than the pcurve's point, and within half the face's parameter box of
  // it (the pcurve may be parametrised quite differently from its edge, but not on another sheet).
  const double reach = 0.5 * std::max(eval_.uMax - eval_.uMin, eval_.vMax - eval_.vMin);
  if (foot < 0.5 * gap && std::abs(u - uv.X()) <= reach && std::abs(v - uv.Y()) <= reach) uv.SetCoord(u, v);
  return uv;
}

// ---------------------------------------------------------------------------------------------
// Level 0 (or a rebuild): the whole domain from the edge points of level k.
bool FaceMesher::buildDomain(int k, const EdgeTable& edges, FaceMesh& mesh, std::string& problem,
                             const std::atomic<bool>* cancel, bool& cancelled) {
  // A boundary of hundreds of thousands of points (an edge at its point bound) takes a second.
  std::size_t steps = 0;
  auto stop = [&] {
    if (cancel && ++steps % cet::Triangulator::kCancelStride == 0 && cancel->load(std::memory_order_relaxed))
      cancelled = true;
    return cancelled;
  };
  cdt_ = std::make_unique<cet::Triangulator>();
  base_ = static_cast<std::uint32_t>(mesh.vertexCount());
  clearVertexData();
  foldPointCount_ = 0;
  foldsFailed_ = false;
  records_.clear();
  touched_.clear();

  // Points of each occurrence in increasing parameter: natural UV and 3D.
  struct OccPoints {
    std::vector<gp_Pnt2d> uv;
    std::vector<gp_Pnt> p;
  };
  std::vector<std::vector<OccPoints>> occPoints(topology_.loops.size());
  for (std::size_t l = 0; l < topology_.loops.size(); ++l) {
    const auto& loop = topology_.loops[l];
    occPoints[l].resize(loop.size());
    double lengthSum = 0;
    std::size_t segmentCount = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const LoopEdge& le = loop[i];
      if (le.degenerated) continue;
      const EdgePoints& ep = edges.points(le.edge, k);
      OccPoints& op = occPoints[l][i];
      for (std::size_t j = 0; j < ep.t.size(); ++j) {
        if (stop()) return false;
        op.uv.push_back(boundaryUV(le, ep.t[j], ep.p[j]));
        op.p.push_back(ep.p[j]);
        if (j > 0) {
          const cet::Point2 a = scaled(op.uv[j - 1].X(), op.uv[j - 1].Y()), b = scaled(op.uv[j].X(), op.uv[j].Y());
          lengthSum += std::hypot(b.x - a.x, b.y - a.y);
          ++segmentCount;
        }
      }
    }
    // Degenerate edges (poles, apexes) belong to this face alone: split them so their segments are
    // about as long in scaled UV as the loop's others (poleSegments). On a flat face the plane takes
    // the whole edge to one point, as the surface does: the edge is that point alone, which the
    // junctions below share with the edges on either side (its ends, rounding apart there, made
    // boundary segments crossing at the pole).
    const double typical = segmentCount ? lengthSum / static_cast<double>(segmentCount) : 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const LoopEdge& le = loop[i];
      if (!le.degenerated) continue;
      const gp_Pnt2d a = le.pcurve->Value(le.pcurveFirst).Translated(le.shift);
      OccPoints& op = occPoints[l][i];
      if (eval_.flat()) {
        op.uv.push_back(a);
        op.p.push_back(le.pole);
        continue;
      }
      const gp_Pnt2d b = le.pcurve->Value(le.pcurveLast).Translated(le.shift);
      const cet::Point2 sa = scaled(a.X(), a.Y()), sb = scaled(b.X(), b.Y());
      const double len = std::hypot(sb.x - sa.x, sb.y - sa.y);
      const int n = poleSegments(len, typical);
      for (int j = 0; j <= n; ++j) {
        const double t = le.pcurveFirst + (le.pcurveLast - le.pcurveFirst) * j / n;
        op.uv.push_back(le.pcurve->Value(t).Translated(le.shift));
        op.p.push_back(le.pole);
      }
    }
  }

  // Loops as polygons of triangulator ids in loop direction. Consecutive occurrences share their
  // junction point when their pcurves meet; a gap in UV stays as a short segment whose two ends are
  // the same 3D vertex (the triangles on it have no area and are dropped).
  const double mergeDistance = std::max(0.1 * settings_.finalChordal, 1e-12);
  auto newPoint = [&](const gp_Pnt2d& uv, const gp_Pnt& p) {
    const cet::VertexId id = static_cast<cet::VertexId>(points_.size());
    points_.push_back(scaled(uv.X(), uv.Y()));
    appendVertex(mesh, uv.X(), uv.Y(), &p);
    return id;
  };
  auto close = [&](cet::VertexId a, const gp_Pnt2d& uv) {
    const cet::Point2 p = points_[a], q = scaled(uv.X(), uv.Y());
    return std::hypot(p.x - q.x, p.y - q.y) <= mergeDistance;
  };
  std::vector<std::vector<cet::VertexId>> loops;
  std::vector<std::vector<std::size_t>> loopOccurrences;
  bool gapBridged = false;
  for (std::size_t l = 0; l < topology_.loops.size(); ++l) {
    const auto& loop = topology_.loops[l];
    std::vector<cet::VertexId> ids;
    std::vector<std::size_t> occs;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const OccPoints& op = occPoints[l][i];
      const std::size_t n = op.uv.size();
      if (n == 0) continue;
      Occurrence occ;
      occ.loop = l, occ.index = i, occ.forward = !loop[i].reversed;
      occ.chain.assign(n, cet::kNoVertex);
      for (std::size_t s = 0; s < n; ++s) {
        if (stop()) return false;
        const std::size_t j = occ.forward ? s : n - 1 - s;
        const bool firstOfOcc = s == 0, lastOfLoop = i + 1 == loop.size() && s + 1 == n;
        if (firstOfOcc && !ids.empty()) {
          if (close(ids.back(), op.uv[j])) {
            occ.chain[j] = ids.back();
            continue;
          }
          if (!gapBridged) repairs_.push_back("bridged a UV gap between consecutive pcurves");
          gapBridged = repaired_ = true;
        }
        if (lastOfLoop && !ids.empty() && ids.size() > 1 && close(ids.front(), op.uv[j])) {
          occ.chain[j] = ids.front();
          continue;
        }
        occ.chain[j] = newPoint(op.uv[j], op.p[j]);
        ids.push_back(occ.chain[j]);
      }
      occs.push_back(occurrences_.size());
      occurrences_.push_back(std::move(occ));
    }
    loops.push_back(std::move(ids));
    loopOccurrences.push_back(std::move(occs));
  }

  // Orientation: the loop of largest area is the outer one and must run counter-clockwise, the
  // others clockwise (cet::DomainRule::kLoopOrientation). Wrongly oriented wires are reversed;
  // loops without area bound nothing and are dropped.
  std::vector<double> areas(loops.size());
  std::size_t outer = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    areas[l] = loops[l].size() >= 3 ? signedArea(points_, loops[l]) : 0.0;
    if (std::abs(areas[l]) > std::abs(areas[outer])) outer = l;
  }
  if (loops.empty() || !(std::abs(areas[outer]) > 0)) {
    problem = "the boundary encloses no area in UV";
    return false;
  }
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (std::abs(areas[l]) <= 1e-12 * std::abs(areas[outer])) {
      repairs_.push_back("dropped a wire that encloses no area");
      repaired_ = true;
      loops[l].clear();
      continue;
    }
    const bool wantPositive = l == outer;
    if ((areas[l] > 0) != wantPositive) {
      std::reverse(loops[l].begin(), loops[l].end());
      for (std::size_t o : loopOccurrences[l]) occurrences_[o].forward = !occurrences_[o].forward;
      repairs_.push_back(wantPositive ? "outer wire ran clockwise in UV; reversed" : "inner wire ran counter-clockwise in UV; reversed");
      repaired_ = true;
    }
  }
  // Occurrences of dropped loops take no part in boundary refinement.
  occurrences_.erase(std::remove_if(occurrences_.begin(), occurrences_.end(),
                                    [&](const Occurrence& o) { return loops[o.loop].empty(); }),
                     occurrences_.end());

  for (const cet::Point2& p : points_) {
    if (!supported(p)) {
      problem = "boundary parameters outside the triangulator's range";
      return false;
    }
  }
  cdt_->reserve(points_.size() * 4);
  cdt_->addVertices(points_.data(), points_.size());
  if (!cdt_->insertPending(false, cancel)) {
    cancelled = cdt_->cancelled();
    if (!cancelled) problem = "all boundary points are collinear in UV";
    return false;
  }
  for (const auto& loop : loops) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (stop()) return false;
      const cet::VertexId a = cdt_->representative(loop[i]), b = cdt_->representative(loop[(i + 1) % loop.size()]);
      if (a == b) continue;
      const cet::Status s = cdt_->insertSegment(a, b);
      if (!s.ok()) {
        problem = "boundary crosses itself in UV (" + s.message + ")";
        return false;
      }
    }
  }
  cdt_->markDomain(cet::DomainRule::kLoopOrientation);
  if (cdt_->insideTriangleCount() == 0) {
    problem = "no triangle inside the boundary";
    return false;
  }
  boundaryLevel_ = k;
  return true;
}

bool FaceMesher::buildDomainFlatOrScaled(int k, const EdgeTable& edges, FaceMesh& mesh, std::string& problem,
                                         const std::atomic<bool>* cancel, bool& cancelled) {
  const std::size_t repairCount = repairs_.size();
  const bool wasRepaired = repaired_;
  flatRetry_ = false;
  const bool ok = buildDomain(k, edges, mesh, problem, cancel, cancelled);
  if (ok || cancelled || !eval_.flat()) return ok;
  abandonBuild(mesh);
  repairs_.resize(repairCount);
  repaired_ = wasRepaired;
  problem.clear();
  ownEval_->useFlat(false);
  flatRetry_ = true;
  return buildDomain(k, edges, mesh, problem, cancel, cancelled);
}

// ---------------------------------------------------------------------------------------------
// Later levels: every boundary segment that its edge split at level k becomes the chain through the
// new points; degenerate edges (one 3D point) are split evenly in UV to keep pace with their loop.
bool FaceMesher::refineBoundary(int k, const EdgeTable& edges, FaceMesh& mesh, std::string& problem,
                                const std::atomic<bool>* cancel, bool& cancelled) {
  BoundaryProgress& progress = boundaryProgress_;
  if (progress.target != k) {
    if (progress.target >= 0) {  // advanceFace() resumes the level it was cancelled on
      problem = "internal: boundary refinement resumed for another level";
      return false;
    }
    progress = BoundaryProgress{};
    progress.target = k;
  }
  std::vector<gp_Pnt2d> uvs;
  std::vector<const gp_Pnt*> ps;
  for (; progress.occurrence < occurrences_.size(); ++progress.occurrence) {
    Occurrence& occ = occurrences_[progress.occurrence];
    const LoopEdge& le = topology_.loops[occ.loop][occ.index];
    if (le.degenerated) continue;
    const EdgePoints& now = edges.points(le.edge, k);
    const EdgePoints& before = edges.points(le.edge, boundaryLevel_);
    if (now.t.size() == before.t.size()) continue;
    if (before.t.size() != occ.chain.size()) {
      problem = "internal: boundary chain out of step with its edge";
      return false;
    }
    std::vector<cet::VertexId>& chain = progress.chain;
    if (progress.segment == 0) {
      chain.clear();
      chain.reserve(now.t.size());
      progress.next = 0;
    }
    std::size_t& j = progress.next;
    for (std::size_t& o = progress.segment; o + 1 < before.t.size(); ++o) {
      if (cancel && cancel->load(std::memory_order_relaxed)) {
        cancelled = true;
        return false;
      }
      chain.push_back(occ.chain[o]);
      while (j < now.t.size() && now.t[j] <= before.t[o]) ++j;
      uvs.clear(), ps.clear();
      for (; j < now.t.size() && now.t[j] < before.t[o + 1]; ++j) {
        uvs.push_back(boundaryUV(le, now.t[j], now.p[j]));
        ps.push_back(&now.p[j]);
      }
      if (!splitSegment(occ, o, uvs, ps, chain, mesh, problem)) return false;
    }
    chain.push_back(occ.chain.back());
    occ.chain.swap(chain);
    progress.segment = 0;
  }
  if (!refinePoles(mesh, problem)) return false;
  cdt_->markDomain(cet::DomainRule::kLoopOrientation);
  boundaryLevel_ = k;
  progress = BoundaryProgress{};
  return true;
}

// Replaces the boundary segment from occ.chain[o] to occ.chain[o + 1] by the chain through the
// points (uvs, with 3D points ps, in increasing parameter), appending their ids to chain.
bool FaceMesher::splitSegment(const Occurrence& occ, std::size_t o, std::vector<gp_Pnt2d>& uvs,
                              std::vector<const gp_Pnt*>& ps, std::vector<cet::VertexId>& chain, FaceMesh& mesh,
                              std::string& problem) {
  if (uvs.empty()) return true;
  segmentPoints_.clear();
  for (const gp_Pnt2d& uv : uvs) segmentPoints_.push_back(scaled(uv.X(), uv.Y()));
  if (!std::all_of(segmentPoints_.begin(), segmentPoints_.end(), supported)) {
    problem = "refined boundary parameters outside the triangulator's range";
    return false;
  }
  if (!occ.forward) {
    std::reverse(segmentPoints_.begin(), segmentPoints_.end());
    std::reverse(uvs.begin(), uvs.end());
    std::reverse(ps.begin(), ps.end());
  }
  ids_.assign(segmentPoints_.size(), cet::kNoVertex);
  const auto countBefore = static_cast<cet::VertexId>(cdt_->vertexCount());
  const cet::VertexId a = occ.forward ? occ.chain[o] : occ.chain[o + 1];
  const cet::VertexId b = occ.forward ? occ.chain[o + 1] : occ.chain[o];
  const cet::Status s = cdt_->replaceConstraint(a, b, segmentPoints_.data(), segmentPoints_.size(), ids_.data());
  // New triangulator vertices get their output data in id order (the order of the points).
  cet::VertexId next = countBefore;
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    if (ids_[i] == next) {
      appendVertex(mesh, uvs[i].X(), uvs[i].Y(), ps[i]);
      ++next;
    }
  }
  while (next < cdt_->vertexCount()) {  // defensive: any vertex not matched above
    const cet::Point2 q = cdt_->point(next);
    double u = 0, v = 0;
    eval_.unscaled(q, u, v);
    appendVertex(mesh, u, v, nullptr);
    ++next;
  }
  if (!s.ok()) {
    problem = "refined boundary crosses itself in UV (" + s.message + ")";
    return false;
  }
  if (!occ.forward) std::reverse(ids_.begin(), ids_.end());
  chain.insert(chain.end(), ids_.begin(), ids_.end());
  return true;
}

// A degenerate edge's segments, as long in scaled UV as the typical segment of its loop: the
// triangles fanning into a pole or apex stay well shaped in UV, and their corners on the pole row
// stay close in UV to the interior points they join (a fan corner far away in u folds the facet).
int FaceMesher::poleSegments(double length, double typical) {
  return typical > 0 ? std::clamp(static_cast<int>(std::lround(length / typical)), 1, kMaxPoleSegments) : 4;
}

// Degenerate edges split to keep pace with their loop's refined edges: each segment into the same
// number of equal parts in pcurve parameter, so every level's pole points are among the next one's.
bool FaceMesher::refinePoles(FaceMesh& mesh, std::string& problem) {
  std::vector<double> lengthSum(topology_.loops.size(), 0.0);
  std::vector<std::size_t> segmentCount(topology_.loops.size(), 0);
  bool anyPole = false;
  for (const Occurrence& occ : occurrences_) {
    if (topology_.loops[occ.loop][occ.index].degenerated) {
      anyPole = true;
      continue;
    }
    for (std::size_t i = 1; i < occ.chain.size(); ++i) {
      const cet::Point2 a = cdt_->point(occ.chain[i - 1]), b = cdt_->point(occ.chain[i]);
      lengthSum[occ.loop] += std::hypot(b.x - a.x, b.y - a.y);
      ++segmentCount[occ.loop];
    }
  }
  if (!anyPole) return true;
  std::vector<gp_Pnt2d> uvs;
  std::vector<const gp_Pnt*> ps;
  std::vector<cet::VertexId> chain;
  for (Occurrence& occ : occurrences_) {
    const LoopEdge& le = topology_.loops[occ.loop][occ.index];
    if (!le.degenerated || occ.chain.size() < 2 || segmentCount[occ.loop] == 0) continue;
    const double typical = lengthSum[occ.loop] / static_cast<double>(segmentCount[occ.loop]);
    const gp_Pnt2d first = le.pcurve->Value(le.pcurveFirst).Translated(le.shift);
    const gp_Pnt2d last = le.pcurve->Value(le.pcurveLast).Translated(le.shift);
    const cet::Point2 sa = scaled(first.X(), first.Y()), sb = scaled(last.X(), last.Y());
    const std::size_t segments = occ.chain.size() - 1;
    const std::size_t parts = static_cast<std::size_t>(
        std::lround(static_cast<double>(poleSegments(std::hypot(sb.x - sa.x, sb.y - sa.y), typical)) / segments));
    if (parts < 2) continue;
    chain.clear();
    for (std::size_t o = 0; o < segments; ++o) {
      chain.push_back(occ.chain[o]);
      uvs.clear(), ps.clear();
      for (std::size_t r = 1; r < parts; ++r) {
        const double f = static_cast<double>(o * parts + r) / static_cast<double>(segments * parts);
        uvs.push_back(le.pcurve->Value(le.pcurveFirst + (le.pcurveLast - le.pcurveFirst) * f).Translated(le.shift));
        ps.push_back(&le.pole);
      }
      if (!splitSegment(occ, o, uvs, ps, chain, mesh, problem)) return false;
    }
    chain.push_back(occ.chain.back());
    occ.chain.swap(chain);
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
bool FaceMesher::edgeSamplesFromNeighbour(cet::TriangleId t, int i, float& deviation, float& corresponding) const {
  const cet::CetMesh& m = cdt_->mesh();
  const cet::TriangleId n = m.neighbor(t, i);
  if (n == cet::kNoTriangle || m.isGhost(n)) return false;
  const TriangleRecord* r = records_.find(n, m.vertex(n, 0), m.vertex(n, 1), m.vertex(n, 2));
  if (!r) return false;
  const int j = m.edgeTo(n, t);
  if (j < 0 || r->edgeDeviation[j] < 0) return false;
  deviation = r->edgeDeviation[j], corresponding = r->edgeCorresponding[j];
  return true;
}

gp_Pnt FaceMesher::position(const FaceMesh& mesh, cet::VertexId v) const {
  const std::size_t o = out(v);
  return gp_Pnt(mesh.positions[3 * o], mesh.positions[3 * o + 1], mesh.positions[3 * o + 2]);
}

FaceMesher::Corners FaceMesher::corners(cet::TriangleId t, const FaceMesh& mesh) const {
  const cet::CetMesh& m = cdt_->mesh();
  Corners c;
  for (int i = 0; i < 3; ++i) {
    c.v[i] = m.vertex(t, i);
    const std::size_t o = out(c.v[i]);
    c.p[i] = position(mesh, c.v[i]);
    c.u[i] = mesh.uv[2 * o], c.w[i] = mesh.uv[2 * o + 1];
  }
  const double e = settings_.coincident;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (!c.p[i].IsEqual(c.p[j], e)) continue;
    c.collapsed = true;
    if (!singular_[c.v[i]] || !singular_[c.v[j]]) c.onPoleRow = false;
    if (m.isConstrained(t, k)) continue;
    if (std::abs(c.u[i] - c.u[j]) >= 0.5 * uPeriod_ && uPeriod_ > 0) c.wraps = true;
    if (std::abs(c.w[i] - c.w[j]) >= 0.5 * vPeriod_ && vPeriod_ > 0) c.wraps = true;
  }
  return c;
}

double FaceMesher::sample(const Corners& c, const double b[3], double& corresponding, bool centroid) const {
  const gp_Pnt M(b[0] * c.p[0].XYZ() + b[1] * c.p[1].XYZ() + b[2] * c.p[2].XYZ());
  corresponding = 0;
  // On elementary surfaces the distance is in closed form, and the corresponding-point guard (a
  // surface evaluation) is taken at the centroid only: a triangle whose UV region wraps around a
  // periodic direction away from its corners has its centroid there, and the apex of a cone
  // collapses triangles, which keep every sample's.
  if (eval_.closedFormDistance() && !centroid && !c.collapsed) return eval_.projectOnce(M, 0, 0, nullptr);
  // A sample whose own surface point is already within the final tolerance passes on every level
  // (each is at least as coarse): no need to find its foot.
  const double enough = kDeviationMargin * settings_.finalChordal;
  double u = 0, w = 0;
  eval_.blend(3, b, c.u, c.w, u, w);
  if (c.collapsed) {
    // On a pole's row the sector behind the triangle is part of the pole's fan, which the fan's
    // triangles cover within the surface whatever their shape in UV: of |S(uv) - M|, the part
    // across the surface counts, and the part along it only as far as the surface there turns
    // out of the plane at the triangle's regular corner (the sine between their normals). The
    // whole distance along a flat fan split the sector triangles on and on towards the row's
    // ends, each point a quarter as far from the row as the one before, and the slivers fanning
    // from the row's ends flipped (a cone of revolution at 0.01%: 1442 triangles for its fan's
    // 192, one flipped). Turned by a right angle or more (a fold), or elsewhere (two corners on
    // one point off a pole: a pinched sheet), the whole distance.
    gp_Pnt S;
    gp_Dir n;
    if (c.fanNormal && eval_.pointNormal(u, w, S, n) && n.Dot(*c.fanNormal) > 0) {
      const gp_Vec d(M, S);
      const double across = d.Dot(n);
      const double along = (d - gp_Vec(n) * across).Magnitude();
      return corresponding = std::hypot(across, along * gp_Vec(n).Crossed(gp_Vec(*c.fanNormal)).Magnitude());
    }
    return corresponding = eval_.point(u, w).Distance(M);
  }
  return eval_.projectOnce(M, u, w, &corresponding, enough);
}

void FaceMesher::sampleEdge(const Corners& c, int i, double& worst, double& corresponding) const {
  worst = -1, corresponding = -1;
  for (const double f : {0.5, 0.25, 0.75}) {
    if (f != 0.5 && !freeform_) break;
    double b[3] = {0, 0, 0};
    b[(i + 1) % 3] = f, b[(i + 2) % 3] = 1 - f;
    double cd = 0;
    worst = std::max(worst, sample(c, b, cd, false));
    corresponding = std::max(corresponding, cd);
  }
}

void FaceMesher::evaluateTriangle(cet::TriangleId t, const FaceMesh& mesh, const AngleSplit& angleSplit, int stamp,
                                  TriangleRecord& r, Pending& pending) const {
  const cet::CetMesh& m = cdt_->mesh();
  Corners c = corners(t, mesh);
  if (c.collapsed && c.onPoleRow) {
    for (int i = 0; i < 3; ++i)
      if (!singular_[c.v[i]]) c.fanNormal = &normal_[c.v[i]];
  }
  const cet::VertexId* v = c.v;
  const gp_Pnt* P = c.p;
  // Its angle split was dropped (not clear of the chords): the chordal test must judge it now.
  const bool chordalToo = (r.flags & TriangleRecord::kMeasureChordal) && r.matches(v[0], v[1], v[2]);
  r = TriangleRecord{};
  pending = Pending{};
  r.v[0] = v[0], r.v[1] = v[1], r.v[2] = v[2];
  if (chordalToo) r.flags |= TriangleRecord::kMeasureChordal;  // withinByTheMeasure() judges it
  double longest = 0, longestFree = 0;
  r.longestFreeEdge = 3;
  for (int i = 0; i < 3; ++i) {
    const double len = P[(i + 1) % 3].Distance(P[(i + 2) % 3]);  // edge i, opposite corner i
    longest = std::max(longest, len);
    if (!m.isConstrained(t, i) && len > longestFree) longestFree = len, r.longestFreeEdge = static_cast<std::uint8_t>(i);
  }
  r.longest = static_cast<float>(longest);
  pending.longest = longest;

  if (!c.collapsed) {
    // Regularity: corner normals. Poles and apexes have no meaningful normal to compare, and the two
    // ends of a boundary segment are fixed by the edge discretisation: no interior point changes
    // them. Nor does any point change the normals' jump across a crease of the surface or a fold of
    // its parametrisation (SurfaceEval::normalJumps): an edge across one is left to the chordal test
    // (splitting it for the angle, or the triangle as flipped, would go on down to the minimum size
    // all along the crease or fold: 2.3 million triangles on a fuzzed sheet folded flat).
    double minCos = 1;
    bool acrossCrease = false;
    // Fold corners show the normal of the triangle's side (sideNormal).
    const gp_Vec side = folds_.empty() ? gp_Vec(0, 0, 0) : triangleSide(v, P);
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      if (eval_.crossesCrease(c.u[a], c.w[a], c.u[b], c.w[b])) {
        acrossCrease = true;
        // Its ends off the crease on either side, their normals further apart than the angle: the
        // triangle bridges the crease (creasePoint).
        if (!m.isConstrained(t, i) && !singular_[v[a]] && !singular_[v[b]] &&
            normal_[v[a]].Dot(normal_[v[b]]) < angleSplit.minCos &&
            bendBetween(c.u[a], c.w[a], c.u[b], c.w[b]))
          r.flags |= TriangleRecord::kAcrossCrease;
        continue;
      }
      if (singular_[v[a]] || singular_[v[b]] || m.isConstrained(t, i)) continue;
      const gp_Dir& na = sideNormal(v[a], side);
      const gp_Dir& nb = sideNormal(v[b], side);
      const double cosine = na.Dot(nb);
      if (cosine < 0 && eval_.normalJumps(c.u[a], c.w[a], c.u[b], c.w[b], na, nb)) {
        acrossCrease = true;
        if (!isFold(v[a]) && !isFold(v[b])) r.flags |= TriangleRecord::kAcrossFold;
        continue;
      }
      // Turning over within an edge too short for the angle to split: maybe a fold as sharp (foldPoint).
      if (cosine < 0 && P[a].Distance(P[b]) <= angleSplit.minSize && !isFold(v[a]) && !isFold(v[b]))
        r.flags |= TriangleRecord::kAcrossFold;
      if (cosine < minCos) minCos = cosine, r.angleEdge = static_cast<std::uint8_t>(i);
    }
    r.normalCos = static_cast<float>(minCos);

    // Orientation against the surface.
    const gp_Vec n = gp_Vec(P[0], P[1]).Crossed(gp_Vec(P[0], P[2]));
    gp_Vec ref(0, 0, 0);
    for (int i = 0; i < 3; ++i) {
      if (singular_[v[i]])
        r.flags |= TriangleRecord::kPoleCorner;
      else if (!isFold(v[i]))
        ref += gp_Vec(normal_[v[i]]);  // a fold corner's normal is its side's
    }
    if (n.Magnitude() <= 1e-12 * longest * longest) {  // the measure's notion of no area (brep/measure.h)
      r.flags |= TriangleRecord::kFlipped;
    } else if ((r.flags & TriangleRecord::kPoleCorner) && n.Magnitude() <= 1e-4 * longest * longest) {
      // Corners in line through a pole (a fan from the pole's row onto a straight edge out of the
      // pole, in line up to the row's width): the facet's normal is noise, whatever it says.
      r.flags |= TriangleRecord::kFlipped | TriangleRecord::kInLine;
    } else if (ref.Magnitude() > 0 && !acrossCrease) {  // corner normals from both sides of a crease: no reference
      r.facetCos = static_cast<float>(n.Dot(ref) / (n.Magnitude() * ref.Magnitude()));
    }
    // A triangle the angle splits anyway needs no chordal samples (most triangles of a finely
    // curved surface end this way): refine() measures it if a later rule would keep it.
    if (angleSplit.splits(r) && !chordalToo) {
      r.flags |= TriangleRecord::kUnmeasured;
      return;
    }
  }

  static const double kCentroid[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  // A flat face's triangle lies on its plane inside the outline, which the surface covers within
  // the poles' distance from the plane on either side (SurfaceEval::flat): no samples to take.
  if (eval_.flat() && !c.collapsed) {
    r.deviation = static_cast<float>(2 * eval_.flatThickness());
    return;
  }
  if (exactDeviation_ && !c.collapsed) {
    // The deviation in closed form, split where it peaks (inside: the centroid; an edge: its
    // midpoint). The corresponding-point guard (below) at the centroid alone: a triangle whose UV
    // region wraps around a periodic direction away from its corners has its centroid there.
    int where = -1;
    const double d = eval_.triangleDeviation(P[0], P[1], P[2], where);
    if (d >= 0) {
      double u = 0, w = 0;
      eval_.blend(3, kCentroid, c.u, c.w, u, w);
      const double corresponding = eval_.point(u, w).Distance(gp_Pnt((P[0].XYZ() + P[1].XYZ() + P[2].XYZ()) / 3));
      const bool wrapped = corresponding > longest;
      r.deviation = static_cast<float>(wrapped ? corresponding : d);
      r.worstSample = static_cast<std::uint8_t>(wrapped || where < 0 ? 0 : 1 + where);
      return;
    }
  }
  // Chordal: samples of the flat triangle projected onto the surface. The corresponding-point
  // distance |S(uv) - M| at the same samples (on cones and tori at the centroid only: see sample())
  // guards the other direction: a triangle whose UV region maps far from it (spanning a seam, or
  // collapsed on a pole with a whole sector behind it) does not cover its part of the surface,
  // however close its own points are.
  pending.worst = sample(c, kCentroid, pending.corresponding, true);
  if (freeform_) {
    // Free-form surfaces can bend inside a triangle between the centroid and the edge midpoints
    // (bumps narrower than the triangle): the barycentric grid of step 1/4 as the measurement uses,
    // reported as the nearest of the four split points.
    static const double kInner[3][3] = {{.5, .25, .25}, {.25, .5, .25}, {.25, .25, .5}};
    for (const auto& b : kInner) {
      double cd = 0;
      const double d = sample(c, b, cd, false);
      pending.worst = std::max(pending.worst, d), pending.corresponding = std::max(pending.corresponding, cd);
    }
  }
  // Edge i runs between corners i+1 and i+2; a constrained edge is a boundary chord, already
  // within tolerance by the edge discretisation. An edge's samples (its midpoint; on free-form
  // surfaces also its quarter points) depend on the edge alone: the neighbour across it may have them.
  // The neighbour measured in this pass too: a lower one first (its samples are taken when it is
  // done, by finishTriangle), a higher one after this one (it takes these).
  double* edgeWorst = pending.edgeWorst;
  double* edgeCorresponding = pending.edgeCorresponding;
  for (int i = 0; i < 3; ++i) {
    if (m.isConstrained(t, i)) continue;
    if (!c.collapsed) {
      const cet::TriangleId n = m.neighbor(t, i);
      const bool measuredNow = n != cet::kNoTriangle && n < measuredStamp_.size() && measuredStamp_[n] == stamp;
      if (measuredNow && n < t) {
        pending.deferred |= static_cast<std::uint8_t>(1u << i);
        continue;
      }
      if (!measuredNow && edgeSamplesFromNeighbour(t, i, r.edgeDeviation[i], r.edgeCorresponding[i])) {
        edgeWorst[i] = r.edgeDeviation[i], edgeCorresponding[i] = r.edgeCorresponding[i];
        continue;
      }
    }
    sampleEdge(c, i, edgeWorst[i], edgeCorresponding[i]);
    if (!c.collapsed) r.edgeDeviation[i] = static_cast<float>(edgeWorst[i]), r.edgeCorresponding[i] = static_cast<float>(edgeCorresponding[i]);
  }
  if (pending.deferred == 0) conclude(r, pending, c.collapsed, &c);
  // Across a seam: split whatever the tolerance (a level coarser than the whole face, such as a
  // small sphere's level 0, saw every triangle collapsed across its seam and dropped none).
  if (c.wraps) r.deviation = std::numeric_limits<float>::max();
}

void FaceMesher::finishTriangle(cet::TriangleId t, const FaceMesh& mesh, TriangleRecord& r, Pending& pending) const {
  std::optional<Corners> c;  // made when a sample needs it
  const auto cornersOfT = [&]() -> const Corners& {
    if (!c) c = corners(t, mesh);
    return *c;
  };
  for (int i = 0; i < 3; ++i) {
    if (!(pending.deferred >> i & 1u)) continue;
    if (edgeSamplesFromNeighbour(t, i, r.edgeDeviation[i], r.edgeCorresponding[i])) {
      pending.edgeWorst[i] = r.edgeDeviation[i], pending.edgeCorresponding[i] = r.edgeCorresponding[i];
    } else {
      sampleEdge(cornersOfT(), i, pending.edgeWorst[i], pending.edgeCorresponding[i]);
      r.edgeDeviation[i] = static_cast<float>(pending.edgeWorst[i]);
      r.edgeCorresponding[i] = static_cast<float>(pending.edgeCorresponding[i]);
    }
  }
  conclude(r, pending, false, peakSampled_ ? &cornersOfT() : nullptr);
}

void FaceMesher::conclude(TriangleRecord& r, const Pending& pending, bool collapsed, const Corners* c) const {
  const double* edgeWorst = pending.edgeWorst;
  const double* edgeCorresponding = pending.edgeCorresponding;
  // Ties go to the first sample in the order centroid (and interior), edge 0, 1, 2.
  double worst = pending.worst, worstCorresponding = pending.corresponding;
  std::uint8_t worstSample = 0, worstCorrespondingSample = 0;
  for (int i = 0; i < 3; ++i) {
    if (edgeWorst[i] < 0) continue;  // constrained: not sampled
    if (edgeWorst[i] > worst) worst = edgeWorst[i], worstSample = static_cast<std::uint8_t>(1 + i);
    if (edgeCorresponding[i] > worstCorresponding)
      worstCorresponding = edgeCorresponding[i], worstCorrespondingSample = static_cast<std::uint8_t>(1 + i);
  }
  if (peakSampled_ && c && !collapsed) {
    // The edges' largest samples stand for their middles (where a quadratic vanishing at the
    // corners peaks along them); a boundary chord, not sampled, is sampled at its middle for this.
    double middle[3], peak[3];
    for (int i = 0; i < 3; ++i) {
      middle[i] = edgeWorst[i];
      if (middle[i] < 0) {
        double b[3] = {0.5, 0.5, 0.5}, unused = 0;
        b[i] = 0;
        middle[i] = sample(*c, b, unused, false);
      }
    }
    if (quadraticDeviationPeak(middle, peak)) {
      double unused = 0;
      const double d = sample(*c, peak, unused, false);
      if (d > worst) worst = d, worstSample = 0;
    }
  }
  r.worstSample = worstSample;
  if (collapsed || worstCorresponding > pending.longest) {
    worst = worstCorresponding;
    r.worstSample = worstCorrespondingSample;
  }
  r.deviation = static_cast<float>(std::max(worst, 0.0));
  if (collapsed) r.flags = TriangleRecord::kCollapsed;
}

// ---------------------------------------------------------------------------------------------
// Boundary chords and their clearance. The surface under a chord's UV segment bulges away from the
// 3D chord, by w within the tangent plane and by h along the normal (a chord of a curved boundary
// sags below the surface); a point closer to the chord than that makes a flipped or folded triangle
// on it, and no later point can repair it (Delaunay keeps the closest apex on a constrained edge).
void FaceMesher::buildChords(const FaceMesh& mesh) {
  chords_.clear();
  poleChords_.clear();
  gridStart_.clear();
  gridChords_.clear();
  const cet::CetMesh& m = cdt_->mesh();
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, lengthSum = 0;
  const auto triangles = static_cast<cet::TriangleId>(m.triangleCount());
  for (cet::TriangleId t = 0; t < triangles; ++t) {
    if (m.isGhost(t) || m.isOutside(t)) continue;
    for (int i = 0; i < 3; ++i) {
      if (!m.isConstrained(t, i)) continue;
      const cet::VertexId a = m.vertex(t, (i + 1) % 3), b = m.vertex(t, (i + 2) % 3);  // domain on the left
      Chord c;
      c.a = position(mesh, a);
      c.ab = gp_Vec(c.a, position(mesh, b));
      const double len = c.ab.Magnitude();
      gp_Vec n(0, 0, 0);
      if (!singular_[a]) n += gp_Vec(normal_[a]);
      if (!singular_[b]) n += gp_Vec(normal_[b]);
      if (n.Magnitude() == 0 || len == 0) continue;
      c.n = n.Normalized();
      c.pa = cdt_->point(a), c.pb = cdt_->point(b);
      c.pole = singular_[a] ? 0 : singular_[b] ? 1 : -1;
      const std::size_t oa = out(a), ob = out(b);
      const gp_Vec inward = c.n.Crossed(c.ab / len);
      // Sampled at 1/4, 1/2 and 3/4 of the chord (a wavy surface need not peak mid-chord).
      double w = 0, h = 0;
      for (double f : {0.25, 0.5, 0.75}) {
        const double weights[2] = {1 - f, f}, cu[2] = {mesh.uv[2 * oa], mesh.uv[2 * ob]};
        const double cv[2] = {mesh.uv[2 * oa + 1], mesh.uv[2 * ob + 1]};
        double u = 0, v = 0;
        eval_.blend(2, weights, cu, cv, u, v);
        const gp_Pnt under = eval_.point(u, v);
        const gp_Vec bulge(c.a.XYZ() + f * c.ab.XYZ(), under.XYZ());
        w = std::min(w, bulge.Dot(inward));
        h = std::max(h, std::abs(bulge.Dot(c.n)));
      }
      // Outward in the tangent plane: clear the bulge. Along the normal: far enough that the facet
      // on the chord tilts by less than ~40 degrees.
      c.clearance = -1.5 * w + 1.2 * h + 1e-3 * len;
      // The zone the clearance guards, in scaled UV: twice the clearance (scaled lengths approximate
      // 3D ones; x2 margin). Off a chord from a pole the surface moves far slower than the scaled
      // plane, down to nothing at the pole: points well outside that zone lay beyond the chord in
      // 3D, and every triangle they made on it was flipped (a fuzzed sheet fanning from a pole
      // corner: 10206 triangles, 3995 flipped, where BRepMesh makes 1053). There the zone reaches
      // as far out as a point twice the clearance off the chord in 3D (sampled at 1/8, 1/2 and 7/8
      // of the chord), up to the chord's length; past the first zone it refuses only points beyond
      // the chord (with the whole clearance there, points by an apex were refused all round it, and
      // occt's bug33398, a SolidWorks part, kept 5 flipped triangles on a coarse level on its
      // B-spline faces by an apex).
      const double ex = c.pb.x - c.pa.x, ey = c.pb.y - c.pa.y, scaledLength = std::hypot(ex, ey);
      double reach = 2.0 * c.clearance;
      c.near = reach;
      if ((singular_[a] || singular_[b]) && scaledLength > reach) {
        const double px = -ey / scaledLength * reach, py = ex / scaledLength * reach;
        double moved = reach;  // the least 3D distance a point `reach` off the chord moves
        for (double f : {0.125, 0.5, 0.875}) {
          const cet::Point2 q{c.pa.x + f * ex, c.pa.y + f * ey}, q1{q.x + px, q.y + py};
          double u = 0, v = 0, u1 = 0, v1 = 0;
          eval_.unscaled(q, u, v);
          eval_.unscaled(q1, u1, v1);
          moved = std::min(moved, eval_.point(u, v).Distance(eval_.point(u1, v1)));
        }
        reach = std::min(reach * reach / std::max(moved, 1e-300), scaledLength);
      }
      c.x0 = std::min(c.pa.x, c.pb.x) - reach, c.x1 = std::max(c.pa.x, c.pb.x) + reach;
      c.y0 = std::min(c.pa.y, c.pb.y) - reach, c.y1 = std::max(c.pa.y, c.pb.y) + reach;
      x0 = std::min(x0, c.x0), y0 = std::min(y0, c.y0), x1 = std::max(x1, c.x1), y1 = std::max(y1, c.y1);
      lengthSum += std::hypot(c.pb.x - c.pa.x, c.pb.y - c.pa.y);
      if (singular_[a] || singular_[b]) poleChords_.push_back(static_cast<std::uint32_t>(chords_.size()));
      chords_.push_back(c);
    }
  }
  if (chords_.empty()) return;
  // A uniform grid of about one chord length per cell, at most 256 x 256.
  const double cell = std::max(lengthSum / static_cast<double>(chords_.size()), 1e-300);
  gridX0_ = x0, gridY0_ = y0;
  gridNx_ = static_cast<int>(std::clamp((x1 - x0) / cell + 1, 1.0, 256.0));
  gridNy_ = static_cast<int>(std::clamp((y1 - y0) / cell + 1, 1.0, 256.0));
  gridCellX_ = std::max((x1 - x0) / gridNx_, 1e-300), gridCellY_ = std::max((y1 - y0) / gridNy_, 1e-300);
  // Cells in one array (a count per cell, then each cell's chords in order): most cells of a face's
  // grid are empty (the chords run along its boundary), and a vector per cell made up to 65536 of
  // them per level (1.5 MB on occ/terrain.brep, each a page fault's worth on first touch).
  const std::size_t cells = static_cast<std::size_t>(gridNx_) * static_cast<std::size_t>(gridNy_);
  gridStart_.assign(cells + 1, 0);
  const auto forCells = [&](const Chord& c, auto&& f) {
    const int i0 = std::clamp(static_cast<int>((c.x0 - gridX0_) / gridCellX_), 0, gridNx_ - 1);
    const int i1 = std::clamp(static_cast<int>((c.x1 - gridX0_) / gridCellX_), 0, gridNx_ - 1);
    const int j0 = std::clamp(static_cast<int>((c.y0 - gridY0_) / gridCellY_), 0, gridNy_ - 1);
    const int j1 = std::clamp(static_cast<int>((c.y1 - gridY0_) / gridCellY_), 0, gridNy_ - 1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j)
        f(static_cast<std::size_t>(j) * static_cast<std::size_t>(gridNx_) + static_cast<std::size_t>(i));
  };
  for (const Chord& c : chords_) forCells(c, [&](std::size_t g) { ++gridStart_[g + 1]; });
  for (std::size_t g = 0; g < cells; ++g) gridStart_[g + 1] += gridStart_[g];
  gridChords_.resize(gridStart_[cells]);
  std::vector<std::uint32_t>& next = gridFill_;
  next.assign(gridStart_.begin(), gridStart_.end() - 1);
  for (std::uint32_t k = 0; k < chords_.size(); ++k)
    forCells(chords_[k], [&](std::size_t g) { gridChords_[next[g]++] = k; });
}

bool FaceMesher::clearOfChords(double u, double v, bool mayStand) const {
  if (chords_.empty()) return true;
  const cet::Point2 q = scaled(u, v);
  const int i = static_cast<int>((q.x - gridX0_) / gridCellX_), j = static_cast<int>((q.y - gridY0_) / gridCellY_);
  if (i < 0 || j < 0 || i >= gridNx_ || j >= gridNy_) return true;
  gp_Pnt x;
  bool evaluated = false;
  // Past a chord's end, inside its clearance or behind its line: refused unless another chord runs
  // beside the point (its own clearance guards it there). A narrow fillet's splits towards a long
  // chord's end lay just past it, beside the next chord along the same edge, and were all refused
  // (a torus tube of 0.15 on a ring of 20 kept 27.09 degrees; on a ring of 40, 26.07, the points
  // behind the line of a chord whose edge curves on past its end). Where no chord runs beside the
  // point (by a corner of the boundary), every chord it overhangs keeps its clearance: with the
  // side alone there, fuzzed faces gained and lost flipped triangles by the hundred.
  bool besideOne = false, pastEndRefused = false;
  const std::size_t cell =
      static_cast<std::size_t>(j) * static_cast<std::size_t>(gridNx_) + static_cast<std::size_t>(i);
  for (std::uint32_t at = gridStart_[cell]; at < gridStart_[cell + 1]; ++at) {
    const std::uint32_t k = gridChords_[at];
    const Chord& c = chords_[k];
    if (q.x < c.x0 || q.x > c.x1 || q.y < c.y0 || q.y > c.y1) continue;
    // Only points beside the chord (projecting within it, with a small overhang) are at risk.
    const double ex = c.pb.x - c.pa.x, ey = c.pb.y - c.pa.y, e2 = ex * ex + ey * ey;
    const double s = e2 > 0 ? ((q.x - c.pa.x) * ex + (q.y - c.pa.y) * ey) / e2 : 0.5;
    if (s < -0.1 || s > 1.1) continue;
    if (!evaluated) x = eval_.point(u, v), evaluated = true;
    const gp_Vec facet = c.ab.Crossed(gp_Vec(c.a, x));
    // Near the chord, the whole clearance; further out (a pole's chord), only its side.
    const bool near = q.x >= std::min(c.pa.x, c.pb.x) - c.near && q.x <= std::max(c.pa.x, c.pb.x) + c.near &&
                      q.y >= std::min(c.pa.y, c.pb.y) - c.near && q.y <= std::max(c.pa.y, c.pb.y) + c.near;
    const bool alongside = s >= 0 && s <= 1;
    besideOne = besideOne || (near && alongside);
    // Inside the clearance, a point that fixes the angle (or a flipped triangle, sliding along the
    // edge it is bisected on) may still stand on the chord if the facet it makes with it faces the
    // surface's way within 60 degrees (the fold rule's 70, with a margin). Without it, edges from
    // the boundary into tori and free-form faces kept up to 50 degrees on the sample models.
    auto standsOn = [&] {
      gp_Pnt p;
      gp_Dir n;
      if (!mayStand || !eval_.pointNormal(u, v, p, n)) return false;
      const gp_Vec nSum = 2 * c.n + gp_Vec(n);
      return facet.Dot(nSum) > kStandingFacetCos * facet.Magnitude() * nSum.Magnitude();
    };
    const double distance = facet.Dot(c.n), need = near ? c.clearance * c.ab.Magnitude() : 0.0;
    // Far from a chord out of a pole, past the pole in 3D: the point lies round the pole from the
    // chord, not behind it. A full sphere's seam chord into its pole reaches, in scaled UV, over
    // points beyond the pole on the far side, all "behind" its line: a ball of Axis_of_bearing at
    // 0.01% kept a sliver standing edge-on across the pole on two coarse levels, every point that
    // would split it refused.
    if (!near && c.pole >= 0) {
      const double along = gp_Vec(c.a, x).Dot(c.ab) / c.ab.SquareMagnitude();
      if (c.pole == 0 ? along < 0 : along > 1) continue;
    }
    if (!alongside) {
      if (distance < need && !standsOn()) pastEndRefused = true;
      continue;
    }
    if (distance >= need) continue;
    if (standsOn()) continue;
    if (settings_.trace) {
      std::fprintf(stderr, "  not clear: chord length %g clearance %g distance %g at %g\n", c.ab.Magnitude(),
                   c.clearance, distance / c.ab.Magnitude(), s);
    }
    return false;
  }
  if (pastEndRefused && !besideOne) {
    if (settings_.trace) std::fprintf(stderr, "  not clear: past a chord's end, beside no chord\n");
    return false;
  }
  return true;
}

bool FaceMesher::safeSplit(cet::TriangleId t, double& u, double& v, const FaceMesh& mesh, bool anyPoint, bool forAngle,
                           int angleEdge) const {
  if (clearOfChords(u, v, forAngle)) return true;
  // A flipped triangle's split slides along the edge it bisects as one for the angle does, and may
  // stand inside a chord's clearance on the same terms (the facet it makes with the chord faces the
  // surface's way): on faces bending sharply at a coarse level (corner blends of Bottom and trj4 at
  // level 0) the triangle's centroid and midpoints all lay inside a neighbouring chord's clearance.
  const bool mayStand = forAngle || anyPoint;
  const cet::CetMesh& m = cdt_->mesh();
  if (mayStand && angleEdge >= 0) {
    // Off the middle of the edge being split: for the angle, the edge whose ends' normals differ
    // too much, where any point between the middle thirds or so brings both parts within the angle
    // (the normal turns about evenly); for a flipped triangle, the edge it is bisected on.
    const std::size_t oa = out(m.vertex(t, (angleEdge + 1) % 3)), ob = out(m.vertex(t, (angleEdge + 2) % 3));
    const double eu[2] = {mesh.uv[2 * oa], mesh.uv[2 * ob]}, ev[2] = {mesh.uv[2 * oa + 1], mesh.uv[2 * ob + 1]};
    for (double f : {0.65, 0.35, 0.8, 0.2}) {
      const double w[2] = {1 - f, f};
      double uu = 0, vv = 0;
      eval_.blend(2, w, eu, ev, uu, vv);
      if (clearOfChords(uu, vv, true)) {
        u = uu, v = vv;
        return true;
      }
    }
  }
  if (anyPoint) {
    // A flipped triangle: any of its centroid and free-edge midpoints that keeps the clearance.
    double cu[3], cv[3];
    for (int i = 0; i < 3; ++i) {
      const std::size_t o = out(m.vertex(t, i));
      cu[i] = mesh.uv[2 * o], cv[i] = mesh.uv[2 * o + 1];
    }
    double tu[4] = {(cu[0] + cu[1] + cu[2]) / 3, 0, 0, 0}, tv[4] = {(cv[0] + cv[1] + cv[2]) / 3, 0, 0, 0};
    if (!eval_.linear()) {
      const double third[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
      eval_.blend(3, third, cu, cv, tu[0], tv[0]);
    }
    // Free-edge midpoints, except on an edge far shorter than the triangle: its midpoint would all
    // but repeat a corner, leaving t as it was (and t would ask again, pass after pass). Under a
    // tenth of the longest edge is too short: a needle split on its short edge is the same needle
    // (a fuzzed face's needles beside a side with crowded knots, their long edges' midpoints inside
    // the side's clearance, took one split a pass: 964 flipped triangles where 50 are left; at a
    // thousandth, the bound before, one's short edge was 0.004 of 0.9 in 3D).
    double length[3], longest = 0;
    for (int i = 0; i < 3; ++i) {
      const cet::Point2 a = cdt_->point(m.vertex(t, (i + 1) % 3)), b = cdt_->point(m.vertex(t, (i + 2) % 3));
      length[i] = std::hypot(a.x - b.x, a.y - b.y);
      longest = std::max(longest, length[i]);
    }
    int n = 1;
    for (int i = 0; i < 3; ++i) {
      if (m.isConstrained(t, i) || length[i] < 0.1 * longest) continue;
      tu[n] = 0.5 * (cu[(i + 1) % 3] + cu[(i + 2) % 3]), tv[n] = 0.5 * (cv[(i + 1) % 3] + cv[(i + 2) % 3]);
      if (!eval_.linear()) {
        const double half[2] = {0.5, 0.5}, eu[2] = {cu[(i + 1) % 3], cu[(i + 2) % 3]},
                     ev[2] = {cv[(i + 1) % 3], cv[(i + 2) % 3]};
        eval_.blend(2, half, eu, ev, tu[n], tv[n]);
      }
      ++n;
    }
    for (int i = 0; i < n; ++i) {
      if (clearOfChords(tu[i], tv[i], forAngle)) {
        u = tu[i], v = tv[i];
        return true;
      }
    }
  }
  // Slide from the midpoint of one of t's own boundary chords towards the opposite corner.
  for (int own = 0; own < 3; ++own) {
    if (!m.isConstrained(t, own)) continue;
    const std::size_t oa = out(m.vertex(t, (own + 1) % 3)), ob = out(m.vertex(t, (own + 2) % 3));
    const std::size_t oc = out(m.vertex(t, own));
    const double mu = 0.5 * (mesh.uv[2 * oa] + mesh.uv[2 * ob]), mv = 0.5 * (mesh.uv[2 * oa + 1] + mesh.uv[2 * ob + 1]);
    for (double f : {0.5, 0.7}) {
      double uu = mu + f * (mesh.uv[2 * oc] - mu), vv = mv + f * (mesh.uv[2 * oc + 1] - mv);
      if (!eval_.linear()) {
        const double w[3] = {0.5 * (1 - f), 0.5 * (1 - f), f}, cu[3] = {mesh.uv[2 * oa], mesh.uv[2 * ob], mesh.uv[2 * oc]};
        const double cv[3] = {mesh.uv[2 * oa + 1], mesh.uv[2 * ob + 1], mesh.uv[2 * oc + 1]};
        eval_.blend(3, w, cu, cv, uu, vv);
      }
      if (clearOfChords(uu, vv, forAngle)) {
        u = uu, v = vv;
        return true;
      }
    }
  }
  return false;
}

bool FaceMesher::touchesChord(cet::VertexId v) const {
  const cet::CetMesh& m = cdt_->mesh();
  int around = 0;  // bounded: a vertex has a finite star
  for (cet::TriangleId s = m.incident(v), first = s; s != cet::kNoTriangle && around < 4096; ++around) {
    const int iv = m.indexOf(s, v);
    for (int i = 0; i < 3; ++i)
      if (i != iv && m.isConstrained(s, i)) return true;
    s = m.nextAround(s, v);
    if (s == first) break;
  }
  return false;
}

void FaceMesher::keepRowWithinAngleOfChord(cet::TriangleId t, int edge, const FaceMesh& mesh, double minCos,
                                           double& u, double& v) const {
  const cet::CetMesh& m = cdt_->mesh();
  const cet::VertexId ends[2] = {m.vertex(t, (edge + 1) % 3), m.vertex(t, (edge + 2) % 3)};
  gp_Pnt p;
  gp_Dir n;
  if (!eval_.pointNormal(u, v, p, n)) return;
  const gp_Vec nSplit(n);
  // The point at fraction f of the way from end e's vertex to (u, v).
  const auto towards = [&](int e, double f, double& pu, double& pv) {
    const std::size_t o = out(ends[e]);
    const double w[2] = {1 - f, f}, eu[2] = {mesh.uv[2 * o], u}, ev[2] = {mesh.uv[2 * o + 1], v};
    eval_.blend(2, w, eu, ev, pu, pv);
  };
  // The end on a boundary chord whose part of the edge would miss the angle and have no split
  // point of its own (those safeSplit would try); none where both would (nothing to move to).
  int stuck = -1;
  for (int e = 0; e < 2; ++e) {
    const cet::VertexId a = ends[e];
    if (singular_[a] || isFold(a) || gp_Vec(normal_[a]).Dot(nSplit) >= minCos || !touchesChord(a)) continue;
    bool splits = false;
    for (double f : {0.5, 0.65, 0.35, 0.8, 0.2}) {
      double pu = 0, pv = 0;
      towards(e, f, pu, pv);
      if ((splits = clearOfChords(pu, pv, true))) break;
    }
    if (splits) continue;
    if (stuck >= 0) return;
    stuck = e;
  }
  if (stuck < 0) return;
  // The farthest point towards (u, v), at least halfway, within 0.95 of the angle of that end
  // (its part of the edge then keeps the angle with a margin for the chord's other end).
  const gp_Vec nEnd(normal_[ends[stuck]]);
  const double target = std::cos(0.95 * std::acos(std::clamp(minCos, -1.0, 1.0)));
  double within = 0, beyond = 1, pu = 0, pv = 0;
  for (int i = 0; i < 12; ++i) {
    const double f = 0.5 * (within + beyond);
    towards(stuck, f, pu, pv);
    (eval_.pointNormal(pu, pv, p, n) && nEnd.Dot(gp_Vec(n)) >= target ? within : beyond) = f;
  }
  if (within < 0.5) return;
  towards(stuck, within, pu, pv);
  if (!clearOfChords(pu, pv, true)) return;
  if (settings_.trace)
    std::fprintf(stderr,
                 "  split moved to %.3f of the way from a boundary vertex: its part keeps the angle\n",
                 within);
  u = pu, v = pv;
}

bool FaceMesher::onChord(cet::TriangleId t) const {
  const cet::CetMesh& m = cdt_->mesh();
  return m.isConstrained(t, 0) || m.isConstrained(t, 1) || m.isConstrained(t, 2);
}

bool FaceMesher::huggingPoleChord(cet::TriangleId t, const TriangleRecord& r, const FaceMesh& mesh) const {
  if (!(r.flags & TriangleRecord::kPoleCorner)) return false;
  const cet::CetMesh& m = cdt_->mesh();
  int pole = -1;
  for (int i = 0; i < 3; ++i) {
    if (!singular_[m.vertex(t, i)]) continue;
    if (pole >= 0) return false;
    pole = i;
  }
  if (pole < 0) return false;
  const gp_Pnt P = position(mesh, m.vertex(t, pole));
  const gp_Pnt X[2] = {position(mesh, m.vertex(t, (pole + 1) % 3)), position(mesh, m.vertex(t, (pole + 2) % 3))};
  for (const std::uint32_t index : poleChords_) {
    const Chord& c = chords_[index];
    const double len2 = c.ab.SquareMagnitude();
    if (!(len2 > 0)) continue;
    const double len = std::sqrt(len2);
    const gp_Pnt b = c.a.Translated(c.ab);
    const bool fromA = c.a.Distance(P) <= 1e-9 * len;
    if (!fromA && !(b.Distance(P) <= 1e-9 * len)) continue;
    const gp_Pnt& far = fromA ? b : c.a;
    bool both = true;
    for (int k = 0; k < 2 && both; ++k) {
      if (X[k].Distance(far) <= 1e-9 * len) continue;  // the chord's other end
      const gp_Vec ax(c.a, X[k]);
      const double s = ax.Dot(c.ab) / len2;
      if (!(s > 0 && s < 1)) {
        both = false;
        break;
      }
      // The side at the same fraction of the chord: how far it bulges out beyond the chord, against
      // how far in the corner stands (negative: beyond the chord too).
      const cet::Point2 q{c.pa.x + s * (c.pb.x - c.pa.x), c.pa.y + s * (c.pb.y - c.pa.y)};
      double u = 0, v = 0;
      eval_.unscaled(q, u, v);
      const double bulge = -c.ab.Crossed(gp_Vec(c.a, eval_.point(u, v))).Dot(c.n) / len;
      const double in = c.ab.Crossed(ax).Dot(c.n) / len;
      both = bulge > 0 && in < bulge;
    }
    if (both) {
      if (settings_.trace) std::fprintf(stderr, "  triangle %u hugs a chord from a pole (length %g): not split\n", t, len);
      return true;
    }
  }
  return false;
}

bool FaceMesher::alongChord(cet::TriangleId t) const {
  if (chords_.empty()) return false;
  const cet::CetMesh& m = cdt_->mesh();
  const cet::Point2 p[3] = {cdt_->point(m.vertex(t, 0)), cdt_->point(m.vertex(t, 1)),
                            cdt_->point(m.vertex(t, 2))};
  double longest = 0;
  for (int i = 0; i < 3; ++i)
    longest = std::max(longest, std::hypot(p[(i + 1) % 3].x - p[i].x, p[(i + 1) % 3].y - p[i].y));
  const double cx = (p[0].x + p[1].x + p[2].x) / 3, cy = (p[0].y + p[1].y + p[2].y) / 3;
  const int gi = static_cast<int>((cx - gridX0_) / gridCellX_),
            gj = static_cast<int>((cy - gridY0_) / gridCellY_);
  if (gi < 0 || gj < 0 || gi >= gridNx_ || gj >= gridNy_) return false;
  const std::size_t cell =
      static_cast<std::size_t>(gj) * static_cast<std::size_t>(gridNx_) + static_cast<std::size_t>(gi);
  const double band = kAlongChordBand * longest;
  // A corner on the boundary elsewhere (the far side of a thin strip) makes no sliver along the chord.
  bool boundary[3] = {false, false, false};
  for (int i = 0; i < 3; ++i) boundary[i] = touchesChord(m.vertex(t, i));
  for (std::uint32_t at = gridStart_[cell]; at < gridStart_[cell + 1]; ++at) {
    const Chord& c = chords_[gridChords_[at]];
    const double ex = c.pb.x - c.pa.x, ey = c.pb.y - c.pa.y, e2 = ex * ex + ey * ey;
    if (!(e2 > 0)) continue;
    const double e = std::sqrt(e2);
    bool along = true;
    for (int i = 0; i < 3 && along; ++i) {
      const double dx = p[i].x - c.pa.x, dy = p[i].y - c.pa.y;
      const double s = (dx * ex + dy * ey) / e2;
      const bool end = (p[i].x == c.pa.x && p[i].y == c.pa.y) || (p[i].x == c.pb.x && p[i].y == c.pb.y);
      along = s >= -1e-9 && s <= 1 + 1e-9 && std::abs(dx * ey - dy * ex) / e <= band && (end || !boundary[i]);
    }
    if (along) {
      if (settings_.trace)
        std::fprintf(stderr, "  triangle %u lies along a chord (length %g): not split\n", t,
                     c.ab.Magnitude());
      return true;
    }
  }
  return false;
}

double FaceMesher::facing(cet::VertexId a, cet::VertexId b, cet::VertexId c, const FaceMesh& mesh) const {
  const cet::VertexId v[3] = {a, b, c};
  gp_Pnt P[3];
  double u[3], w[3];
  gp_Vec ref(0, 0, 0);
  for (int i = 0; i < 3; ++i) {
    const std::size_t o = out(v[i]);
    P[i] = position(mesh, v[i]);
    u[i] = mesh.uv[2 * o], w[i] = mesh.uv[2 * o + 1];
    if (!singular_[v[i]] && !isFold(v[i])) ref += gp_Vec(normal_[v[i]]);
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (eval_.crossesCrease(u[i], w[i], u[j], w[j])) return -2;
    if (isFold(v[i]) || isFold(v[j])) continue;  // a fold corner shows its side's normal
    if (!singular_[v[i]] && !singular_[v[j]] && normal_[v[i]].Dot(normal_[v[j]]) < 0 &&
        eval_.normalJumps(u[i], w[i], u[j], w[j], normal_[v[i]], normal_[v[j]]))
      return -2;
  }
  const gp_Vec n = gp_Vec(P[0], P[1]).Crossed(gp_Vec(P[0], P[2]));
  const double longest = std::max({P[0].Distance(P[1]), P[1].Distance(P[2]), P[2].Distance(P[0])});
  if (!(n.Magnitude() > 1e-12 * longest * longest) || !(ref.Magnitude() > 0)) return -2;
  // The output's normals as well, poles included (those the measure judges facing by), back on
  // the surface's natural side.
  gp_Vec shown(0, 0, 0);
  const gp_Vec side = folds_.empty() ? gp_Vec(0, 0, 0) : triangleSide(v, P);
  for (int i = 0; i < 3; ++i) {
    const std::size_t o = folds_.empty() ? out(v[i]) : shownVertex(v[i], side);
    shown += gp_Vec(mesh.normals[3 * o], mesh.normals[3 * o + 1], mesh.normals[3 * o + 2]);
  }
  if (settings_.reversed) shown.Reverse();
  if (!(shown.Magnitude() > 0)) return -2;
  return std::min(n.Dot(ref) / (n.Magnitude() * ref.Magnitude()), n.Dot(shown) / (n.Magnitude() * shown.Magnitude()));
}

int FaceMesher::repairingFlip(cet::TriangleId t, const FaceMesh& mesh) const {
  const cet::CetMesh& m = cdt_->mesh();
  for (int i = 0; i < 3; ++i) {
    if (m.isConstrained(t, i)) continue;
    const cet::EdgeRef across = m.twin(cet::EdgeRef{t, i});
    if (across.t == cet::kNoTriangle || m.isGhost(across.t) || m.isOutside(across.t)) continue;
    // t = (a, b, c) with a = corner i, d opposite in the neighbour: the flip makes (a, b, d) and (a, d, c).
    const cet::VertexId a = m.vertex(t, i), b = m.vertex(t, (i + 1) % 3), c = m.vertex(t, (i + 2) % 3);
    const cet::VertexId d = m.vertex(across.t, across.i);
    if (const auto it = quadFlips_.find(quadKey(a, d, b, c));
        it != quadFlips_.end() && it->second >= kMaxQuadFlips)
      continue;  // flipped back and forth this level
    auto pivoted = [this](cet::VertexId x, cet::VertexId y) {
      const auto it = pivotFlips_.find(pairKey(x, y));
      return it != pivotFlips_.end() && it->second >= kMaxPivotFlips;
    };
    if (pivoted(a, b) || pivoted(a, c)) continue;  // walking around a fan
    if (const auto it = vertexPivotFlips_.find(a);
        it != vertexPivotFlips_.end() && it->second >= kMaxVertexPivotFlips)
      continue;
    const cet::Point2 pa = cdt_->point(a), pb = cdt_->point(b), pc = cdt_->point(c), pd = cdt_->point(d);
    if (!(cet::orient2d(pa, pb, pd) > 0 && cet::orient2d(pa, pd, pc) > 0)) continue;  // not strictly convex
    // Not across a fold of the parametrisation (corners' normals opposed), where no flat triangle
    // faces both ways and a flip only moves the flipped one elsewhere.
    const cet::VertexId q[4] = {a, b, c, d};
    bool fold = false;
    for (int j = 0; j < 4 && !fold; ++j)
      for (int k = j + 1; k < 4 && !fold; ++k)
        fold = !singular_[q[j]] && !singular_[q[k]] && !isFold(q[j]) && !isFold(q[k]) &&
               normal_[q[j]].Dot(normal_[q[k]]) < 0;
    if (fold) continue;
    if (facing(a, b, d, mesh) >= kFoldCos && facing(a, d, c, mesh) >= kFoldCos) return i;
  }
  return -1;
}

bool FaceMesher::inLineOnChordIntoPole(cet::TriangleId t, const TriangleRecord& r) const {
  if (!(r.flags & TriangleRecord::kInLine)) return false;
  const cet::CetMesh& m = cdt_->mesh();
  for (int i = 0; i < 3; ++i)
    if (m.isConstrained(t, i) && (singular_[m.vertex(t, (i + 1) % 3)] || singular_[m.vertex(t, (i + 2) % 3)])) return true;
  return false;
}

bool FaceMesher::allSingular(cet::TriangleId t) const {
  const cet::CetMesh& m = cdt_->mesh();
  return singular_[m.vertex(t, 0)] && singular_[m.vertex(t, 1)] && singular_[m.vertex(t, 2)];
}

void FaceMesher::ontoCreaseLine(cet::TriangleId t, const FaceMesh& mesh, double& u, double& v) const {
  const cet::CetMesh& m = cdt_->mesh();
  double cu[3], cv[3];
  cet::Point2 q[3];
  for (int i = 0; i < 3; ++i) {
    const std::size_t o = out(m.vertex(t, i));
    cu[i] = mesh.uv[2 * o], cv[i] = mesh.uv[2 * o + 1];
    q[i] = cdt_->point(m.vertex(t, i));
  }
  for (const bool uDir : {true, false}) {
    const double* c = uDir ? cu : cv;
    const double first = std::min({c[0], c[1], c[2]}), last = std::max({c[0], c[1], c[2]});
    double knot = 0;
    if (!eval_.sharpKnotBetween(uDir, first, last, uDir ? u : v, knot) &&
        !eval_.bendBetween(uDir, first, last, knot))
      continue;
    // The line (`knot`: a sharp knot's or a bend's) in scaled (u, v) (straight there, as t's edges
    // are) crosses two of t's edges: take the point of that chord nearest the split point's other
    // coordinate, a little inside.
    const cet::Point2 at = scaled(uDir ? knot : u, uDir ? v : knot);
    const double x = uDir ? at.x : at.y;
    double lo = 1e300, hi = -1e300;
    for (int i = 0; i < 3; ++i) {
      const cet::Point2 a = q[i], b = q[(i + 1) % 3];
      const double xa = uDir ? a.x : a.y, xb = uDir ? b.x : b.y;
      if ((xa - x) * (xb - x) > 0 || xa == xb) continue;
      const double f = (x - xa) / (xb - xa);
      const double y = uDir ? a.y + f * (b.y - a.y) : a.x + f * (b.x - a.x);
      lo = std::min(lo, y), hi = std::max(hi, y);
    }
    if (!(hi > lo)) continue;
    const double inset = 0.05 * (hi - lo);
    const double y = std::clamp(uDir ? at.y : at.x, lo + inset, hi - inset);
    eval_.unscaled(uDir ? cet::Point2{x, y} : cet::Point2{y, x}, u, v);
    if (uDir) u = knot; else v = knot;
    return;
  }
}

bool FaceMesher::bendBetween(double ua, double va, double ub, double vb) const {
  double line = 0;
  return eval_.bendBetween(true, std::min(ua, ub), std::max(ua, ub), line) ||
         eval_.bendBetween(false, std::min(va, vb), std::max(va, vb), line);
}

bool FaceMesher::creasePoint(cet::TriangleId t, const FaceMesh& mesh, double& u, double& v) const {
  const cet::CetMesh& m = cdt_->mesh();
  const Corners c = corners(t, mesh);
  double longest = -1;
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    if (m.isConstrained(t, i) || singular_[c.v[a]] || singular_[c.v[b]]) continue;
    const double length = c.p[a].Distance(c.p[b]);
    if (length <= longest) continue;
    for (const bool uDir : {true, false}) {
      const double xa = uDir ? c.u[a] : c.w[a], xb = uDir ? c.u[b] : c.w[b];
      double line = 0;
      if (!eval_.bendBetween(uDir, std::min(xa, xb), std::max(xa, xb), line)) continue;
      // The line is straight in the scaled plane (each direction scales on its own), as the edge is.
      const cet::Point2 qa = cdt_->point(c.v[a]), qb = cdt_->point(c.v[b]);
      const cet::Point2 ql = scaled(uDir ? line : c.u[a], uDir ? c.w[a] : line);
      const double ya = uDir ? qa.x : qa.y, yb = uDir ? qb.x : qb.y, yl = uDir ? ql.x : ql.y;
      if (ya == yb) continue;
      const double f = std::clamp((yl - ya) / (yb - ya), 0.0, 1.0);
      eval_.unscaled(cet::Point2{qa.x + f * (qb.x - qa.x), qa.y + f * (qb.y - qa.y)}, u, v);
      if (uDir)
        u = line;
      else
        v = line;
      longest = length;
      break;
    }
  }
  return longest >= 0;
}

// Beside a pole, or a part of the surface collapsed onto a point, the surface's speed changes by
// orders of magnitude within a triangle, and the refinement's few Gauss-Newton steps from a sample's
// (u, v) may stop short of its foot: the distance read is to where they stopped, the same whatever
// the triangle's apex, and the splits pile points up against the boundary (a fuzzed fan, most of it
// collapsed onto one point: 91916 triangles at 5.6%, 19643 flipped, where the measure found the
// face within 0.22 of the tolerance). Such a triangle is split only where the measure, which the
// promise is judged by (damped steps, then seeds from a grid over the triangle), finds it too far
// as well (the measure's deviation costs several times the refinement's: asked only there). So is
// a triangle measured because its angle split was dropped (kMeasureChordal), whose split overrides
// the chords' clearance: taken on the refinement's reading alone, those splits cascaded against
// the chords on fuzzed faces the measure finds within their tolerance (seed 303: 214k flipped
// triangles instead of 189k).
bool FaceMesher::withinByTheMeasure(cet::TriangleId t, const FaceMesh& mesh, const TriangleRecord& r, double reachable) const {
  if (exactDeviation_ || (r.flags & (TriangleRecord::kCollapsed | TriangleRecord::kUnmeasured)) ||
      !(r.flags & (TriangleRecord::kPoleCorner | TriangleRecord::kMeasureChordal)))
    return false;
  // A triangle the refinement left to the angle is held to the tolerance itself (the promise), not
  // to the margin inside it the refinement aims at: its split overrides the chords, so no more of
  // those than the promise needs.
  return measuredWithin(
      t, mesh, (r.flags & TriangleRecord::kMeasureChordal) ? reachable / kDeviationMargin : reachable);
}

bool FaceMesher::measuredWithin(cet::TriangleId t, const FaceMesh& mesh, double bound) const {
  const Corners c = corners(t, mesh);
  if (c.wraps) return false;
  double positions[9], uv[6];
  for (int i = 0; i < 3; ++i) {
    positions[3 * i] = c.p[i].X(), positions[3 * i + 1] = c.p[i].Y(), positions[3 * i + 2] = c.p[i].Z();
    uv[2 * i] = c.u[i], uv[2 * i + 1] = c.w[i];
  }
  // Read as the promise is judged (measureFaces): its own SurfaceEval, the corners in the order the
  // level's index array gives them. On wild parametrisations the measure's reading hangs on where
  // its projections start, down to rounding: a fuzzed triangle read 9e-6 in one corner order and
  // 0.0036 (10.6x its tolerance) in another, and a split dropped on the one reading left the level
  // over its tolerance by the other.
  if (!judge_) judge_ = std::make_unique<SurfaceEval>(eval_.adaptor().Face());
  static const std::uint32_t kForward[3] = {0, 1, 2}, kReversed[3] = {0, 2, 1};
  return measureDeviation(*judge_, positions, uv, settings_.reversed ? kReversed : kForward, 1, bound,
                          bound) <= bound;
}

bool FaceMesher::refine(int levelIndex, const Level& level, FaceMesh& mesh, const std::atomic<bool>* cancel) {
  const double chordal = deviationMargin() * level.chordal;
  const double minSize = 0.1 * level.chordal;  // no angular or orientation split below it (BRepMesh's MinSize)
  // The records keep cosines in float (about 6e-8 apart near the tolerance, 5e-7 of the angle):
  // the threshold sits a little inside the angle so that no rounding lets an edge past it.
  const AngleSplit angleSplit{static_cast<float>(std::cos(level.angleRad * (1 - 2e-6))), static_cast<float>(minSize)};
  std::vector<gp_Pnt2d> uvs;
  if (settings_.trace) std::fprintf(stderr, "refine to %g (angle %g)\n", level.chordal, level.angleRad);
  buildChords(mesh);  // the boundary is fixed while the interior refines
  if (refineLevel_ != levelIndex)
    quadFlips_.clear(), pivotFlips_.clear(), vertexPivotFlips_.clear(), failedSplits_.clear(),
        noFold_.clear();
  int flippedSplits = 0;  // splits of flipped triangles, this level (kMaxFlippedSplits)
  int foldTroubleThisCall = 0;
  // Counted from the level's first call: a cancelled level resumes to the mesh an uninterrupted run makes.
  if (refineLevel_ != levelIndex) refineLevel_ = levelIndex, refineStart_ = cdt_->vertexCount();
  makeLattice();
  const std::size_t start = refineStart_;
  const std::size_t mostPoints = refinePointBound(start, settings_.maxRefinePoints);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    if (cancel && cancel->load(std::memory_order_relaxed)) return false;
    if (cdt_->vertexCount() - start > mostPoints) {
      char line[200];
      std::snprintf(line, sizeof line, "refinement stopped on level %d after %zu points (%zu before it): the level's tolerances "
                    "are not reached on this face", levelIndex, cdt_->vertexCount() - start, start);
      repairs_.push_back(line);
      repaired_ = true;
      refinementStopped_ = true;
      return true;
    }
    const int stamp = ++passStamp_;
    const cet::CetMesh& m = cdt_->mesh();
    points_.clear();
    uvs.clear();
    splitTriangles_.clear();
    splitKeys_.clear();
    flips_.clear();
    foldSplits_.clear();
    int waiting = 0;  // triangles put off to the next pass: a corner taken by another's split
    const auto triangles = static_cast<cet::TriangleId>(m.triangleCount());
    nextWork_.clear();
    // The first pass looks at every triangle (the tolerances are new); later ones only at the
    // triangles the previous pass changed (all incident to its new vertices: insertion and Lawson's
    // flips only make triangles around the inserted point) and those it put off, in id order: a
    // triangle that needs no split has no effect on the others, so this is the full scan's result.
    visit_.clear();
    if (pass == 0) {
      for (cet::TriangleId t = 0; t < triangles; ++t)
        if (!m.isGhost(t) && !m.isOutside(t)) visit_.push_back(t);
    } else {
      // Each once, in id order: marked in a bitmap and read back word by word (a new point's ~6
      // triangles are mostly its neighbours' too; sorting the list took 2% of A319's time).
      workBits_.assign((triangles + 63) / 64, 0);
      for (const cet::TriangleId t : work_) workBits_[t >> 6] |= std::uint64_t{1} << (t & 63);
      for (std::size_t w = 0; w < workBits_.size(); ++w) {
        for (std::uint64_t bits = workBits_[w]; bits != 0; bits &= bits - 1) {
          const auto t = static_cast<cet::TriangleId>(64 * w + static_cast<std::size_t>(__builtin_ctzll(bits)));
          if (!m.isGhost(t) && !m.isOutside(t)) visit_.push_back(t);
        }
      }
    }
    // Triangles without a current record are measured, in parallel where the run has idle workers.
    measured_.clear();
    if (measuredStamp_.size() < triangles) measuredStamp_.resize(triangles, -1);
    for (const cet::TriangleId t : visit_) {
      const TriangleRecord* r = records_.find(t, m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2));
      if (!r || ((r->flags & TriangleRecord::kUnmeasured) &&
                 (!angleSplit.splits(*r) ||
                  (r->flags & TriangleRecord::kMeasureChordal)))) {  // (a looser angle now)
        measured_.push_back(t);
        measuredStamp_[t] = stamp;
      }
    }
    records_.reserve(triangles);
    // evaluateTriangle makes each entry afresh: when the pass outgrows the array, the old entries
    // are dropped rather than copied, so the allocator can hand back the same memory, extended.
    if (pending_.capacity() < measured_.size()) {
      std::vector<Pending>().swap(pending_);
      pending_.reserve(measured_.size() + measured_.size() / 2);
    }
    pending_.resize(measured_.size());
    // A pass over a whole level's triangles can take a second on a wild face: the cancel flag is
    // read every few triangles (a cancelled level resumes to the same mesh: no point or flip is
    // made before the pass is decided, and records left half measured are dropped).
    const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    const std::function<void(std::size_t, std::size_t)> measure = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        if ((i - begin) % kCancelGrain == 0 && cancelled()) return;
        evaluateTriangle(measured_[i], mesh, angleSplit, stamp, records_.at(measured_[i]), pending_[i]);
      }
    };
    const std::function<void(std::size_t, std::size_t)> finish = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        if ((i - begin) % kCancelGrain == 0 && cancelled()) return;
        if (pending_[i].deferred) finishTriangle(measured_[i], mesh, records_.at(measured_[i]), pending_[i]);
      }
    };
    if (settings_.sharing && eval_.concurrentSafe()) {
      settings_.sharing->forEach(measured_.size(), kMeasureGrain, measure);
      settings_.sharing->forEach(measured_.size(), kMeasureGrain, finish);
    } else {
      measure(0, measured_.size());
      finish(0, measured_.size());
    }
    if (cancelled()) {
      for (const cet::TriangleId t : measured_) records_.at(t).v[0] = cet::kNoVertex;
      return false;
    }

    std::size_t decided = 0;
    for (const cet::TriangleId t : visit_) {
      if (++decided % kCancelGrain == 0 && cancelled()) return false;
      const TriangleRecord* r = &records_.at(t);
      // Barycentric split point: 0 the centroid, 1 + i the midpoint of edge i.
      int at = -1, flipEdge = -1;
      bool forAngle = false, forDeviation = false, forFold = false, forCrease = false;
      double foldU = 0, foldV = 0;  // (also a crease point's)
      gp_Dir foldBefore, foldAfter;
      // Corners off the surface (edge points of an edge that strays from it within its tolerance)
      // hold the triangle that far from it at those corners whatever its size. Within the level's
      // tolerance, the samples inside take a corner's distance only in part, and as the triangles
      // shrink they come within the target wherever the corners are: the target then, or the
      // corners' distance where that is larger (with the target plus the distance, a fuzzed face
      // with corners 3.6e-6 off its surface ended 1.16x its tolerance of 1.02e-5). Beyond the
      // level's tolerance, the target plus the distance: the deviation it can reach (held to the
      // distance alone, a fuzzed face straying 8x its tolerance took 391 flipped triangles instead
      // of 6). A face whose edges stray beyond the final deflection says so (strayReported_).
      const double off =
          std::max({offset_[m.vertex(t, 0)], offset_[m.vertex(t, 1)], offset_[m.vertex(t, 2)]});
      const double reachable = off <= level.chordal ? std::max(chordal, off) : chordal + off;
      // Triangles at a fold point that face away while their corners agree: a few are split as any
      // such triangle is (A319's wing tips, Propeller's blade tips); more, and the fold's line bends
      // between its points or the sheet folds more than once there, and fold points and splits
      // beside them fed each other (a fuzzed flat sheet's level: 21 -> 1071 triangles, 671
      // flipped). Past kFoldTrouble of them on a level, no more fold points on the face, nor such
      // splits at its fold points.
      const bool atFold =
          !folds_.empty() && (isFold(m.vertex(t, 0)) || isFold(m.vertex(t, 1)) || isFold(m.vertex(t, 2)));
      if (atFold && ((r->flags & TriangleRecord::kFlipped) || r->facetCos < 0) && r->normalCos >= 0 &&
          ++foldTroubleThisCall > kFoldTrouble)
        foldsFailed_ = true;
      // A triangle across a fold is split for its deviation only where the measure also reads it
      // over: the refinement's projections start on the wrong side of the fold and stall there, and
      // its splits along a sheet folded flat (no fold point found: the normals exactly opposed),
      // each a hair off the fold, made slivers across it that read over again (a fuzzed sheet's
      // last level: 79141 triangles, 5811 flipped; 75 and 8 so).
      if (r->deviation > reachable &&
          (r->longest > 1e-3 * level.chordal || (r->flags & TriangleRecord::kCollapsed)) &&
          !withinByTheMeasure(t, mesh, *r, reachable) &&
          !((r->flags & TriangleRecord::kAcrossFold) && measuredWithin(t, mesh, reachable))) {
        at = r->worstSample;
        forDeviation = true;
      } else if (r->flags & TriangleRecord::kCollapsed) {
        at = -1;
      } else if ((r->flags & TriangleRecord::kAcrossFold) && !foldsFailed_ &&
                 r->longest > kFoldFloor * level.chordal && foldRoom() &&
                 foldPoint(t, mesh, level.angleRad, foldU, foldV, foldBefore, foldAfter)) {
        // An edge across a fold of the parametrisation: no flat triangle across it faces both ways
        // (nor does any split beside the fold end that). A point on the fold, with a normal for each
        // side (appendFoldTwin), lets the triangles on either side face their own.
        at = 0;
        forFold = true;
      } else if (angleSplit.splits(*r)) {
        at = m.isConstrained(t, r->angleEdge) ? 0 : 1 + r->angleEdge;
        forAngle = true;
        // Between two fold points the fold runs on: the point splitting their edge is one too.
        const cet::VertexId ea = m.vertex(t, (r->angleEdge + 1) % 3),
                            eb = m.vertex(t, (r->angleEdge + 2) % 3);
        if (at > 0 && isFold(ea) && isFold(eb) && !foldsFailed_ && foldRoom() &&
            foldBetween(ea, eb, mesh, level.angleRad, foldU, foldV, foldBefore, foldAfter)) {
          at = 0;
          forAngle = false, forFold = true;
        }
      } else if ((r->flags & TriangleRecord::kAcrossCrease) && r->longest > minSize &&
                 creasePoint(t, mesh, foldU, foldV)) {
        // Corners a hair either side of a crease (points the deviation put beside it): the facet
        // stands for both sides and shows each one's normal at its corners, a streak of the other
        // side's shading across it. A point on the crease where the edge crosses it, with a normal
        // for each side (showCreaseCorners), puts the triangles on either side.
        at = 0;
        forCrease = true;
      } else if (((r->flags & TriangleRecord::kFlipped) || r->facetCos < kFoldCos) && !allSingular(t) &&
                 !inLineOnChordIntoPole(t, *r) && flippedSplits < kMaxFlippedSplits &&
                 (r->longest > minSize || (splitsBelowMinSize(*r) && !(atFold && foldsFailed_) &&
                                           r->longest > 1e-3 * level.chordal))) {
        // Flipped, or folded (the facet turns further from the surface than its corners' spread
        // allows): such triangles are slivers; bisect the longest free edge (a centroid would make
        // thinner ones), unless flipping an edge puts them right (repairingFlip).
        at = r->longestFreeEdge < 3 ? 1 + r->longestFreeEdge : 0;
        if (r->longest > level.chordal) flipEdge = repairingFlip(t, mesh);
        if (flipEdge < 0 && (huggingPoleChord(t, *r, mesh) || alongChord(t))) continue;
        if (flipEdge < 0) ++flippedSplits;
      }
      if (at < 0) continue;
      if (flipEdge < 0 && !failedSplits_.empty() &&
          failedSplits_.count(triangleKey(m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2))))
        continue;
      // One split per neighbourhood and pass: points requested by adjacent triangles in the same
      // pass crowd each other and leave slivers that need more points.
      if (touched_.size() < m.vertexCount()) touched_.resize(m.vertexCount(), -1);
      if (touched_[m.vertex(t, 0)] == stamp || touched_[m.vertex(t, 1)] == stamp || touched_[m.vertex(t, 2)] == stamp) {
        nextWork_.push_back(t);  // again next pass
        ++waiting;
        continue;
      }
      if (flipEdge >= 0) {
        const cet::EdgeRef across = m.twin(cet::EdgeRef{t, flipEdge});
        const cet::VertexId d = m.vertex(across.t, across.i);
        if (touched_[d] == stamp) {
          nextWork_.push_back(t);
          continue;
        }
        if (settings_.trace) {
          std::fprintf(stderr, "pass %d: triangle %u (%u %u %u; facet %g) flipped on edge %d to %u\n", pass, t, m.vertex(t, 0),
                       m.vertex(t, 1), m.vertex(t, 2), r->facetCos, flipEdge, d);
        }
        for (int i = 0; i < 3; ++i) touched_[m.vertex(t, i)] = stamp;
        touched_[d] = stamp;
        flips_.emplace_back(t, flipEdge);
        continue;
      }
      double b[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
      if (at > 0) b[0] = b[1] = b[2] = 0.5, b[at - 1] = 0;
      if (at == 0 && forDeviation && exactDeviation_) {  // inside, too far from an analytic surface (split_point.h)
        const cet::Point2 p[3] = {cdt_->point(m.vertex(t, 0)), cdt_->point(m.vertex(t, 1)), cdt_->point(m.vertex(t, 2))};
        const bool chord[3] = {m.isConstrained(t, 0), m.isConstrained(t, 1), m.isConstrained(t, 2)};
        analyticSplitWeights(p, chord, b);
      }
      double cu[3], cv[3];
      for (int i = 0; i < 3; ++i) {
        const std::size_t o = out(m.vertex(t, i));
        cu[i] = mesh.uv[2 * o], cv[i] = mesh.uv[2 * o + 1];
      }
      double u = 0, v = 0;
      eval_.blend(3, b, cu, cv, u, v);
      if (forFold || forCrease) u = foldU, v = foldV;
      // Too far from a surface across a sharp knot or a bend: the worst sample sits by the line,
      // where the surface bends, and a point beside it leaves the bend cut by the triangles on either
      // side and slivers along it (a fuzzed band: 234 triangles flipped beside a sharp knot; a fuzzed
      // tube across a bend where its speed jumps 50-fold: 135233 triangles, 249 flipped). A point on
      // the line puts the bend on edges of the mesh (6 flipped besides those across the knot; the
      // tube 8689 triangles, 1 flipped besides those across folds).
      if (forDeviation) ontoCreaseLine(t, mesh, u, v);
      // Splits for the deviation or the angle move onto the face's lattice, if it has one (a point
      // moved there is clear of the chords: snapToLattice asked).
      const bool snapped = (forDeviation || forAngle) && snapToLattice(t, u, v);
      // The chordal promise outranks the clearance (which only guards against folds): a triangle
      // too far from the surface is split at its worst sample regardless.
      const bool tooFar = r->deviation > reachable;
      const bool flipped = (r->flags & TriangleRecord::kFlipped) || r->facetCos < 0;
      // So does a flipped triangle larger than the tolerance (small faces at coarse levels, where a
      // chord's clearance can cover the whole face), unless it stands on a boundary chord: its
      // split points (midpoints of the edges to the chord's ends) come twice as close to the chord
      // as its apex, and the triangle they make on the chord is flipped as well, as long as the
      // chord itself: a cascade towards the boundary that no size test stops.
      const bool largeFlipped = flipped && r->longest > level.chordal && !onChord(t);
      // A fold point stays on the fold: taken where it keeps the chords' clearance, else not at all.
      bool override = !forFold && !forCrease && (tooFar || largeFlipped);
      const bool safe = snapped || (forFold || forCrease ? clearOfChords(u, v, true)
                                                         : (r->flags & TriangleRecord::kCollapsed) ||
                                                               safeSplit(t, u, v, mesh, flipped, forAngle, at - 1));
      // Overriding the clearance on the refinement's reading alone: where its few Gauss-Newton steps
      // stop short of the foot (a parametrisation far from uniform, its speed across a side 1e-4 of
      // that along it), the reading stays over the tolerance however near the chord the point comes,
      // and centroid splits marched towards a chord, each a third as far as the one before, until
      // the point bound (a fuzzed pyramid: 501884 triangles on a level, 71973 of no area, where the
      // measure finds the face within 0.85 of the tolerance). The measure (the promise's judge)
      // decides such an override, against the margin the refinement aims at rather than the
      // tolerance itself (against the tolerance, a fuzzed face's last level read 1.0003x); asked
      // only for splits that break the clearance, so seldom.
      if (!safe && !forFold && !forCrease && tooFar && !largeFlipped && !exactDeviation_ &&
          !(r->flags & TriangleRecord::kCollapsed) && measuredWithin(t, mesh, reachable)) {
        override = false;
        if (settings_.trace)
          std::fprintf(stderr, "pass %d: triangle %u (deviation %g) within by the measure: split dropped\n",
                       pass, t, r->deviation);
      }
      if (!safe && !override) {
        if (settings_.trace) std::fprintf(stderr, "pass %d: triangle %u (split at %d) dropped: not clear of chords\n", pass, t, at);
        // Never measured (the angle split it): measured next pass, its deviation split regardless
        // of the chords if too far (a fuzzed face's last level kept 112 such triangles up to 6.2x
        // its tolerance, silently).
        if (r->flags & TriangleRecord::kUnmeasured) {
          records_.at(t).flags |= TriangleRecord::kMeasureChordal;
          nextWork_.push_back(t);
        }
        continue;
      }
      if (forAngle && safe && at > 0 && !snapped) keepRowWithinAngleOfChord(t, at - 1, mesh, angleSplit.minCos, u, v);
      if (settings_.trace) {
        std::fprintf(stderr, "pass %d: triangle %u (deviation %g, normal cosine %g, facet %g, longest %g, flags %d) split at (%.6f, %.6f)\n",
                     pass, t, r->deviation, r->normalCos, r->facetCos, r->longest, r->flags, u, v);
      }
      // A point the predicates cannot handle is no split: refinement towards a corner (a pole, a
      // sliver) must not end in underflowing coordinates.
      const cet::Point2 q = scaled(u, v);
      if (!supported(q)) continue;
      for (int i = 0; i < 3; ++i) touched_[m.vertex(t, i)] = stamp;
      if (forFold) foldSplits_.push_back(FoldSplit{points_.size(), foldBefore, foldAfter}), ++foldPointCount_;
      uvs.emplace_back(u, v);
      points_.push_back(q);
      splitTriangles_.push_back(t);
      splitKeys_.push_back(triangleKey(m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2)));
    }
    // The flips first: their quadrilaterals share no vertex with each other or with a split
    // triangle (touched_), so none of them has changed since it was chosen.
    for (const auto& [t, i] : flips_) {
      // t = (a, b, c), d across edge i: the flip takes diagonal (b, c) away and makes (a, d).
      const cet::VertexId a = m.vertex(t, i), b = m.vertex(t, (i + 1) % 3), c = m.vertex(t, (i + 2) % 3);
      const cet::EdgeRef across = m.twin(cet::EdgeRef{t, i});
      const cet::VertexId d = m.vertex(across.t, across.i);
      if (!cdt_->flipEdge(t, i)) continue;
      ++quadFlips_[quadKey(b, c, a, d)];
      ++pivotFlips_[pairKey(a, b)], ++pivotFlips_[pairKey(a, c)];
      ++vertexPivotFlips_[a];
      nextWork_.push_back(t);
      nextWork_.push_back(m.neighbor(t, 1));  // t = (a, b, d), its neighbour (a, d, c) across edge 1
    }
    if (points_.empty() && flips_.empty()) return true;
    const auto countBefore = static_cast<cet::VertexId>(cdt_->vertexCount());
    ids_.assign(points_.size(), cet::kNoVertex);
    outcomes_.assign(points_.size(), cet::InsertOutcome::kOutside);
    if (!points_.empty()) cdt_->insertPoints(points_.data(), points_.size(), ids_.data(), outcomes_.data(), splitTriangles_.data());
    const auto countAfter = static_cast<cet::VertexId>(cdt_->vertexCount());
    const std::size_t failedBefore = failedSplits_.size();
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (outcomes_[i] != cet::InsertOutcome::kInserted) failedSplits_.insert(splitKeys_[i]);
    // Every request merged or rejected: nothing left to gain, unless a triangle waited for its
    // turn beside one of them.
    if (countAfter == countBefore && flips_.empty() && (waiting == 0 || failedSplits_.size() == failedBefore))
      return true;
    std::vector<std::uint32_t> inputOf(countAfter - countBefore, UINT32_MAX);
    for (std::size_t i = 0; i < ids_.size(); ++i)
      if (outcomes_[i] == cet::InsertOutcome::kInserted && ids_[i] >= countBefore) inputOf[ids_[i] - countBefore] = static_cast<std::uint32_t>(i);
    for (cet::VertexId id = countBefore; id < countAfter; ++id) {
      int around = 0;  // bounded: a vertex has a finite star
      for (cet::TriangleId t = m.incident(id), first = t; t != cet::kNoTriangle && around < 4096; ++around) {
        nextWork_.push_back(t);
        t = m.nextAround(t, id);
        if (t == first) break;
      }
      const std::uint32_t i = inputOf[id - countBefore];
      if (i != UINT32_MAX) {
        appendVertex(mesh, uvs[i].X(), uvs[i].Y(), nullptr);
        const auto fold = std::lower_bound(foldSplits_.begin(), foldSplits_.end(), std::size_t{i},
                                           [](const FoldSplit& f, std::size_t x) { return f.point < x; });
        if (fold != foldSplits_.end() && fold->point == i)
          appendFoldTwin(mesh, id, fold->before, fold->after);
      } else {
        const cet::Point2 q = cdt_->point(id);
        double u = 0, v = 0;
        eval_.unscaled(q, u, v);
        appendVertex(mesh, u, v, nullptr);
      }
    }
    work_.swap(nextWork_);
  }
  char line[200];
  std::snprintf(line, sizeof line,
                "refinement stopped on level %d after %d passes (%zu points): the level's tolerances "
                "are not reached on this face",
                levelIndex, kMaxPasses, cdt_->vertexCount() - start);
  repairs_.push_back(line);
  repaired_ = true;
  refinementStopped_ = true;
  return true;
}

void FaceMesher::makeLattice() {
  if (latticeMade_) return;
  latticeMade_ = true;
  const BRepAdaptor_Surface& surface = eval_.adaptor();
  if (eval_.flat()) return;  // (never for tori and spheres; snapToLattice maps u and v on their own)
  TorusLatticeSpec spec;
  spec.u0 = eval_.uMin, spec.u1 = eval_.uMax, spec.v0 = eval_.vMin, spec.v1 = eval_.vMax;
  const GeomAbs_SurfaceType type = surface.GetType();
  if (type == GeomAbs_Torus) {
    const gp_Torus torus = surface.Torus();
    spec.major = torus.MajorRadius(), spec.minor = torus.MinorRadius();
  } else if (type == GeomAbs_Sphere) {
    spec.major = 0, spec.minor = surface.Sphere().Radius();  // a torus without its ring
  } else if (eval_.ringAngles()) {
    ringAngles_ = &*eval_.ringAngles();
    spec.major = ringAngles_->major, spec.minor = ringAngles_->minor;
    spec.u0 = ringAngles_->ring.firstAngle(), spec.u1 = ringAngles_->ring.lastAngle();
    spec.v0 = ringAngles_->tube.firstAngle(), spec.v1 = ringAngles_->tube.lastAngle();
  } else {
    return;
  }
  // A little inside the refinement's target: lattice triangles right at it, read a hair over (the
  // torus is not quite its quadratic), were split off the lattice (at 1.05 of it, a full torus of
  // 80 x 2.5 at 0.001 took 1.19x the triangles it took at 1.0; at 0.95, 1.05x).
  spec.deviation = 0.95 * deviationMargin() * settings_.finalChordal;
  spec.angle = settings_.finalAngle;
  spec.maxPoints = static_cast<double>(kRefineCeiling);
  lattice_ = std::make_unique<TorusLattice>(spec);
  if (lattice_->empty()) lattice_.reset();
}

void FaceMesher::latticePointsNear(double u, double v) {
  latticeNear_.clear();
  if (!ringAngles_) {
    lattice_->near(u, v, latticeRaw_);
    for (const LatticePoint& p : latticeRaw_) latticeNear_.push_back({p.u, p.v, p.step, lattice_->vStep()});
    return;
  }
  // In the disguised surface's angles, and back: the lattice's u runs along the ring, its v round
  // the tube.
  const RingAngles& a = *ringAngles_;
  const double ringParam = a.tubeAlongU ? v : u, tubeParam = a.tubeAlongU ? u : v;
  lattice_->near(a.ring.angle(ringParam), a.tube.angle(tubeParam), latticeRaw_);
  for (const LatticePoint& p : latticeRaw_) {
    const double r = a.ring.param(p.u), t = a.tube.param(p.v);
    const double rowStep = a.ring.param(p.u + p.step) - r, across = a.tube.param(p.v + lattice_->vStep()) - t;
    if (!(rowStep > 0) || !(across > 0)) continue;  // at the box's end: no span to measure clearance by
    latticeNear_.push_back(a.tubeAlongU ? LatticeCandidate{t, r, across, rowStep} : LatticeCandidate{r, t, rowStep, across});
  }
}

bool FaceMesher::snapToLattice(cet::TriangleId t, double& u, double& v) {
  if (!lattice_) return false;
  latticePointsNear(u, v);
  if (latticeNear_.empty()) return false;
  const cet::CetMesh& m = cdt_->mesh();
  const cet::Point2 p[3] = {cdt_->point(m.vertex(t, 0)), cdt_->point(m.vertex(t, 1)), cdt_->point(m.vertex(t, 2))};
  // The circumcircle, in scaled UV.
  const double bx = p[1].x - p[0].x, by = p[1].y - p[0].y, cx = p[2].x - p[0].x, cy = p[2].y - p[0].y;
  const double det = 2 * (bx * cy - by * cx);
  if (!(std::abs(det) > 0)) return false;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double ox = (cy * b2 - by * c2) / det, oy = (bx * c2 - cx * b2) / det;
  const double radius2 = ox * ox + oy * oy;
  const auto side = [](const cet::Point2& a, const cet::Point2& b, const cet::Point2& q) {
    return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
  };
  // Whether q lies in t, or in the neighbour across one free edge of t (inside that neighbour's
  // other edges): a point outside the domain fails to insert, and t is then given up on for the
  // level. The corners it must keep clear of: t's, and that neighbour's apex.
  const auto inCavity = [&](const cet::Point2& q, cet::Point2& apex) {
    apex = p[0];
    int beyond = -1;
    for (int i = 0; i < 3; ++i) {
      // edge i runs from corner i + 1 to corner i + 2 (counter-clockwise)
      if (side(p[(i + 1) % 3], p[(i + 2) % 3], q) > 0) continue;
      if (beyond >= 0 || m.isConstrained(t, i)) return false;
      beyond = i;
    }
    if (beyond < 0) return true;
    const cet::EdgeRef across = m.twin(cet::EdgeRef{t, beyond});
    const cet::TriangleId n = across.t;
    if (n == cet::kNoTriangle || m.isGhost(n) || m.isOutside(n)) return false;
    for (int i = 0; i < 3; ++i) {
      if (i == across.i) continue;
      if (side(cdt_->point(m.vertex(n, (i + 1) % 3)), cdt_->point(m.vertex(n, (i + 2) % 3)), q) <= 0) return false;
    }
    apex = cdt_->point(m.vertex(n, across.i));
    return true;
  };
  // The nearest candidate that splits t, keeps half a lattice step from the corners about it and
  // is clear of the boundary chords (a deviation split overrides the clearance, so a point moved
  // towards a chord must not come closer than the chords allow). Nearest in the scaled plane, as
  // the axes' local slopes put it (each exact map is a search along the axis' pieces): most
  // splits take their first candidate. (The scaled plane maps u and v each on its own: off flat
  // faces, which have no lattice.)
  const UvAxis& uAxis = eval_.uAxis();
  const UvAxis& vAxis = eval_.vAxis();
  const double x0 = uAxis.map(u), y0 = vAxis.map(v);
  const double du = latticeNear_[0].stepU, dv = latticeNear_[0].stepV;
  const double slopeU = (uAxis.map(u + du) - x0) / du, slopeV = (vAxis.map(v + dv) - y0) / dv;
  latticeOrder_.clear();
  for (std::size_t k = 0; k < latticeNear_.size(); ++k) {
    const double ax = (latticeNear_[k].u - u) * slopeU, ay = (latticeNear_[k].v - v) * slopeV;
    latticeOrder_.emplace_back(ax * ax + ay * ay, k);
  }
  std::sort(latticeOrder_.begin(), latticeOrder_.end());
  const auto squared = [](const cet::Point2& a, const cet::Point2& b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
  };
  for (const auto& [away, k] : latticeOrder_) {
    const LatticeCandidate& lp = latticeNear_[k];
    const cet::Point2 q{uAxis.map(lp.u), vAxis.map(lp.v)};
    if (!supported(q)) continue;
    const double dx = q.x - p[0].x - ox, dy = q.y - p[0].y - oy;
    if (!(dx * dx + dy * dy < 0.98 * radius2)) continue;
    cet::Point2 apex;
    if (!inCavity(q, apex)) continue;
    const double along = uAxis.map(lp.u + lp.stepU) - q.x, across = vAxis.map(lp.v + lp.stepV) - q.y;
    const double crowd2 = 0.25 * std::min(along * along, across * across);
    bool crowded = squared(apex, q) < crowd2;
    for (int i = 0; i < 3; ++i) crowded = crowded || squared(p[i], q) < crowd2;
    if (crowded || !clearOfChords(lp.u, lp.v, false)) continue;
    u = lp.u, v = lp.v;
    return true;
  }
  return false;
}

void FaceMesher::twinSingularCorners(FaceMesh& mesh) {
  const cet::CetMesh& m = cdt_->mesh();
  const auto triangles = static_cast<cet::TriangleId>(m.triangleCount());
  for (cet::TriangleId t = 0; t < triangles; ++t) {
    if (m.isGhost(t) || m.isOutside(t)) continue;
    const cet::VertexId v[3] = {m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2)};
    if (!singular_[v[0]] && !singular_[v[1]] && !singular_[v[2]]) continue;
    const gp_Pnt P[3] = {position(mesh, v[0]), position(mesh, v[1]), position(mesh, v[2])};
    const gp_Vec side = triangleSide(v, P);
    if (!(side.Magnitude() > 0)) continue;
    double cu = 0, cv = 0;
    for (int i = 0; i < 3; ++i) cu += mesh.uv[2 * out(v[i])] / 3, cv += mesh.uv[2 * out(v[i]) + 1] / 3;
    for (int i = 0; i < 3; ++i) {
      if (!singular_[v[i]] || singularTwins_.count(v[i]) || gp_Vec(normal_[v[i]]).Dot(side) >= 0) continue;
      // The normal on the triangle's side: the surface's an eighth of the way to its centroid, else
      // the first regular one nearer (its limit at the point can be far from the surface beside it:
      // shell1's face 40 curls within 1e-3 of its pole row, where the limit turns 45 degrees and more
      // from the sheet; shown, it shaded the curl over the fan triangle's whole width).
      const std::size_t o = out(v[i]);
      const double u = mesh.uv[2 * o], w = mesh.uv[2 * o + 1];
      if (eval_.pinches(u, w, cu - u, cv - w, side))
        continue;  // a pole: its row has one point, not two sides
      for (int k = SurfaceEval::kFoldReach; k <= SurfaceEval::kFoldBisections; ++k) {
        const double e = std::ldexp(1.0, -k);
        gp_Pnt p;
        gp_Dir n;
        if (!eval_.pointNormal(u + e * (cu - u), w + e * (cv - w), p, n) || gp_Vec(n).Dot(side) <= 0)
          continue;
        singularTwins_[v[i]] = FoldVertex{n, appendTwin(mesh, v[i], n)};
        break;
      }
    }
  }
}

void FaceMesher::showCreaseCorners(FaceMesh& mesh) {
  if (!eval_.hasCreases()) return;
  const cet::CetMesh& m = cdt_->mesh();
  const auto triangles = static_cast<cet::TriangleId>(m.triangleCount());
  const std::uint32_t published = mesh.levelVertexEnd.empty() ? 0 : mesh.levelVertexEnd.back();
  const double sign = settings_.reversed ? -1.0 : 1.0;
  for (cet::TriangleId t = 0; t < triangles; ++t) {
    if (m.isGhost(t) || m.isOutside(t)) continue;
    const cet::VertexId v[3] = {m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2)};
    double u[3], w[3], cu = 0, cw = 0;
    bool on[3], any = false;
    for (int i = 0; i < 3; ++i) {
      const std::size_t o = out(v[i]);
      u[i] = mesh.uv[2 * o], w[i] = mesh.uv[2 * o + 1];
      cu += u[i] / 3, cw += w[i] / 3;
      on[i] = !singular_[v[i]] && !isFold(v[i]) && eval_.onCrease(u[i], w[i]);
      any = any || on[i];
    }
    if (!any) continue;
    // Across a crease (a corner off the creases with one between it and the centroid): no one side.
    bool across = false;
    for (int i = 0; i < 3; ++i) across = across || (!on[i] && eval_.crossesCrease(u[i], w[i], cu, cw));
    if (across) continue;
    for (int i = 0; i < 3; ++i) {
      if (!on[i]) continue;
      const auto it = creaseCorners_.find(v[i]);
      if (it != creaseCorners_.end() && it->second.twin != kNoTwin) continue;  // both sides shown
      // The normal just inside the triangle: the first point on the way to its centroid that is off
      // the crease with no crease between it and the centroid.
      gp_Dir n;
      bool found = false;
      for (int k = SurfaceEval::kFoldBisections; k >= SurfaceEval::kFoldReach && !found; --k) {
        const double e = std::ldexp(1.0, -k);
        const double pu = u[i] + e * (cu - u[i]), pw = w[i] + e * (cw - w[i]);
        if (eval_.onCrease(pu, pw) || eval_.crossesCrease(pu, pw, cu, cw)) continue;
        gp_Pnt p;
        found = eval_.pointNormal(pu, pw, p, n);
        break;
      }
      if (!found) continue;
      const std::uint32_t o = out(v[i]);
      if (it == creaseCorners_.end()) {
        if (n.Angle(normal_[v[i]]) <= SurfaceEval::kSettledRad) {
          creaseCorners_[v[i]] = CreaseCorner{normal_[v[i]], kNoTwin, normal_[v[i]]};
        } else if (o >= published) {  // not sent with an earlier level: it shows this side's normal
          for (int c = 0; c < 3; ++c) mesh.normals[3 * o + c] = static_cast<float>(sign * n.Coord(c + 1));
          creaseCorners_[v[i]] = CreaseCorner{n, kNoTwin, n};
        } else {
          creaseCorners_[v[i]] = CreaseCorner{normal_[v[i]], appendTwin(mesh, v[i], n), n};
        }
      } else if (n.Angle(it->second.shown) > SurfaceEval::kSettledRad) {
        it->second.twin = appendTwin(mesh, v[i], n);
        it->second.other = n;
      }
    }
  }
}

std::vector<std::uint32_t> FaceMesher::snapshot(const FaceMesh& mesh) const {
  const cet::CetMesh& m = cdt_->mesh();
  std::vector<std::uint32_t> indices;
  indices.reserve(cdt_->insideTriangleCount() * 3);
  const auto triangles = static_cast<cet::TriangleId>(m.triangleCount());
  auto same = [&](std::uint32_t a, std::uint32_t b) {
    const double* p = &mesh.positions[3 * a];
    const double* q = &mesh.positions[3 * b];
    const double c = settings_.coincident;
    return std::abs(p[0] - q[0]) <= c && std::abs(p[1] - q[1]) <= c && std::abs(p[2] - q[2]) <= c;
  };
  for (cet::TriangleId t = 0; t < triangles; ++t) {
    if (m.isGhost(t) || m.isOutside(t)) continue;
    const cet::VertexId v[3] = {m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2)};
    std::uint32_t a = out(v[0]), b = out(v[1]), c = out(v[2]);
    const auto twinned = [this](cet::VertexId x) {
      return isFold(x) || (!singularTwins_.empty() && singularTwins_.count(x)) || isCreaseCorner(x);
    };
    if ((!folds_.empty() || !singularTwins_.empty() || !creaseCorners_.empty()) &&
        (twinned(v[0]) || twinned(v[1]) || twinned(v[2]))) {
      const gp_Pnt P[3] = {position(mesh, v[0]), position(mesh, v[1]), position(mesh, v[2])};
      const gp_Vec side = triangleSide(v, P);
      a = shownVertex(v[0], side), b = shownVertex(v[1], side), c = shownVertex(v[2], side);
    }
    if (same(a, b) || same(b, c) || same(a, c)) continue;  // collapsed on a pole, a singular row or a UV gap
    if (settings_.reversed) {
      indices.insert(indices.end(), {a, c, b});
    } else {
      indices.insert(indices.end(), {a, b, c});
    }
  }
  return indices;
}

// An edge of the face stopped at the point bound on level k: its chords, and the face's mesh
// beside them, may miss the level's tolerances (said once, as every repair).
void FaceMesher::noteCappedEdges(int k, const EdgeTable& edges) {
  for (const auto& loop : topology_.loops) {
    for (const LoopEdge& le : loop) {
      if (le.degenerated || !edges.points(le.edge, k).capped) continue;
      repairs_.push_back("an edge's discretisation stopped at " + std::to_string(EdgeTable::kMaxPoints) +
                         " points: its chords may miss the tolerances");
      repaired_ = true;
      return;
    }
  }
}

// Each repair once, in the order first made: a domain rebuilt on a later level repeats the repairs
// its wires needed ("inner wire ran counter-clockwise in UV; reversed" 24 times on a fuzzed face).
std::string FaceMesher::repairsReason(bool withDeferredLevels) const {
  std::string reason;
  for (std::size_t i = 0; i < repairs_.size(); ++i) {
    if (std::find(repairs_.begin(), repairs_.begin() + static_cast<std::ptrdiff_t>(i), repairs_[i]) !=
        repairs_.begin() + static_cast<std::ptrdiff_t>(i))
      continue;
    if (!withDeferredLevels && (repairs_[i].find(kDeferredLevel) != std::string::npos ||
                                repairs_[i].find(kEmptyLevel) != std::string::npos))
      continue;
    reason += (reason.empty() ? "" : "; ") + repairs_[i];
  }
  return reason;
}

void FaceMesher::clearVertexData() {
  normal_.clear();
  singular_.clear();
  offset_.clear();
  folds_.clear();
  singularTwins_.clear();
  creaseCorners_.clear();
  outShift_.clear();
  points_.clear();
  occurrences_.clear();
  boundaryProgress_ = BoundaryProgress{};
  noFold_.clear();  // vertex ids name other vertices in a new build
}

FaceStatus FaceMesher::abandonBuild(FaceMesh& mesh) {
  cdt_.reset();
  // The per-vertex arrays of the build go with its vertices (buildDomain() starts them afresh).
  clearVertexData();
  mesh.positions.resize(3 * std::size_t(base_));
  mesh.normals.resize(3 * std::size_t(base_));
  mesh.uv.resize(2 * std::size_t(base_));
  return FaceStatus::kCancelled;
}

FaceStatus FaceMesher::leaveEmpty(const std::string& why, FaceMesh& mesh, FaceReport& report) {
  cdt_.reset();
  records_.clear();
  fallback_ = true;
  fallbackStatus_ = FaceStatus::kEmpty;
  report.status = fallbackStatus_;
  report.reason = why;
  mesh.levels.emplace_back();
  mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(mesh.vertexCount()));
  return fallbackStatus_;
}

FaceStatus FaceMesher::useFallback(std::string why, FaceMesh& mesh, FaceReport& report,
                                   const std::atomic<bool>* cancel) {
  cdt_.reset();
  records_.clear();
  std::vector<std::uint32_t> indices;
  std::string failure;
  // A deferred coarse level has made the fallback mesh already (at the same tolerances): BRepMesh
  // can take seconds on a face whose boundary crosses itself.
  bool ok = true;
  if (!deferredFailure_.empty()) {
    ok = false;
    failure = deferredFailure_;
  } else if (deferredIndices_.empty()) {
    const FallbackResult result = fallbackJob_.run(topology_.face, settings_.reversed, settings_.finalChordal,
                                                   settings_.finalAngle, mesh, indices, failure, cancel);
    if (result == FallbackResult::kCancelled) {
      pendingFallback_ = why;
      return FaceStatus::kCancelled;
    }
    ok = result == FallbackResult::kMeshed;
  } else {
    indices = deferredIndices_;
  }
  pendingFallback_.clear();
  fallback_ = true;
  fallbackStatus_ = ok ? FaceStatus::kFallback : FaceStatus::kEmpty;
  report.status = fallbackStatus_;
  // What the face needed before it fell back (an edge stopped at its point bound, a wire reversed)
  // may be why it did: said after the cause. The deferred levels' lines repeat a cause; left out.
  const std::string before = repairsReason(false);
  report.reason =
      why + (before.empty() ? "" : "; " + before) + (ok ? "" : "; fallback failed too: " + failure);
  mesh.levels.push_back(std::move(indices));
  mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(mesh.vertexCount()));
  return fallbackStatus_;
}

// A coarse level whose boundary polygon crosses itself in UV (coarse chords of close loops can cross
// where finer ones do not): that level shows the fallback mesh, and the next level starts afresh.
FaceStatus FaceMesher::deferLevel(int k, std::string why, FaceMesh& mesh, FaceReport& report,
                                  const std::atomic<bool>* cancel) {
  cdt_.reset();
  records_.clear();
  if (deferredIndices_.empty() && deferredFailure_.empty()) {
    std::string failure;
    const FallbackResult result =
        fallbackJob_.run(topology_.face, settings_.reversed, settings_.finalChordal, settings_.finalAngle,
                         mesh, deferredIndices_, failure, cancel);
    if (result == FallbackResult::kCancelled) {
      pendingDefer_ = why;
      return FaceStatus::kCancelled;
    }
    pendingDefer_.clear();
    // BRepMesh failed: this level shows nothing and the next starts afresh all the same (a finer
    // boundary need not cross itself); useFallback() says so without running BRepMesh again.
    if (result == FallbackResult::kFailed) deferredFailure_ = failure;
  }
  if (deferredFailure_.empty()) {
    repairs_.push_back("level " + std::to_string(k) + kDeferredLevel + why);
  } else if (emptyLast_ >= 0 && emptyLast_ == k - 1 && emptyLine_ < repairs_.size()) {
    const std::string& line = repairs_[emptyLine_];
    repairs_[emptyLine_] = "levels " + std::to_string(emptyFirst_) + " to " + std::to_string(k) + " show" +
                           line.substr(line.find(kEmptyLevel));
    emptyLast_ = k;
  } else {
    emptyLine_ = repairs_.size(), emptyFirst_ = emptyLast_ = k;
    repairs_.push_back("level " + std::to_string(k) + " shows" + kEmptyLevel + why +
                       " (fallback failed too: " + deferredFailure_ + ")");
  }
  repaired_ = true;
  mesh.levels.push_back(deferredIndices_);
  mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(mesh.vertexCount()));
  // No triangles on this level: empty for now (a later level CET meshes says repaired).
  report.status = deferredFailure_.empty() ? FaceStatus::kRepaired : FaceStatus::kEmpty;
  report.reason = repairsReason();
  return report.status;
}

FaceStatus FaceMesher::advance(int k, const Level& level, const EdgeTable& edges, FaceMesh& mesh, FaceReport& report,
                               const std::atomic<bool>* cancel, bool finalLevel) {
  if (cancel && cancel->load(std::memory_order_relaxed)) return FaceStatus::kCancelled;
  if (fallback_) {
    // The fallback mesh is at the final tolerance: within every level's.
    mesh.levels.push_back(mesh.levels.back());
    mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(mesh.vertexCount()));
    report.status = fallbackStatus_;
    return fallbackStatus_;
  }
  // A fallback the flag stopped: BRepMesh again, for the same reason (the domain is not rebuilt).
  if (!pendingFallback_.empty()) return useFallback(pendingFallback_, mesh, report, cancel);
  if (!pendingDefer_.empty()) return deferLevel(k, pendingDefer_, mesh, report, cancel);
  if (!topology_.failure.empty()) return useFallback(topology_.failure, mesh, report, cancel);
  if (!areaChecked_) {
    areaChecked_ = true;
    if (eval_.collapsed()) return leaveEmpty("the surface has no area (it collapses onto a curve or a point)", mesh, report);
  }
  std::string problem;
  noteCappedEdges(k, edges);
  try {
    bool ok = true, cancelled = false;
    if (!cdt_) {
      ok = buildDomainFlatOrScaled(k, edges, mesh, problem, cancel, cancelled);
    } else if (boundaryLevel_ < k && flatRetry_) {
      // An earlier level's domain failed in the flat plane: this level's may not.
      ownEval_->useFlat(true);
      ok = buildDomainFlatOrScaled(k, edges, mesh, problem, cancel, cancelled);
      refinementStopped_ = false;
    } else if (boundaryLevel_ < k) {
      ok = refineBoundary(k, edges, mesh, problem, cancel, cancelled);
      if (cancelled) return FaceStatus::kCancelled;  // the next call goes on where it stopped
      if (!ok) {
        repairs_.push_back("rebuilt at level " + std::to_string(k) + ": " + problem);
        repaired_ = true;
        problem.clear();
        ok = buildDomainFlatOrScaled(k, edges, mesh, problem, cancel, cancelled);
        // The interior a stopped refinement left is gone with the old domain: the new one is refined
        // (bounded as any level). Kept stopped, a fuzzed face rebuilt after its level 1 stopped at
        // the pass bound showed its bare boundary triangulation on the levels after, 6.9x to 23.5x
        // their tolerances.
        refinementStopped_ = false;
      }
    }
    if (cancelled) return abandonBuild(mesh);
    if (!ok && !finalLevel) return deferLevel(k, problem, mesh, report, cancel);
    if (!ok) return useFallback(problem, mesh, report, cancel);
    if (!refinementStopped_ && !refine(k, level, mesh, cancel)) return FaceStatus::kCancelled;
  } catch (const Standard_Failure& e) {
    return useFallback(std::string("OpenCASCADE failed while meshing: ") + e.GetMessageString(), mesh, report,
                       cancel);
  }
  twinSingularCorners(mesh);
  showCreaseCorners(mesh);
  std::vector<std::uint32_t> indices = snapshot(mesh);
  if (indices.empty()) return useFallback("no triangle inside the boundary", mesh, report, cancel);
  if (!strayReported_) {
    // Edges that stray from the surface by more than the deflection (within their own tolerance):
    // the mesh keeps to the shared edge points, so it cannot keep the deflection beside them.
    // (Coarse levels' edge points are among the final level's: found on any, it holds for all.)
    const float stray = offset_.empty() ? 0.0f : *std::max_element(offset_.begin(), offset_.end());
    if (stray > settings_.finalChordal) {
      char line[160];
      std::snprintf(line, sizeof line, "its edges stray up to %.3g from its surface, beyond the deflection %.3g: "
                    "the mesh keeps to them", stray, settings_.finalChordal);
      repairs_.push_back(line);
      repaired_ = true;
      strayReported_ = true;
    }
  }
  mesh.levels.push_back(std::move(indices));
  mesh.levelVertexEnd.push_back(static_cast<std::uint32_t>(mesh.vertexCount()));
  report.status = repaired_ ? FaceStatus::kRepaired : FaceStatus::kOk;
  report.reason = repairsReason();
  return report.status;
}

}  // namespace cetview::brep
