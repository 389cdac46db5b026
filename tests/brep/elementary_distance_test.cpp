// ElementaryDistance (tessellation/brep/src), the refinement's closed-form distance, against
// OpenCASCADE's own point-to-surface projection (GeomAPI_ProjectPointOnSurf, the nearest of all its
// extrema) on every elementary surface type, placed off the origin and tilted, with points near the
// surface and far from it, inside and outside, across a cone's apex and inside a spindle torus.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Ax3.hxx>

#include "elementary_distance.h"

namespace cetview::brep {
namespace {

const gp_Ax3 kFrame(gp_Pnt(3, -2, 7), gp_Dir(1, 2, 3), gp_Dir(2, -1, 0));

// Distances from points spread over a box of half-size `reach` about the frame's origin.
void expectExact(const Handle(Geom_Surface)& surface, double reach, const char* name) {
  SCOPED_TRACE(name);
  const ElementaryDistance distance{GeomAdaptor_Surface(surface)};
  ASSERT_TRUE(distance.valid());
  // OpenCASCADE's extrema need bounds: infinite directions trimmed far beyond the points' reach.
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  const auto bound = [](double t) { return std::max(-1e3, std::min(1e3, t)); };
  const Handle(Geom_Surface) bounded =
      new Geom_RectangularTrimmedSurface(surface, bound(u0), bound(u1), bound(v0), bound(v1));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-reach, reach);
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    const gp_Pnt m = gp_Pnt(coordinate(rng), coordinate(rng), coordinate(rng)).Translated(gp_Vec(kFrame.Location().XYZ()));
    GeomAPI_ProjectPointOnSurf projection(m, bounded);
    if (projection.NbPoints() == 0) continue;
    EXPECT_NEAR(distance(m), projection.LowerDistance(), 1e-7 * (1 + reach)) << "at " << m.X() << " " << m.Y() << " " << m.Z();
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(ElementaryDistance, MatchesOpenCascadeProjection) {
  expectExact(new Geom_Plane(kFrame), 10, "plane");
  expectExact(new Geom_CylindricalSurface(kFrame, 2.5), 6, "cylinder");
  expectExact(new Geom_ConicalSurface(kFrame, 0.4, 1.5), 6, "cone, both nappes");
  expectExact(new Geom_SphericalSurface(kFrame, 3.0), 6, "sphere");
  expectExact(new Geom_ToroidalSurface(kFrame, 5.0, 1.5), 8, "ring torus");
  expectExact(new Geom_ToroidalSurface(kFrame, 1.0, 3.0), 5, "spindle torus");
}

TEST(ElementaryDistance, OtherSurfacesAreNotElementary) {
  const Handle(Geom_Surface) trimmed = new Geom_RectangularTrimmedSurface(new Geom_Plane(kFrame), 0.0, 1.0, 0.0, 1.0);
  EXPECT_TRUE(ElementaryDistance{GeomAdaptor_Surface(trimmed)}.valid());  // the adaptor sees the plane
  const Handle(Geom_Surface) offset = new Geom_OffsetSurface(new Geom_SphericalSurface(kFrame, 3.0), 0.5);
  EXPECT_FALSE(ElementaryDistance{GeomAdaptor_Surface(offset)}.valid());
}

}  // namespace
}  // namespace cetview::brep
