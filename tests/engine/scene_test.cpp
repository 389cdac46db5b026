// Scene bookkeeping without a GPU: ids, argument checks, bounds, and what counts as pending.
#include <gtest/gtest.h>

#include <glm/ext/matrix_transform.hpp>

#include "engine/scene.h"

namespace cetview::test {
namespace {

using namespace engine;

std::vector<MeshVertex> square() {
  return {{{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{1, 1, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
}

TEST(SceneTest, PartsReserveConsecutiveIds) {
  Scene scene;
  PartRange a = scene.addPart(3, 2);
  PartRange b = scene.addPart(5, 0, Color8{1, 2, 3, 255});
  EXPECT_EQ(toIndex(a.part), 0u);
  EXPECT_EQ(toIndex(b.part), 1u);
  EXPECT_EQ(toIndex(b.firstFace), 3u);
  EXPECT_EQ(toIndex(b.face(4)), 7u);
  EXPECT_EQ(toIndex(b.firstEdge), 2u);
  EXPECT_EQ(scene.faceCount(), 8u);
  EXPECT_EQ(scene.edgeCount(), 2u);
  EXPECT_EQ(scene.faceColor(b.face(0)), (Color8{1, 2, 3, 255}));
}

TEST(SceneTest, RejectsBadArgumentsWithOneLineReasons) {
  Scene scene;
  PartRange part = scene.addPart(1, 1);
  auto vertices = square();
  scene.appendVertices(vertices.data(), vertices.size());
  const std::uint32_t tri[] = {0, 1, 2};
  const std::uint32_t bad[] = {0, 1, 4};
  EXPECT_TRUE(scene.setFaceIndices(part.face(0), tri, 3).ok());
  auto outOfRange = scene.setFaceIndices(part.face(0), bad, 3);
  ASSERT_FALSE(outOfRange.ok());
  EXPECT_EQ(outOfRange.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(outOfRange.error().message.find("index 4"), std::string::npos);
  EXPECT_FALSE(scene.setFaceIndices(part.face(0), tri, 2).ok());
  EXPECT_FALSE(scene.setFaceIndices(FaceId{7}, tri, 3).ok());
  EXPECT_FALSE(scene.setEdgePolyline(EdgeId{1}, nullptr, 0).ok());
  EXPECT_FALSE(scene.setFaceColor(FaceId{1}, Color8{}).ok());
  EXPECT_FALSE(scene.addInstance(PartId{3}).ok());
  EXPECT_FALSE(scene.setInstanceVisible(InstanceId{0}, false).ok());
}

TEST(SceneTest, OnlyTheLatestArrayOfAFaceIsPending) {
  Scene scene;
  PartRange part = scene.addPart(1, 0);
  auto vertices = square();
  scene.appendVertices(vertices.data(), vertices.size());
  std::uint64_t vertexBytes = 4 * sizeof(MeshVertex);
  EXPECT_EQ(scene.pendingBytes(), vertexBytes);
  const std::uint32_t two[] = {0, 1, 2, 0, 2, 3};
  const std::uint32_t one[] = {0, 1, 2};
  ASSERT_TRUE(scene.setFaceIndices(part.face(0), two, 6).ok());
  ASSERT_TRUE(scene.setFaceIndices(part.face(0), one, 3).ok());
  EXPECT_EQ(scene.pendingBytes(), vertexBytes + 3 * sizeof(std::uint32_t));
  EXPECT_TRUE(scene.uploadsPending());
}

TEST(SceneTest, BoundsCoverVisibleInstancesOfEachPart) {
  Scene scene;
  PartRange part = scene.addPart(1, 1);
  auto vertices = square();
  scene.appendVertices(vertices.data(), vertices.size());
  const std::uint32_t tri[] = {0, 1, 2};
  ASSERT_TRUE(scene.setFaceIndices(part.face(0), tri, 3).ok());
  EXPECT_TRUE(scene.bounds().empty());  // no instance yet
  auto first = scene.addInstance(part.part);
  auto second = scene.addInstance(part.part, glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)));
  ASSERT_TRUE(first.ok() && second.ok());
  Bounds b = scene.bounds();
  EXPECT_FLOAT_EQ(b.min.x, 0.0f);
  EXPECT_FLOAT_EQ(b.max.x, 11.0f);
  EXPECT_FLOAT_EQ(b.max.y, 1.0f);
  // An edge above the face grows the part's bounds.
  const float edge[] = {0, 0, 0, 0, 0, 5};
  ASSERT_TRUE(scene.setEdgePolyline(part.edge(0), edge, 2).ok());
  EXPECT_FLOAT_EQ(scene.bounds().max.z, 5.0f);
  ASSERT_TRUE(scene.setInstanceVisible(*second, false).ok());
  EXPECT_FLOAT_EQ(scene.bounds().max.x, 1.0f);
}

TEST(SceneTest, ClearForgetsEverything) {
  Scene scene;
  scene.addPart(2, 0);
  auto vertices = square();
  scene.appendVertices(vertices.data(), vertices.size());
  scene.clear();
  EXPECT_EQ(scene.faceCount(), 0u);
  EXPECT_EQ(scene.vertexCount(), 0u);
  EXPECT_FALSE(scene.uploadsPending());
}

}  // namespace
}  // namespace cetview::test
