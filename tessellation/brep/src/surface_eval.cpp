#include "surface_eval.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <Bnd_Box.hxx>
#include <Bnd_Box2d.hxx>
#include <GProp_PEquation.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <GeomLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "curve_poles.h"

namespace cetview::brep {

namespace {

// A free-form face evenly one-way (see the constructor) bends kTubeRatio times faster one way than
// the other at every point of the 5x5 grid, twists at most kOneWayTwist of its larger curvature
// there (|Suv . N| / (|Su| |Sv|)), and its speeds along u and along v each stay within
// kOneWaySpeeds over the grid. With the tolerances known it takes the steps they allow each way, up
// to 10:1; without, the square-root rule, as far as an analytic surface (10:1) only where it bends
// kOneWayRatio times faster one way.
constexpr double kTubeRatio = 10;
constexpr double kOneWayRatio = 1000;
constexpr double kOneWayTwist = 0.5;
constexpr double kOneWaySpeeds = 3;
// A free-form face straight one way (a ruled B-spline) is developable where its normal turns along
// a whole ruling by less than this (radians; see the constructor).
constexpr double kDevelopableTwist = 1e-4;

// True when every edge of the face runs along an iso-line of the surface in UV (its pcurve a line
// parallel to the u or the v axis, or a B-spline or Bezier curve whose poles all lie on one: the
// curve stays within their hull): the face is a rectangle of its parameter plane, and no boundary
// curves across a stretched direction.
bool boundedByIsoLines(const TopoDS_Face& face, double uRange, double vRange) {
  const double uTol = 1e-9 * uRange, vTol = 1e-9 * vRange;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    double first = 0, last = 0;
    Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull()) return false;
    Geom2dAdaptor_Curve curve(pcurve, first, last);
    std::vector<gp_Pnt2d> poles;
    if (!hullPoints(curve, first, last, poles)) return false;
    bool uIso = true, vIso = true;
    for (const gp_Pnt2d& p : poles) {
      uIso = uIso && std::abs(p.X() - poles.front().X()) <= uTol;
      vIso = vIso && std::abs(p.Y() - poles.front().Y()) <= vTol;
    }
    if (!uIso && !vIso) return false;
  }
  return true;
}

// The box of the face's pcurves in (u, v), however far they leave the surface's range (BRepTools::
// UVBounds cuts them to it): each curve's hull, tightened (BndLib_Add2dCurve::AddOptimal, slow:
// bug33398's 54 faces reaching 3e-4 of their range past it took it from 35 to 68 ms on one thread)
// only where it leaves `within`. False when a pcurve is missing.
bool pcurveReach(const TopoDS_Face& face, const Bnd_Box2d& within, Bnd_Box2d& reach) {
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    double first = 0, last = 0;
    Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (pcurve.IsNull()) return false;
    Geom2dAdaptor_Curve curve(pcurve, first, last);
    std::vector<gp_Pnt2d> hull;
    if (hullPoints(curve, first, last, hull)) {
      bool inside = true;
      for (const gp_Pnt2d& p : hull) inside = inside && !within.IsOut(p);
      if (inside) {
        for (const gp_Pnt2d& p : hull) reach.Add(p);
        continue;
      }
    }
    BndLib_Add2dCurve::AddOptimal(pcurve, first, last, 0.0, reach);
  }
  return true;
}

}  // namespace

