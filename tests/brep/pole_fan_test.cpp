// Triangles standing on a pole's row (two corners on the degenerate edge, one 3D point: no area)
// stand for the sector of the pole's fan between their row corners. The refinement reads how far
// that sector lies from the triangle, at the same (u, v), and splits where it is beyond the
// tolerance; across the surface, not along it, where the surface over the sector turns no further
// than a right angle from the triangle's regular corner: the fan's other triangles cover the
// sector within the surface, whatever their shape in UV, and the part of the distance along it
// only counts as far as the surface turns out of its plane (FaceMesher::sample()).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLib.hxx>
#include <GC_MakeSegment.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax1.hxx>

#include "brep/measure.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A cone (or, with no rise, a disc) as OpenCASCADE writes a revolved B-spline line: a surface of
// revolution of the segment from the apex on the axis to (10, 0, rise), about z. Its side v = first
// is a pole (the degenerate edge at the apex), its seam the segment itself.
TopoDS_Face revolvedLine(double rise) {
  const Handle(Geom_TrimmedCurve) segment = GC_MakeSegment(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, rise)).Value();
  const Handle(Geom_BSplineCurve) line = GeomConvert::CurveToBSplineCurve(segment);
  const Handle(Geom_Surface) surface =
      new Geom_SurfaceOfRevolution(line, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)));
  TopoDS_Face face =
      BRepBuilderAPI_MakeFace(surface, 0, 2 * M_PI, line->FirstParameter(), line->LastParameter(), 1e-7);
  BRepLib::BuildCurves3d(face);
  return face;
}

// Its generators are straight: the fan from the apex onto the rim's chords is within any
// deflection (the chords are, and each triangle holds a generator at either end). The sector
// triangles on the apex's row read the sector's distance along the surface (the gap between two
// generators in UV and in 3D), so the refinement put points between the apex and the rim: at
// 0.01%, 1442 triangles (7.5x the fan), one flipped; the disc and a nearly flat cone the same.
TEST(PoleFan, AConeOfRevolutionIsAFanFromItsApex) {
  for (const double rise : {3.0, 0.05, 0.0}) {
    for (const double fraction : {1e-3, 1e-4}) {
      SCOPED_TRACE("rise " + std::to_string(rise) + ", deflection " + std::to_string(fraction));
      const auto model = test::loadShape(revolvedLine(rise), "revolved_line");
      ASSERT_TRUE(model);
      const auto t = test::tessellateAndCheck(*model, test::relative(fraction));
      ASSERT_TRUE(t);
      const FaceMesh& mesh = t->faceMesh(0);
      // The rim's points, the seam's end counted on both of its sides.
      std::size_t rim = 0;
      for (std::size_t i = 0; i < mesh.vertexCount(); ++i)
        rim += std::abs(std::hypot(mesh.positions[3 * i], mesh.positions[3 * i + 1]) - 10) < 1e-6;
      ASSERT_GT(rim, 3u);
      EXPECT_EQ(mesh.levels.back().size() / 3, rim - 1);
    }
  }
}

// periodic_sheet_doubled_over_from_a_pole_row.brep (face_fuzz, from a two-byte input that every
// seed draws: 287 of the forty-third session's eighteen seeds' faces were this one, meshed alike
// with 98 triangles and 5 flipped): a bilinear sheet,
// periodic in u with two poles a row, so that it runs out and back over one flat triangle, folded
// at its middle knot; its side v = first is a pole. Its sector triangles read the in-plane gaps and
// were split towards the pole's ends, a column of points there each a quarter as far from the row
// as the one before, and slivers fanning from the row's ends flipped: 98 triangles, 5 flipped (one
// across the fold). Now the triangles along the fold alone face the other half's way.
TEST(PoleFan, ASheetDoubledOverFromAPoleRowIsFlippedOnlyAcrossItsFold) {
  const auto model = test::loadTestData("periodic_sheet_doubled_over_from_a_pole_row.brep");
  ASSERT_TRUE(model);
  MeshParams params = test::relative(1e-3, 5);
  params.progressive = false;
  const auto t = test::tessellate(*model, params);
  ASSERT_TRUE(t);
  const FaceQuality q = measureFaces(*t, t->lastLevel()).at(0);
  EXPECT_LE(q.maxDeviation, t->schedule().back().chordal);
  EXPECT_EQ(q.degenerate, 0u);
  EXPECT_EQ(q.flipped, q.flippedAcrossFolds);
  EXPECT_LT(q.triangles, 40u);
}

// occt-misc's shell1.brep, face 40: a small B-spline sheet (0.68 x 0.41) with a pole row at v = 0,
// where the sheet curls within about 1e-3 of the row: the normal's limit on the row turns 45 to
// 126 degrees from the sheet's normal beside it. A pole vertex facing away from a triangle gets a
// twin for it (FaceMesher::twinSingularCorners); showing that limit, the fan triangle beside it
// shaded the curl over its whole width, and turned 44.5 degrees across its edge 0.046 long from the
// pole (over the minimum size at 0.401, 1% of the part's box). The twin now shows the surface an
// eighth of the way into the triangle.
TEST(PoleFan, APoleTwinShowsTheSurfaceBesideThePoleRow) {
  const std::string file = std::string(CETVIEW_OCCT_DATA) + "/occ/shell1.brep";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "occt-misc sample models not installed at " << CETVIEW_OCCT_DATA;
  LoadResult loaded = loadModel(file);
  ASSERT_TRUE(loaded) << loaded.error;
  const auto t = test::tessellate(*loaded.model, test::absolute(0.40095));
  ASSERT_TRUE(t);
  constexpr FaceId kCurledFace = 40;
  ASSERT_GT(loaded.model->faces().size(), kCurledFace);
  const std::vector<FaceQuality> q = measureFaces(*t);
  EXPECT_LE(q[kCurledFace].maxCornerAngle, t->angleRad() * (1 + 1e-4)) << q[kCurledFace].maxCornerAngle * 180 / M_PI;
  EXPECT_EQ(q[kCurledFace].flipped, 0u);
}

}  // namespace
}  // namespace cetview::brep
