#include "spsc_ring.h"

#include <cassert>
#include <cstring>

namespace cetview::stream {
namespace {

std::size_t roundUpPow2(std::size_t n) {
  std::size_t p = 64;
  while (p < n) p <<= 1;
  return p;
}

std::size_t padded(std::size_t n) { return (n + 7) & ~std::size_t{7}; }

struct Header {
  std::uint32_t size;
  std::uint32_t tag;
};

}  // namespace

SpscRing::SpscRing(std::size_t capacityBytes) : mask_(roundUpPow2(capacityBytes) - 1) {
  // Not zeroed (make_unique would): the pages of a large ring are touched only as records reach
  // them. Zeroing the two workers' 4 MiB rings took 2.3 ms before a tiny model's first frame.
  buffer_.reset(new std::uint8_t[mask_ + 1]);
}

bool SpscRing::tryWrite(const void* first, std::size_t firstSize, const void* second, std::size_t secondSize,
                        std::uint32_t tag) {
  const std::size_t size = firstSize + secondSize;
  assert(size <= maxRecordSize() && tag != kSkip);
  const std::uint64_t write = write_.load(std::memory_order_relaxed);
  const std::uint64_t read = read_.load(std::memory_order_acquire);
  const std::size_t cap = capacity();
  const std::size_t need = kHeader + padded(size);
  const std::size_t offset = static_cast<std::size_t>(write) & mask_;
  const std::size_t tail = cap - offset;  // bytes before the end of the array
  const std::size_t skip = tail < need ? tail : 0;
  if (write + skip + need - read > cap) return false;
  std::uint64_t at = write;
  if (skip > 0) {
    // The tail is too short: mark it skipped (offsets are multiples of 8, so it holds a header).
    const Header h{0, kSkip};
    std::memcpy(buffer_.get() + offset, &h, sizeof h);
    at += skip;
  }
  std::uint8_t* dst = buffer_.get() + (static_cast<std::size_t>(at) & mask_);
  const Header h{static_cast<std::uint32_t>(size), tag};
  std::memcpy(dst, &h, sizeof h);
  if (firstSize > 0) std::memcpy(dst + kHeader, first, firstSize);
  if (secondSize > 0) std::memcpy(dst + kHeader + firstSize, second, secondSize);
  write_.store(at + need, std::memory_order_release);
  return true;
}

bool SpscRing::tryRead(View& view) {
  std::uint64_t read = read_.load(std::memory_order_relaxed);
  const std::uint64_t write = write_.load(std::memory_order_acquire);
  if (read == write) return false;
  Header h;
  std::memcpy(&h, buffer_.get() + (static_cast<std::size_t>(read) & mask_), sizeof h);
  if (h.tag == kSkip) {
    read += capacity() - (static_cast<std::size_t>(read) & mask_);
    // The producer wrote the skip and the record after it in one publication.
    std::memcpy(&h, buffer_.get() + (static_cast<std::size_t>(read) & mask_), sizeof h);
  }
  const std::uint8_t* at = buffer_.get() + (static_cast<std::size_t>(read) & mask_);
  view.data = at + kHeader;
  view.size = h.size;
  view.tag = h.tag;
  pendingRelease_ = read + kHeader + padded(h.size);
  return true;
}

void SpscRing::release() { read_.store(pendingRelease_, std::memory_order_release); }

void SpscRing::reset() {
  write_.store(0, std::memory_order_relaxed);
  read_.store(0, std::memory_order_relaxed);
  pendingRelease_ = 0;
}

std::size_t SpscRing::usedBytes() const {
  return static_cast<std::size_t>(write_.load(std::memory_order_acquire) - read_.load(std::memory_order_acquire));
}

bool RecordWriter::tryFragment(const std::uint8_t* data, std::size_t size, std::uint32_t tag,
                               std::uint32_t flags, std::uint64_t total) {
  const FragmentHeader h{flags, 0, total};
  return ring_.tryWrite(&h, sizeof h, data, size, tag);
}

bool RecordReader::next(Record& record) {
  if (holding_) {
    ring_.release();
    holding_ = false;
  }
  SpscRing::View view;
  while (ring_.tryRead(view)) {
    FragmentHeader h;
    std::memcpy(&h, view.data, sizeof h);
    const std::uint8_t* payload = view.data + sizeof h;
    const std::size_t size = view.size - sizeof h;
    if (h.flags & FragmentHeader::kFirst) {
      joining_ = false;  // a new record: drop any partial one (its writer was cancelled)
      joined_.clear();
    }
    if ((h.flags & FragmentHeader::kFirst) && (h.flags & FragmentHeader::kLast)) {
      record = Record{payload, size, view.tag};
      holding_ = true;  // read in place; released on the next call
      return true;
    }
    if (h.flags & FragmentHeader::kFirst) {
      joining_ = true;
      joinedTotal_ = h.total;
      joined_.reserve(static_cast<std::size_t>(h.total));
    }
    if (joining_) joined_.insert(joined_.end(), payload, payload + size);
    ring_.release();
    if (joining_ && (h.flags & FragmentHeader::kLast)) {
      joining_ = false;
      if (joined_.size() != joinedTotal_) continue;  // torn record: drop it
      record = Record{joined_.data(), joined_.size(), view.tag};
      return true;
    }
  }
  return false;
}

}  // namespace cetview::stream
