// SPDX-License-Identifier: MIT
// Tests of the real- and binary-coded GAs: convergence on closed-form optima,
// determinism across thread counts, failed evaluations, stop criteria, option
// errors, fitness boosting (eq. 32-33) and the run log files.
#include "hula/optim/ga.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "hula/optim/test_problems.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

RealGaOptions small_real(std::size_t generations, std::uint64_t seed = 1) {
  RealGaOptions o;
  o.population = 40;
  o.run.seed = seed;
  o.run.stop.generations = generations;
  return o;
}

// checks: real GA best on sphere-5 against the known minimum 0
TEST(OptimRealGa, SolvesSphere) {
  const GaResult r = solve_real_ga(sphere(5), small_real(150));
  EXPECT_LT(r.best.objectives[0], 1e-3);
  EXPECT_EQ(r.report.termination, Termination::MaxGenerations);
  EXPECT_EQ(r.report.evaluations, 40U * 151U);
  EXPECT_EQ(r.report.generations, 150U);
}

// checks: generational survival with elites also converges on sphere and never loses the best (monotone log)
TEST(OptimRealGa, GenerationalElitismIsMonotone) {
  RealGaOptions o = small_real(60);
  o.survival = Survival::Generational;
  o.elites = 2;
  RunLog log;
  o.run.on_generation = log.collector();
  const GaResult r = solve_real_ga(sphere(3), o);
  double previous = std::numeric_limits<double>::infinity();
  for (const auto& g : log.generations()) {
    const double best = statistics(g).best;
    EXPECT_LE(best, previous);
    previous = best;
  }
  EXPECT_EQ(r.best.objectives[0], previous);
  EXPECT_LT(previous, 0.05);
}

// checks: same seed gives a bit-identical run log on 1 and 2 threads; another seed differs
TEST(OptimRealGa, RunLogIdenticalOnOneAndTwoThreads) {
  RunLog a, b, c;
  RealGaOptions o = small_real(20, 9);
  o.run.on_generation = a.collector();
  o.run.threads = 1;
  (void)solve_real_ga(rastrigin(4), o);
  o.run.on_generation = b.collector();
  o.run.threads = 2;
  (void)solve_real_ga(rastrigin(4), o);
  o.run.on_generation = c.collector();
  o.run.seed = 10;
  (void)solve_real_ga(rastrigin(4), o);
  ASSERT_EQ(a.generations().size(), 21U);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a == c);
}

// checks: zero generations evaluates only the initial population and returns its best (against the log)
TEST(OptimRealGa, ZeroGenerationsReturnsInitialBest) {
  RunLog log;
  RealGaOptions o = small_real(0);
  o.run.on_generation = log.collector();
  const GaResult r = solve_real_ga(sphere(2), o);
  ASSERT_EQ(log.generations().size(), 1U);
  EXPECT_EQ(r.report.evaluations, 40U);
  EXPECT_EQ(r.report.generations, 0U);
  EXPECT_EQ(r.best.objectives[0], statistics(log.generations()[0]).best);
}

// checks: NaN-returning and throwing evaluations rank last, are counted, and never become the champion
TEST(OptimRealGa, FailedEvaluationsRankLast) {
  Problem p = sphere(2);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    if (x[0] > 2.0) throw std::runtime_error("evaluation refused");
    f[0] = x[0] < -2.0 ? std::numeric_limits<double>::quiet_NaN() : x[0] * x[0] + x[1] * x[1];
  };
  const GaResult r = solve_real_ga(p, small_real(30));
  EXPECT_GT(r.report.failed_evaluations, 0U);
  EXPECT_TRUE(std::isfinite(r.best.objectives[0]));
  EXPECT_LT(r.best.objectives[0], 1e-2);
}

// checks: a run where no evaluation is finite ends with NumericalFailure naming the first failure
TEST(OptimRealGa, NoFiniteEvaluationIsAnError) {
  Problem p = sphere(2);
  p.evaluate = [](std::span<const double>, std::span<double> f) { f[0] = std::numeric_limits<double>::quiet_NaN(); };
  HULA_EXPECT_ERROR(solve_real_ga(p, small_real(3)), Errc::NumericalFailure,
                    "no evaluation returned finite values in 160 evaluations (first failure: evaluation 0");
  BinaryGaOptions b;
  b.population = 4;
  b.run.stop.generations = 0;
  Problem q = onemax(3);
  q.evaluate = [](std::span<const double>, std::span<double>) { throw std::runtime_error("never"); };
  HULA_EXPECT_ERROR(solve_binary_ga(q, b), Errc::NumericalFailure, "never");
}

