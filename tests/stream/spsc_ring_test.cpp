// The SPSC ring: empty, full, wrap-around, records larger than the ring, and a two-thread stress test
// (run it under -DCETVIEW_SANITIZE=thread to check the memory ordering).
#include "stream/spsc_ring.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <numeric>
#include <random>
#include <thread>

namespace cetview::stream {
namespace {

std::vector<std::uint8_t> pattern(std::size_t n, std::uint32_t seed) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>((i * 131 + seed * 7) & 0xFF);
  return v;
}

TEST(SpscRing, EmptyRingHasNothing) {
  SpscRing ring(256);
  SpscRing::View v;
  EXPECT_FALSE(ring.tryRead(v));
  EXPECT_EQ(ring.usedBytes(), 0u);
  EXPECT_EQ(ring.capacity(), 256u);
}

TEST(SpscRing, CapacityIsRoundedToAPowerOfTwo) {
  EXPECT_EQ(SpscRing(100).capacity(), 128u);
  EXPECT_EQ(SpscRing(1).capacity(), 64u);
  EXPECT_EQ(SpscRing(256).maxRecordSize(), 120u);
}

// Resident memory of this process in bytes (Linux), or 0 where /proc cannot tell.
std::size_t residentBytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * 4096;
}

// A ring's memory is touched only as records reach it: the streams make one of 4 MiB per worker
// for every model, and a tiny model writes a few kilobytes. Zeroing them (std::make_unique)
// took 2.3 ms before a tiny model's first frame and 9 MB of resident memory.
TEST(SpscRing, EmptyRingTakesNoResidentMemory) {
  const std::size_t before = residentBytes();
  if (before == 0) GTEST_SKIP() << "no /proc/self/statm";
  SpscRing ring(std::size_t{64} << 20);
  ASSERT_TRUE(ring.tryWrite("record", 6, 1));
  EXPECT_LT(residentBytes(), before + (std::size_t{8} << 20)) << "a 64 MiB ring with one record";
}

TEST(SpscRing, FullRingRefusesAndRecoversAfterRelease) {
  SpscRing ring(256);
  const auto rec = pattern(56, 1);  // 64 bytes with its header: four fit
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(ring.tryWrite(rec.data(), rec.size(), static_cast<std::uint32_t>(i)));
  EXPECT_FALSE(ring.tryWrite(rec.data(), rec.size(), 9));
  EXPECT_FALSE(ring.tryWrite(rec.data(), 1, 9));
  SpscRing::View v;
  ASSERT_TRUE(ring.tryRead(v));
  EXPECT_EQ(v.tag, 0u);
  EXPECT_FALSE(ring.tryWrite(rec.data(), rec.size(), 9)) << "not released yet";
  ring.release();
  EXPECT_TRUE(ring.tryWrite(rec.data(), rec.size(), 4));
}

// A record written as two pieces (RecordWriter's fragment header and payload, with no copy in
// between) reads back as one record holding both, in order, also where it follows a skipped tail.
TEST(SpscRing, TwoPiecesMakeOneRecord) {
  SpscRing ring(256);
  for (std::uint32_t round = 0; round < 12; ++round) {
    const auto a = pattern(8 + round, round), b = pattern(40 + 3 * round, round + 100);
    ASSERT_TRUE(ring.tryWrite(a.data(), a.size(), b.data(), b.size(), round));
    SpscRing::View v;
    ASSERT_TRUE(ring.tryRead(v));
    EXPECT_EQ(v.tag, round);
    ASSERT_EQ(v.size, a.size() + b.size());
    EXPECT_EQ(std::memcmp(v.data, a.data(), a.size()), 0);
    EXPECT_EQ(std::memcmp(v.data + a.size(), b.data(), b.size()), 0);
    ring.release();
  }
  const auto a = pattern(5, 7);
  ASSERT_TRUE(ring.tryWrite(a.data(), a.size(), nullptr, 0, 3)) << "an empty second piece";
  SpscRing::View v;
  ASSERT_TRUE(ring.tryRead(v));
  EXPECT_EQ(v.size, a.size());
}

