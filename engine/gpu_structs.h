// C++ view of shaders/shared.h, with the layout checks that keep it identical to the GLSL side.
#pragma once

#include "shaders/shared.h"

namespace cetview::engine {

using gpu::DrawConstants;
using gpu::Globals;

static_assert(sizeof(Globals) == 3 * 16, "Globals must match its std140 layout");
static_assert(sizeof(DrawConstants) == 128, "DrawConstants must fit the 128 bytes every device allows");

}  // namespace cetview::engine
