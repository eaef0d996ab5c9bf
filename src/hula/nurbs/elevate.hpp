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
//
// Degree reduction (The NURBS Book 5.6, A5.11 in outline): each Bézier piece
// of degree p is reduced to p − 1 by inverting degree elevation
// P_i = (i/p) Q_{i−1} + (1 − i/p) Q_i from the left (i ≤ r) and from the right
// (i ≥ r + 2), r = ⌊(p − 1)/2⌋; only P_{r+1} is then not reproduced, and the
// difference of the piece and its reduction is a Bézier curve with the single
// non-zero control point P_{r+1} − ((r+1)/p Q_r + (1 − (r+1)/p) Q_{r+1}), whose
// length bounds the error (convex hull). A rational piece is reduced the same
// way on its homogeneous points (w P, w); its reduced weights must stay
// positive, and its bound is taken in Euclidean space (see reduce_degree). The
// pieces join C0 (their end points are kept); knots are then removed within
// what is left of the tolerance (remove_knots), restoring the continuity the
// curve allows.
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

/// Result of reduce_degree().
struct DegreeReductionResult {
  NurbsCurve curve;           ///< degree p − 1, same domain and parameterisation
  double error_bound = 0.0;   ///< bound on max |C_new(t) − C(t)| over the domain, model units (≤ tolerance)
  double bezier_bound = 0.0;  ///< the part of the bound from the per-piece reduction (before knot removal)
};

/// Lowers the degree of a curve by one within a tolerance.
/// @param curve a curve of degree p ≥ 2, rational or not (an unclamped curve is clamped first). A rational piece
///   is reduced on its homogeneous points; the Euclidean change of a piece is then at most
///   (|ΔA − c Δw| + |Δw| R) / min w̃ for the homogeneous mismatch (ΔA, Δw), the centroid c of the piece's control
///   points, R their largest distance to c and min w̃ the least reduced weight (for a non-rational piece, |ΔP|).
/// @param tolerance ≥ 0, model units: the largest change allowed (0: only a curve that is an elevated one of
///   degree p − 1, to rounding)
/// @returns the reduced curve with every interior breakpoint of the lowest multiplicity the tolerance allows
///   (C0 joints first, then knots removed while the accumulated bound stays within the tolerance) and the bound
/// @throws hula::Error(Errc::InvalidDegree) naming "curve" for degree 1
/// @throws hula::Error(Errc::InvalidArgument) naming "tolerance" if negative or not finite
/// @throws hula::Error(Errc::NumericalFailure) naming "curve" when a reduced weight is not positive (the message
///   names the piece's interval and the weight)
/// @throws hula::Error(Errc::NumericalFailure) naming "tolerance" when some piece's bound exceeds it (the message
///   gives the smallest bound reachable)
/// Complexity O(S p²) for S spans, plus remove_knots.
/// Example: `reduce_degree(elevate_degree(c, 1), 0).curve` is c (bound at rounding level), rational c too.
[[nodiscard]] DegreeReductionResult reduce_degree(const NurbsCurve& curve, double tolerance);

}  // namespace hula::nurbs
