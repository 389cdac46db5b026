// Meshes generated in code for the engine tests and the render benchmark: each is a part in the
// shape the tessellation stream produces (faces with exact normals and their own vertices, B-rep
// edges as polylines on the exact curves).
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/render_to_png.h"

namespace cetview::test {

// Every mesh here is a closed solid wound counter-clockwise seen from outside (MeshData::closedSolid),
// except where a test opens it.

// Axis-aligned cube centred at `center`: 6 faces (one per side, each an n x n grid of quads, own
// colour), 12 straight edges.
engine::MeshData cube(float size = 2.0f, std::uint32_t n = 4, glm::vec3 center = glm::vec3(0.0f));

// UV sphere split like a B-rep sphere into 8 faces (4 longitude quarters x 2 hemispheres) with
// `segments` quads along each quarter's longitude and latitude, and 12 edges through the faces'
// boundary vertices: 4 equator quarters and 8 meridian halves. Poles get triangles, not
// degenerate quads.
engine::MeshData sphere(float radius = 1.0f, std::uint32_t segments = 12, glm::vec3 center = glm::vec3(0.0f));

// A count x count x count lattice of small spheres (one face each, colour by position), `spacing`
// apart; `segments` as sphere(). No edges.
engine::MeshData lattice(std::uint32_t count, float spacing, std::uint32_t segments);

// Appends `part` to `into` (vertex indices shifted); the result is closed if both are.
void append(engine::MeshData& into, const engine::MeshData& part);

std::uint64_t triangleCount(const engine::MeshData& mesh);

}  // namespace cetview::test
