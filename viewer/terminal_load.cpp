#include "terminal_load.h"

#include <cmath>

#include "progress_bar.h"

namespace cetview {

brep::LoadResult loadWithProgressBar(const std::string& path, const std::string& command) {
  ProgressBar bar(command + " " + path);
  brep::LoadControl control;
  constexpr std::size_t kSteps = 1000;
  control.progress = [&](const char* phase, double fraction) {
    bar.update(static_cast<std::size_t>(std::lround(fraction * kSteps)), kSteps,
               std::string("loading: ") + phase);
  };
  return brep::loadModel(path, control);
}

}  // namespace cetview
