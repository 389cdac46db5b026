// How a triangle faces against its corners' surface normals (measure_impl.h triangleFacing): the
// classification behind FaceQuality's degenerate, flipped and flippedAcrossFolds counts and the
// bench's cetview_flipped and cetview_flipped_across_folds.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "measure_impl.h"

namespace cetview::brep {
namespace {

// A right triangle in the plane z = 0, counter-clockwise seen from +z, and its corners' normals.
struct Triangle {
  std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::uint32_t corner[3] = {0, 1, 2};
  TriangleFacing facing() const { return triangleFacing(positions.data(), normals.data(), corner); }
  void setNormal(int c, float x, float y, float z) {
    normals[3 * c] = x, normals[3 * c + 1] = y, normals[3 * c + 2] = z;
  }
};

TEST(TriangleFacing, AlongItsCornersNormalsIsFacing) {
  Triangle t;
  EXPECT_EQ(t.facing(), TriangleFacing::kFacing);
  t.setNormal(1, 0.6f, 0, 0.8f);  // spread within 90 degrees
  EXPECT_EQ(t.facing(), TriangleFacing::kFacing);
}

TEST(TriangleFacing, AgainstAgreeingNormalsIsAnOrientationError) {
  Triangle t;
  std::swap(t.corner[1], t.corner[2]);  // clockwise from +z
  EXPECT_EQ(t.facing(), TriangleFacing::kFlipped);
  t.setNormal(0, 0.6f, 0, 0.8f);  // still no two corners more than 90 degrees apart
  EXPECT_EQ(t.facing(), TriangleFacing::kFlipped);
}

TEST(TriangleFacing, AgainstOpposingNormalsIsAcrossAFold) {
  Triangle t;
  t.setNormal(0, 0, 0, -1);  // two corners on the far side of a fold: their sum points down
  t.setNormal(1, 0, 0, -1);
  EXPECT_EQ(t.facing(), TriangleFacing::kFlippedAcrossFold);
  // Opposing normals alone are not a flip: with their sum along the facet it faces.
  t.setNormal(1, 0, 0, 1);
  t.setNormal(2, 0, 0.6f, 0.8f);
  EXPECT_EQ(t.facing(), TriangleFacing::kFacing);
}

TEST(TriangleFacing, NoAreaIsDegenerateWhateverTheNormals) {
  Triangle t;
  t.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0};  // corners on one line
  EXPECT_EQ(t.facing(), TriangleFacing::kDegenerate);
  t.setNormal(0, 0, 0, -1);
  EXPECT_EQ(t.facing(), TriangleFacing::kDegenerate);
}

}  // namespace
}  // namespace cetview::brep
