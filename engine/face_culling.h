// Whole-face culling on the CPU, for devices that draw faces one by one (GpuScene without
// multi-draw indirect, i.e. lavapipe): a face that lies outside the view frustum, or whose every
// triangle faces away from the eye on a back-face-culled part, is not drawn at all, so it costs
// nothing of the software rasteriser's single-threaded front end (which otherwise fetches, shades,
// assembles and only then culls each of its triangles). Planar and gently curved faces of closed
// solids turned away from the camera are typical: about half of a planar model's faces.
//
// Each face keeps a bounding sphere and a cone around the normals of its triangles (geometric
// normals, from the winding the rasteriser culls by, not the vertex normals). Both tests are
// conservative: a face is only culled when no triangle of it can produce a fragment. Pure math,
// unit-tested without a GPU.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/types.h"

namespace cetview::engine {

struct FaceCullBounds {
  glm::vec3 center{0.0f};  // bounding sphere of the face's vertices
  float radius = -1.0f;    // < 0: no triangles (nothing to cull, nothing drawn)
  glm::vec3 axis{0.0f};    // unit cone axis around the triangles' counter-clockwise normals
  float cosAngle = -1.0f;  // cosine of the cone's half angle; <= 0: no usable cone (never back-facing)
};

// Bounds of the triangles `indices[0 .. count)` (count a multiple of 3) into `vertices`; the cone
// is widened a little so that rounding in the rasteriser's own facing test cannot disagree.
FaceCullBounds computeFaceCullBounds(const MeshVertex* vertices, const std::uint32_t* indices,
                                     std::size_t count);

// The camera as one part of an instance sees it: `eye` is the eye position in part space with w = 1
// (perspective), or the unit direction towards the eye with w = 0 (orthographic); the frustum
// planes are in part space (from modelViewProj; a point p is inside when dot(plane, (p, 1)) >= 0).
struct CullView {
  glm::vec4 eye{0.0f, 0.0f, 1.0f, 0.0f};
  glm::vec4 planes[6];
};

// `modelViewProj`: part space -> Vulkan clip space; `eyeInPart` as CullView::eye.
CullView makeCullView(const glm::mat4& modelViewProj, const glm::vec4& eyeInPart);

// True when no part of the sphere lies inside the frustum.
bool outsideFrustum(const CullView& view, const FaceCullBounds& bounds);
// True when every triangle of the face faces away from the eye (culled by back-face culling).
bool backFacing(const CullView& view, const FaceCullBounds& bounds);

}  // namespace cetview::engine
