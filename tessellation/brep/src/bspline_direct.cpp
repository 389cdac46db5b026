#include "bspline_direct.h"

#include "bspline_basis.h"

#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>

namespace cetview::brep {

std::unique_ptr<BSplineDirect> BSplineDirect::create(const Handle(Geom_BSplineSurface)& s, const gp_Trsf& placement) {
  if (s.IsNull() || s->IsUPeriodic() || s->IsVPeriodic()) return nullptr;
  if (s->UDegree() < 1 || s->VDegree() < 1 || s->UDegree() > kMaxDegree || s->VDegree() > kMaxDegree) return nullptr;
  std::unique_ptr<BSplineDirect> d(new BSplineDirect);
  d->u_.degree = s->UDegree(), d->v_.degree = s->VDegree();
  d->u_.poles = s->NbUPoles(), d->v_.poles = s->NbVPoles();
  d->rational_ = s->IsURational() || s->IsVRational();
  auto flat = [](const TColStd_Array1OfReal& k, Direction& out) {
    out.knots.resize(static_cast<std::size_t>(k.Length()));
    for (int i = k.Lower(); i <= k.Upper(); ++i) out.knots[static_cast<std::size_t>(i - k.Lower())] = k(i);
    // A non-periodic B-spline has poles + degree + 1 flat knots.
    if (out.knots.size() != static_cast<std::size_t>(out.poles + out.degree + 1)) return false;
    out.index();
    return true;
  };
  if (!flat(s->UKnotSequence(), d->u_) || !flat(s->VKnotSequence(), d->v_)) return nullptr;
  const TColgp_Array2OfPnt& poles = s->Poles();
  const TColStd_Array2OfReal* weights = s->Weights();
  const std::size_t nu = static_cast<std::size_t>(d->u_.poles), nv = static_cast<std::size_t>(d->v_.poles);
  static_assert(sizeof(gp_Pnt) == 3 * sizeof(double), "gp_Pnt is its three coordinates");
  const gp_Pnt& first = poles(poles.LowerRow(), poles.LowerCol());
  const bool inPlace = !d->rational_ && placement.Form() == gp_Identity &&
                       static_cast<std::size_t>(poles.RowLength()) == nv &&
                       static_cast<std::size_t>(poles.ColLength()) == nu &&
                       &poles(poles.UpperRow(), poles.UpperCol()) == &first + (nu * nv - 1);
  d->stride_ = d->rational_ ? 4 : 3;
  if (inPlace) {
    d->surface_ = s;
    d->poles_ = reinterpret_cast<const double*>(&first);
  } else {
    d->ownPoles_.resize(static_cast<std::size_t>(d->stride_) * nu * nv);
    double* out = d->ownPoles_.data();
    for (int i = 1; i <= d->u_.poles; ++i) {
      for (int j = 1; j <= d->v_.poles; ++j, out += d->stride_) {
        // An affine map of the poles maps the surface (weights unchanged).
        const gp_Pnt p = poles(poles.LowerRow() + i - 1, poles.LowerCol() + j - 1).Transformed(placement);
        const double w = d->rational_ && weights
                             ? (*weights)(weights->LowerRow() + i - 1, weights->LowerCol() + j - 1)
                             : 1.0;
        out[0] = p.X() * w, out[1] = p.Y() * w, out[2] = p.Z() * w;
        if (d->rational_) out[3] = w;
      }
    }
    d->poles_ = d->ownPoles_.data();
  }
  d->buildPatches();
  return d;
}

void BSplineDirect::Direction::buildPower() {
  // Taylor coefficients at the span's midpoint: the k-th derivative of N_i comes from the k-th
  // derivative curve of the unit control vector e_i (degree p - k, control points by differences,
  // The NURBS Book 3.3), evaluated there and scaled by length^k / k!.
  const int p = degree, n = p + 1, spans = poles - degree;
  power.assign(static_cast<std::size_t>(spans * n * n), 0.0);
  mid.assign(static_cast<std::size_t>(spans), 0.0);
  length.assign(static_cast<std::size_t>(spans), 0.0);
  const double* U = knots.data();
  for (int s = p; s < poles; ++s) {
    const double h = U[s + 1] - U[s];
    const std::size_t si = static_cast<std::size_t>(s - p);
    mid[si] = 0.5 * (U[s] + U[s + 1]), length[si] = h;
    if (!(h > 0)) continue;
    double* A = power.data() + si * static_cast<std::size_t>(n * n);
    for (int j = 0; j < n; ++j) {
      double c[kMaxDegree + 1] = {};  // control values on global indices s-p .. s (local r)
      c[j] = 1.0;
      double scale = 1.0;  // length^k / k!
      for (int k = 0; k <= p; ++k) {
        if (k > 0) {
          // Derivative control points of degree p - k + 1 -> p - k, on local indices k .. p.
          const int q = p - k + 1;
          for (int r = p; r >= k; --r) {
            const int i = s - p + r;
            const double den = U[i + q] - U[i];
            c[r] = den != 0.0 ? q * (c[r] - c[r - 1]) / den : 0.0;
          }
          scale *= h / k;
        }
        // N_{s-(p-k) .. s} at the midpoint.
        double inv[kMaxDegree * (kMaxDegree + 1) / 2 + 1], N[kMaxDegree + 1];
        knotReciprocals(U, p - k, s, inv);
        basis<0>(U, inv, p - k, s, mid[si], N, nullptr);
        double value = 0.0;
        for (int r = k; r <= p; ++r) value += c[r] * N[r - k];
        A[j * n + k] = value * scale;
      }
    }
  }
}

void BSplineDirect::Direction::numberSpans() {
  // Knots of multiplicity m > 1 leave m - 1 empty spans in the flat sequence; only the others
  // get patches (a degree-8 direction with 3 interior knots of multiplicity 7: 4 of 22).
  patchIndex.assign(static_cast<std::size_t>(poles - degree), -1);
  patchSpans = 0;
  for (int s = degree; s < poles; ++s)
    if (knots[static_cast<std::size_t>(s + 1)] > knots[static_cast<std::size_t>(s)])
      patchIndex[static_cast<std::size_t>(s - degree)] = patchSpans++;
}

void BSplineDirect::buildPatches() {
  const int p = u_.degree, q = v_.degree;
  if (std::max(p, q) < kPatchDegree) return;
  u_.numberSpans();
  v_.numberSpans();
  const std::size_t spansU = static_cast<std::size_t>(u_.patchSpans), spansV = static_cast<std::size_t>(v_.patchSpans);
  const std::size_t perPatch = static_cast<std::size_t>(4 * (p + 1) * (q + 1));
  const std::size_t doubles = spansU * spansV * perPatch;
  const std::size_t poleDoubles = 4 * static_cast<std::size_t>(u_.poles) * static_cast<std::size_t>(v_.poles);
  if (doubles == 0 || doubles > kPatchDoubles || doubles > kPatchRatio * poleDoubles) return;
  u_.buildPower();
  v_.buildPower();
  patches_.assign(doubles, 0.0);
  const std::size_t stride = static_cast<std::size_t>(stride_),
                    rowStride = stride * static_cast<std::size_t>(v_.poles);
  const int nu = p + 1, nv = q + 1;
  for (std::size_t a = 0; a < u_.patchIndex.size(); ++a) {
    if (u_.patchIndex[a] < 0) continue;
    const double* Au = u_.power.data() + a * static_cast<std::size_t>(nu * nu);
    for (std::size_t b = 0; b < v_.patchIndex.size(); ++b) {
      if (v_.patchIndex[b] < 0) continue;
      const double* Av = v_.power.data() + b * static_cast<std::size_t>(nv * nv);
      double* C = patches_.data() + (static_cast<std::size_t>(u_.patchIndex[a]) * spansV +
                                     static_cast<std::size_t>(v_.patchIndex[b])) * perPatch;
      // C[k][l] = sum over i, j of Au[i][k] Av[j][l] P[a + i][b + j] (span a's first pole is a).
      for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
          const double* P = poles_ + (a + static_cast<std::size_t>(i)) * rowStride +
                            stride * (b + static_cast<std::size_t>(j));
          const double weight = stride == 4 ? P[3] : 1.0;
          for (int k = 0; k < nu; ++k) {
            const double wu = Au[i * nu + k];
            if (wu == 0.0) continue;
            for (int l = 0; l < nv; ++l) {
              const double w = wu * Av[j * nv + l];
              double* c = C + 4 * (k * nv + l);
              c[0] += w * P[0], c[1] += w * P[1], c[2] += w * P[2], c[3] += w * weight;
            }
          }
        }
      }
    }
  }
}

