#include "device_loss.h"

#include <cstdlib>

namespace cetview {

std::string engineErrorLine(const engine::Error& error) {
  if (error.code != engine::ErrorCode::kDeviceLost) return error.message;
  return error.message + "; restart cetview (or pick another device with --device)";
}

void simulateDeviceLossIfRequested(engine::Renderer& renderer, std::uint64_t frame) {
  static const long long at = [] {
    const char* value = std::getenv("CETVIEW_TEST_DEVICE_LOSS_AT_FRAME");
    if (value == nullptr || *value == '\0') return -1LL;
    char* end = nullptr;
    const long long n = std::strtoll(value, &end, 10);
    return *end == '\0' && n >= 0 ? n : -1LL;
  }();
  if (at >= 0 && frame == static_cast<std::uint64_t>(at)) renderer.simulateDeviceLossForTesting();
}

}  // namespace cetview
