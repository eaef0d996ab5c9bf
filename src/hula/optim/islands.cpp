// SPDX-License-Identifier: MIT
// The island model; see islands.hpp. Migration policy (pagmo's select_best +
// fair_replace, one migrant at a time): an island sends copies of its
// `migrants` best individuals (the algorithm's own order) to every
// out-neighbour; the migrants it receives, taken in the order of their
// senders, each replace the island's current worst individual unless that
// individual is at least as good (one objective: Deb's feasibility rules on
// violation, then objective; several: unless it constrained-dominates the
// migrant).
#include "hula/optim/islands.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <map>
#include <mutex>
#include <numeric>
#include <string>
#include <thread>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/optim/islands_mpi.hpp"
#include "hula/optim/pareto.hpp"

namespace hula::optim {

namespace {

// Raised in an island whose neighbour failed; solve_islands reports the neighbour's own error instead.
class PeerFailed : public Error {
 public:
  PeerFailed() : Error(Errc::NumericalFailure, "another island failed: the run stopped", {.field = "islands"}) {}
};

RunSettings& run_of(IslandAlgorithm& a) {
  return std::visit([](auto& o) -> RunSettings& { return o.run; }, a);
}

// (violation, objective) of one value row: the single-objective key of Deb's feasibility rules.
std::pair<double, double> key(const Problem& problem, std::span<const double> values) {
  return {problem.violation(values), values[0]};
}

// The feasible non-dominated members of `pool`, one per objective vector (the first met), thinned by
// iterative crowding distance to at most `capacity`.
std::vector<Solution> thinned_front(std::vector<Solution> pool, std::size_t m, std::size_t capacity) {
  std::vector<double> objectives, violation;
  objectives.reserve(pool.size() * m);
  for (const Solution& s : pool) {
    objectives.insert(objectives.end(), s.objectives.begin(), s.objectives.end());
    violation.push_back(s.violation);
  }
  const ParetoRanking ranking = non_dominated_sort(objectives, m, violation);
  std::vector<std::size_t> members;
  for (std::size_t i = 0; i < pool.size(); ++i)
    if (ranking.rank[i] == 0 && pool[i].violation == 0.0) members.push_back(i);
  // Equal objective vectors add nothing to a front: keep the first of each.
  std::stable_sort(members.begin(), members.end(),
                   [&](std::size_t a, std::size_t b) { return pool[a].objectives < pool[b].objectives; });
  members.erase(std::unique(members.begin(), members.end(),
                            [&](std::size_t a, std::size_t b) { return pool[a].objectives == pool[b].objectives; }),
                members.end());
  std::vector<double> kept;
  kept.reserve(members.size() * m);
  for (const std::size_t i : members) kept.insert(kept.end(), pool[i].objectives.begin(), pool[i].objectives.end());
  std::vector<Solution> front;
  for (const std::size_t q : thin_by_crowding(kept, m, capacity)) front.push_back(std::move(pool[members[q]]));
  return front;
}

// The migration hook of one island: every `interval` generations, send the best, receive, replace the worst.
class Migration {
 public:
  Migration(const Problem& problem, const IslandOptions& options, std::size_t island, Exchange& exchange,
            IslandReport& report)
      : problem_(problem),
        options_(options),
        island_(island),
        exchange_(exchange),
        report_(report),
        to_(out_neighbours(options, island)),
        from_(in_neighbours(options, island)) {}

  void operator()(std::size_t generation, MigrationView& view) {
    if (options_.archive && problem_.objectives > 1) update_archive(view);
    if (generation % options_.interval != 0 || options_.islands == 1) return;
    const std::size_t epoch = generation / options_.interval;
    const std::size_t n = view.rows, d = view.dimension, k = view.values_per_point;
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return view.better(a, b); });