template <bool kDerivatives>
void BSplineDirect::evaluatePatch(double u, double v, int su, int sv, double* out) const {
  const int p = u_.degree, q = v_.degree, nv = q + 1;
  const std::size_t a = static_cast<std::size_t>(su - p), b = static_cast<std::size_t>(sv - q);
  const std::size_t patch = static_cast<std::size_t>(u_.patchIndex[a]) * static_cast<std::size_t>(v_.patchSpans) +
                            static_cast<std::size_t>(v_.patchIndex[b]);
  const double* C = patches_.data() + patch * static_cast<std::size_t>(4 * (p + 1) * nv);
  const double hu = u_.length[a], hv = v_.length[b];
  const double x = (u - u_.mid[a]) / hu, y = (v - v_.mid[b]) / hv;
  double s[4] = {0, 0, 0, 0}, su4[4] = {0, 0, 0, 0}, sv4[4] = {0, 0, 0, 0};
  for (int k = p; k >= 0; --k) {
    // Row k in y by Horner, with its y derivative.
    const double* row = C + 4 * static_cast<std::size_t>(k * nv);
    double r[4] = {row[4 * q], row[4 * q + 1], row[4 * q + 2], row[4 * q + 3]}, dr[4] = {0, 0, 0, 0};
    for (int l = q - 1; l >= 0; --l) {
      for (int c = 0; c < 4; ++c) {
        if (kDerivatives) dr[c] = dr[c] * y + r[c];
        r[c] = r[c] * y + row[4 * l + c];
      }
    }
    // Then in x.
    for (int c = 0; c < 4; ++c) {
      if (kDerivatives) su4[c] = su4[c] * x + s[c], sv4[c] = sv4[c] * x + dr[c];
      s[c] = s[c] * x + r[c];
    }
  }
  for (int c = 0; c < 4; ++c) out[c] = s[c];
  if (kDerivatives)
    for (int c = 0; c < 4; ++c) out[4 + c] = su4[c] / hu, out[8 + c] = sv4[c] / hv;
}

