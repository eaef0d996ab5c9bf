// SPDX-License-Identifier: MIT
// `hula optimise --islands K`: the island model (hula/optim/islands.hpp) for
// the Flexo algorithms of `hula optimise`, on K threads of this process. The
// options live here so that optimise.cpp only forwards to them; the JSON of
// the per-island statistics and migration log is io::islands_to_json.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "commands/common.hpp"
#include "hula/io/optimise_request.hpp"

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

/// The island options of the command line.
/// @throws hula::Error(Errc::InvalidOption) naming --topology for an unknown topology
[[nodiscard]] optim::IslandOptions island_options(const IslandArgs& args);

/// A run of `hula optimise` and where its islands ran.
struct IslandRun {
  optim::SolveResult result;
  std::string transport = "threads";  ///< "threads" or "mpi"
};

/// Runs optim::solve, or, with islands under mpirun (built with HULA_MPI), one island per rank
/// (options.islands->islands must equal the number of ranks).
/// @returns the result, or nothing on an MPI rank other than 0 (rank 0 prints the result)
/// @throws as optim::solve and optim::solve_islands_mpi
[[nodiscard]] std::optional<IslandRun> run_islands_or_solve(const optim::Problem& problem,
                                                            const optim::SolveOptions& options);

}  // namespace hula::cli
