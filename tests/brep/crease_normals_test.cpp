// Vertex normals on a crease of the surface (a C0 knot of a B-spline): each triangle's corners show
// the exact normal of the triangle's own side of the crease (FaceMesher::showCreaseCorners).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "brep/tessellator.h"
#include "measure_impl.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

// A sheet 10 x 10 in z = 0 on its first knot span (u in [0, 1]), bent at the knot u = 1 (of
// multiplicity 1: C0 there) into a second span that rises to `farRow` at u = 2; linear in u, and in
// v a parabola whose middle control row is raised by `roll` (0: bilinear, flat on each span; else
// curved on both sides of the bend, so the face mesher refines there).
Handle(Geom_BSplineSurface) bentSheet(const gp_Pnt& farRow, double roll = 0) {
  const gp_Pnt rows[3] = {gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), farRow};
  TColgp_Array2OfPnt poles(1, 3, 1, 3);
  for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
    for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j)
      poles.SetValue(i, j, rows[i - 1].Translated(gp_Vec(0, 5.0 * (j - 1), j == 2 ? roll : 0)));
  TColStd_Array1OfReal uKnots(1, 3), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, 3), vMults(1, 2);
  for (int k = 1; k <= 3; ++k) uKnots(k) = k - 1, uMults(k) = k == 2 ? 1 : 2;
  vKnots(1) = 0, vKnots(2) = 1, vMults(1) = vMults(2) = 3;
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 1, 2);
}

// Every corner of every triangle on every level against the exact normal a step (1e-6 of the way
// to the centroid) inside the triangle, in the face's orientation, and the triangle faces its
// corners' way; triangles across the crease (corners on both sides of u = 1) have no one side and
// are left out. Returns how many corners were checked.
int expectCornersShowTheirSidesNormal(const Tessellator& t, const Handle(Geom_Surface)& surface) {
  int checked = 0;
  const FaceMesh& m = t.faceMesh(0);
  const double sign = t.model().faces()[0].reversed ? -1 : 1;
  for (std::size_t k = 0; k < m.levels.size(); ++k) {
    const std::vector<std::uint32_t>& idx = m.levels[k];
    for (std::size_t i = 0; i + 2 < idx.size(); i += 3) {
      const double* uv[3] = {&m.uv[2 * idx[i]], &m.uv[2 * idx[i + 1]], &m.uv[2 * idx[i + 2]]};
      bool below = false, above = false;
      for (const double* c : uv) below = below || c[0] < 1 - 1e-9, above = above || c[0] > 1 + 1e-9;
      if (below && above) continue;
      EXPECT_EQ(triangleFacing(m.positions.data(), m.normals.data(), &idx[i]), TriangleFacing::kFacing)
          << "level " << k << ", triangle " << i / 3;
      const double cu = (uv[0][0] + uv[1][0] + uv[2][0]) / 3, cv = (uv[0][1] + uv[1][1] + uv[2][1]) / 3;
      for (int c = 0; c < 3; ++c) {
        gp_Pnt p;
        gp_Vec du, dv;
        surface->D1(uv[c][0] + 1e-6 * (cu - uv[c][0]), uv[c][1] + 1e-6 * (cv - uv[c][1]), p, du, dv);
        const gp_Vec exact = sign * du.Crossed(dv).Normalized();
        const float* n = &m.normals[3 * idx[i + c]];
        const double angle = exact.Angle(gp_Vec(n[0], n[1], n[2])) * 180 / M_PI;
        EXPECT_LT(angle, 1.0) << "level " << k << ", corner (" << uv[c][0] << ", " << uv[c][1] << ")";
        ++checked;
      }
    }
  }
  return checked;
}

// The L-shaped face below (all of the first span, the upper half of the second) and a rectangle
// across the bend, in the sheet's (u, v).
const std::vector<gp_Pnt2d> kLFace = {{0, 0}, {1, 0}, {1, 0.5}, {2, 0.5}, {2, 1}, {0, 1}};
const std::vector<gp_Pnt2d> kAcrossTheBend = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};

// Tessellates the face with `corners` on bentSheet(farRow, roll) at 1% and 0.1% for each far row,
// and hands each run to `check` (in a trace naming the sheet and deflection).
void forEachSheetFace(
    std::initializer_list<gp_Pnt> farRows, double roll, const std::vector<gp_Pnt2d>& corners,
    const std::function<void(const Tessellator&, const Handle(Geom_BSplineSurface) &)>& check) {
  for (const gp_Pnt& farRow : farRows) {
    const Handle(Geom_BSplineSurface) surface = bentSheet(farRow, roll);
    auto model = test::loadShape(test::uvPolygonFace(surface, corners), "face_on_a_bent_sheet");
    ASSERT_TRUE(model);
    for (double d : {0.01, 0.001}) {
      SCOPED_TRACE("far row z " + std::to_string(farRow.Z()) + ", at " + std::to_string(d * 100) + "%");
      auto t = test::tessellate(*model, test::relative(d));
      ASSERT_TRUE(t);
      check(*t, surface);
    }
  }
}

