// SPDX-License-Identifier: MIT
// Stop criteria, cancellation and the run report shared by every iterative
// solver: the Flexo algorithms, pagmo's through the adapter, Nelder–Mead and
// the studies' Levenberg–Marquardt stage (one termination enum and
// message). Modelled on Ceres' Solver::Summary (termination type + message)
// and pagmo's up-front option checks: StopCriteria::validate() refuses bad
// values before any work, and the report says why and when a run ended.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace hula::optim {

/// A point on the monotonic clock by which a whole command must end (`--time S` of a command that runs
/// several optimisers or rounds: every run it starts shares one deadline); unset = none.
using Deadline = std::optional<std::chrono::steady_clock::time_point>;

/// The deadline `seconds` from now, or none for 0.
[[nodiscard]] inline Deadline deadline_after(double seconds) {
  if (!(seconds > 0.0)) return std::nullopt;
  return std::chrono::steady_clock::now() +
         std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

/// True once `deadline` is set and has passed.
[[nodiscard]] inline bool deadline_passed(const Deadline& deadline) noexcept {
  return deadline && std::chrono::steady_clock::now() >= *deadline;
}

/// A flag another thread (a UI, a Ctrl-C handler) sets to end a run cleanly.
/// The algorithm checks it between generations and returns the best so far
/// with Termination::Cancelled.
class CancellationToken {
 public:
  /// Requests cancellation; safe from any thread and from a signal handler.
  void cancel() noexcept { flag_.store(true, std::memory_order_relaxed); }
  /// @returns true once cancel() was called.
  [[nodiscard]] bool is_cancelled() const noexcept { return flag_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> flag_{false};
};

/// Why a run ended. The names are a JSON contract (io/run_report_json.hpp): append, never rename.
enum class Termination {
  MaxGenerations,  ///< StopCriteria::generations were run (local methods: their iteration budget)
  MaxEvaluations,  ///< another generation (or step) would exceed the evaluation budget
  TargetReached,   ///< the best objective reached its target (StopCriteria::target, LmOptions::target_mean)
  Stagnation,      ///< no improvement for StopCriteria::stagnation_generations (local methods: no step
                   ///< lowers the cost any more, e.g. Levenberg–Marquardt's damping overflowed)
  WallTime,        ///< the wall-time limit elapsed
  Cancelled,       ///< the CancellationToken was set
  Converged,       ///< a local method met its convergence tolerances (Nelder–Mead's simplex size and spread,
                   ///< Levenberg–Marquardt's relative cost reduction)
};

/// Whether a run ended early by the user's limits (wall time or cancellation), keeping its best so far.
[[nodiscard]] constexpr bool stopped_early(Termination reason) noexcept {
  return reason == Termination::WallTime || reason == Termination::Cancelled;
}

/// Stable name of a termination reason, e.g. "MaxGenerations".
[[nodiscard]] std::string_view termination_name(Termination reason) noexcept;
/// The reason of a name termination_name() gives; empty for any other text.
[[nodiscard]] std::optional<Termination> termination_from_name(std::string_view name) noexcept;

/// When to stop. Every criterion that is set can end the run; the first met
/// (checked after each generation, in the order of the Termination enum) wins.
struct StopCriteria {
  /// Generations after the initial population. 0 evaluates the initial
  /// population only and returns its best. Default 100.
  std::size_t generations = 100;
  /// Budget of evaluations including the initial population; 0 = unlimited.
  /// The run stops before a generation that would exceed it. Default 0.
  std::size_t max_evaluations = 0;
  /// Single objective only: stop once the best feasible objective is <= target.
  /// Default unset.
  std::optional<double> target{};
  /// Stop when the best objective (single objective) or the hypervolume-free
  /// proxy "sum of per-objective minima" (several objectives) has not improved
  /// by more than stagnation_tolerance for this many generations; 0 = off.
  std::size_t stagnation_generations = 0;
  /// Improvement below which a generation counts as stagnant; >= 0. Default 0.
  double stagnation_tolerance = 0.0;
  /// Wall-clock limit in seconds; 0 = unlimited. Makes a run depend on the
  /// machine: leave it at 0 when reproducibility matters. Default 0.
  double wall_time_seconds = 0.0;
  /// Optional cancellation token, not owned; must outlive the run. Default none.
  const CancellationToken* cancel = nullptr;
  /// A deadline shared with the other runs of a command (its `--time`): the run ends with
  /// Termination::WallTime once it passes, whenever the run started. Default none.
  Deadline deadline{};

  /// @throws hula::Error(Errc::InvalidOption) if target is not finite,
  ///   stagnation_tolerance is negative or not finite, or wall_time_seconds
  ///   is negative or not finite; the message names the field and its value.
  void validate() const;
};

/// What happened in a run.
struct RunReport {
  /// Why the run ended.
  Termination termination = Termination::MaxGenerations;
  /// One line for humans, e.g. "250 generations run".
  std::string message{};
  /// Generations run after the initial population (local methods: iterations).
  std::size_t generations = 0;
  /// Evaluations of the problem, failed ones included.
  std::size_t evaluations = 0;
  /// Evaluations that threw or returned a non-finite value; they ranked last.
  std::size_t failed_evaluations = 0;
  /// Wall-clock duration of the run, seconds.
  double seconds = 0.0;
};

}  // namespace hula::optim
