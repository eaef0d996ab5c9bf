// SPDX-License-Identifier: MIT
// A NURBS curve as a chain of cubic Bézier pieces, the one curve primitive of
// SVG and PostScript paths. A non-rational curve of degree ≤ 3 is exact: it is
// split into its Bézier segments (knot insertion to full multiplicity, The
// NURBS Book A5.6) and degree 1 and 2 segments are raised to 3 (eq. 5.36), so
// every piece is the curve itself up to rounding. A rational curve or one of
// degree > 3 has no exact cubic form; each of its Bézier segments is replaced
// by cubic Hermite pieces (end points and end first derivatives of the piece's
// parameter interval), halved until the piece's deviation is within the
// tolerance.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// One cubic Bézier piece B(x) = Σ C(3, i) (1 − x)^(3 − i) x^i P_i, x ∈ [0, 1], standing for the curve on
/// [start, end].
struct CubicPiece {
  std::array<Vec3, 4> points{};  ///< P0 … P3 (P0 and P3 on the curve)
  double start = 0.0;            ///< the curve parameter at x = 0
  double end = 0.0;              ///< the curve parameter at x = 1
};

/// The pieces of a curve and how far they are from it.
struct CubicPath {
  std::vector<CubicPiece> pieces;  ///< in parameter order; each piece starts where the previous ends
  /// True when the pieces are the curve (non-rational, degree ≤ 3); max_deviation is then 0.
  bool exact = false;
  /// The largest distance |B(x) − C(start + x (end − start))| measured at kCubicSamples interior points of
  /// every approximated piece (a parametric distance: never below the distance from the curve).
  double max_deviation = 0.0;
};

/// Interior points per piece at which an approximation's deviation is measured.
inline constexpr int kCubicSamples = 16;

/// The curve as cubic Bézier pieces, exactly when it is non-rational of degree ≤ 3, else within `tolerance`.
/// @param tolerance largest deviation of an approximated piece, in model units; > 0 and finite
/// @throws hula::Error(Errc::InvalidArgument) with field "tolerance" if it is not finite and > 0
/// @throws hula::Error(Errc::NumericalFailure) if a piece shorter than 2⁻³⁰ of its Bézier segment still
///   misses the tolerance (a tolerance below the rounding of the coordinates)
/// Complexity: exact O(n p + S p²); approximated O(S · k · kCubicSamples) evaluations for k pieces per segment
/// (k grows as tolerance^(−1/4)).
[[nodiscard]] CubicPath cubic_beziers(const NurbsCurve& curve, double tolerance);

}  // namespace hula::nurbs
