// Exact orient2d / incircle, after Shewchuk's adaptive scheme: a floating-point filter (his error
// bounds A), then the determinant of the rounded coordinate differences evaluated exactly (his stage
// B, with bounds derived below; for incircle to within eps^2 in double words first), for incircle
// his stage C (B's value plus the first-order terms of
// the differences' rounding errors: co-circular points of CAD circles, rounded, end there), and the
// full expansion of the original coordinates only when none of them can decide.
#include "predicates.h"

#include <atomic>
#include <cmath>

#include "expansion.h"

namespace cet {
namespace {

constexpr double kEpsilon = 1.1102230246251565e-16;  // 2^-53, half an ulp of 1
constexpr double kOrientBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kIncircleBound = (10.0 + 96.0 * kEpsilon) * kEpsilon;
// Stage B. Each rounded difference is the true one times (1 + d), |d| <= eps, and each term of the
// determinant is a product of 2 (orient) or 4 (incircle) differences, so the exact determinant of
// the rounded differences is within about 2 eps (4 eps) of the permanent from the true one. The
// permanents the filters computed in floating point are that sum of absolute terms up to a few more
// roundings, and the largest component of an expansion is its value within 2 eps: one more eps of
// room covers both.
constexpr double kOrientBoundB = 3.0 * kEpsilon;
constexpr double kIncircleBoundB = 5.0 * kEpsilon;
// Stage C (Shewchuk's error bounds for it): the first-order tail terms leave out terms of order
// eps^2 of the permanent; the value of stage B's expansion is off by a few eps of itself.
constexpr double kIncircleBoundC = (10.0 + 96.0 * kEpsilon) * kEpsilon * kEpsilon;
constexpr double kResultBound = (3.0 + 8.0 * kEpsilon) * kEpsilon;
// Stage B in double words (below) is within this times the permanent of the exact determinant of the
// rounded differences: each minor and lift within 3 eps^2 of itself, each product of them within
// 7 eps^2 more (double-word bounds, below), the two sums within 3 eps^2 each of their partial sums;
// about 20 eps^2 of the sum of absolute terms, which the filter's permanent (a few roundings low at
// most) bounds. Three times that for room.
constexpr double kDoubleWordBound = 64.0 * kEpsilon * kEpsilon;

std::atomic<unsigned long long> gOrientExact{0};
std::atomic<unsigned long long> gIncircleExact{0};
std::atomic<unsigned long long> gOrientFull{0};
std::atomic<unsigned long long> gIncircleFull{0};

using exact::difference;
using exact::exactProduct;
using exact::Expansion;
using exact::product;
using exact::sum;

double orient2dExact(Point2 a, Point2 b, Point2 c) {
  gOrientFull.fetch_add(1, std::memory_order_relaxed);
  const Expansion<2> acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const Expansion<2> bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  const Expansion<8> left = product(acx, bcy);
  const Expansion<8> right = product(acy, bcx);
  return sum(left, exact::negate(right)).sign();
}

double incircleExact(Point2 a, Point2 b, Point2 c, Point2 d) {
  gIncircleFull.fetch_add(1, std::memory_order_relaxed);
  const Expansion<2> adx = difference(a.x, d.x), ady = difference(a.y, d.y);
  const Expansion<2> bdx = difference(b.x, d.x), bdy = difference(b.y, d.y);
  const Expansion<2> cdx = difference(c.x, d.x), cdy = difference(c.y, d.y);

  // Minors of the lifted 3x3 determinant | dx dy dx^2+dy^2 | over rows a, b, c.
  const Expansion<16> bc = sum(product(bdx, cdy), exact::negate(product(cdx, bdy)));
  const Expansion<16> ca = sum(product(cdx, ady), exact::negate(product(adx, cdy)));
  const Expansion<16> ab = sum(product(adx, bdy), exact::negate(product(bdx, ady)));
  const Expansion<16> aLift = sum(product(adx, adx), product(ady, ady));
  const Expansion<16> bLift = sum(product(bdx, bdx), product(bdy, bdy));
  const Expansion<16> cLift = sum(product(cdx, cdx), product(cdy, cdy));

  const Expansion<512> aTerm = product(aLift, bc);
  const Expansion<512> bTerm = product(bLift, ca);
  const Expansion<512> cTerm = product(cLift, ab);
  return sum(sum(aTerm, bTerm), cTerm).sign();
}

// A coordinate difference rounded to a double, and whether the rounding lost anything.
struct Rounded {
  double value, tail;  // the difference is value + tail exactly
  bool inexact;
};
Rounded roundedDifference(double a, double b) {
  double value, tail;
  exact::twoDiff(a, b, value, tail);
  return Rounded{value, tail, tail != 0.0};
}

// x * y - z * w, exactly.
Expansion<4> exactCross(double x, double y, double z, double w) {
  return sum(exactProduct(x, y), exact::negate(exactProduct(z, w)));
}

// Double-word numbers (hi + lo, |lo| at most half an ulp of hi) and two operations with proven
// relative error bounds (Joldes, Muller and Popescu, "Tight and rigorous error bounds for basic
// building blocks of double-word arithmetic", ACM TOMS 2017, with u = 2^-53): the accurate sum
// (their Algorithm 6) within 3u^2 / (1 - 4u) of the exact sum, the product without FMA (their
// Algorithm 10) within 7u^2 of the exact product.
struct DoubleWord {
  double hi, lo;
};

DoubleWord fastTwoSum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

DoubleWord dwProduct(double a, double b) {
  DoubleWord r;
  exact::twoProduct(a, b, r.hi, r.lo);
  return r;
}

DoubleWord dwSum(DoubleWord x, DoubleWord y) {
  double sh, sl, th, tl;
  exact::twoSum(x.hi, y.hi, sh, sl);
  exact::twoSum(x.lo, y.lo, th, tl);
  const DoubleWord v = fastTwoSum(sh, sl + th);
  return fastTwoSum(v.hi, tl + v.lo);
}

DoubleWord dwTimes(DoubleWord x, DoubleWord y) {
  double ch, cl1;
  exact::twoProduct(x.hi, y.hi, ch, cl1);
  const double cl2 = x.hi * y.lo + x.lo * y.hi;
  return fastTwoSum(ch, cl1 + cl2);
}

DoubleWord dwNegate(DoubleWord x) { return {-x.hi, -x.lo}; }

// The in-circle determinant of the rounded differences, exactly (stage B's value as expansions).
double incircleOfDifferences(double ax, double ay, double bx, double by, double cx, double cy) {
  const Expansion<4> bc = exactCross(bx, cy, cx, by);
  const Expansion<4> ca = exactCross(cx, ay, ax, cy);
  const Expansion<4> ab = exactCross(ax, by, bx, ay);
  const Expansion<4> aLift = sum(exactProduct(ax, ax), exactProduct(ay, ay));
  const Expansion<4> bLift = sum(exactProduct(bx, bx), exactProduct(by, by));
  const Expansion<4> cLift = sum(exactProduct(cx, cx), exactProduct(cy, cy));
  return sum(sum(product(aLift, bc), product(bLift, ca)), product(cLift, ab)).sign();
}

// The stages after the filter, out of line: the hot callers inline only the filter. detSum is the
// filter's permanent |detLeft| + |detRight|.
[[gnu::noinline]] double orient2dAdaptive(Point2 a, Point2 b, Point2 c, double detSum) {
  gOrientExact.fetch_add(1, std::memory_order_relaxed);
  const Rounded acx = roundedDifference(a.x, c.x), acy = roundedDifference(a.y, c.y);
  const Rounded bcx = roundedDifference(b.x, c.x), bcy = roundedDifference(b.y, c.y);
  const double det = exactCross(acx.value, bcy.value, acy.value, bcx.value).sign();
  // With no difference rounded (integer grids; nearby points, by Sterbenz's lemma) it is exact.
  if (!(acx.inexact || acy.inexact || bcx.inexact || bcy.inexact)) return det;
  if (std::fabs(det) > kOrientBoundB * detSum) return det;
  return orient2dExact(a, b, c);
}

// The in-circle determinant of exact differences in plain doubles, each operation checked with its
// error-free transformation: when none rounded (small integer coordinates: grids), the result is
// the exact determinant. Otherwise `exact` is false and the result means nothing.
double incircleIfNothingRounds(double adx, double ady, double bdx, double bdy, double cdx, double cdy,
                               bool& exact) {
  bool rounded = false;
  const auto mul = [&](double x, double y) {
    double p, e;
    exact::twoProduct(x, y, p, e);
    rounded |= e != 0.0;
    return p;
  };
  const auto add = [&](double x, double y) {
    double s, e;
    exact::twoSum(x, y, s, e);
    rounded |= e != 0.0;
    return s;
  };
  const auto sub = [&](double x, double y) {
    double s, e;
    exact::twoDiff(x, y, s, e);
    rounded |= e != 0.0;
    return s;
  };
  const double bc = sub(mul(bdx, cdy), mul(cdx, bdy));
  const double ca = sub(mul(cdx, ady), mul(adx, cdy));
  const double ab = sub(mul(adx, bdy), mul(bdx, ady));
  const double aLift = add(mul(adx, adx), mul(ady, ady));
  const double bLift = add(mul(bdx, bdx), mul(bdy, bdy));
  const double cLift = add(mul(cdx, cdx), mul(cdy, cdy));
  const double det = add(add(mul(aLift, bc), mul(bLift, ca)), mul(cLift, ab));
  exact = !rounded;
  return det;
}

[[gnu::noinline]] double incircleAdaptive(Point2 a, Point2 b, Point2 c, Point2 d, double permanent) {
  gIncircleExact.fetch_add(1, std::memory_order_relaxed);
  const Rounded adx = roundedDifference(a.x, d.x), ady = roundedDifference(a.y, d.y);
  const Rounded bdx = roundedDifference(b.x, d.x), bdy = roundedDifference(b.y, d.y);
  const Rounded cdx = roundedDifference(c.x, d.x), cdy = roundedDifference(c.y, d.y);
  const bool inexact = adx.inexact || ady.inexact || bdx.inexact || bdy.inexact || cdx.inexact || cdy.inexact;
  if (!inexact) {
    bool exact = false;
    const double det =
        incircleIfNothingRounds(adx.value, ady.value, bdx.value, bdy.value, cdx.value, cdy.value, exact);
    if (exact) return det;
  }
  const double ax = adx.value, ay = ady.value, bx = bdx.value, by = bdy.value, cx = cdx.value, cy = cdy.value;
  // Stage B's value in double words (within kDoubleWordBound of the permanent): near co-circular
  // rounded points (CAD circles) land here by the hundred per face, and the expansions cost ten
  // times as much.
  const DoubleWord bc = dwSum(dwProduct(bx, cy), dwNegate(dwProduct(cx, by)));
  const DoubleWord ca = dwSum(dwProduct(cx, ay), dwNegate(dwProduct(ax, cy)));
  const DoubleWord ab = dwSum(dwProduct(ax, by), dwNegate(dwProduct(bx, ay)));
  const DoubleWord aLift = dwSum(dwProduct(ax, ax), dwProduct(ay, ay));
  const DoubleWord bLift = dwSum(dwProduct(bx, bx), dwProduct(by, by));
  const DoubleWord cLift = dwSum(dwProduct(cx, cx), dwProduct(cy, cy));
  const DoubleWord stageB = dwSum(dwSum(dwTimes(aLift, bc), dwTimes(bLift, ca)), dwTimes(cLift, ab));
  const double slack = kDoubleWordBound * permanent;  // |stageB - the exact value| <= slack
  if (!inexact) {
    // The differences are exact: stage B's value is the determinant.
    if (std::fabs(stageB.hi) > 2.0 * slack) return stageB.hi;
    return incircleOfDifferences(ax, ay, bx, by, cx, cy);
  }
  if (std::fabs(stageB.hi) > kIncircleBoundB * permanent + 2.0 * slack) return stageB.hi;
  // Stage C: the first-order terms of the differences' rounding errors (their tails) added to the
  // value of stage B's determinant; what is left out is second order in them.
  double det = stageB.hi + stageB.lo;
  const double adxt = adx.tail, adyt = ady.tail, bdxt = bdx.tail, bdyt = bdy.tail, cdxt = cdx.tail, cdyt = cdy.tail;
  const double boundC = kIncircleBoundC * permanent + kResultBound * std::fabs(det) + 2.0 * slack;
  det += ((ax * ax + ay * ay) * ((bx * cdyt + cy * bdxt) - (by * cdxt + cx * bdyt)) +
          2.0 * (ax * adxt + ay * adyt) * (bx * cy - by * cx)) +
         ((bx * bx + by * by) * ((cx * adyt + ay * cdxt) - (cy * adxt + ax * cdyt)) +
          2.0 * (bx * bdxt + by * bdyt) * (cx * ay - cy * ax)) +
         ((cx * cx + cy * cy) * ((ax * bdyt + by * adxt) - (ay * bdxt + bx * adyt)) +
          2.0 * (cx * cdxt + cy * cdyt) * (ax * by - ay * bx));
  if (std::fabs(det) >= boundC) return det;
  return incircleExact(a, b, c, d);
}

}  // namespace

double orient2d(Point2 a, Point2 b, Point2 c) {
  const double detLeft = (a.x - c.x) * (b.y - c.y);
  const double detRight = (a.y - c.y) * (b.x - c.x);
  const double det = detLeft - detRight;
  // Shewchuk tests the signs of detLeft and detRight first (opposite signs or a zero cannot cancel);
  // those branches go either way at random during point location. The single bound below decides
  // the same cases: when the signs differ or one is zero, |det| is |detLeft| + |detRight| up to
  // rounding, far above the bound (and det is exactly 0 only when both products are).
  const double detSum = std::fabs(detLeft) + std::fabs(detRight);
  if (std::fabs(det) >= kOrientBound * detSum) return det;
  return orient2dAdaptive(a, b, c, detSum);
}

double incircle(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;

  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double aLift = adx * adx + ady * ady;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double bLift = bdx * bdx + bdy * bdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double cLift = cdx * cdx + cdy * cdy;

  const double det = aLift * (bdxcdy - cdxbdy) + bLift * (cdxady - adxcdy) + cLift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * aLift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * bLift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * cLift;
  // One test on |det|: the sign itself goes either way at random in the Lawson loop, and the
  // caller branches on it once.
  if (std::fabs(det) > kIncircleBound * permanent) return det;
  return incircleAdaptive(a, b, c, d, permanent);
}

PredicateStats predicateStats() {
  PredicateStats s;
  s.orientExact = gOrientExact.load(std::memory_order_relaxed);
  s.incircleExact = gIncircleExact.load(std::memory_order_relaxed);
  s.orientFullExpansion = gOrientFull.load(std::memory_order_relaxed);
  s.incircleFullExpansion = gIncircleFull.load(std::memory_order_relaxed);
  return s;
}

}  // namespace cet
