#include "stream/stream_threads.h"

#include <algorithm>
#include <system_error>
#include <utility>

namespace cetview::stream {

StreamThreads::StreamThreads(unsigned threads)
    : threads_(std::max(1u, threads)), pool_(std::make_shared<brep::WorkerPool>()) {
  pool_->start(threads_);
  try {
    thread_ = std::thread([this] { loop(); });
  } catch (const std::system_error&) {
    // No coordinator thread: launch() refuses, and each stream starts its own.
  }
}

StreamThreads::~StreamThreads() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return !busy_; });
    stop_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool StreamThreads::launch(std::function<void()> task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (busy_ || !thread_.joinable()) return false;
    task_ = std::move(task);
    busy_ = true;
  }
  changed_.notify_all();
  return true;
}

void StreamThreads::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !busy_; });
}

unsigned StreamThreads::tasksRun() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return tasksRun_;
}

void StreamThreads::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stop_ || task_; });
    if (stop_) return;
    std::function<void()> task = std::move(task_);
    task_ = nullptr;
    lock.unlock();
    task();  // ProgressiveStream::coordinate(), which does not throw
    task = nullptr;
    lock.lock();
    ++tasksRun_;
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace cetview::stream
