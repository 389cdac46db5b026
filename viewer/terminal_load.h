// Loading a model for a terminal command (render, export): a progress bar on stderr while the file
// is read and transferred (large STEP files take seconds), silent when stderr is not a terminal.
#pragma once

#include <string>

#include "brep/model.h"

namespace cetview {

brep::LoadResult loadWithProgressBar(const std::string& path, const std::string& command);

}  // namespace cetview
