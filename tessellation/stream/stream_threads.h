// The threads a viewer keeps for every model it opens: the tessellator's pool (brep::WorkerPool,
// the workers' helpers) and the thread a ProgressiveStream's coordinator runs on. Started before a
// model has loaded (the window opens them with its renderer), they spare each model's first level
// the start of its threads: 0.1-0.3 ms a thread on the project's 2-core virtual machines, against
// 1-3 ms for the whole first frame of a small model.
//
// Use: StreamThreads kept(n); Tessellator::create(model, params, kept.pool()); a StreamOptions with
// threads = n and kept = &kept. One stream at a time runs its coordinator here; another stream
// made meanwhile starts a thread of its own.
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include "brep/worker_pool.h"

namespace cetview::stream {

class StreamThreads {
 public:
  // Starts the coordinator thread and the pool's helpers for `threads` workers.
  explicit StreamThreads(unsigned threads);
  ~StreamThreads();  // waits for a task in progress: its stream must have stopped it
  StreamThreads(const StreamThreads&) = delete;
  StreamThreads& operator=(const StreamThreads&) = delete;

  unsigned threads() const { return threads_; }
  const std::shared_ptr<brep::WorkerPool>& pool() const { return pool_; }

  // Runs `task` on the coordinator thread and returns true, or returns false at once when a task is
  // still in progress there (or the thread could not start).
  bool launch(std::function<void()> task);
  // Waits until the launched task has returned.
  void finish();
  // Tasks run so far (tests).
  unsigned tasksRun() const;

 private:
  void loop();

  unsigned threads_;
  std::shared_ptr<brep::WorkerPool> pool_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> task_;
  bool busy_ = false;  // a task is launched and has not returned
  bool stop_ = false;
  unsigned tasksRun_ = 0;
  std::thread thread_;
};

}  // namespace cetview::stream