// checks: each stop criterion ends the run with its Termination and a consistent report
TEST(OptimRealGa, StopCriteria) {
  RealGaOptions o = small_real(1000);
  o.run.stop.max_evaluations = 1000;
  GaResult r = solve_real_ga(sphere(3), o);
  EXPECT_EQ(r.report.termination, Termination::MaxEvaluations);
  EXPECT_LE(r.report.evaluations, 1000U);
  EXPECT_GT(r.report.evaluations, 1000U - 40U);

  o = small_real(1000);
  o.run.stop.target = 1e-3;
  r = solve_real_ga(sphere(3), o);
  EXPECT_EQ(r.report.termination, Termination::TargetReached);
  EXPECT_LE(r.best.objectives[0], 1e-3);

  o = small_real(1000);
  o.run.stop.stagnation_generations = 5;
  o.run.stop.stagnation_tolerance = 1e300;  // nothing counts as improvement
  r = solve_real_ga(sphere(3), o);
  EXPECT_EQ(r.report.termination, Termination::Stagnation);
  EXPECT_EQ(r.report.generations, 5U);

  CancellationToken token;
  o = small_real(1000);
  o.run.stop.cancel = &token;
  o.run.on_generation = [&](const GenerationLog& g) {
    if (g.generation == 3) token.cancel();
  };
  r = solve_real_ga(sphere(3), o);
  EXPECT_EQ(r.report.termination, Termination::Cancelled);
  EXPECT_EQ(r.report.generations, 3U);
  EXPECT_TRUE(std::isfinite(r.best.objectives[0]));
  EXPECT_EQ(r.report.message, "cancelled after 3 generations");

  o = small_real(1000);
  o.run.stop.wall_time_seconds = 1e-300;
  r = solve_real_ga(sphere(3), o);
  EXPECT_EQ(r.report.termination, Termination::WallTime);
}

// checks: constrained sphere min x0^2+x1^2 s.t. x0 + x1 >= 1 reaches the analytic optimum 0.5 with both handlings
TEST(OptimRealGa, ConstraintsFeasibilityAndPenalty) {
  Problem p = sphere(2);
  p.inequality_constraints = 1;
  const auto base = p.evaluate;
  p.evaluate = [base](std::span<const double> x, std::span<double> v) {
    base(x, v);
    v[1] = 1.0 - x[0] - x[1];
  };
  for (const auto handling : {ConstraintHandling::FeasibilityRules, ConstraintHandling::Penalty}) {
    RealGaOptions o = small_real(200);
    o.run.constraints = handling;
    const GaResult r = solve_real_ga(p, o);
    EXPECT_NEAR(r.best.objectives[0], 0.5, 0.01);
    EXPECT_LT(r.best.violation, 1e-3);
  }
}

// checks: every documented RealGaOptions / BinaryGaOptions / StopCriteria error names the field and value
TEST(OptimGaOptions, ValidateNamesFieldAndValue) {
  RealGaOptions o;
  o.population = 0;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "population = 0 must be even");
  o.population = 7;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "population = 7 must be even");
  o = {};
  o.crossover_probability = 1.5;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "crossover_probability = 1.5 must be in [0, 1]");
  o = {};
  o.mutation_probability = -0.1;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "mutation_probability = -0.10000000000000001");
  o = {};
  o.crossover_variable_probability = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "crossover_variable_probability = nan");
  o = {};
  o.crossover_eta = -1;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "crossover_eta = -1");
  o = {};
  o.mutation_eta = std::numeric_limits<double>::infinity();
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "mutation_eta = inf");
  o = {};
  o.tournament_size = 0;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "tournament_size = 0");
  o = {};
  o.survival = Survival::Generational;
  o.elites = 100;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "elites = 100 must be < population = 100");
  o = {};
  o.run.penalty = -2;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "run.penalty = -2");
  o = {};
  o.run.stop.wall_time_seconds = -1;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "stop.wall_time_seconds = -1");
  o = {};
  o.run.stop.target = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "stop.target = nan");
  o = {};
  o.run.stop.stagnation_tolerance = -1;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "stop.stagnation_tolerance = -1");
  o = {};
  o.run.stop.max_evaluations = 50;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "stop.max_evaluations = 50 is below population = 100");

  BinaryGaOptions b;
  b.population = 3;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "population = 3");
  b = {};
  b.mutation_probability = 2;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "mutation_probability = 2");
  b = {};
  b.crossover_level = 10;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "crossover_level = 10");
  b = {};
  b.mutation_level = 12;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "mutation_level = 12");
  b = {};
  b.boost_start = 0;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "boost_start = 0");
  b = {};
  b.boost_end = -3;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "boost_end = -3");
  b = {};
  b.selection = Selection::Tournament;
  b.tournament_size = 51;
  HULA_EXPECT_ERROR(b.validate(), Errc::InvalidOption, "tournament_size = 51");

  // Problem-level refusals happen before any evaluation.
  int calls = 0;
  Problem two = zdt(1);
  two.evaluate = [&calls](std::span<const double>, std::span<double>) { ++calls; };
  HULA_EXPECT_ERROR(solve_real_ga(two), Errc::InvalidOption, "objectives = 2");
  HULA_EXPECT_ERROR(solve_binary_ga(sphere(2)), Errc::InvalidOption, "variables[0].precision = 0");
  Problem inverted = sphere(2);
  inverted.variables[1].lower = 9;
  HULA_EXPECT_ERROR(solve_real_ga(inverted), Errc::InvalidOption, "variables[1].lower = 9 > upper = 5.12");
  EXPECT_EQ(calls, 0);
}

