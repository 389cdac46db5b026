// RGBA8 images in host memory and their PNG files (stb_image_write / stb_image from Debian's libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/result.h"

namespace cetview::engine {

// sRGB-encoded RGBA8, rows top to bottom, no padding.
struct RgbaImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4 bytes

  const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const {
    return &pixels[(std::size_t{y} * width + x) * 4];
  }
  std::uint8_t* at(std::uint32_t x, std::uint32_t y) { return &pixels[(std::size_t{y} * width + x) * 4]; }
};

// Errors: kIo with the path.
Status writePng(const RgbaImage& image, const std::string& path);
Result<RgbaImage> readPng(const std::string& path);

}  // namespace cetview::engine
