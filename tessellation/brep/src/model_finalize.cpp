// Indexing of parts into global face and edge ids, and the per-face facts the API exposes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <Geom_Surface.hxx>
#include <gp_Vec2d.hxx>
#include <Bnd_Box.hxx>
#include <ShapeFix_Edge.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>

#include "model_impl.h"
#include "part_bounds.h"

namespace cetview::brep {
namespace {

SurfaceKind kindOf(GeomAbs_SurfaceType t) {
  switch (t) {
    case GeomAbs_Plane: return SurfaceKind::kPlane;
    case GeomAbs_Cylinder: return SurfaceKind::kCylinder;
    case GeomAbs_Cone: return SurfaceKind::kCone;
    case GeomAbs_Sphere: return SurfaceKind::kSphere;
    case GeomAbs_Torus: return SurfaceKind::kTorus;
    case GeomAbs_BezierSurface: return SurfaceKind::kBezier;
    case GeomAbs_BSplineSurface: return SurfaceKind::kBSpline;
    case GeomAbs_SurfaceOfRevolution: return SurfaceKind::kRevolution;
    case GeomAbs_SurfaceOfExtrusion: return SurfaceKind::kExtrusion;
    case GeomAbs_OffsetSurface: return SurfaceKind::kOffset;
    default: return SurfaceKind::kOther;
  }
}

// An edge is closed-ok when it is degenerate, bounds two faces, or is a seam of its one face.
bool partIsClosed(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  if (edgeFaces.IsEmpty()) return false;
  for (int i = 1; i <= edgeFaces.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edgeFaces.FindKey(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& f : edgeFaces(i)) distinct.Add(f);
    if (distinct.Extent() == 2) continue;
    if (distinct.Extent() == 1 && BRep_Tool::IsClosed(edge, TopoDS::Face(distinct(1)))) continue;
    return false;
  }
  return true;
}

// The area of the parameter box the face spans, measured on a 3 x 3 grid of |Su x Sv|: enough to
// order faces largest first, at a few evaluations per face (Gauss integration over the trimmed
// face, BRepGProp, took most of the loading time of a .brep of a few hundred faces).
double estimatedArea(const TopoDS_Face& face, const BRepAdaptor_Surface& surface) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  if (!std::isfinite(u0) || !std::isfinite(u1) || !std::isfinite(v0) || !std::isfinite(v1) || u1 < u0 || v1 < v0) {
    return 0.0;
  }
  double sum = 0;
  try {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        gp_Pnt p;
        gp_Vec du, dv;
        surface.D1(u0 + (u1 - u0) * (i + 0.5) / 3, v0 + (v1 - v0) * (j + 0.5) / 3, p, du, dv);
        sum += du.Crossed(dv).Magnitude();
      }
    }
  } catch (const Standard_Failure&) {
    return 0.0;  // a face the surface cannot evaluate goes last; meshing reports it
  }
  const double area = sum / 9 * (u1 - u0) * (v1 - v0);
  return std::isfinite(area) ? area : 0.0;
}

}  // namespace

EdgeId ModelImpl::edgeId(PartId p, const TopoDS_Shape& edge) const {
  const int local = partEdgeMaps[p].FindIndex(edge);
  return local == 0 ? UINT32_MAX : parts[p].firstEdge + static_cast<EdgeId>(local - 1);
}

