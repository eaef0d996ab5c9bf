// SPDX-License-Identifier: MIT
// A2.2 and A2.3 of The NURBS Book, written from the algorithm descriptions.
// left[j] = t - U[i+1-j], right[j] = U[i+j] - t; ndu holds the basis functions
// (upper triangle) and the knot differences (lower triangle).
#include "hula/nurbs/basis.hpp"

#include <array>
#include <cmath>

#include "hula/core/error.hpp"

namespace hula::nurbs {

namespace {
// A2.2 with the degree known at compile time (unrolled, no scratch zeroing);
// P = 0 selects the run-time degree version.
template <int P>
inline void basis_functions_impl(const double* U, int p_runtime, std::size_t span, double t, double* out) {
  const int p = P > 0 ? P : p_runtime;
  double left[(P > 0 ? P : kMaxDegree) + 1];
  double right[(P > 0 ? P : kMaxDegree) + 1];
  out[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - U[span + 1 - static_cast<std::size_t>(j)];
    right[j] = U[span + static_cast<std::size_t>(j)] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = out[r] / (right[r + 1] + left[j - r]);
      out[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    out[j] = saved;
  }
}
}  // namespace

void basis_functions(const KnotVector& knots, std::size_t span, double t, std::span<double> out) {
  const int p = knots.degree();
  HULA_ASSERT(out.size() >= static_cast<std::size_t>(p) + 1, "basis output too small");
  const double* U = knots.values().data();
  switch (p) {
    case 1:
      return basis_functions_impl<1>(U, p, span, t, out.data());
    case 2:
      return basis_functions_impl<2>(U, p, span, t, out.data());
    case 3:
      return basis_functions_impl<3>(U, p, span, t, out.data());
    case 4:
      return basis_functions_impl<4>(U, p, span, t, out.data());
    case 5:
      return basis_functions_impl<5>(U, p, span, t, out.data());
    default:
      return basis_functions_impl<0>(U, p, span, t, out.data());
  }
}

std::vector<double> basis_derivatives(const KnotVector& knots, std::size_t span, double t, int order) {
  BasisWorkspace work;
  const std::span<const double> d = basis_derivatives(knots, span, t, order, work);
  return {d.begin(), d.end()};
}

std::span<const double> basis_derivatives(const KnotVector& knots, std::size_t span, double t, int order,
                                          BasisWorkspace& work) {
  const int p = knots.degree();
  const auto P = static_cast<std::size_t>(p);
  const auto nd = static_cast<std::size_t>(order);
  const std::span<const double> U = knots.values();
  std::vector<double>& ders = work.ders;
  ders.assign((nd + 1) * (P + 1), 0.0);
  std::vector<double>& ndu = work.ndu;
  ndu.resize((P + 1) * (P + 1));
  auto NDU = [&](std::size_t r, std::size_t c) -> double& { return ndu[r * (P + 1) + c]; };
  std::vector<double>& left = work.left;
  std::vector<double>& right = work.right;
  left.resize(P + 1);
  right.resize(P + 1);
  NDU(0, 0) = 1.0;
  for (std::size_t j = 1; j <= P; ++j) {
    left[j] = t - U[span + 1 - j];
    right[j] = U[span + j] - t;
    double saved = 0.0;
    for (std::size_t r = 0; r < j; ++r) {
      NDU(j, r) = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = NDU(r, j - 1) / NDU(j, r);
      NDU(r, j) = saved + right[r + 1] * temp;  // upper triangle: basis functions
      saved = left[j - r] * temp;
    }
    NDU(j, j) = saved;
  }
  for (std::size_t j = 0; j <= P; ++j) ders[j] = NDU(j, P);
  const std::size_t n = std::min(nd, P);
  std::vector<double>& a = work.a;
  a.resize(2 * (P + 1));
  auto A = [&](std::size_t s, std::size_t c) -> double& { return a[s * (P + 1) + c]; };
  for (std::size_t r = 0; r <= P; ++r) {
    std::size_t s1 = 0, s2 = 1;
    A(0, 0) = 1.0;
    for (std::size_t k = 1; k <= n; ++k) {
      double d = 0.0;
      const auto rk = static_cast<std::ptrdiff_t>(r) - static_cast<std::ptrdiff_t>(k);
      const auto pk = P - k;
      if (rk >= 0) {
        A(s2, 0) = A(s1, 0) / NDU(pk + 1, static_cast<std::size_t>(rk));
        d = A(s2, 0) * NDU(static_cast<std::size_t>(rk), pk);
      }
      const std::size_t j1 = rk >= -1 ? 1 : static_cast<std::size_t>(-rk);
      const std::size_t j2 = (static_cast<std::ptrdiff_t>(r) - 1 <= static_cast<std::ptrdiff_t>(pk)) ? k - 1 : P - r;
      for (std::size_t j = j1; j <= j2; ++j) {
        const auto col = static_cast<std::size_t>(rk + static_cast<std::ptrdiff_t>(j));
        A(s2, j) = (A(s1, j) - A(s1, j - 1)) / NDU(pk + 1, col);
        d += A(s2, j) * NDU(col, pk);
      }
      if (static_cast<std::ptrdiff_t>(r) <= static_cast<std::ptrdiff_t>(pk)) {
        A(s2, k) = -A(s1, k - 1) / NDU(pk + 1, r);
        d += A(s2, k) * NDU(r, pk);
      }
      ders[k * (P + 1) + r] = d;
      std::swap(s1, s2);
    }
  }
  // Multiply by p! / (p - k)!.
  double factor = static_cast<double>(p);
  for (std::size_t k = 1; k <= n; ++k) {
    for (std::size_t j = 0; j <= P; ++j) ders[k * (P + 1) + j] *= factor;
    factor *= static_cast<double>(P - k);
  }
  return ders;
}

double bernstein(int i, int n, double t) {
  if (i < 0 || i > n) return 0.0;
  // C(n, i) by the multiplicative formula, exact for the degrees we allow.
  double c = 1.0;
  for (int k = 1; k <= i; ++k) c = c * (n - i + k) / k;
  return c * std::pow(t, i) * std::pow(1.0 - t, n - i);
}

void bernstein_all(int n, double t, std::span<double> out) {
  HULA_ASSERT(out.size() >= static_cast<std::size_t>(n) + 1, "bernstein output too small");
  const auto N = static_cast<std::size_t>(n);
  out[0] = 1.0;
  const double t1 = 1.0 - t;
  for (std::size_t j = 1; j <= N; ++j) {
    double saved = 0.0;
    for (std::size_t k = 0; k < j; ++k) {
      const double temp = out[k];
      out[k] = saved + t1 * temp;
      saved = t * temp;
    }
    out[j] = saved;
  }
}

}  // namespace hula::nurbs
