// The tessellator's thread pool (worker_pool.h): every index of a parallel section runs exactly
// once, pool threads do join, a helper's exception reaches the caller, a run made while another
// holds the pool works alone instead of waiting, and the pool is reused across runs.
#include "brep/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cetview::brep {
namespace {

// A parallel section of 300 items of 50 us each on three threads: every item runs once (checked
// here); adds the threads that ran items to `threads`.
void runSection(WorkerPool& pool, std::set<std::thread::id>& threads) {
  std::mutex mutex;
  std::vector<std::atomic<int>> hits(300);
  parallelFor(pool, hits.size(), 3, [&](std::size_t i) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      threads.insert(std::this_thread::get_id());
    }
    std::this_thread::sleep_for(std::chrono::microseconds(50));
    hits[i].fetch_add(1);
  });
  for (const auto& h : hits) ASSERT_EQ(h.load(), 1);
}

TEST(WorkerPool, EveryIndexRunsOnceAndThePoolThreadsHelp) {
  WorkerPool pool;
  std::set<std::thread::id> threads;
  for (int run = 0; run < 20; ++run) {
    SCOPED_TRACE(run);
    runSection(pool, threads);
  }
  // 300 items of 50 us each: the two pool threads wake long before the caller is through.
  EXPECT_EQ(threads.size(), 3u);
  EXPECT_GT(pool.joins(), 0u);
}

TEST(WorkerPool, WorkerIndicesAreDistinctAndBelowTheThreadCount) {
  WorkerPool pool;
  for (int run = 0; run < 20; ++run) {
    std::mutex mutex;
    std::vector<int> calls(4, 0);
    pool.run(4, [&](unsigned worker) {
      ASSERT_LT(worker, 4u);
      std::lock_guard<std::mutex> lock(mutex);
      ++calls[worker];
    });
    EXPECT_EQ(calls[0], 1);
    for (int c : calls) EXPECT_LE(c, 1);
  }
}

TEST(WorkerPool, AHelpersExceptionReachesTheCaller) {
  WorkerPool pool;
  std::atomic<bool> helperRan{false};
  EXPECT_THROW(pool.run(2,
                        [&](unsigned worker) {
                          if (worker == 0) {
                            // Hold the run open until the helper has been and thrown.
                            while (!helperRan.load())
                              std::this_thread::sleep_for(std::chrono::microseconds(100));
                            return;
                          }
                          helperRan = true;
                          throw std::runtime_error("helper");
                        }),
               std::runtime_error);
  // The caller's own exception too, and the pool is usable afterwards.
  EXPECT_THROW(pool.run(2,
                        [](unsigned worker) {
                          if (worker == 0) throw std::logic_error("caller");
                        }),
               std::logic_error);
  std::atomic<int> sum{0};
  parallelFor(pool, 100, 2, [&](std::size_t) { ++sum; });
  EXPECT_EQ(sum.load(), 100);
}

// start() makes the helpers ahead of the first run (a viewer starts them before a model loads);
// runs then use those threads and start no more.
TEST(WorkerPool, HelpersStartedAheadServeTheRuns) {
  WorkerPool pool;
  EXPECT_EQ(pool.start(1), 0u);  // one thread: the caller alone
  EXPECT_EQ(pool.start(3), 2u);
  EXPECT_EQ(pool.start(2), 2u);  // never fewer
  std::set<std::thread::id> threads;
  runSection(pool, threads);
  EXPECT_EQ(threads.size(), 3u);
  EXPECT_EQ(pool.start(3), 2u);  // the run started no thread of its own
}

TEST(WorkerPool, ARunWhileAnotherHoldsThePoolWorksAlone) {
  WorkerPool pool;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<bool> holding{false};
  std::thread holder([&] {
    pool.run(2, [&](unsigned worker) {
      if (worker != 0) return;
      holding = true;
      released.wait();
    });
  });
  while (!holding.load()) std::this_thread::sleep_for(std::chrono::microseconds(100));
  std::vector<unsigned> workers;
  pool.run(3, [&](unsigned worker) { workers.push_back(worker); });  // must not wait for the holder
  EXPECT_EQ(workers, std::vector<unsigned>{0u});
  release.set_value();
  holder.join();
}

}  // namespace
}  // namespace cetview::brep
