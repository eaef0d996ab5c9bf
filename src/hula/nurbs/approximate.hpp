// SPDX-License-Identifier: MIT
// Least-squares approximation with fixed end points (thesis 5.3.3; The NURBS
// Book 9.4.1): a B-spline of chosen degree and number of control points that
// passes through the first and last data point and minimises the sum of
// squared distances at the data parameters; the same fit on given parameters
// and knots; and rebuild, a curve refitted with a chosen degree and number of
// control points (the "Rebuild" of CAD systems), its deviation measured.
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

/// Least-squares fit on given data parameters and knots, through the first and last point: the control points
/// P_1 … P_{n−1} minimise Σ_k |C(t_k) − Q_k|² with P_0 = Q_0, P_n = Q_m (The NURBS Book eq. 9.63–9.67), the
/// normal equations solved as a banded system. The step approximate() takes once it has chosen t and U.
/// @param points Q_0 … Q_m (m ≥ 1), finite (z = 0 when dimension = 2)
/// @param parameters t_0 … t_m, non-decreasing, inside the knots' domain, finite
/// @param knots a clamped knot vector (end multiplicity p + 1), at most m + 1 control points
/// @param dimension 2 or 3
/// @returns the curve on `knots` (non-rational); with P_0 = Q_0 and P_n = Q_m exactly
/// @throws hula::Error(Errc::InvalidArgument) naming "parameters" (count, order, outside the domain) or "knots"
///   (not clamped, more control points than points)
/// @throws hula::Error(Errc::NonFiniteInput) naming the point or parameter
/// @throws hula::Error(Errc::TooFewPoints) if fewer than 2 points; InvalidOption if dimension is not 2 or 3
/// @throws hula::Error(Errc::NumericalFailure) naming "knots" if the normal equations are singular (a knot span
///   holds too few parameters: the Schoenberg–Whitney condition fails)
/// Complexity O(m p²).
[[nodiscard]] NurbsCurve least_squares_fit(std::span<const Vec3> points, std::span<const double> parameters,
                                           const KnotVector& knots, int dimension = 3);

/// Options of rebuild().
struct RebuildOptions {
  /// Degree p of the new curve, 1 … kMaxDegree. Default 3.
  int degree = 3;
  /// Number of control points n + 1 of the new curve, ≥ degree + 1. Required (0 is invalid).
  std::size_t control_points = 0;
  /// Samples of the curve fitted, uniform in its parameter, ends included: 0 (default) takes
  /// max(201, 10 × control_points); else ≥ control_points (fewer cannot determine the fit).
  std::size_t samples = 0;
  /// Samples of the new curve at which its distance to the original is measured (closest points), ≥ 2.
  /// Default 1001.
  std::size_t deviation_samples = 1001;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of rebuild().
struct RebuildResult {
  NurbsCurve curve;
  /// max over the deviation samples s_i of the new curve of the distance from C_new(s_i) to the closest point
  /// of the original curve (closest_point), model units: measured, not a bound.
  double max_deviation = 0.0;
  double mean_deviation = 0.0;  ///< mean of the same distances
  double at = 0.0;              ///< parameter of the new curve where max_deviation is reached
  std::size_t samples = 0;      ///< samples of the original that were fitted
};

/// The curve refitted with a chosen degree and number of control points, same domain and ends: the original
/// sampled at `samples` parameters uniform in its domain, fitted by least_squares_fit at the same parameters on a
/// uniform clamped knot vector of the domain, so the new curve follows the original's parameterisation. A
/// curve of the new spline space (a cubic Bézier rebuilt as a cubic with more control points, or any curve
/// whose breakpoints are among the uniform knots with enough continuity) is reproduced to rounding. The result
/// is non-rational (a rational original is approximated) and of the original's dimension.
/// @param curve any valid curve
/// @param options degree, control_points, samples, deviation_samples
/// @returns the new curve and its deviation from the original (measured with closest_point, see RebuildResult)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) if the fit is singular (cannot happen with the default samples)
/// Complexity O(samples p²) for the fit, deviation_samples closest-point searches for the measure.
/// Example: `rebuild(circle, {.degree = 3, .control_points = 12})` is a cubic within about 1e-3 of the circle.
[[nodiscard]] RebuildResult rebuild(const NurbsCurve& curve, const RebuildOptions& options);

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
