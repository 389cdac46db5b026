#include "disguised_surface.h"

#include <array>
#include <cmath>
#include <vector>

#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace cetview::brep {
namespace {

constexpr int kSamples = 9;            // per direction
constexpr double kRelative = 1e-9;     // of the shape's size (radius, or the samples' spread for a plane)
constexpr double kParallel = 1e-9;     // sine of the angle between normals taken as parallel

struct Sample {
  gp_Pnt p;
  gp_Vec n;  // unit
};

// The point nearest both lines a + s da and b + t db (unit directions, not parallel): the middle of
// their common perpendicular.
gp_Pnt nearestToBoth(const gp_Pnt& a, const gp_Vec& da, const gp_Pnt& b, const gp_Vec& db) {
  const gp_Vec w(b, a);
  const double c = da.Dot(db), d = da.Dot(w), e = db.Dot(w);
  const double den = 1 - c * c;
  const double s = (c * e - d) / den, t = (e - c * d) / den;
  return gp_Pnt(0.5 * (a.XYZ() + s * da.XYZ() + b.XYZ() + t * db.XYZ()));
}

bool isPlane(const std::vector<Sample>& samples, double size) {
  const Sample& o = samples.front();
  for (const Sample& s : samples) {
    if (o.n.Crossed(s.n).Magnitude() > kParallel || std::abs(gp_Vec(o.p, s.p).Dot(o.n)) > kRelative * size) return false;
  }
  return true;
}

// Every sample at `radius` from `center` (a point, or the line through it along `axis` when
// given), its normal along the way from there.
bool onRound(const std::vector<Sample>& samples, const gp_Pnt& center, const gp_Vec* axis, double radius) {
  for (const Sample& s : samples) {
    gp_Vec r(center, s.p);
    if (axis) r -= *axis * r.Dot(*axis);
    const double m = r.Magnitude();
    if (std::abs(m - radius) > kRelative * radius || r.Crossed(s.n).Magnitude() > kParallel * m) return false;
  }
  return true;
}

}  // namespace

bool isPlaneSphereOrCylinder(const Adaptor3d_Surface& surface, double u0, double u1, double v0, double v1) {
  if (!(u1 > u0) || !(v1 > v0)) return false;
  std::vector<Sample> samples;
  samples.reserve(kSamples * kSamples);
  try {
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        const double u = u0 + (u1 - u0) * i / (kSamples - 1), v = v0 + (v1 - v0) * j / (kSamples - 1);
        gp_Pnt p;
        gp_Vec du, dv;
        surface.D1(u, v, p, du, dv);
        const gp_Vec n = du.Crossed(dv);
        if (!(n.Magnitude() > 1e-12 * du.Magnitude() * dv.Magnitude())) return false;  // a pole: not a cylinder's or a plane's
        samples.push_back({p, n / n.Magnitude()});
      }
    }
  } catch (const Standard_Failure&) {
    return false;
  }
  double size = 0;
  for (const Sample& s : samples) size = std::max(size, samples.front().p.Distance(s.p));
  if (!(size > 0)) return false;
  if (isPlane(samples, size)) return true;
  // Two samples whose normals are furthest apart fix the candidates: a sphere's centre, where the
  // normal lines meet; a cylinder's axis, along the cross product of every two normals.
  const Sample& a = samples.front();
  const Sample* b = nullptr;
  for (const Sample& s : samples)
    if (!b || a.n.Crossed(s.n).Magnitude() > a.n.Crossed(b->n).Magnitude()) b = &s;
  if (a.n.Crossed(b->n).Magnitude() <= 1e-6) return false;  // too flat to tell
  const gp_Pnt center = nearestToBoth(a.p, a.n, b->p, b->n);
  if (onRound(samples, center, nullptr, center.Distance(a.p))) return true;
  const gp_Vec axis = a.n.Crossed(b->n).Normalized();
  for (const Sample& s : samples)
    if (std::abs(s.n.Dot(axis)) > kParallel) return false;
  gp_Vec toAxis(a.p, center);
  toAxis -= axis * toAxis.Dot(axis);
  return onRound(samples, center, &axis, toAxis.Magnitude());
}

}  // namespace cetview::brep
