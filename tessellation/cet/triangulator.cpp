// Sequential constrained Delaunay triangulation on the CET arrays.
//
// Sources: S. W. Yang, Y. Choi, "Triangulation of CAD data for visualization using a compact
// array-based triangle data structure", Computers & Graphics 34 (2010) — the arrays, the operators and
// the kd-tree permutation order; C. L. Lawson (1977) — flips restore the Delaunay property after each
// insertion; O. Devillers et al., "Walking in a triangulation" (2002) — the stochastic visibility walk;
// S. W. Sloan, "A fast algorithm for generating constrained Delaunay triangulations" (1993) — segment
// recovery by flipping the crossed edges. Ghost triangles with a vertex at infinity follow the
// convention of CGAL's and Shewchuk's triangulators.
#include "triangulator.h"

#include <algorithm>
#include <deque>

#include "kd_order.h"
#include "mesh_predicates.h"
#include "predicates.h"

namespace cet {

struct Triangulator::Location {
  enum class Kind { kInTriangle, kOnEdge, kOnVertex };
  Kind kind = Kind::kInTriangle;
  TriangleId t = kNoTriangle;
  int i = 0;  // the edge (kOnEdge) or the vertex (kOnVertex), as a local index in t
};

namespace {

std::string vertexName(VertexId v) { return std::to_string(v); }

// The lowest and the highest set bit of a 3-bit edge mask.
constexpr int kLowestEdge[8] = {-1, 0, 1, 0, 2, 0, 1, 0};
constexpr int kHighestEdge[8] = {-1, 0, 1, 1, 2, 2, 2, 2};

}  // namespace

void Triangulator::reserve(std::size_t vertices) { mesh_.reserve(vertices, 2 * vertices + 8); }

VertexId Triangulator::addVertices(const Point2* points, std::size_t count) {
  const auto first = static_cast<VertexId>(mesh_.vertexCount());
  for (std::size_t i = 0; i < count; ++i) mesh_.addVertex(points[i]);
  return first;
}

VertexId Triangulator::representative(VertexId v) const {
  const auto it = merged_.find(v);
  return it == merged_.end() ? v : it->second;
}

// ---------------------------------------------------------------------------------------------
// Point location: a stochastic visibility walk. In a finite triangle, cross an edge whose line has
// the point strictly on its far side (a random one of two such); a ghost triangle (x, y, inf)
// contains the open half-plane left of x -> y, and points on the hull line move along the hull to
// the ghost or edge that holds them. Terminates with probability 1 on any triangulation,
// constrained or not.
Triangulator::Location Triangulator::locate(Point2 p, TriangleId start) const {
  TriangleId t = start;
  if (t == kNoTriangle || t >= mesh_.triangleCount()) t = 0;
  for (;;) {
    const int g = mesh_.ghostIndex(t);
    if (g >= 0) {
      const int ix = next3(g), iy = prev3(g);
      const Point2 x = mesh_.point(mesh_.vertex(t, ix)), y = mesh_.point(mesh_.vertex(t, iy));
      const double o = orient2d(x, y, p);
      if (o > 0.0) return Location{Location::Kind::kInTriangle, t, 0};
      if (o < 0.0) {
        t = mesh_.neighbor(t, g);
        continue;
      }
      if (p == x) return Location{Location::Kind::kOnVertex, t, ix};
      if (p == y) return Location{Location::Kind::kOnVertex, t, iy};
      if (strictlyBetween(x, y, p)) return Location{Location::Kind::kOnEdge, t, g};
      // Beyond y (x, y, p in that order on the line): the next ghost shares (y, inf), opposite x.
      t = strictlyBetween(x, p, y) ? mesh_.neighbor(t, ix) : mesh_.neighbor(t, iy);
      continue;
    }
    // All three edges at once: the tests are independent, so they overlap, and no branch depends on
    // one of them. The edge just crossed has the point strictly inside (the exact sign is the
    // opposite of the one that crossed it), so it is never chosen again.
    Point2 q[3];
    for (int i = 0; i < 3; ++i) q[i] = mesh_.point(mesh_.vertex(t, i));
    int crossable = 0, zeroMask = 0;
    for (int i = 0; i < 3; ++i) {
      const double o = orient2d(q[next3(i)], q[prev3(i)], p);
      crossable |= (o < 0.0 ? 1 : 0) << i;
      zeroMask |= (o == 0.0 ? 1 : 0) << i;
    }
    if (crossable != 0) {
      t = mesh_.neighbor(t, chooseEdge(crossable));
      continue;
    }
    switch (zeroMask) {
      case 0: return Location{Location::Kind::kInTriangle, t, 0};
      case 1: return Location{Location::Kind::kOnEdge, t, 0};
      case 2: return Location{Location::Kind::kOnEdge, t, 1};
      case 4: return Location{Location::Kind::kOnEdge, t, 2};
      // On two edges: the vertex they share, the one opposite the third edge.
      case 3: return Location{Location::Kind::kOnVertex, t, 2};
      case 5: return Location{Location::Kind::kOnVertex, t, 1};
      default: return Location{Location::Kind::kOnVertex, t, 0};
    }
  }
}

// ---------------------------------------------------------------------------------------------
bool Triangulator::buildFirstTriangle() {
  const auto n = static_cast<VertexId>(mesh_.vertexCount());
  if (n < 3) return false;
  const VertexId a = 0;
  VertexId b = kNoVertex, c = kNoVertex;
  for (VertexId v = 1; v < n; ++v) {
    if (mesh_.point(v) != mesh_.point(a)) {
      b = v;
      break;
    }
  }
  if (b == kNoVertex) return false;
  double o = 0.0;
  for (VertexId v = b + 1; v < n; ++v) {
    o = orient2d(mesh_.point(a), mesh_.point(b), mesh_.point(v));
    if (o != 0.0) {
      c = v;
      break;
    }
  }
  if (c == kNoVertex) return false;
  if (o < 0.0) std::swap(b, c);
  const TriangleId f = mesh_.addTriangle(a, b, c);
  TriangleId ghost[3];
  for (int i = 0; i < 3; ++i) {
    // Across edge i of f (M[i+1] -> M[i+2]) lies the ghost (M[i+2], M[i+1], inf).
    ghost[i] = mesh_.addTriangle(mesh_.vertex(f, prev3(i)), mesh_.vertex(f, next3(i)), kInfiniteVertex);
    mesh_.link(f, i, ghost[i], 2);
  }
  for (int i = 0; i < 3; ++i) mesh_.link(ghost[i], 0, ghost[(i + 2) % 3], 1);
  lastTouched_ = f;
  return true;
}

// Splits the located triangle or edge by vertex v (already in the vertex array) and restores the
// constrained Delaunay property with Lawson's flips.
// One of the (one or two) edges in the mask, at random when there are two.
int Triangulator::chooseEdge(int mask) const {
  walkSeed_ = walkSeed_ * 1664525u + 1013904223u;
  return (walkSeed_ >> 31) != 0 ? kHighestEdge[mask] : kLowestEdge[mask];
}

InsertOutcome Triangulator::insertLocated(VertexId v, const Location& loc) {
  const SplitResult split = loc.kind == Location::Kind::kOnEdge ? mesh_.splitEdge(loc.t, loc.i, v)
                                                                 : mesh_.splitTriangle(loc.t, v);
  flipStack_.assign(split.t, split.t + split.count);
  // Invariant: v is M0 of every stacked triangle; its edge 0 is the one to test.
  while (!flipStack_.empty()) {
    const TriangleId t = flipStack_.back();
    flipStack_.pop_back();
    if (mesh_.isConstrained(t, 0)) continue;
    const TriangleId u = mesh_.neighbor(t, 0);
    const int j = mesh_.edgeTo(u, t);  // unique: two triangles share at most one edge here
    const VertexId d = mesh_.vertex(u, j);
    if (!inCircumcircle(mesh_, t, d)) continue;
    mesh_.flip(t, 0, j);
    flipStack_.push_back(t);
    flipStack_.push_back(u);
  }
  lastTouched_ = mesh_.incident(v);
  return InsertOutcome::kInserted;
}

bool Triangulator::insertPending(bool alreadyKdOrdered, const std::atomic<bool>* cancel) {
  if (mesh_.empty() && !buildFirstTriangle()) return false;
  const auto n = static_cast<VertexId>(mesh_.vertexCount());
  // All pending ids, including the first triangle's three (skipped below, but still parents), so
  // that a caller's kd-ordered array keeps its tree shape.
  order_.resize(n - firstPending_);
  for (VertexId v = firstPending_; v < n; ++v) order_[v - firstPending_] = v;
  if (!alreadyKdOrdered) kdPermutation(mesh_.points(), order_.data(), order_.size());
  std::vector<KdRange> queue;
  std::size_t visited = 0;
  forEachBreadthFirst(order_.data(), order_.size(), queue, [&](VertexId v, VertexId parent) {
    if (cancelled_) return;
    if (cancel && ++visited % kCancelStride == 0 && cancel->load(std::memory_order_relaxed)) {
      cancelled_ = true;
      return;
    }
    if (mesh_.incident(v) != kNoTriangle || merged_.count(v) != 0) return;  // already in
    TriangleId hint = lastTouched_;
    if (parent != UINT32_MAX) {
      const VertexId host = representative(parent);
      if (mesh_.incident(host) != kNoTriangle) hint = mesh_.incident(host);
    }
    const Location loc = locate(mesh_.point(v), hint);
    if (loc.kind == Location::Kind::kOnVertex) {
      merged_.emplace(v, mesh_.vertex(loc.t, loc.i));
      return;
    }
    insertLocated(v, loc);
  });
  if (cancelled_) return false;
  firstPending_ = n;
  return true;
}

InsertOutcome Triangulator::insertPoint(Point2 p, VertexId* id, TriangleId hint) {
  *id = kNoVertex;
  if (mesh_.empty()) return InsertOutcome::kOutside;
  const Location loc = locate(p, hint == kNoTriangle ? lastTouched_ : hint);
  if (loc.kind == Location::Kind::kOnVertex) {
    *id = mesh_.vertex(loc.t, loc.i);
    return InsertOutcome::kMerged;
  }
  if (loc.kind == Location::Kind::kOnEdge && mesh_.isConstrained(loc.t, loc.i)) return InsertOutcome::kOnConstraint;
  if (domainMarked_ && (mesh_.isGhost(loc.t) || mesh_.isOutside(loc.t))) return InsertOutcome::kOutside;
  const VertexId v = mesh_.addVertex(p);
  *id = v;
  return insertLocated(v, loc);
}

void Triangulator::insertPoints(const Point2* points, std::size_t count, VertexId* ids, InsertOutcome* outcomes,
                                const TriangleId* hints) {
  order_.resize(count);
  for (std::size_t i = 0; i < count; ++i) order_[i] = static_cast<std::uint32_t>(i);
  kdPermutation(points, order_.data(), count);
  std::vector<KdRange> queue;
  const auto triangles = static_cast<TriangleId>(mesh_.triangleCount());
  forEachBreadthFirst(order_.data(), count, queue, [&](std::uint32_t i, std::uint32_t parent) {
    TriangleId hint = lastTouched_;
    if (hints && hints[i] < triangles) {
      hint = hints[i];
    } else if (parent != UINT32_MAX && ids[parent] != kNoVertex) {
      hint = mesh_.incident(ids[parent]);
    }
    const InsertOutcome o = insertPoint(points[i], &ids[i], hint);
    if (outcomes) outcomes[i] = o;
  });
}

// ---------------------------------------------------------------------------------------------
// Constraints.

void Triangulator::setConstraintFlags(VertexId a, VertexId b) {
  const EdgeRef e = mesh_.findEdge(a, b);
  assert(e.t != kNoTriangle);
  mesh_.setFlag(e.t, e.i, static_cast<EdgeFlag>(mesh_.flag(e.t, e.i) | kAlongLoop));
}

// Lawson's flips on a set of edges given by their endpoints: each edge that is unconstrained and not
// locally Delaunay is flipped, and the four edges around it are checked again.
void Triangulator::legalizeEdges(std::vector<std::pair<VertexId, VertexId>>& stack) {
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    const EdgeRef e = mesh_.findEdge(x, y);
    if (e.t == kNoTriangle || mesh_.isConstrained(e.t, e.i)) continue;
    const EdgeRef across = mesh_.twin(e);
    const VertexId d = mesh_.vertex(across.t, across.i);
    if (!inCircumcircle(mesh_, e.t, d)) continue;
    const VertexId p = mesh_.vertex(e.t, e.i);
    mesh_.flip(e.t, e.i);
    stack.emplace_back(p, x);
    stack.emplace_back(x, d);
    stack.emplace_back(d, y);
    stack.emplace_back(y, p);
  }
}