// An L-shaped face on the bent sheet: all of the first span and the upper half of the second. Its
// side from (1, 0) to (1, 0.5) runs along the crease with the face below it only, and its
// parameter box reaches past the knot, where the evaluators take the span above: the vertices on
// that side showed the normal of the part bent up (90 degrees off on a sheet-metal bracket; on a
// sheet folded back, facing away, and the triangles along that side flipped).
TEST(CreaseNormals, AFaceAlongACreaseShowsItsOwnSidesNormals) {
  const struct {
    const char* name;
    gp_Pnt farRow;
  } sheets[] = {{"bracket bent by 90 degrees", gp_Pnt(10, 0, 10)}, {"sheet folded back", gp_Pnt(0, 0, 1)}};
  for (const auto& sheet : sheets) {
    for (const bool reversed : {false, true}) {
      SCOPED_TRACE(std::string(sheet.name) + (reversed ? ", face reversed" : ""));
      const Handle(Geom_BSplineSurface) surface = bentSheet(sheet.farRow);
      TopoDS_Face face = test::uvPolygonFace(surface, kLFace);
      if (reversed) face.Reverse();
      auto model = test::loadShape(face, "l_face_on_a_crease");
      ASSERT_TRUE(model);
      for (double d : {0.01, 0.001}) {
        SCOPED_TRACE("at " + std::to_string(d * 100) + "%");
        auto t = test::tessellate(*model, test::relative(d));
        ASSERT_TRUE(t);
        EXPECT_GT(expectCornersShowTheirSidesNormal(*t, surface), 0);
      }
    }
  }
}

// The same L-face's sides on flat ground: the side along the bend (u = 1, v from 0 to 0.5) and the
// side that ends on it (v = 0, u from 0 to 1) are straight lines on a flat part of the sheet, and no
// criterion asks for a point inside them, on any level. The edges took the normals at their ends
// on the crease from the part bent up (the span OpenCASCADE evaluates there): every triangle
// standing on the side along the bend failed the angle and it was halved level after level (4098
// points at 0.1%, 4139 triangles for two flat plates); the side ending there was halved towards
// that end down to the minimum size.
TEST(CreaseNormals, SidesAlongAndOntoTheBendOfFlatPlatesAreNotSplit) {
  const auto check = [](const Tessellator& t, const Handle(Geom_BSplineSurface)&) {
    const FaceMesh& m = t.faceMesh(0);
    ASSERT_FALSE(m.levels.empty());
    for (std::size_t k = 0; k < m.levels.size(); ++k) {
      int alongTheBend = 0, ontoTheBend = 0;
      for (const std::uint32_t i : m.levels[k]) {
        const double u = m.uv[2 * i], v = m.uv[2 * i + 1];
        alongTheBend += std::abs(u - 1) < 1e-9 && v > 1e-9 && v < 0.5 - 1e-9;
        ontoTheBend += std::abs(v) < 1e-9 && u > 1e-9 && u < 1 - 1e-9;
      }
      // (counted once per triangle corner)
      EXPECT_EQ(alongTheBend, 0) << "level " << k;
      EXPECT_EQ(ontoTheBend, 0) << "level " << k;
    }
  };
  forEachSheetFace({gp_Pnt(10, 0, 10), gp_Pnt(0, 0, 1)}, 0, kLFace, check);
}

// A face across the bend of a sheet rolled along it (curved on both sides, so refined there): the
// vertices on the crease inside the face and on its sides are used by triangles on both sides, and
// each side's triangles show their own normal there (a twin vertex for the other side,
// FaceMesher::showCreaseCorners). Without the twins, 141 checks of corners and facing fail, and
// the twin count on every run.
TEST(CreaseNormals, ACreaseThroughAFaceShowsBothSidesNormals) {
  const auto check = [](const Tessellator& t, const Handle(Geom_BSplineSurface) & surface) {
    EXPECT_GT(expectCornersShowTheirSidesNormal(t, surface), 0);
    // The crease's vertices come twice (one per side): some point on it appears with two normals.
    const FaceMesh& m = t.faceMesh(0);
    std::map<std::pair<double, double>, int> onCrease;
    for (std::size_t i = 0; 2 * i < m.uv.size(); ++i)
      if (std::abs(m.uv[2 * i] - 1) < 1e-9) ++onCrease[{m.uv[2 * i], m.uv[2 * i + 1]}];
    int twinned = 0;
    for (const auto& [uv, count] : onCrease) twinned += count > 1;
    EXPECT_GT(twinned, 0);
  };
  forEachSheetFace({gp_Pnt(10, 0, 10), gp_Pnt(0, 0, 1)}, 3, kAcrossTheBend, check);
}

