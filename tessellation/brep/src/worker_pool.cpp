#include "brep/worker_pool.h"

#include <exception>
#include <system_error>

namespace cetview::brep {

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (auto& t : threads_) t.join();
}

std::uint64_t WorkerPool::joins() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return joins_;
}

void WorkerPool::startHelpers(unsigned helpers) {
  while (threads_.size() < helpers) {
    try {
      threads_.emplace_back([this] { loop(); });
    } catch (const std::system_error&) {
      return;  // fewer helpers; the callers do the rest
    }
  }
}

unsigned WorkerPool::start(unsigned threads) {
  std::lock_guard<std::mutex> lock(mutex_);
  startHelpers(threads > 1 ? threads - 1 : 0);
  return static_cast<unsigned>(threads_.size());
}

void WorkerPool::run(unsigned threads, const std::function<void(unsigned)>& body) {
  const unsigned helpers = threads > 1 ? threads - 1 : 0;
  bool shared = false;
  {
    // Another thread's run holds the pool, or no helper is wanted: this call works alone.
    std::lock_guard<std::mutex> lock(mutex_);
    if (!busy_ && helpers > 0) {
      shared = true;
      busy_ = true;
      startHelpers(helpers);
      body_ = &body;
      wanted_ = helpers;
      joined_ = 0;
      error_ = nullptr;
    }
  }
  if (!shared) {
    body(0);
    return;
  }
  wake_.notify_all();
  std::exception_ptr error;
  try {
    body(0);
  } catch (...) {
    error = std::current_exception();
  }
  {
    // Close the run (no helper joins any more) and wait for the helpers inside body.
    std::unique_lock<std::mutex> lock(mutex_);
    body_ = nullptr;
    idle_.wait(lock, [&] { return active_ == 0; });
    busy_ = false;
    if (!error) error = error_;
  }
  if (error) std::rethrow_exception(error);
}

void WorkerPool::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || (body_ && joined_ < wanted_); });
    if (stop_) return;
    const std::function<void(unsigned)>* body = body_;
    const unsigned worker = ++joined_;
    ++active_;
    ++joins_;
    lock.unlock();
    std::exception_ptr error;
    try {
      (*body)(worker);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error && !error_) error_ = error;
    if (--active_ == 0 && !body_) idle_.notify_all();
  }
}

}  // namespace cetview::brep
