// `cetview render` frames the model's triangles, not its B-rep box: a B-spline face's box takes its
// poles, which can reach far beyond the surface. A torus of 3 x 1 written as rational B-splines
// (BRepBuilderAPI_NurbsConvert: circles of three 120-degree arcs, whose poles make triangles twice
// the circle's radius out) has a box of [-8, 4] x [-6.9, 6.9] x [-1.7, 1.7] for [-4, 4]^2 x [-1, 1],
// and was drawn small and off the picture's centre (seen from the top in a 320 x 240 picture, its
// middle 31 pixels right of the picture's, and under 60% of its height).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>

#include "engine/image.h"
#include "run_command.h"

namespace {

// The box of the pixels that differ from their row's first pixel (the background is a vertical
// gradient, and the model does not reach the picture's left side).
struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0; }
};

PixelBox modelPixels(const cetview::engine::RgbaImage& image) {
  PixelBox box;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    const std::uint8_t* background = image.at(0, y);
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      int differs = 0;
      for (int c = 0; c < 3; ++c) differs = std::max(differs, std::abs(int(p[c]) - int(background[c])));
      if (differs <= 8) continue;
      box.x0 = std::min(box.x0, int(x)), box.x1 = std::max(box.x1, int(x));
      box.y0 = std::min(box.y0, int(y)), box.y1 = std::max(box.y1, int(y));
    }
  }
  return box;
}

TEST(RenderFraming, ATorusWrittenAsBSplinesIsFramedByItsTriangles) {
  std::system(("mkdir -p " + std::string(CETVIEW_TEST_OUTPUT_DIR)).c_str());
  const std::string model = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/nurbs_torus_" + std::to_string(::getpid()) + ".brep";
  ASSERT_TRUE(BRepTools::Write(BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeTorus(3.0, 1.0).Shape()).Shape(),
                               model.c_str()));
  const std::string out = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/nurbs_torus_top.png";
  const cetview::test::CommandResult r = cetview::test::runCommand(
      std::string(CETVIEW_EXE) + " render " + model + " -o " + out +
      " --size 320x240 --view top --projection orthographic --deflection 1% --threads 2");
  ::unlink(model.c_str());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  auto image = cetview::engine::readPng(out);
  ASSERT_TRUE(image) << out;
  const PixelBox box = modelPixels(*image);
  ASSERT_FALSE(box.empty());
  // Centred, and filling the picture's height as a fitted view does (a ring seen from the top: as
  // wide as high).
  EXPECT_NEAR(0.5 * (box.x0 + box.x1), 0.5 * (image->width - 1), 2.0);
  EXPECT_NEAR(0.5 * (box.y0 + box.y1), 0.5 * (image->height - 1), 2.0);
  EXPECT_NEAR(box.x1 - box.x0, box.y1 - box.y0, 3);
  EXPECT_GT(box.y1 - box.y0, 0.6 * image->height) << "drawn small";
}

}  // namespace
