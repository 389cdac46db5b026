// The producer side of progressive loading (DESIGN.md "Data flow", steps 2-6): worker threads take a
// model coarse to fine, level-major (every face reaches level k before any face goes finer, so the
// whole model is on screen first), larger faces first within a level, and publish each face's level
// into their own SpscRing. A control ring carries one kLevelDone record per completed level.
//
// Threads: one coordinator runs the levels; per level it discretises the edges (all threads) and
// then runs `threads` workers over the faces (a model whose level 0 is cheaper than waking them,
// firstLevelIsCheap(), has its level 0 made by the constructor's caller instead). A full ring makes
// its worker wait (back-pressure); setTargetLevel() and the destructor cancel outstanding work at
// once (the tessellator checks the flag between refinement passes), and a cancelled level resumes
// from its current state later.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "brep/tessellator.h"
#include "stream/spsc_ring.h"
#include "stream/stream_threads.h"
#include "stream/update_records.h"

namespace cetview::stream {

struct StreamOptions {
  unsigned threads = 1;
  std::size_t ringBytes = kDefaultRingBytes;  // per worker; larger records are fragmented
  // Called on the coordinator thread once a level's completion record is in the control ring:
  // wakes a consumer that sleeps in an event loop (the window posts an empty event). Must be quick
  // and safe from any thread.
  std::function<void()> onLevelPublished;
  // Threads and rings kept across models (stream_threads.h): the coordinator runs on the kept thread
  // and writes into the kept rings (when they are for as many workers of ringBytes) when no other
  // stream holds them, else on a thread and rings of the stream's own. The tessellator's pool is
  // the caller's business (Tessellator::create(..., kept->pool())). Must outlive the stream.
  StreamThreads* kept = nullptr;
  // Level 0 of a model for which firstLevelIsCheap() holds is made on the constructor's thread,
  // before the coordinator starts (when the rings take it without waiting for a reader).
  bool firstLevelOnCaller = true;
};

// A model of a few analytic faces (at most 16 faces of planes, cylinders, cones, spheres and tori,
// 64 edges): its level 0 takes less than handing it to the coordinator and workers and waking the
// consumer again (0.1-0.3 ms on a virtual machine), so the caller makes it at once.
bool firstLevelIsCheap(const brep::Model& model);

// A snapshot of progress, for panels and the terminal.
struct StreamProgress {
  int levelInProgress = -1;      // -1 when idle
  int lastCompleteLevel = -1;
  std::uint32_t facesDoneInLevel = 0;
  std::uint32_t faceCount = 0;
  int targetLevel = 0;
};

class ProgressiveStream {
 public:
  // `tessellator` must outlive the stream and not be advanced by anyone else meanwhile. Starts
  // working towards `targetLevel` (clamped to the schedule) at once.
  ProgressiveStream(brep::Tessellator& tessellator, int targetLevel, const StreamOptions& options);
  ~ProgressiveStream();  // cancels and joins; returns within about one refinement pass
  ProgressiveStream(const ProgressiveStream&) = delete;
  ProgressiveStream& operator=(const ProgressiveStream&) = delete;

  // Any thread. Finer: work continues from the current state. Coarser: work beyond it is cancelled
  // (faces already finer keep their levels; the consumer decides what to show).
  void setTargetLevel(int level);
  int targetLevel() const { return target_.load(); }
  StreamProgress progress() const;
  // True once every face reached the target level and the coordinator waits.
  bool idle() const;
  // Sleeps until the completion record of `level` (or a finer one) is in the control ring, or for
  // `timeout` at most: a headless consumer's loop wakes as soon as a level can be shown.
  void waitForLevel(int level, std::chrono::microseconds timeout) const;

  // Consumer side: the worker rings and the control ring (read from one consumer thread only).
  std::size_t workerRingCount() const { return rings_.size(); }
  SpscRing& workerRing(std::size_t i) { return *rings_[i]; }
  SpscRing& controlRing() { return *control_; }
  // The coordinator runs on StreamOptions::kept (tests).
  bool onKeptThread() const { return onKept_; }
  // Level 0 was made by the constructor's caller (StreamOptions::firstLevelOnCaller; tests).
  bool firstLevelMadeByCaller() const { return firstLevelByCaller_; }

 private:
  void setUpRings();  // the kept rings, emptied, or rings of its own
  void coordinate();
  // Level 0 on the calling thread, without ever waiting for the reader that does not exist yet:
  // when a ring is full the level is left, as if cancelled, to the coordinator.
  void makeFirstLevelHere();
  bool runLevel(int level, unsigned threads);
  bool publishLevelDone(int level);  // false when the record could not be written
  void publishFace(RecordWriter& writer, std::vector<std::uint8_t>& buffer, brep::FaceId face, int level,
                   brep::FaceStatus status, std::uint32_t& sentVertices);
  bool waitForSpace();
  bool publishEdges(int level);  // false when the record could not be written

  brep::Tessellator& tess_;
  StreamOptions options_;
  std::vector<brep::FaceId> order_;  // faces by decreasing area
  std::vector<std::uint32_t> sent_;  // per face: vertices already published
  std::vector<SpscRing*> rings_;     // the kept rings or ownRings_
  SpscRing* control_ = nullptr;
  std::vector<std::unique_ptr<SpscRing>> ownRings_;  // own rings_ and control_, when not kept
  std::chrono::steady_clock::time_point start_;

  std::atomic<int> target_{0};
  std::atomic<int> inProgress_{-1};
  std::atomic<int> complete_{-1};
  std::atomic<std::uint32_t> facesDone_{0};
  std::atomic<bool> cancel_{false};  // abandon the level in progress
  std::atomic<bool> stop_{false};    // shut down
  int edgesPublished_ = -1;          // the last level whose edge record is written (by the level's runner)
  bool onCaller_ = false;            // the constructor's caller runs level 0: never wait for ring space
  bool firstLevelByCaller_ = false;
  int published_ = -1;               // the last level whose completion record is written (guarded by mutex_)
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  mutable std::condition_variable publishedChanged_;
  std::thread coordinator_;  // when the coordinator does not run on options_.kept
  bool onKept_ = false;      // it runs on options_.kept
};

}  // namespace cetview::stream
