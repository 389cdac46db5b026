// Indexing of parts into global face and edge ids, and the per-face facts the API exposes.
#include <cstdint>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>

#include "model_impl.h"

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

}  // namespace

EdgeId ModelImpl::edgeId(PartId p, const TopoDS_Shape& edge) const {
  const int local = partEdgeMaps[p].FindIndex(edge);
  return local == 0 ? UINT32_MAX : parts[p].firstEdge + static_cast<EdgeId>(local - 1);
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

std::string finalizeModel(ModelImpl& m) {
  m.partEdgeMaps.resize(m.parts.size());
  for (PartId p = 0; p < m.parts.size(); ++p) {
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
    part.closed = partIsClosed(shape);

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
      const TopoDS_Face& face = TopoDS::Face(faceMap(i));
      FaceInfo info;
      info.part = p;
      BRepAdaptor_Surface surface(face, Standard_False);
      info.kind = kindOf(surface.GetType());
      info.reversed = face.Orientation() == TopAbs_REVERSED;
      GProp_GProps props;
      BRepGProp::SurfaceProperties(face, props, 1e-2);  // 1% is plenty for ordering and statistics
      info.area = props.Mass();
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
    Bnd_Box box;
    BRepBndLib::Add(shape, box, Standard_False);  // the optimal box costs seconds on B-spline models
    if (!box.IsVoid()) {
      double x0, y0, z0, x1, y1, z1;
      box.Get(x0, y0, z0, x1, y1, z1);
      part.bounds.add(x0, y0, z0);
      part.bounds.add(x1, y1, z1);
    }
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
