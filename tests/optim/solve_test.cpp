// SPDX-License-Identifier: MIT
// Tests of optim::solve, the one entry to every optimiser: each algorithm
// (binary GA, real GA, NSGA-II, Nelder–Mead, pagmo, islands) reports each
// termination reason it can give on a run built to end that way, and the
// dispatch refuses what an algorithm does not take.
#include "hula/optim/solve.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
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
