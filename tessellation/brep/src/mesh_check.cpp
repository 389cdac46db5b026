// Mesh checks (see brep/mesh_check.h). The self-intersection search follows Jung, Shin & Choi
// (section 3.2): buckets split by the plane through the middle of the longest side of their box until
// they hold few triangles, then every pair in a bucket is tested with Moeller's interval overlap
// ("A fast triangle-triangle intersection test", 1997), here with distances snapped to zero below a
// tolerance so grazing contacts do not count.
#include "brep/mesh_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "brep/tessellator.h"

namespace cetview::brep {
namespace {

using V3 = std::array<double, 3>;
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(const V3& a, const V3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const V3& a) { return std::sqrt(dot(a, a)); }

// Signed distances of p's corners to q's plane, snapped to zero within eps.
bool planeDistances(const V3 q[3], const V3 p[3], double eps, double d[3]) {
  const V3 n = cross(sub(q[1], q[0]), sub(q[2], q[0]));
  const double len = norm(n);
  if (len == 0) return false;
  for (int i = 0; i < 3; ++i) {
    d[i] = dot(n, sub(p[i], q[0])) / len;
    if (std::abs(d[i]) <= eps) d[i] = 0;
  }
  return true;
}

// The interval a triangle cuts from the line of direction D (Moeller's compute_intervals).
bool interval(const V3 p[3], const double d[3], const V3& D, double& lo, double& hi) {
  int lone;
  if (d[0] * d[1] > 0) lone = 2;
  else if (d[0] * d[2] > 0) lone = 1;
  else if (d[1] * d[2] > 0 || d[0] != 0) lone = 0;
  else if (d[1] != 0) lone = 1;
  else if (d[2] != 0) lone = 2;
  else return false;  // coplanar
  const int a = (lone + 1) % 3, b = (lone + 2) % 3;
  const double pl = dot(D, p[lone]), pa = dot(D, p[a]), pb = dot(D, p[b]);
  const double ta = d[lone] == d[a] ? pa : pl + (pa - pl) * d[lone] / (d[lone] - d[a]);
  const double tb = d[lone] == d[b] ? pb : pl + (pb - pl) * d[lone] / (d[lone] - d[b]);
  lo = std::min(ta, tb), hi = std::max(ta, tb);
  return true;
}

// Coplanar triangles: intersect when an edge of one properly crosses an edge of the other, or a
// corner lies strictly inside the other (in the plane's dominant projection).
bool coplanarIntersect(const V3 p[3], const V3 q[3], double eps) {
  const V3 n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
  int drop = 0;
  if (std::abs(n[1]) > std::abs(n[drop])) drop = 1;
  if (std::abs(n[2]) > std::abs(n[drop])) drop = 2;
  const int x = (drop + 1) % 3, y = (drop + 2) % 3;
  auto orient = [&](const V3& a, const V3& b, const V3& c) {
    return (b[x] - a[x]) * (c[y] - a[y]) - (b[y] - a[y]) * (c[x] - a[x]);
  };
  const double area = std::abs(orient(p[0], p[1], p[2])) + std::abs(orient(q[0], q[1], q[2]));
  const double tol = eps * std::sqrt(area);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const V3 &a = p[i], &b = p[(i + 1) % 3], &c = q[j], &e = q[(j + 1) % 3];
      const double o1 = orient(a, b, c), o2 = orient(a, b, e), o3 = orient(c, e, a), o4 = orient(c, e, b);
      if (((o1 > tol && o2 < -tol) || (o1 < -tol && o2 > tol)) && ((o3 > tol && o4 < -tol) || (o3 < -tol && o4 > tol)))
        return true;
    }
  }
  auto inside = [&](const V3& v, const V3 t[3]) {
    const double s = orient(t[0], t[1], t[2]) > 0 ? 1 : -1;
    return s * orient(t[0], t[1], v) > tol && s * orient(t[1], t[2], v) > tol && s * orient(t[2], t[0], v) > tol;
  };
  return inside(p[0], q) || inside(q[0], p);
}

// How deep the triangle with plane distances d reaches through the plane: the smaller of its
// reaches on the two sides.
double depthOf(const double d[3]) {
  double above = 0, below = 0;
  for (int i = 0; i < 3; ++i) above = std::max(above, d[i]), below = std::max(below, -d[i]);
  return std::min(above, below);
}

