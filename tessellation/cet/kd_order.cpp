// The kd permutation: each range's median along its longer axis, found by a selection written for
// this job rather than std::nth_element, whose data-dependent branches mispredict on about half the
// comparisons and whose pivots need several passes over each range (it took a third of the time of
// a whole 1M-point triangulation).
//
// Selection follows R. W. Floyd and R. L. Rivest, "Expected time bounds for selection" (CACM 1975):
// the pivot is taken from a sample of about sqrt(n) points at a rank just beyond the wanted one, so
// that the wanted element lies, with high probability, on the smaller side of the partition. Two
// partitions (one over the whole range, one over about half) then leave only a few thousand points.
// The partition is Edelkamp and Weiss's block partition (BlockQuicksort, ESA 2016), whose
// comparisons feed counters rather than branches.
#include "kd_order.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cet {

namespace {
struct Box {
  double minX, minY, maxX, maxY;
};
enum class Sorted : std::uint8_t { kNo, kAlongX, kAlongY };
struct Pending {
  std::uint32_t lo, hi;
  Box box;
  Sorted sorted;  // whether the range is already sorted along an axis (small ranges, see below)
};
// The points are copied next to their ids while partitioning, so the selection reads contiguous
// memory instead of chasing ids into the vertex array (several times faster on large inputs). The
// coordinates are stored as order-preserving integers (see orderedBits) and the id is widened, so
// an item is three 8-byte words: compilers copied a padded 20-byte item with 4-byte stores and 8-byte
// loads, which defeats store-to-load forwarding in the partition loops.
struct Item {
  std::uint64_t x, y;
  std::uint64_t id;
};

// Maps finite doubles to unsigned integers in the same order (-0 just below +0), so that a
// lexicographic comparison of two coordinates becomes one 128-bit integer comparison.
std::uint64_t orderedBits(double v) {
  if (v == 0.0) v = 0.0;  // -0 and +0 are one value: same key, as the comparisons elsewhere see them
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return (u >> 63) != 0 ? ~u : (u | (std::uint64_t{1} << 63));
}
double fromOrderedBits(std::uint64_t k) {
  const std::uint64_t u = (k >> 63) != 0 ? (k & ~(std::uint64_t{1} << 63)) : ~k;
  double v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

// Ranges this small are finished with insertion sorts: sorting a range along its axis places its
// median and both sides at once, and its sub-ranges along the same axis need nothing more.
constexpr std::size_t kLeafSize = 16;
// Below this size the pivot is the median of three; above it, a Floyd-Rivest sample.
constexpr std::size_t kSampleThreshold = 512;

// Lexicographic order on (key axis, other axis), a strict total order on distinct points: runs of
// equal coordinates (grids) are split along the other axis, which keeps each subtree compact.
// Evaluated as one 128-bit comparison (compare and subtract-with-borrow, no branch) where the
// compiler has 128-bit integers (64-bit targets); the two-word form is about 20% slower here.
template <bool kAlongX>
struct Less {
#ifdef __SIZEOF_INT128__
  __extension__ using Wide = unsigned __int128;
  static Wide key(const Item& a) {
    return kAlongX ? (Wide{a.x} << 64) | a.y : (Wide{a.y} << 64) | a.x;
  }
  bool operator()(const Item& a, const Item& b) const {
    return key(a) < key(b);
  }
#else
  bool operator()(const Item& a, const Item& b) const {
    const std::uint64_t a0 = kAlongX ? a.x : a.y, b0 = kAlongX ? b.x : b.y;
    const std::uint64_t a1 = kAlongX ? a.y : a.x, b1 = kAlongX ? b.y : b.x;
    return (a0 < b0) | ((a0 == b0) & (a1 < b1));
  }
#endif
};

template <class Order>
void insertionSort(Item* first, Item* last, Order less) {
  for (Item* i = first + 1; i < last; ++i) {
    const Item x = *i;
    Item* j = i;
    for (; j > first && less(x, j[-1]); --j) *j = j[-1];
    *j = x;
  }
}

// Moves the items for which goesFirst(item) holds to the front of [first, last) and returns the end
// of that group. After Edelkamp and Weiss's BlockQuicksort (ESA 2016): a block of items at each end
// is classified first, branch-free, recording the offsets of the misplaced ones; then misplaced
// pairs are swapped. No branch depends on a comparison, each item is read once, and only misplaced
// items move.
template <class Predicate>
Item* partition(Item* first, Item* last, Predicate goesFirst) {
  constexpr std::ptrdiff_t kBlock = 64;
  std::uint8_t misplacedLeft[kBlock], misplacedRight[kBlock];
  std::ptrdiff_t leftCount = 0, leftStart = 0, leftSize = 0;
  std::ptrdiff_t rightCount = 0, rightStart = 0, rightSize = 0;
  // Settled: [first, left) go first, [right, last) go last. The left block is [left, left +
  // leftSize), the right block [right - rightSize, right); a block with misplaced items left over
  // (count > 0) waits for the other side's next block.
  Item* left = first;
  Item* right = last;
  for (;;) {
    std::ptrdiff_t unknown =
        (right - left) - (leftCount > 0 ? leftSize : 0) - (rightCount > 0 ? rightSize : 0);
    if (leftCount == 0 && rightCount == 0) {
      leftSize = unknown >= 2 * kBlock ? kBlock : unknown / 2;
      rightSize = unknown >= 2 * kBlock ? kBlock : unknown - leftSize;
    } else if (leftCount == 0) {
      leftSize = std::min(kBlock, unknown);
    } else {
      rightSize = std::min(kBlock, unknown);
    }
    if (leftCount == 0) {
      leftStart = 0;
      for (std::ptrdiff_t i = 0; i < leftSize; ++i) {
        misplacedLeft[leftCount] = static_cast<std::uint8_t>(i);
        leftCount += !goesFirst(left[i]);
      }
      unknown -= leftSize;
    }
    if (rightCount == 0) {
      rightStart = 0;
      for (std::ptrdiff_t i = 0; i < rightSize; ++i) {
        misplacedRight[rightCount] = static_cast<std::uint8_t>(i);
        rightCount += goesFirst(right[-1 - i]);
      }
      unknown -= rightSize;
    }
    const std::ptrdiff_t pairs = std::min(leftCount, rightCount);
    for (std::ptrdiff_t k = 0; k < pairs; ++k) {
      std::swap(left[misplacedLeft[leftStart + k]], right[-1 - misplacedRight[rightStart + k]]);
    }
    leftCount -= pairs, leftStart += pairs;
    rightCount -= pairs, rightStart += pairs;
    if (leftCount == 0) left += leftSize;
    if (rightCount == 0) right -= rightSize;
    if (unknown == 0) break;
  }
  // Everything is classified and at most one block still holds misplaced items; the rest of that
  // block is all it has between the settled groups. Its misplaced items move to the block's far
  // end, farthest first, each swapped with an item that belongs where it lies.
  for (std::ptrdiff_t k = leftCount - 1; k >= 0; --k) std::swap(left[misplacedLeft[leftStart + k]], *--right);
  for (std::ptrdiff_t k = rightCount - 1; k >= 0; --k)
    std::swap(right[-1 - misplacedRight[rightStart + k]], *left++);
  return leftCount > 0 ? right : left;
}

// Chooses a pivot in [first, last) for the search of rank k (0-based within the range). For large
// ranges, a sample of about sqrt(n) evenly spaced items is gathered at the front and its element at
// a rank a couple of standard deviations beyond k's (towards the nearer end) is selected, so the
// partition cuts off the larger side with high probability; otherwise the median of three.
template <class Order>
Item choosePivot(Item* first, Item* last, std::size_t k, Order less);

// Rearranges [first, last) so that first[k] is the item of rank k, those before it are not greater
// and those after it not smaller.
template <class Order>
void select(Item* first, Item* last, std::size_t k, Order less) {
  Item* target = first + k;
  // Unlucky samples only cost time; past this many rounds the library's introselect finishes.
  int roundsLeft = 64;
  while (static_cast<std::size_t>(last - first) > kLeafSize) {
    if (--roundsLeft == 0) {
      std::nth_element(first, target, last, less);
      return;
    }
    const Item pivot = choosePivot(first, last, static_cast<std::size_t>(target - first), less);
    Item* split = partition(first, last, [&](const Item& x) { return less(x, pivot); });
    if (target < split) {
      last = split;
      continue;
    }
    if (split == first) {
      // The pivot is the smallest item: split off the items equal to it (copies of one point),
      // which are all valid answers when they cover the target.
      split = partition(first, last, [&](const Item& x) { return !less(pivot, x); });
      if (target < split) return;
    }
    first = split;
  }
  insertionSort(first, last, less);
}

template <class Order>
Item choosePivot(Item* first, Item* last, std::size_t k, Order less) {
  const auto n = static_cast<std::size_t>(last - first);
  if (n < kSampleThreshold) {
    Item a = first[0], b = first[n / 2], c = first[n - 1];
    if (less(b, a)) std::swap(a, b);
    if (less(c, b)) std::swap(b, c);
    if (less(b, a)) std::swap(a, b);
    return b;
  }
  const auto sampleSize = static_cast<std::size_t>(std::sqrt(static_cast<double>(n))) | 1u;
  const std::size_t stride = n / sampleSize;
  for (std::size_t s = 0; s < sampleSize; ++s) std::swap(first[s], first[s * stride]);
  // Rank of k in the sample, moved by about two standard deviations of the sample's rank error
  // (sqrt(sampleSize) / 2 each) towards the nearer end of the range.
  const std::size_t gap = static_cast<std::size_t>(std::sqrt(static_cast<double>(sampleSize)));
  const std::size_t scaled = k * sampleSize / n;
  const std::size_t rank =
      2 * k < n ? std::min(sampleSize - 1, scaled + gap) : (scaled > gap ? scaled - gap : 0);
  select(first, first + sampleSize, rank, less);
  return first[rank];
}

template <bool kAlongX>
void selectMedian(Item* first, Item* last, Item* mid) {
  select(first, last, static_cast<std::size_t>(mid - first), Less<kAlongX>{});
}

template <bool kAlongX>
void sortRange(Item* first, Item* last) {
  insertionSort(first, last, Less<kAlongX>{});
}

}  // namespace

void kdPermutation(const Point2* points, std::uint32_t* ids, std::size_t n, Point2* orderedPoints) {
  if (n < 2) {
    if (n == 1 && orderedPoints != nullptr) orderedPoints[0] = points[ids[0]];
    return;
  }
  std::vector<Item> items(n);
  Box all{points[ids[0]].x, points[ids[0]].y, points[ids[0]].x, points[ids[0]].y};
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 p = points[ids[i]];
    items[i] = Item{orderedBits(p.x), orderedBits(p.y), ids[i]};
    all.minX = std::min(all.minX, p.x), all.maxX = std::max(all.maxX, p.x);
    all.minY = std::min(all.minY, p.y), all.maxY = std::max(all.maxY, p.y);
  }
  // Depth-first with an explicit stack (depth about log2 n); the child boxes are the parent's box
  // cut at the median, which is enough to choose the longer axis without rescanning points.
  std::vector<Pending> stack;
  stack.push_back(Pending{0, static_cast<std::uint32_t>(n), all, Sorted::kNo});
  Item* const it = items.data();
  while (!stack.empty()) {
    const Pending r = stack.back();
    stack.pop_back();
    if (r.hi - r.lo < 2) continue;
    const bool splitX = (r.box.maxX - r.box.minX) >= (r.box.maxY - r.box.minY);
    const Sorted axis = splitX ? Sorted::kAlongX : Sorted::kAlongY;
    Sorted childrenSorted = Sorted::kNo;
    const std::uint32_t mid = r.lo + (r.hi - r.lo) / 2;
    if (r.hi - r.lo <= kLeafSize) {
      if (r.sorted != axis) {
        if (splitX) {
          sortRange<true>(it + r.lo, it + r.hi);
        } else {
          sortRange<false>(it + r.lo, it + r.hi);
        }
      }
      childrenSorted = axis;
    } else if (splitX) {
      selectMedian<true>(it + r.lo, it + r.hi, it + mid);
    } else {
      selectMedian<false>(it + r.lo, it + r.hi, it + mid);
    }
    const Item m = it[mid];
    Box lower = r.box, upper = r.box;
    if (splitX) {
      lower.maxX = upper.minX = fromOrderedBits(m.x);
    } else {
      lower.maxY = upper.minY = fromOrderedBits(m.y);
    }
    stack.push_back(Pending{r.lo, mid, lower, childrenSorted});
    stack.push_back(Pending{mid + 1, r.hi, upper, childrenSorted});
  }
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::uint32_t>(items[i].id);
  if (orderedPoints != nullptr) {
    for (std::size_t i = 0; i < n; ++i)
      orderedPoints[i] = Point2{fromOrderedBits(items[i].x), fromOrderedBits(items[i].y)};
  }
}

}  // namespace cet
