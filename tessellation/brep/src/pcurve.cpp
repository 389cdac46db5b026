#include "pcurve.h"

namespace cetview::brep {

Pcurve::Pcurve(const Handle(Geom2d_Curve)& curve) : curve_(curve), spline_(splineOf(curve)) {}

gp_Pnt2d Pcurve::value(double t) const {
  if (!spline_) return curve_->Value(t);
  double p[2];
  spline_->evaluate(t, p, nullptr);
  return gp_Pnt2d(p[0], p[1]);
}

void Pcurve::d1(double t, gp_Pnt2d& p, gp_Vec2d& v) const {
  if (!spline_) return curve_->D1(t, p, v);
  double a[2], d[2];
  spline_->evaluate(t, a, d);
  p.SetCoord(a[0], a[1]);
  v.SetCoord(d[0], d[1]);
}

}  // namespace cetview::brep
