// SPDX-License-Identifier: MIT
// Degree elevation of NURBS curves (thesis 5.5; The NURBS Book 5.5). Instead
// of A5.9 (Bézier decomposition, per-segment elevation, knot removal) this
// uses the characterisation of the result: the curve of degree p + t lies in
// the spline space whose breakpoints are those of the curve with every
// multiplicity raised by t (continuity C^(p - m) is unchanged), so its
// control points are the unique solution of collocation at the Greville
// abscissae of the new knot vector (Schoenberg–Whitney theorem: the banded
// collocation matrix is non-singular), solved with hula::BandedMatrix in
// homogeneous coordinates (w P, w) for rational curves.
#pragma once

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Raises the degree of the curve by `times` without changing its shape or parameterisation.
/// @param curve any valid curve; an unclamped curve gives a clamped result on the same domain
/// @param times t ≥ 0; 0 returns the curve unchanged; p + t ≤ kMaxDegree
/// @returns the curve of degree p + t with knots: domain ends of multiplicity
///   p + t + 1, every interior breakpoint of multiplicity m + t
/// @throws hula::Error(Errc::InvalidArgument) if times < 0
/// @throws hula::Error(Errc::InvalidDegree) if p + t > kMaxDegree (names both)
/// @throws hula::Error(Errc::NumericalFailure) if the collocation system is
///   singular to working precision (cannot happen in exact arithmetic)
/// Complexity O(N (p + t)²) for N new control points.
/// Example: `elevate_degree(quadratic_circle, 1)` is the same circle as a rational cubic.
[[nodiscard]] NurbsCurve elevate_degree(const NurbsCurve& curve, int times = 1);

}  // namespace hula::nurbs
