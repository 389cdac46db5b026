// Fuzz target for B-rep face tessellation: the bytes drive a generator of random B-spline surfaces
// (degrees 1-3, rational, periodic in u, collapsed pole rows, nearly flat or folded, C0 knots) and
// random trimming loops in their UV domain (polygons, ellipses, wiggly periodic B-splines; reversed,
// self-intersecting, touching, partly outside the domain, tiny), or natural-bounds faces, a few of
// them sewn into a shell or put in a compound. The shape goes through cetview's public API as a user's
// .brep file would (loadModel, Tessellator) with random MeshParams, level by level within a work
// budget (no level after one above 60k triangles; cancelled after 6 s, FACE_FUZZ_BUDGET_SECONDS).
// Built two ways like poly_fuzz: a libFuzzer target (clang, -DCETVIEW_LIBFUZZER=ON) and the seeded
// driver (fuzz_driver.cpp). A broken contract aborts with one line on stderr; quality promises
// (deviation within the level's tolerance, no degenerate or flipped triangle) are counted and printed
// by printSummary, not aborted on.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Ellipse.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax22d.hxx>
#include <gp_Elips2d.hxx>

#include "brep/measure.h"
#include "brep/model.h"
#include "brep/tessellator.h"
#include "brep/tolerance.h"
#include "fuzz_driver.h"
#include "shape_file.h"

