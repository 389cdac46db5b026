// Writes the OpenCASCADE-made files of the bad-input corpus (tests/hardening/corpus): shapes a real
// user's file can contain and the mesher must survive. The corpus is committed; this program is how
// it was made (build target make_bad_corpus, run: make_bad_corpus tests/hardening/corpus).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Geom2d_Curve.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>

namespace {

std::string dir;

void writeBrep(const TopoDS_Shape& shape, const std::string& name) {
  const std::string path = dir + "/" + name;
  if (!BRepTools::Write(shape, path.c_str())) std::fprintf(stderr, "cannot write %s\n", path.c_str());
}

// A part with a through-hole: the good geometry every mixed case carries next to its bad face.
TopoDS_Shape holedBlock() {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 15, -1), gp::DZ()), 6, 22).Shape();
  return BRepAlgoAPI_Cut(block, hole).Shape();
}

TopoDS_Compound withBlock(const TopoDS_Shape& bad) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, holedBlock());
  b.Add(c, bad);
  return c;
}

TopoDS_Face planarFace(std::initializer_list<gp_Pnt> points) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const gp_Pnt& p : points) polygon.Add(p);
  polygon.Close();
  // An explicit plane: the wire alone may define none (collinear) or cross itself.
  return BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 50), gp::DZ()), polygon.Wire(), Standard_True).Face();
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_bad_corpus DIR\n");
    return 2;
  }
  dir = argv[1];

  // A cylinder face whose edges lost their pcurves (as exporters that drop them write it).
  {
    TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(60, 0, 0), gp::DZ()), 8, 25).Shape();
    BRep_Builder b;
    for (TopExp_Explorer f(cylinder, TopAbs_FACE); f.More(); f.Next()) {
      const TopoDS_Face& face = TopoDS::Face(f.Current());
      for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        b.UpdateEdge(TopoDS::Edge(e.Current()), Handle(Geom2d_Curve)(), face, 1e-7);
      }
      break;  // the lateral face only
    }
    writeBrep(withBlock(cylinder), "missing_pcurves.brep");
  }
  // A planar face whose wire has no area (its corners are collinear).
  writeBrep(withBlock(planarFace({gp_Pnt(0, 0, 50), gp_Pnt(10, 0, 50), gp_Pnt(20, 0, 50)})), "zero_area_face.brep");
  // A planar face whose wire crosses itself (a bow tie).
  writeBrep(withBlock(planarFace({gp_Pnt(0, 0, 50), gp_Pnt(20, 20, 50), gp_Pnt(20, 0, 50), gp_Pnt(0, 30, 50)})),
            "self_intersecting_wire.brep");
  // A block far beyond any real part (1e90 model units).
  // (OpenCASCADE treats 2e100 as infinite and its booleans give up far sooner: a plain block.)
  writeBrep(BRepPrimAPI_MakeBox(gp_Pnt(1e90, 0, 0), 4e90, 3e90, 2e90).Shape(), "huge_coordinates.brep");
  // A STEP file cut off in the middle of its DATA section.
  {
    const std::string full = dir + "/full.step.tmp";
    STEPControl_Writer writer;
    writer.Transfer(holedBlock(), STEPControl_AsIs);
    writer.Write(full.c_str());
    const std::string text = readAll(full);
    std::remove(full.c_str());
    std::ofstream(dir + "/truncated.step", std::ios::binary) << text.substr(0, text.size() * 6 / 10);
  }
  // An IGES file cut off in its parameter section.
  {
    const std::string full = dir + "/full.iges.tmp";
    IGESControl_Writer writer("MM", 1);
    writer.AddShape(holedBlock());
    writer.ComputeModel();
    writer.Write(full.c_str());
    const std::string text = readAll(full);
    std::remove(full.c_str());
    std::ofstream(dir + "/truncated.iges", std::ios::binary) << text.substr(0, text.size() / 2);
  }
  // A vertex and its edge's curve with a NaN coordinate (a broken exporter's .brep).
  {
    std::string text;
    {
      const std::string full = dir + "/nan.brep.tmp";
      BRepTools::Write(holedBlock(), full.c_str());
      text = readAll(full);
      std::remove(full.c_str());
    }
    const std::size_t at = text.find("\n40 0 0");
    if (at != std::string::npos) text.replace(at + 1, 7, "40 nan 0");
    std::ofstream(dir + "/nan_coordinate.brep", std::ios::binary) << text;
  }
  return 0;
}
