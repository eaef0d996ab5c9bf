// SPDX-License-Identifier: MIT
// Oracle tests against pagmo2: hypervolume, non-dominated sorting and
// crowding distance on random sets against pagmo's own implementations;
// NSGA-II front quality on ZDT1 against pagmo's NSGA-II with the same seeds;
// the pagmo adapter solving Flexo problems.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problems/zdt.hpp>
#include <pagmo/utils/hypervolume.hpp>
#include <pagmo/utils/multi_objective.hpp>
#include <utility>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/optim/nsga2.hpp"
#include "hula/optim/pagmo_adapter.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

std::vector<std::vector<double>> random_set(Rng& rng, std::size_t n, std::size_t m) {
  std::vector<std::vector<double>> pts(n, std::vector<double>(m));
  for (auto& p : pts) {
    for (auto& v : p) v = rng.uniform(0.0, 1.0);
  }
  return pts;
}

std::vector<double> flat(const std::vector<std::vector<double>>& pts) {
  std::vector<double> out;
  for (const auto& p : pts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// checks: hypervolume on random non-dominated and random fronts (m = 2..4) against pagmo::hypervolume to 1e-12
TEST(OptimPagmoOracle, HypervolumeMatchesPagmo) {
  Rng rng(31, 0);
  for (std::size_t m = 2; m <= 4; ++m) {
    for (int trial = 0; trial < 10; ++trial) {
      const std::size_t n = 5 + rng.below(m == 4 ? 25 : 60);
      auto pts = random_set(rng, n, m);
      if (trial % 2 == 0) {  // points on a sphere: mutually non-dominated
        for (auto& p : pts) {
          double q = 0;
          for (const double v : p) q += v * v;
          for (auto& v : p) v /= std::sqrt(q);
        }
      }
      const std::vector<double> ref(m, 1.1);
      const double ours = hypervolume(flat(pts), m, ref);
      const double theirs = pagmo::hypervolume(pts).compute(ref);
      EXPECT_NEAR(ours, theirs, 1e-12 * std::max(1.0, theirs)) << "m " << m << " n " << n;
    }
  }
}

// checks: non-dominated ranks and crowding distances on random sets against pagmo's fast_non_dominated_sorting and
// crowding_distance
TEST(OptimPagmoOracle, SortAndCrowdingMatchPagmo) {
  Rng rng(32, 0);
  NonDominatedSorter sorter;
  for (std::size_t m = 2; m <= 3; ++m) {
    for (int trial = 0; trial < 10; ++trial) {
      const std::size_t n = 10 + rng.below(100);
      const auto pts = random_set(rng, n, m);
      const auto f = flat(pts);
      const auto ranks = sorter.sort(f, m, {});
      const auto ndf = pagmo::fast_non_dominated_sorting(pts);
      const auto& pagmo_fronts = std::get<0>(ndf);
      ASSERT_EQ(sorter.fronts(), pagmo_fronts.size());
      std::vector<double> dist(n);
      std::vector<std::size_t> scratch(n);
      for (std::size_t r = 0; r < pagmo_fronts.size(); ++r) {
        std::vector<std::size_t> front(pagmo_fronts[r].begin(), pagmo_fronts[r].end());
        for (const auto i : front) EXPECT_EQ(ranks[i], r);
        if (front.size() < 2) continue;
        crowding_distance(f, m, front, dist, scratch);
        std::vector<std::vector<double>> fp;
        for (const auto i : front) fp.push_back(pts[i]);
        const auto cd = pagmo::crowding_distance(fp);
        for (std::size_t k = 0; k < front.size(); ++k) {
          if (std::isinf(cd[k])) {
            EXPECT_TRUE(std::isinf(dist[front[k]]));
          } else {
            EXPECT_NEAR(dist[front[k]], cd[k], 1e-12);
          }
        }
      }
    }
  }
}

double hv2(const std::vector<Solution>& front) {
  std::vector<double> pts;
  for (const auto& s : front) pts.insert(pts.end(), s.objectives.begin(), s.objectives.end());
  return hypervolume(pts, 2, std::vector<double>{1.1, 1.1});
}

// checks: Flexo NSGA-II hypervolume on ZDT1 (seeds 0..9, 100 x 250) against pagmo's NSGA-II with the same seeds:
// the median and the minimum over the ten seeds no lower than pagmo's (the criterion of issue 27; three seeds
// were too few: one seed moves a median of three by more than the two algorithms' medians differ)
TEST(OptimPagmoOracle, Nsga2NoWorseThanPagmoOnZdt1) {
  std::vector<double> ours, theirs;
  for (unsigned seed = 0; seed < 10; ++seed) {
    Nsga2Options o;
    o.population = 100;
    o.run.stop.generations = 250;
    o.run.seed = seed;
    ours.push_back(hv2(solve_nsga2(zdt(1), o).front));
    pagmo::population pop(pagmo::problem(pagmo::zdt(1, 30)), 100, seed);
    pop = pagmo::algorithm(pagmo::nsga2(250, 0.95, 10., 0.01, 50., seed)).evolve(pop);
    const auto ndf = pagmo::fast_non_dominated_sorting(pop.get_f());
    std::vector<std::vector<double>> front;
    for (const auto i : std::get<0>(ndf).front()) front.push_back(pop.get_f()[i]);
    theirs.push_back(pagmo::hypervolume(front).compute({1.1, 1.1}));
  }
  std::sort(ours.begin(), ours.end());
  std::sort(theirs.begin(), theirs.end());
  EXPECT_GE(ours[4] + ours[5], theirs[4] + theirs[5]);  // medians of ten
  EXPECT_GE(ours[0], theirs[0]);
  EXPECT_GT(ours[0], 0.865);
}

// checks: every adapter algorithm improves on sphere-5 / reaches ZDT1's front region; adapter errors name the field
TEST(OptimPagmoOracle, AdapterSolvesFlexoProblems) {
  for (const char* name : {"cmaes", "de", "sade", "pso", "sga"}) {
    PagmoOptions o;
    o.algorithm = pagmo_algorithm(name);
    o.population = 20;
    o.generations = 100;
    o.seed = 2;
    const PagmoResult r = solve_with_pagmo(sphere(5), o);
    EXPECT_LT(r.best.objectives[0], 0.5) << name;
    EXPECT_GT(r.report.evaluations, 100U) << name;
  }
  for (const char* name : {"moead", "nsga2"}) {
    PagmoOptions o;
    o.algorithm = pagmo_algorithm(name);
    o.population = 100;
    o.generations = 150;
    const PagmoResult r = solve_with_pagmo(zdt(1), o);
    EXPECT_GT(hv2(r.front), 0.6) << name;
  }
  HULA_EXPECT_ERROR(pagmo_algorithm("bfgs"), Errc::InvalidArgument, "algorithm = \"bfgs\"");
  PagmoOptions o;
  o.algorithm = PagmoAlgorithm::De;
  HULA_EXPECT_ERROR(solve_with_pagmo(zdt(1), o), Errc::InvalidOption,
                    "algorithm = de cannot solve a problem with objectives = 2");
  o.algorithm = PagmoAlgorithm::Nsga2;
  o.population = 6;
  HULA_EXPECT_ERROR(solve_with_pagmo(zdt(1), o), Errc::InvalidOption, "pagmo nsga2 refused");
  o.population = 0;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "population = 0");
  Problem c = sphere(2);
  c.inequality_constraints = 1;
  o = {};
  o.algorithm = PagmoAlgorithm::Cmaes;
  HULA_EXPECT_ERROR(solve_with_pagmo(c, o), Errc::InvalidOption, "does not handle constraints");
}

// A pagmo problem evaluating a Flexo problem directly (no constraints), for runs of pagmo itself.
struct FlexoUdp {
  const Problem* problem = nullptr;
  [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    pagmo::vector_double f(problem->objectives);
    problem->evaluate(x, f);
    return f;
  }
  [[nodiscard]] std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    pagmo::vector_double lo, hi;
    for (const Variable& v : problem->variables) {
      lo.push_back(v.lower);
      hi.push_back(v.upper);
    }
    return {lo, hi};
  }
  [[nodiscard]] pagmo::vector_double::size_type get_nobj() const { return problem->objectives; }
};