TEST(SpscRing, WrapAroundKeepsRecordsContiguousAndInOrder) {
  SpscRing ring(256);
  std::uint32_t written = 0, read = 0;
  // Sizes that do not divide the capacity force skips at the end of the array.
  for (int round = 0; round < 200; ++round) {
    const std::size_t size = 1 + static_cast<std::size_t>((round * 37) % 100);
    const auto rec = pattern(size, written);
    while (!ring.tryWrite(rec.data(), rec.size(), written)) {
      SpscRing::View v;
      ASSERT_TRUE(ring.tryRead(v));
      ASSERT_EQ(v.tag, read);
      const std::size_t expectedSize = 1 + static_cast<std::size_t>((read * 37) % 100);
      ASSERT_EQ(v.size, expectedSize);
      ASSERT_EQ(std::memcmp(v.data, pattern(expectedSize, read).data(), expectedSize), 0);
      ring.release();
      ++read;
    }
    ++written;
  }
  SpscRing::View v;
  while (ring.tryRead(v)) {
    ASSERT_EQ(v.tag, read++);
    ring.release();
  }
  EXPECT_EQ(read, written);
}

TEST(RecordStream, RecordsLargerThanTheRingArriveWhole) {
  SpscRing ring(1024);
  RecordWriter writer(ring);
  RecordReader reader(ring);
  const auto big = pattern(100000, 3);  // ~200 fragments
  std::size_t records = 0;
  // Single thread: the writer's wait() drains the reader, as a renderer frame would.
  std::vector<std::uint8_t> received;
  auto drain = [&] {
    RecordReader::Record r;
    while (reader.next(r)) {
      received.assign(r.data, r.data + r.size);
      EXPECT_EQ(r.tag, 77u);
      ++records;
    }
    return true;
  };
  ASSERT_TRUE(writer.write(big.data(), big.size(), 77, drain));
  drain();
  EXPECT_EQ(records, 1u);
  EXPECT_EQ(received, big);
}

TEST(RecordStream, CancelledRecordIsNeverDelivered) {
  SpscRing ring(1024);
  RecordWriter writer(ring);
  RecordReader reader(ring);
  const auto big = pattern(5000, 4);
  int waits = 0;
  EXPECT_FALSE(writer.write(big.data(), big.size(), 1, [&] { return ++waits < 2; }));
  RecordReader::Record r;
  EXPECT_FALSE(reader.next(r)) << "the fragments of the cancelled record stay partial";
  const auto small = pattern(10, 5);
  ASSERT_TRUE(writer.write(small.data(), small.size(), 2, [&] {
    RecordReader::Record ignored;
    while (reader.next(ignored)) ADD_FAILURE() << "nothing complete before the small record";
    return true;
  }));
  ASSERT_TRUE(reader.next(r));
  EXPECT_EQ(r.tag, 2u);
  EXPECT_EQ(std::vector<std::uint8_t>(r.data, r.data + r.size), small);
}

TEST(RecordStream, TwoThreadStressDeliversEverythingInOrder) {
  SpscRing ring(4096);
  constexpr std::uint32_t kRecords = 20000;
  std::thread producer([&] {
    RecordWriter writer(ring);
    std::mt19937 rng(1);
    for (std::uint32_t i = 0; i < kRecords; ++i) {
      const std::size_t size = (i % 97 == 0) ? 10000 : 1 + rng() % 500;  // some span many fragments
      const auto rec = pattern(size, i);
      writer.write(rec.data(), rec.size(), i, [] {
        std::this_thread::yield();
        return true;
      });
    }
  });
  RecordReader reader(ring);
  std::uint32_t expected = 0;
  std::mt19937 rng(1);
  while (expected < kRecords) {
    RecordReader::Record r;
    if (!reader.next(r)) {
      std::this_thread::yield();
      continue;
    }
    const std::size_t size = (expected % 97 == 0) ? 10000 : 1 + rng() % 500;
    ASSERT_EQ(r.tag, expected);
    ASSERT_EQ(r.size, size);
    ASSERT_EQ(std::memcmp(r.data, pattern(size, expected).data(), size), 0);
    ++expected;
  }
  producer.join();
}

}  // namespace
}  // namespace cetview::stream
