// SPDX-License-Identifier: MIT
// `hula optimise --islands K`: the island model (hula/optim/islands.hpp) for
// the Flexo algorithms of `hula optimise`, on K threads of this process. The
// options and the JSON of the per-island statistics and migration log live
// here so that optimise.cpp only forwards to them.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "commands/common.hpp"
#include "hula/optim/islands.hpp"

namespace hula::cli {

/// The --islands options.
struct IslandArgs {
  std::size_t islands = 0;  ///< 0 = a single population
  std::size_t interval = 10;
  std::size_t migrants = 2;
  std::string topology = "ring";
  std::uint64_t topology_seed = 0;
  bool asynchronous = false;
};

/// Adds --islands, --migration-interval, --migrants, --topology, --topology-seed, --async-migration.
void add_island_options(CLI::App* sub, IslandArgs& args);

/// What an island run gives `hula optimise`.
struct IslandOutcome {
  std::vector<optim::Solution> solutions;  ///< the best champion, or the merged non-dominated front
  optim::RunReport report;                 ///< totals: evaluations summed, wall time, island 0's termination
  Json islands;                            ///< {"count", "topology", ..., "per_island": [...]} with the migration log
  bool quiet = false;                      ///< an MPI rank other than 0: rank 0 prints the result
};

/// Runs `algorithm` as args.islands islands on threads, or, under mpirun (built with HULA_MPI),
/// one island per rank (args.islands must equal the number of ranks).
/// @throws hula::Error(Errc::InvalidOption) for bad island options; the first island's error.
[[nodiscard]] IslandOutcome run_islands(const optim::Problem& problem, const optim::IslandAlgorithm& algorithm,
                                        const IslandArgs& args);

}  // namespace hula::cli
