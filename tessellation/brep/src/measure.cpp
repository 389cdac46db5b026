#include "brep/measure.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include <Standard_Failure.hxx>
#include <TopoDS.hxx>

#include "brep/tessellator.h"
#include "deviation_peak.h"
#include "measure_impl.h"
#include "model_impl.h"
#include "parallel.h"

namespace cetview::brep {

namespace {

// Steps of the grid over a triangle's (u, v) that the measure seeds its projections from.
constexpr int kSeedSteps = 16;
// Even steps along a line of (u, v) (a triangle without area there): as many points as the grid has.
constexpr int kLineSteps = (kSeedSteps + 1) * (kSeedSteps + 2) / 2;

// Seeds along a line of (u, v): `at(s)` seeds the surface point at s in [0, 1] of the line and
// returns it. Points at as many even steps as the measure's seed grid has, and between two
// consecutive ones, by halving, further points while the surface runs more than `gap` between two
// (at most 1024 of them). A surface that runs all its way in a sliver of the line's parameters is
// found so: a fuzzed bilinear patch collapsed onto a point past a knot 0.3% of the way along a
// zero-area boundary triangle had no even step in the 0.3% before the knot; the triangle, lying on
// the surface, read 2.38x its tolerance.
template <class At>
void seedLine(At&& at, double gap) {
  constexpr int kMaxExtra = 1024;
  constexpr int kMaxDepth = 40;
  struct Span {
    double s0, s1;
    gp_Pnt p0, p1;
    int depth;
  };
  std::vector<Span> open;
  int extra = 0;
  gp_Pnt previous = at(0.0);
  for (int i = 1; i <= kLineSteps; ++i) {
    const double s = double(i) / kLineSteps;
    const gp_Pnt p = at(s);
    open.push_back({double(i - 1) / kLineSteps, s, previous, p, 0});
    while (!open.empty()) {
      const Span span = open.back();
      open.pop_back();
      if (!(gap > 0) || span.depth >= kMaxDepth || extra >= kMaxExtra || span.p0.Distance(span.p1) <= gap)
        continue;
      const double mid = 0.5 * (span.s0 + span.s1);
      const gp_Pnt pm = at(mid);
      ++extra;
      open.push_back({mid, span.s1, pm, span.p1, span.depth + 1});
      open.push_back({span.s0, mid, span.p0, pm, span.depth + 1});
    }
    previous = p;
  }
}

// Golden-section search for a minimum of f over [a, b] (f unimodal there, else some local
// minimum), to a millionth of the interval.
template <class F>
void goldenSection(F&& f, double a, double b) {
  constexpr double kInvPhi = 0.6180339887498949;
  double x1 = b - kInvPhi * (b - a), x2 = a + kInvPhi * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 30; ++i) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - kInvPhi * (b - a);
      f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + kInvPhi * (b - a);
      f2 = f(x2);
    }
  }
}

// The longest side of triangle v in space.
double longestSide(const double* positions, const std::uint32_t v[3]) {
  double longest = 0;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t a = v[i], b = v[(i + 1) % 3];
    const gp_Pnt pa(positions[3 * a], positions[3 * a + 1], positions[3 * a + 2]);
    longest =
        std::max(longest, pa.Distance(gp_Pnt(positions[3 * b], positions[3 * b + 1], positions[3 * b + 2])));
  }
  return longest;
}

}  // namespace

