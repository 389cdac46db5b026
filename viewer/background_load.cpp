#include "background_load.h"

#include <utility>

namespace cetview {

BackgroundLoad::BackgroundLoad(std::string path, std::function<void()> wake)
    : path_(std::move(path)), start_(std::chrono::steady_clock::now()) {
  thread_ = std::thread([this, wake = std::move(wake)] {
    brep::LoadControl control;
    control.cancel = &cancel_;
    control.progress = [this](const char* phase, double fraction) {
      std::lock_guard<std::mutex> lock(mutex_);
      phase_ = phase;
      fraction_ = fraction;
    };
    brep::LoadResult result = brep::loadModel(path_, control);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      result_ = std::move(result);
    }
    done_.store(true, std::memory_order_release);
    if (wake) wake();
  });
}

BackgroundLoad::~BackgroundLoad() {
  cancel_ = true;
  thread_.join();
}

BackgroundLoad::Progress BackgroundLoad::progress() const {
  Progress p;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    p.phase = phase_;
    p.fraction = fraction_;
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return p;
}

brep::LoadResult BackgroundLoad::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::move(result_);
}

}  // namespace cetview
