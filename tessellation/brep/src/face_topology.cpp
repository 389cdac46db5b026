// Face wires -> ordered loops of edge occurrences with pcurves and period shifts.
#include "face_topology.h"

#include <cmath>

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include "model_impl.h"

namespace cetview::brep {
namespace {

gp_Pnt2d endUV(const LoopEdge& le, bool start) {
  const bool atFirst = start != le.reversed;
  const double t = atFirst ? le.pcurveFirst : le.pcurveLast;
  return le.pcurve->Value(t).Translated(le.shift);
}

// The shift, a multiple of the period, that brings `gap` closest to zero.
double periodShift(double gap, bool periodic, double period) {
  if (!periodic || period <= 0 || std::abs(gap) < 0.5 * period) return 0.0;
  return -std::round(gap / period) * period;
}

}  // namespace

FaceTopology buildFaceTopology(const ModelImpl& model, FaceId f) {
  FaceTopology topo;
  const PartId part = model.faces[f].part;
  topo.face = TopoDS::Face(model.faceShapes[f].Oriented(TopAbs_FORWARD));
  if (!model.loadRepairs[f].empty()) topo.repairs.push_back(model.loadRepairs[f]);
  try {
    BRepAdaptor_Surface surface(topo.face, Standard_False);
    const bool uPeriodic = surface.IsUPeriodic(), vPeriodic = surface.IsVPeriodic();
    const double uPeriod = uPeriodic ? surface.UPeriod() : 0.0, vPeriod = vPeriodic ? surface.VPeriod() : 0.0;

    std::vector<TopoDS_Wire> wires;
    const TopoDS_Wire outer = BRepTools::OuterWire(topo.face);
    if (!outer.IsNull()) wires.push_back(outer);
    for (TopoDS_Iterator it(topo.face); it.More(); it.Next())
      if (it.Value().ShapeType() == TopAbs_WIRE && !it.Value().IsSame(outer)) wires.push_back(TopoDS::Wire(it.Value()));
    if (wires.empty()) {
      topo.failure = "face has no wire";
      return topo;
    }
    for (const TopoDS_Wire& wire : wires) {
      std::vector<TopoDS_Edge> ordered;
      int total = 0;
      for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) ++total;
      for (BRepTools_WireExplorer e(wire, topo.face); e.More(); e.Next()) ordered.push_back(e.Current());
      if (static_cast<int>(ordered.size()) != total) {
        // The wire is not a simple chain (non-manifold or disconnected): take its stored order.
        ordered.clear();
        for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) ordered.push_back(TopoDS::Edge(e.Current()));
        topo.repairs.push_back("wire is not a connected chain; used its stored edge order");
      }
      std::vector<LoopEdge> loop;
      for (const TopoDS_Edge& edge : ordered) {
        LoopEdge le;
        le.edge = model.edgeId(part, edge);
        if (le.edge == UINT32_MAX) {
          topo.failure = "wire edge not found in its part";
          return topo;
        }
        le.reversed = edge.Orientation() == TopAbs_REVERSED;
        le.degenerated = BRep_Tool::Degenerated(edge);
        BRep_Tool::Range(edge, le.edgeFirst, le.edgeLast);
        le.pcurve = BRep_Tool::CurveOnSurface(edge, topo.face, le.pcurveFirst, le.pcurveLast);
        if (le.pcurve.IsNull()) {
          topo.failure = "edge " + std::to_string(le.edge) + " has no pcurve on this face";
          return topo;
        }
        if (le.degenerated) {
          TopoDS_Vertex v0, v1;
          TopExp::Vertices(edge, v0, v1);
          le.pole = v0.IsNull() ? surface.Value(le.pcurve->Value(le.pcurveFirst).X(), le.pcurve->Value(le.pcurveFirst).Y())
                                : BRep_Tool::Pnt(v0);
        }
        if (!loop.empty()) {
          const gp_Vec2d gap(endUV(loop.back(), false), endUV(le, true));
          le.shift = gp_Vec2d(periodShift(gap.X(), uPeriodic, uPeriod), periodShift(gap.Y(), vPeriodic, vPeriod));
        }
        loop.push_back(le);
      }
      if (!loop.empty()) topo.loops.push_back(std::move(loop));
    }
    // Inner loops into the period of the outer one.
    if (uPeriodic || vPeriodic) {
      auto center = [](const std::vector<LoopEdge>& loop) {
        gp_XY c(0, 0);
        for (const LoopEdge& le : loop) c += endUV(le, true).XY();
        return c / static_cast<double>(loop.size());
      };
      const gp_XY c0 = center(topo.loops.front());
      for (std::size_t l = 1; l < topo.loops.size(); ++l) {
        const gp_XY c = center(topo.loops[l]);
        const gp_Vec2d s(periodShift(c.X() - c0.X(), uPeriodic, uPeriod), periodShift(c.Y() - c0.Y(), vPeriodic, vPeriod));
        if (s.SquareMagnitude() == 0) continue;
        for (LoopEdge& le : topo.loops[l]) le.shift += s;
      }
    }
  } catch (const Standard_Failure& e) {
    topo.failure = std::string("OpenCASCADE failed on its wires: ") + e.GetMessageString();
  }
  return topo;
}

}  // namespace cetview::brep
