// SPDX-License-Identifier: MIT
// Scanned points to a class-A curve (thesis chapter 3, 3.4–3.6: digitised
// points with noise and strays, a curve within the A-class 0.3 mm or B-class
// 0.5 mm tolerance with a clean curvature profile). Four stages:
//
//  1. order: the points are ordered along the curve (order_along_curve, an MST
//     skeleton) unless the caller says they already are;
//  2. robust fit: a B-spline with uniform knots is fitted by iteratively
//     reweighted least squares (Huber weights for three rounds, then Tukey's
//     biweight), the foot parameters of every point being corrected by Newton
//     projection each round (Hoschek's parameter correction). The scale is
//     σ̂ = 1.4826 · median distance (MAD of the normal distances) and the biweight
//     vanishes beyond c = max(4.685 σ̂, tolerance). A point farther than the
//     tolerance from the converged robust fit is a stray (no curve within the
//     class band may keep it);
//  3. tolerance fit: the fewest control points (uniform knots) whose fit keeps
//     every kept point within the tolerance, measured at corrected feet: each
//     candidate is fitted with parameter correction — a least-squares solve,
//     Newton projection of the feet, then tangent-distance solves (Wang, Pottmann
//     and Liu's TDM, the Gauss–Newton step of the foot-point distance) each with
//     its projection — so a count passes only if the curve itself is within the
//     tolerance. At the highest degree the count grows by half from p + 1, then
//     bisection; lower degrees down to min_degree are then tried below the count
//     found (a single Bézier piece of degree q needs only q + 1 control points),
//     the higher degree kept among equal counts. A stray that this fit passes
//     within the tolerance (global closest point) is re-admitted and the stage
//     repeated (at most 3 times);
//  4. fairing: on the same knots, the fit minimises Σ|C(tᵢ) − Qᵢ|² + λ ∫|C'''(t)|² dt
//     with the largest λ (bisection on log λ) that still keeps every kept point within
//     the tolerance. For a curve parameterised near arc length, |C'''|² = κ'² + κ⁴
//     (planar), so the penalty is ∫κ'² ds up to the κ⁴ term, small for gentle curves.
//
// The nurbs::approximate family is not reused for stages 2–4 because it fixes the
// end points to the first and last data point: with noisy data and strays the
// ends must be fitted too.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/studies/point_order.hpp"

namespace hula::studies {

/// A-class tolerance of thesis 3.4 (0.3 mm, in the data's units).
inline constexpr double kClassATolerance = 0.3;
/// B-class tolerance of thesis 3.4 (0.5 mm, in the data's units).
inline constexpr double kClassBTolerance = 0.5;

/// Options of fit_scan.
struct ScanFitOptions {
  /// Largest distance of a kept point from the curve, model units. Default A-class 0.3; valid > 0.
  double tolerance = kClassATolerance;
  /// Highest degree p of the B-spline. Default 5 (C⁴: κ' continuous); valid [3, 9] (the penalty needs C''').
  int degree = 5;
  /// Lowest degree stage 3 may choose, only when it needs fewer control points than every higher
  /// degree (as Open CASCADE's approximation tries degree after degree). Default 3; valid
  /// [3, degree]; min_degree = degree fixes the degree.
  int min_degree = 3;
  /// The points are already in order along the curve (skip stage 1; keys = index / (n − 1)). Default false.
  bool ordered = false;
  /// Ordering options (stage 1). Default {}.
  PointOrderOptions order{};
  /// Control points of the robust stage 2 fit: 0 (default) chooses clamp(n / 10, p + 1, 40).
  std::size_t robust_control_points = 0;
  /// Largest number of control points stage 3 may use. Default 200; valid ≥ p + 1.
  std::size_t max_control_points = 200;
  /// Run stage 4 (fairing). Default true.
  bool fair = true;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Shape figures of one curve.
struct ScanCurveReport {
  double max_deviation = 0.0;   ///< max distance (closest point) of a kept point, model units
  double mean_deviation = 0.0;  ///< mean distance of the kept points
  std::size_t control_points = 0;
  std::size_t inflections = 0;        ///< sign changes of the signed curvature about +Z (planar clouds)
  std::size_t curvature_extrema = 0;  ///< curvature maxima and minima in the open domain
  double curvature_variation = 0.0;   ///< ∫(dκ/ds)² ds, 1/model units³
  double bending = 0.0;               ///< ∫κ² ds, 1/model units
};

/// Result of fit_scan.
struct ScanFitResult {
  /// Stage 3: fewest control points within the tolerance ("before" fairing).
  nurbs::NurbsCurve fit;
  /// Stage 4: the faired curve on fit's knots (equal to fit when fairing is off, or when fairing
  /// did not lower ∫κ'² ds: the penalty is ∫|C'''|² dt, which can disagree on near-circular curves).
  nurbs::NurbsCurve faired;
  /// Input indices of the rejected points (strays), increasing.
  std::vector<std::size_t> strays;
  /// Input indices of the kept points in curve order (increasing foot parameter on `faired`).
  std::vector<std::size_t> order;
  /// Per input point: foot parameter on `faired` (strays: of their global closest point).
  std::vector<double> parameters;
  /// Per input point: distance to `faired` (closest point), model units.
  std::vector<double> deviations;
  /// Robust noise scale σ̂ = 1.4826 · median distance at the end of stage 2.
  double noise_scale = 0.0;
  /// Scale c = max(4.685 σ̂, tolerance) beyond which the biweight is 0 (strays: distance > tolerance).
  double biweight_scale = 0.0;
  /// Fairing weight λ (relative: λ · trace(BᵀB) / trace(G) is what was added to BᵀB); 0 without fairing.
  double smoothing = 0.0;
  /// Least-squares solves run in all stages.
  std::size_t fits = 0;
  ScanCurveReport before;  ///< figures of `fit`
  ScanCurveReport after;   ///< figures of `faired`
};

/// Fits a smooth B-spline to a scanned cloud within a tolerance (see the file comment).
/// @param points n ≥ 10 finite points, model units (z = 0 for planar clouds: the curves are then 2-D)
/// @returns the fits, the strays by index, and the figures before and after fairing
/// @throws hula::Error(Errc::TooFewPoints) if n < 10 or fewer than p + 1 points are kept
/// @throws hula::Error(Errc::NonFiniteInput) naming the first non-finite point
/// @throws hula::Error(Errc::CoincidentPoints) if all points coincide
/// @throws hula::Error(Errc::NumericalFailure) if no count up to max_control_points meets the tolerance
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Complexity O(n k log n) for the ordering plus O(n p²) per least-squares solve (about 35–55 solves).
/// Example: `fit_scan(cloud, {}).faired` is the A-class curve; `.strays` the rejected indices.
[[nodiscard]] ScanFitResult fit_scan(std::span<const Vec3> points, const ScanFitOptions& options = {});

}  // namespace hula::studies
