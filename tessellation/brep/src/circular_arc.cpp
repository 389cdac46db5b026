#include "circular_arc.h"

#include <cmath>

#include <Standard_Failure.hxx>
#include <gp_Vec.hxx>

namespace cetview::brep {
namespace {

constexpr double kLeastTurn = 1e-3;  // radians: below it a curve is as good as straight

}  // namespace

double CircularArc::angleOf(const gp_Pnt& p) const {
  const gp_Vec r(center, p);
  const gp_Vec x(start), y = gp_Vec(axis).Crossed(x);
  const double a = std::atan2(r.Dot(y), r.Dot(x));
  return a < 0 ? a + 2 * M_PI : a;
}

double CircularArc::parameterAt(const Adaptor3d_Curve& curve, double first, double last, double phi) const {
  double lo = first, hi = last;
  double t = first + (last - first) * phi / angle;
  for (int i = 0; i < 40; ++i) {
    gp_Pnt p;
    gp_Vec d;
    curve.D1(t, p, d);
    double a = angleOf(p);
    a += 2 * M_PI * std::round((phi - a) / (2 * M_PI));  // the turn nearest phi (0 reads 2 pi at the start)
    const double g = a - phi;
    if (std::abs(g) <= 1e-15 * angle) return t;
    (g > 0 ? hi : lo) = t;
    const gp_Vec r(center, p);
    const double rate = r.Crossed(d).Dot(gp_Vec(axis)) / r.SquareMagnitude();  // the turn's speed
    double next = rate > 0 ? t - g / rate : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == t) return t;
    t = next;
  }
  return t;
}

std::optional<CircularArc> circularArcOf(const Adaptor3d_Curve& curve, double first, double last, bool closed) {
  // Only a rational curve runs exactly on a circle; a polynomial one stays near it at best, and a
  // straight B-spline reads as a circle of 1e13 whose turn is rounding noise (hammer.brep's edges).
  if (!(last > first) || !curve.IsRational()) return std::nullopt;
  try {
    // The circle through three points spread along the curve (a closed one's ends coincide).
    const gp_Pnt a = curve.Value(first), b = curve.Value(first + (last - first) / 3),
                 c = curve.Value(first + 2 * (last - first) / 3);
    const gp_Vec ab(a, b), ac(a, c);
    const gp_Vec n = ab.Crossed(ac);
    const double n2 = n.SquareMagnitude();
    if (!(n2 > 0)) return std::nullopt;
    // Circumcentre: a + (|ab|^2 (ac x n) + |ac|^2 (n x ab)) / (2 |n|^2).
    const gp_Vec toCenter = (ac.Crossed(n) * ab.SquareMagnitude() + n.Crossed(ab) * ac.SquareMagnitude()) / (2 * n2);
    CircularArc arc;
    arc.center = a.Translated(toCenter);
    arc.radius = toCenter.Magnitude();
    if (!(arc.radius > 0)) return std::nullopt;
    arc.axis = gp_Dir(n);
    arc.start = gp_Dir(gp_Vec(arc.center, a));
    constexpr int kSamples = 32;
    const double tolerance = 1e-9 * arc.radius;
    double previous = 0;
    for (int i = 1; i <= kSamples; ++i) {
      const gp_Pnt p = curve.Value(i == kSamples ? last : first + (last - first) * i / kSamples);
      const gp_Vec r(arc.center, p);
      if (std::abs(r.Magnitude() - arc.radius) > tolerance || std::abs(r.Dot(gp_Vec(arc.axis))) > tolerance)
        return std::nullopt;
      double turned = arc.angleOf(p);
      if (i == kSamples && closed) turned = 2 * M_PI;
      if (!(turned > previous)) return std::nullopt;  // not turning steadily one way
      previous = turned;
    }
    arc.angle = previous;
    if (!(arc.angle > kLeastTurn)) return std::nullopt;
    return arc;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace cetview::brep
