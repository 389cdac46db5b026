// Evaluation of a B-spline surface through a table of span caches. OpenCASCADE's adaptor keeps the
// polynomial form of one span and rebuilds it whenever an evaluation falls in another, which is
// nearly every time when refinement visits triangles all over a face of thousands of spans; here
// each span keeps its own slot in a tiled table (neighbouring spans never share one), so a rebuild
// happens only when a far span takes the slot over.
#pragma once

#include <vector>

#include <BSplSLib_Cache.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

namespace cetview::brep {

class SplineSpans {
 public:
  // `surface` untransformed; `trsf` places it (the face's location).
  SplineSpans(const Handle(Geom_BSplineSurface) & surface, const gp_Trsf& trsf);

  void d0(double u, double v, gp_Pnt& p);
  void d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv);

 private:
  const BSplSLib_Cache& spanOf(double u, double v);
  // t moved into the first period [knots.front(), knots.back()) of a periodic direction.
  static double wrap(const std::vector<double>& knots, double period, double t);
  // Index of the span of t (the last one found when t is still in it).
  static int span(const std::vector<double>& knots, double t, int last);

  Handle(Geom_BSplineSurface) surface_;
  gp_Trsf trsf_;
  bool moved_ = false;
  std::vector<double> uKnots_, vKnots_;  // distinct knots, increasing
  double uPeriod_ = 0, vPeriod_ = 0;     // 0 unless periodic
  int tilesU_ = 1, tilesV_ = 1;
  int lastU_ = 0, lastV_ = 0;
  struct Slot {
    Handle(BSplSLib_Cache) cache;
    int u = -1, v = -1;  // the span it holds
  };
  std::vector<Slot> slots_;
};

}  // namespace cetview::brep