namespace {

using namespace cetview::brep;

[[noreturn]] void fail(const char* what, const std::string& detail = {}) {
  std::fprintf(stderr, "face_fuzz: %s%s%s\n", what, detail.empty() ? "" : ": ", detail.c_str());
  std::abort();
}

bool oneLine(const std::string& s) { return s.find('\n') == std::string::npos && s.find('\r') == std::string::npos; }

// The bytes as a stream of choices; past the end every read is zero (every pick() its first option,
// every chance() taken, every range() its low end): short inputs are valid too.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  int pick(int n) { return byte() % n; }
  bool chance(int percent) { return byte() % 100 < percent; }
  double unit() {  // [0, 1]
    const unsigned hi = byte(), lo = byte();
    return static_cast<double>(hi << 8 | lo) / 65535.0;
  }
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  double logRange(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Shape generation (OpenCASCADE may throw anywhere in here: the input is then uninteresting).

// Why OCCT refused the last input's shape (for the summary: how much of the input space is wasted).
enum Refusal { kNoRefusal, kRefusedEdge, kRefusedWire, kRefusedFace, kRefusedThrow, kRefusalCount };
Refusal refusal = kNoRefusal;

// Knots and multiplicities of one direction. Clamped: end multiplicities degree+1 and interior ones
// mostly 1, sometimes up to the degree (C0 creases); periodic: all 1. Knot spacing is uneven,
// sometimes nearly repeated, over a random parameter range.
void makeKnots(Bytes& in, int degree, int poles, bool periodic, std::vector<double>& knots, std::vector<int>& mults) {
  mults.clear();
  if (periodic) {
    mults.assign(static_cast<std::size_t>(poles + 1), 1);
  } else {
    mults.push_back(degree + 1);
    for (int remaining = poles - degree - 1; remaining > 0;) {
      const int m = in.chance(15) ? 1 + in.pick(std::min(degree, remaining)) : 1;
      mults.push_back(m);
      remaining -= m;
    }
    mults.push_back(degree + 1);
  }
  const double start = in.chance(30) ? in.range(-1e3, 1e3) : 0.0;
  const double length = in.chance(40) ? in.logRange(1e-3, 1e3) : 1.0;
  std::vector<double> steps(mults.size() - 1);
  double sum = 0;
  for (double& s : steps) sum += s = in.chance(8) ? 1e-6 : in.range(0.2, 1.0);
  knots.assign(1, start);
  for (double s : steps) knots.push_back(knots.back() + s / sum * length);
}

Handle(Geom_BSplineSurface) makeSurface(Bytes& in) {
  const int du = 1 + in.pick(3), dv = 1 + in.pick(3);
  const bool uPeriodic = in.chance(20);
  const int nu = std::max(2 + in.pick(7), du + 1), nv = std::max(2 + in.pick(7), dv + 1);
  const double scale = in.logRange(1e-3, 1e4);
  const double aspect = in.logRange(0.05, 20.0);
  const int kind = in.pick(5);
  const double flat = in.logRange(1e-9, 1e-3), fold = in.range(0.0, 1.5);
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  for (int i = 1; i <= nu; ++i) {
    for (int j = 1; j <= nv; ++j) {
      const double s = (i - 1) / double(nu - 1), t = (j - 1) / double(nv - 1);
      double x = (s - 0.5) * scale, y = (t - 0.5) * scale * aspect, z = 0;
      switch (kind) {
        case 0: z = in.range(-0.3, 0.3) * scale; break;                 // smooth bumps
        case 1: z = in.range(-1.0, 1.0) * flat * scale; break;          // nearly flat
        case 2:                                                         // anything in a box
          x = in.range(-1.0, 1.0) * scale, y = in.range(-1.0, 1.0) * scale, z = in.range(-1.0, 1.0) * scale;
          break;
        case 3:                                                         // strongly wavy, folded
          z = ((i + j) % 2 ? 1.0 : -1.0) * in.range(0.5, 3.0) * scale;
          x += in.range(-1.0, 1.0) * fold * scale;
          break;
        default: {                                                      // tube-like (closed when periodic)
          const double a = 2 * M_PI * (i - 1) / (uPeriodic ? nu : nu - 1);
          const double r = scale * in.range(0.5, 1.0);
          x = r * std::cos(a), y = r * std::sin(a), z = t * scale * aspect;
        }
      }
      poles(i, j) = gp_Pnt(x, y, z);
    }
  }
  if (in.chance(20)) {  // a row of poles on one point: a pole of the surface (degenerate edge)
    const int side = uPeriodic ? 2 + in.pick(2) : in.pick(4);
    const int i0 = side == 1 ? nu : 1, j0 = side == 3 ? nv : 1;
    const gp_Pnt p = poles(i0, j0);
    for (int i = 1; i <= nu; ++i)
      for (int j = 1; j <= nv; ++j)
        if ((side < 2 && i == i0) || (side >= 2 && j == j0)) poles(i, j) = p;
  }
  std::vector<double> uk, vk;
  std::vector<int> um, vm;
  makeKnots(in, du, nu, uPeriodic, uk, um);
  makeKnots(in, dv, nv, false, vk, vm);
  TColStd_Array1OfReal uKnots(1, static_cast<int>(uk.size())), vKnots(1, static_cast<int>(vk.size()));
  TColStd_Array1OfInteger uMults(1, static_cast<int>(um.size())), vMults(1, static_cast<int>(vm.size()));
  for (int i = 1; i <= uKnots.Upper(); ++i) uKnots(i) = uk[std::size_t(i - 1)], uMults(i) = um[std::size_t(i - 1)];
  for (int i = 1; i <= vKnots.Upper(); ++i) vKnots(i) = vk[std::size_t(i - 1)], vMults(i) = vm[std::size_t(i - 1)];
  if (in.chance(25)) {
    const bool extreme = in.chance(15);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 1; i <= nu; ++i)
      for (int j = 1; j <= nv; ++j) weights(i, j) = extreme ? in.logRange(1e-3, 1e3) : in.logRange(0.2, 5.0);
    return new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, du, dv, uPeriodic, false);
  }
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, du, dv, uPeriodic, false);
}

// One edge of a loop: a 2D curve and its range; consecutive pieces meet end to start.
struct Piece {
  Handle(Geom2d_Curve) curve;
  double first = 0, last = 0;
};

// UV domain of the surface and the map from normalised coordinates (the unit square) into it.
struct Domain {
  double u1 = 0, u2 = 1, v1 = 0, v2 = 1;
  gp_Pnt2d at(double s, double t) const { return gp_Pnt2d(u1 + s * (u2 - u1), v1 + t * (v2 - v1)); }
};

// Splits a closed curve over [a, b) into 1-3 pieces.
void splitClosed(Bytes& in, const Handle(Geom2d_Curve)& c, double a, double b, std::vector<Piece>& loop) {
  const int n = 1 + in.pick(3);
  std::vector<double> cuts{a};
  for (int k = 1; k < n; ++k) cuts.push_back(a + (b - a) * (k + in.range(-0.3, 0.3)) / n);
  cuts.push_back(b);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) loop.push_back({c, cuts[k], cuts[k + 1]});
}