// checks: the adapter's DE and NSGA-II runs are pagmo's own runs of pagmo::de(60, 0.8, 0.9, 2, 1e-6, 1e-6, seed)
// on sphere-5 and pagmo::nsga2(40, 0.95, 10, 0.01, 50, seed) on ZDT1-8 (same seed, population 20) to the last
// bit — champion, first front and evaluations — with nothing that can stop them, and with a token that is never
// set, a wall-time limit never reached and a progress callback (which must not change the run)
TEST(OptimPagmoOracle, AdapterRunsArePagmosBitForBitWhetherStoppableOrNot) {
  const CancellationToken never;
  const Problem sph = sphere(5);
  const Problem z = zdt(1, 8);
  pagmo::population de_pop(pagmo::problem(FlexoUdp{&sph}), 20, 11);
  de_pop = pagmo::algorithm(pagmo::de(60, 0.8, 0.9, 2u, 1e-6, 1e-6, 11)).evolve(de_pop);
  pagmo::population ns_pop(pagmo::problem(FlexoUdp{&z}), 20, 11);
  ns_pop = pagmo::algorithm(pagmo::nsga2(40, 0.95, 10., 0.01, 50., 11)).evolve(ns_pop);
  std::vector<std::vector<double>> ns_front;
  // The sorting's result is kept: a range-for over a member of the temporary would read it after its end.
  const auto sorting = pagmo::fast_non_dominated_sorting(ns_pop.get_f());
  for (const auto i : std::get<0>(sorting).front()) ns_front.push_back(ns_pop.get_x()[i]);
  std::sort(ns_front.begin(), ns_front.end());
  for (const bool stoppable : {false, true}) {
    std::size_t calls = 0;
    PagmoOptions o;
    o.population = 20;
    o.seed = 11;
    if (stoppable) {
      o.cancel = &never;
      o.wall_time_seconds = 1e6;
      o.on_generation = [&calls](const GenerationLog&) { ++calls; };
    }
    o.algorithm = PagmoAlgorithm::De;
    o.generations = 60;
    const PagmoResult de = solve_with_pagmo(sph, o);
    EXPECT_EQ(de.best.variables, de_pop.champion_x()) << stoppable;
    EXPECT_EQ(de.best.objectives, de_pop.champion_f()) << stoppable;
    EXPECT_EQ(de.report.evaluations, de_pop.get_problem().get_fevals()) << stoppable;
    EXPECT_EQ(de.report.termination, Termination::MaxGenerations);
    o.algorithm = PagmoAlgorithm::Nsga2;
    o.generations = 40;
    const PagmoResult ns = solve_with_pagmo(z, o);
    std::vector<std::vector<double>> front;
    for (const Solution& m : ns.front) front.push_back(m.variables);
    std::sort(front.begin(), front.end());
    EXPECT_EQ(front, ns_front) << stoppable;
    EXPECT_EQ(ns.report.evaluations, ns_pop.get_problem().get_fevals()) << stoppable;
    if (stoppable) {
      EXPECT_GT(calls, 60U + 40U);
    }
  }
}

}  // namespace
}  // namespace hula::optim
