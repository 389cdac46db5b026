// C++ view of shaders/shared.h, with the layout checks that keep it identical to the GLSL side.
#pragma once

#include "shaders/shared.h"

namespace cetview::engine {

using gpu::DrawConstants;
using gpu::Globals;
using gpu::InstanceData;

static_assert(sizeof(Globals) == 2 * 64 + 6 * 16 + 16, "Globals must match its std140 layout");
static_assert(sizeof(InstanceData) == 160, "InstanceData must match its std430 layout");
static_assert(sizeof(DrawConstants) == 16, "DrawConstants must match the push-constant block");

}  // namespace cetview::engine
