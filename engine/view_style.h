// The look of a frame: display mode, colour toggles and palette. Per frame, not per scene, so the
// viewer's toggles cost no upload.
#pragma once

#include "engine/scene.h"
#include "engine/types.h"

namespace cetview::engine {

struct ViewStyle {
  DisplayMode mode = DisplayMode::kShadedWithEdges;
  bool fileColors = true;  // false: every face in defaultFaceColor (instance colours too)
  Color8 defaultFaceColor = kDefaultFaceColor;
  Color8 edgeColor{28, 30, 36, 255};
  Color8 backgroundTop{222, 228, 236, 255};
  Color8 backgroundBottom{150, 160, 176, 255};
};

}  // namespace cetview::engine
