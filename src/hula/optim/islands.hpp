// SPDX-License-Identifier: MIT
// The island model (pagmo's archipelago; Whitley, Rana & Heckendorn 1999):
// K populations of a Flexo algorithm evolve apart and, every M generations,
// each island sends copies of its best individuals to its neighbours in a
// topology (ring, fully connected, or a random graph drawn from a seed); the
// migrants received replace the island's worst individuals when they are
// better (pagmo's select_best / fair_replace policies). The final result
// gathers the islands' champions (one objective) or merges their populations
// and keeps the non-dominated set (several objectives), with per-island
// statistics.
//
// One island is run by run_island over an Exchange, the only part that knows
// where the other islands are: solve_islands runs K islands on threads with a
// ThreadExchange; an MPI program runs one island per rank over an exchange of
// messages, with the same migration code.
//
// Synchronous migration (the default) waits, at every migration, for the
// migrants of each in-neighbour that has not finished: a run is then a
// function of (seed, K, options) alone, repeated exactly on any machine and
// thread schedule. Asynchronous migration takes whatever has arrived and never
// waits, so a slow island does not stall the others, at the price of
// determinism (the migrants an island sees depend on timing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "hula/optim/ga.hpp"
#include "hula/optim/nsga2.hpp"
#include "hula/optim/problem.hpp"
#include "hula/optim/run_report.hpp"
#include "hula/optim/solution.hpp"

namespace hula::optim {

/// How islands are connected (who sends to whom).
enum class Topology {
  Ring,            ///< island i sends to i - 1 and i + 1 (mod K), pagmo's ring
  FullyConnected,  ///< every island sends to every other
  Random,          ///< each island sends to `random_degree` distinct others drawn from topology_seed
};

/// "ring", "fully-connected", "random".
[[nodiscard]] std::string_view topology_name(Topology topology) noexcept;
/// @throws hula::Error(Errc::InvalidOption) naming `field` for another name.
[[nodiscard]] Topology topology_from_name(std::string_view name, std::string_view field = "topology");

/// The algorithm every island runs (its options' run.seed is the archipelago's seed).
using IslandAlgorithm = std::variant<RealGaOptions, BinaryGaOptions, Nsga2Options>;

/// Options of the island model.
struct IslandOptions {
  /// Number of islands K >= 1. Default 4.
  std::size_t islands = 4;
  /// Generations between migrations M >= 1. Default 10.
  std::size_t interval = 10;
  /// Individuals sent to each neighbour per migration, >= 1 and below the population. Default 2.
  std::size_t migrants = 2;
  /// Connection graph. Default Ring.
  Topology topology = Topology::Ring;
  /// Seed of the Random topology's graph (fixed for the run). Default 0.
  std::uint64_t topology_seed = 0;
  /// Out-degree of the Random topology, in [1, K - 1] (clamped to K - 1 for small K). Default 2.
  std::size_t random_degree = 2;
  /// Asynchronous migration: never wait for neighbours (not deterministic). Default false.
  bool asynchronous = false;
  /// Several objectives: each island keeps an external archive of the feasible non-dominated points
  /// its population has held, at most K x its population, thinned by iterative crowding distance
  /// (thin_by_crowding); the merged front is drawn from the archives. Default true.
  bool archive = true;

  /// @throws hula::Error(Errc::InvalidOption) naming the field if islands, interval, migrants
  ///   or random_degree is 0.
  void validate() const;
};

/// The islands `island` sends its migrants to, in increasing order (empty when K = 1).
[[nodiscard]] std::vector<std::size_t> out_neighbours(const IslandOptions& options, std::size_t island);
/// The islands that send to `island`, in increasing order.
[[nodiscard]] std::vector<std::size_t> in_neighbours(const IslandOptions& options, std::size_t island);

/// The seed island `island` runs with: a SplitMix-derived stream of the archipelago's seed.
[[nodiscard]] std::uint64_t island_seed(std::uint64_t seed, std::size_t island) noexcept;

/// One individual on the move: its variables and values (objectives, inequality, equality).
struct Migrant {
  std::vector<double> variables{};
  std::vector<double> values{};
};

/// One migration seen by the receiving island (the run log of migration).
struct MigrationEvent {
  std::size_t generation = 0;  ///< generation after which it happened
  std::size_t from = 0;        ///< sending island
  std::size_t to = 0;          ///< receiving island
  std::size_t received = 0;    ///< migrants that arrived
  std::size_t accepted = 0;    ///< migrants that replaced a worse individual
};

/// Where the other islands are: threads of one process or MPI ranks.
class Exchange {
 public:
  Exchange() = default;
  Exchange(const Exchange&) = delete;
  Exchange& operator=(const Exchange&) = delete;
  virtual ~Exchange() = default;

  /// Sends `outgoing` from `island` to each island of `to` for migration number `epoch`
  /// (1, 2, ...) and returns, for each island of `from` in order, the migrants it sent
  /// `island` for that epoch. Synchronous: waits for each sender that has not finished
  /// (a finished sender contributes nothing). Asynchronous: the newest migrants that have
  /// arrived from each sender, never waiting (possibly none).
  /// @throws hula::Error(Errc::NumericalFailure) if another island failed (the run stops).
  virtual std::vector<std::vector<Migrant>> exchange(std::size_t island, std::size_t epoch,
                                                     const std::vector<std::size_t>& to,
                                                     const std::vector<std::size_t>& from,
                                                     const std::vector<Migrant>& outgoing) = 0;
  /// Announces that `island` will exchange no more (it stopped or failed).
  virtual void finish(std::size_t island, bool failed) = 0;
};

/// What one island returns.
struct IslandReport {
  std::size_t island = 0;
  std::uint64_t seed = 0;
  Solution best{};                   ///< champion (one objective)
  std::vector<Solution> population;  ///< final population (NSGA-II) for the merged front
  std::vector<Solution> archive;     ///< external archive (NSGA-II with IslandOptions::archive)
  RunReport report{};
  std::size_t sent = 0;      ///< migrants sent (all neighbours)
  std::size_t received = 0;  ///< migrants received
  std::size_t accepted = 0;  ///< migrants that replaced an individual
  std::vector<MigrationEvent> migrations;
};

/// The archipelago's result.
struct IslandsResult {
  Solution best{};  ///< best champion over the islands (one objective)
  /// Non-dominated feasible set of the merged populations and archives (NSGA-II), thinned by
  /// iterative crowding distance to at most the archipelago's total population.
  std::vector<Solution> front;
  std::vector<IslandReport> islands;
  /// The archipelago's report: island 0's termination and message, the most generations an island ran,
  /// evaluations and failed evaluations summed over the islands, the wall time of the whole run.
  RunReport report{};
};

/// Runs island `island` of `options.islands` with `algorithm` on `problem`, migrating through `exchange`.
/// @throws hula::Error as the algorithm, and from the exchange.
[[nodiscard]] IslandReport run_island(const Problem& problem, const IslandAlgorithm& algorithm,
                                      const IslandOptions& options, std::size_t island, Exchange& exchange);

/// Gathers island reports (in island order) into the result: champions or merged front.
[[nodiscard]] IslandsResult merge_islands(const Problem& problem, std::vector<IslandReport> islands, double seconds);

/// Runs the archipelago on options.islands threads of this process (ThreadExchange).
/// The problem's evaluate must be safe to call concurrently (as for threads > 1).
/// @throws hula::Error(Errc::InvalidOption) for invalid options, or the first island's error.
[[nodiscard]] IslandsResult solve_islands(const Problem& problem, const IslandAlgorithm& algorithm,
                                          const IslandOptions& options);

}  // namespace hula::optim
