// SPDX-License-Identifier: MIT
// Tests of optim::solve, the one entry to every optimiser: each algorithm
// (binary GA, real GA, NSGA-II, Nelder–Mead, pagmo, islands) reports each
// termination reason it can give on a run built to end that way, and the
// dispatch refuses what an algorithm does not take.
#include "hula/optim/solve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "hula/optim/test_problems.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

// A population algorithm's options with `generations` and a population of 8.
template <class Options>
Options population_options(std::size_t generations) {
  Options o;
  o.population = 8;
  o.run.seed = 3;
  o.run.stop.generations = generations;
  return o;
}

Problem binary_sphere() {
  Problem p = sphere(3);
  for (Variable& v : p.variables) v.precision = 1e-4;
  return p;
}

// Runs `options` (a GA's or NSGA-II's) on `problem` after `edit` set its stop criteria.
template <class Options, class Edit>
RunReport run_with(const Problem& problem, Edit edit) {
  Options o = population_options<Options>(1000);
  edit(o.run.stop);
  return solve(problem, {.algorithm = o}).report;
}

// checks: each population algorithm ends with the reason its stop criteria force, the generation
// count and message saying so: 5 generations; a budget of 40 evaluations (8 + 4 generations of 8);
// a target every finite value meets (generation 0); a tolerance no improvement beats (5 stagnant
// generations); a 1e-300 s wall time; a token cancelled before the run
template <class Options>
void expect_every_reason(const Problem& problem, bool single_objective) {
  const std::string name = problem.name;
  RunReport r = run_with<Options>(problem, [](StopCriteria& s) { s.generations = 5; });
  EXPECT_EQ(r.termination, Termination::MaxGenerations) << name;
  EXPECT_EQ(r.generations, 5U) << name;
  EXPECT_EQ(r.message, "5 generations run") << name;

  r = run_with<Options>(problem, [](StopCriteria& s) { s.max_evaluations = 40; });
  EXPECT_EQ(r.termination, Termination::MaxEvaluations) << name;
  EXPECT_EQ(r.evaluations, 40U) << name;
  EXPECT_EQ(r.generations, 4U) << name;

  if (single_objective) {
    r = run_with<Options>(problem, [](StopCriteria& s) { s.target = 1e300; });
    EXPECT_EQ(r.termination, Termination::TargetReached) << name;
    EXPECT_EQ(r.generations, 0U) << name;
  }

  r = run_with<Options>(problem, [](StopCriteria& s) {
    s.stagnation_generations = 5;
    s.stagnation_tolerance = 1e300;
  });
  EXPECT_EQ(r.termination, Termination::Stagnation) << name;
  EXPECT_EQ(r.generations, 5U) << name;

  r = run_with<Options>(problem, [](StopCriteria& s) { s.wall_time_seconds = 1e-300; });
  EXPECT_EQ(r.termination, Termination::WallTime) << name;
  EXPECT_EQ(r.generations, 0U) << name;

  CancellationToken token;
  token.cancel();
  r = run_with<Options>(problem, [&](StopCriteria& s) { s.cancel = &token; });
  EXPECT_EQ(r.termination, Termination::Cancelled) << name;
  EXPECT_EQ(r.message, "cancelled after 0 generations") << name;
}

// checks: the binary GA on sphere-3 (4e-4 resolution) through solve, every reason
TEST(OptimSolve, BinaryGaEveryTermination) { expect_every_reason<BinaryGaOptions>(binary_sphere(), true); }

// checks: the real GA on sphere-3 through solve, every reason
TEST(OptimSolve, RealGaEveryTermination) { expect_every_reason<RealGaOptions>(sphere(3), true); }

// checks: NSGA-II on ZDT1 (two objectives; no target) through solve, every other reason
TEST(OptimSolve, Nsga2EveryTermination) { expect_every_reason<Nsga2Options>(zdt(1, 4), false); }

// checks: solve's results: the GAs' best (one solution) and NSGA-II's front and whole population
TEST(OptimSolve, ResultShapes) {
  const SolveResult ga = solve(sphere(3), {.algorithm = population_options<RealGaOptions>(5)});
  ASSERT_EQ(ga.solutions.size(), 1U);
  EXPECT_TRUE(ga.population.empty());
  // Direct call with the same options: solve adds nothing and changes nothing.
  const GaResult direct = solve_real_ga(sphere(3), population_options<RealGaOptions>(5));
  EXPECT_EQ(ga.solutions[0].variables, direct.best.variables);
  EXPECT_EQ(ga.report.evaluations, direct.report.evaluations);

  const SolveResult front = solve(zdt(1, 4), {.algorithm = population_options<Nsga2Options>(5)});
  EXPECT_FALSE(front.solutions.empty());
  EXPECT_EQ(front.population.size(), 8U);
}

