// One-call headless rendering: a mesh in, an image or PNG out, for tests and tools (`cetview render`
// streams levels through a Renderer instead). It sets up its own instance, device and renderer, so
// it costs a device creation per call (use a Renderer directly to render many frames).
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/camera.h"
#include "engine/image.h"
#include "engine/renderer.h"
#include "engine/result.h"
#include "engine/scene.h"
#include "engine/types.h"

namespace cetview::engine {

// A whole part at one tessellation level, in the Scene's terms.
struct MeshFace {
  Color8 color = kDefaultFaceColor;
  std::vector<std::uint32_t> indices;  // triangles into MeshData::vertices
};

struct MeshData {
  std::vector<MeshVertex> vertices;
  std::vector<MeshFace> faces;
  std::vector<std::vector<glm::vec3>> edges;  // B-rep edges as polylines
  bool closedSolid = false;                   // see Scene::addPart()
};

// Adds `mesh` to `scene` as one part with one identity instance; face i is range.face(i).
// Errors: kInvalidArgument for out-of-range indices.
Result<PartRange> addMesh(Scene& scene, const MeshData& mesh);

struct RenderOptions {
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
  StandardView view = StandardView::kIso;
  Projection projection = Projection::kPerspective;
  ViewStyle style;
  std::string deviceName;   // substring of the device name; empty: best device (lavapipe last)
  bool validation = false;  // VK_LAYER_KHRONOS_validation; a missing layer or any report is an error
  std::uint32_t msaaSamples = 4;
};

// Renders `mesh` from a standard view fitted to its bounds. Errors: those of device and renderer
// setup (kNoVulkan, kNoDevice, kDeviceNotFound, ...), and of addMesh().
Result<RgbaImage> renderMesh(const MeshData& mesh, const RenderOptions& options);
Status renderMeshToPng(const MeshData& mesh, const RenderOptions& options, const std::string& path);

}  // namespace cetview::engine
