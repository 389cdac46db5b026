// A model loading on a thread of its own, so that the window stays live while a large file loads:
// its progress for the panel, cancellation at once, and the result picked up by the UI thread when
// done. Cancelled, the load stops at OpenCASCADE's next check (its STEP and IGES parser cannot be
// stopped inside: the thread then runs on until the parse ends, and its result is dropped).
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "brep/model.h"

namespace cetview {

class BackgroundLoad {
 public:
  // Starts loading `path` ("demo" builds the demo part). `wake` is called on the loading thread
  // when the load is done (the window posts an empty event); it must be safe from any thread.
  BackgroundLoad(std::string path, std::function<void()> wake);
  ~BackgroundLoad();  // cancels and waits for the thread
  BackgroundLoad(const BackgroundLoad&) = delete;
  BackgroundLoad& operator=(const BackgroundLoad&) = delete;

  const std::string& path() const { return path_; }
  void cancel() { cancel_ = true; }
  bool cancelled() const { return cancel_.load(); }
  bool done() const { return done_.load(std::memory_order_acquire); }

  struct Progress {
    std::string phase;    // "starting" until the loader reports
    double fraction = 0;  // of the whole load, in [0, 1]
    double seconds = 0;   // since the load started
  };
  Progress progress() const;

  // The result, once done() (moved out: call once).
  brep::LoadResult take();

 private:
  const std::string path_;
  const std::chrono::steady_clock::time_point start_;
  std::atomic<bool> cancel_{false};
  std::atomic<bool> done_{false};
  mutable std::mutex mutex_;
  std::string phase_ = "starting";
  double fraction_ = 0;
  brep::LoadResult result_;
  std::thread thread_;
};

}  // namespace cetview
