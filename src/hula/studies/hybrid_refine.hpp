// SPDX-License-Identifier: MIT
// Hybrid refinement: after the GA, a bounded
// nonlinear least-squares solve on the residuals r_i = κ(u_i) − κ*(u_i) of the
// curvature-matching problem, so that matching reaches 1e-6 in mean curvature
// distance where an exact solution exists, with tens of free coordinates (the
// GA alone degrades beyond four, thesis Table 9).
//
// Two solvers share one Jacobian and one result type. The Jacobian is exact
// for curvature matching at parameter abscissae (CurvatureMatch::
// residuals_jacobian: the tangent-linear spline, given to Ceres as an analytic
// cost function), otherwise central finite differences (one-sided at a bound):
// - LsqSolver::Ceres (default): Ceres Solver 2.1's trust-region
//   Levenberg–Marquardt with box constraints (Problem::SetParameterLowerBound /
//   UpperBound; the trust-region step is projected on the box and the step
//   sequence stays feasible), dense QR, Jacobi scaling, non-monotonic steps.
// - LsqSolver::ClampedLm (the first hybrid solver, kept to compare): Moré's (1978)
//   Levenberg–Marquardt with Marquardt scaling D = diag(‖J_j‖), step from
//   [J; √λ D] δ ≈ [−r; 0] by Householder QR, then clamped to the box; λ ×1/3
//   after an accepted step, ×4 after a rejected one. Clamping is not a bounded
//   method: a clamped step is not the minimiser over the box.
//
// Far starts (thesis 8.2.1's open problem): from starts perturbed by 15 % of
// the point spacing with 20-50 free coordinates, a single solve from the GA's
// best stalls at 1e-3..1e-2 with either solver: Ceres converges there too
// (parameter tolerance), so these are local minima, not a solver failure. The
// hybrid therefore also starts from the direct route (LmOptions::direct_start,
// match_study.cpp): where the target is a spline's profile, through the data
// parameters read off it (spline_profile_breaks), which reaches 1e-6 with 20,
// 35 and 50 free coordinates. A continuation over the profile (κ0 → κ* in 4
// steps) was measured and did not help. docs/studies.md gives the measured table.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/optim/run_report.hpp"
#include "hula/studies/curvature_match.hpp"

namespace hula::studies {

/// Which bounded least-squares solver refines.
enum class LsqSolver {
  /// Ceres Solver's bounded trust-region Levenberg–Marquardt (default).
  Ceres,
  /// The first hybrid Levenberg–Marquardt with the step clamped to the bounds (for comparison).
  ClampedLm,
};

/// "ceres" | "clamped".
[[nodiscard]] std::string_view lsq_solver_name(LsqSolver s) noexcept;
/// @throws hula::Error(Errc::ParseError) naming `field` and the accepted names for any other name
[[nodiscard]] LsqSolver lsq_solver_from_name(std::string_view name, std::string_view field);

/// Options of refine_levenberg_marquardt.
struct LmOptions {
  /// The solver. Default Ceres; ClampedLm only to compare with its results.
  LsqSolver solver = LsqSolver::Ceres;
  /// Matching studies (run_curvature_match, planar): also build starts by integrating the target profile from
  /// the start point and tangent (the direct route, the profile read as one of normalised arc length). Where the
  /// target shows the data parameters of a spline (spline_profile_breaks), the data points go there along the
  /// integrated curve, its length chosen by a scan and, if the end may slide, a golden-section search over
  /// lengths on the distance after a 20-step refinement; that refinement comes first. Otherwise the length is the
  /// start spline's, the points at the start's chord fractions or equally spaced, and the refinement starts from
  /// the closer of it and the GA's best. If the target was not reached, the other start is refined too, keeping
  /// the better (MatchResult::lm_start says which; the iterations add up). Default true.
  bool direct_start = true;
  /// Steps (accepted or rejected) at most; >= 1. Default 200.
  std::size_t max_iterations = 200;
  /// Accepted steps at most (each one recomputes the Jacobian); 0 = no limit but max_iterations (default).
  /// A solve it ends reports Termination::MaxGenerations.
  std::size_t max_accepted_steps = 0;
  /// Stop once the mean curvature distance is <= this; >= 0, finite. Default 1e-10.
  double target_mean = 1e-10;
  /// Stop when an accepted step lowers ‖r‖² by less than this fraction of it; >= 0. Default 1e-14.
  double relative_tolerance = 1e-14;
  /// Starting damping λ; > 0, finite. Default 1e-3.
  double initial_lambda = 1e-3;
  /// Curvature matching at parameter abscissae: use the exact Jacobian (CurvatureMatch::residuals_jacobian).
  /// false = central finite differences as for arc-length abscissae (to compare; about 2 x n residual
  /// evaluations per Jacobian instead of one). Default true.
  bool exact_jacobian = true;
  /// Finite-difference step relative to max(1, |x_j|); in (0, 1e-2]. Default 1e-6.
  double difference_step = 1e-6;
  /// Without an exact Jacobian: one-sided (forward, or backward at an upper bound) differences from the
  /// residuals at x, n residual evaluations per Jacobian instead of 2n, accurate to O(step) instead of
  /// O(step²) (for a caller with a deadline: the fairing assistant's ghost). Default false (central).
  bool forward_differences = false;
  /// Wall-clock budget of the solve, seconds; 0 = none (default), otherwise finite and > 0. Checked after
  /// every step once a step has been accepted (the first accepted step always runs); a solve it ends reports
  /// Termination::WallTime and keeps its best point. Not part of the study files (a caller's limit).
  double time_budget_seconds = 0.0;

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
  /// Why it stopped: TargetReached, Converged (an accepted step lowered ‖r‖² by less than relative_tolerance,
  /// or Ceres's CONVERGENCE), MaxGenerations (max_iterations steps), Stagnation (the damping overflowed: no
  /// step lowers the cost; Ceres's FAILURE), WallTime (LmOptions::time_budget_seconds ran out), with a
  /// message (Ceres's own for its solver).
  optim::Termination termination = optim::Termination::MaxGenerations;
  std::string message{};
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
  /// Optional exact Jacobian: writes the residuals and ∂r_i/∂x_j (residual_count × variables, row-major); returns
  /// false where undefined. Unset = central finite differences (one-sided at a bound).
  std::function<bool(std::span<const double> x, std::span<double> r, std::span<double> jacobian)> jacobian{};
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
