// Surfaces without area over part or all of a face, as face_fuzz wrote them (tests/brep/data).
#include <gtest/gtest.h>

#include <memory>
#include <ostream>
#include <string>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_Plane.hxx>
#include <TopoDS_Face.hxx>

#include "brep/export.h"
#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "surface_eval.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// The flat sheets fanning from a pole below are meshed in their plane since the forty-third
// session (SurfaceEval::flat(); FlatSheetFanningFromAPole.IsMeshedInItsPlane): the tests of how
// the scaled UV plane handles them run with flat faces off while this lives, so that handling,
// which faces bent out of their plane still need, stays tested.
struct ScaledPlaneOnly {
  ScaledPlaneOnly() { SurfaceEval::enableFlatFaces(false); }
  ~ScaledPlaneOnly() { SurfaceEval::enableFlatFaces(true); }
  ScaledPlaneOnly(const ScaledPlaneOnly&) = delete;
  ScaledPlaneOnly& operator=(const ScaledPlaneOnly&) = delete;
};

// A tests/brep/data model tessellated with `params`; a test failure where it does not load or
// tessellate, or where face 0's refinement stopped at a work bound (its reason says so).
struct Tessellated {
  std::unique_ptr<Model> model;
  std::unique_ptr<Tessellator> t;
};
Tessellated tessellateWithoutAStop(const std::string& file, const MeshParams& params) {
  Tessellated r;
  r.model = test::loadTestData(file);
  EXPECT_TRUE(r.model) << file;
  if (r.model) r.t = test::tessellate(*r.model, params);
  EXPECT_TRUE(r.t) << file;
  if (r.t) {
    EXPECT_EQ(r.t->report(0).reason.find("refinement stopped"), std::string::npos) << r.t->report(0).reason;
  }
  return r;
}

// collapsed_half.brep is a B-spline whose poles over the last half of its u span all lie on one
// point. Its triangles there have no area and corners without a first-derivative normal: no
// orientation a split could put right. Split as flipped triangles, they ran on to the minimum size
// everywhere in the collapsed half: 4.7 million triangles in 31 s at 0.1% (BRepMesh: 1552).

TEST(CollapsedSurface, HalfCollapsedToAPointIsNotRefinedThere) {
  auto model = test::loadTestData("collapsed_half.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  for (const FaceQuality& q : test::expectEveryLevelWithinTolerance(*t, 0)) EXPECT_LE(q.triangles, 20000u);
}

// collapsed_bilinear.brep is a bilinear patch of 3 x 2 spans whose first row of poles is one point
// and whose others are all a second point but one pole: two thirds of its box collapse onto that
// point, and most of the rest onto the segment between the two, where Su and Sv are parallel and
// their cross product is rounding noise. The edge along that segment (a straight line) was halved
// for the noise, standing triangles on it failing the angle against noise normals, down to a
// tenth of the tolerance: 3973 points on it at the last level, and 4095 triangles, 4041 of them of
// no area (BRepMesh: none there). The edge table takes no normal where the surface has no area.
TEST(CollapsedSurface, AnEdgeBesideAPatchCollapsedOntoASegmentIsNotHalvedForNoise) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("collapsed_bilinear.brep", test::fuzzed("collapsed_bilinear.brep", 0.0014130215179088082, 53.703135728999769));
  ASSERT_FALSE(levels.empty());
  EXPECT_LE(levels.back().triangles, 400u) << "4095 with the edge halved for noise";
  EXPECT_LE(levels.back().degenerate, 100u) << "4041 with the edge halved for noise";
}

