// SPDX-License-Identifier: MIT
// Hybrid refinement (issue 6 item 3): after the GA, a bounded
// Levenberg–Marquardt on the residuals r_i = κ(u_i) − κ*(u_i) of the
// curvature-matching problem, so that matching reaches 1e-6 in mean
// curvature distance where an exact solution exists, with tens of free
// coordinates (the GA alone degrades beyond four, thesis Table 9).
//
// Method (Moré 1978, "The Levenberg–Marquardt algorithm: implementation and
// theory"): central finite-difference Jacobian (one-sided at a bound), step
// from the damped least-squares problem [J; √λ D] δ ≈ [−r; 0] by Householder
// QR (Eigen) with Marquardt's scaling D = diag(‖J_j‖), the step projected
// onto the bounds; λ shrinks ×1/3 after an accepted step and grows ×4 after a
// rejected one.
//
// Basin: the residuals are not convex in the points. Started within a few
// percent of the point spacing of an exact solution it converges in 5-25 steps
// with 4-50 free coordinates; from 15% of the spacing it does with 4 and 9, but
// stalls at mean distances of 1e-3..1e-2 with 20 or 50 (measured, see
// docs/studies/curvature-matching.md), and the GA does not bring such starts
// closer. A continuation on the target (κ(x0) -> κ*) was tried and did not help:
// the intermediate profiles have no exact solution with a fixed end point.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "hula/studies/curvature_match.hpp"

namespace hula::studies {

/// Options of refine_levenberg_marquardt.
struct LmOptions {
  /// Steps (accepted or rejected) at most; >= 1. Default 200.
  std::size_t max_iterations = 200;
  /// Stop once the mean curvature distance is <= this; >= 0, finite. Default 1e-10.
  double target_mean = 1e-10;
  /// Stop when an accepted step lowers ‖r‖² by less than this fraction of it; >= 0. Default 1e-14.
  double relative_tolerance = 1e-14;
  /// Starting damping λ; > 0, finite. Default 1e-3.
  double initial_lambda = 1e-3;
  /// Finite-difference step relative to max(1, |x_j|); in (0, 1e-2]. Default 1e-6.
  double difference_step = 1e-6;

  /// @throws hula::Error(Errc::InvalidOption) naming the field and its value when outside the ranges above
  void validate() const;
};

/// Outcome of refine_levenberg_marquardt.
struct LmResult {
  /// Refined design variables (within the bounds).
  std::vector<double> variables{};
  /// Mean curvature distance at the start and at the end.
  double mean_before = 0.0;
  double mean_after = 0.0;
  /// Steps tried (accepted or not) and residual evaluations (Jacobian columns included).
  std::size_t iterations = 0;
  std::size_t evaluations = 0;
  /// Why it stopped: "target reached", "converged", "max iterations", "damping overflow".
  std::string termination{};
  /// Wall time in seconds.
  double seconds = 0.0;
};

/// A bounded nonlinear least-squares problem: minimise ‖r(x)‖² with every x_j in
/// [variables[j].lower, variables[j].upper].
struct LeastSquaresProblem {
  /// The variables and their bounds (names are used in error messages).
  std::vector<optim::Variable> variables{};
  /// Number of residuals, >= 1.
  std::size_t residual_count = 0;
  /// Writes residual_count residuals of x; returns false where they are undefined (such a step is rejected).
  std::function<bool(std::span<const double> x, std::span<double> r)> residuals{};
};

/// Bounded Levenberg–Marquardt on any least-squares problem (the method above); LmResult's
/// mean_before / mean_after are mean |r_i| and LmOptions::target_mean applies to it.
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::InvalidArgument) if the problem has no residual or no function, or start has the
///   wrong size or leaves the bounds (naming the variable)
/// @throws hula::Error(Errc::NumericalFailure) if the residuals are undefined at the start
[[nodiscard]] LmResult refine_levenberg_marquardt(const LeastSquaresProblem& problem, std::span<const double> start,
                                                  const LmOptions& options = {});

/// Refines design variables of a curvature-matching problem by bounded Levenberg–Marquardt
/// (the residuals r_i = κ(u_i) − κ*(u_i); mean |r_i| is the mean curvature distance).
/// @param match the problem; @param start its dimension() values, within the bounds
/// @param options iteration limits and tolerances
/// @returns the refined variables and a report (never worse than the start)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::InvalidArgument) if start has the wrong size or leaves the bounds (naming the variable)
/// @throws hula::Error(Errc::NumericalFailure) if the start point's spline is degenerate
[[nodiscard]] LmResult refine_levenberg_marquardt(const CurvatureMatch& match, std::span<const double> start,
                                                  const LmOptions& options = {});

}  // namespace hula::studies