// A closed loop around normalised centre (cs, ct) with normalised radius r, counter-clockwise unless
// `clockwise`. `corners` receives polygon corners (for touching loops); `touch` (if any) becomes the
// first corner of a polygon.
std::vector<Piece> makeLoop(Bytes& in, const Domain& d, double cs, double ct, double r, bool clockwise,
                            std::vector<gp_Pnt2d>& corners, const gp_Pnt2d* touch) {
  std::vector<Piece> loop;
  const int kind = in.pick(4);
  if (kind <= 1) {  // polygon: star-shaped (simple) or random corners (may cross itself)
    const int n = 3 + in.pick(6);
    std::vector<gp_Pnt2d> pts;
    for (int k = 0; k < n; ++k) {
      if (kind == 0) {
        const double a = 2 * M_PI * (k + in.range(0.0, 0.8)) / n, rr = r * in.range(0.3, 1.0);
        pts.push_back(d.at(cs + rr * std::cos(a), ct + rr * std::sin(a)));
      } else {
        pts.push_back(d.at(cs + in.range(-r, r), ct + in.range(-r, r)));
      }
    }
    if (clockwise) std::reverse(pts.begin(), pts.end());
    if (touch) pts[0] = *touch;
    for (int k = 0; k < n; ++k) {
      const gp_Pnt2d& a = pts[std::size_t(k)];
      const gp_Pnt2d& b = pts[std::size_t((k + 1) % n)];
      if (a.Distance(b) <= gp::Resolution()) return {};
      Handle(Geom2d_TrimmedCurve) seg = GCE2d_MakeSegment(a, b).Value();
      loop.push_back({seg, seg->FirstParameter(), seg->LastParameter()});
    }
    corners.insert(corners.end(), pts.begin(), pts.end());
  } else if (kind == 2) {  // ellipse (a circle in normalised coordinates, squashed by the domain)
    const double ru = r * (d.u2 - d.u1) * in.range(0.5, 1.0), rv = r * (d.v2 - d.v1) * in.range(0.5, 1.0);
    const gp_Pnt2d c = d.at(cs, ct);
    const gp_Dir2d x = ru >= rv ? gp_Dir2d(1, 0) : gp_Dir2d(0, 1);
    const gp_Dir2d y = ru >= rv ? gp_Dir2d(0, clockwise ? -1 : 1) : gp_Dir2d(clockwise ? 1 : -1, 0);
    if (!(std::min(ru, rv) > 0)) return {};
    Handle(Geom2d_Ellipse) e = new Geom2d_Ellipse(gp_Elips2d(gp_Ax22d(c, x, y), std::max(ru, rv), std::min(ru, rv)));
    splitClosed(in, e, 0, 2 * M_PI, loop);
  } else {  // wiggly periodic B-spline: around the centre (mostly simple) or anywhere near it
    const int degree = 2 + in.pick(2), n = std::max(4 + in.pick(7), degree + 1);
    const bool wild = in.chance(30);
    TColgp_Array1OfPnt2d poles(1, n);
    for (int k = 0; k < n; ++k) {
      const int at = clockwise ? n - k : k + 1;
      if (wild) {
        poles(at) = d.at(cs + in.range(-r, r), ct + in.range(-r, r));
      } else {
        const double a = 2 * M_PI * k / n, rr = r * in.range(0.3, 1.0);
        poles(at) = d.at(cs + rr * std::cos(a), ct + rr * std::sin(a));
      }
    }
    TColStd_Array1OfReal knots(1, n + 1);
    TColStd_Array1OfInteger mults(1, n + 1);
    for (int k = 1; k <= n + 1; ++k) knots(k) = k - 1, mults(k) = 1;
    Handle(Geom2d_BSplineCurve) c = new Geom2d_BSplineCurve(poles, knots, mults, degree, true);
    splitClosed(in, c, c->FirstParameter(), c->LastParameter(), loop);
  }
  return loop;
}