// A seam's pair of projected pcurves may come out whole periods away from the surface's domain (u = 2pi
// and 4pi on a cylinder) and the wrong way round (the face's interior must lie on the left of each
// occurrence, in the FORWARD face's UV). Both are put right here.
void fixProjectedSeam(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  const TopoDS_Edge forwardEdge = TopoDS::Edge(edge.Oriented(TopAbs_FORWARD));
  const TopoDS_Edge reversedEdge = TopoDS::Edge(edge.Oriented(TopAbs_REVERSED));
  double first = 0, last = 0, f2 = 0, l2 = 0;
  Handle(Geom2d_Curve) c1 = BRep_Tool::CurveOnSurface(forwardEdge, face, first, last);
  Handle(Geom2d_Curve) c2 = BRep_Tool::CurveOnSurface(reversedEdge, face, f2, l2);
  if (c1.IsNull() || c2.IsNull() || c1 == c2) return;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  surface->Bounds(u0, u1, v0, v1);
  const double mid = 0.5 * (first + last);
  gp_Pnt2d a, b;
  gp_Vec2d along;
  c1->D1(mid, a, along);
  b = c2->Value(mid);
  // The FORWARD edge runs along `along`; its left side is (-along.y, along.x).
  bool swap = false;
  gp_Vec2d shift(0, 0);
  if (surface->IsUPeriodic() && std::abs(std::abs(a.X() - b.X()) - surface->UPeriod()) < 1e-6 * surface->UPeriod()) {
    swap = (b.X() - a.X()) * -along.Y() < 0;
    shift.SetX(-std::round((std::min(a.X(), b.X()) - u0) / surface->UPeriod()) * surface->UPeriod());
  } else if (surface->IsVPeriodic() &&
             std::abs(std::abs(a.Y() - b.Y()) - surface->VPeriod()) < 1e-6 * surface->VPeriod()) {
    swap = (b.Y() - a.Y()) * along.X() < 0;
    shift.SetY(-std::round((std::min(a.Y(), b.Y()) - v0) / surface->VPeriod()) * surface->VPeriod());
  } else {
    return;
  }
  if (!swap && shift.X() == 0 && shift.Y() == 0) return;
  Handle(Geom2d_Curve) m1 = Handle(Geom2d_Curve)::DownCast(c1->Translated(shift));
  Handle(Geom2d_Curve) m2 = Handle(Geom2d_Curve)::DownCast(c2->Translated(shift));
  if (swap) std::swap(m1, m2);
  BRep_Builder().UpdateEdge(forwardEdge, m1, m2, face, BRep_Tool::Tolerance(edge));
  BRep_Builder().Range(forwardEdge, face, first, last);
}

