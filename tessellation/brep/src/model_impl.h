// Private: the OpenCASCADE side of a Model. Only brep/ sources include this header.
#pragma once

#include <string>
#include <vector>

#include <TDocStd_Document.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Trsf.hxx>

#include "brep/model.h"
#include "load_progress.h"

namespace cetview::brep {

class ModelImpl {
 public:
  ModelImpl() = default;
  ModelImpl(const ModelImpl&) = delete;
  ModelImpl& operator=(const ModelImpl&) = delete;
  ~ModelImpl();  // closes the XCAF document (the application keeps every open one alive)

  std::string source;
  // The XCAF document for STEP and IGES (names, colours, assembly); null for .brep and the demo part,
  // for which export builds one from `root`.
  Handle(TDocStd_Document) doc;
  TopoDS_Shape root;  // the whole model: instances placed in the world

  std::vector<TopoDS_Shape> partShapes;  // by PartId, located at the identity (part coordinates)
  std::vector<PartInfo> parts;
  std::vector<InstanceInfo> instances;

  std::vector<TopoDS_Face> faceShapes;  // by FaceId, with their orientation inside the part
  std::vector<FaceInfo> faces;
  std::vector<std::string> loadRepairs;  // by FaceId: sound repairs made while loading ("" for none)
  std::vector<TopoDS_Edge> edgeShapes;  // by EdgeId
  std::vector<TopTools_IndexedMapOfShape> partEdgeMaps;  // per part, edge -> 1-based local index

  Bounds bounds;  // world box

  // Colours the file attaches to sub-shapes of a part (faces, shells, solids), applied to faces by
  // finalizeModel(): a face's own colour wins over a solid's, which wins over the part's.
  std::vector<std::vector<std::pair<TopoDS_Shape, Color>>> subshapeColors;  // by PartId

  // The global id of an edge of part p (as found in one of its faces' wires), or UINT32_MAX.
  EdgeId edgeId(PartId p, const TopoDS_Shape& edge) const;
};

// Adds one part (shape in part coordinates) and returns its id; faces, edges and infos are filled
// by finalizeModel().
PartId addPart(ModelImpl& m, const TopoDS_Shape& shape, const std::string& name);
void addInstance(ModelImpl& m, PartId part, const gp_Trsf& placement, const std::string& name,
                 std::vector<std::string> path);
// Indexes faces and edges of every part, computes face kinds, areas, closedness and boxes.
// Returns an error line when the model has no B-rep face.
// Reports within the current phase of `progress` and stops (returning an error) when cancelled.
std::string finalizeModel(ModelImpl& m, LoadProgress& progress);

// Format loaders: fill parts and instances (before finalizeModel) or return an error line. They
// report their phases through `progress` and stop early when it is cancelled.
std::string loadXcaf(ModelImpl& m, const std::string& path, bool iges, LoadProgress& progress);
std::string loadBrepFile(ModelImpl& m, const std::string& path, LoadProgress& progress);
// Splits a plain shape into parts: solids or shells used at several places become one part with
// several instances; everything else is one part.
void addPartsFromShape(ModelImpl& m, const TopoDS_Shape& shape, const std::string& name);
TopoDS_Shape buildDemoPart();

// OpenCASCADE prints progress and warnings to stdout through its default messenger; cetview
// reports through returned errors instead. Idempotent and thread-safe.
void silenceOcctMessages();

}  // namespace cetview::brep
