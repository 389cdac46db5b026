// cetview bench's triangle account over the faces where BRepMesh keeps its promise: on a box every
// face is kept and the account is the whole mesh; on occt-misc's Ball, where BRepMesh misses the
// deflection on its two sphere faces (1.6x and 1.9x) and the angle on its B-spline fillets, those
// faces are left out of both sides. The deviation measure on spheres is exact. And the triangle
// goal on the occt-misc models where a rule of the edges or the refinement brought it in reach.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>

#include "brep/bench.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

BenchOptions oneTenthPercent() {
  BenchOptions options;
  options.params = test::relative(0.001);
  options.threads = 2;
  return options;
}

// The bench at 0.1% on an occt-misc sample model (a path under its data folder); none when
// occt-misc is not installed.
std::optional<BenchResult> benchSample(const std::string& file) {
  const std::string path = std::string(CETVIEW_OCCT_DATA) + "/" + file;
  if (!std::filesystem::exists(path)) return std::nullopt;
  return benchModel(path, oneTenthPercent());
}
#define SKIP_WITHOUT_SAMPLES(r) \
  if (!(r)) GTEST_SKIP() << "occt-misc sample models not installed at " << CETVIEW_OCCT_DATA

// The run succeeded and cetview kept both tolerances on every face, the ground on which its
// triangle count is compared with BRepMesh's; false (and the test failed) when the run failed.
bool keptBothTolerances(const BenchResult& r) {
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.cetview_faces_over + r.cetview_faces_over_angle, 0u);
  return r.error.empty();
}

TEST(BenchKept, EveryFaceOfABoxIsKept) {
  const std::string path = test::tempPath("box.brep");
  ASSERT_TRUE(BRepTools::Write(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), path.c_str()));
  const BenchResult r = benchModel(path, oneTenthPercent());
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.brepmesh_faces_over + r.brepmesh_faces_over_angle, 0u);
  EXPECT_EQ(r.cetview_triangles, 12u);
  EXPECT_EQ(r.cetview_triangles_kept, r.cetview_triangles);
  EXPECT_EQ(r.brepmesh_triangles_kept, r.brepmesh_triangles);
}

TEST(BenchKept, FacesBRepMeshMissesAreLeftOut) {
  const std::optional<BenchResult> sample = benchSample("occ/Ball.brep");
  SKIP_WITHOUT_SAMPLES(sample);
  const BenchResult& r = *sample;
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_GT(r.brepmesh_faces_over, 0u);
  ASSERT_GT(r.brepmesh_faces_over_angle, 0u);
  EXPECT_GT(r.brepmesh_triangles_kept, 0u);
  EXPECT_LT(r.brepmesh_triangles_kept, r.brepmesh_triangles);
  EXPECT_GT(r.cetview_triangles_kept, 0u);
  EXPECT_LT(r.cetview_triangles_kept, r.cetview_triangles);
}

// The measure on elementary surfaces is the exact distance (the largest over each triangle on
// planes, cylinders and spheres; closed-form distances of the samples on cones and tori), not a
// Gauss-Newton projection that overstates where it does not converge. BRepMesh keeps the deflection
// on all four of fuse's sphere patches (at most 0.72 of it); the projection read one of them at 14x.
TEST(BenchKept, SpherePatchesAreMeasuredExactly) {
  const std::optional<BenchResult> sample = benchSample("occ/fuse.brep");
  SKIP_WITHOUT_SAMPLES(sample);
  const BenchResult& r = *sample;
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.brepmesh_faces_over, 0u);
  EXPECT_LE(r.brepmesh_max_dev, r.deflection);
  EXPECT_GT(r.brepmesh_max_dev, 0.5 * r.deflection);  // a measure, not a zero
  EXPECT_EQ(r.brepmesh_triangles_kept, r.brepmesh_triangles);
}

// Edges beside a B-spline fillet: the tall triangle standing on a segment may miss the angle a
// little where the low ones keep it, so the edge is not halved for the fillet's sake (Ball's
// cylinder took 128 segments on the edge it shares with its fillet, BRepMesh 30). Ball: no more
// triangles than BRepMesh on the faces where BRepMesh keeps both tolerances (546 against 567; 618
// before); bearing: no more on the whole model (12240 against 12285; 13184 before). cetview keeps
// both tolerances on every face of both. (The rule's guards, a narrow torus along a long chord on
// Top.brep and a terrain twisting near its boundary on MAT.brep, are held by the sample models'
// angle checks at 1%.)
TEST(BenchKept, FilletNeighboursTakeNoMoreThanBRepMesh) {
  for (const char* file : {"occ/Ball.brep", "iges/bearing.iges"}) {
    SCOPED_TRACE(file);
    const std::optional<BenchResult> sample = benchSample(file);
    SKIP_WITHOUT_SAMPLES(sample);
    const BenchResult& r = *sample;
    if (!keptBothTolerances(r)) continue;
    EXPECT_LE(r.cetview_triangles_kept, r.brepmesh_triangles_kept);
    if (std::string(file) == "iges/bearing.iges") {
      EXPECT_LE(r.cetview_triangles, r.brepmesh_triangles);
    }
  }
}

// Spheres: refinement splits at circumcentres (or, in an obtuse triangle, on its longest edge), and
// circles on spheres take equal segments. CylinderHead (a block with a hemispherical dome in two
// lunes, BRepMesh within both tolerances on every face) took 1172 triangles against BRepMesh's 1164
// with centroid splits and halved circles; fuse's four sphere patches take 882 against 1171.
TEST(BenchKept, SpheresTakeNoMoreThanBRepMesh) {
  const std::optional<BenchResult> sample = benchSample("occ/CylinderHead.rle");
  SKIP_WITHOUT_SAMPLES(sample);
  const BenchResult& r = *sample;
  if (!keptBothTolerances(r)) return;
  EXPECT_EQ(r.brepmesh_faces_over + r.brepmesh_faces_over_angle, 0u);  // the same tolerances kept
  EXPECT_LE(r.cetview_triangles, r.brepmesh_triangles);
  const std::optional<BenchResult> fuse = benchSample("occ/fuse.brep");
  ASSERT_TRUE(fuse);
  if (!keptBothTolerances(*fuse)) return;
  EXPECT_LE(fuse->cetview_triangles_kept, fuse->brepmesh_triangles_kept);
}

// A sphere's scaled UV is conformal (Mercator), so Delaunay triangles are well shaped on it at every
// latitude. With one scale each way a whole sphere of radius 10 took 2984 triangles at 0.1% against
// BRepMesh's 2836, and Ball (two sphere faces of 2870 and 1765 triangles) 9674 against 9209 in all.
TEST(BenchKept, WholeSphereTakesFewerTrianglesThanBRepMesh) {
  const std::string path = test::tempPath("sphere.brep");
  ASSERT_TRUE(BRepTools::Write(BRepPrimAPI_MakeSphere(10).Shape(), path.c_str()));
  const BenchResult r = benchModel(path, oneTenthPercent());
  if (keptBothTolerances(r)) {
    EXPECT_LE(r.cetview_triangles, r.brepmesh_triangles);
  }
  const std::optional<BenchResult> ball = benchSample("occ/Ball.brep");
  SKIP_WITHOUT_SAMPLES(ball);
  if (keptBothTolerances(*ball)) {
    EXPECT_LE(ball->cetview_triangles, ball->brepmesh_triangles);
  }
}

}  // namespace
}  // namespace cetview::brep
