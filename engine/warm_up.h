// Software devices (lavapipe) compile a pipeline's machine code at its first draw, about 50 ms that
// would otherwise land on the first frame of the first model. warmUp() draws a small scene once,
// a closed solid and an open shell with their edges, shaded with edges (the default look), and
// clears the scene again. Call it right after creating the renderer, before filling the scene.
#pragma once

#include "engine/renderer.h"

namespace cetview::engine {

Status warmUp(Renderer& renderer);

}  // namespace cetview::engine
