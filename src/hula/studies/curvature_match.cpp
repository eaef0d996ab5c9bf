// SPDX-License-Identifier: MIT
#include "hula/studies/curvature_match.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/studies/detail/profile_kernel_select.hpp"

namespace hula::studies {

namespace {

// τ is undefined where |C' × C''| <= kTorsionCutoff |C'|³, i.e. κ below 1e-12 per model unit: below it the
// binormal is noise (DESIGN: undefined quantities are NaN, documented).
constexpr double kTorsionCutoff = 1e-12;
constexpr const char* kAxis[3] = {"x", "y", "z"};

std::string indexed(const char* field, std::size_t i) { return std::string(field) + "[" + std::to_string(i) + "]"; }

template <class V>
void grow(std::vector<V>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}

Vec3 checked_direction(const Vec3& d, const char* field) {
  if (!is_finite(d)) throw Error(Errc::NonFiniteInput, std::string(field) + " is not finite", {.field = field});
  const double len = norm(d);
  if (!(len > 0.0)) throw Error(Errc::InvalidArgument, std::string(field) + " is the zero vector", {.field = field});
  return d / len;
}

// Chord slopes (P_{k+1} − P_k) / h_k of the D coordinates (compile-time, so pairs of coordinates share
// one vector division).
template <std::size_t D>
void chord_slopes(std::size_t n, const Vec3* points, const double* h, double* slopes) {
  for (std::size_t k = 0; k + 1 < n; ++k) {
    double p0[D], p1[D];
    for (std::size_t c = 0; c < D; ++c) {
      p0[c] = points[k][c];
      p1[c] = points[k + 1][c];
    }
    for (std::size_t c = 0; c < D; ++c) slopes[3 * k + c] = (p1[c] - p0[c]) / h[k];
  }
}

// Per-span coefficients of C' and C'' from the moments: b = slope − h (2 M_k + M_{k+1}) / 6,
// c = M_k / 2, d = (M_{k+1} − M_k) / (6 h), at coef[9 k + 3 c + 0…2].
template <std::size_t D>
void span_coefficients(std::size_t n, const double* slopes, const double* h, const double* M, double* coef) {
  for (std::size_t k = 0; k + 1 < n; ++k) {
    double b[D], cc[D], d[D];
    for (std::size_t c = 0; c < D; ++c) {
      const double m0 = M[3 * k + c], m1 = M[3 * (k + 1) + c];
      b[c] = slopes[3 * k + c] - h[k] * (2.0 * m0 + m1) / 6.0;
      cc[c] = 0.5 * m0;
      d[c] = (m1 - m0) / (6.0 * h[k]);
    }
    for (std::size_t c = 0; c < D; ++c) {
      double* q = coef + 9 * k + 3 * c;
      q[0] = b[c];
      q[1] = cc[c];
      q[2] = d[c];
    }
  }
}

// Solves the moment system in place (sample()'s Thomas algorithm): diag and the sub-diagonal h[k − 1]
// (last_lower on the last row), upper becomes c'_k, rhs becomes d'_k, M the moments. Running values (the
// previous row, the next moment) stay in locals: reloading them from the arrays just written put a
// store-to-load forward on every step's critical path.
template <std::size_t D>
void thomas_moments(std::size_t n, const double* diag, double* upper, double* rhs, const double* h, double last_lower,
                    double* M) {
  const std::size_t last = n - 1;
  double upper_prev = 0.0, rhs_prev[D];
  {
    const double inv = 1.0 / diag[0];
    upper[0] *= inv;
    upper_prev = upper[0];
    for (std::size_t c = 0; c < D; ++c) {
      rhs[c] *= inv;
      rhs_prev[c] = rhs[c];
    }
  }
  for (std::size_t k = 1; k < n; ++k) {
    const double lower = k == last ? last_lower : h[k - 1];
    const double inv = 1.0 / (diag[k] - lower * upper_prev);
    upper[k] *= inv;
    upper_prev = upper[k];
    for (std::size_t c = 0; c < D; ++c) {
      rhs_prev[c] = (rhs[3 * k + c] - lower * rhs_prev[c]) * inv;
      rhs[3 * k + c] = rhs_prev[c];
    }
  }
  double next[D];
  for (std::size_t c = 0; c < D; ++c) M[3 * last + c] = next[c] = rhs[3 * last + c];
  for (std::size_t k = last; k-- > 0;)
    for (std::size_t c = 0; c < D; ++c) M[3 * k + c] = next[c] = rhs[3 * k + c] - upper[k] * next[c];
}

}  // namespace

SplineProfileSampler::SplineProfileSampler(std::size_t point_count, int dimension, std::vector<double> sample_u,
                                           std::optional<Vec3> start_tangent, std::optional<Vec3> end_tangent,
                                           ProfileAbscissa abscissa)
    : n_(point_count), dim_(dimension), u_(std::move(sample_u)), abscissa_(abscissa) {
  if (n_ < 2)
    throw Error(Errc::TooFewPoints, "the spline needs at least 2 points, got " + std::to_string(n_),
                {.field = "points"});
  if (dim_ != 2 && dim_ != 3)
    throw Error(Errc::InvalidArgument, "dimension = " + std::to_string(dim_) + " must be 2 or 3",
                {.field = "dimension"});
  for (std::size_t i = 0; i < u_.size(); ++i) {
    if (!std::isfinite(u_[i]))
      throw Error(Errc::NonFiniteInput, indexed("samples", i) + " is not finite", {.field = "samples", .index = i});
    if (u_[i] < 0.0 || u_[i] > 1.0 || (i > 0 && u_[i] < u_[i - 1]))
      throw Error(Errc::InvalidArgument,
                  indexed("samples", i) + " = " + format_number(u_[i]) + " must be in [0, 1] and non-decreasing",
                  {.field = "samples", .index = i});
  }
  if (start_tangent) start_ = checked_direction(*start_tangent, "start_tangent");
  if (end_tangent) end_ = checked_direction(*end_tangent, "end_tangent");
  if (dim_ == 2) {
    if (start_ && start_->z != 0.0)
      throw Error(Errc::InvalidArgument, "start_tangent has z != 0 in a planar study", {.field = "start_tangent"});
    if (end_ && end_->z != 0.0)
      throw Error(Errc::InvalidArgument, "end_tangent has z != 0 in a planar study", {.field = "end_tangent"});
  }
}

bool SplineProfileSampler::sample(std::span<const Vec3> points, Workspace& ws, std::span<double> kappa,
                                  std::span<double> tau) const {
  if (points.size() != n_ || kappa.size() != u_.size() || (!tau.empty() && tau.size() != u_.size()))
    throw Error(Errc::InvalidArgument,
                "sample: expected " + std::to_string(n_) + " points and " + std::to_string(u_.size()) +
                    " samples, got " + std::to_string(points.size()) + " points, " + std::to_string(kappa.size()) +
                    " kappa and " + std::to_string(tau.size()) + " tau values",
                {.field = "points"});
  const std::size_t n = n_;
  const std::size_t D = static_cast<std::size_t>(dim_);
  grow(ws.t, n);
  grow(ws.h, n);
  grow(ws.diag, n);
  grow(ws.upper, n);
  grow(ws.rhs, 3 * n);
  grow(ws.moments, 3 * n);
  grow(ws.coefficients, 9 * n);
  grow(ws.span_length, n);
  auto fail = [&] {
    std::fill(kappa.begin(), kappa.end(), kNaN);
    std::fill(tau.begin(), tau.end(), kNaN);
    return false;
  };
  // Chord-length parameters normalised to [0, 1] (thesis eq. 29). Running values (the previous t, the
  // previous row of the elimination, the next moment) stay in locals below: reloading them from the
  // arrays just written put a store-to-load forward on every step's critical path.
  double* t = ws.t.data();
  double* h = ws.h.data();
  t[0] = 0.0;
  double acc = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    double d2 = 0.0;
    for (std::size_t c = 0; c < D; ++c) {
      const double e = points[k][c] - points[k - 1][c];
      d2 += e * e;
    }
    acc = acc + std::sqrt(d2);
    t[k] = acc;
  }
  const double length = t[n - 1];
  if (!(length > 0.0) || !std::isfinite(length)) return fail();
  const double inv_length = 1.0 / length;
  for (std::size_t k = 1; k < n; ++k) t[k] *= inv_length;
  t[n - 1] = 1.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = t[k + 1] - t[k];
    if (!(h[k] > 0.0)) return fail();
  }
  // Chord slopes (P_{k+1} − P_k) / h_k, each computed once.
  grow(ws.slopes, 3 * n);
  double* slopes = ws.slopes.data();
  if (D == 2)
    chord_slopes<2>(n, points.data(), h, slopes);
  else
    chord_slopes<3>(n, points.data(), h, slopes);
  auto slope = [&](std::size_t k, std::size_t c) { return slopes[3 * k + c]; };
  // Tridiagonal system for the moments M_k (same matrix for every coordinate).
  double* diag = ws.diag.data();
  double* upper = ws.upper.data();
  double* rhs = ws.rhs.data();
  if (start_) {
    diag[0] = 2.0;
    upper[0] = 1.0;
    for (std::size_t c = 0; c < D; ++c) rhs[c] = 6.0 * (slope(0, c) - (*start_)[c] * length) / h[0];
  } else {
    diag[0] = 1.0;
    upper[0] = 0.0;
    for (std::size_t c = 0; c < D; ++c) rhs[c] = 0.0;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    diag[k] = 2.0 * (h[k - 1] + h[k]);
    upper[k] = h[k];
    for (std::size_t c = 0; c < D; ++c) rhs[3 * k + c] = 6.0 * (slope(k, c) - slope(k - 1, c));
  }
  const std::size_t last = n - 1;
  double last_lower = 0.0;
  if (end_) {
    diag[last] = 2.0;
    last_lower = 1.0;
    for (std::size_t c = 0; c < D; ++c)
      rhs[3 * last + c] = 6.0 * ((*end_)[c] * length - slope(last - 1, c)) / h[last - 1];
  } else {
    diag[last] = 1.0;
    for (std::size_t c = 0; c < D; ++c) rhs[3 * last + c] = 0.0;
  }
  upper[last] = 0.0;
  // Thomas algorithm (diagonally dominant: no pivoting needed); upper becomes c', rhs becomes d'. The
  // coordinate count is a compile-time constant so the running rows live in registers.
  double* M = ws.moments.data();
  if (D == 2)
    thomas_moments<2>(n, diag, upper, rhs, h, last_lower, M);
  else
    thomas_moments<3>(n, diag, upper, rhs, h, last_lower, M);
  // Per-span coefficients of C' and C'': b, c (= M_k / 2), d.
  double* coef = ws.coefficients.data();
  if (D == 2)
    span_coefficients<2>(n, slopes, h, M, coef);
  else
    span_coefficients<3>(n, slopes, h, M, coef);
  // |C'(t_k + w)| on span k.
  auto speed = [&](std::size_t span, double w) {
    const double* q = coef + 9 * span;
    double v2 = 0.0;
    for (std::size_t c = 0; c < D; ++c) {
      const double d = q[3 * c] + w * (2.0 * q[3 * c + 1] + 3.0 * q[3 * c + 2] * w);
      v2 += d * d;
    }
    return std::sqrt(v2);
  };
  // ∫_a^b |C'(t_k + v)| dv by 8-point Gauss–Legendre (Boost.Math's positive nodes on [-1, 1] and their weights).
  using Gauss8 = boost::math::quadrature::gauss<double, 8>;
  const auto& gauss_nodes = Gauss8::abscissa();
  const auto& gauss_weights = Gauss8::weights();
  auto integral = [&](std::size_t span, double a, double b) {
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    for (std::size_t j = 0; j < gauss_nodes.size(); ++j)
      sum += gauss_weights[j] * (speed(span, mid - half * gauss_nodes[j]) + speed(span, mid + half * gauss_nodes[j]));
    return half * sum;
  };
  // Span lengths on kPanels panels (the speed of a clamped end span can vary by orders of magnitude); between
  // consecutive samples a single 8-point rule on the short interval is enough.
  constexpr int kPanels = 8;
  const bool by_length = abscissa_ == ProfileAbscissa::ArcLength;
  double* S = ws.span_length.data();  // cumulative length at t_k
  if (by_length) {
    S[0] = 0.0;
    for (std::size_t j = 0; j + 1 < n; ++j) {
      const double p = h[j] / kPanels;
      double len = 0.0;
      for (int panel = 0; panel < kPanels; ++panel) len += integral(j, p * panel, p * (panel + 1));
      S[j + 1] = S[j] + len;
    }
    if (!(S[n - 1] > 0.0) || !std::isfinite(S[n - 1])) return fail();
  }
  const bool want_tau = !tau.empty();
  if (!by_length) {
    // κ at the parameter: the samples of each span in one run of the vectorised kernel
    // (detail/profile_kernel.hpp: the operations below, lane by lane). The abscissae are sorted, so a
    // sample belongs to the first span k (from the previous one) with u <= t[k + 1], the last span
    // taking the rest.
    const detail::ProfileKernel kernel = detail::profile_kernel(dim_, want_tau);
    const std::size_t m = u_.size();
    if (ws.span_of.size() < m) ws.span_of.resize(m);
    unsigned* span = ws.span_of.data();
    std::size_t i = 0;
    for (std::size_t k = 0; k + 1 < n && i < m; ++k) {
      std::size_t end = m;
      if (k + 2 < n)
        end = static_cast<std::size_t>(
            std::upper_bound(u_.begin() + static_cast<std::ptrdiff_t>(i), u_.end(), t[k + 1]) - u_.begin());
      std::fill(span + i, span + end, static_cast<unsigned>(k));
      i = end;
    }
    const double probe =
        kernel(coef, t, span, u_.data(), m, kappa.data(), want_tau ? tau.data() : nullptr);  // 0 or NaN
    if (probe != 0.0) return fail();
    return true;
  }
  // Samples: the abscissae are sorted, so the span only moves forward.
  std::size_t k = 0;
  double w_base = 0.0, g_base = 0.0;  // last arc-length sample in span k: local parameter and length from t_k
  for (std::size_t i = 0; i < u_.size(); ++i) {
    double w = 0.0;
    if (by_length) {
      const double s = u_[i] * S[n - 1];
      while (k + 2 < n && s > S[k + 1]) {
        ++k;
        w_base = g_base = 0.0;
      }
      // Newton on g_base + ∫_{w_base}^{w} |C'| = s - S[k], safeguarded to the span. Not Boost.Math's
      // newton_raphson_iterate: this is the fitness's inner loop, warm-started a step or two from the root,
      // and Boost's stop is relative to w, never met at a span start (w = 0), where this one is relative to h.
      const double goal = s - S[k];
      const double span_len = S[k + 1] - S[k];
      // Start from the last sample, one explicit step along the speed there (or proportionally if it vanishes).
      const double v0 = speed(k, w_base);
      w = v0 > 0.0 ? w_base + (goal - g_base) / v0 : (span_len > 0.0 ? h[k] * goal / span_len : 0.0);
      w = std::clamp(w, 0.0, h[k]);
      for (int it = 0; it < 20; ++it) {
        const double v = speed(k, w);
        if (!(v > 0.0)) break;
        const double step = (g_base + integral(k, w_base, w) - goal) / v;
        w = std::clamp(w - step, 0.0, h[k]);
        // Relative 1e-13 in the local parameter: far below the matching's needs, and reachable in rounding.
        if (std::fabs(step) <= 1e-13 * h[k]) break;
      }
      w_base = w;
      g_base = goal;
    } else {
      const double u = u_[i];
      while (k + 2 < n && u > t[k + 1]) ++k;
      w = u - t[k];
    }
    const double* q = coef + 9 * k;
    double d1[3] = {0.0, 0.0, 0.0}, d2[3] = {0.0, 0.0, 0.0}, d3[3] = {0.0, 0.0, 0.0};
    for (std::size_t c = 0; c < D; ++c) {
      const double* s = q + 3 * c;
      d1[c] = s[0] + w * (2.0 * s[1] + 3.0 * s[2] * w);
      d2[c] = 2.0 * s[1] + 6.0 * s[2] * w;
      d3[c] = 6.0 * s[2];
    }
    const double cx = d1[1] * d2[2] - d1[2] * d2[1];
    const double cy = d1[2] * d2[0] - d1[0] * d2[2];
    const double cz = d1[0] * d2[1] - d1[1] * d2[0];
    const double cross2 = cx * cx + cy * cy + cz * cz;
    const double speed2 = d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2];
    const double speed3 = speed2 * std::sqrt(speed2);
    const double cross_norm = std::sqrt(cross2);
    kappa[i] = cross_norm / speed3;
    if (want_tau) {
      if (D == 2)
        tau[i] = 0.0;
      else if (cross_norm <= kTorsionCutoff * speed3)
        tau[i] = kNaN;
      else
        tau[i] = (cx * d3[0] + cy * d3[1] + cz * d3[2]) / cross2;
    }
    if (!std::isfinite(kappa[i])) return fail();
  }
  return true;
}

