// What `cetview view` and `cetview render` do about a lost Vulkan device: end with one line that
// says so and what to do, exit code 1. And the test hook that makes lavapipe "lose" its device.
#pragma once

#include <cstdint>
#include <string>

#include "engine/renderer.h"
#include "engine/result.h"

namespace cetview {

// An engine error as the one line a command prints (after "cetview COMMAND: "); a lost device
// adds "; restart cetview (or pick another device with --device)".
std::string engineErrorLine(const engine::Error& error);

// TEST HOOK, for tests/viewer and tests/stream only (not in --help): with the environment variable
// CETVIEW_TEST_DEVICE_LOSS_AT_FRAME=N, calls renderer.simulateDeviceLossForTesting() when `frame`
// is N (0-based; `view`: the window's frames, `render`: the captured pictures), so the renderer's
// next submission or wait reports VK_ERROR_DEVICE_LOST. Does nothing when the variable is unset.
void simulateDeviceLossIfRequested(engine::Renderer& renderer, std::uint64_t frame);

}  // namespace cetview
