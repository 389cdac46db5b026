// Threads kept for a tessellator's parallel sections. Starting and joining threads for every
// section cost 0.1-0.5 ms a section on an idle 2-core machine and up to 2 ms beside a renderer:
// more than all of level 0 of a small model, whose level runs four or five sections. Pool threads
// sleep between sections. The caller starts on the work at once and a pool thread joins only
// while the caller's own call still runs, so a section never waits for a thread to wake.
//
// A tessellator makes its own pool unless it is given one (Tessellator::create): the viewer keeps
// one pool for every model it opens and starts its threads before the first model has loaded, so
// that no model's first level waits for a thread to start (0.1-0.3 ms each here).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cetview::brep {

class WorkerPool {
 public:
  WorkerPool() = default;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool();

  // Calls body(0) on the calling thread and body(1), body(2), ... (at most threads - 1 more) on
  // pool threads that wake while body(0) runs; returns once every call that started has returned.
  // body must therefore share its work out itself (an atomic counter) and not wait for a worker
  // that may never be called. The pool grows to threads - 1 threads; a thread that cannot start
  // leaves fewer helpers. The first exception a call throws is rethrown once every call has
  // returned. A run made while another is in progress (from another thread) runs
  // body(0) alone.
  void run(unsigned threads, const std::function<void(unsigned)>& body);

  // Starts the helpers a run with `threads` threads takes (threads - 1) now rather than at the
  // first such run. Returns the number of helper threads the pool has (fewer where one could not
  // start).
  unsigned start(unsigned threads);

  // Times a pool thread joined a run (tests).
  std::uint64_t joins() const;

 private:
  void loop();
  void startHelpers(unsigned helpers);  // mutex_ held

  mutable std::mutex mutex_;
  std::condition_variable wake_;  // pool threads: a run opened, or stop
  std::condition_variable idle_;  // the caller: the last helper returned
  std::vector<std::thread> threads_;
  const std::function<void(unsigned)>* body_ = nullptr;  // the open run, null when none
  unsigned wanted_ = 0;                                  // helpers the open run takes
  unsigned joined_ = 0;                                  // helpers that joined the open run
  unsigned active_ = 0;                                  // helpers inside body
  bool busy_ = false;  // a run is in progress (open or waiting for its helpers)
  bool stop_ = false;
  std::exception_ptr error_;  // the first exception a helper's body threw in the open run
  std::uint64_t joins_ = 0;
};

// fn(index) for every index in [0, count), claimed one at a time from an atomic counter by the
// caller and by the pool's helpers (at most threads - 1). threads <= 1 or one index runs inline.
template <class Fn>
void parallelFor(WorkerPool& pool, std::size_t count, unsigned threads, Fn&& fn);

}  // namespace cetview::brep

#include <atomic>

namespace cetview::brep {

template <class Fn>
void parallelFor(WorkerPool& pool, std::size_t count, unsigned threads, Fn&& fn) {
  if (threads <= 1 || count <= 1) {
    for (std::size_t i = 0; i < count; ++i) fn(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  pool.run(threads, [&](unsigned) {
    for (std::size_t i = next.fetch_add(1, std::memory_order_relaxed); i < count;
         i = next.fetch_add(1, std::memory_order_relaxed))
      fn(i);
  });
}

}  // namespace cetview::brep
