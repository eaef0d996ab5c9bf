// SPDX-License-Identifier: MIT
// Tight axis-aligned bounding box of a NURBS curve itself (not of its control
// polygon): on every knot span and for every coordinate, the extrema are at
// the span ends or at roots of the coordinate's derivative x'(t) (for a
// rational curve the derivative of the quotient X/W, from the curve's own
// derivative evaluator, eq. 4.8 of The NURBS Book). Roots are bracketed by
// sampling and polished by TOMS 748 (Boost.Math), a bracketing root finder.
#pragma once

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Smallest axis-aligned box containing the curve over its domain.
/// @returns a box inside control_box() (convex-hull property); exact up to
///   rounding at span ends, to ~1e-15 × model size at interior extrema. A pair
///   of extrema closer together than the sampling step (8 (p + 1) samples per
///   span) may be missed; the box then still contains every sampled point.
/// Complexity O(S · p) evaluations for S spans.
/// Example: the unit circle as four rational quadratic arcs gives [-1, 1]² × [0, 0].
[[nodiscard]] Box3 bounding_box(const NurbsCurve& curve);

}  // namespace hula::nurbs
