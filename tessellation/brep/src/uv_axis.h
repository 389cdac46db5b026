// One parameter direction's scaling into the face's scaled UV plane, where lengths approximate 3D
// ones (DESIGN.md "Data flow" step 3): piecewise linear, x = x[k] + (t - t[k]) * slope[k] in span k,
// extended linearly past the ends and repeated with the period when periodic. One span:
// x = (t - t[0]) * slope[0]. The face mesher triangulates in this plane (SurfaceEval::scaled), and
// the edge discretisation stands its trial triangles on boundary chords in the same plane.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace cetview::brep {

struct UvAxis {
  std::vector<double> t, x, slope;
  double period = 0, periodX = 0;

  double map(double value) const {
    if (slope.size() == 1) return (value - t[0]) * slope[0];
    double shift = 0;
    if (period > 0) {
      const double turns = std::floor((value - t.front()) / period);
      value -= turns * period, shift = turns * periodX;
    }
    const auto k =
        static_cast<std::size_t>(std::upper_bound(t.begin() + 1, t.end() - 1, value) - t.begin() - 1);
    return shift + x[k] + (value - t[k]) * slope[k];
  }
  double inverse(double value) const {
    if (slope.size() == 1) return t[0] + (value - x[0]) / slope[0];
    double shift = 0;
    if (period > 0) {
      const double turns = std::floor((value - x.front()) / periodX);
      value -= turns * periodX, shift = turns * period;
    }
    const auto k =
        static_cast<std::size_t>(std::upper_bound(x.begin() + 1, x.end() - 1, value) - x.begin() - 1);
    return shift + t[k] + (value - x[k]) / slope[k];
  }
};

}  // namespace cetview::brep
