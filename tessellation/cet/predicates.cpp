// Exact orient2d / incircle: Shewchuk's floating-point filter (error bounds A of his 1997 paper),
// then an exact evaluation with expansion arithmetic when the filter cannot decide.
#include "predicates.h"

#include <atomic>
#include <cmath>

#include "expansion.h"

namespace cet {
namespace {

constexpr double kEpsilon = 1.1102230246251565e-16;  // 2^-53, half an ulp of 1
constexpr double kOrientBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kIncircleBound = (10.0 + 96.0 * kEpsilon) * kEpsilon;

std::atomic<unsigned long long> gOrientExact{0};
std::atomic<unsigned long long> gIncircleExact{0};

using exact::difference;
using exact::Expansion;
using exact::product;
using exact::sum;

double orient2dExact(Point2 a, Point2 b, Point2 c) {
  gOrientExact.fetch_add(1, std::memory_order_relaxed);
  const Expansion<2> acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const Expansion<2> bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  const Expansion<8> left = product(acx, bcy);
  const Expansion<8> right = product(acy, bcx);
  return sum(left, exact::negate(right)).sign();
}

double incircleExact(Point2 a, Point2 b, Point2 c, Point2 d) {
  gIncircleExact.fetch_add(1, std::memory_order_relaxed);
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

}  // namespace

double orient2d(Point2 a, Point2 b, Point2 c) {
  const double detLeft = (a.x - c.x) * (b.y - c.y);
  const double detRight = (a.y - c.y) * (b.x - c.x);
  const double det = detLeft - detRight;
  // Shewchuk tests the signs of detLeft and detRight first (opposite signs or a zero cannot cancel);
  // those branches go either way at random during point location. The single bound below decides
  // the same cases: when the signs differ or one is zero, |det| is |detLeft| + |detRight| up to
  // rounding, far above the bound (and det is exactly 0 only when both products are).
  const double bound = kOrientBound * (std::fabs(detLeft) + std::fabs(detRight));
  if (std::fabs(det) >= bound) return det;
  return orient2dExact(a, b, c);
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
  const double bound = kIncircleBound * permanent;
  if (det > bound || -det > bound) return det;
  return incircleExact(a, b, c, d);
}

PredicateStats predicateStats() {
  PredicateStats s;
  s.orientExact = gOrientExact.load(std::memory_order_relaxed);
  s.incircleExact = gIncircleExact.load(std::memory_order_relaxed);
  return s;
}

}  // namespace cet