// checks: binary GA solves OneMax-40 (optimum 0) with tournament and uniform crossover, and with the thesis roulette
TEST(OptimBinaryGa, SolvesOneMax) {
  BinaryGaOptions o;
  o.population = 40;
  o.selection = Selection::Tournament;
  o.crossover = BinaryCrossover::Uniform;
  o.mutation_probability = 0.025;
  o.mutation_level = 3;
  o.run.stop.generations = 200;
  o.run.stop.target = 0.0;
  o.run.seed = 3;
  GaResult r = solve_binary_ga(onemax(40), o);
  EXPECT_EQ(r.best.objectives[0], 0.0);
  EXPECT_EQ(r.report.termination, Termination::TargetReached);

  BinaryGaOptions thesis;  // roulette, single point, p_m 0.01 level 2, boosting 1 -> 8
  thesis.boost_end = 8.0;
  thesis.run.stop.generations = 150;
  r = solve_binary_ga(onemax(20), thesis);
  EXPECT_LE(r.best.objectives[0], 1.0);
}

// checks: the logged binary-GA fitness equals (1/(1+e))^power with power rising linearly start -> end (eq. 32-33)
TEST(OptimBinaryGa, FitnessBoostingFollowsEquations32And33) {
  BinaryGaOptions o;
  o.population = 10;
  o.boost_start = 1.0;
  o.boost_end = 8.0;
  o.run.stop.generations = 4;
  RunLog log;
  o.run.on_generation = log.collector();
  Problem p = sphere(2);
  for (auto& v : p.variables) v.precision = 1e-3;
  (void)solve_binary_ga(p, o);
  ASSERT_EQ(log.generations().size(), 5U);
  for (const auto& g : log.generations()) {
    const double power = 1.0 + 7.0 * static_cast<double>(g.generation) / 4.0;
    EXPECT_EQ(boost_power(1.0, 8.0, g.generation, 4), power);
    for (std::size_t i = 0; i < g.size(); ++i) {
      EXPECT_NEAR(g.fitness[i], std::pow(1.0 / (1.0 + g.objective_values[i]), power), 1e-15);
    }
  }
  EXPECT_EQ(boosted_fitness(std::numeric_limits<double>::quiet_NaN(), 2.0), 0.0);
  EXPECT_EQ(boosted_fitness(0.0, 3.0), 1.0);
}

// checks: binary GA with roulette and boosting is deterministic across 1 and 2 threads and improves on the initial best
TEST(OptimBinaryGa, DeterministicAndImproving) {
  Problem p = rastrigin(3);
  for (auto& v : p.variables) v.precision = 1e-4;
  BinaryGaOptions o;
  o.boost_end = 8.0;
  o.run.stop.generations = 40;
  o.run.seed = 5;
  RunLog a, b;
  o.run.on_generation = a.collector();
  const GaResult ra = solve_binary_ga(p, o);
  o.run.threads = 2;
  o.run.on_generation = b.collector();
  const GaResult rb = solve_binary_ga(p, o);
  EXPECT_TRUE(a == b);
  EXPECT_EQ(ra.best.objectives, rb.best.objectives);
  EXPECT_LT(ra.best.objectives[0], statistics(a.generations().front()).best);
}

// checks: CSV header/row count and JSON structure of the run log; JSON doubles read back bit-exactly
TEST(OptimRunLog, CsvAndJsonRoundTrip) {
  RunLog log;
  RealGaOptions o = small_real(2);
  o.population = 4;
  o.run.on_generation = log.collector();
  (void)solve_real_ga(sphere(2), o);
  std::ostringstream csv;
  log.write_csv(csv);
  std::istringstream lines(csv.str());
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "generation,evaluations,individual,x0,x1,f0,violation,fitness,failed");
  std::size_t rows = 0;
  for (std::string line; std::getline(lines, line);) ++rows;
  EXPECT_EQ(rows, 12U);
  std::ostringstream js;
  log.write_json(js);
  const auto doc = nlohmann::json::parse(js.str());
  ASSERT_EQ(doc["generations"].size(), 3U);
  const auto& g1 = log.generations()[1];
  const auto& ind = doc["generations"][1]["individuals"][2];
  EXPECT_EQ(ind["variables"][1].get<double>(), g1.variables[2 * 2 + 1]);
  EXPECT_EQ(ind["objectives"][0].get<double>(), g1.objective_values[2]);
  EXPECT_EQ(doc["generations"][1]["evaluations"].get<std::size_t>(), 8U);
  EXPECT_FALSE(ind["failed"].get<bool>());
}

}  // namespace
}  // namespace hula::optim
