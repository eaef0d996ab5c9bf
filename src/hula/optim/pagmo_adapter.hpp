// SPDX-License-Identifier: MIT
// The "flexible optimisation wheel" (thesis appendix 1.5): a Flexo Problem
// solved by one of pagmo2's algorithms (CMA-ES, DE, SADE, PSO, SGA, MOEA/D,
// NSGA-II), so the user picks the algorithm per problem and the benchmarks
// measure Flexo against pagmo in the same run. Built as the separate target
// hula::optim_pagmo so only its users link pagmo.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "hula/optim/problem.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"
#include "hula/optim/solution.hpp"

namespace hula::optim {

/// pagmo2 algorithms reachable through the adapter.
enum class PagmoAlgorithm {
  Cmaes,  ///< pagmo::cmaes, single objective, box constraints
  De,     ///< pagmo::de, single objective
  Sade,   ///< pagmo::sade (self-adaptive DE), single objective
  Pso,    ///< pagmo::pso, single objective
  Sga,    ///< pagmo::sga (simple genetic algorithm), single objective
  Moead,  ///< pagmo::moead, several objectives
  Nsga2,  ///< pagmo::nsga2, several objectives
};

/// Looks an algorithm up by its pagmo name ("cmaes", "de", "sade", "pso", "sga", "moead", "nsga2").
/// @throws hula::Error(Errc::InvalidArgument) naming the unknown algorithm.
[[nodiscard]] PagmoAlgorithm pagmo_algorithm(std::string_view name);

/// Options of solve_with_pagmo.
struct PagmoOptions {
  /// The algorithm. Default Nsga2.
  PagmoAlgorithm algorithm = PagmoAlgorithm::Nsga2;
  /// Population size; pagmo's own limits apply (NSGA-II: multiple of 4, > 4;
  /// DE, CMA-ES: >= 5; SADE: >= 7). Default 100.
  std::size_t population = 100;
  /// Generations of the algorithm. Default 100.
  std::size_t generations = 100;
  /// Seed of pagmo's population and algorithm. Default 0.
  std::uint64_t seed = 0;
  /// Called on the caller's thread once per generation. pagmo runs its own loop, so a generation is
  /// counted by its evaluations (each of these algorithms evaluates `population` points per generation):
  /// generation 0 is the initial population, generation g ≥ 1 the `population` points evaluated g-th
  /// (the offspring, trial vectors or samples of pagmo's generation g), and the last generation is the
  /// final population pagmo returns (for several objectives, the front the result is drawn from; for one
  /// objective pagmo's champion, the result, is its best member except with CMA-ES, whose population holds
  /// the last samples). Failed evaluations are flagged failed; violation 0; fitness NaN (pagmo's own
  /// ranking is not exposed). It only reads: the run is the same with or without it. Default none.
  GenerationCallback on_generation{};
  /// Ends the run early once set (Termination::Cancelled), from any thread. pagmo runs its own loop, so the
  /// adapter looks at it before every evaluation pagmo asks for (once one evaluation has succeeded) and
  /// unwinds pagmo's loop from there: the result is the best evaluation so far (one objective; the first of
  /// equal values) or the non-dominated set of every successful evaluation so far (several objectives),
  /// not pagmo's population, which stays inside pagmo. While it is not set the run is the same as without
  /// it, to the last bit. Not owned; must outlive the run. Default none.
  const CancellationToken* cancel = nullptr;
  /// Wall-clock limit in seconds, checked as `cancel` is (Termination::WallTime); 0 = unlimited. Makes a
  /// run depend on the machine. Default 0.
  double wall_time_seconds = 0.0;

  /// @throws hula::Error(Errc::InvalidOption) naming the field and value if
  ///   population or generations is 0, or wall_time_seconds is negative or not finite.
  void validate() const;
};

/// Result of a pagmo run.
struct PagmoResult {
  /// Single objective: pagmo's champion. Several objectives: empty.
  Solution best{};
  /// Several objectives: the final population's first non-dominated front. Single objective: empty.
  std::vector<Solution> front{};
  /// Evaluations (pagmo's fevals; a stopped run: the evaluations made), failed evaluations, time;
  /// termination MaxGenerations, or Cancelled / WallTime for a run ended early (PagmoOptions::cancel,
  /// wall_time_seconds) with `generations` the complete generations of `population` evaluations made
  /// after the initial population.
  RunReport report{};
};

/// Solves a Flexo problem with a pagmo2 algorithm. Failed evaluations (throw
/// or NaN) are given the worst representable value so pagmo ranks them last,
/// and are counted in the report.
/// @param problem a problem without constraints (pagmo's algorithms here do not take them).
/// @param options algorithm, population, generations, seed (pagmo takes 32 bits of it).
/// @returns pagmo's champion (one objective) or first front (several) and a report.
/// @throws hula::Error(Errc::InvalidOption) if the problem or options are
///   invalid, the algorithm cannot handle the problem (objective count,
///   constraints), or pagmo refuses the settings (its message is included).
/// @throws hula::Error(Errc::NumericalFailure) if no evaluation returned finite values.
[[nodiscard]] PagmoResult solve_with_pagmo(const Problem& problem, const PagmoOptions& options = {});

}  // namespace hula::optim