bool SplineProfileSampler::sample_jacobian(std::span<const Vec3> points, Workspace& ws,
                                           std::span<const std::size_t> coordinates, std::span<double> kappa,
                                           std::span<double> jacobian) const {
  if (abscissa_ != ProfileAbscissa::Parameter)
    throw Error(Errc::InvalidArgument, "sample_jacobian: the exact Jacobian needs abscissa \"parameter\"",
                {.field = "abscissa"});
  const std::size_t m = u_.size(), columns = coordinates.size();
  if (jacobian.size() != m * columns)
    throw Error(Errc::InvalidArgument,
                "sample_jacobian: expected " + std::to_string(m * columns) + " Jacobian values, got " +
                    std::to_string(jacobian.size()),
                {.field = "jacobian"});
  for (std::size_t j = 0; j < columns; ++j)
    if (coordinates[j] / 3 >= n_ || coordinates[j] % 3 >= static_cast<std::size_t>(dim_))
      throw Error(Errc::InvalidArgument,
                  indexed("coordinates", j) + " = " + std::to_string(coordinates[j]) + " is not a coordinate of " +
                      std::to_string(n_) + " points in dimension " + std::to_string(dim_),
                  {.field = "coordinates", .index = j});
  if (!sample(points, ws, kappa)) {
    std::fill(jacobian.begin(), jacobian.end(), kNaN);
    return false;
  }
  // sample() left t, h, the moments M, the span coefficients, diag (A's diagonal) and upper (A's factor c'_k).
  const std::size_t n = n_, D = static_cast<std::size_t>(dim_), last = n - 1;
  grow(ws.pivot, n);
  grow(ws.dt, n);
  grow(ws.dh, n);
  grow(ws.dslope, 3 * n);
  grow(ws.drhs, 3 * n);
  grow(ws.dmoments, 3 * n);
  const double* t = ws.t.data();
  const double* h = ws.h.data();
  const double* M = ws.moments.data();
  const double* coef = ws.coefficients.data();
  const double* cprime = ws.upper.data();
  double* pivot = ws.pivot.data();
  double* dt = ws.dt.data();
  double* dh = ws.dh.data();
  double* dslope = ws.dslope.data();
  double* drhs = ws.drhs.data();
  double* dM = ws.dmoments.data();
  double length = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    double d2 = 0.0;
    for (std::size_t c = 0; c < D; ++c) d2 += (points[k][c] - points[k - 1][c]) * (points[k][c] - points[k - 1][c]);
    length += std::sqrt(d2);
  }
  auto chord = [&](std::size_t k) {  // |P_k − P_{k−1}|
    double d2 = 0.0;
    for (std::size_t c = 0; c < D; ++c) d2 += (points[k][c] - points[k - 1][c]) * (points[k][c] - points[k - 1][c]);
    return std::sqrt(d2);
  };
  auto slope = [&](std::size_t k, std::size_t c) { return (points[k + 1][c] - points[k][c]) / h[k]; };
  // A's sub-diagonal and the Thomas pivots 1 / (diag_k − lower_k c'_{k−1}) of sample()'s elimination.
  auto lower = [&](std::size_t k) { return k == last ? (end_ ? 1.0 : 0.0) : h[k - 1]; };
  pivot[0] = 1.0 / ws.diag[0];
  for (std::size_t k = 1; k < n; ++k) pivot[k] = 1.0 / (ws.diag[k] - lower(k) * cprime[k - 1]);
  // What does not depend on the column, once per sample: span k, w, C', C'', X = C' × C'', |X|, |C'|², |C'|³.
  constexpr std::size_t kCached = 16;
  thread_local std::vector<double> cache;  // one per thread, grown once (no allocation when warm)
  grow(cache, kCached * m);
  {
    std::size_t k = 0;
    for (std::size_t i = 0; i < m; ++i) {
      while (k + 2 < n && u_[i] > t[k + 1]) ++k;
      double* e = cache.data() + kCached * i;
      const double w = u_[i] - t[k];
      e[0] = static_cast<double>(k);
      e[1] = w;
      double* d1 = e + 2;
      double* d2 = e + 5;
      for (std::size_t c = 0; c < 3; ++c) {
        const double* q = coef + 9 * k + 3 * c;
        d1[c] = c < D ? q[0] + w * (2.0 * q[1] + 3.0 * q[2] * w) : 0.0;
        d2[c] = c < D ? 2.0 * q[1] + 6.0 * q[2] * w : 0.0;
      }
      e[8] = d1[1] * d2[2] - d1[2] * d2[1];
      e[9] = d1[2] * d2[0] - d1[0] * d2[2];
      e[10] = d1[0] * d2[1] - d1[1] * d2[0];
      e[11] = std::sqrt(e[8] * e[8] + e[9] * e[9] + e[10] * e[10]);
      e[12] = d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2];
      e[13] = e[12] * std::sqrt(e[12]);
    }
  }
  for (std::size_t j = 0; j < columns; ++j) {
    const std::size_t p = coordinates[j] / 3, axis = coordinates[j] % 3;
    // Chord-length parameters t_k = T_k / L: dT_k = Σ_{i<=k} dc_i, only the chords at p and p + 1 change.
    const double dc_p = p >= 1 ? (points[p][axis] - points[p - 1][axis]) / chord(p) : 0.0;
    const double dc_next = p + 1 < n ? -(points[p + 1][axis] - points[p][axis]) / chord(p + 1) : 0.0;
    const double dlength = dc_p + dc_next;
    for (std::size_t k = 0; k < n; ++k) {
      const double dT = (k >= p ? dc_p : 0.0) + (k >= p + 1 ? dc_next : 0.0);
      dt[k] = k == 0 || k == last ? 0.0 : (dT - t[k] * dlength) / length;
    }
    for (std::size_t k = 0; k + 1 < n; ++k) dh[k] = dt[k + 1] - dt[k];
    // Slopes (P_{k+1} − P_k) / h_k.
    for (std::size_t k = 0; k + 1 < n; ++k)
      for (std::size_t c = 0; c < D; ++c) {
        const double dp = c == axis ? (k + 1 == p ? 1.0 : 0.0) - (k == p ? 1.0 : 0.0) : 0.0;
        dslope[3 * k + c] = (dp - slope(k, c) * dh[k]) / h[k];
      }
    // A dM = db − dA M (the end rows of A are constant; their right-hand sides depend on L and h).
    for (std::size_t c = 0; c < D; ++c) {
      if (start_) {
        const double b0 = 6.0 * (slope(0, c) - (*start_)[c] * length) / h[0];
        drhs[c] = (6.0 * (dslope[c] - (*start_)[c] * dlength) - b0 * dh[0]) / h[0];
      } else {
        drhs[c] = 0.0;
      }
      for (std::size_t k = 1; k < last; ++k)
        drhs[3 * k + c] =
            6.0 * (dslope[3 * k + c] - dslope[3 * (k - 1) + c]) -
            (dh[k - 1] * M[3 * (k - 1) + c] + 2.0 * (dh[k - 1] + dh[k]) * M[3 * k + c] + dh[k] * M[3 * (k + 1) + c]);
      if (end_) {
        const double bl = 6.0 * ((*end_)[c] * length - slope(last - 1, c)) / h[last - 1];
        drhs[3 * last + c] =
            (6.0 * ((*end_)[c] * dlength - dslope[3 * (last - 1) + c]) - bl * dh[last - 1]) / h[last - 1];
      } else {
        drhs[3 * last + c] = 0.0;
      }
      // The factorisation of sample() reused: forward elimination, then back substitution.
      dM[c] = drhs[c] * pivot[0];
      for (std::size_t k = 1; k < n; ++k) dM[3 * k + c] = (drhs[3 * k + c] - lower(k) * dM[3 * (k - 1) + c]) * pivot[k];
      for (std::size_t k = last; k-- > 0;) dM[3 * k + c] -= cprime[k] * dM[3 * (k + 1) + c];
    }
    // Each sample: C' = b + 2 c w + 3 d w², C'' = 2 c + 6 d w on span k, w = u − t_k (dw = −dt_k), then
    // dκ = d|X| / |C'|³ − (3/2) |X| d(|C'|²) / |C'|⁵ with X = C' × C'', d|X| = X · dX / |X|.
    for (std::size_t i = 0; i < m; ++i) {
      const double* e = cache.data() + kCached * i;
      const auto k = static_cast<std::size_t>(e[0]);
      const double w = e[1], dw = -dt[k];
      const double* d1 = e + 2;
      const double* d2 = e + 5;
      double e1[3] = {0.0, 0.0, 0.0}, e2[3] = {0.0, 0.0, 0.0};
      for (std::size_t c = 0; c < D; ++c) {
        const double* q = coef + 9 * k + 3 * c;
        const double m0 = M[3 * k + c], m1 = M[3 * (k + 1) + c];
        const double dm0 = dM[3 * k + c], dm1 = dM[3 * (k + 1) + c];
        const double db = dslope[3 * k + c] - dh[k] * (2.0 * m0 + m1) / 6.0 - h[k] * (2.0 * dm0 + dm1) / 6.0;
        const double dc = 0.5 * dm0;
        const double dd = (dm1 - dm0) / (6.0 * h[k]) - q[2] * dh[k] / h[k];
        e1[c] = db + w * (2.0 * dc + 3.0 * dd * w) + d2[c] * dw;
        e2[c] = 2.0 * dc + 6.0 * dd * w + 6.0 * q[2] * dw;
      }
      const double* X = e + 8;
      const double dX[3] = {e1[1] * d2[2] - e1[2] * d2[1] + d1[1] * e2[2] - d1[2] * e2[1],
                            e1[2] * d2[0] - e1[0] * d2[2] + d1[2] * e2[0] - d1[0] * e2[2],
                            e1[0] * d2[1] - e1[1] * d2[0] + d1[0] * e2[1] - d1[1] * e2[0]};
      const double xn = e[11], S = e[12], s32 = e[13];
      const double dxn = xn > 0.0 ? (X[0] * dX[0] + X[1] * dX[1] + X[2] * dX[2]) / xn : 0.0;
      const double dS = 2.0 * (d1[0] * e1[0] + d1[1] * e1[1] + d1[2] * e1[2]);
      jacobian[i * columns + j] = dxn / s32 - 1.5 * xn * dS / (s32 * S);
    }
  }
  for (const double v : jacobian)
    if (!std::isfinite(v)) {
      std::fill(jacobian.begin(), jacobian.end(), kNaN);
      return false;
    }
  return true;
}

