// A part's box, which relative deflections are fractions of (DESIGN.md "Tolerance semantics") and the
// window's Model panel shows.
#pragma once

#include <TopoDS_Shape.hxx>

#include "brep/model.h"

namespace cetview::brep {

// The box of the part's geometry, from samples: every vertex, every edge at kEdgeSamples points along
// its curve, and each face that can bulge past its boundary (anything but a plane, cylinder, cone or
// extrusion, whose extremes lie on their boundaries: lines run across them) on a kFaceGrid x
// kFaceGrid grid over its parameter box, a B-spline face near a side of the box again on a grid by
// its knot spans; the samples near each side then sharpened by a local search (the extreme can lie
// between them: an arc's middle, a sphere's top turned off the axes, a bump between grid points).
// OpenCASCADE's quick box (BRepBndLib::Add without triangulation) bounds a
// B-spline by its control points and a torus, cone or cylinder face by more than the face: a NURBS
// torus 8 x 8 x 2 read 12 x 13.9 x 3.5, and 17 of the 62 sample models were more than 1% over
// (screw.step's diagonal 2.03x, shell1's 2.07x, Pump_Nut's 1.06x), their relative deflections that much
// coarser. Its optimal box is exact but costs seconds (trj4 3 s, Top 1.5 s). A face's grid covers its
// parameter box, which a trimmed face need not fill (hammer: 0.5% over). Where sampling finds
// nothing finite (no usable curve or surface), OpenCASCADE's quick box stands in.
Bounds partBounds(const TopoDS_Shape& shape);

constexpr int kEdgeSamples = 32;  // segments along an edge
constexpr int kFaceGrid = 17;     // points each way over a face's parameter box
constexpr int kSpanSamples = 2;   // a B-spline face's segments per knot span each way near a side,
constexpr int kMaxGrid = 65;      // up to this many points each way
// Samples this near a side of the box (a fraction of its diagonal) are near it: sampled by spans,
// and sharpened.
constexpr double kSharpenBand = 0.02;

}  // namespace cetview::brep
