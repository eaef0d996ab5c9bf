// SPDX-License-Identifier: MIT
// `hula optimise --islands K`; see islands.hpp.
#include "commands/islands.hpp"

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

}  // namespace hula::cli
