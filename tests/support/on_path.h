// Whether an executable is on PATH, for tests that need a tool the machine may lack (Xvfb).
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace cetview::test {

inline bool onPath(const char* program) {
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    if (access((dirs.substr(start, end - start) + "/" + program).c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace cetview::test
