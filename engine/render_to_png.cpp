#include "engine/render_to_png.h"

#include <string>

#include "engine/context.h"

namespace cetview::engine {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "edge polylines are passed as packed xyz floats");

Result<PartRange> addMesh(Scene& scene, const MeshData& mesh) {
  PartRange range =
      scene.addPart(static_cast<std::uint32_t>(mesh.faces.size()),
                    static_cast<std::uint32_t>(mesh.edges.size()), kDefaultFaceColor, mesh.closedSolid);
  std::uint32_t base = scene.appendVertices(mesh.vertices.data(), mesh.vertices.size());
  std::vector<std::uint32_t> shifted;
  for (std::uint32_t i = 0; i < range.faceCount; ++i) {
    const MeshFace& face = mesh.faces[i];
    shifted.resize(face.indices.size());
    for (std::size_t k = 0; k < face.indices.size(); ++k) shifted[k] = face.indices[k] + base;
    CETVIEW_TRY(scene.setFaceColor(range.face(i), face.color));
    CETVIEW_TRY(scene.setFaceIndices(range.face(i), shifted.data(), shifted.size()));
  }
  for (std::uint32_t i = 0; i < range.edgeCount; ++i) {
    const auto& points = mesh.edges[i];
    CETVIEW_TRY(scene.setEdgePolyline(range.edge(i), points.empty() ? nullptr : &points[0].x, points.size()));
  }
  auto instance = scene.addInstance(range.part);
  CETVIEW_TRY(instance);
  return range;
}

namespace {

// Everything renderMesh() creates, destroyed in reverse order whichever way it returns.
struct HeadlessSession {
  Instance instance;
  Device device;
  std::unique_ptr<Renderer> renderer;
  ~HeadlessSession() {
    renderer.reset();
    destroyDevice(device);
    destroyInstance(instance);
  }
};

}  // namespace

Result<RgbaImage> renderMesh(const MeshData& mesh, const RenderOptions& options) {
  HeadlessSession session;
  InstanceOptions instanceOptions;
  instanceOptions.validation = options.validation;
  auto instance = createInstance(instanceOptions);
  CETVIEW_TRY(instance);
  session.instance = std::move(*instance);
  DeviceOptions deviceOptions;
  deviceOptions.name = options.deviceName;
  auto device = createDevice(session.instance, deviceOptions);
  CETVIEW_TRY(device);
  session.device = *device;

  RendererOptions rendererOptions;
  rendererOptions.msaaSamples = options.msaaSamples;
  auto renderer = Renderer::createHeadless(session.device, {options.width, options.height}, rendererOptions);
  CETVIEW_TRY(renderer);
  session.renderer = std::move(*renderer);
  Renderer& r = *session.renderer;

  CETVIEW_TRY(addMesh(r.scene(), mesh));
  CETVIEW_TRY(r.finishUploads());
  Camera camera = standardView(options.view, r.scene().bounds(), r.aspect(), options.projection);
  auto image = r.capture(camera, options.style);
  CETVIEW_TRY(image);
  if (options.validation && session.instance.log->count() > 0) {
    return makeError(ErrorCode::kVulkan, "the validation layer reported " +
                                             std::to_string(session.instance.log->count()) +
                                             " problem(s), printed above");
  }
  return image;
}

Status renderMeshToPng(const MeshData& mesh, const RenderOptions& options, const std::string& path) {
  auto image = renderMesh(mesh, options);
  CETVIEW_TRY(image);
  return writePng(*image, path);
}

}  // namespace cetview::engine
