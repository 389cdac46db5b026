// A minimal parallel for-each over indices with std::thread: work is claimed one index at a time
// from an atomic counter, so long and short items balance. threads <= 1 runs inline.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace cetview::brep {

// fn(index, worker) for every index in [0, count); worker is in [0, threads).
template <class Fn>
void parallelFor(std::size_t count, unsigned threads, Fn&& fn) {
  threads = static_cast<unsigned>(std::min<std::size_t>(std::max(1u, threads), std::max<std::size_t>(count, 1)));
  if (threads <= 1) {
    for (std::size_t i = 0; i < count; ++i) fn(i, 0u);
    return;
  }
  std::atomic<std::size_t> next{0};
  auto body = [&](unsigned worker) {
    for (std::size_t i = next.fetch_add(1, std::memory_order_relaxed); i < count;
         i = next.fetch_add(1, std::memory_order_relaxed))
      fn(i, worker);
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned w = 1; w < threads; ++w) pool.emplace_back(body, w);
  body(0);
  for (auto& t : pool) t.join();
}

}  // namespace cetview::brep
