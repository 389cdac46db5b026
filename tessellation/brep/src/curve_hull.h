// Whether a B-spline or Bezier 3D curve stays within a distance of a chord over a parameter range,
// decided from the curve's control points rather than samples of it. A polynomial span's control
// points (from its blossom, the de Boor recursion with one argument per step; a part's from its
// span's by de Casteljau's construction) enclose the curve there, weights being positive; the
// distance to a segment is convex, so the farthest control point bounds the curve's distance.
// Where that bound exceeds the distance, the part is halved (the farthest-reaching part first),
// until a point of the curve is found beyond (it leaves) or every part's control points are within
// (it stays).
//
// Samples at fixed fractions of a segment can miss a hook much shorter than it: a fuzzed edge, a
// rational cubic with weights from 0.018 to 476, ran 20 units out and back within its last 2% of
// parameter, 2.0 off a chord of level 0 whose every eighth lay within 0.67 of it.
#pragma once

#include <vector>

#include <gp_Pnt.hxx>

class BRepAdaptor_Curve;

namespace cetview::brep {

class CurveHull {
 public:
  // Empty (available() false) for curves other than B-splines and Bezier curves.
  explicit CurveHull(const BRepAdaptor_Curve& curve);

  bool available() const { return degree_ > 0; }

  // Whether samples at fixed fractions of its parameter may miss much of `curve`: a rational
  // B-spline or Bezier curve whose weights differ more than kUnevenWeights times (its speed then
  // varies as much, and a pole's pull can gather a hook into a sliver of parameter). A polynomial
  // curve is left to its samples: through nine of them a span of degree up to eight is
  // interpolated exactly, and between them it strays a bounded fraction beyond (searching every
  // B-spline cost trj4, curves of degree 6 to 11, about 7% and the wing, degree 14, about 37% more
  // edge time, and changed neither mesh; of the 62 sample models only MAT's gained a triangle).
  static bool samplesMayMiss(const BRepAdaptor_Curve& curve);

  // Whether the curve over [ta, tb] goes farther than `distance` from the segment (pa, pb), as far
  // as the search resolves: a part is halved at most kMaxDepth times, and kMaxParts parts are looked
  // at in all; undecided counts as staying. False outside the curve's knot range.
  bool leaves(double ta, double tb, const gp_Pnt& pa, const gp_Pnt& pb, double distance) const;

  static constexpr double kUnevenWeights = 2;
  static constexpr int kMaxDepth = 12;
  static constexpr int kMaxParts = 256;

 private:
  struct Homogeneous {
    double x, y, z, w;  // the pole times its weight, and the weight
  };
  // The control points of span `span` (index into knots_, knots_[span] < knots_[span + 1]) over
  // [a, b]: degree_ + 1 of them.
  void controlPoints(std::size_t span, double a, double b, Homogeneous* out) const;
  // The blossom of span `span` at args (degree_ of them).
  Homogeneous blossom(std::size_t span, const double* args) const;

  int degree_ = 0;
  std::vector<double> knots_;       // flat knot sequence
  std::vector<Homogeneous> poles_;  // as many as knots_.size() - degree_ - 1
  mutable std::vector<Homogeneous> work_;
  mutable std::vector<double> args_;
  mutable std::vector<Homogeneous> polygons_;    // leaves()'s parts' control points
  mutable std::vector<Homogeneous> spanBezier_;  // each span's control points, once asked for
  mutable std::vector<char> spanReady_;
};

}  // namespace cetview::brep