bool trianglesIntersect(const V3 p[3], const V3 q[3], double eps, double minDepth) {
  double dp[3], dq[3];
  if (!planeDistances(q, p, eps, dp) || !planeDistances(p, q, eps, dq)) return false;
  if (minDepth > 0 && std::min(depthOf(dp), depthOf(dq)) <= minDepth) return false;  // both must straddle
  if ((dp[0] > 0 && dp[1] > 0 && dp[2] > 0) || (dp[0] < 0 && dp[1] < 0 && dp[2] < 0)) return false;
  if ((dq[0] > 0 && dq[1] > 0 && dq[2] > 0) || (dq[0] < 0 && dq[1] < 0 && dq[2] < 0)) return false;
  if (dp[0] == 0 && dp[1] == 0 && dp[2] == 0) return coplanarIntersect(p, q, eps);
  const V3 D = cross(cross(sub(p[1], p[0]), sub(p[2], p[0])), cross(sub(q[1], q[0]), sub(q[2], q[0])));
  const double len = norm(D);
  if (len == 0) return false;
  const V3 dir = {D[0] / len, D[1] / len, D[2] / len};
  double a0, a1, b0, b1;
  if (!interval(p, dp, dir, a0, a1) || !interval(q, dq, dir, b0, b1)) return false;
  return std::min(a1, b1) - std::max(a0, b0) > eps;
}

struct Box {
  V3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(const V3& p) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
};

}  // namespace

TriangleSoup partSoup(const Tessellator& t, std::uint32_t part, int level) {
  TriangleSoup soup;
  const PartInfo& info = t.model().parts()[part];
  for (FaceId f = info.firstFace; f < info.firstFace + info.faceCount; ++f) {
    const FaceMesh& m = t.faceMesh(f);
    if (m.levels.empty()) continue;
    const std::size_t k = level < 0 ? m.levels.size() - 1 : std::min<std::size_t>(static_cast<std::size_t>(level), m.levels.size() - 1);
    const auto base = static_cast<std::uint32_t>(soup.positions.size() / 3);
    soup.positions.insert(soup.positions.end(), m.positions.begin(), m.positions.end());
    for (std::uint32_t i : m.levels[k]) soup.indices.push_back(base + i);
    soup.faceOf.insert(soup.faceOf.end(), m.levels[k].size() / 3, f);
  }
  return soup;
}

std::vector<std::uint32_t> weldVertices(const std::vector<double>& positions, double tolerance) {
  const std::size_t n = positions.size() / 3;
  std::vector<std::uint32_t> rep(n);
  // Cells no finer than 1e-15 of the coordinates, so cell indices fit in 64 bits.
  double maxAbs = 0;
  for (double c : positions) maxAbs = std::max(maxAbs, std::abs(c));
  const double cell = std::max({tolerance, 1e-15 * maxAbs, 1e-300});
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>(static_cast<std::uint64_t>(k.x) * 73856093u ^ static_cast<std::uint64_t>(k.y) * 19349663u ^
                                      static_cast<std::uint64_t>(k.z) * 83492791u);
    }
  };
  std::unordered_map<Key, std::vector<std::uint32_t>, Hash> grid;
  grid.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &positions[3 * i];
    const Key k{static_cast<std::int64_t>(std::floor(p[0] / cell)), static_cast<std::int64_t>(std::floor(p[1] / cell)),
                static_cast<std::int64_t>(std::floor(p[2] / cell))};
    rep[i] = static_cast<std::uint32_t>(i);
    bool found = false;
    for (std::int64_t dx = -1; dx <= 1 && !found; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && !found; ++dy)
        for (std::int64_t dz = -1; dz <= 1 && !found; ++dz) {
          auto it = grid.find({k.x + dx, k.y + dy, k.z + dz});
          if (it == grid.end()) continue;
          for (std::uint32_t j : it->second) {
            const double* q = &positions[3 * j];
            if (std::abs(p[0] - q[0]) <= tolerance && std::abs(p[1] - q[1]) <= tolerance && std::abs(p[2] - q[2]) <= tolerance) {
              rep[i] = j;
              found = true;
              break;
            }
          }
        }
    if (!found) grid[k].push_back(static_cast<std::uint32_t>(i));
  }
  return rep;
}

std::size_t countOpenEdges(const TriangleSoup& soup, double weldTolerance, std::size_t* nonManifold) {
  const std::vector<std::uint32_t> rep = weldVertices(soup.positions, weldTolerance);
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(soup.indices.size());
  for (std::size_t t = 0; t + 2 < soup.indices.size(); t += 3) {
    for (int i = 0; i < 3; ++i) {
      std::uint32_t a = rep[soup.indices[t + static_cast<std::size_t>(i)]], b = rep[soup.indices[t + static_cast<std::size_t>((i + 1) % 3)]];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      ++uses[(static_cast<std::uint64_t>(a) << 32) | b];
    }
  }
  std::size_t open = 0, many = 0;
  for (const auto& u : uses) {
    if (u.second == 1) ++open;
    if (u.second > 2) ++many;
  }
  if (nonManifold) *nonManifold = many;
  return open;
}

