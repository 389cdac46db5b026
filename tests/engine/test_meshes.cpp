#include "test_meshes.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace cetview::test {

using engine::Color8;
using engine::MeshData;
using engine::MeshFace;
using engine::MeshVertex;

namespace {

constexpr float kPi = 3.14159265358979f;

// Soft, distinct face colours (sRGB).
const Color8 kPalette[] = {
    {196, 112, 92, 255},  {108, 150, 196, 255}, {122, 176, 128, 255}, {214, 182, 96, 255},
    {160, 126, 190, 255}, {96, 178, 178, 255},  {200, 200, 204, 255}, {190, 140, 160, 255},
};

MeshVertex vertex(glm::vec3 p, glm::vec3 n) {
  return MeshVertex{{p.x, p.y, p.z}, {n.x, n.y, n.z}};
}

}  // namespace

MeshData cube(float size, std::uint32_t n, glm::vec3 center) {
  MeshData mesh;
  mesh.closedSolid = true;
  float h = 0.5f * size;
  // Per side: normal, and two axes spanning it (u x v = normal, so triangles wind outward).
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int side = 0; side < 6; ++side) {
    glm::vec3 normal = normals[side];
    glm::vec3 u = std::abs(normal.z) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    glm::vec3 v = glm::cross(normal, u);
    MeshFace face;
    face.color = kPalette[side];
    auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (std::uint32_t j = 0; j <= n; ++j) {
      for (std::uint32_t i = 0; i <= n; ++i) {
        float s = -h + size * static_cast<float>(i) / static_cast<float>(n);
        float t = -h + size * static_cast<float>(j) / static_cast<float>(n);
        mesh.vertices.push_back(vertex(center + normal * h + u * s + v * t, normal));
      }
    }
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t a = first + j * (n + 1) + i;
        face.indices.insert(face.indices.end(), {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1});
      }
    }
    mesh.faces.push_back(std::move(face));
  }
  // The 12 edges: segments between corners that differ in exactly one coordinate.
  for (int a = 0; a < 8; ++a) {
    for (int bit = 0; bit < 3; ++bit) {
      int b = a | (1 << bit);
      if (b == a) continue;
      auto corner = [&](int c) {
        return center + glm::vec3((c & 1) ? h : -h, (c & 2) ? h : -h, (c & 4) ? h : -h);
      };
      mesh.edges.push_back({corner(a), corner(b)});
    }
  }
  return mesh;
}

MeshData sphere(float radius, std::uint32_t segments, glm::vec3 center) {
  MeshData mesh;
  mesh.closedSolid = true;
  auto point = [&](float longitude, float latitude) {
    glm::vec3 n(std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude),
                std::sin(latitude));
    return vertex(center + radius * n, n);
  };
  std::uint32_t n = segments;
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    for (int quarter = 0; quarter < 4; ++quarter) {
      MeshFace face;
      face.color = hemisphere == 0 ? Color8{176, 184, 196, 255} : Color8{132, 160, 200, 255};
      if (quarter == 1) face.color = Color8{214, 150, 96, 255};
      auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      // Rows from the equator (j = 0) to the pole (j = n); the pole row is one vertex.
      for (std::uint32_t j = 0; j < n; ++j) {
        float latitude =
            (hemisphere == 0 ? 1.0f : -1.0f) * 0.5f * kPi * static_cast<float>(j) / static_cast<float>(n);
        for (std::uint32_t i = 0; i <= n; ++i) {
          float longitude =
              0.5f * kPi * (static_cast<float>(quarter) + static_cast<float>(i) / static_cast<float>(n));
          mesh.vertices.push_back(point(longitude, latitude));
        }
      }
      std::uint32_t pole = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(point(0.0f, (hemisphere == 0 ? 0.5f : -0.5f) * kPi));
      // Counter-clockwise seen from outside: east x north points out, so the southern half
      // (rows running south) swaps two corners of each triangle.
      auto triangle = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
        if (hemisphere == 0) {
          face.indices.insert(face.indices.end(), {p, q, r});
        } else {
          face.indices.insert(face.indices.end(), {p, r, q});
        }
      };
      for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
          std::uint32_t a = first + j * (n + 1) + i;
          if (j + 1 == n) {
            triangle(a, a + 1, pole);
          } else {
            triangle(a, a + 1, a + n + 2);
            triangle(a, a + n + 2, a + n + 1);
          }
        }
      }
      mesh.faces.push_back(std::move(face));
    }
  }
  // Edges are sampled where the faces' boundary vertices are, as a B-rep tessellator shares one
  // edge discretisation between the faces on both sides.
  std::uint32_t samples = n;
  for (int quarter = 0; quarter < 4; ++quarter) {
    std::vector<glm::vec3> equator;
    for (std::uint32_t i = 0; i <= samples; ++i) {
      float longitude =
          0.5f * kPi * (static_cast<float>(quarter) + static_cast<float>(i) / static_cast<float>(samples));
      MeshVertex v = point(longitude, 0.0f);
      equator.emplace_back(v.position[0], v.position[1], v.position[2]);
    }
    mesh.edges.push_back(std::move(equator));
    for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
      std::vector<glm::vec3> meridian;
      for (std::uint32_t j = 0; j <= samples; ++j) {
        float latitude = (hemisphere == 0 ? 1.0f : -1.0f) * 0.5f * kPi * static_cast<float>(j) /
                         static_cast<float>(samples);
        MeshVertex v = point(0.5f * kPi * static_cast<float>(quarter), latitude);
        meridian.emplace_back(v.position[0], v.position[1], v.position[2]);
      }
      mesh.edges.push_back(std::move(meridian));
    }
  }
  return mesh;
}

MeshData lattice(std::uint32_t count, float spacing, std::uint32_t segments) {
  MeshData mesh;
  mesh.closedSolid = true;
  float radius = 0.35f * spacing;
  float extent = spacing * static_cast<float>(count - 1);
  for (std::uint32_t z = 0; z < count; ++z) {
    for (std::uint32_t y = 0; y < count; ++y) {
      for (std::uint32_t x = 0; x < count; ++x) {
        glm::vec3 c(spacing * static_cast<float>(x), spacing * static_cast<float>(y),
                    spacing * static_cast<float>(z));
        MeshData ball = sphere(radius, segments, c - glm::vec3(0.5f * extent));
        // One face per object, coloured by position.
        MeshFace merged;
        glm::vec3 t = c / std::max(extent, 1e-6f);
        merged.color = engine::colorFromFloat(0.35f + 0.6f * t.x, 0.35f + 0.6f * t.y, 0.35f + 0.6f * t.z);
        for (const MeshFace& f : ball.faces)
          merged.indices.insert(merged.indices.end(), f.indices.begin(), f.indices.end());
        ball.faces = {merged};
        ball.edges.clear();
        append(mesh, ball);
      }
    }
  }
  return mesh;
}

void append(MeshData& into, const MeshData& part) {
  into.closedSolid = (into.faces.empty() || into.closedSolid) && part.closedSolid;
  auto base = static_cast<std::uint32_t>(into.vertices.size());
  into.vertices.insert(into.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (MeshFace face : part.faces) {
    for (std::uint32_t& i : face.indices) i += base;
    into.faces.push_back(std::move(face));
  }
  into.edges.insert(into.edges.end(), part.edges.begin(), part.edges.end());
}

std::uint64_t triangleCount(const MeshData& mesh) {
  std::uint64_t n = 0;
  for (const MeshFace& f : mesh.faces) n += f.indices.size() / 3;
  return n;
}

}  // namespace cetview::test
