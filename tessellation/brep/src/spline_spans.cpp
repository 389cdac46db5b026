#include "spline_spans.h"

#include <algorithm>
#include <cmath>

namespace cetview::brep {
namespace {

// Slots per direction: 64 x 64 at most (about 2.5 MB of bicubic spans), fewer for fewer spans.
constexpr int kMaxTiles = 64;

std::vector<double> distinctKnots(const TColStd_Array1OfReal& knots) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(knots.Length()));
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) out.push_back(knots(i));
  return out;
}

}  // namespace

SplineSpans::SplineSpans(const Handle(Geom_BSplineSurface) & surface, const gp_Trsf& trsf)
    : surface_(surface), trsf_(trsf), moved_(trsf.Form() != gp_Identity) {
  uKnots_ = distinctKnots(surface_->UKnots());
  vKnots_ = distinctKnots(surface_->VKnots());
  if (surface_->IsUPeriodic()) uPeriod_ = uKnots_.back() - uKnots_.front();
  if (surface_->IsVPeriodic()) vPeriod_ = vKnots_.back() - vKnots_.front();
  tilesU_ = std::clamp(static_cast<int>(uKnots_.size()) - 1, 1, kMaxTiles);
  tilesV_ = std::clamp(static_cast<int>(vKnots_.size()) - 1, 1, kMaxTiles);
  slots_.resize(static_cast<std::size_t>(tilesU_ * tilesV_));
}

double SplineSpans::wrap(const std::vector<double>& knots, double period, double t) {
  if (period > 0 && (t < knots.front() || t >= knots.back())) {
    t = knots.front() + std::fmod(std::fmod(t - knots.front(), period) + period, period);
    if (t >= knots.back()) t = knots.front();  // rounding up to the period's end
  }
  return t;
}

int SplineSpans::span(const std::vector<double>& knots, double t, int last) {
  const int spans = static_cast<int>(knots.size()) - 1;
  // Below the first knot or past the last, the end spans extend (as OpenCASCADE evaluates there).
  if (t >= knots[last] && (t < knots[last + 1] || last + 1 == spans)) return last;
  if (t < knots[last] && last == 0) return 0;
  const auto it = std::upper_bound(knots.begin(), knots.end(), t);
  return std::clamp(static_cast<int>(it - knots.begin()) - 1, 0, spans - 1);
}

const BSplSLib_Cache& SplineSpans::spanOf(double u, double v) {
  const int iu = lastU_ = span(uKnots_, u, lastU_);
  const int iv = lastV_ = span(vKnots_, v, lastV_);
  Slot& slot = slots_[static_cast<std::size_t>((iv % tilesV_) * tilesU_ + iu % tilesU_)];
  if (slot.cache.IsNull()) {
    slot.cache = new BSplSLib_Cache(surface_->UDegree(), surface_->IsUPeriodic(), surface_->UKnotSequence(),
                                    surface_->VDegree(), surface_->IsVPeriodic(), surface_->VKnotSequence(),
                                    surface_->Weights());
  }
  if (slot.u != iu || slot.v != iv) {
    // Built at the span's middle: at a knot, OpenCASCADE could pick the span on the other side.
    const double mu = 0.5 * (uKnots_[iu] + uKnots_[iu + 1]), mv = 0.5 * (vKnots_[iv] + vKnots_[iv + 1]);
    slot.cache->BuildCache(mu, mv, surface_->UKnotSequence(), surface_->VKnotSequence(), surface_->Poles(),
                           surface_->Weights());
    slot.u = iu, slot.v = iv;
  }
  return *slot.cache;
}

void SplineSpans::d0(double u, double v, gp_Pnt& p) {
  u = wrap(uKnots_, uPeriod_, u), v = wrap(vKnots_, vPeriod_, v);
  spanOf(u, v).D0(u, v, p);
  if (moved_) p.Transform(trsf_);
}

void SplineSpans::d1(double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) {
  u = wrap(uKnots_, uPeriod_, u), v = wrap(vKnots_, vPeriod_, v);
  spanOf(u, v).D1(u, v, p, du, dv);
  if (moved_) {
    p.Transform(trsf_);
    du.Transform(trsf_);
    dv.Transform(trsf_);
  }
}

}  // namespace cetview::brep
