// SPDX-License-Identifier: MIT
// Flexo against pagmo2 in the same run. Each benchmark runs
// exactly 10 iterations, one per seed 0..9, so the time column is the mean
// wall time per run and the counters give the quality over the 10 seeds:
//   - NSGA-II, population 100 x 250 generations on ZDT1-4 and ZDT6: hypervolume of the
//     final first front with reference (1.1, 1.1), median / min / max;
//   - single-objective GA on Rastrigin-10 and Rosenbrock-10 with 25,000
//     evaluations (population 100: initial population + 249 generations):
//     best objective, median / min / max; pagmo's yardstick is its SGA;
//   - NSGA-II on a costly ZDT1 with 1 and 2 evaluation threads.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problems/rastrigin.hpp>
#include <pagmo/problems/rosenbrock.hpp>
#include <pagmo/problems/zdt.hpp>
#include <pagmo/utils/multi_objective.hpp>
#include <vector>

#include "hula/optim/ga.hpp"
#include "hula/optim/nsga2.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"

namespace {

using namespace hula::optim;

constexpr int kSeeds = 10;

void report(benchmark::State& state, std::vector<double> values, const char* name) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  state.counters[std::string(name) + "_median"] = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  state.counters[std::string(name) + "_min"] = values.front();
  state.counters[std::string(name) + "_max"] = values.back();
}

void BM_optim_nsga2_zdt(benchmark::State& state) {
  const auto which = static_cast<unsigned>(state.range(0));
  const Problem problem = zdt(which);
  std::vector<double> hv;
  std::uint64_t seed = 0;
  for (auto _ : state) {
    Nsga2Options o;
    o.population = 100;
    o.run.stop.generations = 250;
    o.run.seed = seed++;
    const Nsga2Result r = solve_nsga2(problem, o);
    state.PauseTiming();
    std::vector<double> pts;
    for (const auto& s : r.front) pts.insert(pts.end(), s.objectives.begin(), s.objectives.end());
    hv.push_back(hypervolume(pts, 2, std::vector<double>{1.1, 1.1}));
    state.ResumeTiming();
  }
  report(state, hv, "hv");
}

void BM_optim_pagmo_nsga2_zdt(benchmark::State& state) {
  const auto which = static_cast<unsigned>(state.range(0));
  std::vector<double> hv;
  unsigned seed = 0;
  for (auto _ : state) {
    pagmo::population pop(pagmo::problem(pagmo::zdt(which, which <= 3 ? 30 : 10)), 100, seed);
    pop = pagmo::algorithm(pagmo::nsga2(250, 0.95, 10., 0.01, 50., seed)).evolve(pop);
    ++seed;
    state.PauseTiming();
    // Same indicator for both: our hypervolume equals pagmo::hypervolume to
    // 1e-12 (tests/optim/pagmo_oracle_test.cpp) and, unlike pagmo's, accepts
    // points beyond the reference point (ZDT4/ZDT6 fronts early on).
    const auto ndf = pagmo::fast_non_dominated_sorting(pop.get_f());
    std::vector<double> pts;
    for (const auto i : std::get<0>(ndf).front()) pts.insert(pts.end(), pop.get_f()[i].begin(), pop.get_f()[i].end());
    hv.push_back(hypervolume(pts, 2, std::vector<double>{1.1, 1.1}));
    state.ResumeTiming();
  }
  report(state, hv, "hv");
}

Problem single(int which) { return which == 0 ? rastrigin(10) : rosenbrock(10); }

void BM_optim_real_ga(benchmark::State& state) {
  const Problem problem = single(static_cast<int>(state.range(0)));
  std::vector<double> best;
  std::uint64_t seed = 0;
  for (auto _ : state) {
    RealGaOptions o;
    o.population = 100;
    o.run.seed = seed++;
    o.run.stop.generations = 1000000;
    o.run.stop.max_evaluations = 25000;
    const GaResult r = solve_real_ga(problem, o);
    best.push_back(r.best.objectives[0]);
    state.counters["evaluations"] = static_cast<double>(r.report.evaluations);
  }
  report(state, best, "best");
}

void BM_optim_pagmo_sga(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  std::vector<double> best;
  unsigned seed = 0;
  for (auto _ : state) {
    pagmo::problem prob = which == 0 ? pagmo::problem(pagmo::rastrigin(10)) : pagmo::problem(pagmo::rosenbrock(10));
    pagmo::population pop(prob, 100, seed);
    pop = pagmo::algorithm(pagmo::sga(249, .90, 1., .02, 1., 2u, "exponential", "polynomial", "tournament", seed))
              .evolve(pop);
    ++seed;
    best.push_back(pop.champion_f()[0]);
    state.counters["evaluations"] = static_cast<double>(pop.get_problem().get_fevals());
  }
  report(state, best, "best");
}

// Parallel batch evaluation: ZDT1 made costly (~20 us per evaluation, as a
// curve-fitting objective would be), 1 vs 2 threads, same seed so the same
// run; the ratio of the two times is the speed-up.
void BM_optim_nsga2_threads(benchmark::State& state) {
  Problem problem = zdt(1);
  const EvaluateFn cheap = problem.evaluate;
  problem.evaluate = [cheap](std::span<const double> x, std::span<double> f) {
    double burn = 0.0;
    for (int i = 0; i < 4000; ++i) burn += std::sin(x[0] + i);
    cheap(x, f);
    benchmark::DoNotOptimize(burn);
  };
  for (auto _ : state) {
    Nsga2Options o;
    o.population = 100;
    o.run.stop.generations = 20;
    o.run.threads = static_cast<std::size_t>(state.range(0));
    benchmark::DoNotOptimize(solve_nsga2(problem, o));
  }
  state.SetItemsProcessed(state.iterations() * 100 * 21);
}

}  // namespace

// Argument: ZDT number (ZDT1-3: 30 variables, ZDT4 and ZDT6: 10).
BENCHMARK(BM_optim_nsga2_zdt)->DenseRange(1, 4)->Arg(6)->Iterations(kSeeds)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_optim_pagmo_nsga2_zdt)->DenseRange(1, 4)->Arg(6)->Iterations(kSeeds)->Unit(benchmark::kMillisecond);
// Argument: 0 = Rastrigin-10, 1 = Rosenbrock-10.
BENCHMARK(BM_optim_real_ga)->Arg(0)->Arg(1)->Iterations(kSeeds)->Unit(benchmark::kMillisecond);
// Argument: threads.
BENCHMARK(BM_optim_nsga2_threads)->Arg(1)->Arg(2)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_optim_pagmo_sga)->Arg(0)->Arg(1)->Iterations(kSeeds)->Unit(benchmark::kMillisecond);
