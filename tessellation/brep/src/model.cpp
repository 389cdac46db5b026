// Model accessors, bounding boxes, and the loader front door (format detection, file checks).
#include "brep/model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sys/stat.h>

#include <Standard_Failure.hxx>
#include <XCAFApp_Application.hxx>

#include "file_extension.h"
#include "model_impl.h"

namespace cetview::brep {

double Bounds::diagonal() const {
  if (empty()) return 0.0;
  const double dx = max[0] - min[0], dy = max[1] - min[1], dz = max[2] - min[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

void Bounds::add(double x, double y, double z) {
  min[0] = std::min(min[0], x), min[1] = std::min(min[1], y), min[2] = std::min(min[2], z);
  max[0] = std::max(max[0], x), max[1] = std::max(max[1], y), max[2] = std::max(max[2], z);
}

const char* surfaceKindName(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::kPlane: return "plane";
    case SurfaceKind::kCylinder: return "cylinder";
    case SurfaceKind::kCone: return "cone";
    case SurfaceKind::kSphere: return "sphere";
    case SurfaceKind::kTorus: return "torus";
    case SurfaceKind::kBezier: return "bezier";
    case SurfaceKind::kBSpline: return "bspline";
    case SurfaceKind::kRevolution: return "revolution";
    case SurfaceKind::kExtrusion: return "extrusion";
    case SurfaceKind::kOffset: return "offset";
    case SurfaceKind::kOther: return "other";
  }
  return "other";
}

ModelImpl::~ModelImpl() {
  if (!doc.IsNull()) XCAFApp_Application::GetApplication()->Close(doc);
}

Model::Model(std::unique_ptr<ModelImpl> impl) : impl_(std::move(impl)) {}
Model::~Model() = default;
const std::string& Model::source() const { return impl_->source; }
const std::vector<PartInfo>& Model::parts() const { return impl_->parts; }
const std::vector<InstanceInfo>& Model::instances() const { return impl_->instances; }
const std::vector<FaceInfo>& Model::faces() const { return impl_->faces; }
std::uint32_t Model::edgeCount() const { return static_cast<std::uint32_t>(impl_->edgeShapes.size()); }
Bounds Model::bounds() const { return impl_->bounds; }

namespace {

enum class Format { kUnknown, kStep, kIges, kBrep };


// Recognises the format from the first bytes, so a file with a wrong or missing extension still
// loads and a renamed text file is refused before any reader sees it.
Format sniff(const std::string& head) {
  if (head.find("ISO-10303-21") != std::string::npos) return Format::kStep;
  if (head.find("DBRep_DrawableShape") != std::string::npos ||
      head.find("CASCADE Topology") != std::string::npos)
    return Format::kBrep;
  // IGES: fixed 80-column records; the start section is flagged 'S' in column 73.
  const auto eol = head.find('\n');
  const std::string first = head.substr(0, eol == std::string::npos ? head.size() : eol);
  if (first.size() >= 73 && first[72] == 'S') return Format::kIges;
  return Format::kUnknown;
}

}  // namespace

LoadResult loadModel(const std::string& pathOrDemo, const LoadControl& control) {
  silenceOcctMessages();
  LoadResult result;
  auto impl = std::make_unique<ModelImpl>();
  impl->source = pathOrDemo;
  LoadProgress progress(control);
  std::string error;
  try {
    if (pathOrDemo == "demo") {
      progress.phase("building the demo part", 0.0, 0.85);
      addPartsFromShape(*impl, buildDemoPart(), "demo bracket");
    } else {
      struct stat st {};
      if (::stat(pathOrDemo.c_str(), &st) != 0) {
        result.error = pathOrDemo + ": no such file";
        return result;
      }
      if (S_ISDIR(st.st_mode)) {
        result.error = pathOrDemo + ": is a directory, not a model file";
        return result;
      }
      if (!S_ISREG(st.st_mode)) {
        // Opening a pipe or a terminal for reading would wait for a writer, perhaps for ever.
        result.error = pathOrDemo + ": not a regular file (a pipe or a device)";
        return result;
      }
      std::ifstream in(pathOrDemo, std::ios::binary);
      if (!in) {
        result.error = pathOrDemo + ": cannot be read (permission denied?)";
        return result;
      }
      if (st.st_size == 0) {
        result.error = pathOrDemo + ": empty file";
        return result;
      }
      std::string head(4096, '\0');
      in.read(&head[0], static_cast<std::streamsize>(head.size()));
      head.resize(static_cast<std::size_t>(in.gcount()));
      Format format = sniff(head);
      if (format == Format::kUnknown) {
        const std::string ext = lowerExtension(pathOrDemo);
        const bool claimed = ext == "step" || ext == "stp" || ext == "iges" || ext == "igs" ||
                             ext == "brep" || ext == "brp";
        result.error = pathOrDemo + (claimed ? ": not a valid " + ext + " file (unrecognised header)"
                                             : ": not a CAD model (expected STEP, IGES or .brep)");
        return result;
      }
      if (format == Format::kStep) error = loadXcaf(*impl, pathOrDemo, false, progress);
      if (format == Format::kIges) error = loadXcaf(*impl, pathOrDemo, true, progress);
      if (format == Format::kBrep) error = loadBrepFile(*impl, pathOrDemo, progress);
    }
    if (error.empty() && !progress.cancelled()) {
      progress.phase("indexing faces", 0.85, 1.0);
      error = finalizeModel(*impl, progress);
    }
  } catch (const Standard_Failure& e) {
    error = std::string("OpenCASCADE failed to read it: ") + e.GetMessageString();
  } catch (const std::exception& e) {
    error = std::string("failed to read it: ") + e.what();
  }
  if (progress.cancelled()) {
    // Whatever the readers made of an interrupted run (an error, a partial model), it is dropped.
    result.error = pathOrDemo + ": cancelled";
    result.cancelled = true;
    return result;
  }
  if (!error.empty()) {
    result.error = (pathOrDemo == "demo" ? std::string("demo") : pathOrDemo) + ": " + error;
    return result;
  }
  progress.within(1.0);
  result.model = std::make_unique<Model>(std::move(impl));
  return result;
}

}  // namespace cetview::brep
