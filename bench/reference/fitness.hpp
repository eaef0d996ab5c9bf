// SPDX-License-Identifier: MIT
// The hand-written floor for the curvature-matching fitness (thesis 8.2.1, eq. 31; issue 27): the
// natural chord-length C2 cubic through N planar points in the moment form (de Boor, "A practical
// guide to splines", ch. IV), κ at m sorted abscissae, e = (1/m) Σ |κ(u_i) − κ*(u_i)| — one plain
// scalar loop, no allocation, written for this one case (planar, natural ends, κ at the parameter).
//
// Notation: t_k chord-length parameters in [0, 1], h_k = t_{k+1} − t_k, M_k = C''(t_k); on span k with
// w = t − t_k, C'(t) = b + 2 c w + 3 d w², C''(t) = 2 c + 6 d w (b, c, d per coordinate);
// κ = |x' y'' − y' x''| / |C'|³.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include "hula/core/vec.hpp"

namespace hula::bench {

/// e of eq. 31 for the spline through q (2 ≤ N ≤ kMaxPoints) against target[i] at u[i].
inline double reference_fitness(std::span<const Vec3> q, std::span<const double> u, std::span<const double> target) {
  constexpr std::size_t kMaxPoints = 64;
  const std::size_t n = q.size();
  std::array<double, kMaxPoints> t, h, diag, upper;
  std::array<double, 2 * kMaxPoints> rhs, coef_b, coef_c, coef_d;
  t[0] = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double dx = q[k].x - q[k - 1].x, dy = q[k].y - q[k - 1].y;
    t[k] = t[k - 1] + std::sqrt(dx * dx + dy * dy);
  }
  const double inv = 1.0 / t[n - 1];
  for (std::size_t k = 1; k < n; ++k) t[k] *= inv;
  t[n - 1] = 1.0;
  for (std::size_t k = 0; k + 1 < n; ++k) h[k] = t[k + 1] - t[k];
  // Moments: natural ends M_0 = M_{n−1} = 0; interior rows h_{k−1} M_{k−1} + 2 (h_{k−1} + h_k) M_k + h_k M_{k+1}
  // = 6 (slope_k − slope_{k−1}). Thomas algorithm.
  auto slope = [&](std::size_t k, int c) { return ((c == 0 ? q[k + 1].x - q[k].x : q[k + 1].y - q[k].y)) / h[k]; };
  diag[0] = 1.0;
  upper[0] = 0.0;
  rhs[0] = rhs[1] = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double m = h[k - 1] / diag[k - 1];
    diag[k] = 2.0 * (h[k - 1] + h[k]) - m * upper[k - 1];
    upper[k] = h[k];
    for (int c = 0; c < 2; ++c) rhs[2 * k + c] = 6.0 * (slope(k, c) - slope(k - 1, c)) - m * rhs[2 * (k - 1) + c];
  }
  std::array<double, 2 * kMaxPoints> M;
  M[2 * (n - 1)] = M[2 * (n - 1) + 1] = 0.0;
  for (std::size_t k = n - 1; k-- > 1;)
    for (int c = 0; c < 2; ++c) M[2 * k + c] = (rhs[2 * k + c] - upper[k] * M[2 * (k + 1) + c]) / diag[k];
  M[0] = M[1] = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (int c = 0; c < 2; ++c) {
      const double m0 = M[2 * k + c], m1 = M[2 * (k + 1) + c];
      coef_b[2 * k + c] = slope(k, c) - h[k] * (2.0 * m0 + m1) / 6.0;
      coef_c[2 * k + c] = 0.5 * m0;
      coef_d[2 * k + c] = (m1 - m0) / (6.0 * h[k]);
    }
  double sum = 0.0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    while (k + 2 < n && u[i] > t[k + 1]) ++k;
    const double w = u[i] - t[k];
    const double* b = &coef_b[2 * k];
    const double* c = &coef_c[2 * k];
    const double* d = &coef_d[2 * k];
    const double x1 = b[0] + w * (2.0 * c[0] + 3.0 * d[0] * w), y1 = b[1] + w * (2.0 * c[1] + 3.0 * d[1] * w);
    const double x2 = 2.0 * c[0] + 6.0 * d[0] * w, y2 = 2.0 * c[1] + 6.0 * d[1] * w;
    const double v2 = x1 * x1 + y1 * y1;
    const double kappa = std::fabs(x1 * y2 - y1 * x2) / (v2 * std::sqrt(v2));
    sum += std::fabs(kappa - target[i]);
  }
  return sum / static_cast<double>(u.size());
}

}  // namespace hula::bench