// collapsed_fan.brep is a bilinear-by-cubic B-spline fanning between two points 1e-3 apart: its
// first row of poles is one point and most of the others another, so that most of its parameter
// box collapses onto that point. Beside the collapsed part the surface's speed changes by orders of
// magnitude and the refinement's Gauss-Newton steps stop short of the foot: a triangle standing on a
// boundary chord from the pole read the same distance whatever its apex, and its splits piled
// points up against the chord at 5.6% (one level): 91916 triangles, 19643 of them flipped, where the
// measure finds the face within 0.22 of the tolerance. A triangle with a corner at a pole that reads
// too far is checked by the measure itself before it is split: 1908 triangles, 13 flipped, all of
// them across folds. Since the edges stand their trial triangles in the mesher's scaled plane
// (twenty-fifth session), the side v = vmin takes 33 points instead of 11 and the level 1722
// triangles, 8 flipped: 5 across folds and 3 beside the corner where the fan starts, whose corners'
// normals the refinement reads within 12 degrees of each other where the output's normals (and so
// the check) are 72 degrees apart (open).
TEST(CollapsedSurface, AFanCollapsedOntoAPointIsNotSplitOnAndOnBesideIt) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("collapsed_fan.brep", test::fuzzed("collapsed_fan.brep", 0.055875193901701303, 27.75532158388647));
  ASSERT_FALSE(levels.empty());
  EXPECT_LE(levels.back().triangles, 5000u) << "91916 when the samples' short projections decide";
  EXPECT_LE(levels.back().flipped, 13u) << "19643 flipped";
  EXPECT_LE(levels.back().flipped - levels.back().flippedAcrossFolds, 3u);
}

// periodic_fan_between_two_points.brep (fuzz seed 505 input 175) is a B-spline, periodic and cubic
// in u over a range of 1e-3, whose first row of poles is one point and most of the others another:
// it fans between the two. On level 0 at 0.0161% one triangle's split point, at a corner of the
// collapsed part, could not be made (merged with a vertex or rejected), pass after pass; each time
// it marked its corners taken, so a triangle beside it, 2.04x the level's tolerance, waited for its
// turn, and the level ended when no point went in. A split that merges or is rejected is not asked again on
// that level, and the passes go on while a triangle waits beside one.
TEST(CollapsedSurface, ATriangleWaitingBesideASplitThatCannotBeMadeIsStillSplit) {
  const std::vector<FaceQuality> levels = test::testDataEveryLevel(
      "periodic_fan_between_two_points.brep", test::fuzzed("periodic_fan_between_two_points.brep", 0.00016081154893116633, 49.102388036926833));
  ASSERT_FALSE(levels.empty());
}

