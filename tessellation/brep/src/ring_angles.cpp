#include "ring_angles.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Standard_Failure.hxx>

namespace cetview::brep {
namespace {

constexpr double kRelative = 1e-7;  // of a radius, or of the face's size (Ring::size): on it, the same
constexpr double kAngle = 1e-7;     // radians: the same angle
constexpr int kSamples = 9;         // per direction, for the check
constexpr int kTableSteps = 64;     // per table

// The circle through three points: its centre, radius and the unit normal of its plane. False
// when they are (nearly) on a line.
bool circleThrough(const gp_Pnt& p1, const gp_Pnt& p2, const gp_Pnt& p3, gp_Pnt& centre, double& radius,
                   gp_Vec& normal) {
  const gp_Vec a(p1, p2), b(p1, p3);
  const gp_Vec n = a.Crossed(b);
  const double n2 = n.SquareMagnitude();
  if (!(n2 > 1e-24 * a.SquareMagnitude() * b.SquareMagnitude())) return false;
  const gp_Vec offset = (b.Crossed(n) * a.SquareMagnitude() + n.Crossed(a) * b.SquareMagnitude()) / (2 * n2);
  centre = p1.Translated(offset);
  radius = offset.Magnitude();
  normal = n / std::sqrt(n2);
  return true;
}

// A torus (or a sphere: major 0) placed in space, and its two angles at a point.
struct Ring {
  gp_Pnt origin;
  gp_Vec x, y, z;  // z the axis
  double major = 0, minor = 0;
  // The tube's radius plus how far apart the fitted tube circles' centres lie: the scale of the
  // face's own extent, not of the ring's (a nearly straight tube fits a ring of any major radius).
  double size = 0;

  double axial(const gp_Pnt& p) const { return gp_Vec(origin, p).Dot(z); }
  double radial(const gp_Pnt& p) const {
    const gp_Vec w(origin, p);
    return std::hypot(w.Dot(x), w.Dot(y));
  }
  double ringAngle(const gp_Pnt& p) const {
    const gp_Vec w(origin, p);
    return std::atan2(w.Dot(y), w.Dot(x));
  }
  double tubeAngle(const gp_Pnt& p) const { return std::atan2(axial(p), radial(p) - major); }
  double offSurface(const gp_Pnt& p) const { return std::abs(std::hypot(radial(p) - major, axial(p)) - minor); }
};

double angleGap(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }

// The ring whose tube circles are the surface's iso-curves along the tube parameter (at three
// values of the ring parameter), or nothing. point(ring, tube) evaluates the surface.
template <class Point>
std::optional<Ring> fitRing(const Point& point, double r0, double r1, double t0, double t1) {
  const double ringAt[3] = {r0 + 0.1 * (r1 - r0), r0 + 0.45 * (r1 - r0), r0 + 0.8 * (r1 - r0)};
  const double tubeAt[3] = {t0 + 0.1 * (t1 - t0), t0 + 0.4 * (t1 - t0), t0 + 0.7 * (t1 - t0)};
  gp_Pnt centre[3];
  gp_Vec plane[3];
  double radius[3];
  for (int k = 0; k < 3; ++k) {
    if (!circleThrough(point(ringAt[k], tubeAt[0]), point(ringAt[k], tubeAt[1]), point(ringAt[k], tubeAt[2]),
                       centre[k], radius[k], plane[k]))
      return std::nullopt;
    // The first curve's fourth point tells most free-form surfaces at once.
    if (k == 0 && std::abs(centre[0].Distance(point(ringAt[0], t0 + 0.9 * (t1 - t0))) - radius[0]) >
                      kRelative * radius[0])
      return std::nullopt;
    if (std::abs(radius[k] - radius[0]) > kRelative * radius[0]) return std::nullopt;
  }
  Ring ring;
  ring.minor = radius[0];
  const double spread = std::max(centre[0].Distance(centre[1]), centre[0].Distance(centre[2]));
  ring.size = ring.minor + spread;
  if (spread <= kRelative * ring.minor) {
    // A sphere: its meridians' planes meet along the axis.
    const gp_Vec axis = plane[0].Crossed(plane[1]);
    if (!(axis.Magnitude() > 1e-6)) return std::nullopt;
    ring.origin = centre[0];
    ring.z = axis.Normalized();
  } else {
    double major = 0;
    gp_Vec axis;
    if (!circleThrough(centre[0], centre[1], centre[2], ring.origin, major, axis)) return std::nullopt;
    if (!(major > ring.minor * (1 + 1e-6))) return std::nullopt;  // not a ring torus
    ring.major = major;
    ring.z = axis;
  }
  gp_Vec x(ring.origin, centre[0]);
  x -= ring.z * x.Dot(ring.z);
  if (!(x.Magnitude() > kRelative * ring.size)) {
    // A sphere's first meridian centred on the axis: any direction across it.
    x = std::abs(ring.z.X()) < 0.9 ? gp_Vec(1, 0, 0) : gp_Vec(0, 1, 0);
    x -= ring.z * x.Dot(ring.z);
  }
  ring.x = x.Normalized();
  ring.y = ring.z.Crossed(ring.x);
  return ring;
}

// y at x on the polyline through (from[k], to[k]) (from increasing), held at its ends.
double interpolate(const std::vector<double>& from, const std::vector<double>& to, double x) {
  if (x <= from.front()) return to.front();
  if (x >= from.back()) return to.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(from.begin(), from.end(), x) - from.begin());
  const double f = (x - from[k - 1]) / (from[k] - from[k - 1]);
  return to[k - 1] + f * (to[k] - to[k - 1]);
}

// The angle along [a, b] in kTableSteps steps, continuous (no jump of 2 pi) and increasing (negated
// when it falls); nothing unless strictly monotone.
template <class Angle>
std::optional<AngleTable> tabulate(const Angle& angleAt, double a, double b) {
  std::vector<double> params(kTableSteps + 1), angles(kTableSteps + 1);
  for (int k = 0; k <= kTableSteps; ++k) {
    params[k] = a + (b - a) * k / kTableSteps;
    angles[k] = angleAt(params[k]);
    if (k > 0) angles[k] += 2 * M_PI * std::round((angles[k - 1] - angles[k]) / (2 * M_PI));
  }
  const double sign = angles.back() >= angles.front() ? 1.0 : -1.0;
  for (double& angle : angles) angle *= sign;
  for (int k = 1; k <= kTableSteps; ++k)
    if (!(angles[k] > angles[k - 1])) return std::nullopt;
  return AngleTable(std::move(params), std::move(angles));
}

}  // namespace

