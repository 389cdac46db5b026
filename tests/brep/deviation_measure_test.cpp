// The deviation measure (measure_impl.h) on rational patches with wild weights, as face_fuzz wrote
// them (tests/brep/data): their parametrisation runs so unevenly that a sample's interpolated (u, v)
// can lie beyond another local minimum of its distance, and projections from there stall short of
// the foot. The measure then also starts from the surface point nearest to the sample among a grid
// over the triangle's (u, v). Before, boundary chords lying on the surface read 3.6x
// (uneven_rational_a.brep, level 0), 2.5x (uneven_rational_b.brep, level 1) and 11x to 183x on
// every level but the last (uneven_pole_walk.brep, face_fuzz's corpus input pole_subnormal_walk,
// whose corner sits at a subnormal v) the level's tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomConvert.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax3.hxx>
#include <gp_Torus.hxx>

#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "measure_impl.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

struct UnevenPatch {
  const char* file;
  double deflection;  // relative, as the fuzzer drew it
  double angleDeg;
};
std::ostream& operator<<(std::ostream& out, const UnevenPatch& p) { return out << p.file; }

class UnevenRationalPatch : public testing::TestWithParam<UnevenPatch> {};

TEST_P(UnevenRationalPatch, EveryLevelMeasuresWithinItsTolerance) {
  auto model = test::loadTestData(GetParam().file);
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::fuzzed(GetParam().file, GetParam().deflection, GetParam().angleDeg));
  ASSERT_TRUE(t);
  test::expectEveryLevelWithinTolerance(*t, 0);
}

INSTANTIATE_TEST_SUITE_P(FuzzedFaces, UnevenRationalPatch,
                         testing::Values(UnevenPatch{"uneven_rational_a.brep", 0.0034381443112038895, 46.451209277485312},
                                         UnevenPatch{"uneven_rational_b.brep", 0.00022715833633490608, 40.050278477149611},
                                         UnevenPatch{"uneven_pole_walk.brep", 0.00054744222549954612, 54.084153505760284}));

// The measure's reading of the triangle with these corner parameters (corners on the surface),
// its finer seeds taken past `fineAbove`.
double measuredTriangle(const SurfaceEval& eval, const double uv[6], double fineAbove = INFINITY) {
  double positions[9];
  for (int i = 0; i < 3; ++i) {
    const gp_Pnt p = eval.point(uv[2 * i], uv[2 * i + 1]);
    positions[3 * i] = p.X(), positions[3 * i + 1] = p.Y(), positions[3 * i + 2] = p.Z();
  }
  const std::uint32_t idx[3] = {0, 1, 2};
  return measureDeviation(eval, positions, uv, idx, 1, fineAbove);
}

// The same on the first face of a test data file.
double measuredTriangle(const std::string& file, const double uv[6]) {
  const TopoDS_Face face = test::firstFace(file);
  EXPECT_FALSE(face.IsNull()) << file;
  if (face.IsNull()) return 1e300;
  return measuredTriangle(SurfaceEval(face), uv);
}

// wild_weights_across_a_tiny_span.brep (the CI fuzz seed's input 13) is a rational B-spline,
// periodic in u, with weights from 0.003 to 901 and a u span 7e-8 wide. A triangle of its level 0
// at 0.6% (tolerance 3.45e-4) has a corner inside that span, 0.01 from the other two. The measure
// read it 0.0036 (10.6x) with its corners in one order and 9e-6 in another: the nearest point of
// its coarse seed grid lay in another basin of the distance, and where the steps went from there
// hung on rounding. A grid of step 1/400 over its (u, v) finds the surface within 1.75e-4 of every
// sample. Past the tolerance the measure also seeds from a grid of step 1/64.
TEST(WildWeights, ATriangleAcrossATinySpanReadsAlikeInEveryCornerOrder) {
  const TopoDS_Face face = test::firstFace("wild_weights_across_a_tiny_span.brep");
  ASSERT_FALSE(face.IsNull());
  const SurfaceEval eval(face);
  const double corners[3][2] = {{0.067025128230357112, 96.700662441748761},
                                {0.066782831553266531, 95.913231052997162},
                                {0.091386026340667781, 96.154864008305054}};
  const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& o : orders) {
    const double uv[6] = {corners[o[0]][0], corners[o[0]][1], corners[o[1]][0],
                          corners[o[1]][1], corners[o[2]][0], corners[o[2]][1]};
    EXPECT_LT(measuredTriangle(eval, uv, 3.4453e-4), 1.75e-4)
        << "order " << o[0] << o[1] << o[2] << ": 0.0036 in two orders";
  }
}

