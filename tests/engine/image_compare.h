// Image comparison for the render tests: golden PNGs with a tolerance, regenerated on request.
//
// Goldens live in tests/engine/golden/NAME.png. To regenerate after an intended change in the
// look, run the render tests with CETVIEW_UPDATE_GOLDEN=1, e.g.
//   CETVIEW_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden
// then look at every changed PNG before committing it. Every test also writes what it rendered to
// <build>/tests/engine/output/ (plus NAME.diff.png on a mismatch) for inspection.
#pragma once

#include <cstdint>
#include <string>

#include "engine/image.h"

namespace cetview::test {

struct ImageDiff {
  std::uint32_t differing = 0;  // pixels whose largest channel difference exceeds the threshold
  std::uint32_t maxDelta = 0;   // largest channel difference anywhere
  // Bounding box of the differing pixels (empty when differing == 0).
  std::uint32_t minX = UINT32_MAX, minY = UINT32_MAX, maxX = 0, maxY = 0;
};

// Sizes must match. `threshold`: a channel difference up to this is noise.
ImageDiff compareImages(const engine::RgbaImage& a, const engine::RgbaImage& b, std::uint32_t threshold);

// Red where the images differ beyond `threshold`, the dimmed first image elsewhere.
engine::RgbaImage diffImage(const engine::RgbaImage& a, const engine::RgbaImage& b, std::uint32_t threshold);

// Writes `image` to the test output folder as NAME.png; returns the path.
std::string saveOutput(const engine::RgbaImage& image, const std::string& name);

// The golden check: fails the current test (gtest) when more than `maxDifferingFraction` of the
// pixels differ from golden/NAME.png by more than `threshold` in any channel. With
// CETVIEW_UPDATE_GOLDEN=1 it writes the golden instead.
void expectMatchesGolden(const engine::RgbaImage& image, const std::string& name,
                         std::uint32_t threshold = 24, double maxDifferingFraction = 0.005);

}  // namespace cetview::test
