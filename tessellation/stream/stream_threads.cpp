#include "stream/stream_threads.h"

#include <algorithm>
#include <system_error>
#include <utility>

namespace cetview::stream {

StreamThreads::StreamThreads(unsigned threads, std::size_t ringBytes)
    : threads_(std::max(1u, threads)), ringBytes_(ringBytes), pool_(std::make_shared<brep::WorkerPool>()) {
  pool_->start(threads_);
  for (unsigned i = 0; i < threads_; ++i) rings_.push_back(std::make_unique<SpscRing>(ringBytes_));
  control_ = std::make_unique<SpscRing>(kControlRingBytes);
  try {
    thread_ = std::thread([this] { loop(); });
  } catch (const std::system_error&) {
    // No coordinator thread: acquire() refuses, and each stream starts its own thread and rings.
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

bool StreamThreads::acquire() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (busy_ || !thread_.joinable()) return false;
  busy_ = true;
  return true;
}

void StreamThreads::launch(std::function<void()> task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    task_ = std::move(task);
  }
  changed_.notify_all();
}

void StreamThreads::release() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    busy_ = false;
  }
  changed_.notify_all();
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