// Edges on the surface from the pieces, sharing their vertices; null wire when OCCT refuses.
// Consecutive corners on one 3D point (a pole row, a tiny surface) share their vertex, as OCCT
// requires; such an edge is sometimes flagged degenerated, as CAD systems write poles.
TopoDS_Wire makeWire(Bytes& in, const std::vector<Piece>& loop, const Handle(Geom_Surface)& s) {
  if (loop.empty()) return {};
  std::vector<TopoDS_Vertex> vertices;
  std::vector<gp_Pnt> points;
  for (const Piece& p : loop) {
    const gp_Pnt2d uv = p.curve->Value(p.first);
    points.push_back(s->Value(uv.X(), uv.Y()));
    if (!vertices.empty() && points.back().Distance(points[points.size() - 2]) <= Precision::Confusion()) {
      vertices.push_back(vertices.back());
    } else {
      vertices.push_back(BRepBuilderAPI_MakeVertex(points.back()).Vertex());
    }
  }
  for (std::size_t k = vertices.size() - 1; k > 0 && points[k].Distance(points[0]) <= Precision::Confusion(); --k)
    vertices[k] = vertices[0];
  BRepBuilderAPI_MakeWire wire;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Piece& p = loop[k];
    const TopoDS_Vertex& v1 = vertices[k];
    const TopoDS_Vertex& v2 = vertices[(k + 1) % loop.size()];
    BRepBuilderAPI_MakeEdge edge(p.curve, s, v1, v2, p.first, p.last);
    if (!edge.IsDone()) {
      refusal = kRefusedEdge;
      return {};
    }
    TopoDS_Edge e = edge.Edge();
    if (loop.size() > 1 && v1.IsSame(v2) && in.chance(50)) BRep_Builder().Degenerated(e, Standard_True);
    wire.Add(e);
    if (!wire.IsDone()) {
      refusal = kRefusedWire;
      return {};
    }
  }
  return wire.Wire();
}

// A face on surface s: natural bounds, or an outer loop and up to four inner loops.
TopoDS_Face makeFace(Bytes& in, const Handle(Geom_BSplineSurface)& s, bool natural) {
  Domain d;
  s->Bounds(d.u1, d.u2, d.v1, d.v2);
  if (natural) return BRepBuilderAPI_MakeFace(s, Precision::Confusion()).Face();
  std::vector<gp_Pnt2d> corners;
  std::vector<Piece> outer;
  if (in.chance(15)) {  // the domain's own rectangle (or part of it) in lines: edges on pole rows too
    const double s0 = in.chance(50) ? 0 : in.range(0, 0.4), s1 = in.chance(50) ? 1 : in.range(0.6, 1);
    const gp_Pnt2d p[4] = {d.at(s0, 0), d.at(s1, 0), d.at(s1, 1), d.at(s0, 1)};
    for (int k = 0; k < 4; ++k) {
      if (p[k].Distance(p[(k + 1) % 4]) <= gp::Resolution()) return {};
      Handle(Geom2d_TrimmedCurve) seg = GCE2d_MakeSegment(p[k], p[(k + 1) % 4]).Value();
      outer.push_back({seg, seg->FirstParameter(), seg->LastParameter()});
      corners.push_back(p[k]);
    }
  } else {
    const bool spill = in.chance(15);  // partly outside the domain
    const double cs = spill ? in.range(-0.2, 1.2) : in.range(0.4, 0.6), ct = spill ? in.range(-0.2, 1.2) : in.range(0.4, 0.6);
    const double r = spill ? in.range(0.3, 0.9) : in.range(0.2, 0.45);
    outer = makeLoop(in, d, cs, ct, r, in.chance(10), corners, nullptr);
  }
  const TopoDS_Wire outerWire = makeWire(in, outer, s);
  if (outerWire.IsNull()) return {};
  BRepBuilderAPI_MakeFace face(s, outerWire, in.chance(70));
  if (!face.IsDone()) {
    refusal = kRefusedFace;
    return {};
  }
  const int holes = in.pick(5);
  for (int h = 0; h < holes; ++h) {
    const double r = in.chance(15) ? in.logRange(1e-7, 1e-3) : in.range(0.02, 0.25);
    const double cs = in.range(0.1, 0.9), ct = in.range(0.1, 0.9);
    const gp_Pnt2d* touch = !corners.empty() && in.chance(20) ? &corners[std::size_t(in.pick(int(corners.size())))] : nullptr;
    std::vector<gp_Pnt2d> innerCorners;
    const TopoDS_Wire w = makeWire(in, makeLoop(in, d, cs, ct, r, !in.chance(15), innerCorners, touch), s);
    if (w.IsNull()) continue;
    face.Add(w);
    if (!face.IsDone()) {
      refusal = kRefusedFace;
      return {};
    }
    corners.insert(corners.end(), innerCorners.begin(), innerCorners.end());
  }
  TopoDS_Face f = face.Face();
  BRepLib::BuildCurves3d(f);  // a failure leaves edges without 3D curves: still a face to mesh
  return f;
}

