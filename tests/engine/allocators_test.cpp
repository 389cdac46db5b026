// The pure bookkeeping behind uploads: the ring allocator (upload ring), the range allocator
// (index and edge slots) and the dirty set (table entries).
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "engine/dirty_set.h"
#include "engine/range_allocator.h"
#include "engine/ring_allocator.h"

namespace cetview::test {
namespace {

using namespace engine;

TEST(RingAllocatorTest, AllocatesInOrderAndAligns) {
  RingAllocator ring(256);
  EXPECT_EQ(ring.allocate(10, 16), 0u);
  EXPECT_EQ(ring.allocate(10, 16), 16u);
  EXPECT_EQ(ring.allocate(1, 4), 28u);
  EXPECT_EQ(ring.used(), 29u);
}

TEST(RingAllocatorTest, RefusesWhenFullUntilReleased) {
  RingAllocator ring(256);
  ASSERT_TRUE(ring.allocate(128, 16));
  std::uint64_t frame1 = ring.mark();
  ASSERT_TRUE(ring.allocate(128, 16));
  EXPECT_FALSE(ring.allocate(16, 16));
  ring.release(frame1);
  EXPECT_EQ(ring.allocate(16, 16), 0u);  // wrapped to the start
}

TEST(RingAllocatorTest, BlocksNeverStraddleTheEnd) {
  RingAllocator ring(256);
  ASSERT_TRUE(ring.allocate(200, 16));
  ring.release(ring.mark());
  // 56 bytes are left before the end: a 64-byte block skips them and starts at 0.
  auto offset = ring.allocate(64, 16);
  ASSERT_TRUE(offset);
  EXPECT_EQ(*offset, 0u);
  EXPECT_FALSE(ring.allocate(257, 16));
  EXPECT_FALSE(ring.allocate(0, 16));
}

TEST(RingAllocatorTest, RandomTrafficNeverOverlapsLiveBlocks) {
  RingAllocator ring(4096);
  std::mt19937 rng(7);
  struct Block {
    std::uint64_t offset, size;
  };
  std::vector<std::vector<Block>> frames(3);  // blocks of the frames in flight
  std::vector<std::uint64_t> marks(3, 0);
  for (int frame = 0; frame < 2000; ++frame) {
    int slot = frame % 3;
    ring.release(marks[slot]);
    frames[slot].clear();
    for (int k = 0; k < 8; ++k) {
      std::uint64_t size = 1 + rng() % 300;
      auto offset = ring.allocate(size, 16);
      if (!offset) break;
      ASSERT_EQ(*offset % 16, 0u);
      ASSERT_LE(*offset + size, 4096u);
      for (const auto& live : frames) {
        for (const Block& b : live) ASSERT_TRUE(*offset + size <= b.offset || b.offset + b.size <= *offset);
      }
      frames[slot].push_back({*offset, size});
    }
    marks[slot] = ring.mark();
  }
}

TEST(RangeAllocatorTest, BestFitAndCoalescing) {
  RangeAllocator a(100);
  auto x = a.allocate(10), y = a.allocate(20), z = a.allocate(30);
  ASSERT_TRUE(x && y && z);
  EXPECT_EQ(*x, 0u);
  EXPECT_EQ(*y, 10u);
  EXPECT_EQ(*z, 30u);
  a.free(*y, 20);
  // Best fit: a 15-element request takes the 20-element hole, not the 40-element tail.
  EXPECT_EQ(a.allocate(15), 10u);
  a.free(10, 15);
  a.free(*x, 10);
  a.free(*z, 30);
  EXPECT_EQ(a.freeRangeCount(), 1u);
  EXPECT_EQ(a.largestFree(), 100u);
  EXPECT_EQ(a.freeCount(), 100u);
}

TEST(RangeAllocatorTest, GrowExtendsTheTrailingFreeRange) {
  RangeAllocator a(10);
  ASSERT_EQ(a.allocate(6), 0u);
  EXPECT_FALSE(a.allocate(8));
  a.grow(20);
  EXPECT_EQ(a.largestFree(), 14u);
  EXPECT_EQ(a.freeRangeCount(), 1u);
  EXPECT_EQ(a.allocate(8), 6u);
}

TEST(RangeAllocatorTest, RandomTrafficKeepsRangesDisjoint) {
  RangeAllocator a(1000);
  std::map<std::uint64_t, std::uint64_t> live;  // offset -> count
  std::mt19937 rng(11);
  std::uint64_t used = 0;
  for (int step = 0; step < 20000; ++step) {
    if (live.empty() || rng() % 3 != 0) {
      std::uint64_t count = 1 + rng() % 50;
      auto offset = a.allocate(count);
      if (!offset) {
        a.grow(a.capacity() * 2);
        offset = a.allocate(count);
      }
      ASSERT_TRUE(offset);
      auto next = live.lower_bound(*offset);
      if (next != live.end()) {
        ASSERT_LE(*offset + count, next->first);
      }
      if (next != live.begin()) {
        ASSERT_LE(std::prev(next)->first + std::prev(next)->second, *offset);
      }
      live[*offset] = count;
      used += count;
    } else {
      auto it = live.begin();
      std::advance(it, rng() % live.size());
      a.free(it->first, it->second);
      used -= it->second;
      live.erase(it);
    }
    ASSERT_EQ(a.freeCount() + used, a.capacity());
  }
}

TEST(DirtySetTest, MarksOnceInFirstMarkedOrder) {
  DirtySet s;
  s.mark(5);
  s.mark(2);
  s.mark(5);
  s.mark(9);
  s.unmark(2);
  std::vector<std::uint32_t> order;
  std::uint32_t i = 0;
  while (s.front(&i)) {
    order.push_back(i);
    s.popFront();
  }
  EXPECT_EQ(order, (std::vector<std::uint32_t>{5, 9}));
  EXPECT_TRUE(s.empty());
  s.mark(5);  // can be marked again after it was consumed
  EXPECT_TRUE(s.contains(5));
}

}  // namespace
}  // namespace cetview::test
