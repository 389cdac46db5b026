// Idle workers lend themselves to busy ones. A tessellation run hands faces to its workers; once a
// worker has no face left it would sit idle until the others finish (the end of every level, and
// the whole run on a model of one large face). Instead it helps with the parallel sections that the
// busy workers open inside a face (FaceMesher's evaluation of a refinement pass): chunks of a
// section are claimed from an atomic counter by its owner and by any helper.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "brep/worker_pool.h"

namespace cetview::brep {

class WorkSharing {
 public:
  explicit WorkSharing(WorkerPool& pool) : pool_(pool) {}

  // Runs work(0) on the calling thread and work(1), ... work(threads - 1) on the pool's threads
  // that wake while the calls run (WorkerPool::run: work shares its items out itself), and
  // returns when all have returned. A worker whose call has returned helps with the sections
  // opened by the others until every call has returned. Not reentrant.
  void run(unsigned threads, const std::function<void(unsigned)>& work);

  // fn(begin, end) over [0, count) in chunks of at most `grain`, each exactly once, possibly on
  // other threads (fn must be safe to call concurrently); returns when every chunk is done. Runs
  // on the calling thread alone outside run() or when no worker is idle.
  void forEach(std::size_t count, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& fn);

  // Chunks run by helpers so far (a helper ran them, not the section's owner).
  std::size_t helpedChunks() const { return helpedChunks_.load(std::memory_order_relaxed); }

 private:
  struct Section {
    const std::function<void(std::size_t, std::size_t)>* fn = nullptr;
    std::size_t count = 0, grain = 1;
    std::atomic<std::size_t> next{0};
    int helpers = 0;  // helpers inside fn (guarded by mutex_)
    std::mutex errorMutex;
    std::exception_ptr error;  // the first exception fn threw, rethrown to the owner
  };
  static std::size_t drain(Section& s);  // chunks run
  void help();

  WorkerPool& pool_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Section*> open_;  // sections with chunks possibly left
  unsigned running_ = 0;        // workers whose call has not returned
  unsigned idle_ = 0;           // workers waiting to help
  std::atomic<std::size_t> helpedChunks_{0};
};

}  // namespace cetview::brep
