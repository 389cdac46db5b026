#include "engine/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

namespace cetview::engine {

Status writePng(const RgbaImage& image, const std::string& path) {
  if (image.width == 0 || image.height == 0 ||
      image.pixels.size() != std::size_t{image.width} * image.height * 4) {
    return makeError(ErrorCode::kInvalidArgument, "cannot write an empty or malformed image to " + path);
  }
  int ok = stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 4,
                          image.pixels.data(), static_cast<int>(image.width * 4));
  if (!ok) return makeError(ErrorCode::kIo, "cannot write PNG " + path);
  return {};
}

Result<RgbaImage> readPng(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (data == nullptr) {
    const char* reason = stbi_failure_reason();
    return makeError(ErrorCode::kIo, "cannot read PNG " + path + ": " + (reason ? reason : "unknown error"));
  }
  RgbaImage image;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.pixels.assign(data, data + std::size_t(width) * std::size_t(height) * 4);
  stbi_image_free(data);
  return image;
}

}  // namespace cetview::engine
