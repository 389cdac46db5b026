// The angular deflection measure (measure_impl.h, used by `cetview bench` for cetview's meshes and
// BRepMesh's alike): the largest angle between the exact surface normals at a triangle edge's ends.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <gp_Ax3.hxx>

#include "brep/measure.h"
#include "measure_impl.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A quarter of a unit cylinder, 1 high, as two strips of two triangles: columns at u = 0, pi/4, pi/2.
struct QuarterCylinder {
  TopoDS_Face face = BRepBuilderAPI_MakeFace(new Geom_CylindricalSurface(gp_Ax3(), 1.0), 0, M_PI / 2, 0, 1, 1e-7);
  std::vector<double> uv, positions;
  std::vector<std::uint32_t> indices = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
  QuarterCylinder() {
    for (double v : {0.0, 1.0}) {
      for (double u : {0.0, M_PI / 4, M_PI / 2}) {
        uv.insert(uv.end(), {u, v});
        positions.insert(positions.end(), {std::cos(u), std::sin(u), v});
      }
    }
  }
};

TEST(CornerAngle, IsTheTurnOfTheNormalsAcrossAStrip) {
  const QuarterCylinder q;
  const SurfaceEval eval(q.face);
  EXPECT_NEAR(measureCornerAngle(eval, q.positions.data(), q.uv.data(), 6, q.indices.data(), 4, 0.0), M_PI / 4, 1e-9);
  // Edges shorter than the minimum length are not counted: the rows' edges are 0.77 long, the
  // diagonals 1.26 (both turn by 45 degrees), the columns 1 (the same normal at both ends).
  EXPECT_NEAR(measureCornerAngle(eval, q.positions.data(), q.uv.data(), 6, q.indices.data(), 4, 1.0), M_PI / 4, 1e-9);
  EXPECT_NEAR(measureCornerAngle(eval, q.positions.data(), q.uv.data(), 6, q.indices.data(), 4, 1.3), 0.0, 1e-12);
}

TEST(CornerAngle, TessellatedCylinderKeepsTheAngularDeflection) {
  auto model = test::loadShape(BRepPrimAPI_MakeCylinder(5, 20).Shape(), "cylinder");
  ASSERT_TRUE(model);
  for (double angle : {20.0, 8.0}) {
    auto created = Tessellator::create(*model, test::relative(0.01, angle));
    ASSERT_TRUE(created.tessellator) << created.error;
    ASSERT_TRUE(created.tessellator->run(1));
    double worst = 0;
    for (const FaceQuality& f : measureFaces(*created.tessellator)) worst = std::max(worst, f.maxCornerAngle);
    EXPECT_LE(worst, angle * M_PI / 180 * (1 + 1e-6)) << angle << " degrees";
    EXPECT_GT(worst, 0.5 * angle * M_PI / 180) << angle << " degrees: the mesh is finer than the angle needs";
  }
}

}  // namespace
}  // namespace cetview::brep
