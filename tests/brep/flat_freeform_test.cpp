// Flat free-form faces (SurfaceEval::flat()): a B-spline whose poles lie in one plane, within a
// hundredth of the tolerance, whose face lies within one period where it is periodic, and whose
// parametrisation keeps its orientation over the face (a pole row on its side excepted) but is
// uneven there (speeds 4x apart, or down to nothing on a pole row), is meshed in that plane: its
// scaled plane is the plane itself, so the triangulation is one of the face's outline in 3D,
// whatever its weights do to the parametrisation. Where its domain fails in that plane, the level
// is built in the scaled UV plane.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <ostream>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "brep/measure.h"
#include "surface_eval.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A rational bicubic patch over [0, 1]^2 on the plane z = 0, its 4 x 4 poles at x from `columns`
// and y = 0..3, weights from 0.1 to 10 (all 1 when not `weighted`); `lift` raises one inner pole
// off the plane; with `poleRow` the first column's poles are one point (y = 1.5), the side u = 0
// a pole.
TopoDS_Face weightedSheet(const double columns[4], double lift = 0, bool weighted = true,
                          bool poleRow = false) {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  TColStd_Array2OfReal weights(1, 4, 1, 4);
  const double w[4][4] = {{1, 10, 0.1, 2}, {0.2, 5, 8, 0.1}, {3, 0.1, 0.5, 10}, {1, 4, 0.3, 1}};
  for (int i = 1; i <= 4; ++i) {
    for (int j = 1; j <= 4; ++j) {
      poles(i, j) = gp_Pnt(columns[i - 1], poleRow && i == 1 ? 1.5 : j - 1.0, i == 2 && j == 3 ? lift : 0.0);
      weights(i, j) = weighted ? w[i - 1][j - 1] : 1.0;
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots(1) = 0, knots(2) = 1, mults(1) = mults(2) = 4;
  const Handle(Geom_BSplineSurface) sheet = new Geom_BSplineSurface(poles, weights, knots, knots, mults, mults, 3, 3);
  return BRepBuilderAPI_MakeFace(sheet, 1e-7).Face();
}

constexpr double kColumns[4] = {0, 1, 2, 3};
constexpr double kChordal = 1e-3;  // the patch is about 4.2 across

// Flat: the scaled plane is the plane (distances there are 3D distances) and unscaled() inverts it.
TEST(FlatFreeForm, ARationalSheetInAPlaneIsMeshedInThatPlane) {
  const SurfaceEval eval(weightedSheet(kColumns), kChordal, 0.3);
  ASSERT_TRUE(eval.flat());
  std::vector<std::pair<double, double>> at;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) at.emplace_back(0.05 + 0.15 * i, 0.05 + 0.15 * j);
  for (std::size_t k = 0; k < at.size(); ++k) {
    const auto [u, v] = at[k];
    const cet::Point2 q = eval.scaled(u, v);
    double bu = -1, bv = -1;
    eval.unscaled(q, bu, bv);
    EXPECT_NEAR(bu, u, 1e-8) << "at " << u << ", " << v;
    EXPECT_NEAR(bv, v, 1e-8) << "at " << u << ", " << v;
    const auto [u2, v2] = at[(k * 7 + 3) % at.size()];
    const cet::Point2 q2 = eval.scaled(u2, v2);
    EXPECT_NEAR(std::hypot(q.x - q2.x, q.y - q2.y), eval.point(u, v).Distance(eval.point(u2, v2)), 1e-9);
  }
}

// Not flat: poles off the plane by more than a hundredth of the tolerance, a sheet folding over
// itself (its columns out of order), no tolerance to judge by, or a parametrisation close to
// uniform (the same grid without weights: it meshes as well, and cheaper, in the scaled UV plane).
TEST(FlatFreeForm, OnlyASheetFlatForTheToleranceAndUnfoldedIsFlat) {
  EXPECT_TRUE(SurfaceEval(weightedSheet(kColumns, 0.005 * kChordal), kChordal, 0.3).flat());
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns, 0.02 * kChordal), kChordal, 0.3).flat());
  const double folded[4] = {0, 3, -1, 2};
  EXPECT_FALSE(SurfaceEval(weightedSheet(folded), kChordal, 0.3).flat());
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns)).flat());
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns, 0, false), kChordal, 0.3).flat());
}