// The shape of one input: mostly one trimmed face; sometimes natural bounds, strips of one surface
// sewn into a shell, or a compound of independent faces. Null when OCCT refuses.
TopoDS_Shape makeShape(Bytes& in) {
  const int kind = in.pick(10);
  if (kind == 8) {  // 2-3 natural strips of one surface, sewn
    const Handle(Geom_BSplineSurface) s = makeSurface(in);
    double u1, u2, v1, v2;
    s->Bounds(u1, u2, v1, v2);
    const int n = 2 + in.pick(2);
    BRepBuilderAPI_Sewing sewing(1e-6 * std::max(1.0, s->Pole(1, 1).Distance(s->Pole(s->NbUPoles(), s->NbVPoles()))));
    for (int k = 0; k < n; ++k) {
      const double a = u1 + (u2 - u1) * k / n, b = u1 + (u2 - u1) * (k + 1) / n;
      BRepBuilderAPI_MakeFace f(s, a, b, v1, v2, Precision::Confusion());
      if (!f.IsDone()) {
        refusal = kRefusedFace;
        return {};
      }
      sewing.Add(f.Face());
    }
    sewing.Perform();
    return sewing.SewedShape();
  }
  const int faces = kind == 9 ? 2 + in.pick(2) : 1;
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  TopoDS_Face last;
  for (int k = 0; k < faces; ++k) {
    const Handle(Geom_BSplineSurface) s = makeSurface(in);
    TopoDS_Face f = makeFace(in, s, kind == 6 || kind == 7 || (kind == 9 && in.chance(50)));
    if (f.IsNull()) return {};
    if (in.chance(20)) f.Reverse();
    builder.Add(compound, f);
    last = f;
  }
  if (faces == 1) return last;
  return compound;
}

// ---------------------------------------------------------------------------------------------
constexpr std::size_t kTriangleBudget = 60000;

// Seconds a tessellation may take before the target cancels it (FACE_FUZZ_BUDGET_SECONDS).
double budgetSeconds() {
  static const double seconds = [] {
    const char* text = std::getenv("FACE_FUZZ_BUDGET_SECONDS");
    const double s = text ? std::atof(text) : 0.0;
    return s > 0 ? s : 6.0;
  }();
  return seconds;
}

// Raises `flag` after `seconds` unless stopped first.
class Watchdog {
 public:
  Watchdog(double seconds, std::atomic<bool>& flag)
      : thread_([this, seconds, &flag] {
          std::unique_lock<std::mutex> lock(mutex_);
          if (!wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return stopped_; })) {
            flag = true;
            raisedAt_ = std::chrono::steady_clock::now();
            raised_ = true;
          }
        }) {}
  ~Watchdog() { stop(); }
  // Stops it; returns the seconds since the flag was raised (0 when it was not).
  double stop() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopped_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    return raised_ ? std::chrono::duration<double>(std::chrono::steady_clock::now() - raisedAt_).count() : 0.0;
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopped_ = false, raised_ = false;
  std::chrono::steady_clock::time_point raisedAt_;
  std::thread thread_;  // last: starts once the members above exist
};

// What the run counted (single-threaded: the target runs one input at a time).
struct Counts {
  long inputs = 0, shapes = 0, refused = 0, loadErrors = 0, createErrors = 0;
  long refusedBy[kRefusalCount] = {};  // kNoRefusal: a degenerate loop the generator itself dropped
  long faces = 0, ok = 0, repaired = 0, fallback = 0, empty = 0;
  // The promise is measured on the faces CET meshed (kOk, and kRepaired after a sound repair).
  long measuredLevels = 0;         // (face, level) pairs measured on such faces
  long cetLevelsOver = 0;          // those deviating beyond the level's chordal tolerance
  long cetFacesOverFinal = 0;      // faces deviating beyond the tolerance of the last level run
  long cetNotMeasurable = 0;       // faces whose deviation came out infinite or NaN
  // Faces reporting edges that stray from their surface beyond the deflection (within the edges'
  // own tolerance): the mesh keeps to the edges, so no level can keep the deflection beside them.
  // Their levels are not counted against the promise.
  long cetStray = 0;
  double worstRatio = 0;           // largest deviation / tolerance
  long cetFacesDegenerate = 0, cetDegenerate = 0, cetFacesFlipped = 0, cetFlipped = 0;  // kOk, kRepaired
  long fallbackFacesDegenerate = 0, fallbackFacesFlipped = 0;
  long triangles = 0;
  long budgetStops = 0;            // runs stopped before the last level (kTriangleBudget)
  long budgetCancels = 0;          // runs cancelled by the time budget (their promise not measured)
};
Counts counts;
std::string firstLoadError;  // a shape OCCT built and wrote that cetview would not load: worth a look

