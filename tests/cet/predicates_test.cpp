// orient2d and incircle against CGAL's exact predicates on the inputs that break naive floating
// point: nearly collinear and nearly co-circular points, at scales from 1e-12 to 1e12.
#include "cet/predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cet {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int sign(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
K::Point_2 cg(Point2 p) { return K::Point_2(p.x, p.y); }

int referenceOrient(Point2 a, Point2 b, Point2 c) { return static_cast<int>(CGAL::orientation(cg(a), cg(b), cg(c))); }
int referenceIncircle(Point2 a, Point2 b, Point2 c, Point2 d) {
  return static_cast<int>(CGAL::side_of_oriented_circle(cg(a), cg(b), cg(c), cg(d)));
}

TEST(Predicates, NearlyCollinearGridOfUlps) {
  // Shewchuk's classic failure case: a 256x256 grid of points ulps apart near (0.5, 0.5) against the
  // line through (12, 12) and (24, 24). Naive evaluation gets a large share of these wrong.
  const double ulp = std::ldexp(1.0, -53);
  int exactZero = 0, checked = 0;
  for (double scale : {1e-12, 1.0, 1e12}) {
    for (int i = 0; i < 256; ++i) {
      for (int j = 0; j < 256; j += 3) {
        const Point2 a{(0.5 + i * ulp) * scale, (0.5 + j * ulp) * scale};
        const Point2 b{12 * scale, 12 * scale}, c{24 * scale, 24 * scale};
        const int expected = referenceOrient(a, b, c);
        ASSERT_EQ(sign(orient2d(a, b, c)), expected) << i << "," << j << " scale " << scale;
        ASSERT_EQ(sign(orient2d(b, c, a)), expected);
        ASSERT_EQ(sign(orient2d(b, a, c)), -expected);
        exactZero += expected == 0;
        ++checked;
      }
    }
  }
  EXPECT_GT(exactZero, 0);
  EXPECT_GT(predicateStats().orientExact, 0u) << "the exact fallback must have run";
}

TEST(Predicates, ExactlyCollinearAndCoCircularGiveZero) {
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {1e12, 1e12}), 0.0);
  EXPECT_EQ(orient2d({0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}) == 0.0, referenceOrient({0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}) == 0);
  EXPECT_EQ(incircle({0, 0}, {1, 0}, {1, 1}, {0, 1}), 0.0);
  EXPECT_EQ(incircle({-3, 4}, {5, 0}, {0, 5}, {4, -3}), 0.0);  // the circle of radius 5
  EXPECT_GT(incircle({0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}), 0.0);
  EXPECT_LT(incircle({0, 0}, {1, 0}, {0, 1}, {2, 2}), 0.0);
}

