// SPDX-License-Identifier: MIT
// `hula optimise --islands K`; see islands.hpp.
#include "commands/islands.hpp"

#include <optional>
#include <utility>
#include <variant>

#if defined(HULA_WITH_MPI)
#include "hula/optim/islands_mpi.hpp"
#endif

namespace hula::cli {

void add_island_options(CLI::App* sub, IslandArgs& args) {
  sub->add_option("--islands", args.islands,
                  "Run K islands (one population each) with migration, on threads, or one per rank under "
                  "mpirun -np K; 0 = one population (default)");
  sub->add_option("--migration-interval", args.interval, "Generations between migrations (default 10)");
  sub->add_option("--migrants", args.migrants, "Best individuals sent to each neighbour per migration (default 2)");
  sub->add_option("--topology", args.topology, "ring | fully-connected | random (default ring)");
  sub->add_option("--topology-seed", args.topology_seed, "Seed of the random topology's graph (default 0)");
  sub->add_flag("--async-migration", args.asynchronous,
                "Never wait for neighbours' migrants (faster with uneven islands; not repeatable)");
}

optim::IslandOptions island_options(const IslandArgs& args) {
  optim::IslandOptions o;
  o.islands = args.islands;
  o.interval = args.interval;
  o.migrants = args.migrants;
  o.topology = optim::topology_from_name(args.topology, "topology");
  o.topology_seed = args.topology_seed;
  o.asynchronous = args.asynchronous;
  return o;
}

std::optional<IslandRun> run_islands_or_solve(const optim::Problem& problem, const optim::SolveOptions& options) {
#if defined(HULA_WITH_MPI)
  if (options.islands && optim::launched_by_mpi()) {
    std::optional<optim::IslandsResult> merged =
        optim::solve_islands_mpi(problem, optim::island_algorithm(options.algorithm), *options.islands);
    if (!merged) return std::nullopt;
    return IslandRun{optim::solve_result(problem, std::move(*merged)), "mpi"};
  }
#endif
  return IslandRun{optim::solve(problem, options), "threads"};
}

}  // namespace hula::cli