SurfaceEval::SurfaceEval(const TopoDS_Face& face, double chordal, double angleRad)
    : surface_(face, Standard_False), elementary_(surface_), face_(face) {
  if (surface_.GetType() == GeomAbs_BSplineSurface) {
    TopLoc_Location location;  // applied to the poles (BRep_Tool::Surface(face) would copy the surface)
    Handle(Geom_Surface) basis = BRep_Tool::Surface(face, location);
    while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis)) basis = trimmed->BasisSurface();
    direct_ = BSplineDirect::create(Handle(Geom_BSplineSurface)::DownCast(basis), location.Transformation());
  }
  concurrentSafe_ = direct_ || elementary_.valid();
  uPeriodic_ = surface_.IsUPeriodic();
  vPeriodic_ = surface_.IsVPeriodic();
  su0_ = surface_.FirstUParameter(), su1_ = surface_.LastUParameter();
  sv0_ = surface_.FirstVParameter(), sv1_ = surface_.LastVParameter();
  BRepTools::UVBounds(face, uMin, uMax, vMin, vMax);
  if (!(uMax >= uMin) || !(vMax >= vMin) || !std::isfinite(uMin) || !std::isfinite(vMax)) {
    uMin = std::max(su0_, -1e6), uMax = std::min(su1_, 1e6), vMin = std::max(sv0_, -1e6), vMax = std::min(sv1_, 1e6);
  }
  reachU0_ = uMin, reachU1_ = uMax, reachV0_ = vMin, reachV1_ = vMax;
  if (direct_) {
    try {
      // Only a reach past kReachMargin of an end span is told apart (buildAxis).
      const Handle(Geom_BSplineSurface) bs = surface_.Surface().BSpline();
      auto margin = [](const Handle(Geom_BSplineSurface) & b, bool uDir, bool first) {
        const int n = uDir ? b->NbUKnots() : b->NbVKnots();
        const double k0 = uDir ? b->UKnot(first ? 1 : n) : b->VKnot(first ? 1 : n);
        const double k1 = uDir ? b->UKnot(first ? 2 : n - 1) : b->VKnot(first ? 2 : n - 1);
        return kReachMargin * std::abs(k1 - k0);
      };
      Bnd_Box2d within, reach;
      within.Update(uPeriodic_ ? -1e300 : su0_ - margin(bs, true, true),
                    vPeriodic_ ? -1e300 : sv0_ - margin(bs, false, true),
                    uPeriodic_ ? 1e300 : su1_ + margin(bs, true, false),
                    vPeriodic_ ? 1e300 : sv1_ + margin(bs, false, false));
      if (pcurveReach(face, within, reach) && !reach.IsVoid()) {
        double a = 0, b = 0, c = 0, d = 0;
        reach.Get(a, b, c, d);
        reachU0_ = std::min(a, uMin), reachV0_ = std::min(b, vMin), reachU1_ = std::max(c, uMax),
        reachV1_ = std::max(d, vMax);
      }
    } catch (const Standard_Failure&) {
    }
  }
  findDegenerateRows();
  u0 = uMin, v0 = vMin;
  if (mayBeRing(surface_.GetType())) {
    ringAngles_ = brep::ringAngles(
        [this](double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) {
          if (direct_) direct_->d1(u, v, p, du, dv);
          else surface_.D1(u, v, p, du, dv);
        },
        uMin, uMax, vMin, vMax);
  }
  // Mean |Su|, |Sv| and normal curvatures along u and v on a 5x5 grid over the parameter box.
  double lu = 0, lv = 0, ku = 0, kv = 0;  // means
  double luMin = HUGE_VAL, luMax = 0, lvMin = HUGE_VAL, lvMax = 0;  // the speeds' range
  double kuMax = 0, kvMax = 0;
  double twistMax = 0;  // |Suv . N| / (|Su| |Sv|): how the normal turns along one direction as it moves the other
  int n = 0;
  int uTurns = 0, vTurns = 0;  // grid points where one direction's curvature is 4x the other's
  double uOverV = HUGE_VAL, vOverU = HUGE_VAL;  // the least ratio of the two curvatures over the grid, each way
  double twistOverBend = 0;  // the largest ratio of |Suv . N| / (|Su| |Sv|) to the larger curvature over the grid
  Bnd_Box extent;
  double boxArea = 0;  // the largest |Su x Sv| times the parameter box's area
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const double u = uMin + (uMax - uMin) * (i + 0.5) / 5, v = vMin + (vMax - vMin) * (j + 0.5) / 5;
      gp_Pnt p;
      gp_Vec du, dv, duu, dvv, duv;
      surface_.D2(u, v, p, du, dv, duu, dvv, duv);
      const double mu = du.Magnitude(), mv = dv.Magnitude();
      lu += mu, lv += mv;
      luMin = std::min(luMin, mu), luMax = std::max(luMax, mu), lvMin = std::min(lvMin, mv), lvMax = std::max(lvMax, mv);
      const gp_Vec c = du.Crossed(dv);
      extent.Add(p);
      boxArea = std::max(boxArea, c.Magnitude() * (uMax - uMin) * (vMax - vMin));
      if (c.Magnitude() > 1e-12 * mu * mv && mu > 0 && mv > 0) {
        const gp_Vec nrm = c / c.Magnitude();
        const double pu = std::abs(duu.Dot(nrm)) / (mu * mu), pv = std::abs(dvv.Dot(nrm)) / (mv * mv);
        ku += pu, kv += pv;
        kuMax = std::max(kuMax, pu), kvMax = std::max(kvMax, pv);
        const double twist = std::abs(duv.Dot(nrm)) / (mu * mv);
        twistMax = std::max(twistMax, twist);
        if (pu > 4 * pv) ++uTurns;
        if (pv > 4 * pu) ++vTurns;
        uOverV = std::min(uOverV, pv > 0 ? pu / pv : HUGE_VAL);
        vOverU = std::min(vOverU, pu > 0 ? pv / pu : HUGE_VAL);
        twistOverBend = std::max(twistOverBend, twist > 0 ? twist / std::max({pu, pv, 1e-300}) : 0.0);
      }
      ++n;
    }
  }
  lu /= n, lv /= n, ku /= n, kv /= n;
  meanLu_ = lu, meanLv_ = lv;
  // Creases: the ends of the surface's C1 intervals inside its parameter range; a periodic
  // direction's seam as well where the surface has any crease in that direction (its seam knot is
  // then as likely C0 as the others; a seam wrongly taken for a crease only skips angle tests
  // there, which the chordal test still covers).
  auto creases = [&](bool uDir, std::vector<double>& out) {
    const int count = uDir ? surface_.NbUIntervals(GeomAbs_C1) : surface_.NbVIntervals(GeomAbs_C1);
    if (count < 2 || count > 100000) return;
    TColStd_Array1OfReal t(1, count + 1);
    if (uDir) {
      surface_.UIntervals(t, GeomAbs_C1);
    } else {
      surface_.VIntervals(t, GeomAbs_C1);
    }
    const bool periodic = uDir ? uPeriodic_ : vPeriodic_;
    for (int i = periodic ? 1 : 2; i <= count; ++i) out.push_back(t(i));
    std::sort(out.begin(), out.end());
  };
  try {
    creases(true, uCreases_);
    creases(false, vCreases_);
    keepTurningBreaks(true, uCreases_);
    keepTurningBreaks(false, vCreases_);
  } catch (const Standard_Failure&) {
    uCreases_.clear(), vCreases_.clear(), uBends_.clear(), vBends_.clear();
  }
  const double extent2 = extent.IsVoid() ? 0 : extent.SquareExtent();
  gridArea_ = extent2 > 0 ? boxArea / extent2 : 0;
  const double floor = 1e-9 * std::max({lu, lv, 1e-300});
  su = std::max(lu, floor);
  sv = std::max(lv, floor);
  // Stretch the direction that bends less, so that the Delaunay criterion judges shapes by how far
  // an edge may run each way rather than by length. On a curve of normal curvature k an edge of
  // length h sags by k h^2 / 8 and turns by k h: the step each way goes as 1 / sqrt(k) by the sag
  // alone, and with the tolerances known, as the tolerances allow. A cylinder's or cone's triangles
  // then run the whole length of its straight direction, a thin torus's far along its tube.
  // Only where the curvature is directional by construction (cylinders, cones, linear extrusions:
  // straight in one direction; tori, whose fillets turn fast round the tube and slowly along it),
  // or on a free-form face where it is so at every grid point (a fillet or a tube written as a
  // B-spline): elsewhere averaged curvatures say little about any one place, and a wrong stretch
  // makes slivers that fold on a wavy surface.
  const GeomAbs_SurfaceType type = surface_.GetType();
  const bool directional = type == GeomAbs_Cylinder || type == GeomAbs_Cone || type == GeomAbs_SurfaceOfExtrusion ||
                           type == GeomAbs_Torus || (ringAngles_ && ringAngles_->major > 0);
  const bool freeformDirectional = !directional && (uTurns == n || vTurns == n);
  const double size = std::max(su * (uMax - uMin), sv * (vMax - vMin));
  // A smooth free-form face straight one way and untwisted at every grid point (a developable
  // B-spline: a wing's skin, a swept profile, a cone written as a B-spline) bends like an
  // extrusion. (Not across creases: long triangles along a fold leave its ridge between their
  // samples; nor where the rulings twist: the normal turns along them.) Untwisted: the normal
  // turns along a whole ruling by under kDevelopableTwist radians (twistMax * size), and a
  // triangle w wide running the face's length sags off it by about twistMax * w * size / 4, under
  // a quarter of 0.01% of the size. occ/wing.brep's skins, lofted between ribs, turn by 1.2e-5:
  // held to 1e-6 (rounding) they were meshed as curved free-form faces, 440 triangles at 1% where
  // BRepMesh takes 298 (now 70).
  const bool straightOneWay = freeformDirectional && std::min(kuMax, kvMax) * size < 1e-9 &&
                              twistMax * size < kDevelopableTwist && uCreases_.empty() && vCreases_.empty();
  if ((directional || freeformDirectional) && std::max(ku, kv) * size > 1e-3) {
    double hu = 0, hv = 0, most = 0;
    const bool tolerances = chordal > 0 && angleRad > 0;
    // The steps the tolerances allow each way, where the surface bends most that way.
    const auto toleranceSteps = [&] {
      const auto step = [&](double k) { return k > 0 ? std::min(angleRad / k, std::sqrt(8 * chordal / k)) : HUGE_VAL; };
      hu = step(kuMax), hv = step(kvMax);
      // A triangle long one way and short the other tilts off the surface by about its sag along
      // the long way over its width; a quarter of the width at most (about 15 degrees) leaves room
      // for the Delaunay triangles that are longer or thinner than the steps. Further folded, the
      // refinement takes them for slivers, and a sliver split on its long edge makes more.
      if (kuMax > 0) hu = std::min(hu, std::sqrt(2 * hv / kuMax));
      if (kvMax > 0) hv = std::min(hv, std::sqrt(2 * hu / kvMax));
    };
    // A free-form face evenly one-way: at every grid point it bends kTubeRatio times faster one
    // way than the other, twists at most half as fast as it bends (the twist sags the diagonals of
    // triangles long one way), and its speeds are even (one scale a direction then gives triangles
    // the shape in 3D that it gives them in the scaled plane). Fuzzed ruled faces twisting faster
    // or parametrised unevenly took more triangles at 10:1 and more of them flipped; r0901's face
    // 65 (a fillet of radius 0.5 along a curved spine, bending 140 times faster round than along,
    // but slowing into a degenerate corner) flipped triangles at that corner.
    const bool evenlyOneWay = freeformDirectional && std::max(uOverV, vOverU) >= kTubeRatio &&
                              twistOverBend <= kOneWayTwist && luMax <= kOneWaySpeeds * luMin &&
                              lvMax <= kOneWaySpeeds * lvMin;
    if ((directional || straightOneWay) && tolerances) {
      toleranceSteps();
      // 1000:1 at most on an analytic surface, which bends the same way all along it, and on a
      // developable free-form face bounded by iso-lines (a wing's skin between its ribs); 30:1 on
      // other developable free-form faces, whose boundary pcurves may curve across the long
      // direction (at 100:1 the Delaunay triangulation joins three points of such a curve: a
      // flipped triangle).
      most = directional || boundedByIsoLines(face, uMax - uMin, vMax - vMin) ? 1e-3 : 1.0 / 30;
    } else if (evenlyOneWay && tolerances) {
      // An evenly one-way free-form face (a tube along a spine, a fillet, a wing's skin) takes the
      // steps the tolerances allow as the analytic surfaces do, up to 10:1: its curvature still
      // varies along the stretch. By the square-root rule Ball.brep's tubes (radius 0.2 along
      // spines bending 20 to 30 times slower) ran 3:1 where the angle allows steps 20 to 30 times
      // longer along them than round them: 5592 triangles at 1% against BRepMesh's 4215 (now 3212).
      toleranceSteps();
      most = 0.1;
    } else {
      const double kmin = 1e-300;
      hu = 1 / std::sqrt(std::max(ku, kmin)), hv = 1 / std::sqrt(std::max(kv, kmin));
      // 10:1 at most on analytic surfaces; 3:1 on free-form faces, whose curvature still varies along
      // the stretch. But 10:1 on a free-form face that bends a thousand times faster one way than the
      // other at every grid point, evenly one-way otherwise (a wing's or a fuselage's skin, a fillet
      // along a gentle spine): the square-root rule asks for 30:1 even where it is least one-way,
      // three times the stretch given. A319's skins took 10384 triangles at 0.1% with 3:1, 6094
      // with 10:1 (BRepMesh 6595). (Without tolerances: with them, the steps they allow, above.)
      most = directional || (evenlyOneWay && std::max(uOverV, vOverU) >= kOneWayRatio) ? 0.1 : 1.0 / 3;
    }
    const double h = std::min(hu, hv);
    su *= std::max(h / hu, most);
    sv *= std::max(h / hv, most);
  }
  if (!(su > 0) || !std::isfinite(su)) su = 1;
  if (!(sv > 0) || !std::isfinite(sv)) sv = 1;
  uAxis_.t = {u0}, uAxis_.x = {0.0}, uAxis_.slope = {su};
  vAxis_.t = {v0}, vAxis_.x = {0.0}, vAxis_.slope = {sv};
  std::vector<std::pair<double, double>> uUneven, vUneven;  // spans divideUnevenSpans() divides
  try {
    buildAxis(true, uAxis_, uUneven);
    buildAxis(false, vAxis_, vUneven);
    if (surface_.GetType() == GeomAbs_Sphere) buildConformalSphereAxes();
    else if (ringAngles_ && ringAngles_->major == 0) buildConformalDisguisedSphereAxes();
  } catch (const Standard_Failure&) {
    uAxis_.t = {u0}, uAxis_.x = {0.0}, uAxis_.slope = {su}, uAxis_.period = 0;
    vAxis_.t = {v0}, vAxis_.x = {0.0}, vAxis_.slope = {sv}, vAxis_.period = 0;
    uUneven.clear(), vUneven.clear();
  }

  if (chordal > 0 && angleRad > 0) {
    // Knots the mesher must take for creases: the band the normal turns in is narrower than its
    // smallest angular split (a tenth of the tolerance, as BRepMesh's MinSize).
    try {
      findSharpKnots(true, uAxis_, 0.1 * chordal, angleRad, uSharpKnots_);
      findSharpKnots(false, vAxis_, 0.1 * chordal, angleRad, vSharpKnots_);
    } catch (const Standard_Failure&) {
      uSharpKnots_.clear(), vSharpKnots_.clear();
    }
    for (const bool uDir : {true, false}) {
      std::vector<double>& all = uDir ? uCreases_ : vCreases_;
      const std::vector<double>& sharp = uDir ? uSharpKnots_ : vSharpKnots_;
      if (sharp.empty()) continue;
      all.insert(all.end(), sharp.begin(), sharp.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
    }
  }
  // After the sharp knots, which compare the spans' mean speeds either side of a knot.
  if (!uUneven.empty() || !vUneven.empty()) {
    const Axis uKnots = uAxis_, vKnots = vAxis_;
    try {
      divideUnevenSpans(true, uUneven, uSharpKnots_, uAxis_);
      divideUnevenSpans(false, vUneven, vSharpKnots_, vAxis_);
    } catch (const Standard_Failure&) {
      uAxis_ = uKnots, vAxis_ = vKnots;
    }
  }
  if (uPeriodic_ && !uCreases_.empty()) uPeriod_ = surface_.UPeriod();
  if (vPeriodic_ && !vCreases_.empty()) vPeriod_ = surface_.VPeriod();
  detectFlat(chordal);
}

