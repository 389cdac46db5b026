// Export: OpenCASCADE reads the .brep back with a full Poly_Triangulation on every face (nodes, UV
// nodes, normals, natural orientation); the other formats are written with content.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "brep/export.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Export : public ::testing::Test {
 protected:
  void SetUp() override {
    LoadResult r = loadModel("demo");
    ASSERT_TRUE(r) << r.error;
    model_ = std::move(r.model);
    MeshParams p = test::relative(0.002);
    p.progressive = false;
    tess_ = Tessellator::create(*model_, p).tessellator;
    ASSERT_TRUE(tess_->run(2));
  }
  std::unique_ptr<Model> model_;
  std::unique_ptr<Tessellator> tess_;
};

TEST_F(Export, BrepCarriesTriangulationsOpenCascadeReads) {
  const std::string path = test::tempPath("demo_out.brep");
  ASSERT_EQ(exportModel(*tess_, path), "");
  TopoDS_Shape shape;
  BRep_Builder builder;
  ASSERT_TRUE(BRepTools::Read(shape, path.c_str(), builder));
  std::size_t faces = 0, triangles = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face face = TopoDS::Face(e.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    ASSERT_FALSE(tri.IsNull()) << "face " << faces << " without triangulation";
    EXPECT_TRUE(tri->HasUVNodes());
    EXPECT_TRUE(tri->HasNormals());
    triangles += static_cast<std::size_t>(tri->NbTriangles());
    // Natural orientation: each triangle's normal agrees with the stored (surface) normals.
    BRepAdaptor_Surface surface(TopoDS::Face(face.Oriented(TopAbs_FORWARD)));
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a, b, c;
      tri->Triangle(i).Get(a, b, c);
      const gp_Vec n = gp_Vec(tri->Node(a), tri->Node(b)).Crossed(gp_Vec(tri->Node(a), tri->Node(c)));
      const gp_Vec stored = gp_Vec(tri->Normal(a).XYZ()) + gp_Vec(tri->Normal(b).XYZ()) + gp_Vec(tri->Normal(c).XYZ());
      ASSERT_GT(n.Dot(stored), 0) << "face " << faces << " triangle " << i;
      // The UV node evaluates to the node.
      const gp_Pnt s = surface.Value(tri->UVNode(a).X(), tri->UVNode(a).Y()).Transformed(loc.Transformation().Inverted());
      EXPECT_LT(s.Distance(tri->Node(a)), tess_->chordal()) << "face " << faces;
    }
    ++faces;
  }
  EXPECT_EQ(faces, model_->faces().size());
  EXPECT_EQ(triangles, tess_->triangleCount(tess_->lastLevel()));
}

TEST_F(Export, MeshFormats) {
  for (const char* ext : {"stl", "obj", "glb", "gltf"}) {
    const std::string path = test::tempPath(std::string("demo_out.") + ext);
    ASSERT_EQ(exportModel(*tess_, path), "") << ext;
    const std::string bytes = readAll(path);
    EXPECT_GT(bytes.size(), 1000u) << ext;
    if (std::string(ext) == "obj") {
      EXPECT_NE(bytes.find("\nv "), std::string::npos);
      EXPECT_NE(bytes.find("demo bracket"), std::string::npos);  // the part name
    }
    if (std::string(ext) == "stl") {
      EXPECT_EQ(bytes.size(), 84u + 50u * tess_->triangleCount(tess_->lastLevel()));
    }
  }
}

TEST_F(Export, RefusesUnknownFormatsAndUnwritablePaths) {
  EXPECT_NE(exportModel(*tess_, test::tempPath("x.ply")), "");
  EXPECT_NE(exportModel(*tess_, "/nonexistent_dir/x.stl"), "");
}

}  // namespace
}  // namespace cetview::brep