// A flat sheet fanning from a pole row (a degenerate edge on the box's side, where Su x Sv is
// nothing and its direction noise) is flat: the plane takes the row to one point as the surface
// does, and the row makes the parametrisation uneven (a sheet of even weights is flat too). Not
// flat: the same sheet folded over, or with flat faces switched off (the tests of the scaled UV
// plane's handling of such sheets).
TEST(FlatFreeForm, ASheetFanningFromAPoleRowIsFlat) {
  EXPECT_TRUE(SurfaceEval(weightedSheet(kColumns, 0, true, true), kChordal, 0.3).flat());
  EXPECT_TRUE(SurfaceEval(weightedSheet(kColumns, 0, false, true), kChordal, 0.3).flat());
  const double folded[4] = {0, 3, -1, 2};
  EXPECT_FALSE(SurfaceEval(weightedSheet(folded, 0, false, true), kChordal, 0.3).flat());
  SurfaceEval::enableFlatFaces(false);
  EXPECT_FALSE(SurfaceEval(weightedSheet(kColumns, 0, false, true), kChordal, 0.3).flat());
  SurfaceEval::enableFlatFaces(true);
}

// The whole patch, meshed: its outline's four iso-lines are straight, so each level is two
// triangles, within the tolerance and facing the surface's way.
TEST(FlatFreeForm, AWeightedFlatPatchTakesItsOutlineOnly) {
  auto model = test::loadShape(weightedSheet(kColumns), "weighted sheet");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  const std::vector<FaceQuality> levels = test::expectEveryLevelWithinTolerance(*t, 0);
  for (const FaceQuality& q : levels) {
    EXPECT_EQ(q.flipped, 0u);
    EXPECT_EQ(q.degenerate, 0u);
    EXPECT_LE(q.triangles, 8u);
  }
}

// flat_sheet_with_extreme_weights.brep (face_fuzz seed 101, input 79): a degree 1 x 2 sheet 73000
// long, flat within 1.7e-4, its weights from 1e-3 to 712 (a step of 1e-6 in u moves a point by 115
// near one side). Meshed in the scaled UV plane its first level (0.24%, 35.4 degrees) took 375788
// triangles, 53756 of them flipped, in 57 s: triangles well shaped there overlapped in 3D, and
// their splits made more. In its plane: two triangles a level, within 1e-6 of the tolerance.
TEST(FlatFreeForm, AFlatSheetWithExtremeWeightsIsMeshedAsItsOutline) {
  const std::vector<FaceQuality> levels = test::testDataEveryLevel(
      "flat_sheet_with_extreme_weights.brep", test::fuzzed("flat_sheet_with_extreme_weights.brep", 0.0024064050719198024, 35.363088426031894));
  ASSERT_FALSE(levels.empty());
  for (const FaceQuality& q : levels) {
    EXPECT_EQ(q.flipped, 0u);
    EXPECT_EQ(q.degenerate, 0u);
    EXPECT_LE(q.triangles, 8u);
  }
}

