// SPDX-License-Identifier: MIT
// The natural-equation kind of the curve value type (curve::NaturalData,
// thesis 8.2.2, 10: "F-rep … gives a more generic and more exact definition of
// curves than NURBS"): parses κ(s) and τ(s), integrates them from the start
// frame (reconstruct, to NaturalData::tolerance), and gives the Curve its
// exact evaluator — position and frame from the integration, κ, τ and their
// derivatives from the laws (curve::NaturalEvaluator) — besides the quintic
// NURBS fitted for drawing and export (fit_nurbs), refusing a fit that does
// not meet its tolerance. Conversion to a NURBS within a chosen tolerance is
// to_nurbs().
#pragma once

#include "hula/curve/curve.hpp"
#include "hula/intrinsic/natural_equations.hpp"

namespace hula::intrinsic {

/// The curve with curvature κ(s) and torsion τ(s), s ∈ [0, L], from a start point and frame.
/// Evaluation (Curve::point, derivatives, and so diffgeom's analysis) is exact in κ, τ and their
/// derivatives and holds position and frame to data.tolerance; nurbs() is a quintic fit within
/// `tolerance` of the integrated curve (approximation_deviation() is its measured deviation).
/// @param data κ and τ as expressions of data.parameter, L, start point, tangent and normal, and the
///   integration tolerance in [1e-13, 1e-2]
/// @param tolerance largest deviation of nurbs() from the integrated curve, model units, in
///   [1e-9, 0.1] (curve::kApproximationTolerance is the usual choice)
/// @returns a Curve of kind Natural with domain [0, L], parameterised by arc length
/// @throws hula::Error(Errc::ParseError) naming "curvature" or "torsion" (with line/column) for
///   a bad expression or one that is not a scalar of the parameter
/// @throws hula::Error(Errc::InvalidArgument) naming "tolerance" for either tolerance out of range
/// @throws as reconstruct() (InvalidArgument / NonFiniteInput naming "length",
///   "start_frame.tangent", "start_frame.normal"; NumericalFailure where κ or τ is undefined)
/// @throws hula::Error(Errc::NumericalFailure) naming "tolerance" if the fit cannot meet it
[[nodiscard]] curve::Curve natural_curve(const curve::NaturalData& data, double tolerance);

/// The integrated curve behind a natural Curve (dense frames, nodes, breakpoints), or nullptr for
/// another kind.
[[nodiscard]] const IntrinsicCurve* intrinsic_of(const curve::Curve& curve) noexcept;

/// Result of to_nurbs().
struct CurveToNurbsResult {
  /// The NURBS: the curve's own for the exact kinds (nurbs, bezier, interpolated, hermite), else a fit.
  nurbs::NurbsCurve curve;
  /// Largest distance from the curve found by dense sampling (0 for the exact kinds).
  double max_deviation = 0.0;
  /// The tolerance applied.
  double tolerance = 0.0;
};

/// A curve as a NURBS within `tolerance` (model units): the conversion on request of law and natural
/// curves (law::to_nurbs of the law, a C2 quintic on its domain; fit_nurbs_converged of the integrated
/// natural curve, a quintic parameterised by arc length); the exact kinds are returned as they are.
/// @param tolerance in [1e-13, 1] for natural curves (not below their integration tolerance), > 0 for laws
/// @throws hula::Error(Errc::InvalidArgument) naming "tolerance" when out of range or, for a natural curve,
///   below its integration tolerance
/// @throws hula::Error(Errc::NumericalFailure) when the tolerance cannot be met (law::to_nurbs, fit_nurbs_converged)
[[nodiscard]] CurveToNurbsResult to_nurbs(const curve::Curve& curve, double tolerance);

}  // namespace hula::intrinsic
