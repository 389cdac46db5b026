// STEP and IGES through XCAF: parts (unique shapes), instances (placement, colour, assembly path),
// names and face colours survive. A part referenced by several instances is loaded once.
#include <fstream>
#include <map>
#include <string>

#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopoDS_Compound.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XCAFPrs.hxx>
#include <XCAFPrs_DocumentExplorer.hxx>
#include <XCAFPrs_IndexedDataMapOfShapeStyle.hxx>
#include <XSControl_WorkSession.hxx>

#include "model_impl.h"

namespace cetview::brep {
namespace {

// Whether a STEP file carries AP242 tessellated geometry (triangulated faces, tessellated shells),
// for a clear error when that is all it has. Read in blocks: files can be large.
bool mentionsTessellatedGeometry(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string block(1 << 16, '\0');
  std::string carry;
  while (in) {
    in.read(&block[0], static_cast<std::streamsize>(block.size()));
    const std::string text = carry + block.substr(0, static_cast<std::size_t>(in.gcount()));
    if (text.find("TRIANGULATED_FACE") != std::string::npos || text.find("TESSELLATED_") != std::string::npos)
      return true;
    carry = text.size() > 32 ? text.substr(text.size() - 32) : text;
  }
  return false;
}

std::string labelName(const TDF_Label& label) {
  Handle(TDataStd_Name) name;
  if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), name)) return {};
  return TCollection_AsciiString(name->Get()).ToCString();  // UTF-8
}

Color toColor(const Quantity_ColorRGBA& c) {
  Color out;
  Standard_Real r = 0, g = 0, b = 0;
  c.GetRGB().Values(r, g, b, Quantity_TOC_RGB);
  out.r = static_cast<float>(r), out.g = static_cast<float>(g), out.b = static_cast<float>(b);
  out.a = c.Alpha();
  return out;
}

}  // namespace

std::string loadXcaf(ModelImpl& m, const std::string& path, bool iges, LoadProgress& progress) {
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  if (iges) {
    IGESCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    progress.phase("reading", 0.0, 0.4);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return "not a readable IGES file";
    if (progress.cancelled()) return "cancelled";
    if (reader.NbRootsForTransfer() == 0) return "the IGES file holds no geometry to transfer";
    progress.phase("transferring", 0.4, 0.85);
    if (!reader.Transfer(doc, progress.indicator()->Start())) return "IGES transfer failed";
  } else {
    STEPCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    reader.SetPropsMode(false);
    reader.SetGDTMode(false);
    reader.SetMatMode(false);
    reader.SetViewMode(false);
    progress.phase("reading", 0.0, 0.4);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return "not a readable STEP file (truncated or malformed)";
    if (progress.cancelled()) return "cancelled";
    if (reader.ChangeReader().NbRootsForTransfer() == 0) return "the STEP file holds no shape to transfer";
    progress.phase("transferring", 0.4, 0.85);
    if (!reader.Transfer(doc, progress.indicator()->Start())) {
      if (progress.cancelled()) return "cancelled";
      return mentionsTessellatedGeometry(path) ? "no B-rep faces: the STEP file holds only tessellated geometry"
                                               : "STEP transfer failed (no shape could be made from its entities)";
    }
  }
  m.doc = doc;
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  Handle(XCAFDoc_ColorTool) colors = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  TDF_LabelSequence freeShapes;
  shapes->GetFreeShapes(freeShapes);
  if (freeShapes.Length() == 1) {
    m.root = XCAFDoc_ShapeTool::GetShape(freeShapes.First());
  } else {
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const TDF_Label& l : freeShapes) builder.Add(all, XCAFDoc_ShapeTool::GetShape(l));
    m.root = all;
  }

  std::map<std::string, PartId> partByLabel;  // TDF entry of the part label -> part
  for (XCAFPrs_DocumentExplorer it(doc, XCAFPrs_DocumentExplorerFlags_OnlyLeafNodes); it.More(); it.Next()) {
    const XCAFPrs_DocumentNode& node = it.Current();
    const TDF_Label partLabel = node.RefLabel.IsNull() ? node.Label : node.RefLabel;
    TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(partLabel);
    if (shape.IsNull()) continue;
    TCollection_AsciiString entry;
    TDF_Tool::Entry(partLabel, entry);
    PartId part;
    auto found = partByLabel.find(entry.ToCString());
    if (found != partByLabel.end()) {
      part = found->second;
    } else {
      std::string name = labelName(partLabel);
      part = addPart(m, shape.Located(TopLoc_Location()), name.empty() ? "part " + std::to_string(m.parts.size()) : name);
      partByLabel.emplace(entry.ToCString(), part);
      Quantity_ColorRGBA c;
      if (colors->GetColor(partLabel, XCAFDoc_ColorSurf, c) || colors->GetColor(partLabel, XCAFDoc_ColorGen, c)) {
        m.parts[part].color = toColor(c);
        m.parts[part].hasColor = true;
      }
      // Sub-shape colours (faces, solids of a multi-solid part), in part coordinates.
      XCAFPrs_IndexedDataMapOfShapeStyle styles;
      XCAFPrs::CollectStyleSettings(partLabel, shape.Location().Inverted(), styles);
      auto& sub = m.subshapeColors[part];
      for (XCAFPrs_IndexedDataMapOfShapeStyle::Iterator s(styles); s.More(); s.Next()) {
        if (!s.Value().IsSetColorSurf()) continue;
        sub.emplace_back(s.Key(), toColor(s.Value().GetColorSurfRGBA()));
      }
    }
    std::vector<std::string> assembly;
    for (int d = 0; d < it.CurrentDepth(); ++d) assembly.push_back(labelName(it.Current(d).Label));  // ancestors
    std::string instanceName = labelName(node.Label);
    if (instanceName.empty()) instanceName = m.parts[part].name;
    gp_Trsf placement = node.Location.Transformation() * shape.Location().Transformation();
    addInstance(m, part, placement, instanceName, std::move(assembly));
    if (node.Style.IsSetColorSurf()) {
      m.instances.back().color = toColor(node.Style.GetColorSurfRGBA());
      m.instances.back().hasColor = true;
    }
  }
  return {};
}

}  // namespace cetview::brep
