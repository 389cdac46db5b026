// BSplineDirect (tessellation/brep/src), the refinement's B-spline evaluator, against OpenCASCADE's
// own evaluation (Geom_BSplineSurface::D1) on random surfaces: degrees 1 to 5 (and a few up to 11)
// in each direction, uneven knots with interior multiplicities (down to C0), rational and
// polynomial, at parameters inside, on knots and a little outside the range (where both extend the end span's
// polynomial), and with a placement (a face's location) applied to the poles.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include "bspline_direct.h"

namespace cetview::brep {
namespace {

// Knots 0 < ... < spans with random spacing; interior multiplicities from `mults` (cycled, capped at
// the degree), end multiplicities degree + 1.
void makeKnots(std::mt19937& rng, int degree, int spans, std::vector<int> mults, TColStd_Array1OfReal& knots,
               TColStd_Array1OfInteger& multiplicities, int& poles) {
  std::uniform_real_distribution<double> step(0.2, 3.0);
  knots.Resize(1, spans + 1, false);
  multiplicities.Resize(1, spans + 1, false);
  double t = -1.5;
  poles = 0;
  for (int i = 1; i <= spans + 1; ++i) {
    knots(i) = t;
    t += step(rng);
    const int m = i == 1 || i == spans + 1 ? degree + 1 : std::min(degree, mults[std::size_t(i) % mults.size()]);
    multiplicities(i) = m;
    poles += m;
  }
  poles -= degree + 1;
}

Handle(Geom_BSplineSurface) randomSurface(std::mt19937& rng, int uDegree, int vDegree, bool rational,
                                          const std::vector<int>& mults, int uSpans = 7, int vSpans = 5) {
  TColStd_Array1OfReal uKnots(1, 2), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, 2), vMults(1, 2);
  int nu = 0, nv = 0;
  makeKnots(rng, uDegree, uSpans, mults, uKnots, uMults, nu);
  makeKnots(rng, vDegree, vSpans, mults, vKnots, vMults, nv);
  std::uniform_real_distribution<double> jitter(-0.7, 0.7), weight(0.3, 3.0);
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int i = 1; i <= nu; ++i) {
    for (int j = 1; j <= nv; ++j) {
      poles(i, j) = gp_Pnt(i + jitter(rng), j + jitter(rng), 2 * jitter(rng));
      weights(i, j) = rational ? weight(rng) : 1.0;
    }
  }
  if (rational) return new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, uDegree, vDegree);
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, uDegree, vDegree);
}

// Which evaluation the surface must get: either, the polynomial patches, or the basis functions.
enum class Path { kAny, kPatches, kBasis };

void expectSame(const Handle(Geom_BSplineSurface)& s, std::mt19937& rng, double tolerance = 1e-9,
                Path path = Path::kAny) {
  const auto direct = BSplineDirect::create(s);
  ASSERT_NE(direct, nullptr);
  if (path != Path::kAny) {
    EXPECT_EQ(direct->usesPatches(), path == Path::kPatches) << "the evaluation path tested";
  }
  double u0, u1, v0, v1;
  s->Bounds(u0, u1, v0, v1);
  std::uniform_real_distribution<double> u(u0 - 0.05 * (u1 - u0), u1 + 0.05 * (u1 - u0));
  std::uniform_real_distribution<double> v(v0 - 0.05 * (v1 - v0), v1 + 0.05 * (v1 - v0));
  std::vector<std::pair<double, double>> params;
  for (int i = 0; i < 300; ++i) params.emplace_back(u(rng), v(rng));
  for (int i = 1; i <= s->NbUKnots(); ++i)  // exactly on knots, where spans meet
    for (int j = 1; j <= s->NbVKnots(); ++j) params.emplace_back(s->UKnot(i), s->VKnot(j));
  for (const auto& [pu, pv] : params) {
    gp_Pnt p, q;
    gp_Vec du, dv, eu, ev;
    s->D1(pu, pv, p, du, dv);
    direct->d1(pu, pv, q, eu, ev);
    const double scale = 1.0 + du.Magnitude() + dv.Magnitude();
    EXPECT_NEAR(p.Distance(q), 0.0, tolerance) << "at (" << pu << ", " << pv << ")";
    EXPECT_NEAR(p.Distance(direct->value(pu, pv)), 0.0, tolerance);
    // One-sided derivatives at a C0 knot differ: OpenCASCADE takes the span starting there, and so
    // must the direct evaluator.
    EXPECT_NEAR((du - eu).Magnitude(), 0.0, tolerance * scale) << "Su at (" << pu << ", " << pv << ")";
    EXPECT_NEAR((dv - ev).Magnitude(), 0.0, tolerance * scale) << "Sv at (" << pu << ", " << pv << ")";
  }
}