    std::vector<Migrant> outgoing;
    for (std::size_t q = 0; q < std::min(options_.migrants, n); ++q) {
      const std::size_t i = order[q];
      if (view.failed[i] != 0) break;  // failed rows carry no information
      outgoing.push_back(Migrant{{view.x.begin() + static_cast<std::ptrdiff_t>(i * d),
                                  view.x.begin() + static_cast<std::ptrdiff_t>((i + 1) * d)},
                                 {view.values.begin() + static_cast<std::ptrdiff_t>(i * k),
                                  view.values.begin() + static_cast<std::ptrdiff_t>((i + 1) * k)}});
    }
    report_.sent += outgoing.size() * to_.size();
    const std::vector<std::vector<Migrant>> incoming = exchange_.exchange(island_, epoch, to_, from_, outgoing);

    // Replace from the worst upwards; a row is replaced at most once per migration.
    std::size_t worst = n;
    for (std::size_t s = 0; s < incoming.size(); ++s) {
      MigrationEvent event{.generation = generation, .from = from_[s], .to = island_, .received = incoming[s].size()};
      for (const Migrant& m : incoming[s]) {
        if (worst == 0 || m.variables.size() != d || m.values.size() != k) continue;
        const std::size_t row = order[worst - 1];
        if (!accepts(view, row, m)) continue;
        std::copy(m.variables.begin(), m.variables.end(), view.x.begin() + static_cast<std::ptrdiff_t>(row * d));
        std::copy(m.values.begin(), m.values.end(), view.values.begin() + static_cast<std::ptrdiff_t>(row * k));
        view.failed[row] = 0;
        view.replaced.push_back(row);
        --worst;
        ++event.accepted;
      }
      report_.received += event.received;
      report_.accepted += event.accepted;
      report_.migrations.push_back(event);
    }
  }

 private:
  // Adds the population's feasible non-dominated rows to the archive, thinned to K x the population.
  void update_archive(const MigrationView& view) {
    const std::size_t m = problem_.objectives, d = view.dimension, k = view.values_per_point;
    std::vector<Solution> pool = std::move(report_.archive);
    for (std::size_t i = 0; i < view.rows; ++i) {
      const std::span<const double> values = view.values.subspan(i * k, k);
      if (view.failed[i] != 0 || problem_.violation(values) != 0.0) continue;
      pool.push_back(Solution{{view.x.begin() + static_cast<std::ptrdiff_t>(i * d),
                               view.x.begin() + static_cast<std::ptrdiff_t>((i + 1) * d)},
                              {values.begin(), values.begin() + static_cast<std::ptrdiff_t>(m)},
                              0.0});
    }
    report_.archive = thinned_front(std::move(pool), m, options_.islands * view.rows);
  }

  // True when migrant m should replace row `row`.
  bool accepts(const MigrationView& view, std::size_t row, const Migrant& m) const {
    if (view.failed[row] != 0) return true;
    const std::span<const double> have = view.values.subspan(row * view.values_per_point, view.values_per_point);
    if (problem_.objectives == 1) return key(problem_, m.values) < key(problem_, have);
    const std::size_t mo = problem_.objectives;
    return !constrained_dominates(have.first(mo), problem_.violation(have), std::span<const double>(m.values).first(mo),
                                  problem_.violation(m.values));
  }

  const Problem& problem_;
  const IslandOptions& options_;
  std::size_t island_;
  Exchange& exchange_;
  IslandReport& report_;
  std::vector<std::size_t> to_, from_;
};

// Islands on threads of one process: mailboxes under one mutex.
class ThreadExchange final : public Exchange {
 public:
  ThreadExchange(std::size_t islands, bool asynchronous) : done_(islands, false), asynchronous_(asynchronous) {}

  std::vector<std::vector<Migrant>> exchange(std::size_t island, std::size_t epoch, const std::vector<std::size_t>& to,
                                             const std::vector<std::size_t>& from,
                                             const std::vector<Migrant>& outgoing) override {
    std::unique_lock lock(mutex_);
    for (const std::size_t t : to) box_[{t, island}][epoch] = outgoing;
    changed_.notify_all();
    std::vector<std::vector<Migrant>> incoming(from.size());
    for (std::size_t s = 0; s < from.size(); ++s) {
      auto& mail = box_[{island, from[s]}];
      if (asynchronous_) {
        // The newest delivery at or before this epoch; older ones are superseded.
        auto it = mail.upper_bound(epoch);
        if (it != mail.begin()) {
          --it;
          incoming[s] = std::move(it->second);
          mail.erase(mail.begin(), std::next(it));
        }
      } else {
        changed_.wait(lock, [&] { return failed_ || mail.contains(epoch) || done_[from[s]]; });
        if (auto it = mail.find(epoch); it != mail.end()) {
          incoming[s] = std::move(it->second);
          mail.erase(it);
        }
      }
      if (failed_) throw PeerFailed();
    }
    return incoming;
  }

