// cetview bench's triangle account over the faces where BRepMesh keeps its promise: on a box every
// face is kept and the account is the whole mesh; on occt-misc's fuse, where BRepMesh misses the
// deflection on some faces (up to 14x), those faces are left out of both sides.
#include <gtest/gtest.h>

#include <filesystem>

#include <BRepPrimAPI_MakeBox.hxx>
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
  const std::string path = std::string(CETVIEW_OCCT_DATA) + "/occ/fuse.brep";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "occt-misc sample models not installed at " << CETVIEW_OCCT_DATA;
  const BenchResult r = benchModel(path, oneTenthPercent());
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_GT(r.brepmesh_faces_over, 0u);
  EXPECT_GT(r.brepmesh_triangles_kept, 0u);
  EXPECT_LT(r.brepmesh_triangles_kept, r.brepmesh_triangles);
  EXPECT_GT(r.cetview_triangles_kept, 0u);
  EXPECT_LT(r.cetview_triangles_kept, r.cetview_triangles);
}

}  // namespace
}  // namespace cetview::brep
