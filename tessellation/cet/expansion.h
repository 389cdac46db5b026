// Exact floating-point expansion arithmetic (Shewchuk 1997, sections 2.3–2.6), used by the exact
// fallback of the predicates. An expansion is a sum of doubles, ordered by increasing magnitude and
// nonoverlapping, whose exact sum is the represented value; its sign is the sign of its last
// (largest) component. Capacities are fixed at compile time so nothing is allocated.
//
// Requires strict IEEE double arithmetic with round-to-nearest: the cet target is compiled with
// -ffp-contract=off so no fused multiply-add changes a rounding.
#pragma once

#include <cstddef>

namespace cet::exact {

// x + y = a + b exactly, x = fl(a + b) (Knuth's two-sum).
inline void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  y = (a - aVirtual) + (b - bVirtual);
}

// x + y = a - b exactly.
inline void twoDiff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bVirtual = a - x;
  const double aVirtual = x + bVirtual;
  y = (a - aVirtual) + (bVirtual - b);
}

// a = hi + lo with each half holding at most 26 significant bits (Veltkamp/Dekker split).
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y = a * b exactly, x = fl(a * b) (Dekker's two-product).
inline void twoProduct(double a, double b, double& x, double& y) {
  x = a * b;
  double aHi, aLo, bHi, bLo;
  split(a, aHi, aLo);
  split(b, bHi, bLo);
  const double err1 = x - (aHi * bHi);
  const double err2 = err1 - (aLo * bHi);
  const double err3 = err2 - (aHi * bLo);
  y = (aLo * bLo) - err3;
}

template <std::size_t N>
struct Expansion {
  static constexpr std::size_t kCapacity = N;
  double c[N];
  std::size_t n = 0;  // number of components in use; 0 means the value 0

  double sign() const { return n == 0 ? 0.0 : c[n - 1]; }
};

// The exact difference a - b of two doubles as an expansion.
inline Expansion<2> difference(double a, double b) {
  Expansion<2> e;
  double x, y;
  twoDiff(a, b, x, y);
  if (y != 0.0) e.c[e.n++] = y;
  if (x != 0.0) e.c[e.n++] = x;
  return e;
}

// h = e + f, with zero components removed. Merges the components by magnitude, then carries a
// running two-sum (Shewchuk's fast-expansion-sum, with the always-correct two-sum at each step).
template <std::size_t N, std::size_t M>
Expansion<N + M> sum(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> h;
  if (e.n == 0 && f.n == 0) return h;
  double merged[N + M];
  std::size_t i = 0, j = 0, k = 0;
  while (i < e.n && j < f.n) {
    const double ei = e.c[i], fj = f.c[j];
    const bool takeE = (ei < 0 ? -ei : ei) < (fj < 0 ? -fj : fj);
    merged[k++] = takeE ? e.c[i++] : f.c[j++];
  }
  while (i < e.n) merged[k++] = e.c[i++];
  while (j < f.n) merged[k++] = f.c[j++];

  double q = merged[0];
  for (std::size_t m = 1; m < k; ++m) {
    double qNew, err;
    twoSum(q, merged[m], qNew, err);
    if (err != 0.0) h.c[h.n++] = err;
    q = qNew;
  }
  if (q != 0.0 || h.n == 0) h.c[h.n++] = q;
  if (h.n == 1 && h.c[0] == 0.0) h.n = 0;
  return h;
}

template <std::size_t N>
Expansion<N> negate(Expansion<N> e) {
  for (std::size_t i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
  return e;
}

// h = e * b, zero components removed (Shewchuk's scale-expansion).
template <std::size_t N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) {
  Expansion<2 * N> h;
  if (e.n == 0 || b == 0.0) return h;
  double q, err;
  twoProduct(e.c[0], b, q, err);
  if (err != 0.0) h.c[h.n++] = err;
  for (std::size_t i = 1; i < e.n; ++i) {
    double productHi, productLo, s;
    twoProduct(e.c[i], b, productHi, productLo);
    twoSum(q, productLo, s, err);
    if (err != 0.0) h.c[h.n++] = err;
    twoSum(productHi, s, q, err);
    if (err != 0.0) h.c[h.n++] = err;
  }
  if (q != 0.0 || h.n == 0) h.c[h.n++] = q;
  if (h.n == 1 && h.c[0] == 0.0) h.n = 0;
  return h;
}

// h = e * f: the sum of e scaled by each component of f.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> product(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> h;
  for (std::size_t j = 0; j < f.n; ++j) {
    const Expansion<2 * N> term = scale(e, f.c[j]);
    Expansion<2 * N * M> next;
    // Accumulate into a buffer of the final capacity; the running sum never exceeds it.
    const auto s = sum(h, term);
    for (std::size_t k = 0; k < s.n; ++k) next.c[k] = s.c[k];
    next.n = s.n;
    h = next;
  }
  return h;
}

}  // namespace cet::exact