// Edges of `face` without a pcurve on it (exporters that keep only 3D curves write such faces) get
// one projected from their 3D curve, as OpenCASCADE's shape healing does: sound, since the 3D curve
// lies on the surface. Returns the repair for the face's report ("" when none was needed); edges
// whose projection fails stay without, and the face reports that when it is meshed.
std::string addMissingPcurves(const TopoDS_Face& face) {
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  TopTools_IndexedDataMapOfShapeListOfShape uses;  // edge -> its occurrences in the face's wires
  TopExp::MapShapesAndAncestors(forward, TopAbs_EDGE, TopAbs_WIRE, uses);
  int added = 0;
  for (int i = 1; i <= uses.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(uses.FindKey(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    double first = 0, last = 0;
    if (!BRep_Tool::CurveOnSurface(edge, forward, first, last).IsNull()) continue;
    int occurrences = 0;
    for (TopExp_Explorer e(forward, TopAbs_EDGE); e.More(); e.Next()) occurrences += e.Current().IsSame(edge) ? 1 : 0;
    ShapeFix_Edge fix;
    fix.FixAddPCurve(edge, forward, occurrences > 1, BRep_Tool::Tolerance(edge));
    if (BRep_Tool::CurveOnSurface(edge, forward, first, last).IsNull()) continue;
    ++added;
    if (occurrences > 1) fixProjectedSeam(edge, forward);
  }
  if (added == 0) return {};
  return "projected the missing pcurve" + std::string(added > 1 ? "s of " + std::to_string(added) + " edges" : " of an edge") +
         " from the 3D curve";
}

// The surface's own iso curve under a pcurve that runs along one (u or v fixed, the other
// parameter growing at unit speed: a natural-bounds face's rim), parametrised as the pcurve is;
// null for other pcurves. Exact where BRepLib::BuildCurve3d approximates: on a cylinder a circle,
// on a B-spline surface turning round a rational circle, which takes equal segments like the
// face's other rims (edge_table.cpp); approximated, the rim was halved (a cylinder's tube: 88
// triangles against the clean tube's 80).
static Handle(Geom_Curve) isoCurveAlong(const Handle(Geom_Surface)& surface, const Handle(Geom2d_Curve)& pcurve) {
  Handle(Geom2d_Curve) basis = pcurve;
  while (const Handle(Geom2d_TrimmedCurve) trimmed = Handle(Geom2d_TrimmedCurve)::DownCast(basis))
    basis = trimmed->BasisCurve();
  const Handle(Geom2d_Line) line = Handle(Geom2d_Line)::DownCast(basis);
  if (line.IsNull()) return nullptr;
  const gp_Dir2d d = line->Direction();
  const gp_Pnt2d o = line->Location();
  const bool alongU = d.X() == 1 && d.Y() == 0, alongV = d.X() == 0 && d.Y() == 1;
  if (!alongU && !alongV) return nullptr;
  Handle(Geom_Curve) iso = alongU ? surface->VIso(o.Y()) : surface->UIso(o.X());
  const double offset = alongU ? o.X() : o.Y();  // the iso curve's parameter at the pcurve's 0
  if (offset == 0) return iso;
  const Handle(Geom_BSplineCurve) bspline = Handle(Geom_BSplineCurve)::DownCast(iso);
  if (bspline.IsNull()) return nullptr;
  TColStd_Array1OfReal knots(1, bspline->NbKnots());
  bspline->Knots(knots);
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) knots(i) -= offset;
  bspline->SetKnots(knots);
  return Handle(Geom_Curve)(bspline);
}

// Edges of `face` flagged degenerated whose pcurve does not stay on one point of the surface (beyond
// ten times their tolerances and a thousandth of the face: a closed iso row of a periodic surface
// flagged as a pole, BRepCheck's InvalidDegeneratedFlag) are made regular edges, their 3D curve
// built from the pcurve on the surface. Meshed as a pole, such a row puts the whole boundary on one
// point while the surface along it spans a curve: no mesh of the face is then within any tolerance,
// and refinement runs down to its smallest size chasing it. Returns the repair for the face's
// report ("" when none was needed).
std::string fixFalseDegenerateEdges(const TopoDS_Face& face) {
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(forward);
  if (surface.IsNull()) return {};
  int fixed = 0;
  double widest = 0;
  TopTools_IndexedMapOfShape seen;
  for (TopExp_Explorer e(forward, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    if (!BRep_Tool::Degenerated(edge) || seen.Contains(edge)) continue;
    seen.Add(edge);
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, forward, first, last);
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edge, v0, v1);
    if (pcurve.IsNull() || v0.IsNull() || !std::isfinite(first) || !std::isfinite(last)) continue;
    // A true pole keeps its surface row within the tolerances the file gives it.
    const double allowed = 10 * std::max({BRep_Tool::Tolerance(edge), BRep_Tool::Tolerance(v0), Precision::Confusion()});
    const gp_Pnt pole = BRep_Tool::Pnt(v0);
    double spread = 0;
    try {
      constexpr int kSamples = 32;
      for (int i = 0; i <= kSamples; ++i) {
        const gp_Pnt2d uv = pcurve->Value(first + (last - first) * i / kSamples);
        spread = std::max(spread, surface->Value(uv.X(), uv.Y()).Distance(pole));
      }
    } catch (const Standard_Failure&) {
      continue;  // the face reports what it cannot evaluate when it is meshed
    }
    if (!(spread > allowed)) continue;
    // A B-spline's collapsed row is often a micron wide (surface_eval.h): a pole still, whatever the
    // tolerances say. A row spanning a thousandth of the face is not.
    Bnd_Box box;
    BRepBndLib::Add(forward, box, Standard_False);
    if (box.IsVoid() || !(spread > 1e-3 * std::sqrt(box.SquareExtent()))) continue;
    BRep_Builder().Degenerated(edge, Standard_False);
    Handle(Geom_Curve) iso;
    try {
      iso = isoCurveAlong(surface, pcurve);
    } catch (const Standard_Failure&) {
      iso.Nullify();
    }
    if (!iso.IsNull()) {
      BRep_Builder builder;
      builder.UpdateEdge(edge, iso, BRep_Tool::Tolerance(edge));
      builder.Range(edge, first, last, Standard_True);
      builder.SameParameter(edge, Standard_True);
      builder.SameRange(edge, Standard_True);
    } else if (!BRepLib::BuildCurve3d(edge, BRep_Tool::Tolerance(edge))) {
      BRep_Builder().Degenerated(edge, Standard_True);  // left as it was: the face reports the bad row
      continue;
    }
    ++fixed;
    widest = std::max(widest, spread);
  }
  if (fixed == 0) return {};
  char span[32];
  std::snprintf(span, sizeof span, "%.3g", widest);
  return (fixed > 1 ? std::to_string(fixed) + " edges" : std::string("an edge")) + " flagged degenerated but spanning " +
         span + " on the surface: meshed as regular";
}

PartId addPart(ModelImpl& m, const TopoDS_Shape& shape, const std::string& name) {
  PartInfo info;
  info.name = name;
  m.parts.push_back(info);
  m.partShapes.push_back(shape);
  m.subshapeColors.emplace_back();
  return static_cast<PartId>(m.parts.size() - 1);
}