void SurfaceEval::detectFlat(double chordal) {
  try {
    findFlatPlane(chordal);
  } catch (const Standard_Failure&) {
    flat_ = false;
  }
}

void SurfaceEval::findFlatPlane(double chordal) {
  if (flat_ || !flatFacesEnabled_.load(std::memory_order_relaxed) || !(chordal > 0) || !(uMax > uMin) ||
      !(vMax > vMin))
    return;
  // A periodic face within one period (a whole period would bring its seam's two sides onto one
  // line of the plane).
  if ((uPeriodic_ && !(uMax - uMin < (1 - 1e-9) * surface_.UPeriod())) ||
      (vPeriodic_ && !(vMax - vMin < (1 - 1e-9) * surface_.VPeriod())))
    return;
  TopLoc_Location location;
  Handle(Geom_Surface) basis = BRep_Tool::Surface(face_, location);
  while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis))
    basis = trimmed->BasisSurface();
  const Handle(Geom_BSplineSurface) bs = Handle(Geom_BSplineSurface)::DownCast(basis);
  if (bs.IsNull()) return;
  // The poles' plane, within the thickness allowed.
  const gp_Trsf& placement = location.Transformation();
  TColgp_Array1OfPnt poles(1, bs->NbUPoles() * bs->NbVPoles());
  for (int i = 1, k = 1; i <= bs->NbUPoles(); ++i)
    for (int j = 1; j <= bs->NbVPoles(); ++j) poles(k++) = bs->Pole(i, j).Transformed(placement);
  const GProp_PEquation fit(poles, kFlatThickness * chordal);
  if (!fit.IsPlanar()) return;
  gp_XYZ normal = fit.Plane().Axis().Direction().XYZ();
  // The orientation at the points of a grid over the face's box: one side of the plane at each.
  // (Over the box, not only the face: telling the points on the face from the rest took 5-30 ms a
  // face, with OpenCASCADE's classifier, on the sample models' flat faces.)
  const int n = kFlatGrid;
  std::vector<gp_Pnt> at;
  struct Orientation {
    double across, speeds;  // (Su x Sv) . normal and |Su| |Sv|
    bool onBoxSide;
  };
  std::vector<Orientation> orientations;
  double suLow = HUGE_VAL, suHigh = 0, svLow = HUGE_VAL, svHigh = 0;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      d1(uMin + (uMax - uMin) * i / n, vMin + (vMax - vMin) * j / n, p, du, dv);
      at.push_back(p);
      suLow = std::min(suLow, du.Magnitude()), suHigh = std::max(suHigh, du.Magnitude());
      svLow = std::min(svLow, dv.Magnitude()), svHigh = std::max(svHigh, dv.Magnitude());
      orientations.push_back({du.Crossed(dv).XYZ().Dot(normal), du.Magnitude() * dv.Magnitude(),
                              i == 0 || i == n || j == 0 || j == n});
    }
  }
  // Inside the box the normal must be there and on one side everywhere. On the box's sides, points
  // where Su x Sv is next to nothing beside the grid's largest speeds are left out: a pole row (a
  // degenerate edge, Su or Sv nothing there and its direction noise), which the plane takes to one
  // point as the surface does. Such a row also makes the parametrisation uneven below: in the
  // scaled UV plane the triangles fanning into it could flip (a fuzzed flat sheet fanning from a
  // pole: two flipped at its pole corner on each level).
  int side = 0;
  for (const Orientation& o : orientations) {
    if (o.onBoxSide && !(std::abs(o.across) > kNoNormalSine * suHigh * svHigh)) continue;
    if (!(std::abs(o.across) > kNoNormalSine * o.speeds)) return;  // a pole or a fold inside
    const int here = o.across > 0 ? 1 : -1;
    if (side != 0 && here != side) return;  // the parametrisation folds the sheet over
    side = here;
  }
  if (side == 0) return;
  // A parametrisation close to uniform meshes as well in the scaled UV plane, and cheaper (the
  // plane's points are surface evaluations, its inverse Newton steps: bearing's 28 flat faces,
  // meshed the same either way, took 8% longer in their plane).
  if (suHigh <= kFlatSpeedSpread * suLow && svHigh <= kFlatSpeedSpread * svLow) return;
  if (side < 0) normal.Reverse();
  const gp_XYZ origin = at[at.size() / 2].XYZ();
  double thickness = 0;  // from the plane through the middle point
  for (int k = poles.Lower(); k <= poles.Upper(); ++k)
    thickness = std::max(thickness, std::abs((poles(k).XYZ() - origin).Dot(normal)));
  // The frame: x along Su at the middle, y across it (x, y and the normal right-handed, so the
  // plane's orientation is UV's).
  gp_Pnt p;
  gp_Vec du, dv;
  d1(0.5 * (uMin + uMax), 0.5 * (vMin + vMax), p, du, dv);
  gp_XYZ x = du.XYZ() - normal * du.XYZ().Dot(normal);
  if (!(x.Modulus() > 0)) return;
  x.Normalize();
  flatOrigin_ = origin, flatX_ = x, flatY_ = normal.Crossed(x);
  Bnd_Box2d extent;
  flatGrid_.clear();
  for (const gp_Pnt& q : at) {
    const gp_XYZ d = q.XYZ() - origin;
    flatGrid_.push_back({d.Dot(flatX_), d.Dot(flatY_)});
    extent.Add(gp_Pnt2d(flatGrid_.back().x, flatGrid_.back().y));
  }
  flatSize_ = std::sqrt(extent.SquareExtent());
  if (!(flatSize_ > 0)) return;
  flat_ = flatFound_ = true;
  flatThickness_ = thickness;
  // A plane has no creases, bends or sharp knots (a free-form one can have knots where the
  // parametrisation breaks, its speed jumping; the surface does not turn there).
  uCreases_.clear(), vCreases_.clear(), uBends_.clear(), vBends_.clear();
  uSharpKnots_.clear(), vSharpKnots_.clear();
}

double SurfaceEval::flatNewton(const cet::Point2& q, double& u, double& v) const {
  const double uLow = std::min(su0_, reachU0_), uHigh = std::max(su1_, reachU1_);
  const double vLow = std::min(sv0_, reachV0_), vHigh = std::max(sv1_, reachV1_);
  u = std::clamp(u, uLow, uHigh), v = std::clamp(v, vLow, vHigh);
  gp_Pnt p;
  gp_Vec du, dv;
  d1(u, v, p, du, dv);
  auto residual = [&](const gp_Pnt& s, double& rx, double& ry) {
    const gp_XYZ d = s.XYZ() - flatOrigin_;
    rx = q.x - d.Dot(flatX_), ry = q.y - d.Dot(flatY_);
    return std::sqrt(rx * rx + ry * ry);
  };
  double rx = 0, ry = 0;
  double error = residual(p, rx, ry);
  for (int it = 0; it < kFlatNewtonSteps && error > 1e-13 * flatSize_; ++it) {
    const double a = du.XYZ().Dot(flatX_), b = dv.XYZ().Dot(flatX_), c = du.XYZ().Dot(flatY_),
                 d = dv.XYZ().Dot(flatY_);
    const double det = a * d - b * c;
    if (!(std::abs(det) > 0)) break;
    double stepU = (rx * d - b * ry) / det, stepV = (a * ry - c * rx) / det;
    // Shortened to stay inside the box, in the same direction (clamping each parameter on its own
    // turned steps along the box's side, where they stalled).
    double keep = 1;
    if (u + stepU > uHigh) keep = std::min(keep, (uHigh - u) / stepU);
    if (u + stepU < uLow) keep = std::min(keep, (uLow - u) / stepU);
    if (v + stepV > vHigh) keep = std::min(keep, (vHigh - v) / stepV);
    if (v + stepV < vLow) keep = std::min(keep, (vLow - v) / stepV);
    stepU *= std::max(keep, 0.0), stepV *= std::max(keep, 0.0);
    bool better = false;
    for (double f = 1; f > 1e-6 && !better; f *= 0.5) {  // halved until the residual falls
      const double nu = std::clamp(u + f * stepU, uLow, uHigh), nv = std::clamp(v + f * stepV, vLow, vHigh);
      gp_Pnt np;
      gp_Vec ndu, ndv;
      d1(nu, nv, np, ndu, ndv);
      double nrx = 0, nry = 0;
      const double e = residual(np, nrx, nry);
      if (e < error) u = nu, v = nv, du = ndu, dv = ndv, rx = nrx, ry = nry, error = e, better = true;
    }
    if (!better) break;
  }
  return error;
}

