// SPDX-License-Identifier: MIT
// Common option and result types of the Flexo algorithms: a solution (design
// variables with their objectives and violation), constraint handling
// (Deb's feasibility rules or a static penalty) and the run settings shared
// by every algorithm (seed, threads, stop criteria, run-log callback).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "hula/optim/problem.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"

namespace hula::optim {

/// One evaluated point.
struct Solution {
  /// Design variables.
  std::vector<double> variables{};
  /// Objective values (minimised).
  std::vector<double> objectives{};
  /// Total constraint violation; 0 = feasible.
  double violation = 0.0;
};

/// How constraints beyond the bounds are handled.
enum class ConstraintHandling {
  /// Deb's feasibility rules: feasible beats infeasible, lower violation beats
  /// higher, objectives decide between feasible points.
  FeasibilityRules,
  /// Static penalty: individuals are ranked by objective + penalty x violation
  /// (single objective only; NSGA-II always uses constrained domination).
  Penalty,
};

/// A population as a migration policy sees it (the island model, islands.hpp),
/// after the survivors of a generation are chosen. Row i holds the variables
/// x[i * dimension ...], the values[i * values_per_point ...] (objectives,
/// inequality then equality constraints) and failed[i]. A policy may
/// overwrite rows and must list them in `replaced`; the algorithm then
/// re-derives its ranking keys (and binary chromosomes) from them.
struct MigrationView {
  std::size_t rows = 0;
  std::size_t dimension = 0;
  std::size_t values_per_point = 0;
  std::span<double> x{};
  std::span<double> values{};
  std::span<std::uint8_t> failed{};
  /// The algorithm's own order of rows: true when row a ranks before row b
  /// (GAs: lower violation, then lower objective; NSGA-II: lower rank, then
  /// larger crowding distance).
  std::function<bool(std::size_t, std::size_t)> better{};
  /// Rows the policy overwrote.
  std::vector<std::size_t> replaced{};
};

/// Called after generation g >= 1 with the surviving population.
using MigrationHook = std::function<void(std::size_t generation, MigrationView& view)>;

/// Settings every algorithm shares.
struct RunSettings {
  /// Seed of the run: the same seed gives the same run log on any thread count. Default 0.
  std::uint64_t seed = 0;
  /// Threads for batch evaluation: 1 = serial (default), 0 = all cores.
  std::size_t threads = 1;
  /// When to stop.
  StopCriteria stop{};
  /// Called after every generation (generation 0 = initial population); may be empty.
  GenerationCallback on_generation{};
  /// Migration between islands (optim/islands.hpp); empty (default) = a
  /// single population. Set by the island model, not by hand.
  MigrationHook migrate{};
  /// Constraint handling. Default FeasibilityRules.
  ConstraintHandling constraints = ConstraintHandling::FeasibilityRules;
  /// Penalty factor for ConstraintHandling::Penalty; finite, >= 0. Default 1000.
  double penalty = 1000.0;
  /// Individuals placed first in the initial population instead of random ones (thesis 10.1.1: seed the
  /// population with the current design), each with one value per variable inside the bounds, at most
  /// `population` of them; the binary GA codes each to its nearest grid value. Default none.
  std::vector<std::vector<double>> initial{};

  /// @throws hula::Error(Errc::InvalidOption) naming the field and value if
  ///   penalty is negative or not finite, or stop is invalid.
  void validate() const;
  /// Checks `initial` against a problem and a population size.
  /// @throws hula::Error(Errc::InvalidOption) naming run.initial[i] if there are more than `population`, one has
  ///   the wrong size, or a value is not finite or outside its variable's bounds
  void validate_initial(std::span<const Variable> variables, std::size_t population) const;
};

}  // namespace hula::optim
