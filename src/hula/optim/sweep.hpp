// SPDX-License-Identifier: MIT
// The thesis's practices as tools: fitness mapping / sensitivity sweeps over
// one or two variables with the others held at nominal values (appendix 6.1,
// 8.2.1 "fitness function test"), re-running with bounds re-centred on the
// best solution (8.2.1), and convergence statistics of a run log (10.1:
// best, mean, spread and the slope of the convergence front).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "hula/optim/ga.hpp"
#include "hula/optim/problem.hpp"
#include "hula/optim/run_log.hpp"

namespace hula::optim {

/// One swept variable.
struct SweepAxis {
  /// Index of the variable in Problem::variables.
  std::size_t variable = 0;
  /// First value; default the variable's lower bound (NaN = use the bound).
  double from = std::numeric_limits<double>::quiet_NaN();
  /// Last value; default the variable's upper bound (NaN = use the bound).
  double to = std::numeric_limits<double>::quiet_NaN();
  /// Number of samples, >= 2 (from and to included). Default 11 (appendix 6.1's 0, 0.1, ..., 1).
  std::size_t steps = 11;
};

/// Options of sweep().
struct SweepOptions {
  /// Nominal values of every variable (size = dimension); the swept ones are overwritten.
  std::vector<double> nominal{};
  /// First swept variable (columns of the map).
  SweepAxis x{};
  /// Optional second swept variable (rows of the map).
  std::optional<SweepAxis> y{};
  /// Objective whose map is returned, < objectives. Default 0.
  std::size_t objective = 0;
  /// Fitness power n of eq. 33 for the fitness map (1/(1+e))^n, finite, > 0. Default 1 (eq. 32).
  double power = 1.0;
  /// Evaluation threads (1 = serial, 0 = all cores); results do not depend on it. Default 1.
  std::size_t threads = 1;

  /// @throws hula::Error(Errc::InvalidOption) naming the field and value if
  ///   nominal has the wrong size or a non-finite value, an axis variable is
  ///   out of range, steps < 2, from/to are not finite, objective is out of
  ///   range, or power is not finite and > 0.
  void validate(const Problem& problem) const;
};

/// A one- or two-variable map.
struct SweepResult {
  /// Sampled values of the x variable (size x.steps).
  std::vector<double> x_values{};
  /// Sampled values of the y variable (size y.steps, or empty).
  std::vector<double> y_values{};
  /// Objective values, row-major rows = y samples (1 if no y), columns = x samples; NaN where failed.
  std::vector<double> objective{};
  /// Every objective of each sample (Problem::objectives per sample, samples in the order of `objective`); NaN
  /// where failed.
  std::vector<double> values{};
  /// Fitness (1/(1+e))^power of each sample, 0 where failed (e is shifted so that min e >= 0).
  std::vector<double> fitness{};
  /// Constraint violation of each sample (NaN where failed).
  std::vector<double> violation{};
  /// Number of failed evaluations.
  std::size_t failed = 0;
};

/// Evaluates the problem on a regular grid over one or two variables (appendix 6.1's fitness map).
/// @param problem the problem; variables not swept stay at options.nominal.
/// @param options axes, objective, fitness power, threads.
/// @returns the sampled values and the objective, fitness and violation maps.
/// @throws hula::Error(Errc::InvalidOption) if the problem or options are invalid.
/// Complexity: x.steps x y.steps evaluations in one batch.
[[nodiscard]] SweepResult sweep(const Problem& problem, const SweepOptions& options);

/// A copy of the problem whose bounds are shrunk by `shrink` around `centre`
/// (8.2.1): new width = shrink x old width, centred on centre and clipped to
/// the original bounds; precisions are kept.
/// @param centre dimension() values inside the bounds.
/// @param shrink in (0, 1].
/// @throws hula::Error(Errc::InvalidOption) if centre has the wrong size or
///   is outside the bounds, or shrink is outside (0, 1].
[[nodiscard]] Problem recentred(const Problem& problem, std::span<const double> centre, double shrink);

/// Result of rerun_recentred.
struct RecentredRunResult {
  /// Best solution over all rounds.
  Solution best{};
  /// Best objective after each round (round 0 = the run on the original bounds).
  std::vector<double> round_best{};
  /// Reports of each round.
  std::vector<RunReport> reports{};
};

/// Runs the real-coded GA, then re-runs it `rounds` times with bounds
/// re-centred on the best so far and shrunk by `shrink` each time (seeds
/// seed, seed+1, ...).
/// @param problem a single-objective problem.
/// @param options GA options of every round.
/// @param rounds re-runs after the first run.
/// @param shrink width factor per round, in (0, 1].
/// @returns the best over all rounds and each round's best and report.
/// @throws hula::Error(Errc::InvalidOption) as solve_real_ga and recentred.
[[nodiscard]] RecentredRunResult rerun_recentred(const Problem& problem, const RealGaOptions& options,
                                                 std::size_t rounds, double shrink);

/// Convergence statistics of a run (single objective, objective 0).
struct ConvergenceSummary {
  /// Per-generation best, mean and spread.
  std::vector<GenerationStatistics> generations{};
  /// Least-squares slope of the best-so-far objective against the generation
  /// over the last `window` generations (<= 0 while converging; ~0 when stalled). NaN if undefined.
  double slope = 0.0;
};

/// Summarises a run log.
/// @param log a single-objective run's log.
/// @param window number of final generations for the slope, >= 2.
/// @throws hula::Error(Errc::InvalidOption) if window < 2.
[[nodiscard]] ConvergenceSummary convergence(const RunLog& log, std::size_t window = 10);

/// The best `count` mutually distinct solutions a single-objective run evaluated (thesis 2.1.2, 7.4.2, app. 2:
/// a GA should return several good, different designs): niching by clearing (Pétrowski 1996) over every
/// individual of the log. Individuals are ranked feasible first, then by objective 0 (violation between
/// infeasible ones); one is kept when its distance to every kept one, √(Σ_j ((x_j − y_j) / w_j)² / d) with w_j the
/// variable's box width (fixed variables ignored), exceeds `radius`.
/// @param log every generation of a run (RunLog::collector()); @param variables the problem's variables
/// @param count >= 1 solutions at most; @param radius normalised niche radius in (0, 1], default 0.05
/// @returns up to `count` solutions, best first (fewer if the run had fewer distinct ones)
/// @throws hula::Error(Errc::InvalidOption) for count 0, a radius outside (0, 1], or a log whose dimension
///   differs from the variables'
/// Complexity: O(I log I + I · count · d) for I logged individuals.
[[nodiscard]] std::vector<Solution> distinct_best(const RunLog& log, std::span<const Variable> variables,
                                                  std::size_t count, double radius = 0.05);

}  // namespace hula::optim
