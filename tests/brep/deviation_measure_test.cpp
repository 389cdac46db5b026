// The deviation measure (measure_impl.h) on rational patches with wild weights, as face_fuzz wrote
// them (tests/brep/data): their parametrisation runs so unevenly that a sample's interpolated (u, v)
// can lie beyond another local minimum of its distance, and projections from there stall short of
// the foot. The measure then also starts from the surface point nearest to the sample among a grid
// over the triangle's (u, v). Before, boundary chords lying on the surface read 3.6x
// (uneven_rational_a.brep, level 0), 2.5x (uneven_rational_b.brep, level 1) and 11x to 183x on
// every level but the last (uneven_pole_walk.brep, face_fuzz's corpus input pole_subnormal_walk,
// whose corner sits at a subnormal v) the level's tolerance.
#include <gtest/gtest.h>

#include <ostream>

#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
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
  auto t = test::tessellate(*model, test::relative(GetParam().deflection, GetParam().angleDeg));
  ASSERT_TRUE(t);
  test::expectEveryLevelWithinTolerance(*t, 0);
}

INSTANTIATE_TEST_SUITE_P(FuzzedFaces, UnevenRationalPatch,
                         testing::Values(UnevenPatch{"uneven_rational_a.brep", 0.0034381443112038895, 46.451209277485312},
                                         UnevenPatch{"uneven_rational_b.brep", 0.00022715833633490608, 40.050278477149611},
                                         UnevenPatch{"uneven_pole_walk.brep", 0.00054744222549954612, 54.084153505760284}));

}  // namespace
}  // namespace cetview::brep