double measureDeviation(const SurfaceEval& eval, const double* positions, const double* uv,
                        const std::uint32_t* idx, std::size_t triangles, double fineAbove, double stopAbove) {
  // The centroid and the barycentric grid of step 1/4 without the corners.
  static const double kSamples[13][3] = {
      {1.0 / 3, 1.0 / 3, 1.0 / 3}, {.75, .25, 0}, {.5, .5, 0}, {.25, .75, 0}, {0, .75, .25}, {0, .5, .5}, {0, .25, .75},
      {.25, 0, .75}, {.5, 0, .5}, {.75, 0, .25}, {.5, .25, .25}, {.25, .5, .25}, {.25, .25, .5}};
  double worst = 0;
  const bool exact = eval.exactTriangleDeviation();
  const bool closedForm = eval.closedFormDistance();
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t v[3] = {idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]};
    const double cu[3] = {uv[2 * v[0]], uv[2 * v[1]], uv[2 * v[2]]};
    const double cv[3] = {uv[2 * v[0] + 1], uv[2 * v[1] + 1], uv[2 * v[2] + 1]};
    // A triangle without area in (u, v) (its corners on one line, as along a side): the grid below
    // then holds only kSeedSteps + 1 distinct points, along its longest side.
    int longest = 0;  // the side from corner `longest` to the next
    double longestSq = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const double sq = (cu[j] - cu[i]) * (cu[j] - cu[i]) + (cv[j] - cv[i]) * (cv[j] - cv[i]);
      if (sq > longestSq) longestSq = sq, longest = i;
    }
    const double uvCross = (cu[1] - cu[0]) * (cv[2] - cv[0]) - (cv[1] - cv[0]) * (cu[2] - cu[0]);
    const bool collinear = std::abs(uvCross) <= 1e-9 * longestSq;
    if (exact) {  // planes, cylinders, spheres: the largest distance itself, not only at the samples
      auto corner = [&](int i) { return gp_Pnt(positions[3 * v[i]], positions[3 * v[i] + 1], positions[3 * v[i] + 2]); };
      int where = -1;
      const double d = eval.triangleDeviation(corner(0), corner(1), corner(2), where);
      worst = std::max(worst, d);
      if (worst > stopAbove) return worst;
      if (d >= 0) continue;  // a triangle with no area falls through to the samples
    }
    const auto flatPoint = [&](const double b[3]) {
      gp_XYZ m(0, 0, 0);
      for (int i = 0; i < 3; ++i) m += b[i] * gp_XYZ(positions[3 * v[i]], positions[3 * v[i] + 1], positions[3 * v[i] + 2]);
      return gp_Pnt(m);
    };
    if (closedForm) {
      // Cones and tori (and degenerate triangles on the others): the distance itself, at the grid
      // and where the quadratic through the edges' middles peaks (deviation_peak.h: inside an acute
      // triangle on a torus's outside the grid reads down to 0.96 of the peak).
      double read[13];
      for (int k = 0; k < 13; ++k) worst = std::max(worst, read[k] = eval.projectOnce(flatPoint(kSamples[k]), 0, 0, nullptr));
      const double middle[3] = {read[5], read[8], read[2]};  // edges opposite corners 0, 1, 2
      double peak[3];
      if (quadraticDeviationPeak(middle, peak)) worst = std::max(worst, eval.projectOnce(flatPoint(peak), 0, 0, nullptr));
      if (worst > stopAbove) return worst;
      continue;
    }
    // The foot of sample j from its interpolated (u, v), by Gauss-Newton then damped steps, found
    // once a triangle (the same whatever else was read: a stopped reading stays exact).
    double feet[13][2];
    bool footFound[13] = {};
    const auto sampleFoot = [&](int j, double& fu, double& fw) {
      if (!footFound[j]) {
        const double* bj = kSamples[j];
        double u = 0, w = 0;
        eval.blend(3, bj, cu, cv, u, w);
        const gp_Pnt mj = flatPoint(bj);
        eval.project(mj, u, w, 8);
        eval.projectDamped(mj, u, w, 50);
        feet[j][0] = u, feet[j][1] = w, footFound[j] = true;
      }
      fu = feet[j][0], fw = feet[j][1];
    };
    for (const auto& b : kSamples) {
      const gp_XYZ m = flatPoint(b).XYZ();
      double u = 0, w = 0;
      for (int i = 0; i < 3; ++i) u += b[i] * uv[2 * v[i]], w += b[i] * uv[2 * v[i] + 1];
      // Elsewhere Gauss-Newton from a UV start: never under the distance, but over it where the
      // projection does not converge in 8 steps.
      const double startU = u, startW = w;
      double d = eval.project(gp_Pnt(m), u, w, 8);
      if (!eval.linear()) {
        // Spans with scales of their own (surface_eval.h): the triangle is straight in the scaled
        // plane, where its point's parameters are a much better start than the UV interpolation.
        const double b3[3] = {b[0], b[1], b[2]};
        eval.blend(3, b3, cu, cv, u, w);
        d = std::min(d, eval.project(gp_Pnt(m), u, w, 8));
      }
      // A sample that would raise the maximum is taken on by damped steps from the best point found:
      // where the parametrisation folds or pinches (Su or Sv vanishing), Gauss-Newton overshoots and
      // stalls far from the foot (a fuzzed folded sheet read 6x its true deviation; BRepMesh's mesh of
      // terrain 1.17x the deflection, 0.93x measured so).
      if (d > worst) d = std::min(d, eval.projectDamped(gp_Pnt(m), u, w, 50));
      // And if it still would, from the surface point nearest to it among a grid over the
      // triangle's (u, v) (step 1/16, corners included): a rational patch with wild weights runs so
      // unevenly along its iso-lines that the interpolated start, and the corners, lie beyond other
      // local minima of the distance (fuzzed patches' boundary chords, lying on the surface, read
      // 3.6x and 11x the deflection; from the grid's nearest point the foot is at 1e-4x).
      if (d > worst) {
        double su = u, sw = w, nearest = 1e300;
        auto seed = [&](const double g[3]) {
          double gu = 0, gw = 0;
          eval.blend(3, g, cu, cv, gu, gw);
          const gp_Pnt p = eval.point(gu, gw);
          const double dg = p.Distance(gp_Pnt(m));
          if (dg < nearest) nearest = dg, su = gu, sw = gw;
          return p;
        };
        if (collinear) {
          // As many points as the grid has, along the one line (a fuzzed patch's zero-area
          // triangle along its side u = 1, whose iso-line runs 20x faster near one end, read 3.06x
          // its tolerance from 17 points, where it lies on the surface; its level now reads 0.16x),
          // and between two of them further points wherever the surface runs more than a 64th of
          // the triangle's size between them (seedLine).
          double nearestS = 0, nearestSeen = 1e300;
          const auto along = [&](double s) {
            double g[3] = {0, 0, 0};
            g[longest] = 1.0 - s;
            g[(longest + 1) % 3] = s;
            const gp_Pnt p = seed(g);
            if (nearest < nearestSeen) nearestSeen = nearest, nearestS = s;
            return p;
          };
          seedLine(along, longestSide(positions, v) / 64);
          // Then the line's nearest point by golden sections between the even steps beside the
          // nearest seed, without derivatives: where the surface collapses onto a point past a
          // knot, the seed at or past the knot is as near as the one before it, and projections
          // from there cannot move (no derivative); a fuzzed patch's zero-area triangle along its
          // seam, lying on the surface, read 4.37x its tolerance so.
          goldenSection([&](double s) { return along(s).Distance(gp_Pnt(m)); },
                        std::max(0.0, nearestS - 1.0 / kLineSteps),
                        std::min(1.0, nearestS + 1.0 / kLineSteps));
        } else {
          for (int i = 0; i <= kSeedSteps; ++i) {
            for (int j = 0; i + j <= kSeedSteps; ++j) {
              const double g[3] = {double(i) / kSeedSteps, double(j) / kSeedSteps,
                                   double(kSeedSteps - i - j) / kSeedSteps};
              seed(g);
            }
          }
        }
        double ds = std::min(nearest, eval.project(gp_Pnt(m), su, sw, 8));
        if (ds > worst) ds = std::min(ds, eval.projectDamped(gp_Pnt(m), su, sw, 50));
        d = std::min(d, ds);
      }
      // And if it still would, by damped steps held inside a box around the triangle and nowhere
      // else (SurfaceEval::triangleBox: the face's parameter box in a periodic direction, the
      // surface's bounds in another, each widened to the triangle's corners). Beside
      // the seam of a periodic surface that turns sharply across it (spans a millionth wide just
      // past the seam), every step crossed the seam into the far side's spans, and the distance
      // stayed where it started (a fuzzed face's seam chord read 0.0965, 1.75x its tolerance, where
      // the surface is 0.037 away). On a face reaching past its surface's knots, steps stopped at
      // the knots (a fuzzed face 0.54 of v beyond them read 4.93x its tolerance, 134.5 where the
      // extrapolated surface is 5.5 away).
      if (d > worst) {
        double box[4];
        eval.triangleBox(cu, cv, box);
        double bu = startU, bw = startW;
        d = std::min(d, eval.projectDamped(gp_Pnt(m), bu, bw, 50, box));
      }
      // And if it still would, past `fineAbove`, from the nearest point of a grid four times as fine
      // (step 1/64): on a rational patch with wild weights the coarse grid's nearest point can lie
      // in another basin of the distance, so that the reading hung on rounding in where the steps
      // started (a fuzzed triangle read 0.0036, 10.6x its tolerance, with its corners in one order
      // and 9e-6 in another; a grid of step 1/400 over its (u, v) finds 1.75e-4). Past the
      // tolerance only: 2145 surface points a sample.
      if (d > worst && d > fineAbove && !collinear) {
        constexpr int kFine = 64;
        double su = u, sw = w, nearest = 1e300;
        for (int i = 0; i <= kFine; ++i)
          for (int j = 0; i + j <= kFine; ++j) {
            const double g[3] = {double(i) / kFine, double(j) / kFine, double(kFine - i - j) / kFine};
            double gu = 0, gw = 0;
            eval.blend(3, g, cu, cv, gu, gw);
            const double dg = eval.point(gu, gw).Distance(gp_Pnt(m));
            if (dg < nearest) nearest = dg, su = gu, sw = gw;
          }
        double ds = std::min(nearest, eval.project(gp_Pnt(m), su, sw, 8));
        if (ds > worst) ds = std::min(ds, eval.projectDamped(gp_Pnt(m), su, sw, 50));
        d = std::min(d, ds);
      }
      // And if it still would, past `fineAbove`, from the feet of the triangle's other samples
      // (sampleFoot): where the surface folds over itself many times, a sample's foot can lie far
      // from its triangle in (u, v), beyond other local minima from every start over it, while its
      // neighbours' feet are beside it. A fuzzed B-spline sheet periodic in u with a period of 1e-3,
      // most of its poles one point, read 1.48x its tolerance (0.2 against 0.135) on a triangle
      // whose samples all lie within 3e-8 of the sheet, 0.0008 of u away (a 1000 x 1000 grid over
      // the face's (u, v) finds none of them nearer than 0.0008).
      if (d > worst && d > fineAbove) {
        for (int j = 0; j < 13; ++j) {
          if (&kSamples[j] == &b) continue;
          double fu = 0, fw = 0;
          sampleFoot(j, fu, fw);
          double ds = eval.project(gp_Pnt(m), fu, fw, 8);
          if (ds > worst) ds = std::min(ds, eval.projectDamped(gp_Pnt(m), fu, fw, 50));
          d = std::min(d, ds);
          if (d <= worst) break;
        }
      }
      worst = std::max(worst, d);
      if (worst > stopAbove) return worst;
    }
  }
  return worst;
}

