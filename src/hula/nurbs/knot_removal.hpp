// SPDX-License-Identifier: MIT
// Knot removal within a tolerance: The NURBS Book (Piegl & Tiller, 2nd ed.)
// A5.8 "RemoveCurveKnot" and its error bound (eqs. 5.28–5.36), one removal at a
// time, and a greedy removal of every knot the tolerance allows (the idea of
// their section 9.4.5: the cheapest removal first, the error of each knot span
// accumulated). Knot removal is the inverse of insertion: a knot that was
// inserted is removed exactly, and a curve fitted with too many knots (a
// natural-equation fit, a scanned-point fit, a converted foreign curve) gets
// the fewest its shape needs. The parameterisation and the domain never change.
#pragma once

#include <cstddef>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Result of remove_knot() and remove_knots().
struct KnotRemovalResult {
  NurbsCurve curve;          ///< the curve with the knots removed (the input when none could be)
  std::size_t removed = 0;   ///< number of knots removed (each removal takes one control point)
  double error_bound = 0.0;  ///< bound on max |C_new(t) − C(t)| over the domain (model units)
};

/// Removes the interior knot u up to `times` times, as long as the curve moves
/// by at most `tolerance` (A5.8, applied once per removal; the bounds of the
/// successive removals add up).
/// @param curve any valid curve
/// @param u an interior knot of the curve (a breakpoint strictly inside the domain)
/// @param times ≥ 1 removals wanted; fewer are made when the next one would pass the tolerance
/// @param tolerance ≥ 0 in model units; 0 removes only knots that change nothing (to rounding: 1e-12 of the
///   curve's size)
/// @returns the curve, how many times u was removed (0 … min(times, multiplicity of u)) and the bound
/// @throws hula::Error(Errc::NonFiniteInput) naming u or tolerance if not finite
/// @throws hula::Error(Errc::InvalidArgument) naming u if it is not an interior knot, times if < 1,
///   tolerance if < 0
/// Complexity O(times (n + p)). For a rational curve the test is made on the homogeneous points with
/// the bound scaled by (1 + max |P_i|) / min w_i (The NURBS Book eq. 5.36), so it is conservative.
/// Example: `remove_knot(insert_knot(c, 0.3), 0.3, 1, 0.0)` gives back c (removed = 1).
[[nodiscard]] KnotRemovalResult remove_knot(const NurbsCurve& curve, double u, int times, double tolerance);

/// Removes every interior knot it can while the curve stays within
/// `tolerance` of the input everywhere: repeatedly the removal with the
/// smallest bound whose knot spans still have room in the tolerance (the error
/// bound of each span of the input accumulates the removals that touch it).
/// @param tolerance ≥ 0 in model units (0: only knots that change nothing, to 1e-12 of the size)
/// @returns the reduced curve, the number of knots removed and the largest accumulated span bound
/// @throws hula::Error(Errc::NonFiniteInput) / hula::Error(Errc::InvalidArgument) naming tolerance
/// Complexity O(k²) comparisons and O(k p²) arithmetic for k interior knots.
[[nodiscard]] KnotRemovalResult remove_knots(const NurbsCurve& curve, double tolerance);

}  // namespace hula::nurbs
