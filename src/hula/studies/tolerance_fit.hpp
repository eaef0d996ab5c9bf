// SPDX-License-Identifier: MIT
// Compact fair B-spline fits within a tolerance: the one engine behind
// `hula fit` (studies::fit_scan, after ordering and noise estimation) and
// `hula approximate --tolerance`. Given points with starting foot parameters:
//
//  1. knots adapted to the shape: from one polynomial piece, every knot span
//     holding a point the fit leaves beyond the tolerance is split at its middle,
//     so knots gather where the curvature changes fast (an airfoil's leading
//     edge) and stay sparse elsewhere; then every interior knot whose removal
//     still meets the tolerance is removed (smallest jump of the p-th derivative
//     first);
//  2. each candidate is fitted with parameter correction: a least-squares solve,
//     every foot moved to its Newton projection on the new curve, then
//     tangent-distance solves (Wang, Pottmann & Liu, ACM TOG 25, 2006), each with
//     its projection, so a candidate passes only if the curve itself is within the
//     tolerance (deviations are |C(tᵢ) − Qᵢ| at the corrected feet);
//     Where points are dense (a scan), spans whose points lie systematically on
//     one side of the curve by more than `bias_limit` are split as well (sliding
//     windows, and at an open end windows anchored there, so that a deviation over
//     the last few points is not diluted);
//  3. degree choice: degrees from `degree` down to `min_degree` are tried; among
//     those within 15 % of the fewest control points, the curve with the fewest
//     curvature extrema wins (then the fewer control points, then the higher degree);
//  4. fairing: on the chosen knots, Σ|C(tᵢ) − Qᵢ|² + λ∫|C‴(t)|² dt with the largest
//     λ (bisection on log λ) that keeps every kept point within the tolerance and
//     moves the curve by at most `fairing_shift` at the feet.
//
// Outliers (reject_outliers): a point beyond the tolerance is a spike when the kept
// points beside it (up to 4 on each side along the curve, themselves within the
// tolerance) show no residual in its direction: their mean residual along its
// direction is at most max(0.2 × its distance, 1.5 σ̂) on both sides (σ̂ =
// `noise`). A spike leaves the fit; a point beyond the tolerance whose neighbours
// lean the same way (the curve is short of a feature) is kept and its span split.
// Spikes are re-judged every round, and a left-out point the fit passes within the
// tolerance comes back, so only points no curve of the chosen resolution can keep
// end as outliers. Without reject_outliers every point is kept.
//
// Closed curves (`closed`): a periodic B-spline (Cᵖ⁻¹ everywhere, the parameter
// wrapping at 1), returned in clamped form on [0, 1] (its first and last control
// points coincide). Open curves have free ends, or ends interpolating the points
// whose starting parameters are 0 and 1 (`ends = Interpolated`, The NURBS Book
// 9.4.1's fixed end points).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/optim/run_log.hpp"

