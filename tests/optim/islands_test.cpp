// SPDX-License-Identifier: MIT
// The island model on threads (optim/islands.hpp): topologies, exact
// repetition of synchronous runs, migration really moving individuals,
// K = 1 equal to the plain algorithm, a failing island stopping the run with
// its own error, merged fronts that are non-dominated, and the NSGA-II
// islands' external archives.
#include "hula/optim/islands.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

RealGaOptions real_ga(std::size_t population, std::size_t generations, std::uint64_t seed) {
  RealGaOptions o;
  o.population = population;
  o.run.stop.generations = generations;
  o.run.seed = seed;
  return o;
}

// checks the neighbour lists against their definitions: ring i±1, all others, random of the given degree
TEST(OptimIslands, Topologies) {
  IslandOptions o;
  o.islands = 5;
  EXPECT_EQ(out_neighbours(o, 0), (std::vector<std::size_t>{1, 4}));
  EXPECT_EQ(in_neighbours(o, 2), (std::vector<std::size_t>{1, 3}));
  o.topology = Topology::FullyConnected;
  EXPECT_EQ(out_neighbours(o, 2), (std::vector<std::size_t>{0, 1, 3, 4}));
  o.topology = Topology::Random;
  o.random_degree = 2;
  o.topology_seed = 9;
  for (std::size_t i = 0; i < 5; ++i) {
    const auto to = out_neighbours(o, i);
    EXPECT_EQ(to.size(), 2U);
    EXPECT_TRUE(std::find(to.begin(), to.end(), i) == to.end());
    EXPECT_EQ(to, out_neighbours(o, i));  // a fixed graph for a seed
    for (const std::size_t j : to) {
      const auto from = in_neighbours(o, j);
      EXPECT_TRUE(std::find(from.begin(), from.end(), i) != from.end());
    }
  }
  o.islands = 1;
  EXPECT_TRUE(out_neighbours(o, 0).empty());
  HULA_EXPECT_ERROR((void)topology_from_name("star"), Errc::InvalidOption, "star");
}

// checks a synchronous run repeats bit for bit, also with other evaluation thread counts
TEST(OptimIslands, SynchronousRunsRepeatExactly) {
  const Problem p = rastrigin(10);
  IslandOptions o;
  o.islands = 4;
  o.interval = 5;
  for (const Topology t : {Topology::Ring, Topology::FullyConnected, Topology::Random}) {
    o.topology = t;
    const IslandsResult a = solve_islands(p, real_ga(20, 30, 3), o);
    RealGaOptions threaded = real_ga(20, 30, 3);
    threaded.run.threads = 2;
    const IslandsResult b = solve_islands(p, threaded, o);
    EXPECT_EQ(a.best.variables, b.best.variables) << topology_name(t);
    EXPECT_EQ(a.best.objectives, b.best.objectives);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(a.islands[i].best.variables, b.islands[i].best.variables);
      EXPECT_EQ(a.islands[i].accepted, b.islands[i].accepted);
    }
    EXPECT_EQ(a.report.evaluations, 4U * 20U * 31U);
  }
}

// checks migration happens every M generations from each in-neighbour, and that migrants are accepted
TEST(OptimIslands, MigrationMovesIndividuals) {
  IslandOptions o;
  o.islands = 4;
  o.interval = 5;
  o.migrants = 2;
  const IslandsResult r = solve_islands(schwefel(10), real_ga(20, 30, 1), o);
  std::size_t accepted = 0;
  for (const IslandReport& isl : r.islands) {
    // 6 migrations (generations 5, 10, ..., 30) from 2 ring neighbours, 2 migrants each
    ASSERT_EQ(isl.migrations.size(), 12U);
    EXPECT_EQ(isl.migrations[0].generation, 5U);
    EXPECT_EQ(isl.received, 24U);
    EXPECT_EQ(isl.sent, 24U);
    accepted += isl.accepted;
  }
  EXPECT_GT(accepted, 0U);
  // Without migration (interval beyond the run) the islands are independent runs: a different result.
  o.interval = 1000;
  const IslandsResult alone = solve_islands(schwefel(10), real_ga(20, 30, 1), o);
  for (const IslandReport& isl : alone.islands) EXPECT_EQ(isl.received, 0U);
  EXPECT_NE(alone.best.variables, r.best.variables);
}

// checks one island is exactly the plain algorithm run with the island's seed
TEST(OptimIslands, OneIslandIsThePlainAlgorithm) {
  IslandOptions o;
  o.islands = 1;
  const IslandsResult r = solve_islands(sphere(5), real_ga(16, 20, 11), o);
  const GaResult plain = solve_real_ga(sphere(5), real_ga(16, 20, island_seed(11, 0)));
  EXPECT_EQ(r.best.variables, plain.best.variables);
  EXPECT_EQ(r.best.objectives, plain.best.objectives);
}

