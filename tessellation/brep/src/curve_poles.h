// The control points of a curve whose hull bounds it: a line's ends, a B-spline's or a Bezier
// curve's poles. For BRepAdaptor_Curve (3D, gp_Pnt) and Geom2dAdaptor_Curve (UV, gp_Pnt2d) alike;
// tests of straightness and of iso-lines look at them instead of sampling the curve. Callers
// include the curve classes their adaptor hands out (Geom_BSplineCurve.hxx and Geom_BezierCurve.hxx,
// or their Geom2d_ counterparts): the template needs them complete.
#pragma once

#include <vector>

#include <GeomAbs_CurveType.hxx>

namespace cetview::brep {

// False for other curve types (circles, offsets, ...): no hull to look at.
template <class Adaptor, class Point>
bool hullPoints(const Adaptor& curve, double first, double last, std::vector<Point>& out) {
  out.clear();
  switch (curve.GetType()) {
    case GeomAbs_Line:
      out = {curve.Value(first), curve.Value(last)};
      return true;
    case GeomAbs_BSplineCurve: {
      const auto bspline = curve.BSpline();
      for (int i = 1; i <= bspline->NbPoles(); ++i) out.push_back(bspline->Pole(i));
      return true;
    }
    case GeomAbs_BezierCurve: {
      const auto bezier = curve.Bezier();
      for (int i = 1; i <= bezier->NbPoles(); ++i) out.push_back(bezier->Pole(i));
      return true;
    }
    default:
      return false;
  }
}

}  // namespace cetview::brep