// flat_periodic_sheet_from_a_pole.brep (fuzz seed 505 input 16) is a flat B-spline sheet, periodic
// in u over a range of 1e-3, whose row v = vmin is one point: a disc fanning from a pole. On its
// last level at 0.0542% a triangle with a corner on the pole and its corners in line through it
// (flipped, its facet noise, whatever its third corner) took repairing flips that kept the pole
// and one other corner, a new quadrilateral each pass, until the pass bound (3800 passes; the face
// then reported as not reaching its tolerances). Flips that keep an edge of the flipped triangle
// are bounded per level.
TEST(CollapsedSurface, RepairingFlipsDoNotWalkAroundAFan) {
  auto model = test::loadTestData("flat_periodic_sheet_from_a_pole.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::fuzzed("flat_periodic_sheet_from_a_pole.brep", 0.00054221631301118206, 21.797512779430839));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->report(0).status, FaceStatus::kOk) << t->report(0).reason;
  test::expectEveryLevelWithinTolerance(*t, 0);
}

// fan_onto_straight_side.brep is a flat B-spline sheet whose last v span, 5e-6 wide against 1,
// fans its row onto one corner point (the pole at v = 1): the side u = umax runs straight into
// that point, one boundary chord 57 units long. A triangle from a point inside onto that chord has
// its corners in line through the pole and counts as flipped (its facet is noise), but bisecting
// it made a triangle on the same chord with its apex nearer to it, in line again, on and on, the
// chord keeping it above the minimum size: at 0.08% 66168 triangles, 23578 of no area, in 5 s
// (BRepMesh: 103; now 114). Such a triangle on a chord into a pole is not split as flipped.
TEST(CollapsedSurface, AFanOntoAStraightSideIsNotSplitOnAndOnAlongIt) {
  const ScaledPlaneOnly scaledPlane;
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("fan_onto_straight_side.brep", test::fuzzed("fan_onto_straight_side.brep", 0.00079688600635591966, 26.06507972838941));
  ASSERT_FALSE(levels.empty());
  for (const FaceQuality& q : levels) {
    EXPECT_LE(q.triangles, 1000u) << "66168 on the last level with the splits along the chord";
    EXPECT_EQ(q.degenerate, 0u) << "23578 on the last level with the splits along the chord";
    EXPECT_EQ(q.flipped, 0u);
  }
}

// Sheets fanning from a pole corner: B-splines whose first row of poles is one point. Off a
// boundary chord from the pole the surface moves far slower than the scaled UV plane, and the zone
// where a chord's clearance was checked (twice the clearance in scaled UV) let points through that
// lay beyond the chord in 3D: every triangle on or beside it flipped, and the splits of flipped
// triangles crowded against the side. The zone of a chord from a pole now reaches as far out as the
// surface's speed needs, refusing there only points beyond the chord.
// - sheet_from_pole_corner.brep is flat, 0.03 long, its side v = vmax a curve from the pole (one
//   chord 0.024 long on the first levels): at 0.037% 10206 triangles, 3995 flipped (BRepMesh 1053);
//   now 112. One stays flipped on level 1, where a split of a triangle collapsed onto the pole
//   (such splits skip the clearance: its other points flipped triangles by the pole instead) lands
//   beyond the chord; level 2 halves the chord.
// - bent_sheet_from_pole_corner.brep is bent along its length, 82 long: at 0.042% 12993 triangles,
//   4211 flipped (BRepMesh 1503); now 999. Where the widened zone kept the whole clearance rather
//   than only the chord's side, one stayed flipped on each of its last three levels (as 5 did on a
//   coarse level of a SolidWorks part's B-spline faces by an apex).
// - sheet_bulging_from_a_pole_corner.brep is flat, 0.025 long, its side from the pole bulging out
//   beyond its chord (by 2e-5 on a chord 0.014 long). Once a point stood in that bulge, the
//   triangle on the chord from it and the pole was flipped, and each split of it (sliding along
//   the edge it bisects, standing on the chord as a facet facing the surface's way) put another
//   point in the bulge, nearer the side: at 0.041% 13022 triangles, 4526 flipped, from level 2 on
//   (BRepMesh 394). A flipped triangle from the pole whose other corners stand within the bulge
//   of a chord from it (FaceMesher::huggingPoleChord) is no longer split: 82, none flipped on the
//   last level.
struct PoleCornerSheet {
  const char* file;
  double deflection, angleDeg;
  std::size_t mostTriangles;  // a tenth of what the last level took with points beyond the chords
};
void PrintTo(const PoleCornerSheet& sheet, std::ostream* os) { *os << sheet.file; }

class FanFromAPoleCorner : public testing::TestWithParam<PoleCornerSheet> {};

TEST_P(FanFromAPoleCorner, KeepsItsPointsOnTheInsideOfItsChords) {
  const ScaledPlaneOnly scaledPlane;
  const PoleCornerSheet& sheet = GetParam();
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel(sheet.file, test::fuzzed(sheet.file, sheet.deflection, sheet.angleDeg));
  ASSERT_FALSE(levels.empty());
  for (const FaceQuality& q : levels) {
    EXPECT_LE(q.triangles, sheet.mostTriangles) << "10 times as many with points beyond the chords";
    EXPECT_LE(q.flipped, 1u) << "thousands on the last level with points beyond the chords";
    EXPECT_EQ(q.degenerate, 0u);
  }
  EXPECT_EQ(levels.back().flipped, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    FuzzedFaces, FanFromAPoleCorner,
    testing::Values(PoleCornerSheet{"sheet_from_pole_corner.brep", 0.00037327612484975826, 49.29289692530709, 1000},
                    PoleCornerSheet{"bent_sheet_from_pole_corner.brep", 0.00042445578391277453, 16.234149691004806, 1300},
                    PoleCornerSheet{"sheet_bulging_from_a_pole_corner.brep", 0.00040839277467001951, 18.001602197299153, 1300}));

// plane_fanning_from_a_pole_corner.brep is a flat quadratic B-spline 139 x 9.5 whose last row of
// poles is one corner point, and whose last four u spans, a millionth of the first's width, carry
// two thirds of its length (in the second the speed ramps up 3e5x). By the pole its triangles are
// long slivers fanning from the corner, over which the surface's map from the scaled plane is far
// from linear: a Delaunay quadrilateral there can face away on the surface while its other
// diagonal faces right, and splitting the flipped triangle made more such quadrilaterals beside it:
// at 0.1% and 21 degrees (the final level alone) 57893 triangles, 12334 flipped, the whole face
// within 5e-5 of the tolerance (BRepMesh: 431). Flipping the diagonal instead: 83, none flipped.
TEST(CollapsedSurface, AFlippedTriangleIsPutRightByFlippingAnEdgeRatherThanBySplits) {
  const ScaledPlaneOnly scaledPlane;
  MeshParams params = test::fuzzed("plane_fanning_from_a_pole_corner.brep", 0.001, 21.082475013351644);
  params.progressive = false;
  const std::vector<FaceQuality> levels = test::testDataEveryLevel("plane_fanning_from_a_pole_corner.brep", params);
  ASSERT_EQ(levels.size(), 1u);
  EXPECT_LE(levels[0].triangles, 1000u) << "57893 splitting flipped triangles";
  EXPECT_EQ(levels[0].flipped, 0u) << "12334 splitting flipped triangles";
  EXPECT_EQ(levels[0].degenerate, 0u);
}

// Faces whose surface has no area anywhere: reported empty, with the reason, on every level.
// - collapsed_segment.brep is a biquadratic B-spline whose three rows of poles are three points on
//   one segment, bounded by two degenerate edges and the segment twice. Its vertices' normals were
//   rounding noise, and refinement chased them: 225k triangles (58k of zero area) in 3 s at 0.1%,
//   and 35 s for the final level alone. BRepMesh makes none.
// - collapsed_extrapolated.brep is a rational patch whose face lies 23 to 53 units of v below its
//   knots (v from 0 to 191), where the extrapolated surface is one curve: |Sv| is 1e-13 against
//   |Su| of 4 to 13, a width of 3e-12 over a face 0.017 long. It ended 267x over the deflection in
//   40 triangles on every level. BRepMesh makes none.
class CollapsedOntoACurve : public testing::TestWithParam<const char*> {};

TEST_P(CollapsedOntoACurve, IsReportedEmpty) {
  auto model = test::loadTestData(GetParam());
  ASSERT_TRUE(model);
  ASSERT_EQ(model->faces().size(), 1u);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  const FaceReport report = t->report(0);
  EXPECT_EQ(report.status, FaceStatus::kEmpty);
  EXPECT_NE(report.reason.find("no area"), std::string::npos) << report.reason;
  for (int k = 0; k <= t->lastLevel(); ++k) EXPECT_EQ(t->triangleCount(k), 0u) << "level " << k;
  // Export has nothing to write, and says so.
  const std::string error = exportModel(*t, test::tempPath("collapsed.stl"));
  EXPECT_NE(error.find("no face of the model has triangles"), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(FuzzedFaces, CollapsedOntoACurve,
                         testing::Values("collapsed_segment.brep", "collapsed_extrapolated.brep"));

// extension_past_a_tiny_span.brep is a rational B-spline whose first v span is 1e-6 long (the next
// one 1) and whose face reaches 0.24 of v below its knots, onto OCCT's extension of that span. The
// extension runs at |Sv| 2.6e4 at the knot and 1e-8 0.02 further out: it collapses onto a curve.
// Scaled with the tiny span's speed carried on past the knot, the face's part there stood 100000
// times as tall in the scaled plane as the rest of it, and refinement never reached the tolerance:
// 1.04 million triangles (914k of no area) in 4.4 s at 0.1%, stopped by the point bound on level 2
// at 2.6x the tolerance (BRepMesh: 37 triangles, 24x over it). Bands past the knots scaled by their
// own speed: about 32k triangles, within each level's tolerance.
TEST(CollapsedSurface, AFaceOnTheExtensionOfATinyEndSpanIsMeshedWithinItsTolerance) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("extension_past_a_tiny_span.brep", test::relative(0.001));
  ASSERT_FALSE(levels.empty());
  EXPECT_LE(levels.back().triangles, 100000u) << "1.04 million with the end span's scale past the knot";
  EXPECT_LE(levels.back().degenerate, 100u) << "914k with the end span's scale past the knot";
}

// half_collapsed_wavy_sheet.brep (fuzz seed 404 input 240) is a B-spline, linear in u, whose last
// five of eight columns of poles are one point: it collapses onto that point over more than half of
// u and turns wildly beside it.
// - At 1.5% and 10 degrees its last level kept triangles 1.87x its tolerance (at face_fuzz's 0.22%,
//   112 triangles up to 6.2x, the face reported ok): the angle split them, so their chordal
//   samples were never taken, and each angle split was dropped, its point not clear of the chords.
//   Such a triangle is now measured and, if too far, split at its worst sample whatever the chords.
// - At 3% and 5 degrees two repairing flips undid each other pass after pass (the triangles' flip
//   rules disagree on a triangle in line with a pole corner) until the pass bound ended the level.
//   A flip no longer restores a diagonal this level's flips took away, and a level that reaches the
//   pass bound says so.
TEST(CollapsedSurface, ATriangleWhoseAngleSplitIsDroppedIsStillHeldToTheTolerance) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("half_collapsed_wavy_sheet.brep", test::relative(0.015, 10));
  ASSERT_FALSE(levels.empty());
}

TEST(CollapsedSurface, RepairingFlipsDoNotUndoEachOther) {
  tessellateWithoutAStop("half_collapsed_wavy_sheet.brep", test::fuzzed("half_collapsed_wavy_sheet.brep", 0.03, 5.0453192950331882));
}

// wavy_sheet_rebuilt_after_a_stop.brep (face_fuzz seed 2323, input 161): a sheet fanning from a
// pole corner whose poles swing 7 across in z, 0.2 in y, meshed at 0.1208% and 9.17 degrees.
// Its level 1 walked repairing flips around one pole-row vertex, one flip a pass (the walk took a
// new second corner each time one edge reached its bound), to the pass bound: "refinement stopped
// on level 1 after 4096 passes". A vertex now keeps at most kMaxVertexPivotFlips a level.
TEST(CollapsedSurface, RepairingFlipsDoNotWalkAroundAVertexToThePassBound) {
  const Tessellated r = tessellateWithoutAStop("wavy_sheet_rebuilt_after_a_stop.brep",
                                               test::fuzzed("wavy_sheet_rebuilt_after_a_stop.brep", 0.0012077769156757115, 9.1651789120317382));
  ASSERT_TRUE(r.t);
  test::expectEveryLevelWithinTolerance(*r.t, 0);
}

// A domain rebuilt after a stopped level is refined again. In the fuzzer's run of the same face
// (seed 2323 input 161) level 1 stopped at the pass bound and level 2's boundary no longer fit the
// domain, which was rebuilt; the stop held for the levels after it, so the rebuilt domain was never
// refined: levels 2 to 4 showed its bare boundary triangulation (119 to 230 triangles, 6.87x to
// 23.5x their tolerances). (Its level 0 no longer leaves the points along a side that made the
// boundary no longer fit: FaceMesher::alongChord.) sheet_with_a_sliver_wire_rebuilt_at_level_1.brep
// (face_fuzz seed 404, input 66) is rebuilt at level 1 (its refined boundary no longer fits); with
// its levels bounded to 20 points, level 0 stops there, and the rebuilt level 1 is refined (to the
// same bound) instead of showing its boundary alone.
TEST(CollapsedSurface, ADomainRebuiltAfterAStoppedLevelIsRefined) {
  auto model = test::loadTestData("sheet_with_a_sliver_wire_rebuilt_at_level_1.brep");
  ASSERT_TRUE(model);
  MeshParams params = test::fuzzed("sheet_with_a_sliver_wire_rebuilt_at_level_1.brep", 0.00180409753754177, 37.146486610208285);
  params.maxPointsPerFaceLevel = 20;
  auto t = test::tessellate(*model, params);
  ASSERT_TRUE(t);
  const std::string& reason = t->report(0).reason;
  EXPECT_NE(reason.find("refinement stopped on level 0"), std::string::npos) << reason;
  EXPECT_NE(reason.find("rebuilt at level 1"), std::string::npos) << reason;
  EXPECT_NE(reason.find("refinement stopped on level 1"), std::string::npos) << reason;
}

// A plane strip 100 long and 1e-6 wide (area 1e-8 of its extent squared, a hundred times the bar)
// has area: it is meshed, not reported empty.
TEST(CollapsedSurface, AStripAMillionthOfItsLengthWideIsMeshed) {
  const TopoDS_Face strip = BRepBuilderAPI_MakeFace(new Geom_Plane(gp::XOY()), 0, 100, 0, 1e-6, 1e-9).Face();
  auto model = test::loadShape(strip, "strip");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->report(0).status, FaceStatus::kOk) << t->report(0).reason;
  EXPECT_GT(t->triangleCount(t->lastLevel()), 0u);
}

// zigzag_sheet_from_a_pole.brep (face_fuzz seed 2222, input 204): a sheet whose first row of poles
// is one point and which zigzags 56 units across its v span of 1017 (degree 1 in v). At 0.0676%
// level 0's side v = vmax is one chord 885 long from the pole, and the surface folds beside it:
// triangles on that chord were flipped, each split of one (bisecting a free edge) put a point twice
// as near the chord's line, and the slivers between such points were flipped in turn, one split a
// pass to the pass bound ("refinement stopped on level 0 after 4096 passes", 24675 points, 25k of
// them within 1e-8 of the line in UV). The finer levels then kept level 0's interior: 1.1x to
// 8.8x their tolerances, 10074 of 49472 triangles flipped. Slivers along a chord are not split.
TEST(CollapsedSurface, SliversAlongABoundaryChordAreNotSplitTowardsIt) {
  const Tessellated r = tessellateWithoutAStop("zigzag_sheet_from_a_pole.brep",
                                               test::fuzzed("zigzag_sheet_from_a_pole.brep", 0.00067620056944267037, 45.724422064545664));
  ASSERT_TRUE(r.t);
  const std::vector<FaceQuality> levels = test::expectEveryLevelWithinTolerance(*r.t, 0);
  ASSERT_FALSE(levels.empty());
  EXPECT_LE(levels.back().triangles, 10000u) << "49472 with the splits along the chord";
  EXPECT_LE(levels.back().flipped, levels.back().triangles / 100) << "10074 with the splits along the chord";
}

// drill_point_cone_beside_a_far_cube.brep: half of a drill point's cone (semi-angle 59 degrees,
// slant 7.06; nist_ctc_04's face 0) and a unit cube that stretches the model to nist_ctc_04's
// diagonal (935), so that at 0.1% level 0's tolerance (15) is twice the cone's size, as in that
// model. Its coarse levels fan from the apex's points, which lie in a thin band along the seam's
// chord in the scaled plane: bisecting such triangles puts them right, so those with a corner on
// the boundary elsewhere are not taken for slivers along a chord (taken so: 3 or 4 flipped
// triangles of 8 to 10 on levels 0 to 2, and 161 over nist_ctc_04's coarse levels).
TEST(CollapsedSurface, ATriangleFromAnApexAcrossAChordIsSplitWhenFlipped) {
  auto model = test::loadTestData("drill_point_cone_beside_a_far_cube.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  ASSERT_GT(t->schedule()[0].chordal, 14.0);
  for (int k = 0; k <= t->lastLevel(); ++k) {
    const FaceQuality q = measureFaces(*t, k).at(0);
    EXPECT_GT(q.triangles, 0u) << "level " << k;
    EXPECT_EQ(q.flipped, 0u) << "level " << k;
  }
}

}  // namespace
}  // namespace cetview::brep
