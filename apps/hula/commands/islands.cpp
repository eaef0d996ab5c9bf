// SPDX-License-Identifier: MIT
// `hula optimise --islands K`; see islands.hpp.
#include "commands/islands.hpp"

#include <optional>
#include <utility>
#include <variant>

#include "hula/io/run_report_json.hpp"

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

Json islands_json(const optim::IslandOptions& o, const optim::SolveResult& result, const optim::Problem& problem,
                  const std::string& transport) {
  Json per = Json::array();
  for (const optim::IslandReport& i : result.islands) {
    Json migrations = Json::array();
    for (const optim::MigrationEvent& e : i.migrations)
      migrations.push_back(
          Json{{"generation", e.generation}, {"from", e.from}, {"received", e.received}, {"accepted", e.accepted}});
    Json j = Json::object();
    j["island"] = i.island;
    j["seed"] = i.seed;
    if (problem.objectives == 1) j["best"] = Json{{"variables", i.best.variables}, {"objectives", i.best.objectives}};
    j.update(io::run_report_to_json(i.report));
    j["sent"] = i.sent;
    j["received"] = i.received;
    j["accepted"] = i.accepted;
    if (problem.objectives > 1) j["archive"] = i.archive.size();
    j["migrations"] = std::move(migrations);
    per.push_back(std::move(j));
  }
  return Json{{"count", o.islands},
              {"interval", o.interval},
              {"migrants", o.migrants},
              {"topology", std::string(optim::topology_name(o.topology))},
              {"topology_seed", o.topology_seed},
              {"mode", o.asynchronous ? "asynchronous" : "synchronous"},
              {"transport", transport},
              {"per_island", std::move(per)}};
}

}  // namespace hula::cli