void SurfaceEval::flatUnscaled(const cet::Point2& q, double& u, double& v, const double* bu, const double* bv,
                               const double* bw, int n) const {
  const double enough = 1e-9 * flatSize_;
  double error = HUGE_VAL;
  if (bu) {
    u = 0, v = 0;
    for (int i = 0; i < n; ++i) u += bw[i] * bu[i], v += bw[i] * bv[i];
    error = flatNewton(q, u, v);
    // Then from the corners it blends: where the parametrisation is squeezed (a 1e-6 step of u
    // moving the point 5% of the face's size), the blend of their parameters can lie in another
    // part of the face than the point.
    for (int i = 0; i < n && error > enough; ++i) {
      if (!(bw[i] > 0)) continue;
      double cu = bu[i], cv = bv[i];
      const double e = flatNewton(q, cu, cv);
      if (e < error) error = e, u = cu, v = cv;
    }
    if (error <= enough) return;
  } else {
    // From where the scales per direction put it (near on a parametrisation close to affine).
    u = uAxis_.inverse(q.x), v = vAxis_.inverse(q.y);
    error = flatNewton(q, u, v);
    if (error <= enough) return;
  }
  // From the grid point nearest q.
  std::size_t nearest = 0;
  double least = HUGE_VAL;
  for (std::size_t k = 0; k < flatGrid_.size(); ++k) {
    const double dx = flatGrid_[k].x - q.x, dy = flatGrid_[k].y - q.y;
    if (dx * dx + dy * dy < least) least = dx * dx + dy * dy, nearest = k;
  }
  const int i = static_cast<int>(nearest) / (kFlatGrid + 1), j = static_cast<int>(nearest) % (kFlatGrid + 1);
  double gu = uMin + (uMax - uMin) * i / kFlatGrid, gv = vMin + (vMax - vMin) * j / kFlatGrid;
  if (flatNewton(q, gu, gv) < error) u = gu, v = gv;
}

void SurfaceEval::buildAxis(bool uDir, Axis& axis, std::vector<std::pair<double, double>>& uneven) const {
  uneven.clear();
  if (surface_.GetType() != GeomAbs_BSplineSurface) return;
  const Handle(Geom_BSplineSurface) bs = surface_.Surface().BSpline();  // unlocated: no copy (knots only)
  const int n = uDir ? bs->NbUKnots() : bs->NbVKnots();
  if (n < 2 || n > 2049) return;  // more spans than are worth sampling
  std::vector<double> knots(static_cast<std::size_t>(n));
  for (int i = 1; i <= n; ++i) knots[std::size_t(i - 1)] = uDir ? bs->UKnot(i) : bs->VKnot(i);
  const bool periodic = uDir ? uPeriodic_ : vPeriodic_;
  const double reachLow = uDir ? reachU0_ : reachV0_, reachHigh = uDir ? reachU1_ : reachV1_;
  const double firstSpan = knots[1] - knots[0],
               lastSpan = knots[std::size_t(n) - 1] - knots[std::size_t(n) - 2];
  const bool before = !periodic && reachLow < knots.front() - kReachMargin * firstSpan;
  const bool after = !periodic && reachHigh > knots.back() + kReachMargin * lastSpan;
  if (n < 3 && !before && !after) return;  // one span: one scale
  // Mean 3D speed of each span the face covers, sampled across the face's extent in the other
  // direction; those spans decide whether one scale will do. The spans it does not cover (a face
  // trimmed from a large surface: most of them) are not sampled and take the mean speed: no point of
  // the face maps through them, and they shift the covered spans' x by a constant only. A periodic
  // direction samples every span, as its period in x depends on all of them.
  const double lo = uDir ? vMin : uMin, hi = uDir ? vMax : uMax;
  const double from = uDir ? uMin : vMin, to = uDir ? uMax : vMax;
  std::vector<double> slope(knots.size() - 1, std::numeric_limits<double>::quiet_NaN());
  struct SlowEnd {
    std::size_t span;
    int side;      // 0: its first knot, 1: its last
    double speed;  // just inside it
    double spread;  // there, the fastest of the five lines across the face over the slowest
  };
  std::vector<SlowEnd> slowEnds;
  double smin = 1e300, smax = 0;
  // Past the knots (kReachBands): the bands' ends, from the reach to the end knot, and the 3D
  // length of their chords over their width, the mean over five lines across the face.
  auto bands = [&](double end, double far, std::vector<double>& t, std::vector<double>& s) {
    const double width = std::abs(far - end), finest = 1e-3 * (far < end ? firstSpan : lastSpan);
    const double side = far < end ? -1.0 : 1.0;
    t.push_back(far);
    for (int j = 1; j < kReachBands && width * std::ldexp(1.0, -j) > finest; ++j)
      t.push_back(end + side * width * std::ldexp(1.0, -j));
    t.push_back(end);
    for (std::size_t k = 0; k + 1 < t.size(); ++k) {
      double sum = 0;
      for (int j = 0; j < 5; ++j) {
        const double w = lo + (hi - lo) * (j + 0.5) / 5;
        gp_Pnt a, b;
        gp_Vec du, dv;
        if (uDir) {
          d1(t[k], w, a, du, dv), d1(t[k + 1], w, b, du, dv);
        } else {
          d1(w, t[k], a, du, dv), d1(w, t[k + 1], b, du, dv);
        }
        sum += a.Distance(b);
      }
      s.push_back(sum / 5 / std::abs(t[k + 1] - t[k]));
      smin = std::min(smin, s.back()), smax = std::max(smax, s.back());
    }
    if (side < 0) return;  // increasing already
    std::reverse(t.begin(), t.end());
    std::reverse(s.begin(), s.end());
  };
  std::vector<double> lowT, lowSlope, highT, highSlope;
  if (before) bands(knots.front(), reachLow, lowT, lowSlope);
  if (after) bands(knots.back(), reachHigh, highT, highSlope);
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const bool covered = knots[k + 1] > from && knots[k] < to;
    if (!covered && !periodic) continue;
    double sum = 0, third[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 5; ++j) {
        const double t = knots[k] + (knots[k + 1] - knots[k]) * (i + 0.5) / 3, w = lo + (hi - lo) * (j + 0.5) / 5;
        const double speed = speedAlong(uDir, t, w);
        sum += speed, third[i] += speed;
      }
    }
    slope[k] = sum / 15;
    if (covered) smin = std::min(smin, slope[k]), smax = std::max(smax, slope[k]);
    // Uneven: the speed differs between the thirds, and just inside an end it is far above the
    // span's mean (where the span's one scale squeezes the surface into a sliver of the scaled
    // plane) or far below it (where it stretches the scaled plane most).
    const double low = std::min({third[0], third[1], third[2]}),
                 high = std::max({third[0], third[1], third[2]});
    if (covered && high > kUnevenSpanSpread * low && std::isfinite(high)) {
      const double width = knots[k + 1] - knots[k];
      double spreads[2];
      const double ends[2] = {meanSpeedAcross(uDir, knots[k] + 1e-3 * width, &spreads[0]),
                              meanSpeedAcross(uDir, knots[k + 1] - 1e-3 * width, &spreads[1])};
      const int slow = ends[0] <= ends[1] ? 0 : 1, fast = 1 - slow;
      if (ends[fast] > kFastEndRatio * slope[k] && ends[fast] > spreads[fast] * spreads[fast] * slope[k])
        uneven.emplace_back(knots[k], knots[k + 1]);
      else if (ends[slow] * kSlowEndRatio < slope[k])
        slowEnds.push_back({k, slow, ends[slow], spreads[slow]});
    }
  }
  // Only where the slow end runs on at the speed of the covered span across the knot: a slow
  // span meeting a fast one smoothly. Elsewhere the speed falls towards a line where the surface
  // pinches (its rows collapse), and a scale following it squeezes the plane there (a fuzzed
  // sheet pinched at a knot: 4528 pieces, 86 triangles without a flip became 5426 with 733).
  // And only where the slow end is slow all along the knot line: a scale per piece of u (or v) can
  // follow a speed that changes along the span, not one that also changes 100x across the face (a
  // fuzzed planar sheet whose weights squeeze one corner: dividing took it from 1 flipped
  // triangle to 534).
  for (const SlowEnd& e : slowEnds) {
    if (!(e.spread <= kUnevenSpanSpread)) continue;
    const std::size_t across = e.side == 0 ? e.span - 1 : e.span + 1;
    if ((e.side == 0 && e.span == 0) || across >= slope.size() || !std::isfinite(slope[across])) continue;
    if (!(knots[across + 1] > from && knots[across] < to)) continue;  // not covered
    if (slope[across] <= kUnevenSpanSpread * e.speed && e.speed <= kUnevenSpanSpread * slope[across])
      uneven.emplace_back(knots[e.span], knots[e.span + 1]);
  }
  std::sort(uneven.begin(), uneven.end());  // fast ends first, then slow ones: in span order again
  if (!(smax > 4 * smin) || !std::isfinite(smax)) {
    uneven.clear();
    return;
  }
  // A span without extent (its poles on one point) still needs some room in x.
  const double mean = uDir ? su : sv;
  for (double& s : slope) s = std::isfinite(s) ? std::max(s, 1e-3 * mean) : mean;
  for (auto* band : {&lowSlope, &highSlope})
    for (double& s : *band) s = std::isfinite(s) ? std::max(s, 1e-3 * mean) : mean;
  if (!lowT.empty()) {
    knots.insert(knots.begin(), lowT.begin(), lowT.end() - 1);
    slope.insert(slope.begin(), lowSlope.begin(), lowSlope.end());
  }
  if (!highT.empty()) {
    knots.insert(knots.end(), highT.begin() + 1, highT.end());
    slope.insert(slope.end(), highSlope.begin(), highSlope.end());
  }
  axis.t = knots;
  axis.slope = slope;
  axis.x.assign(1, 0.0);
  for (std::size_t k = 0; k < slope.size(); ++k) axis.x.push_back(axis.x.back() + (knots[k + 1] - knots[k]) * slope[k]);
  axis.period = periodic ? knots.back() - knots.front() : 0.0;
  axis.periodX = axis.x.back();
}