void addInstance(ModelImpl& m, PartId part, const gp_Trsf& placement, const std::string& name,
                 std::vector<std::string> path) {
  InstanceInfo inst;
  inst.part = part;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) inst.transform[static_cast<std::size_t>(r * 4 + c)] = placement.Value(r + 1, c + 1);
  inst.name = name;
  inst.path = std::move(path);
  m.instances.push_back(std::move(inst));
}

std::string finalizeModel(ModelImpl& m, LoadProgress& progress) {
  m.partEdgeMaps.resize(m.parts.size());
  for (PartId p = 0; p < m.parts.size(); ++p) {
    if (progress.cancelled()) return "cancelled";
    PartInfo& part = m.parts[p];
    const TopoDS_Shape& shape = m.partShapes[p];
    TopTools_IndexedMapOfShape faceMap;
    TopExp::MapShapes(shape, TopAbs_FACE, faceMap);
    TopExp::MapShapes(shape, TopAbs_EDGE, m.partEdgeMaps[p]);
    part.firstFace = static_cast<FaceId>(m.faces.size());
    part.faceCount = static_cast<std::uint32_t>(faceMap.Extent());
    part.firstEdge = static_cast<EdgeId>(m.edgeShapes.size());
    part.edgeCount = static_cast<std::uint32_t>(m.partEdgeMaps[p].Extent());
    for (int i = 1; i <= m.partEdgeMaps[p].Extent(); ++i) m.edgeShapes.push_back(TopoDS::Edge(m.partEdgeMaps[p](i)));

    // Colours attached to sub-shapes: a face's own colour, else the colour of a solid/shell holding it.
    NCollection_DataMap<TopoDS_Shape, Color, TopTools_ShapeMapHasher> ownColor, inheritedColor;
    for (const auto& styled : m.subshapeColors[p]) {
      if (styled.first.ShapeType() == TopAbs_FACE) {
        ownColor.Bind(styled.first, styled.second);
      } else if (styled.first.IsSame(shape)) {
        part.color = styled.second;
        part.hasColor = true;
      } else {
        for (TopExp_Explorer f(styled.first, TopAbs_FACE); f.More(); f.Next()) inheritedColor.Bind(f.Current(), styled.second);
      }
    }
    for (int i = 1; i <= faceMap.Extent(); ++i) {
      if (progress.cancelled()) return "cancelled";
      progress.within((p + static_cast<double>(i - 1) / faceMap.Extent()) /
                      static_cast<double>(m.parts.size()));
      const TopoDS_Face& face = TopoDS::Face(faceMap(i));
      std::string repairs = addMissingPcurves(face);
      const std::string rows = fixFalseDegenerateEdges(face);
      if (!rows.empty()) repairs += (repairs.empty() ? "" : "; ") + rows;
      m.loadRepairs.push_back(std::move(repairs));
      FaceInfo info;
      info.part = p;
      BRepAdaptor_Surface surface(face, Standard_False);
      info.kind = kindOf(surface.GetType());
      info.reversed = face.Orientation() == TopAbs_REVERSED;
      info.area = estimatedArea(face, surface);
      info.color = part.color;
      if (const Color* own = ownColor.Seek(face)) {
        info.color = *own;
        info.hasOwnColor = true;
      } else if (const Color* inherited = inheritedColor.Seek(face)) {
        info.color = *inherited;
        info.hasOwnColor = true;
      }
      m.faceShapes.push_back(face);
      m.faces.push_back(info);
    }
    part.closed = partIsClosed(shape);  // after the repairs: an edge may no longer be degenerated
    part.bounds = partBounds(shape);
  }
  if (m.faces.empty()) return "no B-rep faces (only points, curves or tessellated geometry)";
  for (const InstanceInfo& inst : m.instances) {
    const Bounds& b = m.parts[inst.part].bounds;
    if (b.empty() || m.parts[inst.part].faceCount == 0) continue;
    for (int corner = 0; corner < 8; ++corner) {
      const double p[3] = {(corner & 1) ? b.max[0] : b.min[0], (corner & 2) ? b.max[1] : b.min[1],
                           (corner & 4) ? b.max[2] : b.min[2]};
      double w[3];
      for (int r = 0; r < 3; ++r) {
        const double* row = &inst.transform[static_cast<std::size_t>(r * 4)];
        w[r] = row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];
      }
      m.bounds.add(w[0], w[1], w[2]);
    }
  }
  if (m.bounds.empty() || !(m.bounds.diagonal() > 0.0)) return "the model has no extent";
  return {};
}

}  // namespace cetview::brep
