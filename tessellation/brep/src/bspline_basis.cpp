#include "bspline_basis.h"

namespace cetview::brep {

void knotReciprocals(const double* U, int d, int s, double* inv) {
  for (int j = 1; j <= d; ++j) {
    for (int r = 0; r < j; ++r) {
      const double den = U[s + r + 1] - U[s + r + 1 - j];
      inv[j * (j - 1) / 2 + r] = den > 0 ? 1.0 / den : 0.0;
    }
  }
}

void KnotSpans::index(bool reciprocals) {
  const int first = degree, last = poles - 1;  // spans
  const int perSpan = degree * (degree + 1) / 2;
  if (reciprocals) {
    inverse.assign(static_cast<std::size_t>((last - first + 1) * perSpan), 0.0);
    for (int s = first; s <= last; ++s)
      knotReciprocals(knots.data(), degree, s, inverse.data() + (s - first) * perSpan);
  }
  const double a = knots[static_cast<std::size_t>(first)], b = knots[static_cast<std::size_t>(last + 1)];
  const int buckets = 2 * (last - first + 1);
  t0 = a;
  perBucket = b > a ? buckets / (b - a) : 0.0;
  bucketSpan.assign(static_cast<std::size_t>(buckets), first);
  int s = first;
  for (int i = 0; i < buckets; ++i) {
    const double start = a + i / perBucket;
    while (s < last && knots[static_cast<std::size_t>(s + 1)] <= start) ++s;
    bucketSpan[static_cast<std::size_t>(i)] = s;
  }
}

int KnotSpans::span(double t) const {
  // The largest span s with knots[s] <= t, kept within degree .. poles - 1.
  const int last = poles - 1;
  if (!(t > t0)) return degree;
  const double x = (t - t0) * perBucket;
  int s = x < static_cast<double>(bucketSpan.size()) ? bucketSpan[static_cast<std::size_t>(x)] : last;
  // A bucket's start may round to either side of a knot: step back, then forward.
  while (s > degree && knots[static_cast<std::size_t>(s)] > t) --s;
  while (s < last && knots[static_cast<std::size_t>(s + 1)] <= t) ++s;
  return s;
}

int KnotSpans::spanBelow(double t) const {
  int s = span(t);
  while (s > degree && !(knots[static_cast<std::size_t>(s)] < t)) --s;  // past empty spans of repeated knots
  return s;
}

}  // namespace cetview::brep
