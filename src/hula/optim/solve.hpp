// SPDX-License-Identifier: MIT
// One way to choose and run an optimiser: optim::solve takes a
// problem and the options of one algorithm — the binary or real-coded GA,
// NSGA-II, Nelder–Mead, or one of pagmo2's through the adapter — optionally
// run as islands (islands.hpp), and returns the best solution (one objective)
// or the final non-dominated front (several) with one RunReport. An algorithm
// is named one way (solver_from_name: `hula optimise --algorithm`, the Python
// `optimise(algorithm=...)` and a server problem job's "algorithm" all read
// their name through it), and `hula optimise`, the Python `optimise` and the
// server's problem jobs run it through solve().
//
// Built in the hula::optim_pagmo target (it links pagmo for PagmoOptions).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "hula/optim/ga.hpp"
#include "hula/optim/islands.hpp"
#include "hula/optim/nelder_mead.hpp"
#include "hula/optim/nsga2.hpp"
#include "hula/optim/pagmo_adapter.hpp"
#include "hula/optim/problem.hpp"
#include "hula/optim/run_report.hpp"
#include "hula/optim/solution.hpp"

namespace hula::optim {

/// The algorithm and its options.
using SolverOptions = std::variant<RealGaOptions, BinaryGaOptions, Nsga2Options, NelderMeadOptions, PagmoOptions>;

/// The options of the algorithm named `name`, with their defaults: "ga-real", "ga-binary", "nsga2",
/// "nelder-mead" or "pagmo-<name>" (<name> one of pagmo_algorithm's: cmaes, de, sade, pso, sga, moead,
/// nsga2). The one reader of algorithm names.
/// @throws hula::Error(Errc::InvalidArgument) naming `field` and listing the accepted names
[[nodiscard]] SolverOptions solver_from_name(std::string_view name, std::string_view field = "algorithm");

/// Every name solver_from_name reads, in its order ("ga-real", ..., "pagmo-nsga2"): for completions and
/// listings.
[[nodiscard]] std::vector<std::string> solver_names();

/// The name of the algorithm of `options` (solver_from_name's spelling; pagmo's as "pagmo-<name>").
[[nodiscard]] std::string solver_name(const SolverOptions& options);

/// What optim::solve runs.
struct SolveOptions {
  /// The algorithm. Default the real-coded GA with its defaults.
  SolverOptions algorithm = RealGaOptions{};
  /// Runs the algorithm as an archipelago on threads (solve_islands); only the GAs and NSGA-II take it.
  /// Default none: one population.
  std::optional<IslandOptions> islands{};
  /// Nelder–Mead's start point, one value per variable inside its bounds; empty (default) = the centre of
  /// the bounds. Only Nelder–Mead takes it.
  std::vector<double> start{};
};

/// What optim::solve returns.
struct SolveResult {
  /// The GAs, Nelder–Mead and pagmo on one objective: the best solution (one element). NSGA-II and
  /// several objectives: the final first front (its feasible members; possibly empty).
  std::vector<Solution> solutions{};
  /// NSGA-II on one population: its whole final population. Otherwise empty.
  std::vector<Solution> population{};
  /// Why and when the run ended (for islands: IslandsResult::report).
  RunReport report{};
  /// Islands: each island's report, champion and migration log. Otherwise empty.
  std::vector<IslandReport> islands{};
};

/// The result of an archipelago (from solve_islands or solve_islands_mpi) as optim::solve returns it.
[[nodiscard]] SolveResult solve_result(const Problem& problem, IslandsResult islands);

/// The island algorithm of `algorithm` (the GAs and NSGA-II run as islands).
/// @throws hula::Error(Errc::InvalidOption) naming "islands" for Nelder–Mead or pagmo's algorithms
[[nodiscard]] IslandAlgorithm island_algorithm(const SolverOptions& algorithm);

/// Runs the chosen algorithm on `problem`.
///
/// Nelder–Mead minimises the single objective of an unconstrained problem from `options.start` (the centre
/// of the bounds by default); points outside the bounds are ranked worst (as NaN, counted in
/// failed_evaluations), so the result stays inside them. It runs on the caller's thread.
/// @param problem a valid problem (the algorithm's own limits apply: the GAs and Nelder–Mead take one
///   objective, pagmo's algorithms no constraints)
/// @param options the algorithm, islands and start
/// @returns the best solution or front and the report
/// @throws hula::Error(Errc::InvalidOption) for an invalid problem or options, islands with Nelder–Mead or
///   pagmo, a start with Nelder–Mead's wrong size or outside the bounds, or a start with another algorithm;
///   otherwise as the algorithm (solve_real_ga, solve_binary_ga, solve_nsga2, nelder_mead,
///   solve_with_pagmo, solve_islands)
[[nodiscard]] SolveResult solve(const Problem& problem, const SolveOptions& options);

}  // namespace hula::optim
