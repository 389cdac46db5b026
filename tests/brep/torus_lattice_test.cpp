// The torus lattice (torus_lattice.h): its triangles, between neighbouring rows, come within the
// deviation it was made for on the real torus, and not far under it; where the angle binds, the
// normal turns within the angle along every lattice edge, and not far under it; near() finds the
// nearest points; tori it cannot serve get none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "torus_lattice.h"

namespace cetview::brep {
namespace {

void onTorus(double R, double r, double u, double v, double p[3]) {
  const double rho = R + r * std::cos(v);
  p[0] = rho * std::cos(u), p[1] = rho * std::sin(u), p[2] = r * std::sin(v);
}

// Distance from p to the torus (axis z through the origin).
double toTorus(double R, double r, const double p[3]) {
  const double rho = std::hypot(p[0], p[1]);
  return std::abs(std::hypot(rho - R, p[2]) - r);
}

// The largest distance from the flat triangle (a, b, c) to the torus, over a fine grid of samples.
double triangleDeviation(double R, double r, const LatticePoint& a, const LatticePoint& b, const LatticePoint& c) {
  double pa[3], pb[3], pc[3];
  onTorus(R, r, a.u, a.v, pa), onTorus(R, r, b.u, b.v, pb), onTorus(R, r, c.u, c.v, pc);
  const int n = 40;
  double worst = 0;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double x = double(i) / n, y = double(j) / n, z = 1 - x - y;
      const double p[3] = {x * pa[0] + y * pb[0] + z * pc[0], x * pa[1] + y * pb[1] + z * pc[1],
                           x * pa[2] + y * pb[2] + z * pc[2]};
      worst = std::max(worst, toTorus(R, r, p));
    }
  }
  return worst;
}

// Every triangle between two neighbouring rows of the same step: two neighbours on one row and the
// point of the other row between them. Returns the largest deviation and the count.
double worstBetweenRows(const TorusLatticeSpec& spec, const TorusLattice& lattice, int& triangles) {
  double worst = 0;
  triangles = 0;
  for (int j = 1; j < lattice.rowCount(); ++j) {
    const std::vector<LatticePoint> rows[2] = {lattice.row(j), lattice.row(j + 1)};
    if (rows[0].empty() || rows[1].empty() || rows[0][0].step != rows[1][0].step) continue;
    for (int k = 0; k < 2; ++k) {
      const std::vector<LatticePoint>& base = rows[k];
      const std::vector<LatticePoint>& other = rows[1 - k];
      for (std::size_t i = 0; i + 1 < base.size(); ++i) {
        const double middle = 0.5 * (base[i].u + base[i + 1].u);
        for (const LatticePoint& apex : other) {
          if (std::abs(apex.u - middle) > 1e-9 * base[i].step) continue;
          worst = std::max(worst, triangleDeviation(spec.major, spec.minor, base[i], base[i + 1], apex));
          ++triangles;
        }
      }
    }
  }
  return worst;
}

TEST(TorusLattice, TrianglesComeWithinTheDeviationAndNotFarUnder) {
  // bottle's fillets at 0.01%; a full fat torus (its inside bends the other way); a thin ring; a
  // sphere (major radius 0) from 70 degrees south to 70 north.
  const TorusLatticeSpec specs[] = {
      {82.9, 2.5, 0.02, 0.82, 0, M_PI / 2, 0.0082, 20 * M_PI / 180, 1e6},
      {3, 1, 0, 2 * M_PI, 0, 2 * M_PI, 0.001, 20 * M_PI / 180, 1e6},
      {20, 0.15, 0, M_PI, -M_PI / 2, M_PI / 2, 0.0005, 20 * M_PI / 180, 1e6},
      {0, 5, 0, 2 * M_PI, -1.22, 1.22, 0.002, 20 * M_PI / 180, 1e6},
  };
  for (const TorusLatticeSpec& spec : specs) {
    SCOPED_TRACE("torus " + std::to_string(spec.major) + " x " + std::to_string(spec.minor));
    const TorusLattice lattice(spec);
    ASSERT_FALSE(lattice.empty());
    int triangles = 0;
    const double worst = worstBetweenRows(spec, lattice, triangles);
    EXPECT_GT(triangles, 100);
    EXPECT_LE(worst, 1.02 * spec.deviation);
    // Equilateral where the tube bends most: the worst triangle uses nearly all of the deviation
    // (BRepMesh's grid of right triangles at half the deviation each way would be 0.77x as sparse).
    EXPECT_GE(worst, 0.9 * spec.deviation);
  }
}

// The angle between the torus's normals at (u0, v0) and (u1, v1) (axis z).
double normalTurn(double u0, double v0, double u1, double v1) {
  const double a[3] = {std::cos(v0) * std::cos(u0), std::cos(v0) * std::sin(u0), std::sin(v0)};
  const double b[3] = {std::cos(v1) * std::cos(u1), std::cos(v1) * std::sin(u1), std::sin(v1)};
  return std::acos(std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], -1.0, 1.0));
}

