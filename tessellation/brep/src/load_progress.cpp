#include "load_progress.h"

#include <algorithm>

#include <Message_ProgressScope.hxx>

namespace cetview::brep {
namespace {

class PhaseIndicator : public Message_ProgressIndicator {
 public:
  explicit PhaseIndicator(LoadProgress& load) : load_(load) {}
  Standard_Boolean UserBreak() override { return load_.cancelled(); }
  void Show(const Message_ProgressScope&, const Standard_Boolean) override { load_.within(GetPosition()); }

 private:
  LoadProgress& load_;
};

}  // namespace

void LoadProgress::phase(const char* name, double from, double to) {
  phase_ = name;
  from_ = from, to_ = to;
  reported_ = -1;
  within(0.0);
}

void LoadProgress::within(double fraction) {
  if (!control_.progress) return;
  const double whole = fraction >= 1.0 ? to_ : from_ + (to_ - from_) * std::clamp(fraction, 0.0, 1.0);
  // Every half per cent, and the phase's end.
  if (reported_ >= 0 && (whole == reported_ || (whole < reported_ + 0.005 && whole < to_))) return;
  reported_ = whole;
  control_.progress(phase_, whole);
}

Handle(Message_ProgressIndicator) LoadProgress::indicator() {
  return new PhaseIndicator(*this);
}

}  // namespace cetview::brep
