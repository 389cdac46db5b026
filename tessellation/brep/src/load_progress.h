// The progress and cancellation of one load (LoadControl), in phases that each take a fixed share
// of the whole: the loaders report within their phase, and OpenCASCADE's readers through an
// indicator whose positions map into the phase and whose UserBreak() reads the cancel flag.
#pragma once

#include <Message_ProgressIndicator.hxx>

#include "brep/model.h"

namespace cetview::brep {

class LoadProgress {
 public:
  explicit LoadProgress(const LoadControl& control) : control_(control) {}

  bool cancelled() const { return control_.cancel && control_.cancel->load(std::memory_order_relaxed); }
  // Starts a phase spanning [from, to] of the whole load and reports its start.
  void phase(const char* name, double from, double to);
  // Reports `fraction` of the current phase (rate-limited: every half per cent of the whole).
  void within(double fraction);
  // An indicator for one OpenCASCADE call in the current phase (Start() it for the call's range).
  Handle(Message_ProgressIndicator) indicator();

 private:
  const LoadControl& control_;
  const char* phase_ = "";
  double from_ = 0, to_ = 0;
  double reported_ = -1;
};

}  // namespace cetview::brep