// checks: Nelder–Mead on sphere-3 in [-1, 2]^3 from the centre (0.5, 0.5, 0.5) converges to the
// minimum 0 at the origin, inside the bounds
TEST(OptimSolve, NelderMeadConvergesOnSphere) {
  Problem p = sphere(3);
  for (Variable& v : p.variables) {
    v.lower = -1.0;
    v.upper = 2.0;
  }
  const SolveResult r = solve(p, {.algorithm = NelderMeadOptions{}});
  EXPECT_EQ(r.report.termination, Termination::Converged) << r.report.message;
  ASSERT_EQ(r.solutions.size(), 1U);
  for (const double x : r.solutions[0].variables) EXPECT_NEAR(x, 0.0, 1e-6);
  EXPECT_LT(r.solutions[0].objectives[0], 1e-12);
}

// checks: a minimum outside the box (sphere shifted by the bounds [1, 2]^2: minimum at the corner
// (1, 1), f = 2) is found on the bound: points outside rank worst, so the result stays inside
TEST(OptimSolve, NelderMeadStaysInsideTheBounds) {
  Problem p = sphere(2);
  for (Variable& v : p.variables) {
    v.lower = 1.0;
    v.upper = 2.0;
  }
  const SolveResult r = solve(p, {.algorithm = NelderMeadOptions{}});
  for (const double x : r.solutions[0].variables) {
    EXPECT_GE(x, 1.0);
    EXPECT_NEAR(x, 1.0, 1e-6);
  }
  EXPECT_GT(r.report.failed_evaluations, 0U);  // the steps that left the box
}

// checks: Nelder–Mead through solve ends MaxEvaluations on a budget of 10 (Rosenbrock-2 needs far more),
// Cancelled on a token set before the run, WallTime with a 1 µs limit and a 1 ms objective
TEST(OptimSolve, NelderMeadOtherTerminations) {
  const Problem p = rosenbrock(2);
  NelderMeadOptions o;
  o.max_evaluations = 10;
  EXPECT_EQ(solve(p, {.algorithm = o, .start = {-1.2, 1.0}}).report.termination, Termination::MaxEvaluations);

  CancellationToken token;
  token.cancel();
  o = NelderMeadOptions{};
  o.cancel = &token;
  const SolveResult c = solve(p, {.algorithm = o});
  EXPECT_EQ(c.report.termination, Termination::Cancelled);
  EXPECT_EQ(c.report.message.rfind("cancelled", 0), 0U) << c.report.message;

  Problem slow = rosenbrock(2);
  const EvaluateFn f = slow.evaluate;
  slow.evaluate = [f](std::span<const double> x, std::span<double> v) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    f(x, v);
  };
  o = NelderMeadOptions{};
  o.wall_time_seconds = 1e-6;
  EXPECT_EQ(solve(slow, {.algorithm = o}).report.termination, Termination::WallTime);
}

// checks: islands through solve: 2 islands of 8 for 6 generations end MaxGenerations, the report sums the
// islands' evaluations (2 × 8 × 7) and keeps island 0's reason
TEST(OptimSolve, IslandsReport) {
  IslandOptions islands;
  islands.islands = 2;
  islands.interval = 2;
  const SolveResult r = solve(sphere(3), {.algorithm = population_options<RealGaOptions>(6), .islands = islands});
  ASSERT_EQ(r.islands.size(), 2U);
  EXPECT_EQ(r.report.termination, Termination::MaxGenerations);
  EXPECT_EQ(r.report.evaluations, 2U * 8U * 7U);
  EXPECT_EQ(r.report.generations, 6U);
  EXPECT_EQ(r.report.message, r.islands[0].report.message);
  ASSERT_EQ(r.solutions.size(), 1U);
}

// checks: pagmo's SGA through solve runs its generations and reports MaxGenerations
TEST(OptimSolve, PagmoThroughSolve) {
  PagmoOptions o;
  o.algorithm = PagmoAlgorithm::Sga;
  o.population = 10;
  o.generations = 5;
  const SolveResult r = solve(sphere(3), {.algorithm = o});
  EXPECT_EQ(r.report.termination, Termination::MaxGenerations);
  ASSERT_EQ(r.solutions.size(), 1U);
}

