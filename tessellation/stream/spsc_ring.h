// A bounded, lock-free, single-producer single-consumer ring of variable-size records.
//
// The producer (a tessellation worker) writes each record once into the ring's memory; the consumer
// (the render thread) reads it in place and releases it. Neither side ever blocks the other: a full
// ring makes tryWrite() return false (the worker then waits: back-pressure), an empty one makes
// tryRead() return false (the renderer draws what it has and never waits).
//
// Layout: a power-of-two byte array; read and write positions are monotonically increasing byte
// counters (acquire/release atomics, each on its own cache line). A record is an 8-byte header (size,
// kind) then its payload padded to 8 bytes, always contiguous: when it does not fit before the end
// of the array, a skip header fills the tail and the record starts again at offset 0.
//
// Records longer than maxRecordSize() are split by RecordWriter into fragments and joined again by
// RecordReader, so any size streams through a small ring.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace cetview::stream {

class SpscRing {
 public:
  // Capacity in bytes, rounded up to a power of two, at least 64.
  explicit SpscRing(std::size_t capacityBytes);
  SpscRing(const SpscRing&) = delete;
  SpscRing& operator=(const SpscRing&) = delete;

  std::size_t capacity() const { return mask_ + 1; }
  // The largest payload tryWrite() can ever accept (half the ring, less the header).
  std::size_t maxRecordSize() const { return capacity() / 2 - kHeader; }

  // --- producer thread only ---
  // Copies `size` bytes (size <= maxRecordSize()) as one record; false if the ring is too full now.
  bool tryWrite(const void* data, std::size_t size, std::uint32_t tag = 0) {
    return tryWrite(data, size, nullptr, 0, tag);
  }
  // One record of two pieces back to back (a fragment's header and its payload), with no copy in
  // between.
  bool tryWrite(const void* first, std::size_t firstSize, const void* second, std::size_t secondSize,
                std::uint32_t tag);

  // --- consumer thread only ---
  struct View {
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    std::uint32_t tag = 0;
  };
  // The oldest record, in place; false if there is none. The view stays valid until release().
  bool tryRead(View& view);
  // Releases the record returned by the last successful tryRead().
  void release();

  // Bytes in use (approximate when read while the other side works).
  std::size_t usedBytes() const;

  // Empties the ring for a new producer and consumer; neither side may be using it.
  void reset();

 private:
  static constexpr std::size_t kHeader = 8;
  static constexpr std::uint32_t kSkip = 0xFFFFFFFFu;  // tag of a header that pads the array's tail

  std::unique_ptr<std::uint8_t[]> buffer_;
  std::size_t mask_;
  alignas(64) std::atomic<std::uint64_t> write_{0};
  alignas(64) std::atomic<std::uint64_t> read_{0};
  alignas(64) std::uint64_t pendingRelease_ = 0;  // consumer: where release() moves read_ to
};

// Producer side: writes records of any size, splitting those longer than the ring allows into
// fragments. write() waits for space by calling `wait()` between attempts and gives up (returns
// false) when wait() returns false, e.g. on cancellation; the fragments already written are never
// returned by a RecordReader as a record (it drops a partial record when a new one begins).
class RecordWriter {
 public:
  explicit RecordWriter(SpscRing& ring) : ring_(ring) {}
  template <class Wait>
  bool write(const void* data, std::size_t size, std::uint32_t tag, Wait&& wait);

 private:
  bool tryFragment(const std::uint8_t* data, std::size_t size, std::uint32_t tag, std::uint32_t flags,
                   std::uint64_t total);
  SpscRing& ring_;
};

// Consumer side: returns whole records. Unfragmented ones are read in place; fragmented ones are
// joined into an internal buffer as their fragments arrive (a partial record is never returned).
class RecordReader {
 public:
  explicit RecordReader(SpscRing& ring) : ring_(ring) {}
  struct Record {
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    std::uint32_t tag = 0;
  };
  // The next complete record, if one is available now. Valid until the next call of next().
  bool next(Record& record);

 private:
  SpscRing& ring_;
  bool holding_ = false;  // a ring record is held (released on the next call)
  std::vector<std::uint8_t> joined_;
  std::uint64_t joinedTotal_ = 0;
  bool joining_ = false;
};

// Fragment header, in front of every RecordWriter payload.
struct FragmentHeader {
  std::uint32_t flags;  // kFirst | kLast
  std::uint32_t reserved;
  std::uint64_t total;  // the whole record's size
  static constexpr std::uint32_t kFirst = 1, kLast = 2;
};

template <class Wait>
bool RecordWriter::write(const void* data, std::size_t size, std::uint32_t tag, Wait&& wait) {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  const std::size_t chunk = ring_.maxRecordSize() - sizeof(FragmentHeader);
  std::size_t offset = 0;
  do {
    const std::size_t n = size - offset < chunk ? size - offset : chunk;
    std::uint32_t flags = 0;
    if (offset == 0) flags |= FragmentHeader::kFirst;
    if (offset + n == size) flags |= FragmentHeader::kLast;
    while (!tryFragment(bytes + offset, n, tag, flags, size)) {
      // Cancelled mid-record: the reader drops the partial record when the next one starts.
      if (!wait()) return false;
    }
    offset += n;
  } while (offset < size);
  return true;
}

}  // namespace cetview::stream
