// ElementaryDistance (tessellation/brep/src), the refinement's closed-form distance, against
// OpenCASCADE's own point-to-surface projection (GeomAPI_ProjectPointOnSurf, the nearest of all its
// extrema) on every elementary surface type, placed off the origin and tilted, with points near the
// surface and far from it, inside and outside, across a cone's apex and inside a spindle torus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// The largest distance of a flat triangle with corners on the surface, in closed form, against a
// dense barycentric grid of the same point distance: never below the grid's largest (it is the
// maximum), never more than the grid's resolution above it, and reached on the edge it names.
// A sphere's deepest point is inside acute triangles; a cylinder's is on an edge (its axis would have
// to pierce the triangle): `insideSeen` says whether the inside case must come up.
void expectTriangleDeviation(const Handle(Geom_Surface)& surface, double uSpread, double vSpread, bool insideSeen,
                             const char* name) {
  SCOPED_TRACE(name);
  const ElementaryDistance distance{GeomAdaptor_Surface(surface)};
  ASSERT_TRUE(distance.hasTriangleDeviation());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr int kSteps = 160;
  int insideCount = 0, edgeCount = 0;
  for (int k = 0; k < 300; ++k) {
    // Triangles from tiny to a large part of the surface, acute and obtuse, thin and fat.
    const double scale = std::pow(10.0, -3.0 * unit(rng));
    const double u = 6.28 * unit(rng), v = vSpread * (unit(rng) - 0.5);
    gp_XYZ p[3];
    for (gp_XYZ& c : p) c = surface->Value(u + scale * uSpread * unit(rng), v + scale * vSpread * (unit(rng) - 0.5)).XYZ();
    if ((p[1] - p[0]).Crossed(p[2] - p[0]).Modulus() < 1e-9 * scale * scale) continue;
    int where = -2;
    const double exact = distance.triangleDeviation(p[0], p[1], p[2], where);
    ASSERT_GE(where, -1);
    double grid = 0, onEdge[3] = {0, 0, 0};
    for (int i = 0; i <= kSteps; ++i) {
      for (int j = 0; i + j <= kSteps; ++j) {
        const double b[3] = {double(kSteps - i - j) / kSteps, double(i) / kSteps, double(j) / kSteps};
        const double d = distance(gp_Pnt(b[0] * p[0] + b[1] * p[1] + b[2] * p[2]));
        grid = std::max(grid, d);
        for (int e = 0; e < 3; ++e)
          if (b[e] == 0) onEdge[e] = std::max(onEdge[e], d);
      }
    }
    const double slack = 1e-12 + 2e-3 * grid;
    EXPECT_GE(exact, grid - 1e-12) << "triangle " << k;
    EXPECT_LE(exact, grid + slack) << "triangle " << k;
    if (where >= 0) {
      EXPECT_NEAR(onEdge[where], exact, slack) << "triangle " << k << " edge " << where;
      ++edgeCount;
    } else {
      ++insideCount;
    }
  }
  if (insideSeen) {
    EXPECT_GT(insideCount, 10);
  }
  EXPECT_GT(edgeCount, 10);
}

TEST(ElementaryDistance, TriangleDeviationIsTheLargestDistanceOfTheFlatTriangle) {
  expectTriangleDeviation(new Geom_SphericalSurface(kFrame, 3.0), 2.0, 2.5, true, "sphere");
  expectTriangleDeviation(new Geom_CylindricalSurface(kFrame, 2.5), 2.5, 8.0, false, "cylinder");
  // A corner off the surface (an edge point within its edge's tolerance) counts as far as it is off.
  const Handle(Geom_Surface) sphere = new Geom_SphericalSurface(kFrame, 3.0);
  const ElementaryDistance sphereDistance{GeomAdaptor_Surface(sphere)};
  const gp_XYZ centre = kFrame.Location().XYZ();
  const gp_XYZ a = sphere->Value(0.1, 0.1).XYZ(), b = sphere->Value(0.1002, 0.1).XYZ();
  const gp_XYZ outward = centre + 1.01 * (sphere->Value(0.1001, 0.1002).XYZ() - centre);
  int where = -2;
  EXPECT_NEAR(sphereDistance.triangleDeviation(a, b, outward, where), 0.03, 1e-9);
  const ElementaryDistance plane{GeomAdaptor_Surface(new Geom_Plane(kFrame))};
  EXPECT_NEAR(plane.triangleDeviation(gp_XYZ(3, -2, 7), gp_XYZ(5, -3, 7), gp_XYZ(1, 0, 8), where),
              std::abs(gp_XYZ(-2, 2, 1).Dot(kFrame.Direction().XYZ())), 1e-12);
  const ElementaryDistance torus{GeomAdaptor_Surface(new Geom_ToroidalSurface(kFrame, 5.0, 1.5))};
  EXPECT_FALSE(torus.hasTriangleDeviation());
  EXPECT_LT(torus.triangleDeviation(gp_XYZ(0, 0, 0), gp_XYZ(1, 0, 0), gp_XYZ(0, 1, 0), where), 0);
}

}  // namespace
}  // namespace cetview::brep
