// SPDX-License-Identifier: MIT
// Least-squares approximation with fixed end points (thesis 5.3.3; The NURBS
// Book 9.4.1): a B-spline of chosen degree and number of control points that
// passes through the first and last data point and minimises the sum of
// squared distances at the data parameters.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Options of approximate.
struct ApproximationOptions {
  /// Number of control points n + 1; degree + 1 ≤ n + 1 ≤ number of points. Required (0 is invalid).
  std::size_t control_points = 0;
  /// Degree p ≥ 1. Default 3.
  int degree = 3;
  /// Data parameters rule. Default ChordLength.
  Parameterisation parameterisation = Parameterisation::ChordLength;
  /// 2 for a planar curve, else 3. Default 3.
  int dimension = 3;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of approximate.
struct ApproximationResult {
  NurbsCurve curve;
  /// Data parameters used (in [0, 1]).
  std::vector<double> parameters;
  /// max_i |C(t_i) - Q_i| in model units.
  double max_deviation = 0.0;
  /// Index of the point where max_deviation occurs.
  std::size_t max_deviation_index = 0;
};

/// Least-squares fit with fixed end points.
/// Interior knots by averaging (The NURBS Book eq. 9.69); when control_points
/// equals the number of points the fit is an interpolation and the knots are
/// those of eq. 9.8 (eq. 9.69 is nearly singular there).
/// @param points data points Q_0 … Q_m (m ≥ 1), finite
/// @param options degree, number of control points, parameterisation, dimension
/// @returns the curve (P_0 = Q_0, P_n = Q_m exactly), the data parameters and the maximum deviation
/// @throws hula::Error(Errc::InvalidArgument) if dimension is 2 and a point has z ≠ 0 (names the index)
/// @throws hula::Error(Errc::NumericalFailure) if the normal equations are singular to working precision
/// @throws hula::Error(Errc::InvalidOption) if options are invalid or control_points > number of points
/// @throws hula::Error(Errc::TooFewPoints / NonFiniteInput / CoincidentPoints) as parameterise
[[nodiscard]] ApproximationResult approximate(std::span<const Vec3> points, const ApproximationOptions& options);

/// Result of approximate_to_tolerance().
struct ToleranceFitResult {
  /// The fit with the fewest control points found (its max_deviation ≤ tolerance).
  ApproximationResult fit;
  /// Number of least-squares fits the search ran.
  std::size_t fits = 0;
};

/// Least-squares fit with the fewest control points whose max_deviation (at the data points)
/// meets `tolerance`. Search: n + 1 = N control points interpolates (deviation at rounding
/// level), so the answer exists; a binary search over [degree + 1, N] finds the smallest count
/// that meets the tolerance assuming the deviation does not grow with the count, then counts
/// below it are tried one by one for as long as a smaller one still meets the tolerance (the
/// deviation of averaged-knot fits is not strictly monotone). `options.control_points` is ignored.
/// @param tolerance > 0, model units
/// @throws hula::Error(Errc::InvalidArgument) if tolerance is not positive and finite
/// @throws as approximate()
/// Complexity O(log N) fits plus the downward steps, each O(N p²).
[[nodiscard]] ToleranceFitResult approximate_to_tolerance(std::span<const Vec3> points, double tolerance,
                                                          ApproximationOptions options = {});

}  // namespace hula::nurbs