bool Triangulator::flipEdge(TriangleId t, int i) {
  if (t >= mesh_.triangleCount() || mesh_.isGhost(t) || mesh_.isConstrained(t, i)) return false;
  const EdgeRef across = mesh_.twin(EdgeRef{t, i});
  if (across.t == kNoTriangle || mesh_.isGhost(across.t)) return false;
  const Point2 pa = mesh_.point(mesh_.vertex(t, i)), pd = mesh_.point(mesh_.vertex(across.t, across.i));
  const double ox = orient2d(pa, pd, mesh_.point(mesh_.edgeOrigin(EdgeRef{t, i})));
  const double oy = orient2d(pa, pd, mesh_.point(mesh_.edgeDestination(EdgeRef{t, i})));
  if (!((ox > 0.0 && oy < 0.0) || (ox < 0.0 && oy > 0.0))) return false;
  mesh_.flip(t, i, across.i);
  return true;
}

Status Triangulator::insertSegment(VertexId a, VertexId b) {
  const auto n = static_cast<VertexId>(mesh_.vertexCount());
  if (a >= n || b >= n) {
    return Status{Status::Code::kBadVertex, "segment " + vertexName(a) + "-" + vertexName(b) + " names a vertex that does not exist"};
  }
  if (mesh_.empty()) return Status{Status::Code::kNoTriangulation, "no triangulation yet (all points collinear)"};
  a = representative(a);
  b = representative(b);
  if (mesh_.incident(a) == kNoTriangle || mesh_.incident(b) == kNoTriangle) {
    return Status{Status::Code::kBadVertex, "segment " + vertexName(a) + "-" + vertexName(b) + " has a vertex that is not inserted"};
  }
  ++segmentCount_;
  while (a != b) {
    VertexId reached = kNoVertex;
    Status s = insertSegmentPiece(a, b, &reached);
    if (!s.ok()) return s;
    a = reached;
  }
  return Status{};
}

