// The deviation measure (measure_impl.h) on free-form surfaces, where the samples are projected
// iteratively: it may read above the true distance (it is an upper bound), but not by more than its
// projections fail to converge. Checked against OpenCASCADE's global projection (Extrema).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "measure_impl.h"

namespace cetview::brep {
namespace {

// A flat ruled sheet in the plane y = 0 whose two quadratic rows fold back in x (3987 -> 2459 ->
// 3193, and 4088 -> 3209 -> 2797): the parametrisation folds the sheet over itself. A fuzzed face
// of this shape read 6x its true deviation through Gauss-Newton steps from the samples' UV.
Handle(Geom_BSplineSurface) foldedSheet() {
  const double x[2][3] = {{3987, 2459, 3193}, {4088, 3209, 2797}}, z[3] = {0, 116, 233};
  TColgp_Array2OfPnt poles(1, 2, 1, 3);
  for (int i = 1; i <= 2; ++i)
    for (int j = 1; j <= 3; ++j) poles.SetValue(i, j, gp_Pnt(x[i - 1][j - 1], 0, z[j - 1]));
  TColStd_Array1OfReal uKnots(1, 2), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, 2), vMults(1, 2);
  uKnots(1) = vKnots(1) = 0, uKnots(2) = vKnots(2) = 1;
  uMults(1) = uMults(2) = 2, vMults(1) = vMults(2) = 3;
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 1, 2);
}

// The measure's 13 samples of the flat triangle, each at its true (global) distance to the surface.
double extremaDeviation(const Handle(Geom_Surface)& surface, const std::vector<double>& positions) {
  static const double kSamples[13][3] = {
      {1.0 / 3, 1.0 / 3, 1.0 / 3}, {.75, .25, 0}, {.5, .5, 0}, {.25, .75, 0}, {0, .75, .25}, {0, .5, .5}, {0, .25, .75},
      {.25, 0, .75}, {.5, 0, .5}, {.75, 0, .25}, {.5, .25, .25}, {.25, .5, .25}, {.25, .25, .5}};
  double worst = 0;
  for (const auto& b : kSamples) {
    gp_XYZ m(0, 0, 0);
    for (int i = 0; i < 3; ++i) m += b[i] * gp_XYZ(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    GeomAPI_ProjectPointOnSurf projection(gp_Pnt(m), surface);
    EXPECT_GT(projection.NbPoints(), 0);
    if (projection.NbPoints() > 0) worst = std::max(worst, projection.LowerDistance());
  }
  return worst;
}

TEST(DeviationMeasure, ReachesTheFootAcrossAFoldedSheet) {
  const Handle(Geom_BSplineSurface) surface = foldedSheet();
  const SurfaceEval eval(BRepBuilderAPI_MakeFace(surface, 1e-7).Face());
  // Triangles with corners on the surface, some across the fold (the first is the fuzzed face's).
  const double corners[][6] = {{0, 0.25, 1, 0, 1, 0.5}, {0, 0, 1, 0.5, 0, 1}, {0.2, 0.1, 0.9, 0.6, 0.3, 0.9},
                               {1, 0.25, 0, 0.5, 1, 0.75}};
  for (const auto& c : corners) {
    std::vector<double> uv(c, c + 6), positions;
    for (int i = 0; i < 3; ++i) {
      const gp_Pnt p = surface->Value(uv[2 * i], uv[2 * i + 1]);
      positions.insert(positions.end(), {p.X(), p.Y(), p.Z()});
    }
    const std::uint32_t idx[3] = {0, 1, 2};
    const double measured = measureDeviation(eval, positions.data(), uv.data(), idx, 1);
    const double truth = extremaDeviation(surface, positions);
    SCOPED_TRACE("corners (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ") (" + std::to_string(c[2]) + ", " +
                 std::to_string(c[3]) + ") (" + std::to_string(c[4]) + ", " + std::to_string(c[5]) + ")");
    EXPECT_GE(measured, truth * (1 - 1e-9) - 1e-9) << "the measure is an upper bound";
    EXPECT_LE(measured, truth * 1.01 + 1e-6) << "Extrema: " << truth;
  }
}

}  // namespace
}  // namespace cetview::brep
