// A one-line terminal progress bar on stderr, redrawn in place; silent when stderr is not a
// terminal (logs and CI stay clean).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace cetview {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();  // ends the line if anything was drawn
  // Redraws at most ~10 times a second (and always when done == total).
  void update(std::size_t done, std::size_t total, const std::string& detail = {});

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace cetview
