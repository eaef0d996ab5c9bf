// SPDX-License-Identifier: MIT
// basis_derivatives for a compile-time degree (NurbsCurve's span pieces).
#pragma once

#include <cstddef>
#include <utility>

namespace hula::nurbs::detail {

// basis_derivatives(knots, span, t, P, work) (The NURBS Book A2.3) for a compile-time degree P and order
// P, in arrays on the stack: the same operations in the same order, so the same doubles (tested bit for
// bit), without the general routine's run-time sizes and indexing (called once per span when a curve's
// cache or a span piece is built). U: the full knot vector; ders[k][j] = d^k N_{span-P+j,P} / dt^k.
template <int P>
inline void basis_derivatives_fixed(const double* U, std::size_t span, double t, double (&ders)[P + 1][P + 1]) {
  double ndu[P + 1][P + 1] = {};
  double left[P + 1] = {}, right[P + 1] = {};
  ndu[0][0] = 1.0;
  for (int j = 1; j <= P; ++j) {
    left[j] = t - U[span + 1 - static_cast<std::size_t>(j)];
    right[j] = U[span + static_cast<std::size_t>(j)] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= P; ++j) ders[0][j] = ndu[j][P];
  double a[2][P + 1] = {};
  for (int r = 0; r <= P; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= P; ++k) {
      double d = 0.0;
      const int rk = r - k;
      const int pk = P - k;
      if (rk >= 0) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : P - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = static_cast<double>(P);
  for (int k = 1; k <= P; ++k) {
    for (int j = 0; j <= P; ++j) ders[k][j] *= factor;
    factor *= static_cast<double>(P - k);
  }
}

}  // namespace hula::nurbs::detail