// Inserts the part of a -> b up to the first vertex it meets (b, or a vertex exactly on the segment),
// returned in *reached.
Status Triangulator::insertSegmentPiece(VertexId a, VertexId b, VertexId* reached) {
  if (mesh_.findEdge(a, b).t != kNoTriangle || mesh_.findEdge(b, a).t != kNoTriangle) {
    setConstraintFlags(a, b);
    *reached = b;
    return Status{};
  }
  const Point2 pa = mesh_.point(a), pb = mesh_.point(b);
  // 1. Around a, find the triangle (a, x, y) whose angle at a holds the direction of b, or a
  //    neighbour x exactly on the segment.
  TriangleId t = mesh_.incident(a);
  const TriangleId first = t;
  TriangleId start = kNoTriangle;
  int startEdge = 0;
  VertexId right = kNoVertex, left = kNoVertex;
  do {
    if (!mesh_.isGhost(t)) {
      const int k = mesh_.indexOf(t, a);
      const VertexId x = mesh_.vertex(t, next3(k)), y = mesh_.vertex(t, prev3(k));
      const double ox = orient2d(pa, pb, mesh_.point(x));
      if (ox == 0.0 && strictlyBetween(pa, pb, mesh_.point(x))) {
        setConstraintFlags(a, x);
        *reached = x;
        return Status{};
      }
      const double oy = orient2d(pa, pb, mesh_.point(y));
      if (oy == 0.0 && strictlyBetween(pa, pb, mesh_.point(y))) {
        // Reached here when (a, y) is a hull edge, whose other triangle is a ghost.
        setConstraintFlags(a, y);
        *reached = y;
        return Status{};
      }
      if (ox < 0.0 && oy > 0.0) {
        start = t, startEdge = k, right = x, left = y;
        break;
      }
    }
    t = mesh_.nextAround(t, a);
  } while (t != first);
  if (start == kNoTriangle) {
    return Status{Status::Code::kBadVertex, "segment " + vertexName(a) + "-" + vertexName(b) + " leaves the triangulation"};
  }

  // 2. Walk along the segment collecting the crossed edges (as right/left vertex pairs). A crossed
  //    constraint is an error, found before anything changes; a vertex on the segment ends the piece.
  std::vector<std::pair<VertexId, VertexId>> crossed;
  VertexId stop = kNoVertex;
  t = start;
  int edge = startEdge;
  for (;;) {
    if (mesh_.isConstrained(t, edge)) {
      return Status{Status::Code::kCrossingSegments,
                    "segment " + vertexName(a) + "-" + vertexName(b) + " crosses the constraint edge " +
                        vertexName(right) + "-" + vertexName(left),
                    {right, left}};
    }
    crossed.emplace_back(right, left);
    const EdgeRef across = mesh_.twin(EdgeRef{t, edge});
    const VertexId z = mesh_.vertex(across.t, across.i);
    if (z == b) {
      stop = b;
      break;
    }
    const double oz = orient2d(pa, pb, mesh_.point(z));
    if (oz == 0.0) {
      stop = z;
      break;
    }
    t = across.t;
    if (oz > 0.0) {
      edge = mesh_.indexOf(t, left);  // next crossed edge: (right, z), opposite the old left vertex
      left = z;
    } else {
      edge = mesh_.indexOf(t, right);  // next crossed edge: (z, left), opposite the old right vertex
      right = z;
    }
  }
  const Point2 ps = mesh_.point(stop);

  // 3. Flip the crossed edges away (Sloan). An edge whose quadrilateral is not strictly convex waits
  //    at the back of the queue; one always can be flipped, so this terminates.
  std::deque<std::pair<VertexId, VertexId>> queue(crossed.begin(), crossed.end());
  std::vector<std::pair<VertexId, VertexId>> created;
  while (!queue.empty()) {
    const auto [x, y] = queue.front();
    queue.pop_front();
    const EdgeRef e = mesh_.findEdge(x, y);
    assert(e.t != kNoTriangle);
    const VertexId p = mesh_.vertex(e.t, e.i);
    const EdgeRef across = mesh_.twin(e);
    const VertexId q = mesh_.vertex(across.t, across.i);
    const Point2 pp = mesh_.point(p), pq = mesh_.point(q);
    const double ox = orient2d(pp, pq, mesh_.point(x)), oy = orient2d(pp, pq, mesh_.point(y));
    if (!((ox > 0.0 && oy < 0.0) || (ox < 0.0 && oy > 0.0))) {
      queue.emplace_back(x, y);
      continue;
    }
    mesh_.flip(e.t, e.i);
    if ((p == a && q == stop) || (p == stop && q == a)) continue;
    const double op = orient2d(pa, ps, pp), oq = orient2d(pa, ps, pq);
    if ((op > 0.0 && oq < 0.0) || (op < 0.0 && oq > 0.0)) {
      queue.emplace_back(p, q);
    } else {
      created.emplace_back(p, q);
    }
  }
  setConstraintFlags(a, stop);
  // 4. The new edges may not be Delaunay: Lawson's flips around them (the segment is now fixed).
  legalizeEdges(created);
  *reached = stop;
  return Status{};
}