// bilinear_collapsed_past_a_knot.brep (face_fuzz seed 707, input 253) is a bilinear B-spline patch
// whose side v = vmax runs straight to a point at the knot u = -999.99957142857 and stays there:
// past the knot every pole of that corner is one point. A zero-area triangle of its last level lies
// along that side (its corners on one line of (u, v), 1e-13 apart in v): two corners 1.3e-7 and
// 4.6e-7 of u before the knot, the third 7.1e-5 past it, on the point. In space it lies on the
// side, straight, so on the surface. Its interpolated starts, and every even step of the seed line
// but the first corner, lie past the knot on the point, where no step moves along u: it read
// 0.0085, 2.38x the level's tolerance of 0.00357.
TEST(CollapsedPastAKnot, AZeroAreaTriangleAlongTheSideMeasuresOnTheSide) {
  const TopoDS_Face face = test::firstFace("bilinear_collapsed_past_a_knot.brep");
  ASSERT_FALSE(face.IsNull());
  const double uv[6] = {-999.99957156397556, -999.99900000000025, -999.99957188849032,
                        -999.99900000000025, -999.99950000000001, -999.99900000000014};
  EXPECT_LT(measuredTriangle(SurfaceEval(face), uv), 1e-6) << "0.0085 with the seed line's even steps alone";
}

TEST(CollapsedPastAKnot, EveryLevelMeasuresWithinItsTolerance) {
  test::testDataEveryLevel("bilinear_collapsed_past_a_knot.brep",
                           test::fuzzed("bilinear_collapsed_past_a_knot.brep", 0.00023310095909219373, 29.250858319981688));
}

// seam_collapsed_past_a_knot.brep (face_fuzz seed 1818, input 213): a bilinear B-spline patch,
// periodic in u over 0.001 of parameter, every pole past the third row of v one point. Along the
// seam the surface runs straight from a pole to that point (v = -999.9995 to the knot -999.99933)
// and stays there. A zero-area triangle of levels 6 and 7 lies along the seam: its corners at
// v = -999.9995, 3e-9 of v before the knot and -999.999, all three on that straight run in space.
// A sample midway between the last two is as far from the seed before the knot as from those on
// the point past it, which was the nearest; no projection moves from there (the surface has no
// derivative), and it read 0.0279, 4.37x level 7's tolerance of 0.0064. The measure now also
// searches the line around the nearest seed by golden sections.
TEST(CollapsedPastAKnot, AZeroAreaTriangleAlongTheSeamMeasuresOnTheSeam) {
  const TopoDS_Face face = test::firstFace("seam_collapsed_past_a_knot.brep");
  ASSERT_FALSE(face.IsNull());
  const double uv[6] = {-999.99899999999991, -999.99933354482209, -999.9989999999998,
                        -999.9989999999998,  -999.9989999999998,  -999.9994999999999};
  EXPECT_LT(measuredTriangle(SurfaceEval(face), uv), 1e-6) << "0.0279 from the seeds alone";
}

TEST(CollapsedPastAKnot, ASeamAlongTheCollapseMeasuresWithinItsTolerance) {
  test::testDataEveryLevel("seam_collapsed_past_a_knot.brep",
                           test::fuzzed("seam_collapsed_past_a_knot.brep", 0.00010150801690357978, 47.501945525291831));
}

// seam_beside_tiny_spans.brep is a surface periodic in u whose last u spans, just before the seam,
// are a millionth wide: the surface turns sharply across the seam. A sample on a triangle's chord
// along the seam has its foot on the seam, a few millionths of v away from its interpolated start,
// but every Gauss-Newton and damped step also stepped across the seam into those spans, far from
// the sample, and the distance stayed where it started. The measure also takes damped steps held
// inside the face's parameter box, which slide along the seam instead.
TEST(SeamBesideTinySpans, AChordAlongTheSeamMeasuresItsDistanceToTheSeam) {
  // A triangle of the mesh at 0.0988% (level 3, tolerance 0.055): its first two corners on the
  // seam (u = 0), the third inside. Scanned along the seam in steps of 1.25e-9 of v, the surface
  // comes within 0.037 of the seam chord's midpoint; the measure read up to 0.0965 on the chord
  // (1.75x the level's tolerance).
  const double uv[6] = {2.22044604925e-16, -999.999, 0, -999.999125, 0.0416666666667, -999.9990625};
  EXPECT_LT(measuredTriangle("seam_beside_tiny_spans.brep", uv), 0.055)
      << "0.0965 when no step could stay by the seam";
}

