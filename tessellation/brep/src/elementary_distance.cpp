#include "elementary_distance.h"

#include <algorithm>
#include <cmath>

#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>

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
      return std::min(std::abs(std::hypot(radial - radius_, along) - minor_),
                      std::abs(std::hypot(radial + radius_, along) - minor_));
    default:
      return -1;
  }
}

}  // namespace cetview::brep