// A problem that records every point it evaluates, in order, with its values (pagmo evaluates one at a time).
struct Recorded {
  std::shared_ptr<std::vector<std::pair<std::vector<double>, std::vector<double>>>> points =
      std::make_shared<std::vector<std::pair<std::vector<double>, std::vector<double>>>>();
  Problem problem;
  explicit Recorded(Problem p) : problem(std::move(p)) {
    EvaluateFn inner = problem.evaluate;
    problem.evaluate = [inner, points = points](std::span<const double> x, std::span<double> f) {
      inner(x, f);
      points->emplace_back(std::vector<double>(x.begin(), x.end()), std::vector<double>(f.begin(), f.end()));
    };
  }
};

PagmoOptions pagmo_options(PagmoAlgorithm algorithm, std::size_t population, std::size_t generations) {
  PagmoOptions o;
  o.algorithm = algorithm;
  o.population = population;
  o.generations = generations;
  o.seed = 4;
  return o;
}

// checks: a pagmo run stopped by its token from the progress callback at generation 5 (DE, 20 points a
// generation) ends Cancelled after generation 5's callback (evaluation 121: the first of generation 6, which
// hands generation 5 over; the next one is not made), reports 5 generations and 121 evaluations, and returns
// the best of exactly those 121 evaluations — the first 121 of the same seed's full run, recorded by the
// problem (the first of equal values) — whose objective is the sphere's value at its variables
TEST(OptimSolve, PagmoStopsOnItsTokenWithTheBestSoFar) {
  const Recorded full(sphere(4));
  const PagmoResult whole = solve_with_pagmo(full.problem, pagmo_options(PagmoAlgorithm::De, 20, 40));
  ASSERT_EQ(full.points->size(), 20U * 41U);
  ASSERT_EQ(whole.report.termination, Termination::MaxGenerations);

  const Recorded cut(sphere(4));
  CancellationToken token;
  PagmoOptions o = pagmo_options(PagmoAlgorithm::De, 20, 40);
  o.cancel = &token;
  std::vector<std::size_t> generations;
  o.on_generation = [&](const GenerationLog& g) {
    generations.push_back(g.generation);
    if (g.generation == 5) token.cancel();
  };
  const PagmoResult r = solve_with_pagmo(cut.problem, o);
  EXPECT_EQ(r.report.termination, Termination::Cancelled);
  EXPECT_EQ(r.report.generations, 5U);
  EXPECT_EQ(r.report.evaluations, 121U);
  EXPECT_EQ(r.report.message, "cancelled after 5 generations of pagmo de");
  EXPECT_EQ(generations, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  ASSERT_EQ(cut.points->size(), 121U);
  std::size_t best = 0;
  for (std::size_t i = 0; i < 121; ++i) {
    EXPECT_EQ((*cut.points)[i], (*full.points)[i]) << "evaluation " << i;
    if ((*full.points)[i].second[0] < (*full.points)[best].second[0]) best = i;
  }
  EXPECT_EQ(r.best.variables, (*full.points)[best].first);
  ASSERT_EQ(r.best.objectives.size(), 1U);
  double sum = 0.0;
  for (const double x : r.best.variables) sum += x * x;
  EXPECT_EQ(r.best.objectives[0], sum);
}

// checks: a pagmo NSGA-II run on ZDT1 cancelled from its callback at generation 3 returns the non-dominated
// set of its evaluations so far (every one of them recorded by the problem, the set computed here by
// pairwise comparison), each member's objectives being ZDT1's at its variables
TEST(OptimSolve, PagmoMultiObjectiveStopReturnsTheFrontOfItsEvaluations) {
  const Recorded rec(zdt(1, 6));
  CancellationToken token;
  PagmoOptions o = pagmo_options(PagmoAlgorithm::Nsga2, 12, 1000);
  o.cancel = &token;
  o.on_generation = [&](const GenerationLog& g) {
    if (g.generation == 3) token.cancel();
  };
  const PagmoResult r = solve_with_pagmo(rec.problem, o);
  EXPECT_EQ(r.report.termination, Termination::Cancelled);
  EXPECT_EQ(r.report.evaluations, rec.points->size());
  EXPECT_EQ(r.report.evaluations, 12U * 4U + 1U);
  const auto& pts = *rec.points;
  std::vector<std::vector<double>> expected;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    bool kept = true;
    for (std::size_t j = 0; j < pts.size() && kept; ++j) {
      const auto& a = pts[j].second;
      const auto& b = pts[i].second;
      const bool dominates = a[0] <= b[0] && a[1] <= b[1] && (a[0] < b[0] || a[1] < b[1]);
      const bool earlier_equal = j < i && a == b;
      kept = !dominates && !earlier_equal;
    }
    if (kept) expected.push_back(pts[i].first);
  }
  std::vector<std::vector<double>> got;
  const Problem z = zdt(1, 6);
  for (const Solution& m : r.front) {
    got.push_back(m.variables);
    std::vector<double> f(2);
    z.evaluate(m.variables, f);
    EXPECT_EQ(m.objectives, f);
  }
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
  EXPECT_GE(got.size(), 2U);
}

