// Side-by-side benchmark of cetview's tessellation and OpenCASCADE's BRepMesh_IncrementalMesh on
// one model, in one process, at the same absolute deflection and angle (DESIGN.md "Benchmarks").
// Both meshes are measured by the same code (brep/measure.h, brep/mesh_check.h).
#pragma once

#include <cstddef>
#include <string>

#include "brep/tolerance.h"

namespace cetview::brep {

struct BenchOptions {
  MeshParams params;
  unsigned threads = 0;  // the parallel runs; 0: all hardware threads
  bool measure = true;   // deviation, cracks, degenerate triangles (slower than meshing)
};

struct BenchResult {
  std::string model;
  std::string error;  // set when the model could not be loaded or meshed; the numbers are then zero
  std::size_t faces = 0;
  double deflection = 0;  // absolute
  double angleDeg = 0;
  unsigned threads = 1;
  double load_ms = 0;
  double cetview_ms = 0;          // all coarse-to-fine levels, one thread (what the viewer does)
  double cetview_ms_threads = 0;  // the same with `threads` threads
  // The final level alone on one thread, and BRepMesh on one thread: the pair the speed goal compares,
  // timed in alternating rounds, each the best of up to 5 (1.5 s of rounds at most; one for terrain).
  double cetview_direct_ms = 0;
  double brepmesh_ms = 0;
  double brepmesh_ms_threads = 0;
  std::size_t levels = 0;
  std::size_t cetview_triangles = 0, brepmesh_triangles = 0;
  double cetview_max_dev = 0, brepmesh_max_dev = 0;
  std::size_t cetview_faces_over = 0, brepmesh_faces_over = 0;  // faces measured above the deflection
  // Largest angle between the exact normals at the ends of a triangle edge (measure.h), and the faces
  // above the angular deflection: BRepMesh does not apply it inside faces, cetview does.
  double cetview_max_angle_deg = 0, brepmesh_max_angle_deg = 0;
  std::size_t cetview_faces_over_angle = 0, brepmesh_faces_over_angle = 0;
  std::size_t cetview_cracks = 0, brepmesh_cracks = 0;          // open edges after welding, closed parts only
  std::size_t cetview_degenerate = 0, brepmesh_degenerate = 0;
  // cetview's flipped triangles (brep/measure.h) on the final level, and over its coarser levels;
  // of each, those across folds of the surface's parametrisation (FaceQuality::flippedAcrossFolds).
  std::size_t cetview_flipped = 0, cetview_flipped_coarse = 0;
  std::size_t cetview_flipped_across_folds = 0, cetview_flipped_coarse_across_folds = 0;
  // Triangles of both meshers over the faces where BRepMesh keeps the deflection and the angle:
  // the triangle goal on the faces where the two meet the same promise.
  std::size_t cetview_triangles_kept = 0, brepmesh_triangles_kept = 0;
  double cetview_peak_mb = 0, brepmesh_peak_mb = 0;             // peak heap growth while meshing
  std::size_t repaired_faces = 0, fallback_faces = 0, empty_faces = 0;
};

BenchResult benchModel(const std::string& path, const BenchOptions& options);

// One JSON object on one line.
std::string benchJson(const BenchResult& r);

}  // namespace cetview::brep
