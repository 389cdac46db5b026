#include "curve_hull.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include <BRepAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <TColStd_Array1OfReal.hxx>

namespace cetview::brep {
namespace {

// Distances from the segment (a, b), squared.
class Chord {
 public:
  Chord(const gp_Pnt& a, const gp_Pnt& b)
      : a_(a.XYZ()), d_(b.XYZ() - a.XYZ()), length2_(d_.SquareModulus()) {}

  double squareDistance(const gp_XYZ& q) const {
    const gp_XYZ aq = q - a_;
    if (!(length2_ > 0)) return aq.SquareModulus();
    const double t = std::clamp(aq.Dot(d_) / length2_, 0.0, 1.0);
    return (aq - t * d_).SquareModulus();
  }

 private:
  gp_XYZ a_, d_;
  double length2_;
};

}  // namespace

CurveHull::CurveHull(const BRepAdaptor_Curve& curve) {
  // The adaptor hands out its curve moved by the edge's location.
  if (curve.GetType() == GeomAbs_BSplineCurve) {
    Handle(Geom_BSplineCurve) bspline = curve.BSpline();
    if (bspline->IsPeriodic()) {
      bspline = Handle(Geom_BSplineCurve)::DownCast(bspline->Copy());
      bspline->SetNotPeriodic();
    }
    degree_ = bspline->Degree();
    TColStd_Array1OfReal flat(1, bspline->NbPoles() + degree_ + 1);
    bspline->KnotSequence(flat);
    knots_.assign(flat.begin(), flat.end());
    for (int i = 1; i <= bspline->NbPoles(); ++i) {
      const double w = bspline->Weight(i);
      const gp_Pnt p = bspline->Pole(i);
      poles_.push_back({p.X() * w, p.Y() * w, p.Z() * w, w});
    }
  } else if (curve.GetType() == GeomAbs_BezierCurve) {
    const Handle(Geom_BezierCurve) bezier = curve.Bezier();
    degree_ = bezier->Degree();
    knots_.assign(static_cast<std::size_t>(degree_ + 1), 0.0);
    knots_.resize(static_cast<std::size_t>(2 * degree_ + 2), 1.0);
    for (int i = 1; i <= bezier->NbPoles(); ++i) {
      const double w = bezier->Weight(i);
      const gp_Pnt p = bezier->Pole(i);
      poles_.push_back({p.X() * w, p.Y() * w, p.Z() * w, w});
    }
  }
  if (degree_ < 1 || poles_.size() + static_cast<std::size_t>(degree_) + 1 != knots_.size()) {
    degree_ = 0;
    return;
  }
  work_.resize(static_cast<std::size_t>(degree_ + 1));
  args_.resize(static_cast<std::size_t>(degree_));
}

bool CurveHull::samplesMayMiss(const BRepAdaptor_Curve& curve) {
  if (!curve.IsRational()) return false;
  TColStd_Array1OfReal weights;
  if (curve.GetType() == GeomAbs_BSplineCurve) {
    const Handle(Geom_BSplineCurve) bspline = curve.BSpline();
    weights.Resize(1, bspline->NbPoles(), false);
    bspline->Weights(weights);
  } else if (curve.GetType() == GeomAbs_BezierCurve) {
    const Handle(Geom_BezierCurve) bezier = curve.Bezier();
    weights.Resize(1, bezier->NbPoles(), false);
    bezier->Weights(weights);
  } else {
    return false;
  }
  const auto [lightest, heaviest] = std::minmax_element(weights.begin(), weights.end());
  return *heaviest > kUnevenWeights * *lightest;
}

CurveHull::Homogeneous CurveHull::blossom(std::size_t span, const double* args) const {
  const std::size_t p = static_cast<std::size_t>(degree_);
  for (std::size_t j = 0; j <= p; ++j) work_[j] = poles_[span - p + j];
  for (std::size_t r = 1; r <= p; ++r) {
    const double x = args[r - 1];
    for (std::size_t j = p; j >= r; --j) {
      const std::size_t k = span - p + j;
      const double denominator = knots_[k + p + 1 - r] - knots_[k];
      const double alpha = denominator > 0 ? (x - knots_[k]) / denominator : 0.0;
      const Homogeneous& lo = work_[j - 1];
      Homogeneous& hi = work_[j];
      hi = {lo.x + alpha * (hi.x - lo.x), lo.y + alpha * (hi.y - lo.y), lo.z + alpha * (hi.z - lo.z),
            lo.w + alpha * (hi.w - lo.w)};
    }
  }
  return work_[p];
}

void CurveHull::controlPoints(std::size_t span, double a, double b, Homogeneous* out) const {
  // The span's own (over its whole width) once, from its blossom; a part's by de Casteljau's
  // construction from them: split at b keeping the left, then at a keeping the right.
  const std::size_t p = static_cast<std::size_t>(degree_), size = p + 1;
  if (spanBezier_.empty()) {
    spanBezier_.resize(poles_.size() * size);
    spanReady_.assign(poles_.size(), 0);
  }
  Homogeneous* whole = spanBezier_.data() + span * size;
  const double u0 = knots_[span], u1 = knots_[span + 1];
  if (!spanReady_[span]) {
    for (std::size_t j = 0; j < size; ++j) {
      for (std::size_t r = 0; r < p; ++r) args_[r] = r < p - j ? u0 : u1;
      whole[j] = blossom(span, args_.data());
    }
    spanReady_[span] = 1;
  }
  auto lerp = [](const Homogeneous& lo, const Homogeneous& hi, double t) {
    return Homogeneous{lo.x + t * (hi.x - lo.x), lo.y + t * (hi.y - lo.y), lo.z + t * (hi.z - lo.z),
                       lo.w + t * (hi.w - lo.w)};
  };
  for (std::size_t j = 0; j < size; ++j) out[j] = whole[j];
  const double sb = (b - u0) / (u1 - u0), sa = (a - u0) / (u1 - u0);
  if (sb < 1) {
    // Left of sb: out[j] becomes the first point of the j-th row.
    for (std::size_t r = 1; r < size; ++r)
      for (std::size_t j = p; j >= r; --j) out[j] = lerp(out[j - 1], out[j], sb);
  }
  if (sa > 0) {
    // Right of sa / sb within [0, sb]: out[j] becomes the last point of the row.
    const double t = sb > 0 ? sa / sb : 0;
    for (std::size_t r = 1; r < size; ++r)
      for (std::size_t j = 0; j + r < size; ++j) out[j] = lerp(out[j], out[j + 1], t);
  }
}

bool CurveHull::leaves(double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, double distance) const {
  if (!available() || !(tb > ta)) return false;
  const std::size_t p = static_cast<std::size_t>(degree_), n = poles_.size(), size = p + 1;
  // An edge's range may pass its curve's knots by rounding (6e-14 on a fuzzed edge).
  const double slack = 1e-9 * (knots_[n] - knots_[p]);
  if (ta < knots_[p] - slack || tb > knots_[n] + slack) return false;
  ta = std::max(ta, knots_[p]);
  tb = std::min(tb, knots_[n]);
  const Chord chord(pa, pb);
  const double limit = distance * distance;
  auto squareDistance = [&chord](const Homogeneous& h) {
    return chord.squareDistance(gp_XYZ(h.x / h.w, h.y / h.w, h.z / h.w));
  };
  // Parts whose control points reach beyond `distance`, the farthest first (a hook draws the
  // search to itself; depth-first, the near-misses beside it used up the parts). Each holds its
  // control points (homogeneous) at `first` in `polygons`; a part's halves take theirs from it by
  // de Casteljau's construction.
  struct Part {
    double farthest;  // squared distance of the farthest control point
    std::size_t first;
    int depth;
    bool operator<(const Part& other) const { return farthest < other.farthest; }
  };
  std::priority_queue<Part> open;
  std::vector<Homogeneous>& polygons = polygons_;
  polygons.clear();
  int parts = 0;
  // Looks at the part whose control points were just appended to `polygons`: true where the curve
  // is found beyond (its first and last control points lie on it).
  auto look = [&](int depth) {
    ++parts;
    const std::size_t first = polygons.size() - size;
    double farthest = 0;
    for (std::size_t j = 0; j < size; ++j) farthest = std::max(farthest, squareDistance(polygons[first + j]));
    if (farthest <= limit) {
      polygons.resize(first);
      return false;
    }
    if (squareDistance(polygons[first]) > limit || squareDistance(polygons[first + p]) > limit) return true;
    open.push({farthest, first, depth});
    return false;
  };
  // The span holding ta: the last i in [p, n - 1] with knots_[i] <= ta.
  std::size_t span =
      static_cast<std::size_t>(std::upper_bound(knots_.begin() + static_cast<std::ptrdiff_t>(p),
                                                knots_.begin() + static_cast<std::ptrdiff_t>(n), ta) -
                               knots_.begin());
  span = std::max(span, p + 1) - 1;
  for (; span < n && knots_[span] < tb; ++span) {
    const double a = std::max(ta, knots_[span]), b = std::min(tb, knots_[span + 1]);
    if (!(b > a)) continue;
    polygons.resize(polygons.size() + size);
    controlPoints(span, a, b, polygons.data() + polygons.size() - size);
    if (look(0)) return true;
  }
  while (!open.empty() && parts < kMaxParts) {
    const Part part = open.top();
    open.pop();
    if (part.depth >= kMaxDepth) continue;
    // de Casteljau at the middle: work_ ends as the right half's control points, and the left
    // half's are taken on the way.
    for (std::size_t j = 0; j < size; ++j) work_[j] = polygons[part.first + j];
    const std::size_t left = polygons.size();
    polygons.resize(left + size);
    polygons[left] = work_[0];
    for (std::size_t r = 1; r < size; ++r) {
      for (std::size_t j = 0; j + r < size; ++j) {
        const Homogeneous &lo = work_[j], &hi = work_[j + 1];
        work_[j] = {0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z), 0.5 * (lo.w + hi.w)};
      }
      polygons[left + r] = work_[0];
    }
    if (look(part.depth + 1)) return true;
    polygons.insert(polygons.end(), work_.begin(), work_.begin() + static_cast<std::ptrdiff_t>(size));
    if (look(part.depth + 1)) return true;
  }
  return false;
}

}  // namespace cetview::brep
