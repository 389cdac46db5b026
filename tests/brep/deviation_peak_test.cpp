// Where a quadratic deviation peaks inside a triangle (deviation_peak.h): at the circumcentre of
// any acute triangle when the surface is a paraboloid of revolution (the deviation R^2 - |x - c|^2
// over 2 for the circumcentre c and radius R); nowhere inside for obtuse triangles, saddles and
// surfaces that bend one way only.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "deviation_peak.h"

namespace cetview::brep {
namespace {

struct Point {
  double x, y;
};

TEST(DeviationPeak, AtTheCircumcentreOfAcuteTrianglesOnAParaboloid) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  int acute = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Point p[3] = {{coordinate(random), coordinate(random)}, {coordinate(random), coordinate(random)},
                        {coordinate(random), coordinate(random)}};
    // The paraboloid z = (x^2 + y^2) / 2 over the triangle: the flat triangle through its corners
    // lies above it by (R^2 - |x - c|^2) / 2.
    const double bx = p[1].x - p[0].x, by = p[1].y - p[0].y, cx = p[2].x - p[0].x, cy = p[2].y - p[0].y;
    const double det = 2 * (bx * cy - by * cx);
    if (std::abs(det) < 1e-3) continue;
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const Point centre{p[0].x + (cy * b2 - by * c2) / det, p[0].y + (bx * c2 - cx * b2) / det};
    const double R2 = std::pow(p[0].x - centre.x, 2) + std::pow(p[0].y - centre.y, 2);
    const auto deviation = [&](double x, double y) { return (R2 - std::pow(x - centre.x, 2) - std::pow(y - centre.y, 2)) / 2; };
    double middle[3];
    for (int i = 0; i < 3; ++i) {
      const Point& a = p[(i + 1) % 3];
      const Point& c = p[(i + 2) % 3];
      middle[i] = deviation((a.x + c.x) / 2, (a.y + c.y) / 2);
    }
    bool isAcute = true;
    for (int i = 0; i < 3; ++i) {
      const Point& o = p[i];
      const Point& a = p[(i + 1) % 3];
      const Point& c = p[(i + 2) % 3];
      isAcute = isAcute && (a.x - o.x) * (c.x - o.x) + (a.y - o.y) * (c.y - o.y) > 1e-6;
    }
    double w[3];
    const bool inside = quadraticDeviationPeak(middle, w);
    EXPECT_EQ(inside, isAcute) << "trial " << trial;
    if (!inside || !isAcute) continue;
    ++acute;
    EXPECT_NEAR(w[0] + w[1] + w[2], 1, 1e-12);
    const double x = w[0] * p[0].x + w[1] * p[1].x + w[2] * p[2].x, y = w[0] * p[0].y + w[1] * p[1].y + w[2] * p[2].y;
    EXPECT_NEAR(x, centre.x, 1e-9 * (1 + std::abs(centre.x)));
    EXPECT_NEAR(y, centre.y, 1e-9 * (1 + std::abs(centre.y)));
  }
  EXPECT_GT(acute, 300);
}

TEST(DeviationPeak, NoneInsideForSaddlesOrOneWayBends) {
  double w[3];
  // A right triangle on z = x^2 / 2 (bends one way: the peak on the hypotenuse's middle).
  // Corners (0, 0), (1, 0), (0, 1): the middles of the edges opposite them read 1/8, 0, 1/8.
  const double oneWay[3] = {1.0 / 8, 0, 1.0 / 8};
  EXPECT_FALSE(quadraticDeviationPeak(oneWay, w));
  // A saddle reads opposite signs at the middles; an obtuse triangle's peak lies on its longest edge.
  const double saddle[3] = {0.1, -0.05, 0.1};
  EXPECT_FALSE(quadraticDeviationPeak(saddle, w));
  const double obtuse[3] = {1.0, 0.1, 0.1};  // a long edge opposite corner 0
  EXPECT_FALSE(quadraticDeviationPeak(obtuse, w));
  // Equal middles: an equilateral triangle on a paraboloid peaks at its centroid.
  const double equal[3] = {0.3, 0.3, 0.3};
  ASSERT_TRUE(quadraticDeviationPeak(equal, w));
  for (double weight : w) EXPECT_NEAR(weight, 1.0 / 3, 1e-12);
}

}  // namespace
}  // namespace cetview::brep
