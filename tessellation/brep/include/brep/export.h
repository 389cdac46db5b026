// Writing a finished tessellation (DESIGN.md "Command line": cetview export).
#pragma once

#include <string>

namespace cetview::brep {

class Tessellator;

// Writes the last completed level of every face of t's model to `path`; the format follows the
// extension: .brep (the shape with a Poly_Triangulation on every face: nodes, UV nodes, normals,
// triangles in the surface's natural orientation), .glb / .gltf (RWGltf_CafWriter) and .obj
// (RWObj_CafWriter) with part names and colours, .stl (StlAPI_Writer, binary). Instances are placed
// as in the model. Attaches the triangulations to the model's shapes (not while it is being meshed).
// Returns an empty string on success, else one line.
std::string exportModel(const Tessellator& t, const std::string& path);

// True for the extensions exportModel() writes.
bool exportFormatSupported(const std::string& path);

}  // namespace cetview::brep
