// Loading: every kind of bad input is a returned one-line error, never a crash; good STEP keeps
// names, colours and instances.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "brep/model.h"
#include "test_support.h"

namespace cetview::brep {
namespace {

std::string writeText(const std::string& name, const std::string& text) {
  const std::string path = test::tempPath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

void expectError(const std::string& path, const std::string& fragment) {
  LoadResult r = loadModel(path);
  EXPECT_FALSE(r) << path << " loaded";
  EXPECT_NE(r.error.find(fragment), std::string::npos) << "error was: " << r.error;
  EXPECT_EQ(r.error.find('\n'), std::string::npos) << "more than one line: " << r.error;
}

std::string writeStep(const TopoDS_Shape& shape, const std::string& name) {
  const std::string path = test::tempPath(name);
  STEPControl_Writer writer;
  EXPECT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
  EXPECT_EQ(writer.Write(path.c_str()), IFSelect_RetDone);
  return path;
}

TEST(Load, MissingFile) { expectError(test::tempPath("does_not_exist.step"), "no such file"); }

TEST(Load, EmptyFile) { expectError(writeText("empty.step", ""), "empty file"); }

TEST(Load, Directory) { expectError("/tmp", "directory"); }

// A pipe with no writer: opening it to read would wait for ever (the window would load it for ever).
TEST(Load, PipeOrDevice) {
  const std::string fifo = test::tempPath("model.step");
  ::unlink(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectError(fifo, "not a regular file");
  ::unlink(fifo.c_str());
  expectError("/dev/null", "not a regular file");
}

TEST(Load, NotACadFile) {
  expectError(writeText("notes.txt", "just some text\nnot a model\n"), "not a CAD model");
  expectError(writeText("fake.step", "PK\x03\x04 this is a zip, not STEP"), "not a valid step file");
  std::string binary(5000, '\0');
  for (std::size_t i = 0; i < binary.size(); ++i) binary[i] = static_cast<char>(i * 7919 % 251);
  expectError(writeText("noise.brep", binary), "not a valid brep file");
}

TEST(Load, UnreadableFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads every file";
  const std::string path = writeText("locked.step", "ISO-10303-21;\n");
  ::chmod(path.c_str(), 0);
  expectError(path, "cannot be read");
}

TEST(Load, TruncatedStep) {
  const std::string path = writeStep(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), "box.step");
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string cut = writeText("cut.step", text.substr(0, text.size() / 2));
  LoadResult r = loadModel(cut);
  EXPECT_FALSE(r);  // half a box has no complete face
  EXPECT_FALSE(r.error.empty());
}

TEST(Load, TruncatedBrep) {
  const std::string path = test::tempPath("box.brep");
  auto model = test::loadShape(BRepPrimAPI_MakeBox(1, 2, 3).Shape(), "box_full");
  ASSERT_TRUE(model);
  std::ofstream(path) << "DBRep_DrawableShape\n\nCASCADE Topology V1, (c) Matra-Datavision\nLocations 0\nCurve2ds 3\n1 0 0";
  expectError(path, "not a readable OpenCASCADE .brep file");
}

TEST(Load, StepWithoutFaces) {
  // A STEP file with a wire only: geometry, but no B-rep face to tessellate.
  expectError(writeStep(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(), "wire.step"), "no B-rep faces");
}

TEST(Load, DemoPartHasEverySurfaceKind) {
  LoadResult r = loadModel("demo");
  ASSERT_TRUE(r) << r.error;
  const Model& m = *r.model;
  ASSERT_EQ(m.parts().size(), 1u);
  EXPECT_TRUE(m.parts()[0].closed);
  bool seen[11] = {};
  for (const FaceInfo& f : m.faces()) {
    seen[static_cast<int>(f.kind)] = true;
    EXPECT_GT(f.area, 0.0);
  }
  for (SurfaceKind k : {SurfaceKind::kPlane, SurfaceKind::kCylinder, SurfaceKind::kCone, SurfaceKind::kSphere,
                        SurfaceKind::kTorus, SurfaceKind::kBSpline, SurfaceKind::kRevolution, SurfaceKind::kExtrusion})
    EXPECT_TRUE(seen[static_cast<int>(k)]) << surfaceKindName(k);
  EXPECT_NEAR(m.bounds().diagonal(), 181.1, 5.0);
}

TEST(Load, StepAssemblyKeepsNamesColoursAndInstances) {
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  Handle(XCAFDoc_ColorTool) colors = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  const TDF_Label assembly = shapes->NewShape();
  TDataStd_Name::Set(assembly, "bench");
  const TDF_Label pin = shapes->AddShape(BRepPrimAPI_MakeCylinder(2, 10).Shape(), Standard_False);
  TDataStd_Name::Set(pin, "pin");
  colors->SetColor(pin, Quantity_Color(1, 0, 0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
  gp_Trsf a, b;
  a.SetTranslation(gp_Vec(10, 0, 0));
  b.SetTranslation(gp_Vec(-10, 0, 0));
  shapes->AddComponent(assembly, pin, TopLoc_Location(a));
  shapes->AddComponent(assembly, pin, TopLoc_Location(b));
  shapes->UpdateAssemblies();
  const std::string path = test::tempPath("assembly.step");
  STEPCAFControl_Writer writer;
  ASSERT_TRUE(writer.Transfer(doc, STEPControl_AsIs));
  ASSERT_EQ(writer.Write(path.c_str()), IFSelect_RetDone);

  LoadResult r = loadModel(path);
  ASSERT_TRUE(r) << r.error;
  const Model& m = *r.model;
  ASSERT_EQ(m.parts().size(), 1u) << "a part used twice is loaded once";
  EXPECT_EQ(m.parts()[0].name, "pin");
  EXPECT_TRUE(m.parts()[0].hasColor);
  EXPECT_NEAR(m.parts()[0].color.r, 1.0f, 1e-3);
  EXPECT_NEAR(m.parts()[0].color.g, 0.0f, 1e-3);
  ASSERT_EQ(m.instances().size(), 2u);
  EXPECT_NEAR(m.instances()[0].transform[3] + m.instances()[1].transform[3], 0.0, 1e-9);
  EXPECT_NEAR(std::abs(m.instances()[0].transform[3]), 10.0, 1e-9);
  ASSERT_FALSE(m.instances()[0].path.empty());
  EXPECT_EQ(m.instances()[0].path[0], "bench");
  EXPECT_EQ(m.faces().size(), 3u);  // one cylinder: side, top, bottom
  // The world box spans both instances.
  EXPECT_NEAR(m.bounds().max[0] - m.bounds().min[0], 24.0, 0.5);
}

}  // namespace
}  // namespace cetview::brep
