// SPDX-License-Identifier: MIT
// A deterministic local optimiser: the Nelder–Mead downhill simplex (Nelder &
// Mead 1965) with the adaptive coefficients of Gao & Han (2012) for higher
// dimensions and restarts from the best vertex (the classic remedy for a
// collapsed simplex). Unconstrained and derivative-free: it needs only f(x),
// which suits objectives evaluated by quadrature (curve energies) whose
// gradients are not available. Constraints are the caller's business (an
// unconstrained transform such as log-ratios of interval widths).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"

namespace hula::optim {

/// The objective: f(x) for x of the problem's dimension. May return NaN or
/// +inf for points it refuses; they rank worst.
using ObjectiveFn = std::function<double(std::span<const double> x)>;

/// Options of nelder_mead.
struct NelderMeadOptions {
  /// Initial simplex step added to each coordinate of the start, finite, > 0. Default 0.1.
  double initial_step = 0.1;
  /// Stop when the simplex's largest vertex distance from the best is <= x_tolerance
  /// and the spread of f over the simplex is <= f_tolerance (both finite, >= 0). Default 1e-10.
  double x_tolerance = 1e-10;
  /// See x_tolerance. Absolute spread of f. Default 1e-14.
  double f_tolerance = 1e-14;
  /// Budget of evaluations, >= 1. Default 20000.
  std::size_t max_evaluations = 20000;
  /// Restarts from the best vertex with a fresh simplex after convergence, to
  /// escape a collapsed simplex; the run ends earlier when a restart does not
  /// improve f. Default 3.
  std::size_t restarts = 3;
  /// Wall-clock limit in seconds (finite, >= 0); 0 = none. The run ends with
  /// the best point so far and Termination::WallTime. Default 0.
  double wall_time_seconds = 0.0;
  /// Optional cancellation token (e.g. set on SIGINT), not owned; checked
  /// every iteration. The run ends with the best point so far and
  /// Termination::Cancelled. Default none.
  const CancellationToken* cancel = nullptr;
  /// A deadline shared with the other runs of a command (its `--time`); the run ends with the best
  /// point so far and Termination::WallTime once it passes. Default none.
  Deadline deadline{};
  /// Called on the caller's thread with the simplex after each iteration (its n + 1 vertices as the
  /// population, one objective; a vertex whose value is NaN or +inf is flagged failed): generation i is
  /// the simplex iteration i starts from (0 = the first simplex), then one last generation,
  /// NelderMeadResult::report.generations, holds the final simplex (it contains the best point).
  /// `evaluations` counts f's calls so far. It only reads: the run is the same with or without it. Default
  /// none.
  GenerationCallback on_generation{};
  /// @throws hula::Error(Errc::InvalidOption) naming the field and its value.
  void validate() const;
};

/// Result of nelder_mead.
struct NelderMeadResult {
  /// Best point found.
  std::vector<double> x{};
  /// f(x).
  double value = 0.0;
  /// Why the run ended — Converged (the tolerances were met), MaxEvaluations,
  /// WallTime or Cancelled — with a message; generations = iterations,
  /// evaluations of f, failed_evaluations = evaluations that were NaN or +inf.
  RunReport report{};
  /// Best value after each iteration (a convergence graph).
  std::vector<double> history{};
};

/// Minimises f from `start` by the downhill simplex.
/// @param f the objective (called on the caller's thread only)
/// @param start the first point, at least one finite coordinate
/// @param options steps, tolerances, budget, restarts
/// @returns the best point, its value and the run report
/// @throws hula::Error(Errc::InvalidArgument) for an empty start
/// @throws hula::Error(Errc::NonFiniteInput) naming start[i] if it is not finite
/// @throws hula::Error(Errc::NumericalFailure) if f is not finite at the start
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Complexity: O(n) evaluations per iteration (one or two, n on a shrink), O(n^2) bookkeeping.
[[nodiscard]] NelderMeadResult nelder_mead(const ObjectiveFn& f, std::span<const double> start,
                                           const NelderMeadOptions& options = {});

}  // namespace hula::optim