// checks the binary GA and NSGA-II run as islands: migrants re-encoded, merged front non-dominated
TEST(OptimIslands, BinaryGaAndNsga2) {
  IslandOptions o;
  o.islands = 3;
  o.interval = 4;
  BinaryGaOptions b;
  b.population = 20;
  b.run.stop.generations = 12;
  Problem p = sphere(4);
  for (Variable& v : p.variables) v.precision = 1e-3;
  const IslandsResult rb = solve_islands(p, b, o);
  EXPECT_LT(rb.best.objectives[0], 1.0);
  EXPECT_GT(rb.islands[0].received, 0U);

  Nsga2Options n;
  n.population = 20;
  n.run.stop.generations = 20;
  const IslandsResult rn = solve_islands(zdt(1, 10), n, o);
  ASSERT_FALSE(rn.front.empty());
  for (const Solution& x : rn.front)
    for (const Solution& y : rn.front) EXPECT_FALSE(constrained_dominates(x.objectives, 0.0, y.objectives, 0.0));
  std::size_t accepted = 0;
  for (const IslandReport& isl : rn.islands) accepted += isl.accepted;
  EXPECT_GT(accepted, 0U);
}

// checks NSGA-II islands' archives against their definition (feasible, mutually non-dominated, at most
// K x population, one per objective vector), the merged front bounded by the total population, exact
// repetition with archives, and archive = false merging the final populations alone
TEST(OptimIslands, Nsga2ArchivesAndMergedFront) {
  IslandOptions o;
  o.islands = 3;
  o.interval = 4;
  Nsga2Options n;
  n.population = 12;
  n.run.stop.generations = 40;
  n.run.seed = 5;
  const Problem p = zdt(3, 10);
  const IslandsResult a = solve_islands(p, n, o);
  const auto non_dominated = [](const std::vector<Solution>& set) {
    for (const Solution& x : set) {
      if (x.violation != 0.0) return false;
      for (const Solution& y : set)
        if (&x != &y && (x.objectives == y.objectives || constrained_dominates(x.objectives, 0.0, y.objectives, 0.0)))
          return false;
    }
    return true;
  };
  std::size_t largest = 0;
  for (const IslandReport& isl : a.islands) {
    ASSERT_FALSE(isl.archive.empty());
    EXPECT_LE(isl.archive.size(), 3U * 12U);
    EXPECT_TRUE(non_dominated(isl.archive));
    largest = std::max(largest, isl.archive.size());
  }
  // 40 generations of 12 leave more than 12 distinct front points in an archive.
  EXPECT_GT(largest, 12U);
  EXPECT_LE(a.front.size(), 3U * 12U);
  EXPECT_TRUE(non_dominated(a.front));

  const IslandsResult b = solve_islands(p, n, o);
  ASSERT_EQ(a.front.size(), b.front.size());
  for (std::size_t i = 0; i < a.front.size(); ++i) EXPECT_EQ(a.front[i].variables, b.front[i].variables);

  // The archive only observes: without it the populations are the same and the front is theirs.
  o.archive = false;
  const IslandsResult c = solve_islands(p, n, o);
  std::vector<double> objectives;
  std::size_t members = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(c.islands[i].archive.empty());
    ASSERT_EQ(c.islands[i].population.size(), a.islands[i].population.size());
    for (std::size_t q = 0; q < c.islands[i].population.size(); ++q) {
      EXPECT_EQ(c.islands[i].population[q].variables, a.islands[i].population[q].variables);
      const std::vector<double>& f = c.islands[i].population[q].objectives;
      objectives.insert(objectives.end(), f.begin(), f.end());
      ++members;
    }
  }
  const ParetoRanking ranking = non_dominated_sort(objectives, 2);
  std::size_t first = 0;
  for (std::size_t i = 0; i < members; ++i) first += ranking.rank[i] == 0 ? 1 : 0;
  EXPECT_TRUE(non_dominated(c.front));
  EXPECT_LE(c.front.size(), first);
  EXPECT_GT(c.front.size(), 0U);
}

// checks a failing island ends the run with its own error and without hanging its waiting neighbours
TEST(OptimIslands, FailingIslandStopsTheRun) {
  Problem p = sphere(3);
  auto calls = std::make_shared<std::atomic<int>>(0);
  p.evaluate = {};
  p.evaluate_many = [calls](std::span<const double> x, std::span<double> v) {
    if (++*calls == 20) throw Error(Errc::NumericalFailure, "evaluation backend lost", {.field = "backend"});
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = x[3 * i] * x[3 * i];
  };
  IslandOptions o;
  o.islands = 4;
  o.interval = 2;
  HULA_EXPECT_ERROR((void)solve_islands(p, real_ga(8, 40, 2), o), Errc::NumericalFailure, "backend lost");
}

// checks asynchronous migration completes and still finds the sphere's minimum region
TEST(OptimIslands, AsynchronousCompletes) {
  IslandOptions o;
  o.islands = 4;
  o.interval = 3;
  o.asynchronous = true;
  const IslandsResult r = solve_islands(sphere(5), real_ga(20, 60, 5), o);
  EXPECT_LT(r.best.objectives[0], 1e-2);
  EXPECT_EQ(r.islands.size(), 4U);
}

// checks invalid options are refused by name
TEST(OptimIslands, InvalidOptions) {
  IslandOptions o;
  o.interval = 0;
  HULA_EXPECT_ERROR((void)solve_islands(sphere(2), real_ga(8, 2, 0), o), Errc::InvalidOption, "interval");
}

}  // namespace
}  // namespace hula::optim
