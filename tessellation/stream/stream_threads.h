// What a viewer keeps for every model it opens: the tessellator's pool (brep::WorkerPool, the
// workers' helpers), the thread a ProgressiveStream's coordinator runs on and the stream's rings.
// Made before a model has loaded (the window makes them with its renderer), they spare each model's
// first level the start of its threads (0.1-0.3 ms a thread on the project's 2-core virtual
// machines) and the allocation of its rings (0.2 ms for two 4 MiB rings), against 1-3 ms for the
// whole first frame of a small model.
//
// Use: StreamThreads kept(n); Tessellator::create(model, params, kept.pool()); a StreamOptions with
// threads = n and kept = &kept. One stream at a time runs its coordinator here and writes into
// these rings (emptied for it); another stream made meanwhile starts a thread and rings of its own.
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "brep/worker_pool.h"
#include "stream/spsc_ring.h"

namespace cetview::stream {

constexpr std::size_t kDefaultRingBytes = std::size_t{4} << 20;  // per worker
constexpr std::size_t kControlRingBytes = std::size_t{1} << 20;

class StreamThreads {
 public:
  // Starts the coordinator thread and the pool's helpers for `threads` workers, and makes a ring of
  // `ringBytes` per worker (StreamOptions::ringBytes) and the control ring.
  explicit StreamThreads(unsigned threads, std::size_t ringBytes = kDefaultRingBytes);
  ~StreamThreads();  // waits for a task in progress: its stream must have stopped it
  StreamThreads(const StreamThreads&) = delete;
  StreamThreads& operator=(const StreamThreads&) = delete;

  unsigned threads() const { return threads_; }
  std::size_t ringBytes() const { return ringBytes_; }
  const std::shared_ptr<brep::WorkerPool>& pool() const { return pool_; }

  // Takes the coordinator thread and the rings for one stream: false when another stream holds
  // them (or the thread could not start). The holder empties the rings it uses, then launch()es
  // its coordinator; finish() gives them back once the coordinator has returned.
  bool acquire();
  void launch(std::function<void()> task);
  void finish();
  void release();  // gives them back unlaunched (the holder failed before it could launch)
  SpscRing& workerRing(std::size_t i) { return *rings_[i]; }
  SpscRing& controlRing() { return *control_; }
  // Tasks run so far (tests).
  unsigned tasksRun() const;

 private:
  void loop();

  unsigned threads_;
  std::size_t ringBytes_;
  std::shared_ptr<brep::WorkerPool> pool_;
  std::vector<std::unique_ptr<SpscRing>> rings_;
  std::unique_ptr<SpscRing> control_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> task_;
  bool busy_ = false;  // acquired, until the launched task has returned
  bool stop_ = false;
  unsigned tasksRun_ = 0;
  std::thread thread_;
};

}  // namespace cetview::stream
