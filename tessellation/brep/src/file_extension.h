// A path's file extension, lower-cased and without the dot ("" when it has none): how loading and
// export choose a format.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace cetview::brep {

inline std::string lowerExtension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace cetview::brep
