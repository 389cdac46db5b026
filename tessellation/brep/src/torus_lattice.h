// Where the face mesher splits triangles on a torus or a sphere: the points of a lattice that meets
// the final level's deviation with the fewest points.
//
// Refinement that splits each triangle too far from the surface at its circumcentre packs points
// unevenly: a triangle a little over its tolerance leaves, split there, triangles well under it. On
// a torus the curvature is known everywhere (1 / r round the tube, |cos v| / (R + r cos v) along it),
// and so is the lattice whose triangles are equilateral where the surface's second fundamental form
// is the unit one: staggered rows at equal steps of v, points at equal steps of u on each row (the
// u step taken where the tube bends most along it, doubled on rows that bend less, by powers of two
// so that rows share columns). Its triangles deviate by their circumradius squared over 2 in that
// metric: side sqrt(6 d) for a deviation d, 0.77 times the triangles of the right-angled grid that
// BRepMesh lays on tori (sag d / 2 each way). On the tube's outside only (cos v > 0): its inside is
// a saddle, where the refinement's own splits do better. Where the angle binds (small radii, coarse
// deflections) the lattice is equilateral in the metric of the normal's turn instead, side the
// angle, and the inside takes it too. Splits for the deviation or the angle move to the lattice
// point nearest them (where it still splits the triangle, see FaceMesher::snapToLattice), so every level takes
// lattice points as it needs them and the final level tends to the lattice (bottle's fillets at
// 0.01%: 1294 triangles a face with circumcentres, BRepMesh 988). A sphere is parametrized as the
// torus of major radius 0 (v its latitude), and takes the same lattice (a unit sphere at 0.001:
// 9098 triangles with circumcentres, 7288 with it).
#pragma once

#include <vector>

namespace cetview::brep {

struct TorusLatticeSpec {
  double major = 0, minor = 0;            // the torus's radii (a sphere: 0 and its radius)
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // the face's parameter box
  double deviation = 0;                   // the final level's target deviation of the lattice's triangles
  double angle = 0;                       // the final level's angle (radians): the normal's turn per step at most
  double maxPoints = 0;                   // no lattice (empty()) if it would hold more points
};

struct LatticePoint {
  double u, v;
  double step;  // the u step on its row (for how near another point may come)
};

class TorusLattice {
 public:
  explicit TorusLattice(const TorusLatticeSpec& spec);
  bool empty() const;  // no point anywhere
  // The lattice points about (u, v): on the nearest row and the rows either side, the two nearest
  // in u on each (only points strictly inside the parameter box).
  void near(double u, double v, std::vector<LatticePoint>& out) const;
  // Row j's points (j from 1 to rowCount()), in increasing u; none on the tube's inside.
  std::vector<LatticePoint> row(int j) const;
  int rowCount() const { return static_cast<int>(rows_.size()); }
  double uStep() const { return du_; }  // the finest rows' u step
  double vStep() const { return dv_; }

 private:
  struct Row {
    double v;
    int every;      // the row's u step in units of du_ (a power of two); 0: no points on the row
    double offset;  // its first point's u after u0: half its step on odd rows (staggered)
  };
  TorusLatticeSpec spec_;
  double du_ = 0, dv_ = 0;
  std::vector<Row> rows_;  // rows 1 .. nv - 1 (the box's rims hold edges)
};

}  // namespace cetview::brep
