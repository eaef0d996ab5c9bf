// SPDX-License-Identifier: MIT
// Common option and result types of the Flexo algorithms: a solution (design
// variables with their objectives and violation), constraint handling
// (Deb's feasibility rules or a static penalty) and the run settings shared
// by every algorithm (seed, threads, stop criteria, run-log callback).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

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
  /// Constraint handling. Default FeasibilityRules.
  ConstraintHandling constraints = ConstraintHandling::FeasibilityRules;
  /// Penalty factor for ConstraintHandling::Penalty; finite, >= 0. Default 1000.
  double penalty = 1000.0;

  /// @throws hula::Error(Errc::InvalidOption) naming the field and value if
  ///   penalty is negative or not finite, or stop is invalid.
  void validate() const;
};

}  // namespace hula::optim