double SurfaceEval::speedAlong(bool uDir, double t, double w) const {
  gp_Pnt p;
  gp_Vec du, dv;
  if (uDir) {
    d1(t, w, p, du, dv);
  } else {
    d1(w, t, p, du, dv);
  }
  return (uDir ? du : dv).Magnitude();
}

double SurfaceEval::meanSpeedAcross(bool uDir, double t, double* spread) const {
  const double lo = uDir ? vMin : uMin, hi = uDir ? vMax : uMax;
  double sum = 0, low = 1e300, high = 0;
  for (int j = 0; j < 5; ++j) {
    const double speed = speedAlong(uDir, t, lo + (hi - lo) * (j + 0.5) / 5);
    sum += speed, low = std::min(low, speed), high = std::max(high, speed);
  }
  if (spread) *spread = high / low;
  return sum / 5;
}

void SurfaceEval::divideUnevenSpans(bool uDir, const std::vector<std::pair<double, double>>& uneven,
                                    const std::vector<double>& sharpKnots, Axis& axis) const {
  if (uneven.empty() || axis.slope.size() < 2) return;
  const double lo = uDir ? vMin : uMin, hi = uDir ? vMax : uMax;
  const auto speed = [&](double t) { return meanSpeedAcross(uDir, t); };
  // The mean 3D chord over [a, b] along five lines across the face, over b - a.
  auto chordSlope = [&](double a, double b) {
    double sum = 0;
    for (int j = 0; j < 5; ++j) {
      const double w = lo + (hi - lo) * (j + 0.5) / 5;
      sum += uDir ? point(a, w).Distance(point(b, w)) : point(w, a).Distance(point(w, b));
    }
    return sum / 5 / (b - a);
  };
  double mean = 0;
  for (std::size_t k = 0; k < axis.slope.size(); ++k) mean += axis.slope[k] * (axis.t[k + 1] - axis.t[k]);
  mean /= axis.t.back() - axis.t.front();
  std::vector<double> t{axis.t.front()}, slope;
  std::size_t next = 0;  // the next uneven span
  for (std::size_t k = 0; k < axis.slope.size(); ++k) {
    const double a = axis.t[k], b = axis.t[k + 1];
    while (next < uneven.size() && uneven[next].first < a) ++next;
    const bool bySharpKnot = std::binary_search(sharpKnots.begin(), sharpKnots.end(), a) ||
                             std::binary_search(sharpKnots.begin(), sharpKnots.end(), b);
    if (next == uneven.size() || uneven[next].first != a || uneven[next].second != b || bySharpKnot) {
      t.push_back(b), slope.push_back(axis.slope[k]);
      continue;
    }
    // Halves until the speed at a sixth, the middle and five sixths of a piece is within
    // kEvenPieceSpread (inside it: at a knot, the derivative may be the next span's).
    struct Piece {
      double a, b;
      int depth;
    };
    std::vector<Piece> stack{Piece{a, b, 0}};  // the first half on top: pieces in order
    const std::size_t before = t.size();
    while (!stack.empty()) {
      if (t.size() - before >= kMaxPiecesPerSpan) break;
      const Piece q = stack.back();
      stack.pop_back();
      const double w = q.b - q.a, m = 0.5 * (q.a + q.b);
      const double s0 = speed(q.a + w / 6), s1 = speed(m), s2 = speed(q.b - w / 6);
      const double low = std::min({s0, s1, s2}), high = std::max({s0, s1, s2});
      if (q.depth < kUnevenSpanDepth && m > q.a && m < q.b && !(high <= kEvenPieceSpread * low)) {
        stack.push_back(Piece{m, q.b, q.depth + 1});
        stack.push_back(Piece{q.a, m, q.depth + 1});
        continue;
      }
      const double s = chordSlope(q.a, q.b);
      t.push_back(q.b), slope.push_back(std::isfinite(s) ? std::max(s, 1e-3 * mean) : axis.slope[k]);
    }
    if (!stack.empty()) {  // too many pieces: the span keeps its scale
      t.resize(before), slope.resize(before - 1);
      t.push_back(b), slope.push_back(axis.slope[k]);
    }
  }
  axis.t = t;
  axis.slope = slope;
  axis.x.assign(1, 0.0);
  for (std::size_t k = 0; k < slope.size(); ++k)
    axis.x.push_back(axis.x.back() + (t[k + 1] - t[k]) * slope[k]);
  if (axis.period > 0) axis.periodX = axis.x.back();
}

void SurfaceEval::findSharpKnots(bool uDir, const Axis& axis, double reach, double angleRad, std::vector<double>& out) const {
  if (surface_.GetType() != GeomAbs_BSplineSurface || axis.slope.size() < 2) return;
  const double from = uDir ? uMin : vMin, to = uDir ? uMax : vMax;
  const double lo = uDir ? vMin : uMin, hi = uDir ? vMax : uMax;
  const double cosTurn = std::cos(angleRad);
  auto at = [&](double t, double w, gp_Pnt& p, gp_Dir& n) {
    gp_Vec du, dv;
    if (uDir) {
      d1(t, w, p, du, dv);
    } else {
      d1(w, t, p, du, dv);
    }
    const gp_Vec c = du.Crossed(dv);
    if (!(c.Magnitude() > 1e-12 * du.Magnitude() * dv.Magnitude()) || !(c.Magnitude() > 0)) return false;
    n = gp_Dir(c);
    return true;
  };
  for (std::size_t k = 1; k < axis.slope.size(); ++k) {
    const double knot = axis.t[k];
    if (!(knot > from && knot < to)) continue;
    const std::vector<double>& creases = uDir ? uCreases_ : vCreases_;  // not C1 there: a crease already
    if (std::binary_search(creases.begin(), creases.end(), knot)) continue;
    const double slow = std::min(axis.slope[k - 1], axis.slope[k]), fast = std::max(axis.slope[k - 1], axis.slope[k]);
    if (!(fast > kSharpKnotSpeedRatio * slow)) continue;
    // Step into the fast span until within reach of the knot line, and compare the normals there.
    const double side = axis.slope[k] > axis.slope[k - 1] ? 1.0 : -1.0;
    const double width = side > 0 ? axis.t[k + 1] - knot : knot - axis.t[k - 1];
    bool sharp = false;
    for (int j = 0; j < 9 && !sharp; ++j) {
      const double w = lo + (hi - lo) * (j + 0.5) / 9;
      gp_Pnt p0, p1;
      gp_Dir n0, n1;
      if (!at(knot, w, p0, n0)) continue;
      double step = width;
      for (int halvings = 0; halvings < 64; ++halvings, step *= 0.5) {
        const double t = knot + side * step;
        if (t == knot) break;
        if (!at(t, w, p1, n1)) continue;
        if (p0.Distance(p1) > reach) continue;
        sharp = n0.Dot(n1) < cosTurn;
        break;
      }
    }
    if (sharp) out.push_back(knot);
  }
}

void SurfaceEval::buildConformalSphereAxes() {
  const double r = surface_.Sphere().Radius();
  const double a = std::max(vMin, -M_PI / 2), b = std::min(vMax, M_PI / 2);
  if (!(r > 0) || !(b > a)) return;
  uAxis_.t = {u0}, uAxis_.x = {0.0}, uAxis_.slope = {r}, uAxis_.period = 0;
  // Spans over which the cosine changes by kConformalSpanChange at most (its logarithm's slope is
  // tan v), and no longer than kConformalSpanRad.
  const double cosCap = std::cos(kConformalCapRad);
  Axis merc;
  merc.t = {a};
  merc.x = {0.0};
  while (merc.t.back() < b) {
    const double t0 = merc.t.back();
    const double steep = std::min(std::abs(std::tan(t0)) + kConformalSpanChange, std::tan(kConformalCapRad));
    const double t1 = std::min(b, t0 + std::min(kConformalSpanRad, kConformalSpanChange / steep));
    merc.slope.push_back(r / std::max(std::cos(0.5 * (t0 + t1)), cosCap));
    merc.x.push_back(merc.x.back() + (t1 - t0) * merc.slope.back());
    merc.t.push_back(t1);
  }
  vAxis_ = merc;
}

void SurfaceEval::buildConformalDisguisedSphereAxes() {
  const RingAngles& a = *ringAngles_;
  const double r = a.minor;
  const double cosCap = std::cos(kConformalCapRad);
  // Over the table's points: the analytic sphere's x of each angle.
  const auto axisOf = [](const AngleTable& table, const auto& x) {
    Axis axis;
    const std::vector<double>& t = table.params();
    const std::vector<double>& angle = table.angles();
    axis.t = t;
    axis.x = {0.0};
    for (std::size_t k = 0; k + 1 < t.size(); ++k) {
      axis.x.push_back(axis.x.back() + x(angle[k], angle[k + 1]));
      axis.slope.push_back((axis.x[k + 1] - axis.x[k]) / (t[k + 1] - t[k]));
    }
    return axis;
  };
  const Axis along = axisOf(a.ring, [r](double a0, double a1) { return r * (a1 - a0); });
  // The latitude's conformal map: r / cos over each span, the cosine at its middle (kept off the
  // poles as on the analytic sphere).
  const Axis across = axisOf(a.tube, [r, cosCap](double a0, double a1) {
    return r * (a1 - a0) / std::max(std::cos(0.5 * (a0 + a1)), cosCap);
  });
  uAxis_ = a.tubeAlongU ? across : along;
  vAxis_ = a.tubeAlongU ? along : across;
}