TEST(Predicates, FullExpansionOnlyWhereDifferencesRound) {
  // Exactly collinear / co-circular points the filter cannot decide: with small integer coordinates
  // every difference is exact, and the stages before the full expansion decide (zero, exactly);
  // with decimal coordinates the differences round and only the full expansion can tell.
  const PredicateStats before = predicateStats();
  EXPECT_EQ(orient2d({1, 1}, {2, 2}, {3, 3}), 0.0);
  EXPECT_EQ(orient2d({-7, 3}, {1, -1}, {9, -5}), 0.0);
  EXPECT_EQ(incircle({-3, 4}, {5, 0}, {0, 5}, {4, -3}), 0.0);
  const PredicateStats exactDifferences = predicateStats();
  EXPECT_GT(exactDifferences.orientExact, before.orientExact) << "the filter must not decide an exact zero";
  EXPECT_GT(exactDifferences.incircleExact, before.incircleExact);
  EXPECT_EQ(exactDifferences.orientFullExpansion, before.orientFullExpansion);
  EXPECT_EQ(exactDifferences.incircleFullExpansion, before.incircleFullExpansion);

  const Point2 a{0.1, 0.3}, b{0.7, 0.9}, c{1.3, 1.5};  // on y = x + 0.2 as written, not as rounded
  EXPECT_EQ(sign(orient2d(a, b, c)), referenceOrient(a, b, c));
  // Points of a circle about (0.3, 0.7), rounded: some differences round (no two coordinates within
  // a factor of two of each other), and some quadruples are too nearly co-circular for stage B.
  // Stage C (the differences' rounding errors to first order) decides them: no full expansion.
  for (int k = 0; k < 64; ++k) {
    Point2 q[4];
    for (int i = 0; i < 4; ++i) {
      const double t = 0.37 * k + 1.7 * i;
      q[i] = {0.3 + 0.29 * std::cos(t), 0.7 + 0.29 * std::sin(t)};
    }
    EXPECT_EQ(sign(incircle(q[0], q[1], q[2], q[3])), referenceIncircle(q[0], q[1], q[2], q[3]));
  }
  const PredicateStats roundedDifferences = predicateStats();
  EXPECT_GT(roundedDifferences.orientFullExpansion, exactDifferences.orientFullExpansion);
  EXPECT_GT(roundedDifferences.incircleExact, exactDifferences.incircleExact);
  EXPECT_EQ(roundedDifferences.incircleFullExpansion, exactDifferences.incircleFullExpansion);
  // Exactly co-circular (radius 5 (1 + e), exact in binary) with differences that round (9 + 9e needs
  // 54 bits): stages B and C can only bound the determinant; the full expansion shows it is zero.
  const double e = std::ldexp(1.0, -50);
  const Point2 p{5 + 5 * e, 0}, q{3 + 3 * e, 4 + 4 * e}, r{0, 5 + 5 * e}, s{-4 - 4 * e, 3 + 3 * e};
  EXPECT_EQ(referenceIncircle(p, q, r, s), 0);
  EXPECT_EQ(incircle(p, q, r, s), 0.0);
  EXPECT_GT(predicateStats().incircleFullExpansion, roundedDifferences.incircleFullExpansion);
}

TEST(Predicates, NearlyCoCircularOnRoundedCircles) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  std::uniform_int_distribution<int> ulps(-4, 4);
  int zero = 0, nonZero = 0;
  // About the origin, and off it (more of the differences round: stages B and C both work).
  for (const Point2 centre : {Point2{0, 0}, Point2{0.3, -1.7}})
  for (double scale : {1e-12, 1e-3, 1.0, 1e5, 1e12}) {
    for (int k = 0; k < 4000; ++k) {
      Point2 p[4];
      for (auto& q : p) {
        const double t = angle(rng);
        q = {scale * (centre.x + std::cos(t)), scale * (centre.y + std::sin(t))};
      }
      // Nudge d by a few ulps so it falls just inside, on, or just outside.
      p[3].x = std::nextafter(p[3].x, ulps(rng) > 0 ? 1e300 : -1e300);
      const int expected = referenceIncircle(p[0], p[1], p[2], p[3]);
      ASSERT_EQ(sign(incircle(p[0], p[1], p[2], p[3])), expected) << "scale " << scale << " case " << k;
      ASSERT_EQ(sign(incircle(p[1], p[2], p[0], p[3])), expected);
      ASSERT_EQ(sign(incircle(p[1], p[0], p[2], p[3])), -expected);
      (expected == 0 ? zero : nonZero)++;
    }
  }
  EXPECT_GT(nonZero, 0);
  EXPECT_GT(predicateStats().incircleExact, 0u);
}

TEST(Predicates, IntegerGridCoCircularAndRandomAgreeWithCgal) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> small(-3, 3);
  for (double scale : {1e-12, 1.0, 1e12}) {
    for (int k = 0; k < 20000; ++k) {
      Point2 p[4];
      for (auto& q : p) q = {small(rng) * scale, small(rng) * scale};
      ASSERT_EQ(sign(orient2d(p[0], p[1], p[2])), referenceOrient(p[0], p[1], p[2]));
      ASSERT_EQ(sign(incircle(p[0], p[1], p[2], p[3])), referenceIncircle(p[0], p[1], p[2], p[3]));
    }
  }
}

}  // namespace
}  // namespace cet