double measureCornerAngle(const SurfaceEval& eval, const double* positions, const double* uv,
                          std::size_t vertices, const std::uint32_t* idx, std::size_t triangles,
                          double minLength, const float* normals) {
  std::vector<gp_Dir> normal(vertices);
  std::vector<char> regular(vertices, 0);
  for (std::size_t v = 0; v < vertices; ++v) {
    gp_Pnt p;
    regular[v] = eval.pointNormal(uv[2 * v], uv[2 * v + 1], p, normal[v]) ? 1 : 0;
  }
  // Vertices at one (u, v) and point with another: a fold vertex and its twin (FaceMesh::normals).
  std::vector<char> twinned(vertices, 0);
  if (normals) {
    std::vector<std::uint32_t> order(vertices);
    for (std::uint32_t v = 0; v < vertices; ++v) order[v] = v;
    const auto key = [&](std::uint32_t v) {
      return std::make_tuple(uv[2 * v], uv[2 * v + 1], positions[3 * v], positions[3 * v + 1],
                             positions[3 * v + 2]);
    };
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return key(x) < key(y); });
    for (std::size_t i = 1; i < vertices; ++i)
      if (key(order[i - 1]) == key(order[i])) twinned[order[i - 1]] = twinned[order[i]] = 1;
  }
  // A twinned vertex's normal seen along edge (a, b): of the surface's normals at steps towards b
  // (2^-30 of the edge to an eighth), the nearest to the one it shows (as a line).
  const auto normalTowards = [&](std::uint32_t a, std::uint32_t b, gp_Dir& n) {
    n = normal[a];
    if (!twinned[a]) return regular[a] != 0;
    const gp_Vec shown(normals[3 * a], normals[3 * a + 1], normals[3 * a + 2]);
    double best = -1;
    for (int k = 30; k >= 3; --k) {
      const double e = std::ldexp(1.0, -k);
      gp_Pnt p;
      gp_Dir step;
      if (!eval.pointNormal(uv[2 * a] + e * (uv[2 * b] - uv[2 * a]),
                            uv[2 * a + 1] + e * (uv[2 * b + 1] - uv[2 * a + 1]), p, step))
        continue;
      const double match = std::abs(shown.Dot(gp_Vec(step)));
      if (match > best) best = match, n = step;
    }
    return best >= 0 || regular[a] != 0;
  };
  double worst = 0;
  for (std::size_t t = 0; t < triangles; ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = idx[3 * t + i], b = idx[3 * t + (i + 1) % 3];
      gp_Dir na, nb;
      if (!normalTowards(a, b, na) || !normalTowards(b, a, nb)) continue;
      const gp_Pnt pa(positions[3 * a], positions[3 * a + 1], positions[3 * a + 2]);
      const gp_Pnt pb(positions[3 * b], positions[3 * b + 1], positions[3 * b + 2]);
      if (pa.Distance(pb) < minLength) continue;
      if (eval.crossesCrease(uv[2 * a], uv[2 * a + 1], uv[2 * b], uv[2 * b + 1])) continue;
      if (eval.normalJumps(uv[2 * a], uv[2 * a + 1], uv[2 * b], uv[2 * b + 1], na, nb)) continue;
      worst = std::max(worst, na.Angle(nb));
    }
  }
  return worst;
}

