#include "part_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include "bspline_direct.h"

namespace cetview::brep {
namespace {

constexpr double kInfinite = 1e99;  // OpenCASCADE's Precision::Infinite() is 2e100

bool finite(const gp_Pnt& p) {
  return std::abs(p.X()) < kInfinite && std::abs(p.Y()) < kInfinite && std::abs(p.Z()) < kInfinite;
}

// How far p reaches towards side `side` of a box (0-5: axis side / 2, its minimum's side where odd):
// that coordinate, negated on a minimum's side.
double reach(const gp_Pnt& p, int side) { return (side % 2 ? -1.0 : 1.0) * p.Coord(side / 2 + 1); }

// One sampled curve or surface: its best sample towards each of the box's 6 sides, to be sharpened
// by a local search where it may be the part's extreme.
struct Sampled {
  std::function<gp_Pnt(double, double)> value;  // at (t, unused) or (u, v)
  double lo[2] = {0, 0}, hi[2] = {0, 0};         // parameter box
  double step[2] = {0, 0};                       // grid spacing (0: a curve's second parameter)
  std::array<double, 6> best{};                  // reach of the best sample towards each side
  std::array<std::array<double, 2>, 6> at{};     // its parameters
  int dense[2] = {0, 0};  // a B-spline face's grid by its knot spans (segments each way), 0: none finer
};

void sample(Sampled& s, Bounds& bounds, int n0, int n1) {
  s.best.fill(-1e300);
  for (int i = 0; i <= n0; ++i) {
    for (int j = 0; j <= n1; ++j) {
      const double a = n0 ? s.lo[0] + (s.hi[0] - s.lo[0]) * i / n0 : s.lo[0];
      const double b = n1 ? s.lo[1] + (s.hi[1] - s.lo[1]) * j / n1 : s.lo[1];
      const gp_Pnt p = s.value(a, b);
      if (!finite(p)) continue;
      bounds.add(p.X(), p.Y(), p.Z());
      for (int side = 0; side < 6; ++side) {
        if (reach(p, side) > s.best[side]) s.best[side] = reach(p, side), s.at[side] = {a, b};
      }
    }
  }
}

// Pattern search from the best sample towards `side`: each step tries the neighbours at +-h along
// each parameter (and diagonally on a surface), moves to the best one that reaches farther, else
// halves h. Adds the point reached.
void sharpen(const Sampled& s, int side, Bounds& bounds) {
  constexpr int kSteps = 40;
  double a = s.at[side][0], b = s.at[side][1], value = s.best[side];
  double h[2] = {s.step[0], s.step[1]};
  for (int k = 0; k < kSteps; ++k) {
    double bestA = a, bestB = b, bestValue = value;
    for (int da = -1; da <= 1; ++da) {
      for (int db = -1; db <= 1; ++db) {
        if ((da == 0 && db == 0) || (db != 0 && h[1] == 0)) continue;
        const double ta = std::clamp(a + da * h[0], s.lo[0], s.hi[0]);
        const double tb = h[1] == 0 ? b : std::clamp(b + db * h[1], s.lo[1], s.hi[1]);
        const gp_Pnt p = s.value(ta, tb);
        if (finite(p) && reach(p, side) > bestValue) bestA = ta, bestB = tb, bestValue = reach(p, side);
      }
    }
    if (bestValue > value) {
      a = bestA, b = bestB, value = bestValue;
    } else {
      h[0] *= 0.5, h[1] *= 0.5;
    }
  }
  const gp_Pnt p = s.value(a, b);
  if (finite(p)) bounds.add(p.X(), p.Y(), p.Z());
}

bool ruled(GeomAbs_SurfaceType type) {
  return type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone ||
         type == GeomAbs_SurfaceOfExtrusion;
}

// OpenCASCADE's quick box; with a face whose wires cannot bound its surface (a pcurve still missing)
// it can be infinite, and then the edges' box stands for the part.
Bounds quickBounds(const TopoDS_Shape& shape) {
  Bounds bounds;
  Bnd_Box box;
  BRepBndLib::Add(shape, box, Standard_False);
  if (box.IsVoid() || box.IsOpen() || !(box.SquareExtent() < kInfinite * kInfinite)) {
    box.SetVoid();
    for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) BRepBndLib::Add(e.Current(), box, Standard_False);
  }
  if (box.IsVoid() || box.IsOpen()) return bounds;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  if (!finite(gp_Pnt(x0, y0, z0)) || !finite(gp_Pnt(x1, y1, z1))) return bounds;
  bounds.add(x0, y0, z0);
  bounds.add(x1, y1, z1);
  return bounds;
}

}  // namespace