std::size_t countDegenerate(const TriangleSoup& soup) {
  std::size_t n = 0;
  for (std::size_t t = 0; t + 2 < soup.indices.size(); t += 3) {
    V3 p[3];
    for (int i = 0; i < 3; ++i) {
      const double* q = &soup.positions[3 * soup.indices[t + static_cast<std::size_t>(i)]];
      p[i] = {q[0], q[1], q[2]};
    }
    const double longest = std::max({norm(sub(p[1], p[0])), norm(sub(p[2], p[1])), norm(sub(p[0], p[2]))});
    if (norm(cross(sub(p[1], p[0]), sub(p[2], p[0]))) <= 1e-12 * longest * longest) ++n;
  }
  return n;
}

std::size_t countSelfIntersections(const TriangleSoup& soup, double weldTolerance, double tolerance,
                                   std::vector<std::pair<std::uint32_t, std::uint32_t>>* pairs, std::size_t maxPairs,
                                   double otherFaceDepth) {
  const std::vector<std::uint32_t> rep = weldVertices(soup.positions, weldTolerance);
  const std::size_t n = soup.triangleCount();
  std::vector<std::array<V3, 3>> tri(n);
  std::vector<Box> box(n);
  std::vector<std::array<std::uint32_t, 3>> corner(n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = soup.indices[3 * t + static_cast<std::size_t>(i)];
      tri[t][static_cast<std::size_t>(i)] = {soup.positions[3 * v], soup.positions[3 * v + 1], soup.positions[3 * v + 2]};
      box[t].add(tri[t][static_cast<std::size_t>(i)]);
      corner[t][static_cast<std::size_t>(i)] = rep[v];
    }
  }
  std::unordered_set<std::uint64_t> found;
  constexpr std::size_t kCapacity = 32;  // the bucket capacity C of the paper
  struct Bucket {
    std::vector<std::uint32_t> items;
    int depth;
  };
  std::vector<Bucket> stack;
  Bucket all;
  all.depth = 0;
  all.items.resize(n);
  for (std::size_t t = 0; t < n; ++t) all.items[t] = static_cast<std::uint32_t>(t);
  stack.push_back(std::move(all));
  while (!stack.empty()) {
    Bucket b = std::move(stack.back());
    stack.pop_back();
    bool leaf = b.items.size() <= kCapacity || b.depth > 40;
    if (!leaf) {
      Box bb;
      for (std::uint32_t t : b.items) bb.add(box[t].lo), bb.add(box[t].hi);
      int axis = 0;
      for (int i = 1; i < 3; ++i)
        if (bb.hi[i] - bb.lo[i] > bb.hi[axis] - bb.lo[axis]) axis = i;
      const double mid = 0.5 * (bb.lo[axis] + bb.hi[axis]);
      Bucket left, right;
      left.depth = right.depth = b.depth + 1;
      for (std::uint32_t t : b.items) {
        if (box[t].lo[axis] <= mid) left.items.push_back(t);
        if (box[t].hi[axis] >= mid) right.items.push_back(t);
      }
      if (left.items.size() == b.items.size() || right.items.size() == b.items.size()) {
        leaf = true;  // no improvement: test the bucket as it is
      } else {
        stack.push_back(std::move(left));
        stack.push_back(std::move(right));
      }
    }
    if (!leaf) continue;
    for (std::size_t i = 0; i < b.items.size(); ++i) {
      for (std::size_t j = i + 1; j < b.items.size(); ++j) {
        std::uint32_t s = b.items[i], t = b.items[j];
        if (s > t) std::swap(s, t);
        bool overlap = true;
        for (int a = 0; a < 3 && overlap; ++a)
          overlap = box[s].lo[a] <= box[t].hi[a] + tolerance && box[t].lo[a] <= box[s].hi[a] + tolerance;
        if (!overlap) continue;
        bool shares = false;
        for (std::uint32_t x : corner[s])
          for (std::uint32_t y : corner[t]) shares = shares || x == y;
        if (shares) continue;
        const std::uint64_t key = (static_cast<std::uint64_t>(s) << 32) | t;
        if (found.count(key)) continue;
        const bool sameFace = soup.faceOf.size() != n || soup.faceOf[s] == soup.faceOf[t];  // no face ids: one face
        if (trianglesIntersect(tri[s].data(), tri[t].data(), tolerance, sameFace ? 0.0 : otherFaceDepth)) {
          found.insert(key);
          if (pairs && pairs->size() < maxPairs) pairs->emplace_back(s, t);
        }
      }
    }
  }
  return found.size();
}

}  // namespace cetview::brep