void SurfaceEval::keepTurningBreaks(bool uDir, std::vector<double>& breaks) {
  const double lo = uDir ? su0_ : sv0_, hi = uDir ? su1_ : sv1_;
  const double a0 = uDir ? vMin : uMin, a1 = uDir ? vMax : uMax;  // along the line
  const double cosTurn = std::cos(kCreaseTurnRad);
  // Where along the lines: kCreaseSamples evenly, and on a B-spline the knots of the other direction
  // inside the box and their spans' middles (a jump that lives in one narrow span shows there), up
  // to kCreaseSampleBudget samples over all the direction's lines.
  std::vector<double> along;
  for (int k = 0; k < kCreaseSamples; ++k) along.push_back(a0 + (a1 - a0) * k / (kCreaseSamples - 1));
  if (surface_.GetType() == GeomAbs_BSplineSurface && !breaks.empty()) {
    const Handle(Geom_BSplineSurface) bs = surface_.Surface().BSpline();
    const int n = uDir ? bs->NbVKnots() : bs->NbUKnots();
    std::vector<double> knots;
    for (int i = 1; i <= n; ++i) {
      const double t = uDir ? bs->VKnot(i) : bs->UKnot(i);
      if (i > 1) knots.push_back(0.5 * (knots.back() + t));
      knots.push_back(t);
    }
    const std::size_t room = kCreaseSampleBudget / breaks.size();
    const std::size_t stride = knots.size() > room ? (knots.size() + room - 1) / std::max<std::size_t>(room, 1) : 1;
    for (std::size_t i = 0; i < knots.size(); i += stride)
      if (knots[i] > a0 && knots[i] < a1) along.push_back(knots[i]);
  }
  std::vector<double> kept;
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    const double c = breaks[i];
    // One-sided limits: a step well inside the spans on either side (the nearest other break or
    // the surface's end bounds them).
    double gap = std::numeric_limits<double>::max();
    if (i > 0) gap = std::min(gap, c - breaks[i - 1]);
    if (i + 1 < breaks.size()) gap = std::min(gap, breaks[i + 1] - c);
    if (c > lo) gap = std::min(gap, c - lo);
    if (c < hi) gap = std::min(gap, hi - c);
    if (!(gap > 0) || gap == std::numeric_limits<double>::max()) gap = std::max(hi - lo, 1.0);
    const double step =
        std::max(1e-6 * gap, 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(c)));
    bool turns = false, folds = false, jumps = false;
    int measured = 0;  // samples with a normal on both sides
    for (std::size_t k = 0; k < along.size() && !folds; ++k) {
      const double a = along[k];
      gp_Vec n[2];
      double speed[2] = {0, 0};  // across the line
      bool normals = true;
      for (int side = 0; side < 2; ++side) {
        gp_Pnt p;
        gp_Vec du, dv;
        const double u = uDir ? c : a, v = uDir ? a : c;
        if (direct_) {  // exactly on the line, in the span that ends there and the one that starts there
          const bool below = side == 0;
          direct_->d1(u, v, uDir ? (below ? direct_->uSpanBelow(u) : direct_->uSpan(u)) : direct_->uSpan(u),
                      uDir ? direct_->vSpan(v) : (below ? direct_->vSpanBelow(v) : direct_->vSpan(v)), p, du,
                      dv);
        } else {
          const double t = side == 0 ? c - step : c + step;
          surface_.D1(uDir ? t : u, uDir ? v : t, p, du, dv);
        }
        n[side] = du.Crossed(dv);
        speed[side] = (uDir ? du : dv).Magnitude();
        // No normal, or one that is rounding noise (Su and Sv nearly parallel: a collapsed part; Su or
        // Sv next to nothing against its mean, as regularNormal() judges: a pole, where the other's
        // direction is noise too. A NURBS sphere's meridian at a knot read 36 degrees of turn at its
        // poles and became a crease: triangles from a pole to two points on it, flat in its plane,
        // took no facet test and stayed flipped).
        const double m = n[side].Magnitude();
        normals = normals && std::isfinite(m) && m > kNoNormalSine * du.Magnitude() * dv.Magnitude() &&
                  du.Magnitude() > 1e-7 * meanLu_ && dv.Magnitude() > 1e-7 * meanLv_;
      }
      if (!normals) continue;
      ++measured;
      jumps = jumps || std::max(speed[0], speed[1]) > kSharpKnotSpeedRatio * std::min(speed[0], speed[1]);
      const double dot = n[0].Dot(n[1]), norms = n[0].Magnitude() * n[1].Magnitude();
      turns = turns || dot < cosTurn * norms;
      folds = dot < kFoldingCreaseCos * norms;
    }
    // A line with no normal at any sample (the surface collapsed all along it) stays a crease, and
    // so does one where the speed across it jumps by kSharpKnotSpeedRatio or more (a fuzzed sheet
    // whose speed across two knots 1.6e-7 apart falls from 13000 to 0.009: its triangles across them
    // flipped and their splits cascaded, 17798 -> 506558 triangles, when those were no creases).
    if (turns || jumps || measured == 0) kept.push_back(c);
    if (turns && !folds) (uDir ? uBends_ : vBends_).push_back(c);
  }
  breaks.swap(kept);
}

bool SurfaceEval::crosses(const std::vector<double>& creases, double period, double a, double b) {
  if (creases.empty() || a == b) return false;
  if (a > b) std::swap(a, b);
  if (period > 0) {
    // Bring a into the first period of the crease list; b keeps its distance to it.
    const double k = std::floor((a - creases.front()) / period);
    a -= k * period, b -= k * period;
    if (b - a >= period) return true;
  }
  // A crease c with a <= c <= b, within this period or (periodic) the next.
  for (double shift : {0.0, period}) {
    const auto it = std::lower_bound(creases.begin(), creases.end(), a - shift);
    if (it != creases.end() && *it + shift <= b) return true;
    if (period == 0) break;
  }
  return false;
}

bool SurfaceEval::near(const std::vector<double>& creases, double period, double x, double band) {
  if (creases.empty()) return false;
  if (period > 0) x -= std::floor((x - creases.front()) / period) * period;  // into the crease list's period
  const auto it = std::lower_bound(creases.begin(), creases.end(), x - band);
  if (it != creases.end() && *it <= x + band) return true;
  return period > 0 && x + band >= creases.front() + period;  // the next period's first crease
}

bool CreaseLines::on(double pu, double pv) const {
  return SurfaceEval::near(u, uPeriod, pu, uBand) || SurfaceEval::near(v, vPeriod, pv, vBand);
}

bool SurfaceEval::sharpKnotBetween(bool uDir, double a, double b, double near, double& knot) const {
  const std::vector<double>& knots = uDir ? uSharpKnots_ : vSharpKnots_;
  bool found = false;
  for (auto it = std::upper_bound(knots.begin(), knots.end(), a); it != knots.end() && *it < b; ++it) {
    if (!found || std::abs(*it - near) < std::abs(knot - near)) knot = *it;
    found = true;
  }
  return found;
}

bool SurfaceEval::bendBetween(bool uDir, double a, double b, double& line) const {
  const std::vector<double>& bends = uDir ? uBends_ : vBends_;
  const double period = uDir ? uPeriod_ : vPeriod_;
  const double band = 1e-9 * (uDir ? uMax - uMin : vMax - vMin);
  if (bends.empty() || !(b - a > 2 * band)) return false;
  // Shifts of the lines by whole periods that can land between a and b.
  double k0 = 0, k1 = 0;
  if (period > 0) {
    k0 = std::floor((a - bends.back()) / period), k1 = std::ceil((b - bends.front()) / period);
    if (k1 - k0 > 4) return false;  // wider than the period: no one crossing
  }
  for (double k = k0; k <= k1; ++k) {
    const double shift = k * period;
    const auto it = std::upper_bound(bends.begin(), bends.end(), a + band - shift);
    if (it != bends.end() && *it + shift < b - band) {
      line = *it + shift;
      return true;
    }
  }
  return false;
}

bool SurfaceEval::collapsed() const {
  if (!(uMax > uMin && vMax > vMin) || gridArea_ > 1e3 * kNoArea) return false;
  // A closer look: the 5x5 grid may have missed where the area is.
  constexpr int kSteps = 17;
  const double du = (uMax - uMin) / (kSteps - 1), dv = (vMax - vMin) / (kSteps - 1);
  Bnd_Box extent;
  double largest = 0;  // |Su x Sv|
  for (int i = 0; i < kSteps; ++i) {
    for (int j = 0; j < kSteps; ++j) {
      gp_Pnt p;
      gp_Vec du1, dv1;
      d1(uMin + du * i, vMin + dv * j, p, du1, dv1);
      extent.Add(p);
      largest = std::max(largest, du1.Crossed(dv1).Magnitude());
    }
  }
  const double extent2 = extent.IsVoid() ? 0 : extent.SquareExtent();
  const double area = largest * (uMax - uMin) * (vMax - vMin);  // at least the surface's area over the box
  return !(extent2 > 0 && area > kNoArea * extent2 && area > kNoWidth * std::sqrt(extent2));
}

void faceSideD1(const BSplineDirect* direct, const Adaptor3d_Surface& surface, double uMin, double uMax, double vMin,
                double vMax, double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) {
  if (direct) {
    direct->d1(u, v, u >= uMax ? direct->uSpanBelow(u) : direct->uSpan(u),
               v >= vMax ? direct->vSpanBelow(v) : direct->vSpan(v), p, du, dv);
    return;
  }
  surface.D1(u, v, p, du, dv);
  // A B-spline through OpenCASCADE (periodic, or of high degree): the derivatives just inside.
  if (surface.GetType() == GeomAbs_BSplineSurface && (u >= uMax || v >= vMax)) {
    gp_Pnt inside;
    surface.D1(u >= uMax ? u - 1e-9 * (uMax - uMin) : u, v >= vMax ? v - 1e-9 * (vMax - vMin) : v, inside, du, dv);
  }
}