TriangleFacing triangleFacing(const double* positions, const float* normals, const std::uint32_t corner[3]) {
  gp_XYZ p[3], normal[3], n(0, 0, 0);
  for (int c = 0; c < 3; ++c) {
    const std::uint32_t v = corner[c];
    p[c] = gp_XYZ(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    normal[c] = gp_XYZ(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    n += normal[c];
  }
  const gp_XYZ cr = (p[1] - p[0]).Crossed(p[2] - p[0]);
  const double longest = std::max({(p[1] - p[0]).Modulus(), (p[2] - p[1]).Modulus(), (p[0] - p[2]).Modulus()});
  if (cr.Modulus() <= 1e-12 * longest * longest) return TriangleFacing::kDegenerate;
  if (cr.Dot(n) > 0) return TriangleFacing::kFacing;
  if (normal[0].Dot(normal[1]) < 0 || normal[1].Dot(normal[2]) < 0 || normal[2].Dot(normal[0]) < 0) {
    return TriangleFacing::kFlippedAcrossFold;
  }
  return TriangleFacing::kFlipped;
}

namespace {

// Counts triangle i of `idx` (triangleFacing) in degenerate or flipped, and a flipped one across a
// fold in acrossFolds as well.
void classifyTriangle(const FaceMesh& m, const std::vector<std::uint32_t>& idx, std::size_t i, std::size_t& degenerate,
                      std::size_t& flipped, std::size_t& acrossFolds) {
  switch (triangleFacing(m.positions.data(), m.normals.data(), idx.data() + i)) {
    case TriangleFacing::kFacing:
      break;
    case TriangleFacing::kDegenerate:
      ++degenerate;
      break;
    case TriangleFacing::kFlippedAcrossFold:
      ++acrossFolds;
      ++flipped;
      break;
    case TriangleFacing::kFlipped:
      ++flipped;
      break;
  }
}

// The chordal tolerance of `level` (-1: the last), the one the measure's finer seeds are kept for.
double levelTolerance(const Tessellator& t, int level) {
  return t.schedule()[static_cast<std::size_t>(level < 0 ? t.lastLevel() : std::min(level, t.lastLevel()))]
      .chordal;
}

std::size_t levelIndex(const FaceMesh& m, int level) {
  return level < 0 ? m.levels.size() - 1 : std::min<std::size_t>(static_cast<std::size_t>(level), m.levels.size() - 1);
}

}  // namespace

std::size_t countFlipped(const Tessellator& t, int level, std::size_t* acrossFolds) {
  std::size_t flipped = 0, degenerate = 0, folds = 0;
  for (FaceId f = 0; f < t.model().faces().size(); ++f) {
    const FaceMesh& m = t.faceMesh(f);
    if (m.levels.empty()) continue;
    const std::vector<std::uint32_t>& idx = m.levels[levelIndex(m, level)];
    for (std::size_t i = 0; i + 2 < idx.size(); i += 3) classifyTriangle(m, idx, i, degenerate, flipped, folds);
  }
  if (acrossFolds) *acrossFolds += folds;
  return flipped;
}

std::vector<FaceQuality> measureFaces(const Tessellator& t, int level, unsigned threads) {
  const ModelImpl& model = t.model().impl();
  std::vector<FaceQuality> out(model.faces.size());
  parallelFor(out.size(), threads, [&](std::size_t f, unsigned) {
    const FaceMesh& m = t.faceMesh(static_cast<FaceId>(f));
    FaceQuality& q = out[f];
    if (m.levels.empty()) return;
    const std::vector<std::uint32_t>& idx = m.levels[levelIndex(m, level)];
    q.triangles = idx.size() / 3;
    for (std::size_t i = 0; i + 2 < idx.size(); i += 3) classifyTriangle(m, idx, i, q.degenerate, q.flipped, q.flippedAcrossFolds);
    try {
      SurfaceEval eval(TopoDS::Face(model.faceShapes[f].Oriented(TopAbs_FORWARD)));
      eval.detectFlat(t.chordal());
      q.maxDeviation = measureDeviation(eval, m.positions.data(), m.uv.data(), idx.data(), q.triangles,
                                        levelTolerance(t, level));
      q.maxCornerAngle = measureCornerAngle(eval, m.positions.data(), m.uv.data(), m.vertexCount(),
                                            idx.data(), q.triangles, 0.1 * t.chordal(), m.normals.data());
    } catch (const Standard_Failure&) {
      q.maxDeviation = INFINITY;
      q.maxCornerAngle = INFINITY;
    }
  });
  return out;
}

std::vector<std::vector<float>> measureTriangles(const Tessellator& t, int level, unsigned threads) {
  const ModelImpl& model = t.model().impl();
  std::vector<std::vector<float>> out(model.faces.size());
  parallelFor(out.size(), threads, [&](std::size_t f, unsigned) {
    const FaceMesh& m = t.faceMesh(static_cast<FaceId>(f));
    if (m.levels.empty()) return;
    const std::size_t k = levelIndex(m, level);
    const std::vector<std::uint32_t>& idx = m.levels[k];
    std::vector<float>& d = out[f];
    d.assign(idx.size() / 3, INFINITY);
    try {
      SurfaceEval eval(TopoDS::Face(model.faceShapes[f].Oriented(TopAbs_FORWARD)));
      eval.detectFlat(t.chordal());
      for (std::size_t i = 0; i < d.size(); ++i) {
        d[i] = static_cast<float>(measureDeviation(eval, m.positions.data(), m.uv.data(), idx.data() + 3 * i,
                                                   1, levelTolerance(t, level)));
      }
    } catch (const Standard_Failure&) {
      // Left at INFINITY: the face cannot be measured.
    }
  });
  return out;
}

}  // namespace cetview::brep