// `last`: the level run() was asked for; `cancelled`: the time budget cancelled it (faces may then
// be pending, cancelled, or at any level up to `last`, with a partial level's vertices appended).
void checkFace(const Tessellator& t, FaceId f, int last, bool cancelled) {
  const FaceReport report = t.report(f);
  const FaceMesh& m = t.faceMesh(f);
  const std::string where = "face " + std::to_string(f) + " (" + faceStatusName(report.status) + ")";
  switch (report.status) {
    case FaceStatus::kPending:
    case FaceStatus::kCancelled:
      if (!cancelled) fail("face left pending or cancelled after run()", where);
      break;
    case FaceStatus::kOk: ++counts.ok; break;
    case FaceStatus::kRepaired: ++counts.repaired; break;
    case FaceStatus::kFallback: ++counts.fallback; break;
    case FaceStatus::kEmpty: ++counts.empty; break;
  }
  if (!oneLine(report.reason)) fail("report reason is not one line", where);
  if ((report.status == FaceStatus::kRepaired || report.status == FaceStatus::kFallback) && report.reason.empty())
    fail("repaired or fallback face without a reason", where);
  const int reached = t.faceLevel(f);
  if (reached > last || (!cancelled && reached != last)) fail("face not at the level run() was asked for", where);
  if (m.levels.size() != std::size_t(reached + 1) || m.levelVertexEnd.size() != m.levels.size())
    fail("level arrays out of step with the face's level", where);
  const bool meshed = report.status == FaceStatus::kOk || report.status == FaceStatus::kRepaired ||
                      report.status == FaceStatus::kFallback;
  // A coarse level may show no triangles (its boundary crossed itself and BRepMesh failed too: the
  // reason says so); the last one may not.
  if (meshed && (m.levels.empty() || (reached == t.lastLevel() && m.levels.back().empty())))
    fail("meshed face with an empty final level", where);
  const std::size_t n = m.vertexCount();
  if (m.positions.size() != 3 * n || m.normals.size() != 3 * n || m.uv.size() != 2 * n)
    fail("vertex arrays of different lengths", where);
  std::uint32_t end = 0;
  for (std::size_t k = 0; k < m.levels.size(); ++k) {
    if (m.levelVertexEnd[k] < end || m.levelVertexEnd[k] > n) fail("levelVertexEnd not increasing within the vertices", where);
    end = m.levelVertexEnd[k];
    const auto& idx = m.levels[k];
    if (idx.size() % 3 != 0) fail("level index count not a multiple of 3", where);
    for (std::uint32_t i : idx) {
      if (i >= n) fail("index beyond the vertex count", where);
      if (i >= end) fail("level uses a vertex appended after it completed", where);
    }
  }
  if (end != n && !cancelled) fail("vertices appended after the last level completed", where);
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &m.positions[3 * i];
    const float* q = &m.normals[3 * i];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) fail("non-finite position", where);
    if (!std::isfinite(m.uv[2 * i]) || !std::isfinite(m.uv[2 * i + 1])) fail("non-finite uv", where);
    if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2])) fail("non-finite normal", where);
    const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2]);
    if (std::abs(len - 1.0) > 1e-3) fail("normal not unit length", where + ": |n| = " + std::to_string(len));
  }
  if (!m.levels.empty()) counts.triangles += static_cast<long>(m.levels.back().size() / 3);
}

