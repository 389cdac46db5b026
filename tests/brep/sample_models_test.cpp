// Every sample model of Debian's occt-misc: models with faces pass every check at 1% (and the smaller
// ones at 0.1%); models without faces are refused with a clear error.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Shape.hxx>

#include "brep/measure.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

std::vector<std::string> sampleModels() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const char* dir : {"occ", "step", "iges"}) {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(CETVIEW_OCCT_DATA) + "/" + dir, ec)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".brep" || ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs")
        out.push_back(entry.path().string());
    }
  }
  std::sort(out.begin(), out.end());
  if (out.empty()) out.push_back("");  // one skipped instance when occt-misc is not installed
  return out;
}

class SampleModel : public ::testing::TestWithParam<std::string> {};

TEST_P(SampleModel, KeepsThePromise) {
  if (GetParam().empty()) GTEST_SKIP() << "occt-misc sample models not installed at " << CETVIEW_OCCT_DATA;
  LoadResult r = loadModel(GetParam());
  if (!r) {
    // The only refusals allowed among the samples: files with curves but no face.
    EXPECT_NE(r.error.find("no B-rep faces"), std::string::npos) << r.error;
    return;
  }
  const Model& m = *r.model;
  // Several samples are compounds of touching or overlapping solids: self-intersection within faces.
  test::CheckOptions options;
  options.acrossFaces = false;
  // Known open issue: on Top 318 at 1% (one level) a triangle next to the boundary stays flipped,
  // standing edge-on to its corners' normals (|cosine| < 5e-4: its sign moved with the last bits of
  // the evaluator's polynomial patches) in the corner next to the pole its v = 0 row collapses
  // into. Everything else is checked. (Bottom 181 and 191, shell1 38 and Motor-c 47, 49, 52, 54
  // were on this list until the normals on degenerate rows counted as singular and the pole rows
  // were split with each level; the bottle's neck, face 3, on coarse levels until the edges
  // checked the triangle reaching across a narrow face.)
  const std::string file = GetParam().substr(GetParam().find_last_of('/') + 1);
  if (file == "Top.brep") options.knownFlips = {318};
  // Every face keeps the angle. (Bottom's face 69 turned by 20.3 degrees at 1% until the
  // thirty-seventh session: its boundary chord bulged past every point that would split an edge
  // into the fillet, now halved where the fillet's first row cannot stand on it; Ball 11 and 12,
  // Bottom 318 and 319 and MAT 0 were on the list of known angle misses before.)
  test::tessellateAndCheck(m, test::relative(0.01), options);
  std::size_t triangles = 0;
  {
    auto t = Tessellator::create(m, test::relative(0.01)).tessellator;
    t->run(2, {}, nullptr, 0);
    triangles = t->triangleCount(0);
  }
  // 0.1% where the coarse level stays small (CI time); the big ones run in the bench.
  options.selfIntersection = false;
  if (triangles < 20000) test::tessellateAndCheck(m, test::relative(0.001), options);
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.empty() ? "none" : info.param.substr(std::string(CETVIEW_OCCT_DATA).size() + 1);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(OcctMisc, SampleModel, ::testing::ValuesIn(sampleModels()), testName);

// At 1% of their boxes the 20-degree angle binds on these models' tubes, fillets and lofted skins,
// which take the steps the tolerances allow (fifty-third session): at or under BRepMesh's
// triangles at the same deflection and angle. Before, Ball took 5592 against 4215, Bottom 19812
// against 18824, Pump_TopCover 2892 against 2834, wing 440 against 298; now 3212, 17154, 2168, 70.
TEST(OcctMiscCounts, AngleBoundModelsAtOnePercentTakeNoMoreTrianglesThanBRepMesh) {
  for (const char* file : {"occ/Ball.brep", "occ/Bottom.brep", "occ/Pump_TopCover.brep", "occ/wing.brep"}) {
    SCOPED_TRACE(file);
    const std::string path = std::string(CETVIEW_OCCT_DATA) + "/" + file;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "occt-misc sample models not installed at " << CETVIEW_OCCT_DATA;
    TopoDS_Shape shape;
    BRep_Builder builder;
    ASSERT_TRUE(BRepTools::Read(shape, path.c_str(), builder));
    LoadResult r = loadModel(path);
    ASSERT_TRUE(r) << r.error;
    auto t = test::tessellate(*r.model, test::relative(0.01));
    ASSERT_TRUE(t);
    const std::size_t grid = test::brepMeshTriangles(shape, t->chordal());
    ASSERT_GT(grid, 0u);
    EXPECT_LE(t->triangleCount(t->lastLevel()), grid);
  }
}

// Flip checks on single occt-misc models, each meshed at 0.1% (or `fraction`) on two threads
// (skipped when occt-misc is not installed).
class OcctMiscFlips : public ::testing::Test {
 protected:
  void mesh(const std::string& file, double fraction = 0.001) {
    const std::string path = std::string(CETVIEW_OCCT_DATA) + "/" + file;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "occt-misc sample models not installed at " << CETVIEW_OCCT_DATA;
    LoadResult r = loadModel(path);
    ASSERT_TRUE(r) << r.error;
    model_ = std::move(r.model);
    tessellator_ = Tessellator::create(*model_, test::relative(fraction)).tessellator;
    ASSERT_TRUE(tessellator_ && tessellator_->run(2));
  }
  void expectNoFlippedTriangleOnAnyLevel() const {
    for (int k = 0; k <= tessellator_->lastLevel(); ++k) EXPECT_EQ(countFlipped(*tessellator_, k), 0u) << "level " << k;
  }
  std::unique_ptr<Model> model_;  // outlives the tessellator, which refers to it
  std::unique_ptr<Tessellator> tessellator_;
};

// The bench's flip count over a level (countFlipped: no surface measures) is the per-face measure's
// sum, and so is its count across folds: on a fuzzed face whose coarse and final levels keep
// flipped triangles, most of them across folds of its parametrisation by a pole.
TEST(FlipCounts, CountFlippedIsThePerFaceMeasuresSum) {
  auto model = test::loadTestData("uneven_pole_walk.brep");
  ASSERT_TRUE(model);
  auto t = test::tessellate(*model, test::relative(0.001));
  ASSERT_TRUE(t);
  std::size_t flipped = 0, folds = 0;
  for (int k = 0; k <= t->lastLevel(); ++k) {
    std::size_t perFace = 0, perFaceAcrossFolds = 0, acrossFolds = 0;
    for (const FaceQuality& q : measureFaces(*t, k, 2)) perFace += q.flipped, perFaceAcrossFolds += q.flippedAcrossFolds;
    EXPECT_EQ(countFlipped(*t, k, &acrossFolds), perFace) << "level " << k;
    EXPECT_EQ(acrossFolds, perFaceAcrossFolds) << "level " << k;
    flipped += perFace, folds += acrossFolds;
  }
  EXPECT_GT(folds, 0u);
  EXPECT_GT(flipped, folds);
}

// occ/Propeller.rle at 0.1%: the blade tips are B-spline patches pinched to a thin edge, whose
// parametrisation folds there (corner normals 100-170 degrees apart). A flipped triangle whose
// corners' normals agree is an orientation error however small: level 1 left one 0.98 long on each
// blade (its minimum size 1.09, under which nothing was split for orientation). The triangles
// across the folds stayed flipped (1 on the last level, 12 on coarser ones) until the folds had
// vertices of their own, one for each side (FaceMesher::foldPoint). Every level must be clean.
TEST_F(OcctMiscFlips, BladeTipsHaveNoFlippedTriangle) {
  mesh("occ/Propeller.rle");
  if (IsSkipped() || HasFatalFailure()) return;
  expectNoFlippedTriangleOnAnyLevel();
}

// occ/Axis_of_bearing.brep at 0.01%: its balls are full spheres, a seam from pole to pole. On
// level 1 two points split for the chordal tolerance fell on opposite sides of a pole, on one great
// circle, and the triangle they made with the pole stood edge-on across it (a sliver the measure
// reads as flipped, on six balls and again on level 2). Every point that would split it lay past
// the pole in 3D, which the seam chord into the pole (its zone in the scaled UV reaching round the
// pole) took for behind its line. Every level must be clean.
TEST_F(OcctMiscFlips, ABallsPoleLeavesNoSliverAcrossIt) {
  mesh("occ/Axis_of_bearing.brep", 0.0001);
  if (IsSkipped() || HasFatalFailure()) return;
  expectNoFlippedTriangleOnAnyLevel();
}

// occ/terrain.brep at 0.1%: one B-spline face whose u = max side rises as a rim, its normal turning
// 70-120 degrees within 20 units of a side 8000 long. A standing triangle's apex half a chord away
// passed level 1's angle by a hair while every point nearer the chord failed it, so the face mesher
// crept towards the chord and left slivers a hair inside the boundary: 100 flipped triangles on
// each of levels 1-4 before the edges checked lower apexes too. Every level must be clean.
TEST_F(OcctMiscFlips, TerrainsRimLeavesNoSlivers) {
  mesh("occ/terrain.brep");
  if (IsSkipped() || HasFatalFailure()) return;
  ASSERT_GE(tessellator_->lastLevel(), 4);
  expectNoFlippedTriangleOnAnyLevel();
}

// occ/Bottom.brep at 0.1%: two corner blends (B-spline patches pinched to a side 0.47 long) bend
// sharply at level 0 (2.8 wide there): a triangle fanning from the pinched corner stood flipped, its
// centroid and edge midpoints all inside a neighbouring chord's clearance. A flipped triangle's
// split now slides along the edge it bisects and may stand inside the clearance where its facet on
// the chord faces the surface's way, as a split for the angle may. Every level must be clean.
TEST_F(OcctMiscFlips, CornerBlendsAreNotFlippedOnCoarseLevels) {
  mesh("occ/Bottom.brep");
  if (IsSkipped() || HasFatalFailure()) return;
  expectNoFlippedTriangleOnAnyLevel();
}

// occ/Top.brep at 0.1%: eight corner blends like Bottom's curl so far at level 0 that the far side
// of the patch lies behind a boundary chord 3.1 long: every split point of the triangle fanning from
// the pinched corner was behind it (one flipped triangle on each blend). The edges now halve a
// segment whose face curls behind its chord. Every level must be clean.
TEST_F(OcctMiscFlips, CurledCornerBlendsHalveTheirChords) {
  mesh("occ/Top.brep");
  if (IsSkipped() || HasFatalFailure()) return;
  expectNoFlippedTriangleOnAnyLevel();
}

}  // namespace
}  // namespace cetview::brep
