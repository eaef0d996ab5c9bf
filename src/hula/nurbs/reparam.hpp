// SPDX-License-Identifier: MIT
// Parameter changes that keep the point set of a NURBS curve: affine
// reparameterisation onto a new interval, reversal of direction, and
// splitting at a parameter (thesis 5.5; The NURBS Book 6.4 for affine
// reparameterisation, A5.1 knot insertion for the split). Derivatives
// transform by the chain rule: for t' = a' + (t - a) L'/L,
// dC/dt' = (L / L') dC/dt.
#pragma once

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// The same curve on the parameter interval `domain` (affine map of the knots).
/// @param domain target [start, end], finite, start < end
/// @returns C'(t') = C(a + (t' - a') L / L'); its k-th derivative is the
///   original one times (L / L')^k (chain rule). The domain ends are exact.
/// @throws hula::Error(Errc::InvalidArgument) if the interval is not finite with start < end (names both values)
[[nodiscard]] NurbsCurve reparameterise(const NurbsCurve& curve, Interval domain);

/// The same point set traversed backwards on the same domain [a, b]:
/// R(t) = C(a + b - t), so R'(t) = -C'(a + b - t).
/// @returns knots a + b - U[m - i] (domain ends exact), control points and weights reversed
[[nodiscard]] NurbsCurve reverse(const NurbsCurve& curve);

/// Result of split: the curve on [a, t] and on [t, b], each clamped at t.
struct SplitResult {
  NurbsCurve before;  ///< domain [a, t], equal to the curve there
  NurbsCurve after;   ///< domain [t, b], equal to the curve there
};

/// Splits the curve at parameter t (knot insertion to multiplicity p, A5.1).
/// @param t strictly inside the domain (a < t < b)
/// @throws hula::Error(Errc::NonFiniteInput) if t is NaN or infinite (names t)
/// @throws hula::Error(Errc::OutOfDomain) if t ≤ a or t ≥ b (names t and the domain)
/// Complexity O(n + p²).
[[nodiscard]] SplitResult split(const NurbsCurve& curve, double t);

/// The part of the curve on [start, end] (split at both ends, each end clamped).
/// @param part a ≤ start < end ≤ b
/// @throws hula::Error(Errc::OutOfDomain) naming "part" unless a ≤ start < end ≤ b
[[nodiscard]] NurbsCurve segment(const NurbsCurve& curve, Interval part);

/// Joins two curves end to start into one, C0 at the joint (knot of multiplicity p there): the
/// lower-degree curve is degree-elevated, b is reparameterised to follow a with its own parameter
/// length, and b's weights are scaled so that the shared control point has one weight.
/// @param a, b curves with clamped knot vectors whose end and start meet within `gap` (the shared
///   control point is their midpoint), both planar or mixed (the result is 3-D unless both are 2-D)
/// @throws hula::Error(Errc::InvalidArgument) naming "a" or "b" if a knot vector is not clamped, or naming
///   "gap" if |a(end) − b(start)| > gap (both points given)
/// Complexity O(n_a + n_b) after elevation.
[[nodiscard]] NurbsCurve join(const NurbsCurve& a, const NurbsCurve& b, double gap);

}  // namespace hula::nurbs