Status Triangulator::replaceConstraint(VertexId a, VertexId b, const Point2* points, std::size_t count, VertexId* ids) {
  const auto n = static_cast<VertexId>(mesh_.vertexCount());
  if (a >= n || b >= n) return Status{Status::Code::kBadVertex, "replaceConstraint: no such vertex"};
  a = representative(a);
  b = representative(b);
  const EdgeRef e = mesh_.findEdge(a, b);
  if (e.t == kNoTriangle || (mesh_.flag(e.t, e.i) & kAlongLoop) == 0) {
    return Status{Status::Code::kBadVertex,
                  "replaceConstraint: " + vertexName(a) + "->" + vertexName(b) + " is not a constraint edge"};
  }
  mesh_.setFlag(e.t, e.i, static_cast<EdgeFlag>(mesh_.flag(e.t, e.i) & ~kAlongLoop));
  for (std::size_t i = 0; i < count; ++i) {
    const Location loc = locate(points[i], mesh_.incident(a));
    if (loc.kind == Location::Kind::kOnVertex) {
      ids[i] = mesh_.vertex(loc.t, loc.i);
      continue;
    }
    const VertexId v = mesh_.addVertex(points[i]);
    insertLocated(v, loc);
    ids[i] = v;
  }
  VertexId from = a;
  for (std::size_t i = 0; i <= count; ++i) {
    const VertexId to = i < count ? ids[i] : b;
    Status s = insertSegment(from, to);
    if (!s.ok()) return s;
    from = to;
  }
  return Status{};
}

