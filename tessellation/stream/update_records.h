// The records the progressive stream's workers publish, as plain structs (DESIGN.md "Data flow",
// steps 6-7). Each record is written once into a worker's SpscRing; the consumer reads it in place.
//
//   kFaceLevel: FaceLevelHeader, then vertexCount StreamVertex, then indexCount uint32 indices.
//               The vertices are the face's new ones at this level (face-local ids firstVertex ..
//               firstVertex + vertexCount - 1, appended after all earlier ones); the indices are the
//               face's complete triangle list for the level, in face-local ids.
//   kLevelDone: LevelDoneHeader, sent on the control ring once every face reached the level.
//   kEdgeLevel: EdgeLevelHeader, then per edge: uint32 edge id, uint32 point count, 3 floats per
//               point (part coordinates). Sent on the control ring once the level's edges exist.
#pragma once

#include <cstdint>

namespace cetview::stream {

enum RecordTag : std::uint32_t {
  kFaceLevel = 1,
  kLevelDone = 2,
  kEdgeLevel = 3,
};

struct StreamVertex {
  float position[3];  // part coordinates
  float normal[3];    // exact surface normal, unit, on the face's outer side
};
static_assert(sizeof(StreamVertex) == 24, "packed as the GPU reads it");

struct FaceLevelHeader {
  std::uint32_t face;         // global face id of the model
  std::uint32_t level;
  std::uint32_t firstVertex;  // face-local id of the first new vertex
  std::uint32_t vertexCount;  // new vertices in this record
  std::uint32_t indexCount;   // a multiple of 3
  std::uint32_t status;       // brep::FaceStatus of the face after this level
};

struct LevelDoneHeader {
  std::uint32_t level;
  std::uint32_t faces;      // faces in the model
  std::uint64_t triangles;  // over all faces at this level (parts counted once)
  double chordal;           // the level's chordal tolerance, model units
  double ms;                // since the stream started
};

struct EdgeLevelHeader {
  std::uint32_t level;
  std::uint32_t edgeCount;  // entries that follow
};

}  // namespace cetview::stream
