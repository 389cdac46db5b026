// The built-in demo part: a machined bracket built with OpenCASCADE's modelling API. It carries every
// surface type the tessellator handles, in the places a real part has them:
//   plate (planes) with rounded vertical edges (cylinders, no seam) and four through-holes (cylinders
//   with seams); a boss (cylinder) blended into the plate (torus) with a drilled blind hole ending in a
//   118-degree drill point (cone with its apex); a bell-shaped post revolved from a B-spline profile that
//   touches its axis (surface of revolution with a pole); a lug extruded from a closed spline outline
//   (surface of linear extrusion) with a hole; a lofted lever arm (B-spline surface) ending in a ball
//   knob (sphere with both poles, its seam on the far side).
#include <cmath>
#include <stdexcept>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeEllipse.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>

#include "model_impl.h"

namespace cetview::brep {
namespace {

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Fuse op(a, b);
  if (!op.IsDone()) throw std::runtime_error("demo part: fuse failed");
  return op.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone()) throw std::runtime_error("demo part: cut failed");
  return op.Shape();
}

Handle(Geom_BSplineCurve) interpolate(const std::vector<gp_Pnt>& points, bool periodic) {
  Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, static_cast<int>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) pts->SetValue(static_cast<int>(i) + 1, points[i]);
  GeomAPI_Interpolate interp(pts, periodic, 1e-7);
  interp.Perform();
  if (!interp.IsDone()) throw std::runtime_error("demo part: spline interpolation failed");
  return interp.Curve();
}

// Plate with its four vertical edges rounded.
TopoDS_Shape roundedPlate() {
  TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 120, 80, 12).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge)), b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
    if (a.X() == b.X() && a.Y() == b.Y()) fillet.Add(10.0, edge);
  }
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("demo part: plate fillet failed");
  return fillet.Shape();
}

// Blends the circular edge where the boss (radius 18 at (35, 40)) meets the plate top (z = 12).
TopoDS_Shape blendBoss(const TopoDS_Shape& body) {
  BRepFilletAPI_MakeFillet fillet(body);
  int added = 0;
  for (TopExp_Explorer e(body, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    Standard_Real f, l;
    Handle(Geom_Curve) c = BRep_Tool::Curve(edge, f, l);
    Handle(Geom_Circle) circle = Handle(Geom_Circle)::DownCast(c);
    if (circle.IsNull()) continue;
    const gp_Pnt center = circle->Location();
    if (std::abs(circle->Radius() - 18) < 1e-6 && std::abs(center.Z() - 12) < 1e-6) {
      fillet.Add(4.0, edge);
      ++added;
    }
  }
  if (added == 0) throw std::runtime_error("demo part: boss edge not found");
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("demo part: boss fillet failed");
  return fillet.Shape();
}

// A bell revolved about the vertical axis through (95, 55) from a B-spline profile that reaches the
// axis horizontally at the top (a pole of the surface of revolution).
TopoDS_Shape revolvedPost() {
  const double cx = 95, cy = 55;
  std::vector<gp_Pnt> profile = {gp_Pnt(cx, cy, 34), gp_Pnt(cx + 4, cy, 33), gp_Pnt(cx + 7.5, cy, 28),
                                 gp_Pnt(cx + 9, cy, 20), gp_Pnt(cx + 11, cy, 11)};
  Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, static_cast<int>(profile.size()));
  for (std::size_t i = 0; i < profile.size(); ++i) pts->SetValue(static_cast<int>(i) + 1, profile[i]);
  GeomAPI_Interpolate interp(pts, false, 1e-7);
  interp.Load(gp_Vec(1, 0, 0), gp_Vec(0.3, 0, -1));  // horizontal at the pole: a smooth dome
  interp.Perform();
  if (!interp.IsDone()) throw std::runtime_error("demo part: profile interpolation failed");
  BRepBuilderAPI_MakeWire wire;
  wire.Add(BRepBuilderAPI_MakeEdge(interp.Curve()).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(cx + 11, cy, 11), gp_Pnt(cx, cy, 11)).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(gp_Pnt(cx, cy, 11), gp_Pnt(cx, cy, 34)).Edge());
  TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), Standard_True).Face();
  return BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(cx, cy, 0), gp::DZ()), 2 * M_PI).Shape();
}

// A lug extruded from a closed spline outline, standing on the plate.
TopoDS_Shape extrudedLug() {
  Handle(Geom_BSplineCurve) outline =
      interpolate({gp_Pnt(75, 10, 11), gp_Pnt(86, 7, 11), gp_Pnt(97, 10, 11), gp_Pnt(99, 17, 11),
                   gp_Pnt(90, 22, 11), gp_Pnt(80, 21, 11), gp_Pnt(73, 16, 11)},
                  true);
  TopoDS_Wire wire = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(outline).Edge()).Wire();
  TopoDS_Face face = BRepBuilderAPI_MakeFace(wire, Standard_True).Face();
  return BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 8)).Shape();
}

// Lever arm lofted from an ellipse inside the boss to a small circle, ending in a ball knob.
TopoDS_Shape leverWithBall() {
  gp_Elips ellipse(gp_Ax2(gp_Pnt(25, 40, 28), gp::DX(), gp::DY()), 6, 4);
  gp_Circ circle(gp_Ax2(gp_Pnt(-25, 40, 28), gp::DX()), 3);
  TopoDS_Wire w0 = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(ellipse).Edge()).Wire();
  TopoDS_Wire w1 = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
  BRepOffsetAPI_ThruSections loft(Standard_True, Standard_False);
  loft.AddWire(w0);
  loft.AddWire(w1);
  loft.Build();
  if (!loft.IsDone()) throw std::runtime_error("demo part: loft failed");
  // The sphere's seam faces -x, away from where the arm joins; its poles stay whole.
  TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Ax2(gp_Pnt(-31, 40, 28), gp::DZ(), -gp::DX()), 7).Shape();
  return fuse(loft.Shape(), ball);
}

TopoDS_Shape drill(double x, double y, double radius, double zBottom, double zTop) {
  gp_Ax2 axis(gp_Pnt(x, y, zBottom), gp::DZ());
  return BRepPrimAPI_MakeCylinder(axis, radius, zTop - zBottom).Shape();
}

// A blind hole with a 118-degree drill point whose apex is the cone's apex.
TopoDS_Shape blindHole(double x, double y, double radius, double zFloor, double zTop) {
  const double tip = radius / std::tan(59.0 * M_PI / 180.0);
  TopoDS_Shape bore = drill(x, y, radius, zFloor, zTop);
  TopoDS_Shape point = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(x, y, zFloor - tip), gp::DZ()), 0, radius, tip).Shape();
  return fuse(bore, point);
}

}  // namespace

TopoDS_Shape buildDemoPart() {
  TopoDS_Shape body = roundedPlate();
  body = fuse(body, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(35, 40, 12), gp::DZ()), 18, 26).Shape());
  body = blendBoss(body);
  body = fuse(body, revolvedPost());
  body = fuse(body, extrudedLug());
  body = fuse(body, leverWithBall());
  body = cut(body, blindHole(35, 40, 7, 18, 39));
  const double holes[4][2] = {{12, 12}, {108, 12}, {12, 68}, {108, 68}};
  for (const auto& h : holes) body = cut(body, drill(h[0], h[1], 4, -1, 13));
  body = cut(body, drill(86, 15, 2.5, -1, 20));
  return body;
}

}  // namespace cetview::brep
