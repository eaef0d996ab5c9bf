// SPDX-License-Identifier: MIT
// Knot insertion and refinement of NURBS curves, and decomposition into Bézier
// segments: The NURBS Book (Piegl & Tiller, 2nd ed.) A5.1 "CurveKnotIns",
// A5.4 "RefineKnotVectCurve" and the refinement form of A5.6
// "DecomposeCurve" (thesis 5.5). All work on homogeneous points (w P, w), so
// rational curves are handled exactly; the curve's shape and parameterisation
// never change.
#pragma once

#include <span>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Inserts the knot u `times` times (Boehm's algorithm, A5.1).
/// @param curve any valid curve (clamped or not)
/// @param u knot value inside the closed domain [t0, t1]
/// @param times r ≥ 0 insertions; 0 returns the curve unchanged
/// @returns the same curve with r more knots and r more control points
/// @throws hula::Error(Errc::NonFiniteInput) if u is NaN or infinite (names u)
/// @throws hula::Error(Errc::OutOfDomain) if u is outside the domain (names u)
/// @throws hula::Error(Errc::InvalidArgument) if times < 0
/// @throws hula::Error(Errc::InvalidKnots) if the multiplicity of u would exceed
///   the degree (names u, its multiplicity and times). At a clamped end the
///   multiplicity is already p + 1, so no insertion is possible there.
/// Complexity O(n + r p).
/// Example: `insert_knot(c, 0.5, 2)` adds u = 0.5 twice.
[[nodiscard]] NurbsCurve insert_knot(const NurbsCurve& curve, double u, int times = 1);

/// Inserts all knots of X at once (A5.4).
/// @param knots X: non-decreasing knot values inside the closed domain;
///   repeated values insert repeatedly; empty returns the curve unchanged
/// @throws hula::Error(Errc::NonFiniteInput) naming knots[i] if not finite
/// @throws hula::Error(Errc::OutOfDomain) naming knots[i] if outside the domain
/// @throws hula::Error(Errc::InvalidArgument) naming knots[i] if X decreases there
/// @throws hula::Error(Errc::InvalidKnots) naming the value whose multiplicity would exceed the degree
/// Complexity O(n + |X| p).
[[nodiscard]] NurbsCurve refine_knots(const NurbsCurve& curve, std::span<const double> knots);

/// Splits the curve into its polynomial (or rational) pieces as Bézier curves
/// (A5.6 done as one refinement: every breakpoint raised to multiplicity p).
/// @returns one curve per non-empty knot span, in parameter order; segment i has
///   degree p, knots {a^(p+1), b^(p+1)} on the span [a, b] (the original
///   parameterisation), and the curve's rationality and dimension
/// Complexity O(n p + S p²) for S spans.
[[nodiscard]] std::vector<NurbsCurve> decompose_to_bezier(const NurbsCurve& curve);

}  // namespace hula::nurbs
