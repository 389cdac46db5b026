#include "test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Line.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "brep/measure.h"
#include "brep/mesh_check.h"
#include "shape_file.h"

namespace cetview::brep::test {

std::string tempPath(const std::string& name) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/cetview_brep_" + std::to_string(::getpid()) + "_" + name;
}

std::unique_ptr<Model> loadDemo() {
  LoadResult r = loadModel("demo");
  EXPECT_TRUE(r) << r.error;
  return std::move(r.model);
}

TopoDS_Face uvPolygonFace(const Handle(Geom_Surface) & surface, const std::vector<gp_Pnt2d>& corners) {
  BRepBuilderAPI_MakeWire wire;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const gp_Pnt2d a = corners[i], b = corners[(i + 1) % corners.size()];
    Handle(Geom2d_Line) line = new Geom2d_Line(a, gp_Dir2d(gp_Vec2d(a, b)));
    wire.Add(BRepBuilderAPI_MakeEdge(line, surface, 0, a.Distance(b)).Edge());
  }
  TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, wire.Wire(), Standard_True).Face();
  BRepLib::BuildCurves3d(face);
  return face;
}

std::unique_ptr<Model> loadShape(const TopoDS_Shape& shape, const std::string& name) {
  LoadResult r = cetview::test::loadShapeThroughFile(shape, tempPath(name + ".brep"));
  EXPECT_TRUE(r) << r.error;
  return std::move(r.model);
}

std::unique_ptr<Model> loadTestData(const std::string& file) {
  LoadResult r = loadModel(std::string(CETVIEW_BREP_TEST_DATA) + "/" + file);
  EXPECT_TRUE(r) << r.error;
  return std::move(r.model);
}

TopoDS_Face firstFace(const std::string& file) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  if (!BRepTools::Read(shape, (std::string(CETVIEW_BREP_TEST_DATA) + "/" + file).c_str(), builder)) return {};
  TopExp_Explorer faces(shape, TopAbs_FACE);
  return faces.More() ? TopoDS::Face(faces.Current()) : TopoDS_Face();
}

std::unique_ptr<Tessellator> tessellate(const Model& model, const MeshParams& params, int lastLevel) {
  auto created = Tessellator::create(model, params);
  EXPECT_TRUE(created.tessellator) << created.error;
  if (created.tessellator && !created.tessellator->run(1, {}, nullptr, lastLevel)) {
    ADD_FAILURE() << "run() returned false";
    return nullptr;
  }
  return std::move(created.tessellator);
}

std::vector<FaceQuality> testDataEveryLevel(const std::string& file, const MeshParams& params) {
  auto model = loadTestData(file);
  if (!model) return {};
  auto t = tessellate(*model, params);
  if (!t) return {};
  return expectEveryLevelWithinTolerance(*t, 0);
}

std::vector<FaceQuality> expectEveryLevelWithinTolerance(const Tessellator& t, FaceId f) {
  std::vector<FaceQuality> levels;
  for (int k = 0; k <= t.lastLevel(); ++k) {
    levels.push_back(measureFaces(t, k).at(f));
    EXPECT_LE(levels.back().maxDeviation, t.schedule()[std::size_t(k)].chordal) << "face " << f << ", level " << k;
  }
  return levels;
}

CheckOptions finalLevelOnly() {
  CheckOptions o;
  o.everyLevel = false;
  return o;
}

MeshParams relative(double fraction, double angleDeg) {
  MeshParams p;
  p.chordal = {fraction, true};
  p.angleDeg = angleDeg;
  return p;
}

MeshParams fuzzed(const std::string& file, double fraction, double angleDeg) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  EXPECT_TRUE(BRepTools::Read(shape, (std::string(CETVIEW_BREP_TEST_DATA) + "/" + file).c_str(), builder)) << file;
  Bnd_Box box;
  if (!shape.IsNull()) BRepBndLib::Add(shape, box, Standard_False);
  EXPECT_FALSE(box.IsVoid()) << file;
  return absolute(box.IsVoid() ? fraction : fraction * std::sqrt(box.SquareExtent()), angleDeg);
}

MeshParams absolute(double value, double angleDeg) {
  MeshParams p;
  p.chordal = {value, false};
  p.angleDeg = angleDeg;
  return p;
}