// The promise (DESIGN.md "Tolerance semantics"), measured as the tests do: counted, not aborted on.
void measurePromise(const Tessellator& t, int last) {
  for (int k = 0; k <= last; ++k) {
    const double tolerance = t.schedule()[std::size_t(k)].chordal;
    const std::vector<FaceQuality> quality = measureFaces(t, k, 1);
    for (FaceId f = 0; f < quality.size(); ++f) {
      const FaceStatus status = t.report(f).status;
      const FaceQuality& q = quality[f];
      const bool cet = status == FaceStatus::kOk || status == FaceStatus::kRepaired;
      const bool stray = t.report(f).reason.find("edges stray") != std::string::npos;
      if (cet && stray && k == last) ++counts.cetStray;
      if (cet && !stray) {
        ++counts.measuredLevels;
        if (!std::isfinite(q.maxDeviation)) {
          if (k == last) ++counts.cetNotMeasurable;
        } else {
          counts.worstRatio = std::max(counts.worstRatio, q.maxDeviation / tolerance);
          if (q.maxDeviation > tolerance) {
            ++counts.cetLevelsOver;
            if (k == last) ++counts.cetFacesOverFinal;
          }
        }
      }
      if (k != last) continue;
      if (cet) {
        counts.cetFacesDegenerate += q.degenerate > 0;
        counts.cetDegenerate += static_cast<long>(q.degenerate);
        counts.cetFacesFlipped += q.flipped > 0;
        counts.cetFlipped += static_cast<long>(q.flipped);
      } else if (status == FaceStatus::kFallback) {
        counts.fallbackFacesDegenerate += q.degenerate > 0;
        counts.fallbackFacesFlipped += q.flipped > 0;
      }
    }
  }
}

std::string tempPath() {
  const char* dir = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  return std::string(dir) + "/cetview_face_fuzz_" + std::to_string(::getpid()) + ".brep";
}

void tessellate(const TopoDS_Shape& shape, const MeshParams& params) {
  LoadResult loaded = cetview::test::loadShapeThroughFile(shape, tempPath());
  if (!loaded) {
    if (loaded.error.empty() || !oneLine(loaded.error)) fail("load error not one line", loaded.error);
    if (counts.loadErrors++ == 0) firstLoadError = loaded.error;
    return;
  }
  const Model& model = *loaded.model;
  auto created = Tessellator::create(model, params);
  if (!created.tessellator) {
    if (created.error.empty() || !oneLine(created.error)) fail("create() error empty or not one line", created.error);
    ++counts.createErrors;
    return;
  }
  Tessellator& t = *created.tessellator;
  // Work budget: levels run one at a time, and none after a level above kTriangleBudget triangles;
  // the whole run gets budgetSeconds() before it is cancelled through the public flag. Fine levels
  // of big wavy faces legitimately take millions of triangles (tens of seconds under ASan), and
  // this target looks for broken contracts, crashes and hangs, not for big meshes. A cancelled run
  // must return promptly (cancellation is part of the API); work that ignores the flag still times
  // out, and the summary counts the cancelled runs.
  std::atomic<bool> cancel{false};
  Watchdog watchdog(budgetSeconds(), cancel);
  int last = 0;
  bool cancelled = false;
  for (int k = 0; k <= t.lastLevel() && !cancelled; ++k) {
    last = k;
    if (!t.run(1, {}, &cancel, k)) {
      if (!cancel.load()) fail("run() returned false without cancellation");
      cancelled = true;
    } else if (t.triangleCount(k) > kTriangleBudget) {
      ++counts.budgetStops;
      break;
    }
  }
  const double late = watchdog.stop();
  if (late > budgetSeconds())
    fail("cancellation not honoured", "run() returned " + std::to_string(late) + " s after the flag was raised");
  counts.budgetCancels += cancelled;
  for (FaceId f = 0; f < model.faces().size(); ++f) {
    ++counts.faces;
    checkFace(t, f, last, cancelled);
  }
  if (!cancelled) measurePromise(t, last);
  if (std::getenv("FACE_FUZZ_DUMP")) {
    for (FaceId f = 0; f < model.faces().size(); ++f) {
      const FaceMesh& m = t.faceMesh(f);
      std::fprintf(stderr, "face_fuzz: face %u %s, %zu vertices, triangles per level:", f,
                   faceStatusName(t.report(f).status), m.vertexCount());
      for (const auto& level : m.levels) std::fprintf(stderr, " %zu", level.size() / 3);
      if (!cancelled) {
        std::fprintf(stderr, "; deviation / tolerance per level:");
        for (int k = 0; k <= last; ++k)
          std::fprintf(stderr, " %.3g", measureFaces(t, k, 1)[f].maxDeviation / t.schedule()[std::size_t(k)].chordal);
        const FaceQuality q = measureFaces(t, last, 1)[f];
        std::fprintf(stderr, "; last level: %zu degenerate, %zu flipped (%zu across folds)", q.degenerate, q.flipped,
                     q.flippedAcrossFolds);
      }
      std::fprintf(stderr, "; %s\n", t.report(f).reason.c_str());
    }
  }
}