TEST(SeamBesideTinySpans, EveryLevelMeasuresWithinItsTolerance) {
  test::testDataEveryLevel("seam_beside_tiny_spans.brep", test::fuzzed("seam_beside_tiny_spans.brep", 0.00098784739829485782, 50.430075532158384));
}

// ellipse_past_the_knots.brep's first face is bounded by an ellipse reaching 0.18 of u and 0.54 of
// v past its B-spline surface's knots (spans 0.28 and 1 wide), where the surface is extrapolated:
// the mesh's corners lie on that extrapolation. Every projection stopped at the knots, and a
// sliver there read 134.5 (4.93x the level's tolerance of 27.3) where a dense grid over the
// extrapolated surface finds it 5.5 away; the measure's last damped steps may go as far as the
// triangle's own corners.
TEST(FacePastItsKnots, ATriangleOnTheExtrapolatedSurfaceMeasuresItsDistanceToIt) {
  const double uv[6] = {26.335810123503045, 849.70078483817008, 26.33725742236188, 849.71445272046481,
                        26.334362824644273, 849.68711695587581};
  EXPECT_LT(measuredTriangle("ellipse_past_the_knots.brep", uv), 27.3)
      << "134.5 when every step stopped at the knots";
}

TEST(FacePastItsKnots, EveryLevelMeasuresWithinItsTolerance) {
  test::testDataEveryLevel("ellipse_past_the_knots.brep", test::fuzzed("ellipse_past_the_knots.brep", 0.00056717801270646954, 34.027847714961467));
}

// sheet_folded_many_times_over_a_tiny_period.brep (face_fuzz seed 2121, input 102) is a B-spline
// sheet periodic in u over 0.001 of parameter (six spans), nearly all of its poles one point: the
// sheet folds over itself again and again within the period, and a point on it can lie on a part
// 0.0008 of u away from the part its triangle's corners are on. At 0.0433% (tolerance 0.135) a
// triangle of the last level, 4e-6 by 6e-5 in (u, v), read 0.2 (1.48x): no start over its own
// (u, v) reached the feet of its samples, which lie within 0.0012 of the surface elsewhere in the
// period (nor does the nearest point of a 1000 x 1000 grid over the face). Past the tolerance the
// measure also starts from the feet of the triangle's other samples.
TEST(SheetFoldedOverATinyPeriod, ATriangleMeasuresItsDistanceToTheSheetElsewhereInThePeriod) {
  const double uv[6] = {-999.99987852991057, -999.99931577296024, -999.9998831767856,
                        -999.99937461328284, -999.99988007886896, -999.99933520011382};
  const TopoDS_Face face = test::firstFace("sheet_folded_many_times_over_a_tiny_period.brep");
  ASSERT_FALSE(face.IsNull());
  EXPECT_LT(measuredTriangle(SurfaceEval(face), uv, 0.135), 0.01) << "0.2 from starts over the triangle alone";
}

TEST(SheetFoldedOverATinyPeriod, EveryLevelMeasuresWithinItsTolerance) {
  test::testDataEveryLevel("sheet_folded_many_times_over_a_tiny_period.brep",
                           test::absolute(0.13516312865484317, 33.896925307087812));
}

// zero_area_along_a_side.brep (face_fuzz seed 101, input 79): a rational patch whose u speed runs
// from 0.06 to 3e8, meshed at 0.2406%. Level 1 (tolerance 706) has triangles without area along its
// side u = 1, whose iso-line is a straight line in 3D that runs 20x faster near v = 0.36 than on
// average. The grid over such a triangle's (u, v) has only 17 distinct points along its one line,
// all beyond other local minima of the distance: one read 2160 (3.06x), where the triangle lies on
// the surface. The measure scans such triangles at as many points as a full grid has.
TEST(ZeroAreaAlongASide, ATriangleOnTheSideMeasuresItsDistanceToTheSide) {
  const double uv[6] = {0.99999999999999978, 0.36186550176886012, 0.99999999999999989,
                        0.19238185096072263, 0.99999999999999978, 0.36222043867013715};
  EXPECT_LT(measuredTriangle("zero_area_along_a_side.brep", uv), 0.2 * 706.269)
      << "2160 from 17 points along the side";
}

