// Exact floating-point expansion arithmetic (Shewchuk 1997, sections 2.3–2.6), used by the exact
// fallback of the predicates. An expansion is a sum of doubles, ordered by increasing magnitude and
// nonoverlapping, whose exact sum is the represented value; its sign is the sign of its last
// (largest) component. Capacities are fixed at compile time so nothing is allocated.
//
// Requires strict IEEE double arithmetic with round-to-nearest: the cet target is compiled with
// -ffp-contract=off so no fused multiply-add changes a rounding.
#pragma once

#include <cstddef>
#include <utility>

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
  // The value rounded (components summed smallest first): within a few ulps of it.
  double estimate() const {
    double v = 0.0;
    for (std::size_t i = 0; i < n; ++i) v += c[i];
    return v;
  }
};

// The expansion x + y of a rounded result x and its error y, zero components left out.
inline Expansion<2> twoTerms(double x, double y) {
  Expansion<2> e;
  if (y != 0.0) e.c[e.n++] = y;
  if (x != 0.0) e.c[e.n++] = x;
  return e;
}

// The exact difference a - b of two doubles as an expansion.
inline Expansion<2> difference(double a, double b) {
  double x, y;
  twoDiff(a, b, x, y);
  return twoTerms(x, y);
}

// The exact product a * b of two doubles as an expansion.
inline Expansion<2> exactProduct(double a, double b) {
  double x, y;
  twoProduct(a, b, x, y);
  return twoTerms(x, y);
}

// h = e + f with zero components removed; returns the length of h (at most en + fn). h must not
// alias e or f. Merges the components by magnitude, then carries a running two-sum (Shewchuk's
// fast-expansion-sum, with the always-correct two-sum at each step).
inline std::size_t sumInto(const double* e, std::size_t en, const double* f, std::size_t fn, double* h) {
  if (en == 0) {
    for (std::size_t k = 0; k < fn; ++k) h[k] = f[k];
    return fn;
  }
  if (fn == 0) {
    for (std::size_t k = 0; k < en; ++k) h[k] = e[k];
    return en;
  }
  std::size_t i = 0, j = 0, hn = 0;
  const auto magnitude = [](double v) { return v < 0 ? -v : v; };
  // The smallest component starts the running sum q.
  double q;
  if (magnitude(e[0]) < magnitude(f[0])) {
    q = e[i++];
  } else {
    q = f[j++];
  }
  while (i < en || j < fn) {
    double next;
    if (j >= fn || (i < en && magnitude(e[i]) < magnitude(f[j]))) {
      next = e[i++];
    } else {
      next = f[j++];
    }
    double qNew, err;
    twoSum(q, next, qNew, err);
    if (err != 0.0) h[hn++] = err;
    q = qNew;
  }
  if (q != 0.0) h[hn++] = q;
  return hn;
}

// h = e * b with zero components removed (Shewchuk's scale-expansion); returns the length of h
// (at most 2 en). h must not alias e.
inline std::size_t scaleInto(const double* e, std::size_t en, double b, double* h) {
  if (en == 0 || b == 0.0) return 0;
  std::size_t hn = 0;
  double q, err;
  twoProduct(e[0], b, q, err);
  if (err != 0.0) h[hn++] = err;
  for (std::size_t i = 1; i < en; ++i) {
    double productHi, productLo, s;
    twoProduct(e[i], b, productHi, productLo);
    twoSum(q, productLo, s, err);
    if (err != 0.0) h[hn++] = err;
    twoSum(productHi, s, q, err);
    if (err != 0.0) h[hn++] = err;
  }
  if (q != 0.0) h[hn++] = q;
  return hn;
}

template <std::size_t N, std::size_t M>
Expansion<N + M> sum(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> h;
  h.n = sumInto(e.c, e.n, f.c, f.n, h.c);
  return h;
}

template <std::size_t N>
Expansion<N> negate(Expansion<N> e) {
  for (std::size_t i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
  return e;
}

// h = e * f: the sum of e scaled by each component of f, accumulated in two buffers that swap.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> product(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> h;
  double other[2 * N * M];
  double term[2 * N];
  double* acc = h.c;
  double* spare = other;
  std::size_t n = 0;
  for (std::size_t j = 0; j < f.n; ++j) {
    const std::size_t tn = scaleInto(e.c, e.n, f.c[j], term);
    n = sumInto(acc, n, term, tn, spare);
    std::swap(acc, spare);
  }
  if (acc != h.c) {
    for (std::size_t k = 0; k < n; ++k) h.c[k] = acc[k];
  }
  h.n = n;
  return h;
}

}  // namespace cet::exact