// Fuzzed flat B-spline sheets fanning from a pole (face_fuzz wrote them; the scaled UV plane's
// handling of the first four is tested in collapsed_surface_test.cpp with flat faces off). In the
// scaled UV plane, their parametrisation running down to nothing along the pole row, triangles
// fanning into the pole flipped or crowded; in their plane each level is a few triangles of the
// outline, none flipped:
// - flat_sheet_fanning_from_a_pole.brep (seed 808, input 64): 30, 41 and 55 triangles, 2 flipped
//   by the pole corner on each level; now 8, 9 and 13.
// - sheet_from_pole_corner.brep: 20 to 70 triangles, 1 flipped on level 1; now 4 to 16.
// - sheet_bulging_from_a_pole_corner.brep: 28 to 82, 1 flipped on levels 0 to 3; now 4 to 16.
// - fan_onto_straight_side.brep: 48 to 112; now 26 to 32.
// - plane_fanning_from_a_pole_corner.brep (final level alone): 83; now 11.
// - flat_periodic_sheet_within_one_period.brep (seed 808, input 167): periodic in u, the face over
//   half its period (flat within one period, where the plane is one-to-one): 34 to 93 triangles,
//   3 to 5 flipped on each level; now 8 to 23.
struct PoleSheet {
  const char* file;
  double deflection, angleDeg;
  bool progressive;
  std::size_t mostTriangles;  // half what the scaled UV plane took on the last level
};
void PrintTo(const PoleSheet& sheet, std::ostream* os) {
  *os << sheet.file;
}

class FlatSheetFanningFromAPole : public testing::TestWithParam<PoleSheet> {};

TEST_P(FlatSheetFanningFromAPole, IsMeshedInItsPlane) {
  const PoleSheet& sheet = GetParam();
  auto model = test::loadTestData(sheet.file);
  ASSERT_TRUE(model);
  MeshParams params = test::fuzzed(sheet.file, sheet.deflection, sheet.angleDeg);
  params.progressive = sheet.progressive;
  auto t = test::tessellate(*model, params);
  ASSERT_TRUE(t);
  EXPECT_TRUE(SurfaceEval(test::firstFace(sheet.file), t->schedule().back().chordal, 0.3).flat());
  const std::vector<FaceQuality> levels = test::expectEveryLevelWithinTolerance(*t, 0);
  for (const FaceQuality& q : levels) {
    EXPECT_EQ(q.flipped, 0u);
    EXPECT_EQ(q.degenerate, 0u);
  }
  EXPECT_LE(levels.back().triangles, sheet.mostTriangles);
}

INSTANTIATE_TEST_SUITE_P(
    FuzzedFaces, FlatSheetFanningFromAPole,
    testing::Values(
        PoleSheet{"flat_sheet_fanning_from_a_pole.brep", 0.0029994581136934839, 13.713054093232623, true, 27},
        PoleSheet{"sheet_from_pole_corner.brep", 0.00037327612484975826, 49.29289692530709, true, 35},
        PoleSheet{"sheet_bulging_from_a_pole_corner.brep", 0.00040839277467001951, 18.001602197299153, true,
                  41},
        PoleSheet{"fan_onto_straight_side.brep", 0.00079688600635591966, 26.06507972838941, true, 56},
        PoleSheet{"plane_fanning_from_a_pole_corner.brep", 0.001, 21.082475013351644, false, 41},
        PoleSheet{"flat_periodic_sheet_within_one_period.brep", 0.0019021295860323495, 6.3486686503395129,
                  true, 46}));

// The first face of a fuzzed flat sheet (tests/brep/data), tessellated: its status and per-level
// quality, each level within its tolerance; whether the face is flat() for that tolerance.
struct FlatSheetRun {
  FaceStatus status = FaceStatus::kPending;
  std::vector<FaceQuality> levels;
  bool flat = false;
};
FlatSheetRun tessellateSheet(const char* file, double deflection, double angleDeg) {
  FlatSheetRun run;
  auto model = test::loadTestData(file);
  if (!model) return run;
  auto t = test::tessellate(*model, test::fuzzed(file, deflection, angleDeg));
  if (!t) return run;
  run.status = t->report(0).status;
  run.levels = test::expectEveryLevelWithinTolerance(*t, 0);
  run.flat = SurfaceEval(test::firstFace(file), t->schedule().back().chordal, 0.3).flat();
  return run;
}