std::unique_ptr<Tessellator> tessellateAndCheck(const Model& model, const MeshParams& params, const CheckOptions& options) {
  auto created = Tessellator::create(model, params);
  EXPECT_TRUE(created.tessellator) << created.error;
  if (!created.tessellator) return nullptr;
  Tessellator& t = *created.tessellator;
  EXPECT_TRUE(t.run(2));
  const double diagonal = model.bounds().diagonal();
  const int first = options.everyLevel ? 0 : t.lastLevel();
  for (int k = first; k <= t.lastLevel(); ++k) {
    const double tolerance = t.schedule()[static_cast<std::size_t>(k)].chordal;
    const std::vector<FaceQuality> quality = measureFaces(t, k, 2);
    for (FaceId f = 0; f < quality.size(); ++f) {
      const FaceQuality& q = quality[f];
      const char* kind = surfaceKindName(model.faces()[f].kind);
      EXPECT_GT(q.triangles, 0u) << "level " << k << ": face " << f << " (" << kind << ") has no triangle: "
                                 << t.report(f).reason;
      EXPECT_LE(q.maxDeviation, tolerance) << "level " << k << ": face " << f << " (" << kind << ") deviates "
                                           << q.maxDeviation / tolerance << "x the tolerance " << tolerance;
      EXPECT_EQ(q.degenerate, 0u) << "level " << k << ": face " << f << " (" << kind << ")";
      const auto listed = [f](const std::vector<FaceId>& faces) {
        return std::find(faces.begin(), faces.end(), f) != faces.end();
      };
      // The angular deflection, on the final level (coarser levels leave edges below a tenth of
      // their own, larger, chordal tolerance unsplit), for every face CET meshed.
      const FaceStatus status = t.report(f).status;
      if (k == t.lastLevel() && (status == FaceStatus::kOk || status == FaceStatus::kRepaired)) {
        EXPECT_LE(q.maxCornerAngle, t.angleRad() * (1 + 1e-4))
            << "face " << f << " (" << kind << ") turns " << q.maxCornerAngle * 180 / M_PI
            << " degrees across an edge";
      }
      const bool known = listed(options.knownFlips) || (k < t.lastLevel() && listed(options.knownCoarseFlips));
      if (known && q.flipped > 0) {
        std::printf("known issue: level %d: face %u (%s) has %zu flipped triangles\n", k, f, kind, q.flipped);
      } else {
        EXPECT_EQ(q.flipped, 0u) << "level " << k << ": face " << f << " (" << kind << ")";
      }
    }
    for (PartId p = 0; p < model.parts().size(); ++p) {
      if (!model.parts()[p].closed) continue;
      const TriangleSoup soup = partSoup(t, p, k);
      EXPECT_EQ(countOpenEdges(soup, 1e-9 * diagonal), 0u) << "level " << k << ": part " << p << " is not watertight";
      if (options.selfIntersection && k == t.lastLevel()) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
        // Between faces, only crossings deeper than the deflection: touching solids and tangent
        // faces cross by up to it in any mesh (see brep/mesh_check.h).
        EXPECT_EQ(countSelfIntersections(soup, 1e-9 * diagonal, 1e-9 * diagonal, &pairs, 16,
                                         options.acrossFaces ? tolerance : INFINITY),
                  0u)
            << "part " << p << ": first pair between faces " << (pairs.empty() ? 0 : soup.faceOf[pairs[0].first])
            << " and " << (pairs.empty() ? 0 : soup.faceOf[pairs[0].second]);
      }
    }
  }
  return std::move(created.tessellator);
}

std::size_t brepMeshTriangles(const TopoDS_Shape& shape, double chordal) {
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(shape).Shape();
  BRepMesh_IncrementalMesh(copy, chordal, Standard_False, 20 * M_PI / 180, Standard_False);
  std::size_t triangles = 0;
  for (TopExp_Explorer f(copy, TopAbs_FACE); f.More(); f.Next()) {
    TopLoc_Location where;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(TopoDS::Face(f.Current()), where);
    if (mesh.IsNull()) return 0;
    triangles += static_cast<std::size_t>(mesh->NbTriangles());
  }
  return triangles;
}

}  // namespace cetview::brep::test
