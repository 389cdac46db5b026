// A knot of full multiplicity where the surface is smooth (tangent-continuous): the parametrisation
// is only C0 there, the surface is not. STEP and IGES exports piece their B-splines so (hammer,
// linkrods, r0901), and such a knot line is no crease (SurfaceEval::keepTurningBreaks): the angle
// test holds across it as anywhere else. Taken for creases, edges across those lines were left to
// the chordal test and turned by up to 57 degrees on hammer at 0.1% (angle 20), 94 on r0901.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "brep/tessellator.h"
#include "surface_eval.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

constexpr double kKnot = 0.4;

// A channel 10 long (v, a parabola sagging by 3 in its middle) whose cross-section (u, one cubic
// span) turns by 180 degrees, with the knot u = kKnot inserted to multiplicity 3: the same surface,
// pieced from two spans.
Handle(Geom_BSplineSurface) piecedChannel() {
  const double x[4] = {0, 0, 10, 10}, z[4] = {0, 10, 10, 0};
  TColgp_Array2OfPnt poles(1, 4, 1, 3);
  for (int i = 1; i <= 4; ++i)
    for (int j = 1; j <= 3; ++j)
      poles.SetValue(i, j, gp_Pnt(x[i - 1], 5.0 * (j - 1), z[i - 1] - (j == 2 ? 3 : 0)));
  TColStd_Array1OfReal uKnots(1, 2), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, 2), vMults(1, 2);
  uKnots(1) = 0, uKnots(2) = 1, uMults(1) = uMults(2) = 4;
  vKnots(1) = 0, vKnots(2) = 1, vMults(1) = vMults(2) = 3;
  Handle(Geom_BSplineSurface) channel = new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 3, 2);
  channel->InsertUKnot(kKnot, 3, 1e-12);
  return channel;
}

TEST(SmoothKnot, AKnotOfFullMultiplicityOnASmoothSurfaceIsNoCrease) {
  const Handle(Geom_BSplineSurface) channel = piecedChannel();
  ASSERT_EQ(channel->UMultiplicity(2), 3);  // C0 in its parameters
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(channel, 1e-7).Face();
  EXPECT_FALSE(SurfaceEval(face).crossesCrease(kKnot - 0.1, 0.5, kKnot + 0.1, 0.5));
  EXPECT_FALSE(SurfaceEval(face).onCrease(kKnot, 0.5));
}

// Every edge of every level, its corners' normals (the exact surface's: it is smooth everywhere)
// within the level's angle, down to a tenth of the level's chordal tolerance (below which no
// angular split is made). Without the knot told apart from a crease, edges across it turned by up
// to 40 degrees (angle 20) on the coarse levels at 2%, 1% and 0.5%.
TEST(SmoothKnot, EdgesAcrossAKnotOfASmoothSurfaceKeepTheAngle) {
  auto model = test::loadShape(BRepBuilderAPI_MakeFace(piecedChannel(), 1e-7).Face(), "pieced_channel");
  ASSERT_TRUE(model);
  for (double d : {0.02, 0.01, 0.005, 0.002, 0.001}) {
    SCOPED_TRACE("at " + std::to_string(d * 100) + "%");
    auto t = test::tessellate(*model, test::relative(d));
    ASSERT_TRUE(t);
    const FaceMesh& m = t->faceMesh(0);
    ASSERT_EQ(m.levels.size(), t->schedule().size());
    int across = 0;
    for (std::size_t k = 0; k < m.levels.size(); ++k) {
      const Level& level = t->schedule()[k];
      double worst = 0;
      const std::vector<std::uint32_t>& idx = m.levels[k];
      for (std::size_t i = 0; i < idx.size(); ++i) {
        const std::uint32_t a = idx[i], b = idx[i % 3 == 2 ? i - 2 : i + 1];
        const gp_Pnt pa(m.positions[3 * a], m.positions[3 * a + 1], m.positions[3 * a + 2]);
        const gp_Pnt pb(m.positions[3 * b], m.positions[3 * b + 1], m.positions[3 * b + 2]);
        if (pa.Distance(pb) < 0.1 * level.chordal) continue;
        across += (m.uv[2 * a] - kKnot) * (m.uv[2 * b] - kKnot) < 0;
        const gp_Vec na(m.normals[3 * a], m.normals[3 * a + 1], m.normals[3 * a + 2]);
        const gp_Vec nb(m.normals[3 * b], m.normals[3 * b + 1], m.normals[3 * b + 2]);
        worst = std::max(worst, na.Angle(nb));
      }
      EXPECT_LE(worst, level.angleRad * (1 + 1e-5))
          << "level " << k << ": " << worst * 180 / M_PI << " degrees";
    }
    EXPECT_GT(across, 0);  // the knot line lies inside the face, crossed by its edges
  }
}

}  // namespace
}  // namespace cetview::brep