// checks: a token set before the run stops it after its first successful evaluation (one evaluation,
// generation 0, that point as the best); a wall-time limit of 0.1 s ends a run of a million generations
// WallTime with a best evaluated point; a negative wall time is refused naming the field
TEST(OptimSolve, PagmoStopsBeforeItStartsAndOnItsWallTime) {
  CancellationToken token;
  token.cancel();
  const Recorded rec(sphere(3));
  PagmoOptions o = pagmo_options(PagmoAlgorithm::Pso, 10, 100);
  o.cancel = &token;
  const PagmoResult r = solve_with_pagmo(rec.problem, o);
  EXPECT_EQ(r.report.termination, Termination::Cancelled);
  EXPECT_EQ(r.report.evaluations, 1U);
  EXPECT_EQ(r.report.generations, 0U);
  ASSERT_EQ(rec.points->size(), 1U);
  EXPECT_EQ(r.best.variables, rec.points->front().first);
  EXPECT_EQ(r.best.objectives, rec.points->front().second);

  PagmoOptions timed = pagmo_options(PagmoAlgorithm::Sga, 10, 1000000);  // no tolerance ends it
  timed.wall_time_seconds = 0.1;
  const SolveResult t = solve(sphere(3), {.algorithm = timed});
  EXPECT_EQ(t.report.termination, Termination::WallTime);
  EXPECT_GE(t.report.seconds, 0.1);
  EXPECT_LT(t.report.evaluations, 10U * 1000001U);
  EXPECT_EQ(t.report.message.rfind("wall time 0.10000000000000001 s elapsed after ", 0), 0U) << t.report.message;
  ASSERT_EQ(t.solutions.size(), 1U);
  double sum = 0.0;
  for (const double x : t.solutions[0].variables) sum += x * x;
  EXPECT_EQ(t.solutions[0].objectives[0], sum);

  timed.wall_time_seconds = -1.0;
  HULA_EXPECT_ERROR(timed.validate(), Errc::InvalidOption, "wall_time_seconds = -1 must be >= 0");
}

// checks: what an algorithm does not take is refused by name before any evaluation
TEST(OptimSolve, Refusals) {
  HULA_EXPECT_ERROR((void)solve(zdt(1, 4), {.algorithm = NelderMeadOptions{}}), Errc::InvalidOption,
                    "nelder-mead minimises one objective");
  HULA_EXPECT_ERROR((void)solve(sphere(2), {.algorithm = RealGaOptions{}, .start = {0.0, 0.0}}), Errc::InvalidOption,
                    "start is taken by nelder-mead only");
  HULA_EXPECT_ERROR((void)solve(sphere(2), {.algorithm = NelderMeadOptions{}, .islands = IslandOptions{}}),
                    Errc::InvalidOption, "islands run the GAs and NSGA-II only");
  HULA_EXPECT_ERROR((void)solve(sphere(2), {.algorithm = NelderMeadOptions{}, .start = {0.0}}), Errc::InvalidOption,
                    "start has 1 values but the problem has 2 variables");
  HULA_EXPECT_ERROR(
      (void)solve(sphere(2), {.algorithm = NelderMeadOptions{}, .start = {0.0, 1e9}}), Errc::InvalidOption,
      "start[1] = 1000000000 is outside the bounds [-5.1200000000000001, 5.1200000000000001] of variable 1");
}

}  // namespace
}  // namespace hula::optim