  void finish(std::size_t island, bool failed) override {
    const std::scoped_lock lock(mutex_);
    done_[island] = true;
    failed_ = failed_ || failed;
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::pair<std::size_t, std::size_t>, std::map<std::size_t, std::vector<Migrant>>> box_;  // (to, from)
  std::vector<bool> done_;
  bool failed_ = false;
  bool asynchronous_;
};

}  // namespace

std::string_view topology_name(Topology topology) noexcept {
  switch (topology) {
    case Topology::Ring:
      return "ring";
    case Topology::FullyConnected:
      return "fully-connected";
    case Topology::Random:
      return "random";
  }
  return "ring";
}

Topology topology_from_name(std::string_view name, std::string_view field) {
  if (name == "ring") return Topology::Ring;
  if (name == "fully-connected") return Topology::FullyConnected;
  if (name == "random") return Topology::Random;
  throw Error(Errc::InvalidOption,
              std::string(field) + " = \"" + std::string(name) +
                  "\" is not a topology (expected \"ring\", \"fully-connected\" or \"random\")",
              {.field = std::string(field)});
}

void IslandOptions::validate() const {
  const auto positive = [](std::size_t v, const char* field) {
    if (v == 0) throw Error(Errc::InvalidOption, std::string(field) + " = 0 must be >= 1", {.field = field});
  };
  positive(islands, "islands");
  positive(interval, "interval");
  positive(migrants, "migrants");
  positive(random_degree, "random_degree");
}

std::vector<std::size_t> out_neighbours(const IslandOptions& options, std::size_t island) {
  const std::size_t n = options.islands;
  std::vector<std::size_t> to;
  if (n < 2) return to;
  switch (options.topology) {
    case Topology::Ring:
      to = {(island + n - 1) % n, (island + 1) % n};
      break;
    case Topology::FullyConnected:
      for (std::size_t j = 0; j < n; ++j)
        if (j != island) to.push_back(j);
      break;
    case Topology::Random: {
      // A partial Fisher-Yates shuffle of the others, from the island's own stream of the graph seed.
      std::vector<std::size_t> others;
      for (std::size_t j = 0; j < n; ++j)
        if (j != island) others.push_back(j);
      Rng rng(options.topology_seed, island);
      const std::size_t degree = std::min(options.random_degree, others.size());
      for (std::size_t q = 0; q < degree; ++q) {
        const auto pick = q + static_cast<std::size_t>(rng.below(others.size() - q));
        std::swap(others[q], others[pick]);
      }
      to.assign(others.begin(), others.begin() + static_cast<std::ptrdiff_t>(degree));
      break;
    }
  }
  std::sort(to.begin(), to.end());
  to.erase(std::unique(to.begin(), to.end()), to.end());
  return to;
}

std::vector<std::size_t> in_neighbours(const IslandOptions& options, std::size_t island) {
  std::vector<std::size_t> from;
  for (std::size_t j = 0; j < options.islands; ++j) {
    const std::vector<std::size_t> to = out_neighbours(options, j);
    if (std::binary_search(to.begin(), to.end(), island)) from.push_back(j);
  }
  return from;
}

// Declared in islands_mpi.hpp; here because it needs no MPI (see there).
bool launched_by_mpi() noexcept {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* v = std::getenv(name); v != nullptr && std::atoi(v) > 1) return true;  // NOLINT(cert-err34-c)
  }
  return false;
}

