// SPDX-License-Identifier: MIT
// The hand-written floor the evaluation benchmarks compare against (issue 27): a power-basis span
// cache, the algorithm of Open CASCADE's BSplCLib_Cache written out plainly for one degree and one
// derivative order at a time, with every span cached up front instead of rebuilt on a span change.
//
// Per span s = [b_s, b_{s+1}) the homogeneous curve is stored as its Taylor coefficients at the span
// start in the normalised variable u = (t − b_s) / (b_{s+1} − b_s) ∈ [0, 1] (OCCT's normalisation):
// c_k = A^(k)(b_s) len^k / k!, so A(t) = Σ c_k u^k and A^(k)(t) = len^−k d^k/du^k Σ c_j u^j.
// Position and derivatives are nested Horner schemes (PLib::EvalPolynomial), rational ones follow the
// quotient rule (The NURBS Book eq. 4.8). The span of a parameter is the previous one when it still
// holds (sorted input), else a branch-free binary search over the breakpoints.
//
// The coefficients are built from HulaHoops' own derivatives at the span starts (outside every timed
// loop); the benchmarks check the reference's outputs against HulaHoops' and Open CASCADE's before
// timing anything, so a disagreement stops the run instead of being timed.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::bench {

/// A power-basis copy of a NURBS curve of degree P (R: rational).
template <int P, bool R>
class PowerBasisCurve {
 public:
  static constexpr int kLanes = R ? 4 : 3;

  explicit PowerBasisCurve(const nurbs::NurbsCurve& curve) {
    breaks_ = curve.knots().breakpoints();
    const std::size_t S = breaks_.size() - 1;
    inv_len_.resize(S);
    coef_.assign(S * (P + 1) * kLanes, 0.0);
    // The homogeneous numerator A (points w_i P_i) and the weight function w (as a 1-D curve),
    // both non-rational, give A^(k) and w^(k) at the span start.
    const auto pts = curve.control_points();
    const auto w = curve.weights();
    std::vector<Vec3> a_pts(pts.begin(), pts.end()), w_pts(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double wi = R ? w[i] : 1.0;
      a_pts[i] = pts[i] * wi;
      w_pts[i] = {wi, 0.0, 0.0};
    }
    const nurbs::NurbsCurve A(curve.knots(), a_pts), W(curve.knots(), w_pts);
    for (std::size_t s = 0; s < S; ++s) {
      const double len = breaks_[s + 1] - breaks_[s];
      inv_len_[s] = 1.0 / len;
      const auto da = A.derivatives(breaks_[s], P);
      const auto dw = W.derivatives(breaks_[s], P);
      double f = 1.0;  // len^k / k!
      for (int k = 0; k <= P; ++k) {
        if (k > 0) f *= len / k;
        double* c = &coef_[(s * (P + 1) + static_cast<std::size_t>(k)) * kLanes];
        for (int l = 0; l < 3; ++l) c[l] = da[static_cast<std::size_t>(k)][static_cast<std::size_t>(l)] * f;
        if constexpr (R) c[3] = dw[static_cast<std::size_t>(k)].x * f;
      }
    }
  }

  /// Span of t: `s` when it still holds, else a branch-free binary search (largest s with b_s <= t,
  /// clamped to the last span at the domain end).
  [[nodiscard]] std::size_t span(double t, std::size_t s) const {
    if (breaks_[s] <= t && t < breaks_[s + 1]) return s;
    const double* base = breaks_.data();
    std::size_t n = breaks_.size() - 1;  // candidate spans [base, base + n)
    while (n > 1) {
      const std::size_t half = n / 2;
      base = base[half] <= t ? base + half : base;
      n -= half;
    }
    return static_cast<std::size_t>(base - breaks_.data());
  }

  /// C(t); `s` is the span hint, updated.
  [[nodiscard]] Vec3 d0(double t, std::size_t& s) const {
    s = span(t, s);
    const double u = (t - breaks_[s]) * inv_len_[s];
    const double* c = &coef_[s * (P + 1) * kLanes];
    double h[kLanes];
    for (int l = 0; l < kLanes; ++l) h[l] = c[P * kLanes + l];
    for (int j = P - 1; j >= 0; --j)
      for (int l = 0; l < kLanes; ++l) h[l] = h[l] * u + c[j * kLanes + l];
    if constexpr (R) {
      const double inv = 1.0 / h[3];
      return {h[0] * inv, h[1] * inv, h[2] * inv};
    } else {
      return {h[0], h[1], h[2]};
    }
  }

  /// {C, C', C'', C'''}(t) into out[0..3]; `s` is the span hint, updated.
  void d3(double t, std::size_t& s, Vec3* out) const {
    s = span(t, s);
    const double il = inv_len_[s];
    const double u = (t - breaks_[s]) * il;
    const double* c = &coef_[s * (P + 1) * kLanes];
    // Nested Horner: e0 = f(u), e1 = f'(u), e2 = f''(u) / 2, e3 = f'''(u) / 6.
    double e0[kLanes], e1[kLanes], e2[kLanes], e3[kLanes];
    for (int l = 0; l < kLanes; ++l) {
      e0[l] = c[P * kLanes + l];
      e1[l] = e2[l] = e3[l] = 0.0;
    }
    for (int j = P - 1; j >= 0; --j)
      for (int l = 0; l < kLanes; ++l) {
        e3[l] = e3[l] * u + e2[l];
        e2[l] = e2[l] * u + e1[l];
        e1[l] = e1[l] * u + e0[l];
        e0[l] = e0[l] * u + c[j * kLanes + l];
      }
    const double s1 = il, s2 = 2.0 * il * il, s3 = 6.0 * il * il * il;
    if constexpr (!R) {
      out[0] = {e0[0], e0[1], e0[2]};
      out[1] = {e1[0] * s1, e1[1] * s1, e1[2] * s1};
      out[2] = {e2[0] * s2, e2[1] * s2, e2[2] * s2};
      out[3] = {e3[0] * s3, e3[1] * s3, e3[2] * s3};
    } else {
      const double w0 = e0[3], w1 = e1[3] * s1, w2 = e2[3] * s2, w3 = e3[3] * s3;
      const double inv = 1.0 / w0;
      const Vec3 c0 = Vec3{e0[0], e0[1], e0[2]} * inv;
      const Vec3 c1 = (Vec3{e1[0], e1[1], e1[2]} * s1 - w1 * c0) * inv;
      const Vec3 c2 = (Vec3{e2[0], e2[1], e2[2]} * s2 - 2.0 * w1 * c1 - w2 * c0) * inv;
      const Vec3 c3 = (Vec3{e3[0], e3[1], e3[2]} * s3 - 3.0 * w1 * c2 - 3.0 * w2 * c1 - w3 * c0) * inv;
      out[0] = c0;
      out[1] = c1;
      out[2] = c2;
      out[3] = c3;
    }
  }

  /// κ(t) and τ(t) from C', C'', C''' (κ = |C' × C''| / |C'|³, τ = (C' × C'') · C''' / |C' × C''|²).
  void curvature_torsion(double t, std::size_t& s, double& kappa, double& tau) const {
    Vec3 d[4];
    d3(t, s, d);
    const Vec3 a = cross(d[1], d[2]);
    const double a2 = dot(a, a);
    const double v2 = dot(d[1], d[1]);
    kappa = std::sqrt(a2 / (v2 * v2 * v2));
    tau = dot(a, d[3]) / a2;
  }

 private:
  std::vector<double> breaks_, inv_len_, coef_;
};

}  // namespace hula::bench
