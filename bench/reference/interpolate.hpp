// SPDX-License-Identifier: MIT
// The hand-written floor for global cubic interpolation (issue 27): the C2 cubic B-spline through N ≥ 4
// points with chord-length parameters normalised to [0, 1] and natural ends (C'' = 0), written plainly
// for this one case — the same curve as nurbs::interpolate_cubic with its defaults.
//
// Notation (The NURBS Book 9.2.1): Q_i data points, t_i parameters, U = {0,0,0,0, t_1 … t_{N−2},
// 1,1,1,1}, P_0 … P_{N+1} control points with P_0 = Q_0 and P_{N+1} = Q_{N−1}. The unknowns P_1 … P_N
// satisfy one tridiagonal system: row 0 is C''(0) = 0, i.e. (P_1 − P_0)/t_1 = (P_2 − P_1)/t_2; rows
// 1 … N−2 are C(t_i) = Q_i (three cubic basis functions are non-zero at a simple knot); row N−1 is
// C''(1) = 0. The Thomas algorithm solves it. Scratch lives on the stack up to kMaxStack points; the
// result owns its knots and control points (two allocations, as any curve value must).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/vec.hpp"

namespace hula::bench {

struct ReferenceCubic {
  std::vector<double> knots;
  std::vector<Vec3> points;
};

/// The natural chord-length cubic through q (4 ≤ N ≤ kMaxStack points, consecutive points distinct).
inline ReferenceCubic interpolate_natural(std::span<const Vec3> q) {
  constexpr std::size_t kMaxStack = 64;
  const std::size_t N = q.size();
  ReferenceCubic r;
  r.knots.resize(N + 6);
  r.points.resize(N + 2);
  double* U = r.knots.data();
  double* t = U + 3;  // U[i + 3] = t_i
  U[0] = U[1] = U[2] = 0.0;
  t[0] = 0.0;
  for (std::size_t i = 1; i < N; ++i) {
    const Vec3 d = q[i] - q[i - 1];
    t[i] = t[i - 1] + std::sqrt(dot(d, d));
  }
  const double inv_total = 1.0 / t[N - 1];
  for (std::size_t i = 1; i + 1 < N; ++i) t[i] *= inv_total;
  t[N - 1] = U[N + 3] = U[N + 4] = U[N + 5] = 1.0;

  std::array<double, kMaxStack> a, b, c;  // sub-, main and super-diagonal; row i has columns i-1, i, i+1
  Vec3* x = r.points.data() + 1;          // unknown column j is P_{j+1}; right-hand side, then solution
  // Row 0: −(t_1 + t_2) P_1 + t_1 P_2 = −t_2 P_0.
  b[0] = -(t[1] + t[2]);
  c[0] = t[1];
  x[0] = -t[2] * q[0];
  // Rows 1 … N−2: at u = t_i (span k = i + 3, U[k] = u) the cubic basis of A2.2; N_{k−3..k−1} are
  // non-zero and multiply P_i, P_{i+1}, P_{i+2} (columns i−1, i, i+1).
  for (std::size_t i = 1; i + 1 < N; ++i) {
    const std::size_t k = i + 3;
    const double u = t[i];
    double Nb[4] = {1.0, 0.0, 0.0, 0.0}, left[4], right[4];
    for (std::size_t j = 1; j <= 3; ++j) {
      left[j] = u - U[k + 1 - j];
      right[j] = U[k + j] - u;
      double saved = 0.0;
      for (std::size_t r2 = 0; r2 < j; ++r2) {
        const double temp = Nb[r2] / (right[r2 + 1] + left[j - r2]);
        Nb[r2] = saved + right[r2 + 1] * temp;
        saved = left[j - r2] * temp;
      }
      Nb[j] = saved;
    }
    a[i] = Nb[0];
    b[i] = Nb[1];
    c[i] = Nb[2];
    x[i] = q[i];
  }
  // Row N−1: e1 P_{N−1} − (e1 + e2) P_N = −e2 P_{N+1}, e1 = 1 − t_{N−2}, e2 = 1 − t_{N−3}.
  const double e1 = 1.0 - t[N - 2], e2 = 1.0 - t[N - 3];
  a[N - 1] = e1;
  b[N - 1] = -(e1 + e2);
  x[N - 1] = -e2 * q[N - 1];
  // Thomas: forward elimination, back substitution.
  for (std::size_t i = 1; i < N; ++i) {
    const double m = a[i] / b[i - 1];
    b[i] -= m * c[i - 1];
    x[i] -= m * x[i - 1];
  }
  x[N - 1] = x[N - 1] / b[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) x[i] = (x[i] - c[i] * x[i + 1]) / b[i];
  r.points[0] = q[0];
  r.points[N + 1] = q[N - 1];
  return r;
}

}  // namespace hula::bench