TEST(BSplineDirect, MatchesOpenCascadeOnPolynomialAndRationalSurfaces) {
  std::mt19937 rng(11);
  for (int uDegree = 1; uDegree <= 5; ++uDegree) {
    for (int vDegree = 1; vDegree <= 5; vDegree += 2) {
      for (const bool rational : {false, true}) {
        SCOPED_TRACE(testing::Message() << "degrees " << uDegree << " x " << vDegree << (rational ? " rational" : ""));
        expectSame(randomSurface(rng, uDegree, vDegree, rational, {1}), rng);
        expectSame(randomSurface(rng, uDegree, vDegree, rational, {1, 2, 5, 1}), rng);  // C0 where m = degree
      }
    }
  }
}

// Degrees of 4 and more with few spans go through the per-span polynomial patches (powers of the
// local parameters about each span's midpoint): up to degree 11, the highest among the sample
// models' faces, on one span (a Bezier patch: the common case) and on a few uneven spans with
// interior multiplicities. Past the parameter range a degree-8 or -11 polynomial magnifies rounding:
// there OpenCASCADE and the basis-function evaluation differ by up to 4e-9 too, hence 1e-8. Many
// spans of high degree would make the patches several times the poles' memory: those surfaces keep
// the basis-function evaluation (and match OpenCASCADE there too). The uneven surfaces of 7 x 5
// spans fall on either side of that bound with the degrees: each must take the path the rule
// gives it (documentedPath), and both paths must occur.
// The path bspline_direct.h documents: polynomial patches for degree 4 or more one way where the
// patches of the non-empty span pairs (one per pair of distinct consecutive knots) take at most 4
// times the poles' memory, and at most 2^18 doubles; the basis functions otherwise.
Path documentedPath(const Handle(Geom_BSplineSurface)& s) {
  if (std::max(s->UDegree(), s->VDegree()) < 4) return Path::kBasis;
  const std::size_t spans = std::size_t(s->NbUKnots() - 1) * std::size_t(s->NbVKnots() - 1);
  const std::size_t patchDoubles = spans * 4 * std::size_t(s->UDegree() + 1) * std::size_t(s->VDegree() + 1);
  const std::size_t poleDoubles = 4 * std::size_t(s->NbUPoles()) * std::size_t(s->NbVPoles());
  return patchDoubles <= 4 * poleDoubles && patchDoubles <= (std::size_t(1) << 18) ? Path::kPatches : Path::kBasis;
}

TEST(BSplineDirect, HighDegreePatchesMatchOpenCascade) {
  std::mt19937 rng(23);
  int onPatches = 0, onBasis = 0;  // the uneven many-span surfaces: both paths must be covered
  for (const auto& [uDegree, vDegree] : {std::pair{2, 9}, {2, 11}, {7, 8}, {11, 2}, {4, 1}, {8, 8}}) {
    for (const bool rational : {false, true}) {
      SCOPED_TRACE(testing::Message() << "degrees " << uDegree << " x " << vDegree << (rational ? " rational" : ""));
      expectSame(randomSurface(rng, uDegree, vDegree, rational, {1}, 1, 1), rng, 1e-8, Path::kPatches);
      expectSame(randomSurface(rng, uDegree, vDegree, rational, {1, 2}, 2, 1), rng, 1e-8, Path::kPatches);
      const auto uneven = randomSurface(rng, uDegree, vDegree, rational, {1, 2, 5, 1}, 7, 5);
      const Path path = documentedPath(uneven);
      (path == Path::kPatches ? onPatches : onBasis) += 1;
      expectSame(uneven, rng, 1e-8, path);
    }
  }
  EXPECT_GT(onPatches, 0);
  EXPECT_GT(onBasis, 0);
}

// The patches' memory counts the spans that have a patch: a knot of multiplicity m leaves m - 1
// empty spans in the flat knot sequence, and they get none. Occ-misc's Ball.brep has this face: a
// rational 6 x 8 sweep with 3 interior knots of multiplicity 7, 4 spans of 22 in the flat sequence
// (counting all 22 put it past the memory bound, onto the slower basis functions). Many simple
// spans of high degree both ways still stay with the basis functions.
TEST(BSplineDirect, PatchesCountOnlyNonEmptySpans) {
  std::mt19937 rng(29);
  for (const bool rational : {false, true}) {
    SCOPED_TRACE(rational ? "rational" : "polynomial");
    expectSame(randomSurface(rng, 6, 8, rational, {7}, 1, 4), rng, 1e-8, Path::kPatches);
    expectSame(randomSurface(rng, 8, 8, rational, {1}, 7, 5), rng, 1e-8, Path::kBasis);
  }
}

