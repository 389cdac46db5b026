#include "torus_lattice.h"

#include <algorithm>
#include <cmath>

namespace cetview::brep {
namespace {

// The most a row may thin its points (a power of two): rows far sparser than their neighbours
// make triangles too long across the rows for the Delaunay triangulation to join them row to row.
constexpr int kMaxEvery = 4;

// |cos v| (R + r cos v): a u step du sags |cos v| (R + r cos v) du^2 / 8 off the surface (the
// normal curvature cos v / (R + r cos v) over the circle's length (R + r cos v) du).
double alongBend(double v, double major, double minor) {
  const double c = std::cos(v);
  return std::abs(c) * (major + minor * c);
}

// The largest of alongBend and of |cos v| over [a, b]: at the ends, and where cos v = +-1 inside.
void largestOver(double a, double b, double major, double minor, double& bend, double& cosine) {
  bend = std::max(alongBend(a, major, minor), alongBend(b, major, minor));
  cosine = std::max(std::abs(std::cos(a)), std::abs(std::cos(b)));
  for (double k = std::ceil(a / M_PI); k * M_PI <= b; k += 1) {
    bend = std::max(bend, alongBend(k * M_PI, major, minor));
    cosine = 1;
  }
}

}  // namespace

TorusLattice::TorusLattice(const TorusLatticeSpec& spec) : spec_(spec) {
  const double R = spec.major, r = spec.minor, d = spec.deviation;
  const double spanU = spec.u1 - spec.u0, spanV = spec.v1 - spec.v0;
  // A ring torus (the tube clear of the axis) or a sphere (major radius 0), a face with a box, a
  // tolerance and an angle.
  if (!(r > 0) || !(R > r || R == 0) || !(d > 0) || !(spec.angle > 0) || !(spanU > 0) || !(spanV > 0)) return;
  if (!std::isfinite(R) || !std::isfinite(spanU) || !std::isfinite(spanV)) return;
  // In the metric where the second fundamental form is the unit one (lengths round the tube over
  // sqrt(r), along it times sqrt(|cos v| / (R + r cos v))), an equilateral triangle of side h
  // deviates by h^2 / 6: side sqrt(6 d), rows sqrt(3) / 2 of it apart.
  // The angle: the normal turns by dv round the tube and by |cos v| du along it (the metric of the
  // Gauss map, dv^2 + cos^2 v du^2), so an equilateral triangle there of side `angle` keeps it:
  // rows sqrt(3) / 2 of the angle apart where the angle binds (at the angle itself, the triangles
  // between rows turned by up to 1.12 times it and were split off the lattice: a unit sphere at
  // 1%, 576 triangles where the lattice takes 416).
  const double side = std::sqrt(6 * d);
  double dv = 0.5 * std::sqrt(3.0) * std::min(side / std::sqrt(r), spec.angle);
  double bend = 0, cosine = 0;
  largestOver(spec.v0, spec.v1, R, r, bend, cosine);
  double du = bend > 0 ? side / std::sqrt(bend) : spanU;
  if (cosine > 0) du = std::min(du, spec.angle / cosine);
  const double nv = std::ceil(spanV / dv), nu = std::ceil(spanU / du);
  if (nv < 2 || nu < 2) return;  // no interior row, or no point between the box's sides
  if (!((nv - 1) * nu <= spec.maxPoints)) return;
  dv_ = spanV / nv, du_ = spanU / nu;
  for (int j = 1; j < static_cast<int>(nv); ++j) {
    const double v = spec.v0 + j * dv_;
    // The row's triangles reach the rows either side: its u step must do over [v - dv, v + dv].
    double rowBend = 0, rowCosine = 0;
    largestOver(v - dv_, v + dv_, R, r, rowBend, rowCosine);
    const double forDeviation = rowBend > 0 ? side / std::sqrt(rowBend) : HUGE_VAL;
    const double forAngle = rowCosine > 0 ? spec.angle / rowCosine : HUGE_VAL;
    const double allowed = std::min(forDeviation, forAngle);
    int every = 1;
    while (every < kMaxEvery && 2 * every * du_ <= allowed) every *= 2;
    // For the deviation, only where the tube's outside bends both ways alike: on its inside (cos v
    // < 0) the surface is a saddle, whose triangles deviate far less along its asymptotic lines than
    // the lattice allows for. The angle does not tell the two apart: where it asks for closer points
    // than the deviation, the inside takes the lattice too (a torus of 3 x 1 at 1%: 1544 -> 1172
    // triangles).
    if (!(std::cos(v) > 0) && !(forAngle < forDeviation)) every = 0;
    rows_.push_back(Row{v, every, j % 2 == 1 ? 0.5 * every * du_ : every * du_});
  }
}

bool TorusLattice::empty() const {
  for (const Row& row : rows_)
    if (row.every > 0) return false;
  return true;
}

void TorusLattice::near(double u, double v, std::vector<LatticePoint>& out) const {
  out.clear();
  if (rows_.empty()) return;
  const auto nearest = static_cast<long>(std::lround((v - spec_.v0) / dv_));
  for (long j = nearest - 1; j <= nearest + 1; ++j) {
    if (j < 1 || j > static_cast<long>(rows_.size())) continue;
    const Row& row = rows_[static_cast<std::size_t>(j - 1)];
    if (row.every == 0) continue;
    const double step = row.every * du_;
    const double at = std::floor((u - spec_.u0 - row.offset) / step);
    for (double k : {at, at + 1}) {
      const double pu = spec_.u0 + row.offset + k * step;
      // Strictly inside the box, a quarter step off its sides (an edge may run there).
      if (k < 0 || pu > spec_.u1 - 0.25 * du_) continue;
      out.push_back(LatticePoint{pu, row.v, step});
    }
  }
}

std::vector<LatticePoint> TorusLattice::row(int j) const {
  std::vector<LatticePoint> out;
  if (j < 1 || j > rowCount()) return out;
  const Row& r = rows_[static_cast<std::size_t>(j - 1)];
  if (r.every == 0) return out;
  const double step = r.every * du_;
  for (double k = 0;; k += 1) {
    const double pu = spec_.u0 + r.offset + k * step;
    if (pu > spec_.u1 - 0.25 * du_) break;
    out.push_back(LatticePoint{pu, r.v, step});
  }
  return out;
}

}  // namespace cetview::brep
