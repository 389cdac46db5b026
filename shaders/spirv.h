// The SPIR-V of every cetview shader, compiled at build time and embedded in the binary.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cetview::shaders {

enum class ShaderId {
  kBackgroundVert,
  kBackgroundFrag,
  kMeshVert,  // a colour per face (the face table), for multi-draw indirect
  kMeshFrag,
  kWireFrag,
  kMeshPushedVert,  // CETVIEW_COLOR_PUSHED: one colour per draw (DrawConstants::color)
  kMeshPushedFrag,
  kWirePushedFrag,
  kEdgeVert,
  kEdgeFrag,
};

// Words of one shader module, ready for VkShaderModuleCreateInfo (codeSize is sizeBytes).
struct Spirv {
  const std::uint32_t* words = nullptr;
  std::size_t sizeBytes = 0;
};

Spirv spirv(ShaderId id);

}  // namespace cetview::shaders
