// Headless renders on lavapipe (or CETVIEW_TEST_DEVICE) compared with golden PNGs; see
// image_compare.h for the tolerance and how to regenerate them.
#include <gtest/gtest.h>

#include <glm/ext/matrix_transform.hpp>

#include "engine/render_to_png.h"
#include "image_compare.h"
#include "render_fixture.h"
#include "test_meshes.h"

namespace cetview::test {
namespace {

using namespace engine;

constexpr std::uint32_t kSize = 256;

class GoldenTest : public VulkanTest {
 protected:
  // Goldens are anti-aliased (auto would pick no MSAA on lavapipe).
  static RendererOptions msaa4() {
    RendererOptions options;
    options.msaaSamples = 4;
    return options;
  }

  // Loads `mesh` as one part, uploads it completely, renders one frame.
  RgbaImage render(const MeshData& mesh, StandardView view, Projection projection, const ViewStyle& style) {
    Renderer* r = makeHeadless(kSize, kSize, msaa4());
    if (r == nullptr) return {};
    auto part = addMesh(r->scene(), mesh);
    EXPECT_TRUE(part.ok()) << part.error().message;
    Status uploaded = r->finishUploads();
    EXPECT_TRUE(uploaded.ok()) << uploaded.error().message;
    Camera camera = standardView(view, r->scene().bounds(), r->aspect(), projection);
    auto image = r->capture(camera, style);
    EXPECT_TRUE(image.ok()) << image.error().message;
    return image.ok() ? *image : RgbaImage{};
  }
};

TEST_F(GoldenTest, CubeShadedWithEdges) {
  RgbaImage image = render(cube(), StandardView::kIso, Projection::kPerspective, ViewStyle{});
  expectMatchesGolden(image, "cube_shaded_edges");
}

TEST_F(GoldenTest, CubeWireframe) {
  ViewStyle style;
  style.mode = DisplayMode::kWireframe;
  RgbaImage image = render(cube(2.0f, 3), StandardView::kIso, Projection::kOrthographic, style);
  expectMatchesGolden(image, "cube_wireframe");
}

TEST_F(GoldenTest, SpherePerspectiveWithEdges) {
  RgbaImage image = render(sphere(1.0f, 16), StandardView::kIso, Projection::kPerspective, ViewStyle{});
  expectMatchesGolden(image, "sphere_shaded_edges");
}

TEST_F(GoldenTest, SphereOrthographicFrontShaded) {
  ViewStyle style;
  style.mode = DisplayMode::kShaded;
  RgbaImage image = render(sphere(1.0f, 16), StandardView::kFront, Projection::kOrthographic, style);
  expectMatchesGolden(image, "sphere_front_ortho");
}

TEST_F(GoldenTest, LatticeOfThousandsOfSmallObjects) {
  MeshData mesh = lattice(13, 1.0f, 4);  // 2197 objects, one face each
  ASSERT_EQ(mesh.faces.size(), 2197u);
  ViewStyle style;
  style.mode = DisplayMode::kShaded;
  RgbaImage image = render(mesh, StandardView::kIso, Projection::kPerspective, style);
  expectMatchesGolden(image, "lattice");
}

TEST_F(GoldenTest, InstancesWithTransformsAndColorOverride) {
  Renderer* r = makeHeadless(kSize, kSize, msaa4());
  ASSERT_NE(r, nullptr);
  Scene& scene = r->scene();
  auto part = addMesh(scene, cube(1.0f, 2));  // instance 0: identity
  ASSERT_TRUE(part.ok());
  glm::mat4 right = glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 0.0f, 0.0f));
  glm::mat4 up = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1.6f)), 0.6f,
                             glm::vec3(0.0f, 0.0f, 1.0f));
  auto second = scene.addInstance(part->part, glm::scale(right, glm::vec3(0.6f)));
  auto third = scene.addInstance(part->part, up);
  ASSERT_TRUE(second.ok() && third.ok());
  ASSERT_TRUE(scene.setInstanceColor(*third, Color8{90, 170, 120, 255}).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  Camera camera = standardView(StandardView::kIso, scene.bounds(), r->aspect());
  auto image = r->capture(camera);
  ASSERT_TRUE(image.ok()) << image.error().message;
  expectMatchesGolden(*image, "instances");
}

TEST_F(GoldenTest, CubeWithoutMsaa) {
  RendererOptions noMsaa;
  noMsaa.msaaSamples = 1;
  Renderer* r = makeHeadless(kSize, kSize, noMsaa);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->samples(), VK_SAMPLE_COUNT_1_BIT);
  ASSERT_TRUE(addMesh(r->scene(), cube()).ok());
  ASSERT_TRUE(r->finishUploads().ok());
  auto image = r->capture(standardView(StandardView::kIso, r->scene().bounds(), r->aspect()));
  ASSERT_TRUE(image.ok()) << image.error().message;
  expectMatchesGolden(*image, "cube_no_msaa");
}

TEST_F(GoldenTest, FileColorsOffUsesTheDefaultColor) {
  ViewStyle style;
  style.fileColors = false;
  RgbaImage image = render(cube(), StandardView::kIso, Projection::kPerspective, style);
  expectMatchesGolden(image, "cube_file_colors_off");
}

}  // namespace
}  // namespace cetview::test
