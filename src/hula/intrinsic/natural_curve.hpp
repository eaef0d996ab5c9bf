// SPDX-License-Identifier: MIT
// The natural-equation kind of the curve value type (curve::NaturalData,
// thesis 8.2.2): parses κ(s) and τ(s), integrates them from the start frame
// (reconstruct) and fits the quintic NURBS that stands in for the curve
// (fit_nurbs), refusing a fit that does not meet its tolerance.
#pragma once

#include "hula/curve/curve.hpp"

namespace hula::intrinsic {

/// The curve with curvature κ(s) and torsion τ(s), s ∈ [0, L], from a start point and frame.
/// The integration is held to tolerance / 10 and the NURBS fit to the tolerance, so
/// approximation_deviation() (the measured |NURBS(s) − r(s)|) ≤ tolerance.
/// @param data κ and τ as expressions of data.parameter, L, start point, tangent and normal
/// @param tolerance largest deviation of nurbs() from the integrated curve, model units, in
///   [1e-9, 0.1] (curve::kApproximationTolerance is the usual choice)
/// @returns a Curve of kind Natural with domain [0, L], parameterised by arc length
/// @throws hula::Error(Errc::ParseError) naming "curvature" or "torsion" (with line/column) for
///   a bad expression or one that is not a scalar of the parameter
/// @throws hula::Error(Errc::InvalidArgument) naming "tolerance" for a tolerance out of range
/// @throws as reconstruct() (InvalidArgument / NonFiniteInput naming "length",
///   "start_frame.tangent", "start_frame.normal"; NumericalFailure where κ or τ is undefined)
/// @throws hula::Error(Errc::NumericalFailure) naming "tolerance" if the fit cannot meet it
[[nodiscard]] curve::Curve natural_curve(const curve::NaturalData& data, double tolerance);

}  // namespace hula::intrinsic