void SurfaceEval::d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const {
  faceSideD1(direct_.get(), surface_, uMin, uMax, vMin, vMax, u, v, p, du, dv);
}

gp_Pnt SurfaceEval::point(double u, double v) const { return direct_ ? direct_->value(u, v) : surface_.Value(u, v); }

void SurfaceEval::findDegenerateRows() {
  // A pcurve within a millionth of the range of an iso-line marks that row; a point lies on the row
  // within half the pcurve's span across it plus 1e-9 of the range.
  const double uRange = std::max(uMax - uMin, 1e-300), vRange = std::max(vMax - vMin, 1e-300);
  for (TopExp_Explorer e(face_, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (!BRep_Tool::Degenerated(edge)) continue;
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face_, first, last);
    if (pcurve.IsNull() || !std::isfinite(first) || !std::isfinite(last)) continue;
    const gp_Pnt2d a = pcurve->Value(first), b = pcurve->Value(last), m = pcurve->Value(0.5 * (first + last));
    const double vSpan = std::max({a.Y(), b.Y(), m.Y()}) - std::min({a.Y(), b.Y(), m.Y()});
    const double uSpan = std::max({a.X(), b.X(), m.X()}) - std::min({a.X(), b.X(), m.X()});
    if (vSpan <= 1e-6 * vRange && uSpan * vRange >= vSpan * uRange) {  // along u more than across (a point: v)
      degenerateRows_.push_back({false, 0.5 * (std::max({a.Y(), b.Y(), m.Y()}) + std::min({a.Y(), b.Y(), m.Y()})),
                                 0.5 * vSpan + 1e-9 * vRange});
    } else if (uSpan <= 1e-6 * uRange) {
      degenerateRows_.push_back({true, 0.5 * (std::max({a.X(), b.X(), m.X()}) + std::min({a.X(), b.X(), m.X()})),
                                 0.5 * uSpan + 1e-9 * uRange});
    }
  }
}

bool SurfaceEval::onDegenerateRow(double u, double v) const {
  for (const DegenerateRow& row : degenerateRows_) {
    const bool periodic = row.uConstant ? uPeriodic_ : vPeriodic_;
    double d = (row.uConstant ? u : v) - row.value;
    if (periodic) d = std::remainder(d, row.uConstant ? surface_.UPeriod() : surface_.VPeriod());
    if (std::abs(d) <= row.tolerance) return true;
  }
  return false;
}

bool SurfaceEval::regularNormal(double u, double v, gp_Pnt& p, gp_Dir& n) const {
  gp_Vec du, dv;
  d1(u, v, p, du, dv);
  const gp_Vec c = du.Crossed(dv);
  const double m = c.Magnitude();
  // Regular where both derivatives are well away from zero against their typical lengths (at a pole
  // one of them is rounding noise whose direction means nothing) and not parallel, off the
  // degenerate edges.
  const double mu = du.Magnitude(), mv = dv.Magnitude();
  if (mu > 1e-7 * meanLu_ && mv > 1e-7 * meanLv_ && m > 1e-10 * mu * mv && !onDegenerateRow(u, v)) {
    n = gp_Dir(c);
    return true;
  }
  return false;
}

bool SurfaceEval::normalJumps(double ua, double va, double ub, double vb, const gp_Dir& na, const gp_Dir& nb) const {
  if (na.Dot(nb) >= 0) return false;
  double t0 = 0, t1 = 1;
  gp_Dir n0 = na, n1 = nb;
  for (int k = 0; k < kJumpBisections; ++k) {
    const double t = 0.5 * (t0 + t1);
    gp_Pnt p;
    gp_Dir n;
    // The Jacobian vanishes on a fold line itself; met early, it may be a pole between the ends
    // instead (a pinch: its row collapses to the point). Not by the count alone: on a segment as
    // short as a fuzzed sheet's near where its fold runs into a pole (1e-8 in (u, v) at u = -1000),
    // the fold's own singular band is met within a few steps, and the angle split such segments on
    // and on (4048 of a level's 12.8k splits; 27k triangles on a sheet 1e-3 wide).
    const double u = ua + t * (ub - ua), v = va + t * (vb - va);
    if (!regularNormal(u, v, p, n))
      return k >= kJumpBisections / 2 || !pinches(u, v, ub - ua, vb - va, gp_Vec(n0));
    if (n.Dot(n0) < n.Dot(n1)) {  // the first half turns further
      t1 = t, n1 = n;
    } else {
      t0 = t, n0 = n;
    }
    if (n0.Dot(n1) >= 0) return false;  // the turn divides: the surface bends
  }
  return true;
}

bool SurfaceEval::foldAt(double u, double v, double ua, double va, double ub, double vb) const {
  // A fold of the parametrisation: Su and Sv (nearly) parallel there, or the area element (nearly)
  // vanishing against the ends'. A sheet bending over as sharply with its parametrisation regular
  // (occ/terrain's rim, the bottle's neck: sines 0.9-1, area elements 0.3 of the ends' or more) is
  // left to the angle, which refines it.
  gp_Pnt p;
  gp_Vec du, dv;
  d1(u, v, p, du, dv);
  const double area = du.Crossed(dv).Magnitude();
  if (area < kFoldSine * du.Magnitude() * dv.Magnitude()) return true;
  d1(ua, va, p, du, dv);
  const double areaA = du.Crossed(dv).Magnitude();
  d1(ub, vb, p, du, dv);
  const double areaB = du.Crossed(dv).Magnitude();
  return area < kFoldArea * std::max(areaA, areaB);
}

bool SurfaceEval::findFold(double ua, double va, double ub, double vb, const gp_Dir& na, const gp_Dir& nb,
                           double angleRad, double& at, gp_Dir& before, gp_Dir& after) const {
  if (na.Dot(nb) >= 0) return false;
  // Too short for the parameters' resolution to locate the fold on it (a fuzzed face 1e-3 wide at
  // u, v = -1000, where the bisection's last steps fall below the coordinates' rounding and its
  // points were placed by noise: its fold points fed refinement beside them, 226 -> 37320
  // triangles).
  const double magnitude = std::max({std::abs(ua), std::abs(va), std::abs(ub), std::abs(vb)});
  if (std::hypot(ub - ua, vb - va) < kFoldResolution * magnitude) return false;
  const gp_Vec towardsA = gp_Vec(na) - gp_Vec(nb);
  gp_Pnt p;
  gp_Dir n;
  // The middle of the turn: where the normal is as near to nb as to na (positive towards a). Whether
  // it is a fold is asked after kFoldProbe steps, before the rest: most segments asked turn over
  // as a regular surface bends (occ/terrain's rim asks thousands), and the answer holds that near.
  double t0 = 0, t1 = 1;
  for (int k = 0; k < kFoldBisections; ++k) {
    if (k == kFoldProbe &&
        !foldAt(ua + 0.5 * (t0 + t1) * (ub - ua), va + 0.5 * (t0 + t1) * (vb - va), ua, va, ub, vb))
      return false;
    const double t = 0.5 * (t0 + t1);
    if (!regularNormal(ua + t * (ub - ua), va + t * (vb - va), p, n)) {  // Su x Sv vanishes: the fold itself
      t0 = t1 = t;
      break;
    }
    (gp_Vec(n).Dot(towardsA) > 0 ? t0 : t1) = t;
  }
  at = 0.5 * (t0 + t1);
  if (pinches(ua + at * (ub - ua), va + at * (vb - va), ub - ua, vb - va, gp_Vec(na) - gp_Vec(nb)))
    return false;
  // The normals shown on either side of the fold: the nearest pair of points either side of it
  // between which the normal makes the segment's whole turn (within the angle), a step along the
  // derivative's kernel (straight across the fold: along a segment that crosses it at a slant, the
  // turn spreads along it), else along the segment; from there further out, where they have settled
  // (each within kSettledRad of the normal twice as far out), at most an eighth of the segment's
  // length away. At the turn's end they can still be most of the angle from the side's (a coarse
  // level's angle is wide), and the angle rule then halved edges towards the fold point without end.
  const double turn = na.Angle(nb) - angleRad;
  const double fu = ua + at * (ub - ua), fv = va + at * (vb - va), length = std::hypot(ub - ua, vb - va);
  double ku = 0, kv = 0;
  const bool across = kernel(fu, fv, ku, kv);
  for (const bool alongKernel : {true, false}) {
    if (alongKernel && !across) continue;
    const double stepU = alongKernel ? ku * length : ub - ua, stepV = alongKernel ? kv * length : vb - va;
    // The normals at 2^-k of (stepU, stepV) before and after the fold point (at the segment's ends, theirs).
    const auto normalsAt = [&](int k, gp_Dir& n0, gp_Dir& n1) {
      const double d = std::ldexp(1.0, -k);
      n0 = na, n1 = nb;
      if (alongKernel)
        return regularNormal(fu - d * stepU, fv - d * stepV, p, n0) &&
               regularNormal(fu + d * stepU, fv + d * stepV, p, n1);
      const double ta = std::max(0.0, at - d), tb = std::min(1.0, at + d);
      return (ta <= 0 || regularNormal(ua + ta * (ub - ua), va + ta * (vb - va), p, n0)) &&
             (tb >= 1 || regularNormal(ua + tb * (ub - ua), va + tb * (vb - va), p, n1));
    };
    for (int k = kFoldBisections; k >= kFoldReach; --k) {
      gp_Dir n0, n1;
      if (!normalsAt(k, n0, n1) || n0.Angle(n1) < turn) continue;
      for (; k > kFoldReach; --k) {
        gp_Dir m0, m1;
        if (!normalsAt(k - 1, m0, m1)) break;
        if (n0.Angle(m0) <= kSettledRad && n1.Angle(m1) <= kSettledRad) break;
        n0 = m0, n1 = m1;
      }
      const bool swap = n0.Dot(na) - n0.Dot(nb) < n1.Dot(na) - n1.Dot(nb);  // the kernel may point towards a
      before = swap ? n1 : n0, after = swap ? n0 : n1;
      return true;
    }
  }
  return false;
}