nurbs::NurbsCurve SplineProfileSampler::curve(std::span<const Vec3> points) const {
  nurbs::InterpolationOptions options;
  options.dimension = dim_;
  options.parameterisation = nurbs::Parameterisation::ChordLength;
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) length += distance(points[k - 1], points[k]);
  if (start_) options.start = nurbs::EndCondition::clamped(*start_ * length);
  if (end_) options.end = nurbs::EndCondition::clamped(*end_ * length);
  std::vector<Vec3> p(points.begin(), points.end());
  if (dim_ == 2)
    for (Vec3& v : p) v.z = 0.0;
  return nurbs::interpolate_cubic(p, options);
}

void CurvatureMatchSetup::validate() const {
  validity.validate();
  if (points.size() < 2)
    throw Error(Errc::TooFewPoints, "points: at least 2 data points are needed, got " + std::to_string(points.size()),
                {.field = "points"});
  if (dimension != 2 && dimension != 3)
    throw Error(Errc::InvalidArgument, "dimension = " + std::to_string(dimension) + " must be 2 or 3",
                {.field = "dimension"});
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      if (!std::isfinite(points[i][c]))
        throw Error(Errc::NonFiniteInput, indexed("points", i) + "." + kAxis[c] + " is not finite",
                    {.field = "points", .index = i, .component = c});
  for (const auto* offsets : {&lower, &upper}) {
    const char* name = offsets == &lower ? "lower" : "upper";
    if (offsets->size() != points.size())
      throw Error(Errc::InvalidArgument,
                  std::string(name) + " has " + std::to_string(offsets->size()) + " entries but there are " +
                      std::to_string(points.size()) + " points",
                  {.field = name});
    for (std::size_t i = 0; i < offsets->size(); ++i)
      for (std::size_t c = 0; c < 3; ++c) {
        const double v = (*offsets)[i][c];
        const std::string where = indexed(name, i) + "." + kAxis[c];
        const ErrorWhere at{.field = name, .index = i, .component = c};
        if (!std::isfinite(v)) throw Error(Errc::NonFiniteInput, where + " is not finite", at);
        if (v < 0.0)
          throw Error(Errc::InvalidArgument,
                      where + " = " + format_number(v) +
                          " is negative: the bounds would exclude the start value (offsets are distances below / "
                          "above it)",
                      at);
        if (i == 0 && v != 0.0)
          throw Error(Errc::InvalidArgument,
                      where + " = " + format_number(v) + " would move the start point, which is fixed (thesis 8.2.1)",
                      at);
        if (c == 2 && dimension == 2 && v != 0.0)
          throw Error(Errc::InvalidArgument, where + " = " + format_number(v) + " but the study is planar", at);
      }
  }
  if (!proximity.empty() && proximity.size() != points.size())
    throw Error(Errc::InvalidArgument,
                "proximity has " + std::to_string(proximity.size()) + " weights but there are " +
                    std::to_string(points.size()) + " points",
                {.field = "proximity"});
  for (std::size_t i = 0; i < proximity.size(); ++i)
    if (!(std::isfinite(proximity[i]) && proximity[i] >= 0.0))
      throw Error(Errc::InvalidArgument,
                  indexed("proximity", i) + " = " + format_number(proximity[i]) + " must be finite and >= 0",
                  {.field = "proximity", .index = i});
  if (!proximity_centre.empty() && proximity_centre.size() != points.size())
    throw Error(Errc::InvalidArgument,
                "proximity_centre has " + std::to_string(proximity_centre.size()) + " points but there are " +
                    std::to_string(points.size()),
                {.field = "proximity_centre"});
  for (std::size_t i = 0; i < proximity_centre.size(); ++i)
    if (!(std::isfinite(proximity_centre[i].x) && std::isfinite(proximity_centre[i].y) &&
          std::isfinite(proximity_centre[i].z)))
      throw Error(Errc::NonFiniteInput, indexed("proximity_centre", i) + " is not finite",
                  {.field = "proximity_centre", .index = i});
  bool any_free = false;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) any_free = any_free || lower[i][c] > 0.0 || upper[i][c] > 0.0;
  if (!any_free)
    throw Error(Errc::InvalidArgument, "lower/upper: every coordinate is fixed, nothing to optimise",
                {.field = "upper"});
  if (samples < 2)
    throw Error(Errc::InvalidArgument, "samples = " + std::to_string(samples) + " must be at least 2",
                {.field = "samples"});
  if (!target) throw Error(Errc::InvalidArgument, "target: no target curvature profile", {.field = "target"});
}

