// SPDX-License-Identifier: MIT
// `hula optimise --islands K`: the island model (hula/optim/islands.hpp) for
// the Flexo algorithms of `hula optimise`, on K threads of this process or one
// island per rank under mpirun (oli::solve_on_ranks). The options live here so
// that optimise.cpp only forwards to them; the JSON of the per-island
// statistics and migration log is io::islands_to_json.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
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

}  // namespace hula::cli
