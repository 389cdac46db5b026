// A set of table entries (face colours, draw commands, instances) waiting for upload, consumed in
// the order they were first marked. Marking an entry already waiting is a no-op, so an entry is
// uploaded once however often it changed.
#pragma once

#include <cstdint>
#include <vector>

namespace cetview::engine {

class DirtySet {
 public:
  void mark(std::uint32_t index) {
    if (index >= flags_.size()) flags_.resize(index + 1u, false);
    if (flags_[index]) return;
    flags_[index] = true;
    order_.push_back(index);
  }
  // Drops `index` from the set (it was uploaded by another path).
  void unmark(std::uint32_t index) {
    if (index < flags_.size()) flags_[index] = false;
  }
  bool contains(std::uint32_t index) const { return index < flags_.size() && flags_[index]; }
  // True when nothing waits (an unmarked entry may still make this false until front() skips it).
  bool empty() const { return head_ == order_.size(); }

  // The oldest waiting entry, skipping entries unmarked since; false when nothing waits.
  bool front(std::uint32_t* index) {
    while (head_ < order_.size() && !flags_[order_[head_]]) ++head_;
    if (head_ == order_.size()) {
      clear();
      return false;
    }
    *index = order_[head_];
    return true;
  }
  // Removes the entry front() returned.
  void popFront() {
    flags_[order_[head_]] = false;
    if (++head_ == order_.size()) clear();
  }
  void clear() {
    for (std::size_t i = head_; i < order_.size(); ++i) flags_[order_[i]] = false;
    order_.clear();
    head_ = 0;
  }

 private:
  std::vector<std::uint32_t> order_;
  std::vector<bool> flags_;
  std::size_t head_ = 0;
};

}  // namespace cetview::engine