std::vector<double> uniform_abscissae(std::size_t samples) {
  std::vector<double> u(samples);
  for (std::size_t i = 0; i + 1 < samples; ++i) u[i] = static_cast<double>(i) / static_cast<double>(samples - 1);
  if (samples > 0) u[samples - 1] = 1.0;
  return u;
}

namespace {

// Validates the setup first, so that a bad setup is reported before anything is built from it.
SplineProfileSampler make_sampler(const CurvatureMatchSetup& s) {
  s.validate();
  return SplineProfileSampler(s.points.size(), s.dimension, uniform_abscissae(s.samples), s.start_tangent,
                              s.end_tangent, s.abscissa);
}

}  // namespace

CurvatureMatch::CurvatureMatch(CurvatureMatchSetup setup) : setup_(std::move(setup)), sampler_(make_sampler(setup_)) {
  target_.resize(setup_.samples);
  try {
    setup_.target->sample(sampler_.abscissae(), target_);
  } catch (const Error& e) {
    throw Error(e.code(), "target: " + e.message(), {.field = "target"});
  }
  for (std::size_t i = 0; i < target_.size(); ++i)
    if (!std::isfinite(target_[i]))
      throw Error(
          Errc::NonFiniteInput,
          "target(" + format_number(sampler_.abscissae()[i]) + ") is not finite (sample " + std::to_string(i) + ")",
          {.field = "target", .index = i});
  if (setup_.torsion_target) {
    torsion_target_.resize(setup_.samples);
    try {
      setup_.torsion_target->sample(sampler_.abscissae(), torsion_target_);
    } catch (const Error& e) {
      throw Error(e.code(), "torsion_target: " + e.message(), {.field = "torsion_target"});
    }
  }
  for (std::size_t i = 0; i < setup_.points.size(); ++i)
    for (std::size_t c = 0; c < static_cast<std::size_t>(setup_.dimension); ++c)
      if (setup_.lower[i][c] > 0.0 || setup_.upper[i][c] > 0.0) {
        free_.push_back({i, c});
        free_flat_.push_back(3 * i + c);
      }
  if (setup_.proximity_centre.empty()) setup_.proximity_centre = setup_.points;
  if (setup_.dimension == 2)
    for (auto* points : {&setup_.points, &setup_.proximity_centre})
      for (Vec3& p : *points) p.z = 0.0;
}

