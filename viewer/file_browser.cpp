#include "file_browser.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace cetview {

bool isModelFileName(const std::string& name) {
  const auto dot = name.find_last_of('.');
  if (dot == std::string::npos || dot == 0) return false;
  std::string ext = name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == "step" || ext == "stp" || ext == "iges" || ext == "igs" || ext == "brep" || ext == "brp";
}

BrowserListing listModelDirectory(const std::string& directory) {
  namespace fs = std::filesystem;
  BrowserListing out;
  std::error_code ec;
  const fs::path dir = fs::weakly_canonical(fs::absolute(directory.empty() ? "." : directory, ec), ec);
  out.directory = dir.string();
  fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    out.error = out.directory + ": " + ec.message();
    return out;
  }
  for (const fs::directory_iterator end; it != end; it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code statError;
    if (it->is_directory(statError)) {
      out.entries.push_back({name, true, 0});
    } else if (it->is_regular_file(statError) && isModelFileName(name)) {
      out.entries.push_back({name, false, it->file_size(statError)});
    }
  }
  std::sort(out.entries.begin(), out.entries.end(), [](const BrowserEntry& a, const BrowserEntry& b) {
    if (a.directory != b.directory) return a.directory;
    return a.name < b.name;
  });
  return out;
}

std::string humanBytes(std::uintmax_t bytes) {
  char text[32];
  const double b = static_cast<double>(bytes);
  if (bytes >= (std::uintmax_t{1} << 20)) {
    std::snprintf(text, sizeof text, "%.1f MB", b / (1024.0 * 1024.0));
  } else if (bytes >= 1024) {
    std::snprintf(text, sizeof text, "%.0f KB", b / 1024.0);
  } else {
    std::snprintf(text, sizeof text, "%ju B", bytes);
  }
  return text;
}

}  // namespace cetview
