#include "engine/warm_up.h"

#include "engine/camera.h"
#include "engine/view_style.h"

namespace cetview::engine {

Status warmUp(Renderer& renderer) {
  Scene& scene = renderer.scene();
  // A tetrahedron, once as a closed solid (back faces culled) and once as an open shell.
  const MeshVertex vertices[4] = {{{0, 0, 0}, {-0.577f, -0.577f, -0.577f}},
                                  {{1, 0, 0}, {1, 0, 0}},
                                  {{0, 1, 0}, {0, 1, 0}},
                                  {{0, 0, 1}, {0, 0, 1}}};
  const std::uint32_t first = scene.appendVertices(vertices, 4);
  const std::uint32_t triangles[12] = {first,     first + 2, first + 1, first,     first + 1, first + 3,
                                       first,     first + 3, first + 2, first + 1, first + 2, first + 3};
  const float edge[6] = {0, 0, 0, 1, 0, 0};
  for (const bool closed : {true, false}) {
    const PartRange part = scene.addPart(1, 1, kDefaultFaceColor, closed);
    if (auto s = scene.setFaceIndices(part.face(0), triangles, 12); !s) return s;
    if (auto s = scene.setEdgePolyline(part.edge(0), edge, 2); !s) return s;
    if (auto instance = scene.addInstance(part.part); !instance) return Status(instance.error());
  }
  const Camera camera = standardView(StandardView::kIso, scene.bounds(), renderer.aspect(), Projection::kPerspective);
  auto image = renderer.capture(camera, ViewStyle{});
  scene.clear();
  if (!image) return Status(image.error());
  return renderer.finishUploads();
}

}  // namespace cetview::engine
