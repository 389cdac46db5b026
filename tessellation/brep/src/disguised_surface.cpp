#include "disguised_surface.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <Standard_Failure.hxx>

namespace cetview::brep {
namespace {

constexpr int kSamples = 9;         // per direction
constexpr double kRelative = 1e-9;  // of the shape's size (radius, or the samples' spread for a plane)
constexpr double kParallel = 1e-9;  // sine of the angle between normals taken as parallel

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

// A plane (through `origin`, normal `normal`), a sphere (centre, radius) or a circular cylinder
// (a point of its axis, the axis, radius).
struct Shape {
  enum Kind { kPlane, kSphere, kCylinder } kind;
  gp_Pnt origin;
  gp_Vec axis;
  double size;  // the plane's samples' spread, the radius

  bool fits(const Sample& s) const {
    if (kind == kPlane)
      return axis.Crossed(s.n).Magnitude() <= kParallel && std::abs(gp_Vec(origin, s.p).Dot(axis)) <= kRelative * size;
    gp_Vec r(origin, s.p);
    if (kind == kCylinder) {
      if (std::abs(s.n.Dot(axis)) > kParallel) return false;
      r -= axis * r.Dot(axis);
    }
    const double m = r.Magnitude();
    return std::abs(m - size) <= kRelative * size && r.Crossed(s.n).Magnitude() <= kParallel * m;
  }
};

// The shapes the samples suggest: the plane of the first; the sphere whose centre the normal lines
// of the first and of the one turned furthest from it meet at; the cylinder whose axis runs along
// those two normals' cross product.
std::vector<Shape> candidates(const std::vector<Sample>& samples) {
  const Sample& a = samples.front();
  double spread = 0;
  const Sample* b = &a;
  for (const Sample& s : samples) {
    spread = std::max(spread, a.p.Distance(s.p));
    if (a.n.Crossed(s.n).Magnitude() > a.n.Crossed(b->n).Magnitude()) b = &s;
  }
  if (!(spread > 0)) return {};
  std::vector<Shape> out{{Shape::kPlane, a.p, a.n, spread}};
  if (a.n.Crossed(b->n).Magnitude() <= 1e-6) return out;  // too flat to tell a sphere or a cylinder
  const gp_Pnt center = nearestToBoth(a.p, a.n, b->p, b->n);
  out.push_back({Shape::kSphere, center, gp_Vec(), center.Distance(a.p)});
  const gp_Vec axis = a.n.Crossed(b->n).Normalized();
  gp_Vec toAxis(a.p, center);
  toAxis -= axis * toAxis.Dot(axis);
  out.push_back({Shape::kCylinder, center, axis, toAxis.Magnitude()});
  return out;
}

}  // namespace

bool isPlaneSphereOrCylinder(const SurfaceD1& d1, double u0, double u1, double v0, double v1) {
  if (!(u1 > u0) || !(v1 > v0)) return false;
  const auto sampleAt = [&](int i, int j) -> std::optional<Sample> {
    const double u = u0 + (u1 - u0) * i / (kSamples - 1), v = v0 + (v1 - v0) * j / (kSamples - 1);
    gp_Pnt p;
    gp_Vec du, dv;
    d1(u, v, p, du, dv);
    const gp_Vec n = du.Crossed(dv);
    if (!(n.Magnitude() > 1e-12 * du.Magnitude() * dv.Magnitude())) return std::nullopt;  // a pole
    return Sample{p, n / n.Magnitude()};
  };
  try {
    // The 3 x 3 samples at 0, 3/8 and 3/4 of each range: on a whole turn of a cylinder the ends
    // and the middle (0, 1/2 and 1) face along one line, and no axis follows from them.
    constexpr int kCoarse = 3;
    const auto isCoarse = [](int i) { return i % kCoarse == 0 && i < kSamples - 1; };
    std::vector<Sample> coarse;
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        if (!isCoarse(i) || !isCoarse(j)) continue;
        const std::optional<Sample> s = sampleAt(i, j);
        if (!s) return false;
        coarse.push_back(*s);
      }
    }
    std::vector<Shape> shapes = candidates(coarse);
    const auto keepFitting = [&shapes](const Sample& s) {
      std::vector<Shape> kept;
      for (const Shape& shape : shapes)
        if (shape.fits(s)) kept.push_back(shape);
      shapes.swap(kept);
      return !shapes.empty();
    };
    for (const Sample& s : coarse)
      if (!keepFitting(s)) return false;
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        if (isCoarse(i) && isCoarse(j)) continue;  // taken already
        const std::optional<Sample> s = sampleAt(i, j);
        if (!s || !keepFitting(*s)) return false;
      }
    }
    return true;
  } catch (const Standard_Failure&) {
    return false;
  }
}

bool isPlaneSphereOrCylinder(const Adaptor3d_Surface& surface, double u0, double u1, double v0, double v1) {
  return isPlaneSphereOrCylinder(
      [&surface](double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) { surface.D1(u, v, p, du, dv); }, u0, u1,
      v0, v1);
}

}  // namespace cetview::brep
