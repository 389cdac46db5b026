// Progressive updates on a live renderer: a replaced face changes only its own part of the image,
// large changes spread over frames within the byte budget without ever showing half a face,
// buffers grow, visibility and colour toggles, the direct-draw path matches the indirect one and
// merges adjacent faces of one colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "engine/render_to_png.h"
#include "engine/warm_up.h"
#include "image_compare.h"
#include "render_fixture.h"
#include "test_meshes.h"

namespace cetview::test {
namespace {

using namespace engine;

constexpr std::uint32_t kSize = 256;
constexpr std::uint32_t kTopFace = 4;  // cube(): +Z side

class UpdateTest : public VulkanTest {
 protected:
  Renderer* load(const MeshData& mesh, RendererOptions options = {}) {
    Renderer* r = makeHeadless(kSize, kSize, options);
    if (r == nullptr) return nullptr;
    auto part = addMesh(r->scene(), mesh);
    EXPECT_TRUE(part.ok()) << part.error().message;
    return r;
  }

  RgbaImage shot(Renderer& r, const Camera& camera, const ViewStyle& style = {}) {
    auto image = r.capture(camera, style);
    EXPECT_TRUE(image.ok()) << image.error().message;
    return image.ok() ? *image : RgbaImage{};
  }
};

// Pixel-space box around the projections of `points`, grown by `margin` pixels.
struct PixelBox {
  float minX, minY, maxX, maxY;
  bool contains(std::uint32_t x, std::uint32_t y) const {
    return float(x) >= minX && float(x) <= maxX && float(y) >= minY && float(y) <= maxY;
  }
};

PixelBox project(const Camera& camera, float aspect, const std::vector<MeshVertex>& points, float margin) {
  glm::mat4 m = projectionMatrix(camera, aspect) * viewMatrix(camera);
  PixelBox box{1e9f, 1e9f, -1e9f, -1e9f};
  for (const MeshVertex& v : points) {
    glm::vec4 clip = m * glm::vec4(v.position[0], v.position[1], v.position[2], 1.0f);
    float x = (clip.x / clip.w * 0.5f + 0.5f) * kSize;
    float y = (clip.y / clip.w * 0.5f + 0.5f) * kSize;
    box = {std::min(box.minX, x), std::min(box.minY, y), std::max(box.maxX, x), std::max(box.maxY, y)};
  }
  return {box.minX - margin, box.minY - margin, box.maxX + margin, box.maxY + margin};
}

TEST_F(UpdateTest, ReplacingOneFaceChangesOnlyItsRegion) {
  MeshData mesh = cube(2.0f, 4);
  mesh.closedSolid = false;  // the replacement opens the box
  Renderer* r = load(mesh);
  ASSERT_NE(r, nullptr);
  Scene& scene = r->scene();
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
  RgbaImage before = shot(*r, camera);

  // The top face becomes a smaller square in its middle (new vertices, a different index count).
  std::vector<MeshVertex> inset;
  for (float x : {-0.5f, 0.5f}) {
    for (float y : {-0.5f, 0.5f}) inset.push_back({{x, y, 1.0f}, {0, 0, 1}});
  }
  std::uint32_t base = scene.appendVertices(inset.data(), inset.size());
  std::vector<std::uint32_t> indices = {base, base + 1, base + 3, base, base + 3, base + 2};
  ASSERT_TRUE(scene.setFaceIndices(FaceId{kTopFace}, indices.data(), indices.size()).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  RgbaImage after = shot(*r, camera);
  saveOutput(before, "update_before");
  saveOutput(after, "update_after");

  // The old top face's outline bounds every changed pixel (1.5 px for MSAA coverage at its rim).
  std::vector<MeshVertex> oldTop;
  for (std::uint32_t i : mesh.faces[kTopFace].indices) oldTop.push_back(mesh.vertices[i]);
  PixelBox region = project(camera, r->aspect(), oldTop, 1.5f);
  ImageDiff d = compareImages(before, after, 0);
  EXPECT_GT(d.differing, 1000u) << "the replacement should be visible";
  std::uint32_t outside = 0;
  for (std::uint32_t y = 0; y < kSize; ++y) {
    for (std::uint32_t x = 0; x < kSize; ++x) {
      if (region.contains(x, y)) continue;
      if (std::memcmp(before.at(x, y), after.at(x, y), 4) != 0) ++outside;
    }
  }
  EXPECT_EQ(outside, 0u) << "pixels changed outside the replaced face's region";
}

TEST_F(UpdateTest, LargeUploadSpreadsOverFramesAndNeverShowsHalfAFace) {
  MeshData mesh = sphere(1.0f, 48);  // 8 faces, ~1.3 MB of vertices and indices
  std::uint64_t trianglesPerFace = mesh.faces[0].indices.size() / 3;
  for (const MeshFace& f : mesh.faces) ASSERT_EQ(f.indices.size() / 3, trianglesPerFace);

  RendererOptions small;
  small.uploadBudgetBytes = 64u << 10;
  Renderer* r = load(mesh, small);
  ASSERT_NE(r, nullptr);
  Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  std::uint64_t total = r->scene().pendingBytes();
  int frames = 0;
  while (r->scene().uploadsPending()) {
    auto status = r->drawFrame(camera);
    ASSERT_TRUE(status.ok()) << status.error().message;
    const UploadStats& stats = r->lastUploadStats();
    EXPECT_LE(stats.bytes, small.uploadBudgetBytes);
    EXPECT_EQ(r->committedTriangles() % trianglesPerFace, 0u) << "half a face is drawn";
    ASSERT_LT(++frames, 200) << "uploads do not finish";
  }
  EXPECT_GE(std::uint64_t(frames), total / small.uploadBudgetBytes)
      << total << " bytes in " << frames << " frames";
  EXPECT_EQ(r->committedTriangles(), trianglesPerFace * mesh.faces.size());
  RgbaImage streamed = shot(*r, camera);

  Renderer* whole = load(mesh);
  ASSERT_NE(whole, nullptr);
  ASSERT_TRUE(whole->finishUploads().ok());
  EXPECT_EQ(whole->lastUploadStats().workLeft, false);
  RgbaImage direct = shot(*whole, camera);
  EXPECT_EQ(compareImages(streamed, direct, 0).differing, 0u);
}

TEST_F(UpdateTest, FacesSwitchOnlyWhenCompletelyUploaded) {
  MeshData mesh = sphere(1.0f, 40);
  std::uint64_t trianglesPerFace = mesh.faces[0].indices.size() / 3;
  RendererOptions small;
  small.uploadBudgetBytes = 64u << 10;
  Renderer* r = load(mesh, small);
  ASSERT_NE(r, nullptr);
  Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  ASSERT_TRUE(r->finishUploads().ok());
  ASSERT_EQ(r->committedTriangles(), trianglesPerFace * mesh.faces.size());

  // Replace one face by a far larger array (finer level): while it streams in, the old face
  // stays on screen unchanged; when done, the image is the fine one.
  RgbaImage coarse = shot(*r, camera);
  MeshData fine = sphere(1.0f, 160);
  std::vector<std::uint32_t> indices = fine.faces[1].indices;
  std::uint32_t first = *std::min_element(indices.begin(), indices.end());
  std::uint32_t last = *std::max_element(indices.begin(), indices.end());
  std::uint32_t base = r->scene().appendVertices(&fine.vertices[first], last - first + 1);
  for (std::uint32_t& i : indices) i = i - first + base;
  ASSERT_GT(indices.size() * 4, small.uploadBudgetBytes * 4);
  ASSERT_TRUE(r->scene().setFaceIndices(FaceId{1}, indices.data(), indices.size()).ok());
  int waiting = 0;
  for (;;) {
    RgbaImage frame = shot(*r, camera);
    if (r->lastUploadStats().facesCompleted > 0) break;
    ASSERT_EQ(compareImages(frame, coarse, 0).differing, 0u)
        << "frame " << waiting << " shows a partial face";
    ASSERT_EQ(r->committedTriangles(), trianglesPerFace * mesh.faces.size());
    ASSERT_LT(++waiting, 400);
  }
  EXPECT_GT(waiting, 3);
  ASSERT_TRUE(r->finishUploads().ok());
  EXPECT_GT(compareImages(shot(*r, camera), coarse, 0).differing, 0u);
}

TEST_F(UpdateTest, BuffersGrowFromTinyCapacities) {
  MeshData mesh = lattice(7, 1.0f, 6);  // 343 faces: more than the initial table size
  append(mesh, sphere(2.0f, 24, glm::vec3(0.0f, 0.0f, 6.0f)));
  RendererOptions tiny;
  tiny.scene.initialVertexCapacity = 64;
  tiny.scene.initialIndexCapacity = 192;
  tiny.scene.initialEdgePointCapacity = 64;
  Renderer* r = load(mesh, tiny);
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  RgbaImage grown = shot(*r, camera);

  Renderer* roomy = load(mesh);
  ASSERT_NE(roomy, nullptr);
  ASSERT_TRUE(roomy->finishUploads().ok());
  EXPECT_EQ(compareImages(grown, shot(*roomy, camera), 0).differing, 0u);
}

TEST_F(UpdateTest, DirectDrawsMatchIndirectDraws) {
  // The goldens are drawn one call per face on lavapipe (the default on CPU devices); the
  // multi-draw indirect path must give the same picture.
  MeshData mesh = sphere(1.0f, 16);
  RendererOptions indirect;
  indirect.scene.indirectDrawsOnCpu = true;
  indirect.msaaSamples = 4;  // as the golden
  Renderer* r = load(mesh, indirect);
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->usesIndirectDraws()) << "the test must exercise the indirect path";
  EXPECT_FALSE(r->lastUploadStats().workLeft);
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, r->scene().bounds(), r->aspect());
  expectMatchesGolden(shot(*r, camera), "sphere_shaded_edges");
}

TEST_F(UpdateTest, IndirectDrawsOfPartsAfterTheFirstDrawOnlyTheirOwnFaces) {
  // Multi-draw indirect on a GPU (maxDrawIndirectCount 2^32 - 1): stepping the draw loop by that
  // limit wrapped round, so each instance of a part after the first also drew every face before
  // it, in its own transform. Three parts, the second twice: the picture must be the one-by-one
  // path's, with one face call and one edge call per instance.
  RgbaImage pictures[2];
  for (bool indirectDraws : {false, true}) {
    SCOPED_TRACE(indirectDraws ? "indirect" : "one by one");
    RendererOptions options;
    options.scene.indirectDraws = indirectDraws;
    options.scene.indirectDrawsOnCpu = true;
    Renderer* r = makeHeadless(kSize, kSize, options);
    ASSERT_NE(r, nullptr);
    ASSERT_EQ(r->usesIndirectDraws(), indirectDraws);
    Scene& scene = r->scene();
    ASSERT_TRUE(addMesh(scene, cube(1.0f, 2, glm::vec3(-1.5f, 0.0f, 0.0f))).ok());
    auto second = addMesh(scene, sphere(0.6f, 16));
    ASSERT_TRUE(second.ok());
    ASSERT_TRUE(addMesh(scene, cube(0.8f, 2, glm::vec3(1.5f, 0.0f, 0.0f))).ok());
    glm::mat4 above(1.0f);
    above[3] = glm::vec4(0.0f, 0.0f, 1.4f, 1.0f);
    ASSERT_TRUE(scene.addInstance(second->part, above).ok());
    ASSERT_EQ(scene.instanceCount(), 4u);
    ASSERT_TRUE(r->finishUploads().ok());
    Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
    pictures[indirectDraws] = shot(*r, camera);
    if (indirectDraws) {
      EXPECT_EQ(r->lastFaceDrawCalls(), 4u);
      EXPECT_EQ(r->lastEdgeDrawCalls(), 4u);
    }
  }
  const ImageDiff d = compareImages(pictures[0], pictures[1], 24);
  EXPECT_LE(d.differing, 20u) << d.differing << " pixels differ by more than 24 (largest " << d.maxDelta
                              << ")";
}

TEST_F(UpdateTest, AdjacentFacesOfOneColourAndAllEdgesAreDrawnInFewCalls) {
  // One-by-one draws (lavapipe's default) merge the faces whose index slots follow each other and
  // share a colour, and every edge of a part into one line list; with VK_EXT_multi_draw every run
  // of one colour is one call. The picture stays the same either way.
  MeshData box = cube(2.0f, 4);  // six faces, six colours, twelve edges
  box.closedSolid = false;       // every face drawn (no culling of back-facing faces)
  const Color8 first = box.faces[0].color;
  MeshData recoloured = box;  // faces 1 and 2 in face 0's colour from the start
  for (std::uint32_t f : {1u, 2u}) recoloured.faces[f].color = first;
  RgbaImage pictures[2][2];  // [multi-draw][six colours, merged]
  for (bool multiDraw : {false, true}) {
    SCOPED_TRACE(multiDraw ? "multi-draw" : "one call per run");
    RendererOptions options;
    options.scene.multiDraw = multiDraw;
    options.scene.indirectDraws = false;  // also on GPUs, which have multi-draw indirect
    Renderer* r = load(box, options);
    ASSERT_NE(r, nullptr);
    ASSERT_FALSE(r->usesIndirectDraws()) << "the test must exercise the one-by-one path";
    ASSERT_EQ(r->usesMultiDraw(), multiDraw) << "lavapipe has VK_EXT_multi_draw";
    Scene& scene = r->scene();
    ASSERT_TRUE(r->finishUploads().ok());
    Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
    RgbaImage sixColours = shot(*r, camera);
    EXPECT_EQ(r->lastFaceDrawCalls(), 6u);
    EXPECT_EQ(r->lastEdgeDrawCalls(), 1u);

    // Faces 1 and 2 take face 0's colour: one run of three, then faces 3, 4 and 5.
    for (std::uint32_t f : {1u, 2u}) ASSERT_TRUE(scene.setFaceColor(FaceId{f}, first).ok());
    ASSERT_TRUE(r->finishUploads().ok());
    RgbaImage merged = shot(*r, camera);
    EXPECT_EQ(r->lastFaceDrawCalls(), 4u);

    // A hidden face splits its run (two runs of one colour: one multi-draw call); an instance
    // colour ignores the face colours: one draw again.
    ASSERT_TRUE(scene.setFaceVisible(FaceId{1}, false).ok());
    ASSERT_TRUE(r->finishUploads().ok());
    (void)shot(*r, camera);
    EXPECT_EQ(r->lastFaceDrawCalls(), multiDraw ? 4u : 5u);
    ASSERT_TRUE(scene.setFaceVisible(FaceId{1}, true).ok());
    ASSERT_TRUE(scene.setInstanceColor(InstanceId{0}, Color8{200, 60, 60, 255}).ok());
    ASSERT_TRUE(r->finishUploads().ok());
    (void)shot(*r, camera);
    EXPECT_EQ(r->lastFaceDrawCalls(), 1u);
    ASSERT_TRUE(scene.setInstanceColor(InstanceId{0}, std::nullopt).ok());
    for (std::uint32_t f : {1u, 2u}) ASSERT_TRUE(scene.setFaceColor(FaceId{f}, box.faces[f].color).ok());
    ASSERT_TRUE(r->finishUploads().ok());
    EXPECT_EQ(compareImages(sixColours, shot(*r, camera), 0).differing, 0u);
    EXPECT_EQ(r->lastFaceDrawCalls(), 6u);

    // The merged draws look like the same colours given from the start (this replaces `r`).
    Renderer* reference = load(recoloured, options);
    ASSERT_NE(reference, nullptr);
    ASSERT_TRUE(reference->finishUploads().ok());
    EXPECT_EQ(compareImages(shot(*reference, camera), merged, 0).differing, 0u);
    pictures[multiDraw][0] = sixColours;
    pictures[multiDraw][1] = merged;
  }
  // Multi-draw (faces grouped by colour) gives the same pixels as slot order.
  EXPECT_EQ(compareImages(pictures[0][0], pictures[1][0], 0).differing, 0u);
  EXPECT_EQ(compareImages(pictures[0][1], pictures[1][1], 0).differing, 0u);
}

TEST_F(UpdateTest, HidingRecolouringAndClearing) {
  RendererOptions msaa4;
  msaa4.msaaSamples = 4;  // the end compares with a golden
  MeshData box = cube(2.0f, 4);
  box.closedSolid = false;  // hiding a face opens the box
  Renderer* r = load(box, msaa4);
  ASSERT_NE(r, nullptr);
  Scene& scene = r->scene();
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
  RgbaImage original = shot(*r, camera);

  ASSERT_TRUE(scene.setFaceVisible(FaceId{kTopFace}, false).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  RgbaImage hidden = shot(*r, camera);
  EXPECT_GT(compareImages(original, hidden, 0).differing, 1000u);

  ASSERT_TRUE(scene.setFaceVisible(FaceId{kTopFace}, true).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  EXPECT_EQ(compareImages(original, shot(*r, camera), 0).differing, 0u);

  ASSERT_TRUE(scene.setFaceColor(FaceId{kTopFace}, Color8{20, 200, 40, 255}).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  RgbaImage green = shot(*r, camera);
  // The top face's centre is now green.
  glm::mat4 m = projectionMatrix(camera, r->aspect()) * viewMatrix(camera);
  glm::vec4 c = m * glm::vec4(0, 0, 1, 1);
  auto x = static_cast<std::uint32_t>((c.x / c.w * 0.5f + 0.5f) * kSize);
  auto y = static_cast<std::uint32_t>((c.y / c.w * 0.5f + 0.5f) * kSize);
  const std::uint8_t* p = green.at(x, y);
  EXPECT_GT(p[1], p[0] + 60);
  EXPECT_GT(p[1], p[2] + 60);

  // Clear and load something else into the same renderer.
  scene.clear();
  auto part = addMesh(scene, sphere(1.0f, 16));
  ASSERT_TRUE(part.ok());
  ASSERT_TRUE(r->finishUploads().ok());
  Camera sphereCamera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
  expectMatchesGolden(shot(*r, sphereCamera), "sphere_shaded_edges");
}

TEST_F(UpdateTest, ClosedSolidsLookTheSameWithBackFacesCulled) {
  // Also checks that the test meshes keep their promise: counter-clockwise seen from outside.
  MeshData closed = sphere(1.0f, 16);
  append(closed, cube(1.0f, 3, glm::vec3(1.2f, -1.0f, 0.2f)));
  ASSERT_TRUE(closed.closedSolid);
  MeshData open = closed;
  open.closedSolid = false;
  glm::mat4 mirror(1.0f);
  mirror[0][0] = -1.0f;

  RendererOptions oneByOne;  // the path that leaves out back-facing clusters, also on GPUs
  oneByOne.scene.indirectDraws = false;
  // Without MSAA, as on lavapipe: with it, samples along a silhouette that no front triangle
  // covers take a back face's shade where the part is drawn two-sided (27 pixels on an H200).
  oneByOne.msaaSamples = 1;
  Renderer* r = load(closed, oneByOne);
  ASSERT_NE(r, nullptr);
  Scene& scene = r->scene();
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
  RgbaImage culled = shot(*r, camera);
  saveOutput(culled, "closed_culled");
  // The cube's three far sides (a cluster each) and the sphere's far octant (4 clusters of
  // kClusterTriangles), with parts of the octants next to it, face away as a whole: not drawn.
  EXPECT_GE(r->lastClustersCulled(), 7u);
  // Mirrored instances of a closed part are drawn two-sided, so they do not turn inside out.
  ASSERT_TRUE(scene.setInstanceTransform(InstanceId{0}, mirror).ok());
  RgbaImage culledMirror = shot(*r, camera);
  EXPECT_EQ(r->lastClustersCulled(), 0u);

  scene.clear();
  ASSERT_TRUE(addMesh(scene, open).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  EXPECT_LE(compareImages(culled, shot(*r, camera), 2).differing, 20u);
  ASSERT_TRUE(scene.setInstanceTransform(InstanceId{0}, mirror).ok());
  EXPECT_LE(compareImages(culledMirror, shot(*r, camera), 2).differing, 20u);
}

TEST_F(UpdateTest, FacesOutOfViewOrFacingAwayAreLeftOutWithoutChangingThePicture) {
  // One-by-one draws leave out faces outside the frustum and wholly back-facing faces of culled
  // solids (face_culling.h); indirect draws draw everything. Same pictures, close up and far, in
  // perspective and orthographic views.
  MeshData grid;
  for (int i = 0; i < 9; ++i)
    append(grid, sphere(1.0f, 8, glm::vec3(2.5f * float(i % 3), 2.5f * float(i / 3), 0.0f)));
  append(grid, cube(1.5f, 2, glm::vec3(2.5f, 2.5f, 2.0f)));
  ASSERT_TRUE(grid.closedSolid);
  Bounds all;
  for (const MeshVertex& v : grid.vertices) all.add(glm::vec3(v.position[0], v.position[1], v.position[2]));
  Bounds corner;  // the first sphere only: the others are out of view
  corner.add(glm::vec3(-1.0f));
  corner.add(glm::vec3(1.0f));
  std::vector<Camera> cameras;
  for (Projection projection : {Projection::kPerspective, Projection::kOrthographic}) {
    for (const Bounds& b : {all, corner}) {
      for (StandardView v : {StandardView::kIso, StandardView::kTop, StandardView::kFront}) {
        cameras.push_back(standardView(v, b, 1.0f, projection));
      }
    }
  }

  RendererOptions msaa4;
  msaa4.msaaSamples = 4;
  msaa4.scene.indirectDraws = false;  // one by one, also on GPUs
  Renderer* r = load(grid, msaa4);
  ASSERT_NE(r, nullptr);
  ASSERT_FALSE(r->usesIndirectDraws());
  ASSERT_TRUE(r->finishUploads().ok());
  std::vector<RgbaImage> culled;
  std::uint32_t culledFaces = 0;
  for (const Camera& camera : cameras) {
    culled.push_back(shot(*r, camera));
    culledFaces += r->lastClustersCulled();
  }
  EXPECT_GT(culledFaces, 100u);

  RendererOptions indirect = msaa4;
  indirect.scene.indirectDraws = true;
  indirect.scene.indirectDrawsOnCpu = true;
  Renderer* reference = load(grid, indirect);
  ASSERT_NE(reference, nullptr);
  ASSERT_TRUE(reference->usesIndirectDraws());
  ASSERT_TRUE(reference->finishUploads().ok());
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    // Colours differ by rounding only: the indirect shaders convert the face colours themselves.
    EXPECT_EQ(compareImages(culled[i], shot(*reference, cameras[i]), 2).differing, 0u) << "camera " << i;
  }
}

TEST_F(UpdateTest, InstancesOutOfViewAreNotDrawn) {
  Renderer* r = load(sphere(1.0f, 16));
  ASSERT_NE(r, nullptr);
  Scene& scene = r->scene();
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
  RgbaImage one = shot(*r, camera);
  const std::uint32_t faceDraws = r->lastFaceDrawCalls(), edgeDraws = r->lastEdgeDrawCalls();
  // A second instance far behind the camera: nothing of it is drawn, and the picture is the same.
  glm::mat4 away(1.0f);
  away[3] = glm::vec4(camera.eye() - 50.0f * camera.direction, 1.0f);
  ASSERT_TRUE(scene.addInstance(PartId{0}, away).ok());
  EXPECT_EQ(compareImages(one, shot(*r, camera), 0).differing, 0u);
  EXPECT_EQ(r->lastFaceDrawCalls(), faceDraws);
  EXPECT_EQ(r->lastEdgeDrawCalls(), edgeDraws);
  // Moved into view, it is.
  glm::mat4 near(1.0f);
  near[3] = glm::vec4(0.5f, 0.0f, 0.0f, 1.0f);
  ASSERT_TRUE(scene.setInstanceTransform(InstanceId{1}, near).ok());
  (void)shot(*r, camera);
  EXPECT_GT(r->lastFaceDrawCalls(), faceDraws);
  EXPECT_EQ(r->lastEdgeDrawCalls(), 2 * edgeDraws);
}

TEST_F(UpdateTest, OverlayDrawsInsideTheRenderPassOfRenderedFrames) {
  Renderer* r = load(cube());
  ASSERT_NE(r, nullptr);
  ASSERT_NE(r->renderPass(), VK_NULL_HANDLE);
  int calls = 0;
  // What the viewer's ImGui pass will do, reduced to a clear of a corner rectangle: only valid
  // inside a render pass, and visible in the capture.
  r->setOverlay([&calls](VkCommandBuffer cmd) {
    ++calls;
    VkClearAttachment clear{};
    clear.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    clear.colorAttachment = 0;
    clear.clearValue.color = {{1.0f, 0.0f, 1.0f, 1.0f}};
    VkClearRect rect{{{8, 8}, {32, 16}}, 0, 1};
    vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
  });
  ASSERT_TRUE(r->finishUploads().ok());  // upload-only frames: no render pass, no overlay
  EXPECT_EQ(calls, 0);
  RgbaImage image = shot(*r, standardView(StandardView::kIso, r->scene().bounds(), r->aspect()));
  EXPECT_EQ(calls, 1);
  const std::uint8_t* inside = image.at(20, 12);
  EXPECT_EQ(inside[0], 255);
  EXPECT_EQ(inside[1], 0);
  EXPECT_EQ(inside[2], 255);
  EXPECT_NE(image.at(60, 12)[1], 0);  // the background beside it
  r->setOverlay({});
  RgbaImage plain = shot(*r, standardView(StandardView::kIso, r->scene().bounds(), r->aspect()));
  EXPECT_EQ(calls, 1);
  EXPECT_NE(plain.at(20, 12)[1], 0);
}

TEST_F(UpdateTest, RenderMeshToPngWritesTheSameImage) {
  RenderOptions options;
  options.width = kSize;
  options.height = kSize;
  options.validation = true;
  options.deviceName = testDeviceName();
  std::string path = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/render_mesh_to_png.png";
  Status written = renderMeshToPng(cube(), options, path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  auto image = readPng(path);
  ASSERT_TRUE(image.ok()) << image.error().message;
  expectMatchesGolden(*image, "cube_shaded_edges");

  Status bad = renderMeshToPng(cube(), options, "/nonexistent-dir/x.png");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kIo);
}

// warmUp() draws its own small scene once and leaves nothing behind: the scene is empty afterwards
// and a model drawn next looks exactly as on a renderer that was never warmed up.
TEST_F(UpdateTest, WarmUpLeavesNoTrace) {
  const MeshData mesh = cube(2.0f, 4);
  RgbaImage cold, warm;
  {
    Renderer* r = load(mesh);
    ASSERT_NE(r, nullptr);
    cold = shot(*r, standardView(StandardView::kIso, r->scene().bounds(), r->aspect()));
    renderer_.reset();
  }
  Renderer* r = makeHeadless(kSize, kSize);
  ASSERT_NE(r, nullptr);
  const Status s = warmUp(*r);
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_EQ(r->scene().faceCount(), 0u);
  EXPECT_EQ(r->scene().vertexCount(), 0u);
  EXPECT_EQ(r->scene().instanceCount(), 0u);
  auto part = addMesh(r->scene(), mesh);
  ASSERT_TRUE(part.ok()) << part.error().message;
  warm = shot(*r, standardView(StandardView::kIso, r->scene().bounds(), r->aspect()));
  ASSERT_EQ(cold.pixels.size(), warm.pixels.size());
  EXPECT_TRUE(cold.pixels == warm.pixels);
}

}  // namespace
}  // namespace cetview::test
