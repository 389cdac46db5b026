// `cetview render --levels` on lavapipe, end to end: one complete frame per level, each sharper than
// the last (successive images differ), the final one matching a golden image, validation-clean.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include "engine/image.h"
#include "image_compare.h"
#include "run_command.h"

namespace {

using CliResult = cetview::test::CommandResult;

CliResult run(const std::string& args) { return cetview::test::runCommand(std::string(CETVIEW_EXE) + " " + args); }

struct LevelLine {
  int level;
  double ms, tolerance;
  unsigned long long triangles;
  std::string png;
};

std::vector<LevelLine> parseLines(const std::string& out) {
  std::vector<LevelLine> lines;
  const std::regex re(
      R"re(\{"level":(\d+),"ms":([0-9.]+),"triangles":(\d+),"tolerance":([0-9.e+-]+),"faces":\d+,"png":"([^"]+)"\})re");
  for (auto it = std::sregex_iterator(out.begin(), out.end(), re); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    lines.push_back({std::stoi(m[1]), std::stod(m[2]), std::stod(m[4]), std::stoull(m[3]), m[5]});
  }
  return lines;
}

TEST(RenderLevels, DemoSharpensLevelByLevelAndMatchesGolden) {
  const std::string out = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/demo_levels.png";
  std::system(("mkdir -p " + std::string(CETVIEW_TEST_OUTPUT_DIR)).c_str());
  // The golden is lavapipe's: on lavapipe unless CETVIEW_TEST_DEVICE names another device.
  const char* device = std::getenv("CETVIEW_TEST_DEVICE");
  const std::string deviceName = device != nullptr && *device != '\0' ? device : "llvmpipe";
  const CliResult r = run("render demo -o " + out +
                          " --levels --size 320x240 --threads 2 --validate --device '" + deviceName + "'");
  ASSERT_EQ(r.exitCode, 0) << r.out;
  const std::vector<LevelLine> levels = parseLines(r.out);
  ASSERT_GE(levels.size(), 3u) << r.out;
  std::vector<cetview::engine::RgbaImage> images;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    EXPECT_EQ(levels[k].level, static_cast<int>(k));
    if (k > 0) {
      EXPECT_GE(levels[k].ms, levels[k - 1].ms);
      EXPECT_LT(levels[k].tolerance, levels[k - 1].tolerance);
      EXPECT_GE(levels[k].triangles, levels[k - 1].triangles);
    }
    auto image = cetview::engine::readPng(levels[k].png);
    ASSERT_TRUE(image) << levels[k].png;
    images.push_back(std::move(*image));
  }
  EXPECT_GT(levels.back().triangles, 2 * levels.front().triangles);
  // Each level is a different, complete frame: finer silhouettes and shading change pixels.
  for (std::size_t k = 1; k < images.size(); ++k) {
    const auto diff = cetview::test::compareImages(images[k - 1], images[k], 8);
    EXPECT_GT(diff.differing, 20u) << "levels " << k - 1 << " and " << k << " look the same";
  }
  auto final = cetview::engine::readPng(out);
  ASSERT_TRUE(final);
  EXPECT_EQ(cetview::test::compareImages(*final, images.back(), 0).differing, 0u) << "OUT.png is the last level";
  cetview::test::expectMatchesGolden(*final, "demo_levels_final");
}

// A lost Vulkan device (simulated through the viewer's test hook, as lavapipe never loses it) ends
// the run with exit code 1 and exactly one line on stderr that says so, validation-clean.
CliResult runLosingDeviceAt(int picture, const std::string& args) {
  const std::string err = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/device_loss.err";
  return cetview::test::runCommand("CETVIEW_TEST_DEVICE_LOSS_AT_FRAME=" + std::to_string(picture) + " " +
                                       std::string(CETVIEW_EXE) + " " + args,
                                   err);
}

void expectOneDeviceLostLine(const CliResult& r) {
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not exactly one line:\n" << r.err;
  EXPECT_EQ(r.err.rfind("cetview render: the Vulkan device was lost (VK_ERROR_DEVICE_LOST in ", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("; restart cetview (or pick another device with --device)\n"), std::string::npos)
      << r.err;
  // Nothing from the validation layer (it prints "vulkan: Validation Error: ...").
  EXPECT_EQ(r.err.find("vulkan:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Validation"), std::string::npos) << r.err;
}

TEST(RenderLevels, DeviceLossEndsWithOneLineAndExitCodeOne) {
  std::system(("mkdir -p " + std::string(CETVIEW_TEST_OUTPUT_DIR)).c_str());
  const std::string out = std::string(CETVIEW_TEST_OUTPUT_DIR) + "/device_loss.png";
  std::remove(out.c_str());
  CliResult r = runLosingDeviceAt(0, "render demo -o " + out + " --size 160x120 --threads 2 --validate");
  expectOneDeviceLostLine(r);
  EXPECT_FALSE(cetview::engine::readPng(out).ok()) << "no picture after the loss";

  // Lost at the third picture of --levels: the first two were written.
  r = runLosingDeviceAt(2, "render demo -o " + out + " --levels --size 160x120 --threads 2 --validate");
  expectOneDeviceLostLine(r);
  EXPECT_EQ(parseLines(r.out).size(), 2u) << r.out;
}

TEST(RenderLevels, BadInputExitsTwo) {
  EXPECT_EQ(run("render /nonexistent/model.step -o /tmp/x.png 2>/dev/null").exitCode, 2);
  EXPECT_EQ(run("render demo -o /tmp/x.png --size 10x10 2>/dev/null").exitCode, 2);
  EXPECT_EQ(run("render demo -o /tmp/x.png --view sideways 2>/dev/null").exitCode, 2);
  EXPECT_EQ(run("render demo -o /tmp/x.png --deflection -1 2>/dev/null").exitCode, 2);
  EXPECT_EQ(run("render demo -o /tmp/x.png --device no-such-gpu 2>/dev/null").exitCode, 1);
}

}  // namespace