// ---------------------------------------------------------------------------------------------
void Triangulator::markDomain(DomainRule rule, const Point2* holes, std::size_t holeCount) {
  const auto m = static_cast<TriangleId>(mesh_.triangleCount());
  std::vector<TriangleId> stack;
  for (TriangleId t = 0; t < m; ++t) {
    mesh_.setOutside(t, false);
    if (mesh_.isGhost(t)) {
      if (segmentCount_ > 0) {
        stack.push_back(t);
      } else {
        mesh_.setOutside(t, true);  // ghosts are never part of the domain
      }
    } else if (rule == DomainRule::kLoopOrientation) {
      for (int i = 0; i < 3; ++i) {
        if (mesh_.flag(t, i) == kAgainstLoop) {
          stack.push_back(t);
          break;
        }
      }
    }
  }
  // Hole points in kd order, each walk starting where the previous one ended: short walks even
  // for thousands of holes.
  std::vector<std::uint32_t> holeOrder(holeCount);
  for (std::size_t h = 0; h < holeCount; ++h) holeOrder[h] = static_cast<std::uint32_t>(h);
  kdPermutation(holes, holeOrder.data(), holeCount);
  TriangleId hint = lastTouched_;
  for (std::size_t k = 0; k < holeCount && m > 0; ++k) {
    const Location loc = locate(holes[holeOrder[k]], hint);
    hint = loc.t;
    if (!mesh_.isGhost(loc.t)) stack.push_back(loc.t);
  }
  while (!stack.empty()) {
    const TriangleId t = stack.back();
    stack.pop_back();
    if (mesh_.isOutside(t)) continue;
    mesh_.setOutside(t, true);
    for (int i = 0; i < 3; ++i) {
      if (!mesh_.isConstrained(t, i)) {
        const TriangleId n = mesh_.neighbor(t, i);
        if (!mesh_.isOutside(n)) stack.push_back(n);
      }
    }
  }
  domainMarked_ = true;
}

void Triangulator::collectTriangles(std::vector<VertexId>& indices) const {
  indices.clear();
  const auto m = static_cast<TriangleId>(mesh_.triangleCount());
  for (TriangleId t = 0; t < m; ++t) {
    if (mesh_.isOutside(t) || mesh_.isGhost(t)) continue;
    indices.push_back(mesh_.vertex(t, 0));
    indices.push_back(mesh_.vertex(t, 1));
    indices.push_back(mesh_.vertex(t, 2));
  }
}

std::size_t Triangulator::insideTriangleCount() const {
  std::size_t count = 0;
  const auto m = static_cast<TriangleId>(mesh_.triangleCount());
  for (TriangleId t = 0; t < m; ++t) {
    if (!mesh_.isOutside(t) && !mesh_.isGhost(t)) ++count;
  }
  return count;
}

}  // namespace cet
