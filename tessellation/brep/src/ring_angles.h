// A free-form face that is a torus or a sphere in disguise, and its angles: STEP and IGES files
// often write tori and spheres as rational B-splines (BRepBuilderAPI_NurbsConvert does), whose
// parameters are not the angles the torus lattice is laid out in (torus_lattice.h). Such a surface
// has a lattice all the same when it is parametrized one angle per parameter, as conversions are:
// the angle round the axis a function of one parameter alone, the angle round the tube (a sphere's
// latitude) of the other alone. Both functions are tabulated over the face's box and inverted
// piecewise linearly: the lattice only says where splits go, and every split is then measured on
// the exact surface (a NURBS torus of 3 x 1 at 1% and 20 degrees: 3246 triangles with splits at
// circumcentres, BRepMesh 1376).
#pragma once

#include <optional>
#include <vector>

#include <GeomAbs_SurfaceType.hxx>

#include "disguised_surface.h"

namespace cetview::brep {

// A monotone map between a face parameter and an angle, increasing both ways (an angle that falls
// as the parameter grows is negated: the lattice is symmetric in both angles).
class AngleTable {
 public:
  AngleTable() = default;
  AngleTable(std::vector<double> params, std::vector<double> angles);
  double angle(double param) const;  // clamped to the table's ends
  double param(double angle) const;  // the inverse, clamped likewise
  double firstAngle() const { return angles_.front(); }
  double lastAngle() const { return angles_.back(); }
  const std::vector<double>& params() const { return params_; }
  const std::vector<double>& angles() const { return angles_; }

 private:
  std::vector<double> params_, angles_;
};

struct RingAngles {
  double major = 0, minor = 0;  // the torus's radii (a sphere: 0 and its radius)
  bool tubeAlongU = false;      // the face's u runs round the tube (the analytic torus's v)
  AngleTable ring;              // the parameter along the ring (u, or v when tubeAlongU) -> the angle round the axis
  AngleTable tube;              // the other -> the angle round the tube from its outer equator (a sphere's latitude)
};

// The surface over [u0, u1] x [v0, v1] as a ring torus (major radius above the minor one) or a
// sphere parametrized one angle per parameter: every one of 9 x 9 samples within 1e-7 of the
// face's size (the tube's radius plus the spread of the tube circles fitted) from it and at the
// angles its parameters give. Nothing for any other surface (most are given up on after four
// evaluations each way round, 2-4 us a face).
std::optional<RingAngles> ringAngles(const SurfaceD1& d1, double u0, double u1, double v0, double v1);
// The kinds of surface a torus or a sphere can be written as (B-spline, Bezier, revolution, offset).
bool mayBeRing(GeomAbs_SurfaceType type);
std::optional<RingAngles> ringAngles(const Adaptor3d_Surface& surface, double u0, double u1, double v0, double v1);

}  // namespace cetview::brep