Bounds partBounds(const TopoDS_Shape& shape) {
  Bounds bounds;
  TopTools_IndexedMapOfShape vertices, edges, faces;  // each shared sub-shape once
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  for (int i = 1; i <= vertices.Extent(); ++i) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)));
    if (finite(p)) bounds.add(p.X(), p.Y(), p.Z());
  }
  // The adaptors the samples' functions evaluate (kept alive until the sharpening is done).
  std::vector<std::unique_ptr<BRepAdaptor_Curve>> curves;
  std::vector<std::unique_ptr<BRepAdaptor_Surface>> surfaces;
  std::vector<Sampled> sampled;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    try {
      auto curve = std::make_unique<BRepAdaptor_Curve>(edge);
      Sampled s;
      s.lo[0] = curve->FirstParameter(), s.hi[0] = curve->LastParameter();
      if (!(std::abs(s.lo[0]) < kInfinite && std::abs(s.hi[0]) < kInfinite)) continue;
      s.step[0] = (s.hi[0] - s.lo[0]) / kEdgeSamples;
      const BRepAdaptor_Curve* c = curve.get();
      s.value = [c](double t, double) { return c->Value(t); };
      sample(s, bounds, kEdgeSamples, 0);
      curves.push_back(std::move(curve));
      sampled.push_back(std::move(s));
    } catch (const Standard_Failure&) {
      // no usable curve: its vertices stand for it
    }
  }
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    try {
      auto surface = std::make_unique<BRepAdaptor_Surface>(face, Standard_False);
      if (ruled(surface->GetType())) continue;
      Sampled s;
      BRepTools::UVBounds(face, s.lo[0], s.hi[0], s.lo[1], s.hi[1]);
      // Within the surface's own parameters (a wire's pcurve may overshoot them).
      s.lo[0] = std::max(s.lo[0], surface->FirstUParameter()), s.hi[0] = std::min(s.hi[0], surface->LastUParameter());
      s.lo[1] = std::max(s.lo[1], surface->FirstVParameter()), s.hi[1] = std::min(s.hi[1], surface->LastVParameter());
      if (!(s.lo[0] <= s.hi[0] && s.lo[1] <= s.hi[1]) ||
          !(std::max({std::abs(s.lo[0]), std::abs(s.hi[0]), std::abs(s.lo[1]), std::abs(s.hi[1])}) < kInfinite))
        continue;
      // A B-spline bulges span by span: kSpanSamples segments for each of its knot spans each way
      // over the UV box, up to kMaxGrid points, where its coarse grid comes near a side of the box.
      if (surface->GetType() == GeomAbs_BSplineSurface) {
        const Handle(Geom_BSplineSurface) spline = surface->BSpline();
        s.dense[0] = std::clamp(kSpanSamples * (spline->NbUKnots() - 1), kFaceGrid - 1, kMaxGrid - 1);
        s.dense[1] = std::clamp(kSpanSamples * (spline->NbVKnots() - 1), kFaceGrid - 1, kMaxGrid - 1);
        if (s.dense[0] == kFaceGrid - 1 && s.dense[1] == kFaceGrid - 1) s.dense[0] = s.dense[1] = 0;
      }
      s.step[0] = (s.hi[0] - s.lo[0]) / (kFaceGrid - 1), s.step[1] = (s.hi[1] - s.lo[1]) / (kFaceGrid - 1);
      // A B-spline evaluated from its poles: through the adaptor each sample in a new knot span
      // rebuilt its span cache (A319's box took 11 ms, now 7; MAT's 2.3, now 0.4).
      std::shared_ptr<const BSplineDirect> direct;
      if (surface->GetType() == GeomAbs_BSplineSurface) direct = BSplineDirect::create(surface->BSpline());
      const BRepAdaptor_Surface* f = surface.get();
      if (direct)
        s.value = [direct](double u, double v) { return direct->value(u, v); };
      else
        s.value = [f](double u, double v) { return f->Value(u, v); };
      sample(s, bounds, kFaceGrid - 1, kFaceGrid - 1);
      surfaces.push_back(std::move(surface));
      sampled.push_back(std::move(s));
    } catch (const Standard_Failure&) {
      // no usable surface: its edges stand for it
    }
  }
  if (bounds.empty()) return quickBounds(shape);
  // Samples within kSharpenBand of the diagonal of a side of the box are near enough to reach it.
  const double band = kSharpenBand * bounds.diagonal();
  auto nearSide = [&band](const Sampled& s, const Bounds& box) {
    for (int side = 0; side < 6; ++side)
      if (s.best[side] >= (side % 2 ? -box.min[side / 2] : box.max[side / 2]) - band) return true;
    return false;
  };
  // B-spline faces near a side sampled again by their knot spans (most of a model's faces lie
  // inside its box).
  const Bounds coarseBox = bounds;
  for (Sampled& s : sampled) {
    if (!s.dense[0] || !nearSide(s, coarseBox)) continue;
    try {
      sample(s, bounds, s.dense[0], s.dense[1]);
      s.step[0] = (s.hi[0] - s.lo[0]) / s.dense[0], s.step[1] = (s.hi[1] - s.lo[1]) / s.dense[1];
    } catch (const Standard_Failure&) {
      // the coarse samples stand
    }
  }
  // The samples nearest each side of the box sharpened: the extreme can lie between samples (an
  // arc's middle, a rotated sphere's top, a bump of a B-spline).
  const Bounds sampledBox = bounds;
  for (const Sampled& s : sampled) {
    if (!nearSide(s, sampledBox)) continue;
    for (int side = 0; side < 6; ++side) {
      const double extreme = side % 2 ? -sampledBox.min[side / 2] : sampledBox.max[side / 2];
      if (s.best[side] < extreme - band) continue;
      try {
        sharpen(s, side, bounds);
      } catch (const Standard_Failure&) {
        // the sample stands
      }
    }
  }
  return bounds;
}

}  // namespace cetview::brep