std::vector<optim::Variable> CurvatureMatch::variables(double precision) const {
  std::vector<optim::Variable> v;
  v.reserve(free_.size());
  for (const Free& f : free_) {
    const double x = setup_.points[f.point][f.coordinate];
    v.push_back({indexed("points", f.point) + "." + kAxis[f.coordinate], x - setup_.lower[f.point][f.coordinate],
                 x + setup_.upper[f.point][f.coordinate], precision});
  }
  return v;
}

std::vector<double> CurvatureMatch::start_variables() const {
  std::vector<double> x;
  x.reserve(free_.size());
  for (const Free& f : free_) x.push_back(setup_.points[f.point][f.coordinate]);
  return x;
}

void CurvatureMatch::points_from(std::span<const double> x, std::span<Vec3> out) const {
  HULA_ASSERT(x.size() == free_.size() && out.size() == setup_.points.size(), "points_from: wrong sizes");
  std::copy(setup_.points.begin(), setup_.points.end(), out.begin());
  for (std::size_t j = 0; j < free_.size(); ++j) out[free_[j].point][free_[j].coordinate] = x[j];
}

std::vector<double> CurvatureMatch::variables_from(std::span<const Vec3> points) const {
  HULA_ASSERT(points.size() == setup_.points.size(), "variables_from: wrong size");
  std::vector<double> x;
  x.reserve(free_.size());
  for (const Free& f : free_) x.push_back(points[f.point][f.coordinate]);
  return x;
}