TEST(TorusLattice, WhereTheAngleBindsEveryEdgeTurnsTheNormalWithinIt) {
  // A unit sphere and a torus of 3 x 1 at 1% of their boxes' diagonals, 20 degrees: the sag would
  // allow edges turning the normal by 30 to 45 degrees. Every edge between neighbouring points, on
  // a row and to the row above, turns within the angle, the longest nearly by all of it; rows on
  // the tube's inside take points too.
  const double angle = 20 * M_PI / 180;
  const TorusLatticeSpec specs[] = {
      {0, 1, 0, 2 * M_PI, -1.3, 1.3, 0.0346, angle, 1e6},
      {3, 1, 0, 2 * M_PI, 0, 2 * M_PI, 0.0917, angle, 1e6},
  };
  for (const TorusLatticeSpec& spec : specs) {
    SCOPED_TRACE("torus " + std::to_string(spec.major) + " x " + std::to_string(spec.minor));
    const TorusLattice lattice(spec);
    ASSERT_FALSE(lattice.empty());
    double worst = 0;
    int edges = 0, inside = 0;
    for (int j = 1; j <= lattice.rowCount(); ++j) {
      const std::vector<LatticePoint> row = lattice.row(j);
      if (!row.empty() && std::cos(row[0].v) < 0) ++inside;
      for (std::size_t i = 0; i + 1 < row.size(); ++i) {
        worst = std::max(worst, normalTurn(row[i].u, row[i].v, row[i + 1].u, row[i + 1].v));
        ++edges;
      }
      if (j == lattice.rowCount()) continue;
      for (const LatticePoint& a : row) {
        for (const LatticePoint& b : lattice.row(j + 1)) {
          if (std::abs(b.u - a.u) > 0.5 * std::max(a.step, b.step) + 1e-12) continue;  // not a neighbour
          worst = std::max(worst, normalTurn(a.u, a.v, b.u, b.v));
          ++edges;
        }
      }
    }
    EXPECT_GT(edges, 100);
    EXPECT_LE(worst, angle * (1 + 1e-9));
    EXPECT_GE(worst, 0.9 * angle);
    if (spec.major > 0) {
      EXPECT_GT(inside, 2);
    }
  }
}

TEST(TorusLattice, RowsThinWhereTheTubeBendsLessAlongIt) {
  // From the outside (v = 0) over the top (v = pi / 2): the u step doubles towards the top.
  const TorusLatticeSpec spec{82.9, 2.5, 0.02, 0.82, 0, M_PI / 2, 0.0082, 20 * M_PI / 180, 1e6};
  const TorusLattice lattice(spec);
  ASSERT_GE(lattice.rowCount(), 8);
  EXPECT_EQ(lattice.row(1)[0].step, lattice.uStep());
  EXPECT_GT(lattice.row(lattice.rowCount())[0].step, lattice.uStep());
  for (int j = 1; j < lattice.rowCount(); ++j) EXPECT_LE(lattice.row(j)[0].step, lattice.row(j + 1)[0].step);
}

TEST(TorusLattice, NoPointsOnTheTubesInside) {
  // Pump_Nut's inner fillets (v from pi / 2 to pi): saddles, left to the refinement's own splits
  // (with the lattice there, 2206 triangles on one at 0.01% against 1814).
  EXPECT_TRUE(TorusLattice({16, 1, 0, 2 * M_PI, M_PI / 2, M_PI, 0.006, 20 * M_PI / 180, 1e6}).empty());
  const TorusLattice whole({3, 1, 0, 2 * M_PI, 0, 2 * M_PI, 0.001, 20 * M_PI / 180, 1e6});
  int rows = 0;
  for (int j = 1; j <= whole.rowCount(); ++j) {
    const std::vector<LatticePoint> row = whole.row(j);
    if (row.empty()) continue;
    ++rows;
    EXPECT_GT(std::cos(row[0].v), 0) << "row " << j;
  }
  EXPECT_GT(rows, whole.rowCount() / 3);
}

TEST(TorusLattice, NearFindsTheNearestPointsInsideTheBox) {
  const TorusLatticeSpec spec{3, 1, 0, 1, 0, 1, 0.001, 20 * M_PI / 180, 1e6};
  const TorusLattice lattice(spec);
  ASSERT_FALSE(lattice.empty());
  const std::vector<LatticePoint> row = lattice.row(3);
  ASSERT_GE(row.size(), 3u);
  std::vector<LatticePoint> near;
  lattice.near(row[1].u + 0.1 * row[1].step, row[1].v + 0.1 * lattice.vStep(), near);
  bool found = false;
  for (const LatticePoint& p : near) {
    EXPECT_GT(p.u, spec.u0);
    EXPECT_LT(p.u, spec.u1);
    EXPECT_GT(p.v, spec.v0);
    EXPECT_LT(p.v, spec.v1);
    found = found || (p.u == row[1].u && p.v == row[1].v);
  }
  EXPECT_TRUE(found);
  // Beyond the box's side: only points inside it.
  lattice.near(spec.u1 + 0.5, 0.5, near);
  for (const LatticePoint& p : near) EXPECT_LT(p.u, spec.u1);
}

TEST(TorusLattice, NoneForSpindleToriOrWhenTooLarge) {
  EXPECT_TRUE(TorusLattice({1, 2, 0, 1, 0, 1, 0.001, 0.3, 1e6}).empty());     // spindle: R < r
  EXPECT_TRUE(TorusLattice({3, 1, 0, 1, 0, 1, 0, 0.3, 1e6}).empty());         // no tolerance
  EXPECT_TRUE(TorusLattice({3, 1, 0, 1, 0, 1, 1e-7, 0.3, 1e4}).empty());      // over maxPoints
  EXPECT_TRUE(TorusLattice({3, 1, 0, 1e-3, 0, 1e-3, 0.001, 0.3, 1e6}).empty());  // no interior row
  EXPECT_FALSE(TorusLattice({3, 1, 0, 1, 0, 1, 1e-5, 0.3, 1e6}).empty());
}

}  // namespace
}  // namespace cetview::brep