// A flat face meshed OK on `levelCount` levels; from level `first` on, 1 to `mostTriangles`
// triangles a level, none flipped.
void expectMeshedInItsPlane(const FlatSheetRun& run, std::size_t levelCount, std::size_t mostTriangles,
                            std::size_t first = 0) {
  EXPECT_TRUE(run.flat);
  EXPECT_EQ(run.status, FaceStatus::kOk);
  ASSERT_EQ(run.levels.size(), levelCount);
  for (std::size_t k = first; k < run.levels.size(); ++k) {
    EXPECT_GE(run.levels[k].triangles, 1u) << "level " << k;
    EXPECT_LE(run.levels[k].triangles, mostTriangles) << "level " << k;
    EXPECT_EQ(run.levels[k].flipped, 0u) << "level " << k;
  }
}

// flat_bilinear_sheet_with_a_pole_edge.brep (seed 2323, input 219): a bilinear sheet whose side
// u = umin is a pole, the rest a triangle in its plane. The degenerate edge's two ends, one point
// in the plane but for rounding, made boundary segments crossing at the pole and the face fell
// back to BRepMesh; the edge is now that one point: one triangle a level (11 to 21 in the scaled
// UV plane).
TEST(FlatFreeForm, APoleEdgeIsOnePointOfItsOutline) {
  expectMeshedInItsPlane(tessellateSheet("flat_bilinear_sheet_with_a_pole_edge.brep", 0.00031872078866525794,
                                         19.574349584191651),
                         6, 1);
}

// flat_sheet_across_from_its_planes_origin.brep (seed 606, input 36): a flat sheet fanning from a
// pole whose boundary points across from the plane's origin had a coordinate of 1e-52 there,
// below what the triangulator takes (the face fell back to BRepMesh); rounding noise is now zero:
// 5 and 7 triangles (11 and 15 in the scaled UV plane).
TEST(FlatFreeForm, RoundingNoiseAtThePlanesOriginIsZero) {
  expectMeshedInItsPlane(tessellateSheet("flat_sheet_across_from_its_planes_origin.brep",
                                         0.0060887389133381287, 43.187380788891431),
                         2, 8);
}

// flat_sheet_whose_chords_cross_in_its_plane.brep (seed 909, input 292): a flat rational sheet
// whose first u span, a millionth wide, moves a point 3e8 times faster than the rest. Its boundary
// chords, placed by the edge table in the scaled UV plane, cross in the flat plane: the face fell
// back to BRepMesh there. A flat face whose domain fails in its plane is meshed in the scaled UV
// plane instead, as before flat faces.
TEST(FlatFreeForm, AFlatFaceWhoseBoundaryCrossesInItsPlaneIsMeshedInTheScaledPlane) {
  const FlatSheetRun run = tessellateSheet("flat_sheet_whose_chords_cross_in_its_plane.brep",
                                           0.005014778715107312, 10.525597009231708);
  EXPECT_TRUE(run.flat);
  EXPECT_EQ(run.status, FaceStatus::kOk);
  ASSERT_EQ(run.levels.size(), 2u);
  EXPECT_EQ(run.levels.back().degenerate, 0u);
}

// flat_sheet_whose_coarsest_chords_cross_in_its_plane.brep (seed 808, input 123): a flat bilinear
// rational sheet with a hole, its speeds up to 1e4 apart. Level 0's boundary crosses itself in the
// plane, the finer levels' do not. Kept in the scaled UV plane after level 0, its refinement ran to
// the work bound on level 2 (106476 triangles, 15668 flipped); back in the plane from level 1 on,
// 22 to 58 triangles, none flipped.
TEST(FlatFreeForm, AFlatFaceReturnsToItsPlaneWhereItsBoundaryNoLongerCrosses) {
  expectMeshedInItsPlane(tessellateSheet("flat_sheet_whose_coarsest_chords_cross_in_its_plane.brep",
                                         0.00019265448580190577, 31.447165636682691),
                         7, 100, 1);
}

}  // namespace
}  // namespace cetview::brep
