// OpenCASCADE .brep files and plain shapes (the demo part): parts are the solids and shells that the
// shape places more than once (one part, several instances); everything else forms one part.
#include <fstream>
#include <map>
#include <mutex>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>

#include "model_impl.h"

namespace cetview::brep {
namespace {

void collectLeaves(const TopoDS_Shape& shape, std::vector<TopoDS_Shape>& leaves) {
  if (shape.ShapeType() == TopAbs_COMPOUND) {
    for (TopoDS_Iterator it(shape); it.More(); it.Next()) collectLeaves(it.Value(), leaves);  // locations compose
  } else {
    leaves.push_back(shape);
  }
}

}  // namespace

void silenceOcctMessages() {
  static std::once_flag once;
  std::call_once(once, [] { Message::DefaultMessenger()->ChangePrinters().Clear(); });
}

std::string loadBrepFile(ModelImpl& m, const std::string& path, LoadProgress& progress) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  std::ifstream in(path, std::ios::binary);
  // OpenCASCADE's reader loops for ever on a token it cannot parse (a NaN coordinate, a word where a
  // number belongs): with exceptions on, the failed read ends the load instead (loadModel reports it).
  in.exceptions(std::ios::badbit | std::ios::failbit);
  try {
    progress.phase("reading", 0.0, 0.85);
    BRepTools::Read(shape, in, builder, progress.indicator()->Start());
  } catch (const std::ios_base::failure&) {
    return "not a readable OpenCASCADE .brep file (malformed or truncated)";
  }
  if (progress.cancelled()) return "cancelled";
  if (shape.IsNull()) return "not a readable OpenCASCADE .brep file (truncated or malformed)";
  std::string name = path.substr(path.find_last_of('/') + 1);
  addPartsFromShape(m, shape, name.substr(0, name.find_last_of('.')));
  return {};
}

void addPartsFromShape(ModelImpl& m, const TopoDS_Shape& shape, const std::string& name) {
  m.root = shape;
  std::vector<TopoDS_Shape> leaves;
  collectLeaves(shape, leaves);
  std::map<const TopoDS_TShape*, std::vector<std::size_t>> uses;
  for (std::size_t i = 0; i < leaves.size(); ++i) uses[leaves[i].TShape().get()].push_back(i);
  bool reused = false;
  for (const auto& u : uses) reused = reused || u.second.size() > 1;
  if (!reused) {
    // One part; its coordinates are the world's.
    const PartId part = addPart(m, shape, name);
    addInstance(m, part, gp_Trsf(), name, {});
    return;
  }
  TopoDS_Compound rest;
  BRep_Builder builder;
  builder.MakeCompound(rest);
  bool hasRest = false;
  std::map<const TopoDS_TShape*, PartId> partOf;
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    const TopoDS_Shape& leaf = leaves[i];
    const auto& u = uses[leaf.TShape().get()];
    if (u.size() == 1) {
      builder.Add(rest, leaf);
      hasRest = true;
      continue;
    }
    auto found = partOf.find(leaf.TShape().get());
    PartId part;
    if (found == partOf.end()) {
      part = addPart(m, leaf.Located(TopLoc_Location()), name + " #" + std::to_string(partOf.size() + 1));
      partOf.emplace(leaf.TShape().get(), part);
    } else {
      part = found->second;
    }
    addInstance(m, part, leaf.Location().Transformation(), m.parts[part].name, {name});
  }
  if (hasRest) {
    const PartId part = addPart(m, rest, name);
    addInstance(m, part, gp_Trsf(), name, {});
  }
}

}  // namespace cetview::brep