// A reading asked only whether triangles are within a bound (FaceMesher::measuredWithin, on the
// triangles whose splits would break a chord's clearance) stops once a sample is confirmed over
// it: over the bound exactly where the full reading is. Two triangles of a B-spline sphere, lifted
// 0.01 and 0.1 off it along its normal: a bound under the first one's distance stops within the
// first (each of a sample's readings confirms it over, the finest from 2145 surface points).
TEST(StoppedReading, IsOverItsBoundExactlyWhereTheFullReadingIs) {
  const Handle(Geom_Surface) sphere = GeomConvert::SurfaceToBSplineSurface(
      new Geom_RectangularTrimmedSurface(new Geom_SphericalSurface(gp_Ax3(), 10), 0, 1, -0.5, 0.5));
  const SurfaceEval eval(test::uvPolygonFace(sphere, {{0, -0.5}, {1, -0.5}, {1, 0.5}, {0, 0.5}}));
  const double uv[12] = {0.1, 0.1, 0.2, 0.1, 0.1, 0.2, 0.5, 0.0, 0.6, 0.0, 0.5, 0.1};
  const double lift[2] = {0.01, 0.1};
  std::vector<double> positions(18);
  for (int i = 0; i < 6; ++i) {
    gp_Pnt p;
    gp_Dir n;
    ASSERT_TRUE(eval.pointNormal(uv[2 * i], uv[2 * i + 1], p, n));
    const gp_Pnt q = p.Translated(gp_Vec(n) * lift[i / 3]);
    positions[3 * i] = q.X(), positions[3 * i + 1] = q.Y(), positions[3 * i + 2] = q.Z();
  }
  const std::uint32_t idx[6] = {0, 1, 2, 3, 4, 5};
  const double first = measureDeviation(eval, positions.data(), uv, idx, 1);
  const double full = measureDeviation(eval, positions.data(), uv, idx, 2);
  ASSERT_GT(first, 0.009);
  ASSERT_GT(full, 0.09);
  for (const double bound : {0.5 * first, 0.99 * first, 2 * first, 0.99 * full, full, 2 * full}) {
    const double stopped = measureDeviation(eval, positions.data(), uv, idx, 2, bound, bound);
    const double reading = measureDeviation(eval, positions.data(), uv, idx, 2, bound);
    EXPECT_EQ(stopped > bound, reading > bound) << "bound " << bound;
    if (reading <= bound) {
      EXPECT_EQ(stopped, reading) << "bound " << bound;
    }
  }
  // Stopped within the first triangle, short of the second one's distance.
  EXPECT_LE(measureDeviation(eval, positions.data(), uv, idx, 2, INFINITY, 0.5 * first), first);
}

// On a torus's outside a small flat triangle's distance to it is nearly a positive quadratic,
// peaking (in the metric of the torus's second fundamental form) at the circumcentre, which an
// acute triangle may hold between the grid's samples: this one (0, 0), (1, 0), (0.377, 0.6) in
// that metric, the grid's worst shape, read 0.958 of its deviation from the grid alone. The
// measure also samples the peak of the quadratic through the edges' middles (deviation_peak.h).
TEST(TorusTriangle, AnAcuteTriangleReadsItsPeak) {
  const double R = 10, r = 2;
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Torus(gp_Ax3(), R, r), 0, 1, -0.5, 0.5).Face();
  const SurfaceEval eval(face);
  // Near v = 0 the metric runs sqrt(R + r) per unit of u and sqrt(r) per unit of v.
  const double size = 0.1, mu = std::sqrt(R + r), mv = std::sqrt(r);
  const double corners[3][2] = {{0, 0}, {size, 0}, {0.377 * size, 0.6 * size}};
  double uv[6];
  for (int i = 0; i < 3; ++i) uv[2 * i] = 0.3 + corners[i][0] / mu, uv[2 * i + 1] = -0.02 + corners[i][1] / mv;
  gp_Pnt p[3];
  for (int i = 0; i < 3; ++i) p[i] = eval.point(uv[2 * i], uv[2 * i + 1]);
  // The triangle's deviation by brute force: a fine barycentric grid, the torus's distance in
  // closed form (its axis is z through the origin).
  double dense = 0;
  const int n = 300;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
      const gp_XYZ m = a * p[0].XYZ() + b * p[1].XYZ() + c * p[2].XYZ();
      dense = std::max(dense, std::abs(std::hypot(std::hypot(m.X(), m.Y()) - R, m.Z()) - r));
    }
  }
  ASSERT_GT(dense, 1e-4);
  const double measured = measuredTriangle(eval, uv);
  EXPECT_GE(measured, 0.999 * dense);
  EXPECT_LE(measured, 1.001 * dense);
}

}  // namespace
}  // namespace cetview::brep
