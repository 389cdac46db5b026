#include "elementary_distance.h"

#include <algorithm>
#include <cmath>

#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>
#include <gp_XYZ.hxx>

namespace cetview::brep {

ElementaryDistance::ElementaryDistance(const Adaptor3d_Surface& surface) : type_(surface.GetType()) {
  switch (type_) {
    case GeomAbs_Plane:
      origin_ = surface.Plane().Location(), axis_ = surface.Plane().Axis().Direction();
      break;
    case GeomAbs_Cylinder:
      origin_ = surface.Cylinder().Location(), axis_ = surface.Cylinder().Axis().Direction();
      radius_ = surface.Cylinder().Radius();
      break;
    case GeomAbs_Cone:
      origin_ = surface.Cone().Location(), axis_ = surface.Cone().Axis().Direction();
      radius_ = surface.Cone().RefRadius();
      cosA_ = std::cos(surface.Cone().SemiAngle()), sinA_ = std::sin(surface.Cone().SemiAngle());
      break;
    case GeomAbs_Sphere:
      origin_ = surface.Sphere().Location(), radius_ = surface.Sphere().Radius();
      break;
    case GeomAbs_Torus:
      origin_ = surface.Torus().Location(), axis_ = surface.Torus().Axis().Direction();
      radius_ = surface.Torus().MajorRadius(), minor_ = surface.Torus().MinorRadius();
      break;
    default:
      type_ = GeomAbs_OtherSurface;
  }
}

double ElementaryDistance::operator()(const gp_Pnt& m) const {
  const gp_XYZ w = m.XYZ() - origin_.XYZ();
  const double along = w.Dot(axis_.XYZ());
  const double radial = (w - along * axis_.XYZ()).Modulus();
  switch (type_) {
    case GeomAbs_Plane:
      return std::abs(along);
    case GeomAbs_Cylinder:
      return std::abs(radial - radius_);
    case GeomAbs_Cone:
      // In the half plane through the axis: the generator rho = radius + along * tan(angle), and
      // its mirror (the other nappe).
      return std::min(std::abs((radial - radius_) * cosA_ - along * sinA_),
                      std::abs((radial + radius_) * cosA_ + along * sinA_));
    case GeomAbs_Sphere:
      return std::abs(w.Modulus() - radius_);
    case GeomAbs_Torus:
      // The plane through the axis and m cuts the torus in two circles of the minor radius, about
      // (+major, 0) and (-major, 0); both matter when the minor radius is the larger (a spindle torus).
      // (Plain square roots: std::hypot's overflow care costs several times as much.)
      return std::min(std::abs(std::sqrt((radial - radius_) * (radial - radius_) + along * along) - minor_),
                      std::abs(std::sqrt((radial + radius_) * (radial + radius_) + along * along) - minor_));
    default:
      return -1;
  }
}

namespace {

// Closest point to the origin on the segment p + t e, t in [0, 1]: its squared distance.
double segmentSquared(const gp_XYZ& p, const gp_XYZ& e) {
  const double ee = e.SquareModulus();
  const double t = ee > 0 ? std::clamp(-p.Dot(e) / ee, 0.0, 1.0) : 0.0;
  return (p + t * e).SquareModulus();
}

// Whether the point x of the triangle's plane lies inside triangle (a, b, c) of normal n.
bool insideTriangle(const gp_XYZ& x, const gp_XYZ p[3], const gp_XYZ& n) {
  for (int i = 0; i < 3; ++i) {
    const gp_XYZ& s = p[(i + 1) % 3];
    const gp_XYZ& e = p[(i + 2) % 3];
    if ((e - s).Crossed(x - s).Dot(n) < 0) return false;
  }
  return true;
}

}  // namespace

double ElementaryDistance::triangleDeviation(const gp_XYZ& a, const gp_XYZ& b, const gp_XYZ& c, int& where) const {
  where = -1;
  const gp_XYZ p[3] = {a - origin_.XYZ(), b - origin_.XYZ(), c - origin_.XYZ()};
  const gp_XYZ n = (p[1] - p[0]).Crossed(p[2] - p[0]);
  const double nn = n.SquareModulus();
  switch (type_) {
    case GeomAbs_Plane:  // the distance is linear over the triangle: largest at a corner
      return std::max({std::abs(p[0].Dot(axis_.XYZ())), std::abs(p[1].Dot(axis_.XYZ())), std::abs(p[2].Dot(axis_.XYZ()))});
    case GeomAbs_Sphere:
    case GeomAbs_Cylinder: {
      if (!(nn > 0)) return -1;
      // Work in the plane across the axis for a cylinder (the distance to the axis is the distance
      // to the origin there), in space for a sphere.
      const bool cylinder = type_ == GeomAbs_Cylinder;
      const gp_XYZ d = axis_.XYZ();
      auto across = [&](const gp_XYZ& x) { return cylinder ? x - x.Dot(d) * d : x; };
      double farthest = 0;
      for (const gp_XYZ& x : p) farthest = std::max(farthest, across(x).Modulus());
      double nearest = 0;
      // The inside: the foot of the centre (sphere) or the axis' crossing (cylinder, unless the
      // plane runs along the axis).
      bool inside = false;
      if (!cylinder) {
        const double h = p[0].Dot(n) / nn;  // the centre's foot is h n
        inside = insideTriangle(h * n, p, n);
        nearest = std::abs(h) * std::sqrt(nn);
      } else if (const double dn = d.Dot(n); std::abs(dn) > 1e-12 * std::sqrt(nn)) {
        const double s = p[0].Dot(n) / dn;  // the axis meets the plane at s d
        inside = insideTriangle(s * d, p, n);
        nearest = 0;
      }
      if (!inside) {
        double best = 1e300;
        for (int i = 0; i < 3; ++i) {
          const gp_XYZ& s = p[(i + 1) % 3];
          const double sq = segmentSquared(across(s), across(p[(i + 2) % 3] - s));
          if (sq < best) best = sq, where = i;
        }
        nearest = std::sqrt(best);
      }
      return std::max(radius_ - nearest, farthest - radius_);
    }
    default:
      return -1;
  }
}

}  // namespace cetview::brep