AngleTable::AngleTable(std::vector<double> params, std::vector<double> angles)
    : params_(std::move(params)), angles_(std::move(angles)) {}

double AngleTable::angle(double param) const { return interpolate(params_, angles_, param); }
double AngleTable::param(double angle) const { return interpolate(angles_, params_, angle); }

std::optional<RingAngles> ringAngles(const SurfaceD1& d1, double u0, double u1, double v0, double v1) {
  if (!(u1 > u0) || !(v1 > v0) || !std::isfinite(u1 - u0) || !std::isfinite(v1 - v0)) return std::nullopt;
  try {
    const auto at = [&](double u, double v) {
      gp_Pnt p;
      gp_Vec du, dv;
      d1(u, v, p, du, dv);
      return p;
    };
    for (const bool tubeAlongU : {false, true}) {
      // point(ring parameter, tube parameter)
      const auto point = [&](double r, double t) { return tubeAlongU ? at(t, r) : at(r, t); };
      const double r0 = tubeAlongU ? v0 : u0, r1 = tubeAlongU ? v1 : u1;
      const double t0 = tubeAlongU ? u0 : v0, t1 = tubeAlongU ? u1 : v1;
      const std::optional<Ring> ring = fitRing(point, r0, r1, t0, t1);
      if (!ring) continue;
      // On the ring at every sample, its ring angle a function of the ring parameter alone and its
      // tube angle of the tube parameter alone (a sphere's poles have no ring angle).
      const double size = ring->size;
      double aroundAt[kSamples], tubeAt[kSamples];  // per column i, per row j
      bool ringSeen[kSamples] = {};
      bool fits = true;
      for (int i = 0; i < kSamples && fits; ++i) {
        for (int j = 0; j < kSamples && fits; ++j) {
          const gp_Pnt p = point(r0 + (r1 - r0) * i / (kSamples - 1), t0 + (t1 - t0) * j / (kSamples - 1));
          if (ring->offSurface(p) > kRelative * size) fits = false;
          const double tube = ring->tubeAngle(p);
          if (i == 0) tubeAt[j] = tube;
          else if (angleGap(tube, tubeAt[j]) > kAngle) fits = false;
          if (ring->radial(p) <= 1e-6 * size) continue;
          const double around = ring->ringAngle(p);
          if (!ringSeen[i]) aroundAt[i] = around, ringSeen[i] = true;
          else if (angleGap(around, aroundAt[i]) > kAngle) fits = false;
        }
      }
      if (!fits) continue;
      const double ringMiddle = 0.5 * (r0 + r1), tubeMiddle = 0.5 * (t0 + t1);
      std::optional<AngleTable> ringTable =
          tabulate([&](double r) { return ring->ringAngle(point(r, tubeMiddle)); }, r0, r1);
      std::optional<AngleTable> tubeTable =
          tabulate([&](double t) { return ring->tubeAngle(point(ringMiddle, t)); }, t0, t1);
      if (!ringTable || !tubeTable) continue;
      return RingAngles{ring->major, ring->minor, tubeAlongU, std::move(*ringTable), std::move(*tubeTable)};
    }
  } catch (const Standard_Failure&) {
  }
  return std::nullopt;
}

std::optional<RingAngles> ringAngles(const Adaptor3d_Surface& surface, double u0, double u1, double v0, double v1) {
  return ringAngles([&surface](double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) { surface.D1(u, v, p, du, dv); },
                    u0, u1, v0, v1);
}

bool mayBeRing(GeomAbs_SurfaceType type) {
  return type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface || type == GeomAbs_SurfaceOfRevolution ||
         type == GeomAbs_OffsetSurface;
}

}  // namespace cetview::brep