template <bool kDerivatives, int S, int PU, int PV>
void BSplineDirect::evaluate(double u, double v, int su, int sv, double* out) const {
  // out: the homogeneous point (4), and with derivatives its u (4) and v (4) derivatives; without
  // weights (S = 3) the weight is 1 and its derivatives 0.
  double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1], dNu[kMaxDegree + 1], dNv[kMaxDegree + 1];
  basis<PU>(u_.knots.data(), u_.inverses(su), u_.degree, su, u, Nu, kDerivatives ? dNu : nullptr);
  basis<PV>(v_.knots.data(), v_.inverses(sv), v_.degree, sv, v, Nv, kDerivatives ? dNv : nullptr);
  const int uDegree = PU > 0 ? PU : u_.degree, vDegree = PV > 0 ? PV : v_.degree;
  double s[4] = {0, 0, 0, 1}, su4[4] = {0, 0, 0, 0}, sv4[4] = {0, 0, 0, 0};
  const std::size_t rowStride = S * static_cast<std::size_t>(v_.poles);
  const double* base = poles_ + static_cast<std::size_t>(su - uDegree) * rowStride +
                       S * static_cast<std::size_t>(sv - vDegree);
  if (S == 4) s[3] = 0;
  for (int r = 0; r <= uDegree; ++r) {
    const double* row = base + static_cast<std::size_t>(r) * rowStride;
    double a[S] = {}, b[S] = {};
    for (int c = 0; c <= vDegree; ++c) {
      const double* q = row + S * c;
      for (int k = 0; k < S; ++k) a[k] += Nv[c] * q[k];
      if (kDerivatives)
        for (int k = 0; k < S; ++k) b[k] += dNv[c] * q[k];
    }
    for (int k = 0; k < S; ++k) s[k] += Nu[r] * a[k];
    if (kDerivatives) {
      for (int k = 0; k < S; ++k) su4[k] += dNu[r] * a[k], sv4[k] += Nu[r] * b[k];
    }
  }
  for (int k = 0; k < 4; ++k) out[k] = s[k];
  if (kDerivatives)
    for (int k = 0; k < 4; ++k) out[4 + k] = su4[k], out[8 + k] = sv4[k];
}

