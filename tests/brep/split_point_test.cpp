// The split point of a triangle too far from an analytic surface (split_point.h): its circumcentre
// when inside, else the middle of its longest free edge, else its centroid.
#include <gtest/gtest.h>

#include <cmath>

#include "split_point.h"

namespace cetview::brep {
namespace {

cet::Point2 at(const cet::Point2 p[3], const double b[3]) {
  return {b[0] * p[0].x + b[1] * p[1].x + b[2] * p[2].x, b[0] * p[0].y + b[1] * p[1].y + b[2] * p[2].y};
}
double distance(cet::Point2 a, cet::Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

TEST(AnalyticSplit, AcuteTriangleSplitsAtItsCircumcentre) {
  const cet::Point2 p[3] = {{0, 0}, {4, 0}, {1.5, 3}};
  const bool chord[3] = {true, true, true};  // boundary chords do not matter to an inside point
  double b[3];
  analyticSplitWeights(p, chord, b);
  EXPECT_NEAR(b[0] + b[1] + b[2], 1.0, 1e-12);
  for (double w : b) EXPECT_GT(w, 0.0);
  const cet::Point2 c = at(p, b);
  EXPECT_NEAR(distance(c, p[0]), distance(c, p[1]), 1e-12);
  EXPECT_NEAR(distance(c, p[0]), distance(c, p[2]), 1e-12);
  EXPECT_NEAR(c.x, 2.0, 1e-12);  // on the perpendicular bisector of the base
}

TEST(AnalyticSplit, ObtuseTriangleSplitsItsLongestFreeEdge) {
  const cet::Point2 p[3] = {{0, 0}, {10, 0}, {3, 1}};  // obtuse at corner 2: edge 2 (0-1) longest
  const bool noChord[3] = {false, false, false};
  double b[3];
  analyticSplitWeights(p, noChord, b);
  const cet::Point2 m = at(p, b);
  EXPECT_NEAR(m.x, 5.0, 1e-12);
  EXPECT_NEAR(m.y, 0.0, 1e-12);
  EXPECT_EQ(b[2], 0.0);
}

TEST(AnalyticSplit, RightTriangleDoesNotSplitABoundaryChord) {
  // The circumcentre of a right triangle is the middle of its hypotenuse: not inside. Free, the
  // hypotenuse is bisected; a boundary chord, the triangle splits at its centroid.
  const cet::Point2 p[3] = {{0, 0}, {2, 0}, {0, 2}};  // right angle at corner 0: edge 0 the hypotenuse
  const bool noChord[3] = {false, false, false}, hypotenuseOnBoundary[3] = {true, false, false};
  double b[3];
  analyticSplitWeights(p, noChord, b);
  EXPECT_EQ(b[0], 0.0);
  EXPECT_EQ(b[1], 0.5);
  EXPECT_EQ(b[2], 0.5);
  analyticSplitWeights(p, hypotenuseOnBoundary, b);
  for (double w : b) EXPECT_DOUBLE_EQ(w, 1.0 / 3);
}

TEST(AnalyticSplit, NoAreaFallsBackWithoutDividingByZero) {
  const cet::Point2 p[3] = {{0, 0}, {1, 0}, {2, 0}};  // in line: edge 1 (0-2) longest
  const bool noChord[3] = {false, false, false};
  double b[3];
  analyticSplitWeights(p, noChord, b);
  for (double w : b) EXPECT_TRUE(std::isfinite(w));
  EXPECT_EQ(b[1], 0.0);
  EXPECT_NEAR(at(p, b).x, 1.0, 1e-12);
}

}  // namespace
}  // namespace cetview::brep
