// SPDX-License-Identifier: MIT
// Unit tests of NSGA-II: option errors, determinism across thread counts,
// constrained problems, binary coding, failed evaluations.
#include "hula/optim/nsga2.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

// checks: every documented Nsga2Options error names the field and value, before any evaluation
TEST(OptimNsga2, ValidateNamesFieldAndValue) {
  Nsga2Options o;
  o.population = 0;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "population = 0 must be even and >= 4");
  o.population = 51;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "population = 51");
  o = {};
  o.crossover_probability = -0.5;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "crossover_probability = -0.5");
  o = {};
  o.mutation_probability = 3.0;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "mutation_probability = 3");
  o = {};
  o.crossover_eta = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "crossover_eta = nan");
  int calls = 0;
  Problem p = zdt(1);
  p.evaluate = [&calls](std::span<const double>, std::span<double>) { ++calls; };
  o = {};
  o.coding = Coding::Binary;
  HULA_EXPECT_ERROR(solve_nsga2(p, o), Errc::InvalidOption, "variables[0].precision = 0");
  EXPECT_EQ(calls, 0);
}

// checks: same seed gives a bit-identical NSGA-II run log on 1 and 2 threads
TEST(OptimNsga2, RunLogIdenticalOnOneAndTwoThreads) {
  Nsga2Options o;
  o.population = 20;
  o.run.stop.generations = 15;
  o.run.seed = 4;
  RunLog a, b;
  o.run.on_generation = a.collector();
  const auto ra = solve_nsga2(zdt(1, 8), o);
  o.run.threads = 2;
  o.run.on_generation = b.collector();
  const auto rb = solve_nsga2(zdt(1, 8), o);
  EXPECT_TRUE(a == b);
  ASSERT_EQ(ra.front.size(), rb.front.size());
  EXPECT_EQ(a.generations().back().evaluations, 20U * 16U);
}

// checks: the front of a constrained bi-objective problem (BNH-like) is feasible and non-dominated
TEST(OptimNsga2, ConstrainedFrontIsFeasibleAndNonDominated) {
  Problem p;
  p.variables = {{.lower = 0, .upper = 5}, {.lower = 0, .upper = 3}};
  p.objectives = 2;
  p.inequality_constraints = 2;
  p.evaluate = [](std::span<const double> x, std::span<double> v) {
    v[0] = 4 * x[0] * x[0] + 4 * x[1] * x[1];
    v[1] = (x[0] - 5) * (x[0] - 5) + (x[1] - 5) * (x[1] - 5);
    v[2] = (x[0] - 5) * (x[0] - 5) + x[1] * x[1] - 25;
    v[3] = 7.7 - (x[0] - 8) * (x[0] - 8) - (x[1] + 3) * (x[1] + 3);
  };
  Nsga2Options o;
  o.population = 40;
  o.run.stop.generations = 60;
  const auto r = solve_nsga2(p, o);
  ASSERT_GE(r.front.size(), 20U);
  for (const auto& s : r.front) {
    EXPECT_EQ(s.violation, 0.0);
    for (const auto& t : r.front) {
      EXPECT_FALSE(constrained_dominates(t.objectives, t.violation, s.objectives, s.violation));
    }
  }
}

// checks: binary-coded NSGA-II reaches the ZDT1 front region (hypervolume bound) with precision 1e-4
TEST(OptimNsga2, BinaryCodingOnZdt1) {
  Problem p = zdt(1, 10);
  for (auto& v : p.variables) v.precision = 1e-4;
  Nsga2Options o;
  o.coding = Coding::Binary;
  o.population = 60;
  o.run.stop.generations = 150;
  const auto r = solve_nsga2(p, o);
  std::vector<double> pts;
  for (const auto& s : r.front) pts.insert(pts.end(), s.objectives.begin(), s.objectives.end());
  EXPECT_GT(hypervolume(pts, 2, std::vector<double>{1.1, 1.1}), 0.80);
}

// checks: failed evaluations rank last in NSGA-II and never enter the front; all-failing runs are an error
TEST(OptimNsga2, FailedEvaluations) {
  Problem p = zdt(1, 5);
  const auto base = p.evaluate;
  p.evaluate = [base](std::span<const double> x, std::span<double> v) {
    if (x[2] < 0.3) {
      v[0] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    base(x, v);
  };
  Nsga2Options o;
  o.population = 20;
  o.run.stop.generations = 30;
  const auto r = solve_nsga2(p, o);
  EXPECT_GT(r.report.failed_evaluations, 0U);
  for (const auto& s : r.front) EXPECT_TRUE(std::isfinite(s.objectives[0]));
  p.evaluate = [](std::span<const double>, std::span<double> v) {
    v[0] = v[1] = std::numeric_limits<double>::infinity();
  };
  HULA_EXPECT_ERROR(solve_nsga2(p, o), Errc::NumericalFailure, "no evaluation returned finite values");
}

// checks: zero generations returns the initial population's first front; cancellation returns the front so far
TEST(OptimNsga2, ZeroGenerationsAndCancellation) {
  Nsga2Options o;
  o.population = 12;
  o.run.stop.generations = 0;
  RunLog log;
  o.run.on_generation = log.collector();
  const auto r = solve_nsga2(zdt(1, 4), o);
  EXPECT_EQ(r.report.evaluations, 12U);
  EXPECT_EQ(r.report.generations, 0U);
  ASSERT_EQ(log.generations().size(), 1U);
  std::size_t first_front = 0;
  for (const double rank : log.generations()[0].fitness) first_front += rank == 0.0 ? 1 : 0;
  EXPECT_EQ(r.front.size(), first_front);
  EXPECT_EQ(r.population.size(), 12U);

  CancellationToken token;
  o.run.stop.generations = 1000;
  o.run.stop.cancel = &token;
  o.run.on_generation = [&](const GenerationLog& g) {
    if (g.generation == 4) token.cancel();
  };
  const auto c = solve_nsga2(zdt(1, 4), o);
  EXPECT_EQ(c.report.termination, Termination::Cancelled);
  EXPECT_EQ(c.report.generations, 4U);
  EXPECT_FALSE(c.front.empty());
}

}  // namespace
}  // namespace hula::optim
