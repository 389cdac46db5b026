// The listing behind the window's File > Open dialog: one directory's subdirectories and model
// files (STEP, IGES and .brep by their extension, any case), directories first, each group in name
// order; hidden entries (names starting with '.') are left out. No OpenCASCADE, no ImGui.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cetview {

struct BrowserEntry {
  std::string name;
  bool directory = false;
  std::uintmax_t bytes = 0;  // files only
};

struct BrowserListing {
  std::string directory;  // absolute and normalised
  std::vector<BrowserEntry> entries;
  std::string error;  // one line when the directory cannot be read (entries empty)
};

// Whether `name` has a model file's extension (.step .stp .iges .igs .brep .brp, any case).
bool isModelFileName(const std::string& name);

BrowserListing listModelDirectory(const std::string& directory);

// "12.3 MB", "512 KB", "80 B": for the listing.
std::string humanBytes(std::uintmax_t bytes);

}  // namespace cetview