bool CurvatureMatch::residuals(std::span<const double> x, SplineProfileSampler::Workspace& ws, std::span<Vec3> points,
                               std::span<double> r) const {
  points_from(x, points);
  if (!sampler_.sample(points, ws, r)) return false;
  for (std::size_t i = 0; i < r.size(); ++i) r[i] -= target_[i];
  return true;
}

bool CurvatureMatch::residuals_jacobian(std::span<const double> x, SplineProfileSampler::Workspace& ws,
                                        std::span<Vec3> points, std::span<double> r, std::span<double> jacobian) const {
  points_from(x, points);
  if (!sampler_.sample_jacobian(points, ws, free_flat_, r, jacobian)) return false;
  for (std::size_t i = 0; i < r.size(); ++i) r[i] -= target_[i];
  return true;
}

namespace {

// Eq. 31's (1/m) Σ |κ_i − κ*_i|, leaving r_i = κ_i − κ*_i in `kappa`: four partial sums over i mod 4
// (each in sample order), combined as (s0 + s1) + (s2 + s3). The order is fixed (it does not depend on
// the instruction set or the thread count) and the dependency chain is a quarter of a sequential sum's,
// which was a quarter of a 200-sample evaluation. Against the sequential sum the result
// differs in rounding only (relative 1e-15 for 200 samples).
double mean_abs_residual(std::span<double> kappa, const std::vector<double>& target) {
  const std::size_t m = kappa.size();
  double s[4] = {0.0, 0.0, 0.0, 0.0};
  std::size_t i = 0;
  for (; i + 4 <= m; i += 4)
    for (std::size_t l = 0; l < 4; ++l) {
      kappa[i + l] -= target[i + l];
      s[l] += std::fabs(kappa[i + l]);
    }
  for (std::size_t l = 0; i < m; ++i, ++l) {
    kappa[i] -= target[i];
    s[l] += std::fabs(kappa[i]);
  }
  return ((s[0] + s[1]) + (s[2] + s[3])) / static_cast<double>(m);
}

}  // namespace