template <bool kDerivatives, int S, int PU>
void BSplineDirect::evaluateWithU(double u, double v, int su, int sv, double* out) const {
  switch (v_.degree) {
    case 1:
      return evaluate<kDerivatives, S, PU, 1>(u, v, su, sv, out);
    case 2:
      return evaluate<kDerivatives, S, PU, 2>(u, v, su, sv, out);
    case 3:
      return evaluate<kDerivatives, S, PU, 3>(u, v, su, sv, out);
    default:
      return evaluate<kDerivatives, S, PU, 0>(u, v, su, sv, out);
  }
}

template <bool kDerivatives, int S>
void BSplineDirect::evaluateWithStride(double u, double v, int su, int sv, double* out) const {
  // Degrees 1 to 3 each way (most faces of the sample models have one of them at least) with
  // their loops unrolled; others take the degree at run time.
  switch (u_.degree) {
    case 1:
      return evaluateWithU<kDerivatives, S, 1>(u, v, su, sv, out);
    case 2:
      return evaluateWithU<kDerivatives, S, 2>(u, v, su, sv, out);
    case 3:
      return evaluateWithU<kDerivatives, S, 3>(u, v, su, sv, out);
    default:
      return evaluateWithU<kDerivatives, S, 0>(u, v, su, sv, out);
  }
}

template <bool kDerivatives>
void BSplineDirect::evaluate(double u, double v, int su, int sv, double* out) const {
  if (!patches_.empty() && u_.patchIndex[static_cast<std::size_t>(su - u_.degree)] >= 0 &&
      v_.patchIndex[static_cast<std::size_t>(sv - v_.degree)] >= 0)
    return evaluatePatch<kDerivatives>(u, v, su, sv, out);
  if (stride_ == 4) return evaluateWithStride<kDerivatives, 4>(u, v, su, sv, out);
  return evaluateWithStride<kDerivatives, 3>(u, v, su, sv, out);
}

gp_Pnt BSplineDirect::value(double u, double v, int su, int sv) const {
  double h[4];
  evaluate<false>(u, v, su, sv, h);
  if (!rational_) return gp_Pnt(h[0], h[1], h[2]);
  return gp_Pnt(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
}

void BSplineDirect::d1(double u, double v, int su, int sv, gp_Pnt& p, gp_Vec& du, gp_Vec& dv) const {
  double h[12];
  evaluate<true>(u, v, su, sv, h);
  if (!rational_) {
    p.SetCoord(h[0], h[1], h[2]);
    du.SetCoord(h[4], h[5], h[6]);
    dv.SetCoord(h[8], h[9], h[10]);
    return;
  }
  // S = A / w: S' = (A' - w' S) / w.
  const double w = h[3];
  const gp_XYZ s(h[0] / w, h[1] / w, h[2] / w);
  p.SetXYZ(s);
  du.SetXYZ((gp_XYZ(h[4], h[5], h[6]) - h[7] * s) / w);
  dv.SetXYZ((gp_XYZ(h[8], h[9], h[10]) - h[11] * s) / w);
}

}  // namespace cetview::brep
