// Triangle order for vertex reuse. Tessellators emit a face's triangles in the order they made
// them; a GPU's post-transform cache, and much more so lavapipe's front end, pay for every vertex
// that was not used shortly before. On lavapipe a shuffled triangle order costs up to 2.9 vertex
// shader runs per triangle against 0.6 for a compact one, and its single-threaded front end took
// 90 instead of 52 ms per 1M-triangle frame. Scene::setFaceIndices() reorders every large face
// once. Pure CPU code, unit-tested alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cetview::engine {

// Faces with fewer triangles keep their order: on lavapipe a draw's first 341 triangles share one
// vertex cache whatever their order, and the few vertices of a small face stay in a GPU's cache.
inline constexpr std::size_t kReorderMinTriangles = 256;

// An order needing at most this many vertex shader runs per triangle (lavapipeVertexFetches()) is
// kept: a compact order as it is (e.g. row by row over a grid, 0.6) drew faster on lavapipe than
// meshoptimizer's order of the same mesh (7% of a 1M-triangle frame), though the model counts
// both alike. A shuffled order needs 2 to 3.
inline constexpr double kCompactFetchesPerTriangle = 1.0;

// Reorders the triangles of `indices` (a triangle list, in place) so that consecutive triangles
// share vertices: meshoptimizer's vertex cache optimisation, run on the face's own vertices
// renumbered from 0. Each triangle keeps its vertices and winding. Lists of fewer than
// kReorderMinTriangles triangles, and lists already compact (kCompactFetchesPerTriangle), are
// left alone. About 5 ns per triangle to check, 70 ns to reorder.
void reorderForVertexReuse(std::vector<std::uint32_t>& indices);

// Vertex shader runs for `indices` drawn as one triangle list, in a model of lavapipe's draw
// module (Mesa 22, vsplit): segments of 1023 indices, each with a fresh 256-entry cache indexed by
// vertex % 256. For tests and benchmarks.
std::size_t lavapipeVertexFetches(const std::uint32_t* indices, std::size_t count);

}  // namespace cetview::engine