double CurvatureMatch::mean_distance(std::span<const double> x, SplineProfileSampler::Workspace& ws,
                                     std::span<Vec3> points, std::span<double> kappa) const {
  points_from(x, points);
  if (!sampler_.sample(points, ws, kappa)) return kNaN;
  return mean_abs_residual(kappa, target_);
}

MatchDistances CurvatureMatch::mean_distances(std::span<const double> x, SplineProfileSampler::Workspace& ws,
                                              std::span<Vec3> points, std::span<double> kappa,
                                              std::span<double> tau) const {
  points_from(x, points);
  const bool want_tau = !torsion_target_.empty();
  MatchDistances d{kNaN, kNaN, kNaN};
  if (!sampler_.sample(points, ws, kappa, want_tau ? tau : std::span<double>{})) return d;
  d.mean = mean_abs_residual(kappa, target_);  // the GA objective's doubles (mean_distance)
  d.max = 0.0;
  for (const double r : kappa) d.max = std::max(d.max, std::fabs(r));
  if (want_tau) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < tau.size(); ++i)
      if (std::isfinite(tau[i])) {
        sum += std::fabs(tau[i] - torsion_target_[i]);
        ++count;
      }
    d.torsion_mean = count > 0 ? sum / static_cast<double>(count) : kNaN;
  }
  return d;
}

MatchDistances CurvatureMatch::distances(std::span<const double> x) const {
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> points(setup_.points.size());
  std::vector<double> kappa(setup_.samples), tau(setup_.samples);
  return mean_distances(x, ws, points, kappa, tau);
}

std::vector<double> CurvatureMatch::curvature_samples(std::span<const double> x) const {
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> points(setup_.points.size());
  std::vector<double> kappa(setup_.samples);
  points_from(x, points);
  (void)sampler_.sample(points, ws, kappa);
  return kappa;
}

std::vector<double> CurvatureMatch::torsion_samples(std::span<const double> x) const {
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> points(setup_.points.size());
  std::vector<double> kappa(setup_.samples), tau(setup_.samples);
  points_from(x, points);
  (void)sampler_.sample(points, ws, kappa, tau);
  return tau;
}

double CurvatureMatch::proximity_penalty(std::span<const Vec3> points) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < setup_.proximity.size(); ++i) {
    const Vec3 d = points[i] - setup_.proximity_centre[i];
    sum += setup_.proximity[i] * dot(d, d);
  }
  return sum;
}

std::vector<double> CurvatureMatch::proximity_variables() const { return variables_from(setup_.proximity_centre); }

optim::Problem CurvatureMatch::problem(double precision) const {
  optim::Problem p;
  p.name = "match-curvature";
  p.variables = variables(precision);
  p.objectives = 1;
  p.evaluate = [this](std::span<const double> x, std::span<double> values) {
    // One set of buffers per thread: evaluations may run concurrently, and none allocates once warm.
    thread_local SplineProfileSampler::Workspace ws;
    thread_local std::vector<Vec3> points;
    thread_local std::vector<double> kappa;
    if (points.size() != setup_.points.size()) points.resize(setup_.points.size());
    if (kappa.size() != setup_.samples) kappa.resize(setup_.samples);
    values[0] = mean_distance(x, ws, points, kappa) + proximity_penalty(points);
    validity_constraints(points, values.subspan(1));
  };
  p.inequality_constraints = setup_.validity.count();
  return p;
}

ValidityCheck CurvatureMatch::validity(std::span<const double> x) const {
  if (!setup_.validity.any()) return {};
  std::vector<Vec3> points(setup_.points.size());
  points_from(x, points);
  try {
    return check_validity(sampler_.curve(points), setup_.validity);
  } catch (const Error& e) {
    ValidityCheck c;
    c.reasons.push_back("no curve through these points: " + e.message());
    return c;
  }
}

void CurvatureMatch::validity_constraints(std::span<const Vec3> points, std::span<double> out) const {
  const ValidityRequirements& v = setup_.validity;
  if (!v.any()) return;
  try {
    studies::validity_constraints(check_validity(sampler_.curve(points), v), v, out);
  } catch (const Error&) {
    std::fill(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(v.count()),
              std::numeric_limits<double>::quiet_NaN());
  }
}

namespace {

// κ(u_i) and, when `torsion`, τ(u_i) of the spline through `points`.
std::vector<double> profile_of(std::span<const Vec3> points, int dimension, std::size_t samples,
                               std::optional<Vec3> start_tangent, std::optional<Vec3> end_tangent,
                               ProfileAbscissa abscissa, bool torsion) {
  if (samples < 2)
    throw Error(Errc::InvalidArgument, "samples = " + std::to_string(samples) + " must be at least 2",
                {.field = "samples"});
  const std::vector<double> u = uniform_abscissae(samples);
  const SplineProfileSampler sampler(points.size(), dimension, u, start_tangent, end_tangent, abscissa);
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(samples), tau(torsion ? samples : 0);
  if (!sampler.sample(points, ws, kappa, tau))
    throw Error(Errc::CoincidentPoints, "points: two consecutive points coincide or a value overflowed",
                {.field = "points"});
  if (!torsion) return kappa;
  for (std::size_t i = 0; i < samples; ++i)
    if (!std::isfinite(tau[i]))
      throw Error(Errc::OutOfDomain,
                  "the torsion of the curve is undefined at u = " + format_number(u[i]) +
                      " (its curvature vanishes there, as at a natural end: fix the end tangents)",
                  {.field = "points", .index = i});
  return tau;
}

}  // namespace

std::vector<double> curvature_profile_of(std::span<const Vec3> points, int dimension, std::size_t samples,
                                         std::optional<Vec3> start_tangent, std::optional<Vec3> end_tangent,
                                         ProfileAbscissa abscissa) {
  return profile_of(points, dimension, samples, start_tangent, end_tangent, abscissa, false);
}