TEST(BSplineDirect, SpansFollowTheKnots) {
  std::mt19937 rng(3);
  const auto s = randomSurface(rng, 3, 2, false, {1});
  const auto direct = BSplineDirect::create(s);
  ASSERT_NE(direct, nullptr);
  // Flat index of knot i's first copy: degree + 1 copies of the first knot, one of each interior.
  for (int i = 1; i < s->NbUKnots(); ++i) {
    const double mid = 0.5 * (s->UKnot(i) + s->UKnot(i + 1));
    EXPECT_EQ(direct->uSpan(mid), 3 + i - 1);
    EXPECT_EQ(direct->uSpan(s->UKnot(i)), 3 + i - 1);  // a knot starts its span
  }
  EXPECT_EQ(direct->uSpan(s->UKnot(1) - 10), 3);                    // before: the first span
  EXPECT_EQ(direct->uSpan(s->UKnot(s->NbUKnots()) + 10), 3 + s->NbUKnots() - 2);  // past: the last
  EXPECT_EQ(direct->uSpan(s->UKnot(s->NbUKnots())), 3 + s->NbUKnots() - 2);  // the end knot: the last
}

TEST(BSplineDirect, FollowsThePlacement) {
  // A face's location moves its surface: the evaluator takes it on the poles (a moved copy of them,
  // with their weights or without).
  std::mt19937 rng(5);
  for (const bool rational : {true, false}) {
    SCOPED_TRACE(rational ? "rational" : "polynomial");
    const auto s = randomSurface(rng, 3, 2, rational, {1, 2});
    gp_Trsf placement;
    placement.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(1, 1, 0)), 0.7);
    placement.SetTranslationPart(gp_Vec(-4, 5, 0.5));
    const auto direct = BSplineDirect::create(s, placement);
    ASSERT_NE(direct, nullptr);
    EXPECT_FALSE(direct->readsPolesInPlace());
    const Handle(Geom_BSplineSurface) moved =
        Handle(Geom_BSplineSurface)::DownCast(s->Transformed(placement));
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    for (int i = 0; i <= 10; ++i) {
      for (int j = 0; j <= 10; ++j) {
        const double u = u0 + (u1 - u0) * i / 10, v = v0 + (v1 - v0) * j / 10;
        gp_Pnt p, q;
        gp_Vec du, dv, eu, ev;
        moved->D1(u, v, p, du, dv);
        direct->d1(u, v, q, eu, ev);
        EXPECT_NEAR(p.Distance(q), 0.0, 1e-9);
        EXPECT_NEAR((du - eu).Magnitude(), 0.0, 1e-9 * (1 + du.Magnitude()));
        EXPECT_NEAR((dv - ev).Magnitude(), 0.0, 1e-9 * (1 + dv.Magnitude()));
      }
    }
  }
}

// A polynomial surface in place (no placement) is read from its own pole array, not copied (on
// occ/terrain.brep the copy was 3.2 MB written afresh on every load); the evaluator keeps the
// surface alive, and gives the same points as the surface after the caller has let it go.
TEST(BSplineDirect, APolynomialSurfaceInPlaceIsReadFromItsOwnPoles) {
  std::mt19937 rng(13);
  Handle(Geom_BSplineSurface) s = randomSurface(rng, 3, 3, false, {1, 2});
  const auto direct = BSplineDirect::create(s);
  ASSERT_NE(direct, nullptr);
  EXPECT_TRUE(direct->readsPolesInPlace());
  EXPECT_FALSE(BSplineDirect::create(randomSurface(rng, 3, 3, true, {1}))->readsPolesInPlace())
      << "weighted poles are copied with their weights";
  double u0, u1, v0, v1;
  s->Bounds(u0, u1, v0, v1);
  std::vector<gp_Pnt> expected;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) expected.push_back(s->Value(u0 + (u1 - u0) * i / 8, v0 + (v1 - v0) * j / 8));
  s.Nullify();
  std::size_t k = 0;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j)
      EXPECT_NEAR(expected[k++].Distance(direct->value(u0 + (u1 - u0) * i / 8, v0 + (v1 - v0) * j / 8)), 0.0,
                  1e-12);
}

TEST(BSplineDirect, DeclinesPeriodicSurfaces) {
  std::mt19937 rng(7);
  Handle(Geom_BSplineSurface) s = randomSurface(rng, 3, 3, false, {1});
  s->SetUPeriodic();
  EXPECT_EQ(BSplineDirect::create(s), nullptr);
}

}  // namespace
}  // namespace cetview::brep
