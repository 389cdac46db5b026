// CET operators (Yang & Choi 2010, Table 1): retrieval, traversal and modification of the arrays.
#include "cet_mesh.h"

namespace cet {

void CetMesh::reserve(std::size_t vertices, std::size_t triangles) {
  points_.reserve(vertices);
  L_.reserve(vertices);
  triangles_.reserve(triangles);
}

EdgeRef CetMesh::twin(EdgeRef e) const {
  const TriangleId u = neighbor(e.t, e.i);
  // The neighbour's copy of the edge is opposite the vertex that is not on it; with two triangles
  // sharing two edges (possible only between ghosts of a 2-point hull, which never exists here),
  // the vertex test is the unambiguous one.
  const VertexId a = edgeOrigin(e);
  const Triangle& tu = triangles_[u];
  for (int j = 0; j < 3; ++j) {
    if (tu.N[j] == e.t && tu.M[prev3(j)] == a) return EdgeRef{u, j};
  }
  assert(false && "neighbour does not point back");
  return EdgeRef{};
}

TriangleId CetMesh::nextAround(TriangleId t, VertexId v) const {
  const int k = indexOf(t, v);
  assert(k >= 0);
  // t = (v, x, y) counter-clockwise: the next triangle shares edge (v, y), the one opposite x.
  return neighbor(t, next3(k));
}

TriangleId CetMesh::prevAround(TriangleId t, VertexId v) const {
  const int k = indexOf(t, v);
  assert(k >= 0);
  return neighbor(t, prev3(k));
}

EdgeRef CetMesh::findEdge(VertexId a, VertexId b) const {
  // Turns around a and around b in step: either turn alone would meet the edge, so the first to
  // come full circle without it ends the search, and the cost is at most twice the smaller degree.
  // A segment inserted through a fan crosses edges from its hub, and the edges made while flipping
  // them away share the segment's ends (a fuzzed face: 18486 crossed edges, each looked up by
  // turning around the hub, took 20 s).
  const TriangleId startA = L_[a], startB = L_[b];
  if (startA == kNoTriangle || startB == kNoTriangle) return EdgeRef{};
  TriangleId ta = startA, tb = startB;
  for (;;) {
    const int ka = indexOf(ta, a);
    // In t = (a, x, y) the edge a -> x runs counter-clockwise: it is the edge opposite y.
    if (triangles_[ta].M[next3(ka)] == b) return EdgeRef{ta, prev3(ka)};
    ta = neighbor(ta, next3(ka));
    if (ta == startA) return EdgeRef{};
    const int kb = indexOf(tb, b);
    // In t = (b, x, y) the edge y -> b runs counter-clockwise: it is the edge opposite x.
    if (triangles_[tb].M[prev3(kb)] == a) return EdgeRef{tb, next3(kb)};
    tb = neighbor(tb, next3(kb));
    if (tb == startB) return EdgeRef{};
  }
}

VertexId CetMesh::addVertex(Point2 p) {
  points_.push_back(p);
  L_.push_back(kNoTriangle);
  return static_cast<VertexId>(points_.size() - 1);
}

TriangleId CetMesh::addTriangle(VertexId a, VertexId b, VertexId c) {
  triangles_.push_back(Triangle{{a, b, c}, {kNoTriangle, kNoTriangle, kNoTriangle}, 0});
  const auto t = static_cast<TriangleId>(triangles_.size() - 1);
  touchVertices(t);
  return t;
}

void CetMesh::link(TriangleId t, int i, TriangleId u, int j) {
  triangles_[t].N[i] = u;
  triangles_[u].N[j] = t;
}

void CetMesh::setFlagOneSide(TriangleId t, int i, EdgeFlag f) {
  std::uint8_t& bits = triangles_[t].bits;
  const int shift = 2 * i;
  bits = static_cast<std::uint8_t>((bits & ~(3u << shift)) | (static_cast<unsigned>(f) << shift));
}

void CetMesh::setFlag(TriangleId t, int i, EdgeFlag f) {
  const EdgeRef other = twin(EdgeRef{t, i});
  setFlagOneSide(t, i, f);
  setFlagOneSide(other.t, other.i, twinFlag(f));
}

void CetMesh::setOutside(TriangleId t, bool outside) {
  std::uint8_t& bits = triangles_[t].bits;
  bits = static_cast<std::uint8_t>(outside ? (bits | kOutsideBit) : (bits & ~kOutsideBit));
}

void CetMesh::touchVertices(TriangleId t) {
  const Triangle& tr = triangles_[t];
  for (VertexId v : tr.M) {
    if (v != kInfiniteVertex) L_[v] = t;
  }
}

void CetMesh::flip(TriangleId t, int i) { flip(t, i, twin(EdgeRef{t, i}).i); }

void CetMesh::flip(TriangleId t, int i, int j) {
  Triangle& T = triangles_[t];
  const TriangleId u = T.N[i];
  Triangle& U = triangles_[u];
  assert(flag(t, i) == kUnconstrained);
  const int ti1 = next3(i), ti2 = prev3(i), uj1 = next3(j), uj2 = prev3(j);
  const VertexId a = T.M[i], b = T.M[ti1], c = T.M[ti2], d = U.M[j];
  // Outer edges: (b, d) was U's edge opposite c, (d, c) U's edge opposite b,
  //              (c, a) T's edge opposite b, (a, b) T's edge opposite c.
  const TriangleId nBD = U.N[uj1], nDC = U.N[uj2], nCA = T.N[ti1], nAB = T.N[ti2];
  const unsigned fBD = (U.bits >> (2 * uj1)) & 3u, fDC = (U.bits >> (2 * uj2)) & 3u;
  const unsigned fCA = (T.bits >> (2 * ti1)) & 3u, fAB = (T.bits >> (2 * ti2)) & 3u;
  const unsigned tOut = T.bits & kOutsideBit, uOut = U.bits & kOutsideBit;
  // t' = (a, b, d): opposite a (b, d), opposite b (d, a) = u', opposite d (a, b).
  T = Triangle{{a, b, d}, {nBD, u, nAB}, static_cast<std::uint8_t>(fBD | (fAB << 4) | tOut)};
  // u' = (a, d, c): opposite a (d, c), opposite d (c, a), opposite c (a, d) = t'.
  U = Triangle{{a, d, c}, {nDC, nCA, t}, static_cast<std::uint8_t>(fDC | (fCA << 2) | uOut)};
  // The two outer triangles that changed owner point back to their new neighbour.
  replaceNeighbor(nBD, u, t);
  replaceNeighbor(nCA, t, u);
  // a and d are in both new triangles; b left u and c left t, so only their L may now be stale.
  if (b != kInfiniteVertex) L_[b] = t;
  if (c != kInfiniteVertex) L_[c] = u;
}

// Flattened: GCC otherwise keeps std::vector::push_back out of line, a call per new triangle on the
// insertion's hottest path.
[[gnu::flatten]] SplitResult CetMesh::splitTriangle(TriangleId t, VertexId v) {
  const Triangle T = triangles_[t];
  const VertexId a = T.M[0], b = T.M[1], c = T.M[2];
  const std::uint8_t out = T.bits & kOutsideBit;
  const auto t0 = t;
  const auto t1 = static_cast<TriangleId>(triangles_.size());
  const auto t2 = t1 + 1;
  const auto f = [&](int i) { return static_cast<std::uint8_t>((T.bits >> (2 * i)) & 3u); };
  // t0 = (v, b, c), t1 = (v, c, a), t2 = (v, a, b); edge 0 of each is an old edge of t.
  triangles_[t0] = Triangle{{v, b, c}, {T.N[0], t1, t2}, static_cast<std::uint8_t>(f(0) | out)};
  triangles_.push_back(Triangle{{v, c, a}, {T.N[1], t2, t0}, static_cast<std::uint8_t>(f(1) | out)});
  triangles_.push_back(Triangle{{v, a, b}, {T.N[2], t0, t1}, static_cast<std::uint8_t>(f(2) | out)});
  // Old outer neighbours across (c, a) and (a, b) now see t1 and t2.
  replaceNeighbor(T.N[1], t, t1);
  replaceNeighbor(T.N[2], t, t2);
  // b and c are still in t0 (= t); a is not.
  L_[v] = t0;
  if (a != kInfiniteVertex) L_[a] = t1;
  SplitResult r;
  r.t[0] = t0, r.t[1] = t1, r.t[2] = t2, r.count = 3;
  return r;
}

SplitResult CetMesh::splitEdge(TriangleId t, int i, VertexId v) {
  const TriangleId u = triangles_[t].N[i];
  const int j = twin(EdgeRef{t, i}).i;
  const Triangle T = triangles_[t];
  const Triangle U = triangles_[u];
  const VertexId a = T.M[i], b = T.M[next3(i)], c = T.M[prev3(i)];
  const VertexId d = U.M[j];
  const auto tf = [&](int k) { return static_cast<std::uint8_t>((T.bits >> (2 * k)) & 3u); };
  const auto uf = [&](int k) { return static_cast<std::uint8_t>((U.bits >> (2 * k)) & 3u); };
  const std::uint8_t tOut = T.bits & kOutsideBit, uOut = U.bits & kOutsideBit;
  const std::uint8_t fT = tf(i), fU = uf(j);  // the split edge, seen from t (b -> c) and u (c -> b)

  const TriangleId nCA = T.N[next3(i)], nAB = T.N[prev3(i)];
  const TriangleId nBD = U.N[next3(j)], nDC = U.N[prev3(j)];
  const std::uint8_t fCA = tf(next3(i)), fAB = tf(prev3(i));
  const std::uint8_t fBD = uf(next3(j)), fDC = uf(prev3(j));

  const TriangleId t1 = t;  // (v, c, a)
  const auto t2 = static_cast<TriangleId>(triangles_.size());  // (v, a, b)
  const TriangleId t3 = u;  // (v, b, d)
  const auto t4 = t2 + 1;   // (v, d, c)
  // Each: edge 0 the old outer edge; the halves of the split edge are (v, c) in t1 (edge 2),
  // (b, v) in t2 (edge 1), (v, b) in t3 (edge 2), (c, v) in t4 (edge 1).
  triangles_[t1] = Triangle{{v, c, a}, {nCA, t2, t4}, static_cast<std::uint8_t>(fCA | (fT << 4) | tOut)};
  triangles_.push_back(Triangle{{v, a, b}, {nAB, t3, t1}, static_cast<std::uint8_t>(fAB | (fT << 2) | tOut)});
  triangles_[t3] = Triangle{{v, b, d}, {nBD, t4, t2}, static_cast<std::uint8_t>(fBD | (fU << 4) | uOut)};
  triangles_.push_back(Triangle{{v, d, c}, {nDC, t1, t3}, static_cast<std::uint8_t>(fDC | (fU << 2) | uOut)});

  replaceNeighbor(nAB, t, t2);
  replaceNeighbor(nDC, u, t4);
  L_[v] = t1;
  if (a != kInfiniteVertex) L_[a] = t1;
  if (b != kInfiniteVertex) L_[b] = t2;
  if (c != kInfiniteVertex) L_[c] = t1;
  if (d != kInfiniteVertex) L_[d] = t3;
  SplitResult r;
  r.t[0] = t1, r.t[1] = t2, r.t[2] = t3, r.t[3] = t4, r.count = 4;
  return r;
}

std::size_t CetMesh::bytesVertices() const {
  return points_.capacity() * sizeof(Point2) + L_.capacity() * sizeof(TriangleId);
}

std::size_t CetMesh::bytesTriangles() const { return triangles_.capacity() * sizeof(Triangle); }

}  // namespace cet