std::optional<SplineProfileBreaks> spline_profile_breaks(std::span<const double> kappa, std::size_t interior,
                                                         double separation) {
  const std::size_t n = kappa.size();
  constexpr std::size_t kReach = 4;  // window of a pair (j, j + 1): samples j − 4 … j + 5
  constexpr int kSteps = 50;         // positions tried per sample interval
  if (n < 2 * kReach + 2 || n - 1 < (2 * kReach - 2) * (interior + 1)) return std::nullopt;
  for (const double k : kappa)
    if (!std::isfinite(k)) return std::nullopt;
  // Per interval (j, j + 1): least squares on its window, a cubic in the sample index against the cubic plus
  // J (i − ξ)_+ for ξ in [j, j + 1]; the score is the root of the squares the kink explains, ξ the best position.
  std::vector<double> score(n, 0.0), where(n, 0.0);
  // The window's design matrices depend on the sample offset and ξ only, not on the interval: factored once.
  constexpr Eigen::Index rows = 2 * static_cast<Eigen::Index>(kReach) + 2;
  using Window = Eigen::Matrix<double, rows, 5>;
  Window basis;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const double x = static_cast<double>(r) - static_cast<double>(kReach) - 0.5;
    basis.row(r) << 1.0, x, x * x, x * x * x, 0.0;
  }
  const Eigen::Matrix<double, rows, 4> cubic = basis.leftCols(4);
  const Eigen::ColPivHouseholderQR<Eigen::Matrix<double, rows, 4>> cubic_qr(cubic);
  std::vector<Window> kinked(kSteps + 1, basis);
  std::vector<Eigen::ColPivHouseholderQR<Window>> kinked_qr;
  kinked_qr.reserve(kSteps + 1);
  for (int k = 0; k <= kSteps; ++k) {
    const double xi = static_cast<double>(k) / kSteps - 0.5;
    for (Eigen::Index r = 0; r < rows; ++r) kinked[k](r, 4) = std::max(0.0, basis(r, 1) - xi);
    kinked_qr.emplace_back(kinked[k]);
  }
  Eigen::Matrix<double, rows, 1> y;
  for (std::size_t j = kReach; j + kReach + 1 < n; ++j) {
    for (Eigen::Index r = 0; r < rows; ++r) y(r) = kappa[j - kReach + static_cast<std::size_t>(r)];
    const double scale = std::max(y.cwiseAbs().maxCoeff(), 1e-300);
    y /= scale;
    const double smooth = (cubic * cubic_qr.solve(y) - y).squaredNorm();
    double best = smooth;
    for (int k = 0; k <= kSteps; ++k) {
      const double rss = (kinked[k] * kinked_qr[k].solve(y) - y).squaredNorm();
      if (rss < best) best = rss, where[j] = static_cast<double>(j) + 0.5 + (static_cast<double>(k) / kSteps - 0.5);
    }
    score[j] = std::sqrt(std::max(0.0, smooth - best)) * scale;
  }
  // The unsigned κ crossing zero (an inflection): a local minimum that the straight lines through the two samples
  // on either side carry below zero. κ changes sign between the two samples where the signed ones are straighter.
  std::vector<double> flips;
  for (std::size_t i = 2; i + 2 < n; ++i) {
    if (!(kappa[i] <= kappa[i - 1] && kappa[i] <= kappa[i + 1])) continue;
    const double left = 2.0 * kappa[i - 1] - kappa[i - 2], right = 2.0 * kappa[i + 1] - kappa[i + 2];
    if (!(std::min(left, right) < 0.0)) continue;
    auto bend = [&](std::size_t f) {  // samples after f negated
      double sum = 0.0;
      for (std::size_t m = i - 1; m <= i + 1; ++m) {
        auto v = [&](std::size_t q) { return q > f ? -kappa[q] : kappa[q]; };
        sum += std::fabs(v(m - 1) - 2.0 * v(m) + v(m + 1));
      }
      return sum;
    };
    flips.push_back(static_cast<double>(bend(i - 1) < bend(i) ? i - 1 : i) + 0.5);
  }
  // Intervals strongest first, each a local maximum, none within four samples of one taken before or of a zero
  // crossing (whose kink is not a data parameter).
  std::vector<std::size_t> order;
  for (std::size_t j = kReach; j + kReach + 1 < n; ++j)
    if (score[j] > 0.0 && score[j] >= score[j - 1] && score[j] >= score[j + 1]) order.push_back(j);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return score[p] > score[q]; });
  std::vector<double> taken;
  double weakest = 0.0, left_out = 0.0;
  auto near = [&](const std::vector<double>& v, double x) {
    return std::any_of(v.begin(), v.end(), [&](double w) { return std::fabs(w - x) < static_cast<double>(kReach); });
  };
  for (const std::size_t j : order) {
    if (near(taken, where[j]) || near(flips, where[j])) continue;
    if (taken.size() == interior) {
      left_out = score[j];
      break;
    }
    taken.push_back(where[j]);
    weakest = score[j];
  }
  if (taken.size() != interior || (interior > 0 && !(weakest >= separation * left_out))) return std::nullopt;
  SplineProfileBreaks r;
  const double du = 1.0 / static_cast<double>(n - 1);
  r.parameters.push_back(0.0);
  for (const double x : taken) r.parameters.push_back(x * du);
  r.parameters.push_back(1.0);
  std::sort(r.parameters.begin(), r.parameters.end());
  // The sign flips past each crossing (in order of i), and is positive where the profile turns most.
  r.signed_samples.assign(kappa.begin(), kappa.end());
  double sign = 1.0, total = 0.0;
  for (std::size_t i = 0, next = 0; i < n; ++i) {
    while (next < flips.size() && flips[next] < static_cast<double>(i)) sign = -sign, ++next;
    r.signed_samples[i] *= sign;
    total += r.signed_samples[i];
  }
  if (total < 0.0)
    for (double& v : r.signed_samples) v = -v;
  return r;
}

std::vector<double> torsion_profile_of(std::span<const Vec3> points, std::size_t samples,
                                       std::optional<Vec3> start_tangent, std::optional<Vec3> end_tangent,
                                       ProfileAbscissa abscissa) {
  return profile_of(points, 3, samples, start_tangent, end_tangent, abscissa, true);
}

}  // namespace hula::studies
