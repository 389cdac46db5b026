#include "brepmesh_fallback.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "surface_eval.h"

namespace cetview::brep {

bool meshFaceWithBRepMesh(const TopoDS_Face& forwardFace, bool reversed, double chordal, double angle,
                          FaceMesh& mesh, std::vector<std::uint32_t>& indices, std::string& failure) {
  try {
    // A copy: BRepMesh stores polygons on the edges it meshes, and the originals are shared with
    // faces other threads are meshing.
    BRepBuilderAPI_Copy copier(forwardFace, Standard_True, Standard_False);
    const TopoDS_Face face = TopoDS::Face(copier.Shape());
    BRepMesh_IncrementalMesh mesher(face, chordal, Standard_False, angle, Standard_False);
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || tri->NbTriangles() == 0) {
      failure = "BRepMesh produced no triangles";
      return false;
    }
    const gp_Trsf trsf = loc.Transformation();
    SurfaceEval eval(face);
    const auto base = static_cast<std::uint32_t>(mesh.vertexCount());
    const double sign = reversed ? -1.0 : 1.0;
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(trsf);
      double u = 0, v = 0;
      if (tri->HasUVNodes()) {
        const gp_Pnt2d uv = tri->UVNode(i);
        u = uv.X(), v = uv.Y();
      } else {
        u = 0.5 * (eval.uMin + eval.uMax), v = 0.5 * (eval.vMin + eval.vMax);
        eval.project(p, u, v, 20);
      }
      gp_Pnt s;
      gp_Dir n;
      eval.pointNormal(u, v, s, n);
      mesh.positions.insert(mesh.positions.end(), {p.X(), p.Y(), p.Z()});
      mesh.normals.insert(mesh.normals.end(), {static_cast<float>(sign * n.X()), static_cast<float>(sign * n.Y()),
                                               static_cast<float>(sign * n.Z())});
      mesh.uv.insert(mesh.uv.end(), {u, v});
    }
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a, b, c;
      tri->Triangle(i).Get(a, b, c);  // natural orientation of the surface (the face is FORWARD)
      const std::uint32_t A = base + static_cast<std::uint32_t>(a - 1), B = base + static_cast<std::uint32_t>(b - 1),
                          C = base + static_cast<std::uint32_t>(c - 1);
      if (reversed) {
        indices.insert(indices.end(), {A, C, B});
      } else {
        indices.insert(indices.end(), {A, B, C});
      }
    }
    return true;
  } catch (const Standard_Failure& e) {
    failure = std::string("BRepMesh failed: ") + e.GetMessageString();
    return false;
  }
}

}  // namespace cetview::brep
