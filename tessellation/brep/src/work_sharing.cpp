#include "work_sharing.h"

#include <algorithm>

namespace cetview::brep {

void WorkSharing::run(unsigned threads, const std::function<void(unsigned)>& work) {
  threads = std::max(1u, threads);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    running_ = 1;  // the caller, worker 0, counts from the start: helpers may run before it
    idle_ = 0;
  }
  std::vector<std::exception_ptr> errors(threads);
  pool_.run(threads, [&](unsigned worker) {
    if (worker != 0) {
      // A helper counts from its start: one that joins late finds no work, returns, and helps.
      std::lock_guard<std::mutex> lock(mutex_);
      ++running_;
    }
    try {
      work(worker);
    } catch (...) {
      errors[worker] = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --running_;
    }
    changed_.notify_all();
    help();
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

void WorkSharing::help() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    ++idle_;
    changed_.wait(lock, [&] { return running_ == 0 || !open_.empty(); });
    --idle_;
    if (open_.empty()) return;  // every worker's call has returned: no section can open any more
    Section* s = open_.back();
    ++s->helpers;
    lock.unlock();
    helpedChunks_.fetch_add(drain(*s), std::memory_order_relaxed);
    lock.lock();
    --s->helpers;
    // Every chunk is claimed: no one else needs to look at it (its owner may still be waiting).
    const auto it = std::find(open_.begin(), open_.end(), s);
    if (it != open_.end()) open_.erase(it);
    changed_.notify_all();
  }
}

std::size_t WorkSharing::drain(Section& s) {
  for (std::size_t chunks = 0;; ++chunks) {
    const std::size_t begin = s.next.fetch_add(s.grain, std::memory_order_relaxed);
    if (begin >= s.count) return chunks;
    try {
      (*s.fn)(begin, std::min(begin + s.grain, s.count));
    } catch (...) {
      std::lock_guard<std::mutex> lock(s.errorMutex);
      if (!s.error) s.error = std::current_exception();
    }
  }
}

void WorkSharing::forEach(std::size_t count, std::size_t grain,
                          const std::function<void(std::size_t, std::size_t)>& fn) {
  grain = std::max<std::size_t>(grain, 1);
  bool share;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    share = idle_ > 0 && count > grain;
  }
  if (!share) {
    for (std::size_t begin = 0; begin < count; begin += grain) fn(begin, std::min(begin + grain, count));
    return;
  }
  Section s;
  s.fn = &fn, s.count = count, s.grain = grain;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    open_.push_back(&s);
  }
  changed_.notify_all();
  drain(s);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto it = std::find(open_.begin(), open_.end(), &s);
    if (it != open_.end()) open_.erase(it);
    changed_.wait(lock, [&] { return s.helpers == 0; });
  }
  if (s.error) std::rethrow_exception(s.error);
}

}  // namespace cetview::brep