namespace hula::studies {

/// How the ends of an open fit are held.
enum class FitEnds {
  Free,          ///< the end control points are fitted like the others
  Interpolated,  ///< the curve starts at the point of parameter 0 and ends at the point of parameter 1
};

/// The end-stray check of reject_outliers, before any knot refinement: the `judged` outermost points at each
/// open end are each measured against the least-squares quadratic (in chord length) through the next `window`
/// points inward, continued out to them; one farther from that continuation than the tolerance and 3 σ̂
/// prediction errors leaves the fit. The defaults sit inside a plateau: every (window, judged) cell of
/// window 4–12 × judged 2–5 passes the same clouds of a seeded sweep over five generators to one cloud in
/// 240, four more than with the check off (docs/studies.md, "End strays"; tests/studies/scan_fit_end_sweep.cpp),
/// so they are not tuned to one generator.
struct EndStrayCheck {
  /// Points inward the quadratic is fitted to, [4, 50]. Default 6.
  std::size_t window = 6;
  /// Outermost points judged at each end, [0, 10] (0 turns the check off). Default 3.
  std::size_t judged = 3;
};

/// Options of fit_within_tolerance.
struct ToleranceFitOptions {
  /// Largest distance of a kept point from the curve, model units; > 0 and finite. Required.
  double tolerance = 0.0;
  /// Highest degree tried, [1, 9]. Default 5.
  int degree = 5;
  /// Lowest degree tried, [1, degree]. Default 3.
  int min_degree = 3;
  /// Ends of an open fit. Default Free.
  FitEnds ends = FitEnds::Free;
  /// Periodic closed curve. Default false.
  bool closed = false;
  /// Most control points a fit may use (≥ degree + 1); also never more than the kept points. Default 200.
  std::size_t max_control_points = 200;
  /// Leave spikes out (see the file comment). Default false: every point is kept.
  bool reject_outliers = false;
  /// Noise scale σ̂ of the points, model units, ≥ 0 (0: exact data). Default 0.
  double noise = 0.0;
  /// The end-stray check of reject_outliers (see EndStrayCheck). Default {}.
  EndStrayCheck end_check{};
  /// Largest systematic deviation allowed where the points are dense (at least 10 (p + 1) kept points
  /// in a knot span): the norm of the mean residual of any 15 consecutive kept points, and at an open end
  /// of the 4 … 15 outermost kept points (their residuals normal to the end tangent); a span where it
  /// is exceeded is split even when every point is within the tolerance. 0 (default) turns it off.
  double bias_limit = 0.0;
  /// Run the fairing. Default true (degrees below 3 are never faired: their C‴ vanishes).
  bool fair = true;
  /// Largest move of the curve by the fairing, at the feet of the kept points, model units; < 0 means
  /// the tolerance. Default −1.
  double fairing_shift = -1.0;
  /// Progress: called on the caller's thread after each candidate curve is fitted (a refinement round,
  /// a knot-removal trial, the polish of the chosen fit), as fit_progress(g, solves, deviation) with g
  /// counting the candidates from 0, `solves` the least-squares solves so far and `deviation` the
  /// candidate's largest deviation of a kept point. It only reads: the fit is the same with or without
  /// it. Default none.
  optim::GenerationCallback on_generation{};
  /// @throws hula::Error(Errc::InvalidOption) naming the field and its value
  void validate() const;
};

/// One step of a fit as a generation of the progress callback (the type the optimisers report with): one
/// member, no variables, its one objective `deviation` (model units), feasible; `solves` as evaluations.
[[nodiscard]] optim::GenerationLog fit_progress(std::size_t generation, std::size_t solves, double deviation);

/// Result of fit_within_tolerance.
struct ToleranceFit {
  /// The compact fit (steps 1–3), clamped on [0, 1].
  nurbs::NurbsCurve fit;
  /// The faired curve on fit's knots (equal to fit without fairing).
  nurbs::NurbsCurve faired;
  /// Per point: its foot parameter on `faired` (outliers: of their closest point).
  std::vector<double> parameters{};
  /// Per point: |faired(parameters[i]) − points[i]|, model units.
  std::vector<double> deviations{};
  /// The same on `fit`.
  std::vector<double> fit_parameters{};
  std::vector<double> fit_deviations{};
  /// Indices of the points left out, increasing.
  std::vector<std::size_t> outliers{};
  /// Largest deviation of a kept point from `fit` and from `faired`, and the index where `faired`'s is
  /// (every kept point is within the tolerance of `faired`; a point left out during the search that
  /// `faired` passes within it is kept, and may lie a little beyond it from `fit`).
  double fit_max_deviation = 0.0;
  double max_deviation = 0.0;
  std::size_t max_deviation_index = 0;
  /// Fairing weight λ (relative to trace(BᵀB) / trace(G)); 0 without fairing.
  double smoothing = 0.0;
  /// Least-squares solves run.
  std::size_t fits = 0;
};

/// Fits a compact, fair B-spline within `options.tolerance` (see the file comment).
/// @param points n finite points, model units (all z = 0: a planar, 2-D curve)
/// @param parameters n starting foot parameters in [0, 1] (closed: the wrap is at 1)
/// @param left_out empty, or n flags: 1 = start with the point left out (a suspected outlier; it comes
///   back when the fit passes within the tolerance of it, or leans toward it)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::InvalidArgument) naming the array whose size differs from points, or a
///   parameter outside [0, 1]
/// @throws hula::Error(Errc::NonFiniteInput) naming the first non-finite point or parameter
/// @throws hula::Error(Errc::TooFewPoints) if fewer than min_degree + 1 points (closed: + 2)
/// @throws hula::Error(Errc::NumericalFailure) when no fit with up to max_control_points control points
///   meets the tolerance, naming the best deviation reached, its point and its control-point count
[[nodiscard]] ToleranceFit fit_within_tolerance(std::span<const Vec3> points, std::span<const double> parameters,
                                                std::span<const std::uint8_t> left_out,
                                                const ToleranceFitOptions& options);

}  // namespace hula::studies
