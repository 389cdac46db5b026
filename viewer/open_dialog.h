// The window's File > Open dialog: browse directories for STEP, IGES and .brep files
// (file_browser.h), or type or paste a path. Double-click or Enter opens; Esc or Cancel closes.
#pragma once

#include <optional>
#include <string>

#include "file_browser.h"

namespace cetview {

class OpenDialog {
 public:
  // Shows the dialog, listing `directory`, from the next draw() on.
  void open(const std::string& directory);
  // Draws the dialog while it is shown; returns the path chosen, once.
  std::optional<std::string> draw();

 private:
  void list(const std::string& directory);

  bool opening_ = false;
  BrowserListing listing_;
  int selected_ = -1;
  char path_[1024] = {};
};

}  // namespace cetview
