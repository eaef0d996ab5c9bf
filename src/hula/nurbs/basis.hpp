// SPDX-License-Identifier: MIT
// B-spline basis functions and their derivatives: The NURBS Book (Piegl &
// Tiller, 2nd ed.) A2.2 "BasisFuns" and A2.3 "DersBasisFuns", and the
// Bernstein polynomials of Bézier curves (thesis 5.4.3).
//
// Notation: p = degree, U = knots, i = span index with U[i] ≤ t < U[i+1].
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/nurbs/knot_vector.hpp"

namespace hula::nurbs {

/// The p + 1 non-zero basis functions N_{i-p,p}(t) … N_{i,p}(t) on span i (A2.2).
/// @param out receives p + 1 values; they are ≥ 0 and sum to 1 for t in the span.
/// No allocation.
void basis_functions(const KnotVector& knots, std::size_t span, double t, std::span<double> out);

/// Derivatives of order 0 … `order` of the p + 1 non-zero basis functions on
/// span i (A2.3). Row k of the result holds d^k N_{i-p+j,p}/dt^k for j = 0 … p;
/// rows beyond p are zero.
/// @returns (order + 1) × (p + 1) values, row-major.
[[nodiscard]] std::vector<double> basis_derivatives(const KnotVector& knots, std::size_t span, double t, int order);

/// Reusable scratch space for basis_derivatives in loops (no allocation once warm).
struct BasisWorkspace {
  std::vector<double> ders, ndu, a, left, right;
  /// Extra scratch for callers (homogeneous sums in the curve evaluator).
  std::vector<double> extra;
};

/// As basis_derivatives, writing into `work`; the returned view lives until the next call.
std::span<const double> basis_derivatives(const KnotVector& knots, std::size_t span, double t, int order,
                                          BasisWorkspace& work);

/// Bernstein polynomial B_{i,n}(t) = C(n, i) t^i (1 - t)^(n-i) (thesis 5.4.3).
[[nodiscard]] double bernstein(int i, int n, double t);

/// All n + 1 Bernstein polynomials of degree n at t, by the recursive form
/// B_{i,n} = (1 - t) B_{i,n-1} + t B_{i-1,n-1} (thesis 5.4.5; A1.3).
void bernstein_all(int n, double t, std::span<double> out);

}  // namespace hula::nurbs
