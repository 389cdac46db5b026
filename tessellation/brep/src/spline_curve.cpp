#include "spline_curve.h"

#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <utility>

namespace cetview::brep {

std::shared_ptr<const SplineCurve<2>> splineOf(const Handle(Geom2d_Curve)& curve) {
  Handle(Geom2d_Curve) basis = curve;
  while (!basis.IsNull() && basis->IsKind(STANDARD_TYPE(Geom2d_TrimmedCurve)))
    basis = Handle(Geom2d_TrimmedCurve)::DownCast(basis)->BasisCurve();
  const Handle(Geom2d_BSplineCurve) b = Handle(Geom2d_BSplineCurve)::DownCast(basis);
  if (b.IsNull() || b->IsPeriodic()) return nullptr;
  const TColStd_Array1OfReal& flat = b->KnotSequence();
  std::vector<double> poles;
  poles.reserve(3 * static_cast<std::size_t>(b->NbPoles()));
  for (int i = 1; i <= b->NbPoles(); ++i) {
    const gp_Pnt2d& p = b->Pole(i);
    poles.insert(poles.end(), {p.X(), p.Y(), b->IsRational() ? b->Weight(i) : 1.0});
  }
  return SplineCurve<2>::create(b->Degree(), std::vector<double>(flat.begin(), flat.end()), std::move(poles));
}

std::shared_ptr<const SplineCurve<3>> splineOf(const BRepAdaptor_Curve& curve) {
  // The adaptor holds a trimmed curve's basis curve, at the same parameters.
  if (!curve.Is3DCurve() || curve.GetType() != GeomAbs_BSplineCurve) return nullptr;
  const Handle(Geom_BSplineCurve) b = curve.Curve().BSpline();
  if (b.IsNull() || b->IsPeriodic()) return nullptr;
  const gp_Trsf& placement = curve.Trsf();
  const TColStd_Array1OfReal& flat = b->KnotSequence();
  std::vector<double> poles;
  poles.reserve(4 * static_cast<std::size_t>(b->NbPoles()));
  for (int i = 1; i <= b->NbPoles(); ++i) {
    const gp_Pnt p = b->Pole(i).Transformed(placement);  // an affine map of the poles maps the curve
    poles.insert(poles.end(), {p.X(), p.Y(), p.Z(), b->IsRational() ? b->Weight(i) : 1.0});
  }
  return SplineCurve<3>::create(b->Degree(), std::vector<double>(flat.begin(), flat.end()), std::move(poles));
}

}  // namespace cetview::brep
