// SPDX-License-Identifier: MIT
// Scanned points to a class-A curve (thesis chapter 3, 3.4–3.6: digitised
// points with noise and strays, a curve within the A-class 0.3 mm or B-class
// 0.5 mm tolerance with a clean curvature profile), and precise design points
// (an airfoil's coordinates) to a compact fair curve. Three stages:
//
//  1. order (studies::order_points): the file order when the caller says so or
//     when it is consistent (each point beside the next, short detours of strays
//     aside), else an MST skeleton; starting parameters by chord length or by
//     projection on the skeleton; closed curves detected (ends together, no
//     corner where they meet);
//  2. noise: σ̂ from local quadratic residuals along the order
//     (studies::estimate_noise), never assumed: exact data give σ̂ ≈ 0 and no
//     design point is ever a stray for being far from a coarse curve;
//  3. the tolerance fit of studies::fit_within_tolerance with outlier rejection:
//     knots split where points lie beyond the tolerance and the neighbours lean
//     the same way (the curve is short of a feature), spikes left out as strays,
//     parameter correction, degree choice, knot removal, then fairing within the
//     tolerance that moves the curve by at most max(σ̂, 0.01 × tolerance) (the
//     fairing may not trade the fit to the data for smoothness beyond the noise).
//     When the faired curve's ∫κ'² ds is not lower than the fit's, the fit is kept.
//
// A stray is a point farther than the tolerance from the final curve: it cannot
// be kept. No run of points at an end is dropped: a fit that falls short of an end
// stretches its parameters along the end tangent, and takes back an end point the
// ordering left out (isolated across a gap) when it lies on the curve's extension.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/studies/point_order.hpp"
#include "hula/studies/tolerance_fit.hpp"

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
  /// The points are already in order along the curve: take the file order without testing it (it is
  /// taken anyway when found consistent). Default false.
  bool ordered = false;
  /// Ordering options (stage 1). Default {}.
  PointOrderOptions order{};
  /// Largest number of control points stage 3 may use. Default 200; valid ≥ p + 1.
  std::size_t max_control_points = 200;
  /// Run stage 4 (fairing). Default true.
  bool fair = true;
  /// The end-stray check of stage 3 (ToleranceFitOptions::end_check). Default {}.
  EndStrayCheck end_check{};
  /// Progress of stage 3 (ToleranceFitOptions::on_generation: one generation per candidate curve, its
  /// best the candidate's largest deviation, its evaluations the least-squares solves so far), then one
  /// last generation with the result: after.max_deviation and `fits`. It only reads: the result is the
  /// same with or without it. Default none.
  optim::GenerationCallback on_generation{};
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
  /// Noise scale σ̂ of stage 2 (local quadratic residuals), model units.
  double noise_scale = 0.0;
  /// Distance beyond which a point is judged (a stray, or a feature to refine): the tolerance. Kept
  /// under its former name (the robust stage's biweight scale, max(4.685 σ̂, tolerance)).
  double biweight_scale = 0.0;
  /// Where the order came from, and whether the curve closes on itself (then `fit` and `faired` are
  /// periodic splines in clamped form, their ends equal).
  OrderSource ordering = OrderSource::SpanningTree;
  bool closed = false;
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
/// @throws hula::Error(Errc::TooFewPoints) if n < 10
/// @throws hula::Error(Errc::NonFiniteInput) naming the first non-finite point
/// @throws hula::Error(Errc::CoincidentPoints) if all points coincide
/// @throws hula::Error(Errc::NumericalFailure) if no fit up to max_control_points meets the tolerance,
///   naming the best deviation reached and where
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Complexity O(n k log n) for the ordering plus O(n p²) per least-squares solve.
/// Example: `fit_scan(cloud, {}).faired` is the A-class curve; `.strays` the rejected indices.
[[nodiscard]] ScanFitResult fit_scan(std::span<const Vec3> points, const ScanFitOptions& options = {});

}  // namespace hula::studies
