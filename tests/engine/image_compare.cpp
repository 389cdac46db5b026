#include "image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

namespace cetview::test {

using engine::RgbaImage;

ImageDiff compareImages(const RgbaImage& a, const RgbaImage& b, std::uint32_t threshold) {
  ImageDiff d;
  for (std::uint32_t y = 0; y < a.height; ++y) {
    for (std::uint32_t x = 0; x < a.width; ++x) {
      std::uint32_t delta = 0;
      for (int c = 0; c < 4; ++c) {
        delta = std::max<std::uint32_t>(delta,
                                        static_cast<std::uint32_t>(std::abs(a.at(x, y)[c] - b.at(x, y)[c])));
      }
      d.maxDelta = std::max(d.maxDelta, delta);
      if (delta > threshold) {
        ++d.differing;
        d.minX = std::min(d.minX, x);
        d.minY = std::min(d.minY, y);
        d.maxX = std::max(d.maxX, x);
        d.maxY = std::max(d.maxY, y);
      }
    }
  }
  return d;
}

RgbaImage diffImage(const RgbaImage& a, const RgbaImage& b, std::uint32_t threshold) {
  RgbaImage out = a;
  for (std::uint32_t y = 0; y < a.height; ++y) {
    for (std::uint32_t x = 0; x < a.width; ++x) {
      std::uint8_t* p = out.at(x, y);
      std::uint32_t delta = 0;
      for (int c = 0; c < 4; ++c) {
        delta = std::max<std::uint32_t>(delta,
                                        static_cast<std::uint32_t>(std::abs(a.at(x, y)[c] - b.at(x, y)[c])));
      }
      if (delta > threshold) {
        p[0] = 255, p[1] = 0, p[2] = 0;
      } else {
        for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(p[c] / 3);
      }
      p[3] = 255;
    }
  }
  return out;
}

std::string saveOutput(const RgbaImage& image, const std::string& name) {
  std::filesystem::create_directories(CETVIEW_TEST_OUTPUT_DIR);
  std::string path = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/" + name + ".png";
  auto status = engine::writePng(image, path);
  EXPECT_TRUE(status.ok()) << status.error().message;
  return path;
}

void expectMatchesGolden(const RgbaImage& image, const std::string& name, std::uint32_t threshold,
                         double maxDifferingFraction) {
  std::string golden = std::string(CETVIEW_GOLDEN_DIR) + "/" + name + ".png";
  saveOutput(image, name);
  const char* update = std::getenv("CETVIEW_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    std::filesystem::create_directories(CETVIEW_GOLDEN_DIR);
    auto status = engine::writePng(image, golden);
    ASSERT_TRUE(status.ok()) << status.error().message;
    std::printf("updated golden %s\n", golden.c_str());
    return;
  }
  auto expected = engine::readPng(golden);
  ASSERT_TRUE(expected.ok()) << expected.error().message
                             << " (run with CETVIEW_UPDATE_GOLDEN=1 to create it, then look at it)";
  ASSERT_EQ(expected->width, image.width) << golden;
  ASSERT_EQ(expected->height, image.height) << golden;
  ImageDiff d = compareImages(image, *expected, threshold);
  auto allowed = static_cast<std::uint32_t>(maxDifferingFraction * image.width * image.height);
  if (d.differing > allowed) saveOutput(diffImage(image, *expected, threshold), name + ".diff");
  EXPECT_LE(d.differing, allowed) << name << ": " << d.differing << " pixels differ by more than "
                                  << threshold << " (largest difference " << d.maxDelta << "); see "
                                  << CETVIEW_TEST_OUTPUT_DIR;
}

}  // namespace cetview::test