std::uint64_t island_seed(std::uint64_t seed, std::size_t island) noexcept {
  // Stream 2^40 + i of the archipelago's seed: disjoint from the streams the algorithms draw per
  // individual and per generation pair.
  Rng rng(seed, (std::uint64_t{1} << 40) + island);
  return rng();
}

IslandReport run_island(const Problem& problem, const IslandAlgorithm& algorithm, const IslandOptions& options,
                        std::size_t island, Exchange& exchange) {
  IslandReport report;
  report.island = island;
  IslandAlgorithm mine = algorithm;
  RunSettings& run = run_of(mine);
  report.seed = run.seed = island_seed(run.seed, island);
  Migration migration(problem, options, island, exchange, report);
  run.migrate = [&migration](std::size_t g, MigrationView& view) { migration(g, view); };
  try {
    if (const auto* real = std::get_if<RealGaOptions>(&mine)) {
      GaResult r = solve_real_ga(problem, *real);
      report.best = std::move(r.best);
      report.report = std::move(r.report);
    } else if (const auto* binary = std::get_if<BinaryGaOptions>(&mine)) {
      GaResult r = solve_binary_ga(problem, *binary);
      report.best = std::move(r.best);
      report.report = std::move(r.report);
    } else {
      Nsga2Result r = solve_nsga2(problem, std::get<Nsga2Options>(mine));
      report.population = std::move(r.population);
      report.report = std::move(r.report);
    }
  } catch (...) {
    exchange.finish(island, true);
    throw;
  }
  exchange.finish(island, false);
  return report;
}

IslandsResult merge_islands(const Problem& problem, std::vector<IslandReport> islands, double seconds) {
  IslandsResult result;
  if (!islands.empty()) {
    result.report.termination = islands.front().report.termination;
    result.report.message = islands.front().report.message;
  }
  result.report.seconds = seconds;
  bool first = true;
  std::vector<Solution> pool;
  std::size_t total = 0;
  for (const IslandReport& r : islands) {
    result.report.evaluations += r.report.evaluations;
    result.report.failed_evaluations += r.report.failed_evaluations;
    result.report.generations = std::max(result.report.generations, r.report.generations);
    if (problem.objectives == 1 && r.population.empty()) {
      const auto better = [](const Solution& a, const Solution& b) {
        return std::pair(a.violation, a.objectives[0]) < std::pair(b.violation, b.objectives[0]);
      };
      if (first || better(r.best, result.best)) result.best = r.best;
      first = false;
    }
    total += r.population.size();
    pool.insert(pool.end(), r.archive.begin(), r.archive.end());
    pool.insert(pool.end(), r.population.begin(), r.population.end());
  }
  if (!pool.empty()) result.front = thinned_front(std::move(pool), problem.objectives, total);
  result.islands = std::move(islands);
  return result;
}

IslandsResult solve_islands(const Problem& problem, const IslandAlgorithm& algorithm, const IslandOptions& options) {
  options.validate();
  problem.validate();
  const auto start = std::chrono::steady_clock::now();
  const std::size_t k = options.islands;
  ThreadExchange exchange(k, options.asynchronous);
  std::vector<IslandReport> reports(k);
  std::vector<std::exception_ptr> errors(k);
  std::vector<bool> peer(k, false);
  {
    std::vector<std::jthread> threads;
    threads.reserve(k);
    for (std::size_t i = 0; i < k; ++i) {
      threads.emplace_back([&, i] {
        try {
          reports[i] = run_island(problem, algorithm, options, i, exchange);
        } catch (const PeerFailed&) {
          peer[i] = true;
          errors[i] = std::current_exception();
        } catch (...) {
          errors[i] = std::current_exception();
        }
      });
    }
  }
  // The failing island's own error, not its neighbours' "another island failed".
  for (std::size_t i = 0; i < k; ++i)
    if (errors[i] && !peer[i]) std::rethrow_exception(errors[i]);
  for (std::size_t i = 0; i < k; ++i)
    if (errors[i]) std::rethrow_exception(errors[i]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return merge_islands(problem, std::move(reports), seconds);
}

}  // namespace hula::optim
