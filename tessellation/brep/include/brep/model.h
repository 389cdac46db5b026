// A loaded B-rep model, without any OpenCASCADE type: unique parts, their instances, and per part
// the indexed faces and edges (DESIGN.md "Data flow", step 1).
//
// Contract: a Model is immutable after loadModel() returns and may be read from any number of threads.
// Face and edge ids are global and dense: part p owns faces [firstFace, firstFace + faceCount).
// Geometry of a face (and every vertex a Tessellator produces for it) is in its part's coordinates;
// an instance places its part in the world with a 3x4 transform.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cetview::brep {

using FaceId = std::uint32_t;
using EdgeId = std::uint32_t;
using PartId = std::uint32_t;

struct Color {
  float r = 0.72f, g = 0.74f, b = 0.78f, a = 1.0f;  // linear RGB; the default is a neutral metal grey
};

// Axis-aligned box. An empty box has min > max.
struct Bounds {
  std::array<double, 3> min{1e300, 1e300, 1e300};
  std::array<double, 3> max{-1e300, -1e300, -1e300};
  bool empty() const { return min[0] > max[0]; }
  double diagonal() const;
  void add(double x, double y, double z);
};

// The kind of a face's underlying surface (after unwrapping trimmed surfaces).
enum class SurfaceKind : std::uint8_t {
  kPlane, kCylinder, kCone, kSphere, kTorus, kBezier, kBSpline, kRevolution, kExtrusion, kOffset, kOther
};
const char* surfaceKindName(SurfaceKind kind);

struct FaceInfo {
  PartId part = 0;
  SurfaceKind kind = SurfaceKind::kOther;
  Color color;              // the face's own colour if it has one, else its part's
  bool hasOwnColor = false;
  bool reversed = false;    // the face is reversed relative to its surface's natural normal
  double area = 0.0;        // approximate surface area (its parameter box's), for ordering faces
  std::string name;         // empty unless the file names the face
};

struct PartInfo {
  std::string name;
  FaceId firstFace = 0;
  std::uint32_t faceCount = 0;
  EdgeId firstEdge = 0;
  std::uint32_t edgeCount = 0;
  Color color;
  bool hasColor = false;
  // Every edge of the part is shared by exactly two face sides (solids, closed shells): a correct
  // tessellation of it is watertight.
  bool closed = false;
  Bounds bounds;  // in part coordinates
};

struct InstanceInfo {
  PartId part = 0;
  // Row-major 3x4 [R | t]: world = R * local + t.
  std::array<double, 12> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  Color color;            // instance colour (overrides the part's, not a face's own colour)
  bool hasColor = false;
  std::string name;
  std::vector<std::string> path;  // assembly names from the root down to this instance
};

class ModelImpl;

class Model {
 public:
  ~Model();
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const std::string& source() const;  // the path given to loadModel(), or "demo"
  const std::vector<PartInfo>& parts() const;
  const std::vector<InstanceInfo>& instances() const;
  const std::vector<FaceInfo>& faces() const;
  std::uint32_t edgeCount() const;
  Bounds bounds() const;  // world box over all instances

  // Library internals (tessellation, export) reach the OpenCASCADE data through this.
  ModelImpl& impl() const { return *impl_; }
  explicit Model(std::unique_ptr<ModelImpl> impl);

 private:
  std::unique_ptr<ModelImpl> impl_;
};

struct LoadResult {
  std::unique_ptr<Model> model;  // null on error
  std::string error;             // one line, set when model is null
  bool cancelled = false;        // the load stopped because LoadControl::cancel was raised
  explicit operator bool() const { return model != nullptr; }
};

// Progress and cancellation of a load (a large STEP file takes seconds to minutes).
struct LoadControl {
  // Called on the loading thread with the phase ("reading", "transferring" (STEP and IGES),
  // "indexing faces"; "building the demo part" for the demo) and the fraction of the whole load
  // done, in [0, 1], rising. The reading of a STEP or IGES file (OpenCASCADE's parser) reports
  // only its start.
  std::function<void(const char* phase, double fraction)> progress;
  // Raised (from any thread), the load stops at its next check: between OpenCASCADE's transfer
  // steps, between faces, and after the parser, which cannot be stopped inside.
  const std::atomic<bool>* cancel = nullptr;
};

// Loads a STEP (.step/.stp, through XCAF: names, colours, assembly), IGES (.iges/.igs, through XCAF)
// or OpenCASCADE .brep file; "demo" builds the demo part. Any failure (missing, unreadable, empty,
// truncated, not a CAD file, no B-rep faces) is returned as an error, never thrown; a cancelled
// load returns error "PATH: cancelled" and `cancelled`.
LoadResult loadModel(const std::string& pathOrDemo, const LoadControl& control = {});

}  // namespace cetview::brep