void printCounts(std::FILE* out) {
  const Counts& c = counts;
  std::fprintf(out,
               "face_fuzz: %ld inputs: %ld shapes tessellated, %ld refused by OCCT (edge %ld, wire %ld, face %ld, exception "
               "%ld, degenerate loop %ld), %ld load errors, %ld create errors\n"
               "face_fuzz: %ld faces: %ld ok, %ld repaired, %ld fallback, %ld empty; %ld final triangles; %ld runs "
               "stopped early by the triangle budget, %ld cancelled by the time budget\n"
               "face_fuzz: promise on ok/repaired faces: %ld of %ld faces over the tolerance of their last level, %ld of %ld "
               "(face, level) over the level's, worst %.3gx, %ld not measurable, %ld with edges straying beyond it\n"
               "face_fuzz: ok/repaired faces with degenerate triangles %ld (%ld triangles), with flipped %ld (%ld "
               "triangles); fallback faces with degenerate %ld, flipped %ld\n",
               c.inputs, c.shapes, c.refused, c.refusedBy[kRefusedEdge], c.refusedBy[kRefusedWire],
               c.refusedBy[kRefusedFace], c.refusedBy[kRefusedThrow], c.refusedBy[kNoRefusal], c.loadErrors, c.createErrors, c.faces, c.ok, c.repaired, c.fallback,
               c.empty, c.triangles, c.budgetStops, c.budgetCancels, c.cetFacesOverFinal, c.ok + c.repaired - c.cetStray, c.cetLevelsOver, c.measuredLevels, c.worstRatio,
               c.cetNotMeasurable, c.cetStray, c.cetFacesDegenerate, c.cetDegenerate, c.cetFacesFlipped, c.cetFlipped,
               c.fallbackFacesDegenerate, c.fallbackFacesFlipped);
  if (!firstLoadError.empty()) std::fprintf(out, "face_fuzz: first load error: %s\n", firstLoadError.c_str());
}

}  // namespace

namespace cetview::fuzz {
void printSummary(std::FILE* out) { printCounts(out); }
}  // namespace cetview::fuzz

// libFuzzer only: the counts at exit.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit([] { printCounts(stderr); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ++counts.inputs;
  Bytes in(data, size);
  MeshParams params;
  params.chordal = {in.logRange(1e-4, 0.1), true};
  params.angleDeg = in.range(5.0, 60.0);
  // Without levels the work budget cannot stop early: only down to 0.1% then.
  params.progressive = !in.chance(15);
  if (!params.progressive) params.chordal.value = std::max(params.chordal.value, 1e-3);
  TopoDS_Shape shape;
  refusal = kNoRefusal;
  try {
    shape = makeShape(in);
  } catch (const Standard_Failure&) {
    shape.Nullify();
    refusal = kRefusedThrow;
  }
  if (shape.IsNull()) {
    ++counts.refused;
    ++counts.refusedBy[refusal];
    return 0;
  }
  ++counts.shapes;
  if (const char* dump = std::getenv("FACE_FUZZ_DUMP")) {  // debugging: the shape and the parameters
    BRepTools::Write(shape, dump);
    std::fprintf(stderr, "face_fuzz: wrote %s; deflection %.17g%%, angle %.17g deg, %s\n", dump,
                 params.chordal.value * 100, params.angleDeg, params.progressive ? "progressive" : "final level only");
  }
  try {
    tessellate(shape, params);
  } catch (const Standard_Failure& e) {
    fail("OpenCASCADE exception escaped cetview", e.GetMessageString());
  } catch (const std::exception& e) {
    fail("exception escaped cetview", e.what());
  } catch (...) {
    fail("unknown exception escaped cetview");
  }
  return 0;
}
