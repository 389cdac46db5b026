// Export of the final meshes through OpenCASCADE's own writers: the triangulations are attached to
// the model's faces as Poly_Triangulation, so every writer sees them as it would BRepMesh's.
#include "brep/export.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message_ProgressRange.hxx>
#include <Poly_Triangulation.hxx>
#include <RWGltf_CafWriter.hxx>
#include <RWMesh_CoordinateSystem.hxx>
#include <RWObj_CafWriter.hxx>
#include <Standard_Failure.hxx>
#include <StlAPI_Writer.hxx>
#include <TColStd_IndexedDataMapOfStringString.hxx>
#include <TDataStd_Name.hxx>
#include <TopTools_FormatVersion.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "brep/tessellator.h"
#include "file_extension.h"
#include "model_impl.h"

namespace cetview::brep {
namespace {


// The face's last level as a Poly_Triangulation in the face's own frame: referenced vertices only,
// natural orientation (the FaceMesh is oriented by the face, the triangulation by the surface).
Handle(Poly_Triangulation) toTriangulation(const FaceMesh& m, const TopoDS_Face& face, bool reversed) {
  if (m.levels.empty() || m.levels.back().empty()) return nullptr;
  const std::vector<std::uint32_t>& idx = m.levels.back();
  std::vector<int> remap(m.vertexCount(), 0);
  int nodes = 0;
  for (std::uint32_t v : idx)
    if (remap[v] == 0) remap[v] = ++nodes;
  Handle(Poly_Triangulation) tri = new Poly_Triangulation(nodes, static_cast<int>(idx.size() / 3), Standard_True, Standard_True);
  const gp_Trsf toFace = face.Location().Transformation().Inverted();
  const float sign = reversed ? -1.0f : 1.0f;
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == 0) continue;
    tri->SetNode(remap[v], gp_Pnt(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]).Transformed(toFace));
    tri->SetUVNode(remap[v], gp_Pnt2d(m.uv[2 * v], m.uv[2 * v + 1]));
    gp_Dir n(sign * m.normals[3 * v], sign * m.normals[3 * v + 1], sign * m.normals[3 * v + 2]);
    tri->SetNormal(remap[v], n.Transformed(toFace));
  }
  for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
    const int a = remap[idx[t]], b = remap[idx[t + 1]], c = remap[idx[t + 2]];
    tri->SetTriangle(static_cast<int>(t / 3) + 1, reversed ? Poly_Triangle(a, c, b) : Poly_Triangle(a, b, c));
  }
  return tri;
}

Handle(TDocStd_Document) documentFor(const ModelImpl& m) {
  if (!m.doc.IsNull()) return m.doc;
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label label = shapes->AddShape(m.root, Standard_True);
  const std::string name = m.parts.size() == 1 ? m.parts.front().name : m.source;
  TDataStd_Name::Set(label, TCollection_ExtendedString(name.c_str(), Standard_True));
  return doc;
}

}  // namespace

bool exportFormatSupported(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == "brep" || ext == "glb" || ext == "gltf" || ext == "obj" || ext == "stl";
}

std::string exportModel(const Tessellator& t, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (!exportFormatSupported(path)) return path + ": unknown output format (use .brep, .glb, .gltf, .obj or .stl)";
  ModelImpl& m = t.model().impl();
  bool anyTriangle = false;
  for (FaceId f = 0; f < m.faceShapes.size() && !anyTriangle; ++f) {
    const FaceMesh& mesh = t.faceMesh(f);
    anyTriangle = !mesh.levels.empty() && !mesh.levels.back().empty();
  }
  if (!anyTriangle) return path + ": nothing to write: no face of the model has triangles";
  try {
    BRep_Builder builder;
    for (FaceId f = 0; f < m.faceShapes.size(); ++f) {
      const TopoDS_Face& face = m.faceShapes[f];
      builder.UpdateFace(face, toTriangulation(t.faceMesh(f), face, m.faces[f].reversed));
    }
    bool ok = false;
    if (ext == "brep") {
      ok = BRepTools::Write(m.root, path.c_str(), Standard_True, Standard_True, TopTools_FormatVersion_VERSION_3);
    } else if (ext == "stl") {
      StlAPI_Writer writer;
      writer.ASCIIMode() = Standard_False;
      ok = writer.Write(m.root, path.c_str());
    } else if (ext == "obj") {
      RWObj_CafWriter writer(path.c_str());
      TColStd_IndexedDataMapOfStringString info;
      info.Add("Generator", "cetview");
      const Handle(TDocStd_Document) doc = documentFor(m);
      ok = writer.Perform(doc, info, Message_ProgressRange());
      if (doc != m.doc) XCAFApp_Application::GetApplication()->Close(doc);
    } else {
      RWGltf_CafWriter writer(path.c_str(), ext == "glb");
      // Model units are millimetres (STEP and IGES are read in mm); glTF is in metres, Y up.
      writer.ChangeCoordinateSystemConverter().SetInputLengthUnit(0.001);
      writer.ChangeCoordinateSystemConverter().SetInputCoordinateSystem(RWMesh_CoordinateSystem_Zup);
      TColStd_IndexedDataMapOfStringString info;
      info.Add("Generator", "cetview");
      const Handle(TDocStd_Document) doc = documentFor(m);
      ok = writer.Perform(doc, info, Message_ProgressRange());
      if (doc != m.doc) XCAFApp_Application::GetApplication()->Close(doc);
    }
    if (!ok) return path + ": cannot be written";
  } catch (const Standard_Failure& e) {
    return path + ": writing failed: " + e.GetMessageString();
  }
  return {};
}

}  // namespace cetview::brep