bool SurfaceEval::kernel(double u, double v, double& ku, double& kv, double* smallerOverLarger) const {
  gp_Pnt p;
  gp_Vec du, dv;
  d1(u, v, p, du, dv);
  const double a = du.SquareMagnitude(), b = du.Dot(dv), c = dv.SquareMagnitude();
  const double smaller = std::max(0.0, 0.5 * (a + c) - std::sqrt(0.25 * (a - c) * (a - c) + b * b));
  ku = b, kv = smaller - a;  // (G - smaller I) k = 0
  if (std::abs(ku) + std::abs(kv) <= 1e-300) ku = c - smaller, kv = -b;
  const double n = std::hypot(ku, kv);
  if (!(n > 1e-300)) return false;
  ku /= n, kv /= n;
  if (smallerOverLarger) *smallerOverLarger = std::sqrt(smaller / std::max(a + c - smaller, 1e-300));
  return true;
}

bool SurfaceEval::pinches(double u, double v, double du, double dv, const gp_Vec& side) const {
  // The signed area element, positive on the side of `side`.
  const auto area = [&](double x, double y) {
    gp_Pnt p;
    gp_Vec su1, sv1;
    d1(x, y, p, su1, sv1);
    return su1.Crossed(sv1).Dot(side);
  };
  double ku = 0, kv = 0, ratio = 1;
  if (!kernel(u, v, ku, kv, &ratio)) return false;
  const double step = 1e-3 * std::hypot(du, dv);
  ku *= step, kv *= step;
  const double eu = -kv, ev = ku;  // across the kernel, as far
  const double along = std::abs(area(u + ku, v + kv)) + std::abs(area(u - ku, v - kv));
  const double across = std::abs(area(u + eu, v + ev)) + std::abs(area(u - eu, v - ev));
  return along < kPinch * across && ratio < kCollapsed;
}

bool SurfaceEval::pointNormal(double u, double v, gp_Pnt& p, gp_Dir& n) const {
  if (regularNormal(u, v, p, n)) return true;
  gp_Vec du, dv;
  gp_Dir estimated;
  if (geom_.IsNull()) geom_ = BRep_Tool::Surface(face_);  // located: a copy when the face has a location
  if (GeomLib::NormEstim(geom_, gp_Pnt2d(u, v), 1e-7, estimated) <= 1) {
    n = estimated;
    return false;
  }
  // Last resort: the normal a small step towards the middle of the face's parameter box.
  const double um = 0.5 * (uMin + uMax), vm = 0.5 * (vMin + vMax);
  for (double f : {1e-6, 1e-4, 1e-2}) {
    gp_Pnt q;
    d1(u + f * (um - u), v + f * (vm - v), q, du, dv);
    const gp_Vec c2 = du.Crossed(dv);
    if (c2.Magnitude() > 1e-300) {
      n = gp_Dir(c2);
      return false;
    }
  }
  n = gp_Dir(0, 0, 1);
  return false;
}

double SurfaceEval::project(const gp_Pnt& m, double& u, double& v, int maxIter, double* start) const {
  bool clamped = false;
  double d = projectFrom(m, u, v, maxIter, start, clamped);
  // Stopped against a parameter bound of a surface periodic in the other direction (a sphere's
  // pole): the foot may lie across the pole, half a period round.
  if (clamped && (uPeriodic_ || vPeriodic_)) {
    double u2 = uPeriodic_ ? u + 0.5 * surface_.UPeriod() : u, v2 = vPeriodic_ ? v + 0.5 * surface_.VPeriod() : v;
    bool again = false;
    const double d2 = projectFrom(m, u2, v2, maxIter, nullptr, again);
    if (d2 < d) d = d2, u = u2, v = v2;
  }
  return d;
}

void SurfaceEval::triangleBox(const double cu[3], const double cv[3], double box[4]) const {
  const double lowU = std::min({cu[0], cu[1], cu[2]}), highU = std::max({cu[0], cu[1], cu[2]});
  const double lowV = std::min({cv[0], cv[1], cv[2]}), highV = std::max({cv[0], cv[1], cv[2]});
  box[0] = std::min(uPeriodic_ ? uMin : su0_, lowU), box[1] = std::max(uPeriodic_ ? uMax : su1_, highU);
  box[2] = std::min(vPeriodic_ ? vMin : sv0_, lowV), box[3] = std::max(vPeriodic_ ? vMax : sv1_, highV);
}

double SurfaceEval::projectDamped(const gp_Pnt& m, double& u, double& v, int maxIter, const double* box) const {
  gp_Pnt s;
  gp_Vec du, dv;
  d1(u, v, s, du, dv);
  double d = s.Distance(m);
  double lambda = 1e-3;
  for (int it = 0; it < maxIter && d > 0; ++it) {
    const gp_Vec r(s, m);
    const double a = du.Dot(du), b = du.Dot(dv), c = dv.Dot(dv);
    const double ru = r.Dot(du), rv = r.Dot(dv);
    // Stationary: the residual is normal to the surface (up to rounding).
    if (std::abs(ru) <= 1e-12 * d * std::sqrt(a) && std::abs(rv) <= 1e-12 * d * std::sqrt(c)) break;
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      const double da = a + lambda * (a + 1e-300), dc = c + lambda * (c + 1e-300);
      const double det = da * dc - b * b;
      if (!(det > 0)) {
        lambda *= 4;
        continue;
      }
      double nu = u + (ru * dc - rv * b) / det, nv = v + (da * rv - b * ru) / det;
      if (box) {
        nu = std::clamp(nu, box[0], box[1]), nv = std::clamp(nv, box[2], box[3]);
      } else {
        if (!uPeriodic_) nu = std::clamp(nu, su0_, su1_);
        if (!vPeriodic_) nv = std::clamp(nv, sv0_, sv1_);
      }
      gp_Pnt s2;
      gp_Vec du2, dv2;
      d1(nu, nv, s2, du2, dv2);
      const double d2 = s2.Distance(m);
      if (d2 < d) {
        u = nu, v = nv, s = s2, du = du2, dv = dv2, d = d2;
        lambda = std::max(lambda / 3, 1e-9);
        improved = true;
      } else {
        lambda *= 4;
      }
    }
    if (!improved) break;
  }
  return d;
}

double SurfaceEval::projectOnce(const gp_Pnt& m, double u, double v, double* start, double enough) const {
  if (elementary_.valid()) {
    if (start) *start = point(u, v).Distance(m);
    return elementary_(m);
  }
  bool clamped = false;
  return projectFrom(m, u, v, 3, start, clamped, 0.1, enough);
}

double SurfaceEval::projectFrom(const gp_Pnt& m, double& u, double& v, int maxIter, double* start, bool& clamped,
                                double settle, double enough) const {
  gp_Pnt s;
  gp_Vec du, dv;
  if (direct_ && enough > 0) {
    // Most samples are already within `enough` at their own (u, v): the point alone decides, and
    // only the others need the derivatives. (The direct evaluation's point is the same to the last
    // bit with or without them, in the spans d1() takes: faceSideD1.)
    const int uSpan = u >= uMax ? direct_->uSpanBelow(u) : direct_->uSpan(u);
    const int vSpan = v >= vMax ? direct_->vSpanBelow(v) : direct_->vSpan(v);
    const double d = gp_Vec(direct_->value(u, v, uSpan, vSpan), m).Magnitude();
    if (start) *start = d;
    if (d <= enough) return d;
  }
  double best = 1e300, bu = u, bv = v;
  for (int it = 0; it <= maxIter; ++it) {
    d1(u, v, s, du, dv);
    const gp_Vec r(s, m);
    const double d = r.Magnitude();
    if (it == 0 && start) *start = d;
    if (it == 0 && d <= enough) return d;
    if (d < best) best = d, bu = u, bv = v;
    if (it == maxIter || d == 0) break;
    // Gauss-Newton: [Su.Su Su.Sv; Su.Sv Sv.Sv] (du dv) = (r.Su, r.Sv), lightly damped for poles.
    const double a = du.Dot(du), b = du.Dot(dv), c = dv.Dot(dv);
    const double ru = r.Dot(du), rv = r.Dot(dv);
    const double damp = 1e-12 * (a + c) + 1e-300;
    const double det = (a + damp) * (c + damp) - b * b;
    if (!(std::abs(det) > 0)) break;
    double stepU = (ru * (c + damp) - rv * b) / det, stepV = ((a + damp) * rv - b * ru) / det;
    // Stop when the step moves the foot point by a negligible fraction of the residual.
    const double move = (stepU * du + stepV * dv).Magnitude();
    u += stepU, v += stepV;
    if (!uPeriodic_ && (u < su0_ || u > su1_)) u = std::clamp(u, su0_, su1_), clamped = true;
    if (!vPeriodic_ && (v < sv0_ || v > sv1_)) v = std::clamp(v, sv0_, sv1_), clamped = true;
    if (move < settle * d) {
      const gp_Pnt s2 = point(u, v);
      const double d2 = s2.Distance(m);
      if (d2 < best) best = d2, bu = u, bv = v;
      break;
    }
  }
  u = bu, v = bv;
  return best;
}

}  // namespace cetview::brep
