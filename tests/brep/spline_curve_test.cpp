// The direct B-spline curve evaluation (spline_curve.h: edges' 3D curves and, through Pcurve,
// faces' pcurves) against OpenCASCADE's own on random curves: degrees 1 to 5 and 8, uneven knots
// with interior multiplicities (down to C0), rational and polynomial, at parameters inside, on
// knots and a little outside the range (where both extend the end span's polynomial); a trimmed
// pcurve, a periodic one (left to OpenCASCADE), and an edge moved by a location.
#include <gtest/gtest.h>

#include <random>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include "pcurve.h"
#include "spline_curve.h"

namespace cetview::brep {
namespace {

struct Knots {
  TColStd_Array1OfReal values{1, 2};
  TColStd_Array1OfInteger mults{1, 2};
  int poles = 0;
};

// Knots from -1.5 with random spacing; interior multiplicities cycle through `mults` (capped at the
// degree), end multiplicities degree + 1.
Knots makeKnots(std::mt19937& rng, int degree, int spans, const std::vector<int>& mults) {
  std::uniform_real_distribution<double> step(0.2, 3.0);
  Knots k;
  k.values.Resize(1, spans + 1, false);
  k.mults.Resize(1, spans + 1, false);
  double t = -1.5;
  for (int i = 1; i <= spans + 1; ++i) {
    k.values(i) = t;
    t += step(rng);
    k.mults(i) = i == 1 || i == spans + 1 ? degree + 1 : std::min(degree, mults[std::size_t(i) % mults.size()]);
    k.poles += k.mults(i);
  }
  k.poles -= degree + 1;
  return k;
}

Handle(Geom2d_BSplineCurve) randomCurve2d(std::mt19937& rng, int degree, bool rational, const std::vector<int>& mults) {
  const Knots k = makeKnots(rng, degree, 6, mults);
  std::uniform_real_distribution<double> jitter(-0.7, 0.7), weight(0.3, 3.0);
  TColgp_Array1OfPnt2d poles(1, k.poles);
  TColStd_Array1OfReal weights(1, k.poles);
  for (int i = 1; i <= k.poles; ++i) poles(i) = gp_Pnt2d(i + jitter(rng), 3 * jitter(rng)), weights(i) = weight(rng);
  if (rational) return new Geom2d_BSplineCurve(poles, weights, k.values, k.mults, degree);
  return new Geom2d_BSplineCurve(poles, k.values, k.mults, degree);
}

Handle(Geom_BSplineCurve) randomCurve3d(std::mt19937& rng, int degree, bool rational, const std::vector<int>& mults) {
  const Knots k = makeKnots(rng, degree, 6, mults);
  std::uniform_real_distribution<double> jitter(-0.7, 0.7), weight(0.3, 3.0);
  TColgp_Array1OfPnt poles(1, k.poles);
  TColStd_Array1OfReal weights(1, k.poles);
  for (int i = 1; i <= k.poles; ++i)
    poles(i) = gp_Pnt(i + jitter(rng), 3 * jitter(rng), 2 * jitter(rng)), weights(i) = weight(rng);
  if (rational) return new Geom_BSplineCurve(poles, weights, k.values, k.mults, degree);
  return new Geom_BSplineCurve(poles, k.values, k.mults, degree);
}

// Random parameters over the range and `past` of it past either end, and every knot exactly (where
// spans meet: at a C0 knot both must take the derivative of the span starting there). Far past the
// range a degree-8 polynomial magnifies rounding (OpenCASCADE and the direct form differ by up to
// 7e-6 at 5% past a short end span): such curves are compared inside their range, where edges use them.
std::vector<double> parameters(std::mt19937& rng, double first, double last, const TColStd_Array1OfReal& knots,
                               double past = 0.05) {
  std::uniform_real_distribution<double> t(first - past * (last - first), last + past * (last - first));
  std::vector<double> out;
  for (int i = 0; i < 200; ++i) out.push_back(t(rng));
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) out.push_back(knots(i));
  return out;
}

void expectSamePcurve(const Handle(Geom2d_Curve)& curve, const Handle(Geom2d_BSplineCurve)& spline, std::mt19937& rng) {
  const Pcurve pcurve(curve);
  ASSERT_TRUE(pcurve.direct());
  const double past = spline->Degree() > 5 ? 0.0 : 0.05;
  for (const double t : parameters(rng, spline->FirstParameter(), spline->LastParameter(), spline->Knots(), past)) {
    gp_Pnt2d p, q;
    gp_Vec2d d, e;
    curve->D1(t, p, d);
    pcurve.d1(t, q, e);
    EXPECT_NEAR(p.Distance(q), 0.0, 1e-10) << "at " << t;
    EXPECT_NEAR(p.Distance(pcurve.value(t)), 0.0, 1e-10) << "at " << t;
    EXPECT_NEAR((d - e).Magnitude(), 0.0, 1e-10 * (1 + d.Magnitude())) << "derivative at " << t;
  }
}

TEST(SplineCurve, PcurvesMatchOpenCascade) {
  std::mt19937 rng(5);
  for (const int degree : {1, 2, 3, 4, 5, 8}) {
    for (const bool rational : {false, true}) {
      SCOPED_TRACE(testing::Message() << "degree " << degree << (rational ? " rational" : ""));
      for (const auto& mults : {std::vector<int>{1}, std::vector<int>{1, 2, 9, 1}}) {  // 9: C0 knots
        const Handle(Geom2d_BSplineCurve) c = randomCurve2d(rng, degree, rational, mults);
        expectSamePcurve(c, c, rng);
      }
    }
  }
}

// A polynomial curve ends on its end poles to the last bit, as OpenCASCADE's curves do: an edge's
// end is its vertex. (A rational one's points are divided by their weight, in either evaluation.)
TEST(SplineCurve, EndsOnItsEndPolesExactly) {
  std::mt19937 rng(9);
  for (int i = 0; i < 200; ++i) {
    const int degree = 1 + i % 5;
    const Handle(Geom2d_BSplineCurve) c = randomCurve2d(rng, degree, false, {1, 2});
    const Pcurve pcurve(c);
    ASSERT_TRUE(pcurve.direct());
    for (const bool last : {false, true}) {
      const gp_Pnt2d pole = c->Pole(last ? c->NbPoles() : 1);
      const gp_Pnt2d end = pcurve.value(last ? c->LastParameter() : c->FirstParameter());
      EXPECT_EQ(end.X(), pole.X()) << "degree " << degree << (last ? " last" : " first");
      EXPECT_EQ(end.Y(), pole.Y()) << "degree " << degree << (last ? " last" : " first");
    }
  }
}

TEST(SplineCurve, TrimmedPcurveIsItsBasisCurve) {
  std::mt19937 rng(6);
  const Handle(Geom2d_BSplineCurve) c = randomCurve2d(rng, 3, true, {1, 2});
  const double a = c->FirstParameter(), b = c->LastParameter();
  const Handle(Geom2d_TrimmedCurve) trimmed = new Geom2d_TrimmedCurve(c, a + 0.3 * (b - a), a + 0.8 * (b - a));
  expectSamePcurve(trimmed, c, rng);
}

TEST(SplineCurve, PeriodicPcurveGoesThroughOpenCascade) {
  std::mt19937 rng(7);
  const Handle(Geom2d_BSplineCurve) c = randomCurve2d(rng, 3, false, {1});
  c->SetPeriodic();
  const Pcurve pcurve(c);
  EXPECT_FALSE(pcurve.direct());
  const double a = c->FirstParameter(), b = c->LastParameter();
  for (const double t : {a, 0.5 * (a + b), b, b + 0.3 * (b - a)})  // past the period: it wraps
    EXPECT_NEAR(c->Value(t).Distance(pcurve.value(t)), 0.0, 1e-12);
}

// An edge's 3D curve, the edge moved by a location (an instance's placement inside its part): the
// direct form's points and derivatives are the adaptor's, moved alike.
TEST(SplineCurve, EdgeCurvesMatchTheAdaptorWithTheirLocation) {
  std::mt19937 rng(8);
  gp_Trsf move;
  move.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(1, 1, 0.5)), 0.7);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(10, -4, 2));
  move.PreMultiply(shift);
  for (const int degree : {1, 2, 3, 5}) {
    for (const bool rational : {false, true}) {
      SCOPED_TRACE(testing::Message() << "degree " << degree << (rational ? " rational" : ""));
      const Handle(Geom_BSplineCurve) c = randomCurve3d(rng, degree, rational, {1, 2, 9});
      const double a = c->FirstParameter(), b = c->LastParameter();
      const TopoDS_Edge plain = BRepBuilderAPI_MakeEdge(c, a + 0.1 * (b - a), b);  // trimmed at the start
      const TopoDS_Edge moved = TopoDS::Edge(plain.Moved(TopLoc_Location(move)));
      const BRepAdaptor_Curve adaptor(moved);
      const auto spline = splineOf(adaptor);
      ASSERT_NE(spline, nullptr);
      for (const double t : parameters(rng, a, b, c->Knots())) {
        gp_Pnt p;
        gp_Vec d;
        adaptor.D1(t, p, d);
        double q[3], e[3];
        spline->evaluate(t, q, e);
        EXPECT_NEAR(p.Distance(gp_Pnt(q[0], q[1], q[2])), 0.0, 1e-9) << "at " << t;
        EXPECT_NEAR((d - gp_Vec(e[0], e[1], e[2])).Magnitude(), 0.0, 1e-9 * (1 + d.Magnitude()))
            << "derivative at " << t;
      }
    }
  }
}

}  // namespace
}  // namespace cetview::brep