// The rolled bracket, and a sheet rolled the same way but bent by 58 degrees: no triangle on any
// level bridges the bend, its corners a hair either side of it (u = 0.9995 and 1.001: points the
// deviation put beside the bend), its facet standing for both plates and its corners showing each
// one's normal, a streak of the other plate's shading across it. The refinement puts a point on the
// bend where such a triangle's edge crosses it (FaceMesher::creasePoint). Before, 72 of the
// bracket's 462 triangles at 0.1% bridged it; 9 level checks fail without the split. (Not on a
// fold: the sheet folded back still has 35 of its 272 triangles across the fold, 4 flipped.)
TEST(CreaseNormals, NoTriangleBridgesABend) {
  const auto check = [](const Tessellator& t, const Handle(Geom_BSplineSurface)&) {
    const FaceMesh& m = t.faceMesh(0);
    ASSERT_EQ(m.levels.size(), t.schedule().size());
    for (std::size_t k = 0; k < m.levels.size(); ++k) {
      const std::vector<std::uint32_t>& idx = m.levels[k];
      int bridging = 0, onBothSides = 0;
      for (std::size_t i = 0; i + 2 < idx.size(); i += 3) {
        bool below = false, above = false;
        for (int c = 0; c < 3; ++c) {
          const double u = m.uv[2 * idx[i + c]];
          below = below || u < 1 - 1e-9, above = above || u > 1 + 1e-9;
        }
        if (!below || !above) continue;
        ++onBothSides;
        double minCos = 1;
        for (int a = 0; a < 3; ++a) {
          const float* na = &m.normals[3 * idx[i + a]];
          const float* nb = &m.normals[3 * idx[i + (a + 1) % 3]];
          minCos = std::min(minCos, double(na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2]));
        }
        bridging += minCos < std::cos(t.schedule()[k].angleRad);
      }
      EXPECT_EQ(bridging, 0) << "level " << k << " (" << onBothSides << " with corners on both sides)";
    }
  };
  forEachSheetFace({gp_Pnt(10, 0, 10), gp_Pnt(15, 0, 8)}, 3, kAcrossTheBend,
                   check);  // bent by 90 and 58 degrees
}

// tests/brep/data/triangular_tube_creased_where_its_speed_jumps.brep, written by face_fuzz: a
// rational B-spline tube, degree 1 around (three rows of poles, so a crease at each knot, turning
// about 60 degrees) and a conic along, its weights from 0.002 to 298: across the knot at u =
// 0.5146 the surface runs 50 to 100 times faster on one side than on the other. The refinement's
// deviation splits of triangles across that crease fell at their worst samples, a hair beside the
// line, and each left slivers across it that read over again: 36541 triangles on level 0 (3230
// flipped), 135233 on the last (249 flipped, 15 of them across folds), with 45385 points on the
// line and 29k within 1e-5 of it. A deviation split of a triangle across a bend goes onto the bend's
// line, as one across a sharp knot does (FaceMesher::ontoCreaseLine): 5219 and 8689 triangles, 17
// flipped on the last level, 16 of them across folds.
TEST(CreaseNormals, DeviationSplitsAcrossABendGoOntoItsLine) {
  const std::vector<FaceQuality> levels =
      test::testDataEveryLevel("triangular_tube_creased_where_its_speed_jumps.brep",
                               test::fuzzed("triangular_tube_creased_where_its_speed_jumps.brep", 0.00041551383498714553, 24.253986419470511));
  ASSERT_FALSE(levels.empty());
  for (std::size_t k = 0; k < levels.size(); ++k) {
    EXPECT_EQ(levels[k].degenerate, 0u) << "level " << k;
    EXPECT_LE(levels[k].flipped - levels[k].flippedAcrossFolds, 10u)
        << "level " << k << " (3221 on level 0, 234 on the last with the splits beside the line)";
  }
  EXPECT_LE(levels.front().triangles, 10000u) << "36541 with the splits beside the line";
  EXPECT_LE(levels.back().triangles, 15000u) << "135233 with the splits beside the line";
}

}  // namespace
}  // namespace cetview::brep
