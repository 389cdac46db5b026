// The fallback for a face CET cannot mesh from its wires (crossing or missing pcurves, a domain
// without area): OpenCASCADE's BRepMesh on a private copy of the face, so the model has no hole
// there. Its boundary points are its own, so that face may not be watertight with its neighbours.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <TopoDS_Face.hxx>

#include "brep/tessellator.h"

namespace cetview::brep {

// Appends the vertices to mesh and the triangles (oriented for `reversed`) to indices. Returns false
// with the reason when BRepMesh produces nothing.
bool meshFaceWithBRepMesh(const TopoDS_Face& forwardFace, bool reversed, double chordal, double angle,
                          FaceMesh& mesh, std::vector<std::uint32_t>& indices, std::string& failure);

}  // namespace cetview::brep
