// SPDX-License-Identifier: MIT
// Tests of the built-in test problems against their published optima.
#include "hula/optim/test_problems.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

double at(const Problem& p, const std::vector<double>& x) {
  std::vector<double> f(p.values_per_point());
  p.evaluate(x, f);
  return f[0];
}

// checks: single-objective problems at their known minimisers against the published minima
TEST(OptimTestProblems, KnownOptima) {
  for (const std::size_t d : {1U, 2U, 7U}) {
    EXPECT_EQ(at(sphere(d), std::vector<double>(d, 0.0)), 0.0);
    EXPECT_NEAR(at(rastrigin(d), std::vector<double>(d, 0.0)), 0.0, 1e-12);
    EXPECT_NEAR(at(ackley(d), std::vector<double>(d, 0.0)), 0.0, 1e-12);
    EXPECT_NEAR(at(schwefel(d), std::vector<double>(d, 420.9687)), 0.0, 1e-4 * static_cast<double>(d));
    EXPECT_EQ(at(onemax(d), std::vector<double>(d, 1.0)), 0.0);
    EXPECT_EQ(at(onemax(d), std::vector<double>(d, 0.0)), static_cast<double>(d));
  }
  EXPECT_EQ(at(rosenbrock(10), std::vector<double>(10, 1.0)), 0.0);
  EXPECT_EQ(at(rosenbrock(2), {0.0, 0.0}), 1.0);
  EXPECT_NEAR(at(rastrigin(2), {1.0, 0.0}), 1.0, 1e-12);
  const Problem d = dtlz2(4);
  std::vector<double> x(d.dimension(), 0.5), f(4);
  x[0] = 0.3;
  x[1] = 0.7;
  x[2] = 0.1;
  d.evaluate(x, f);
  double q = 0.0;
  for (const double v : f) q += v * v;
  EXPECT_NEAR(q, 1.0, 1e-12);
}

// checks: lookup by name and its errors
TEST(OptimTestProblems, ByNameAndErrors) {
  EXPECT_EQ(test_problem("zdt2").dimension(), 30U);
  EXPECT_EQ(test_problem("zdt4").variables[1].lower, -5.0);
  EXPECT_EQ(test_problem("dtlz2", 0, 5).objectives, 5U);
  EXPECT_EQ(test_problem("rastrigin").dimension(), 10U);
  HULA_EXPECT_ERROR(test_problem("zdt5"), Errc::InvalidArgument, "problem = \"zdt5\"");
  HULA_EXPECT_ERROR(zdt(7), Errc::InvalidOption, "zdt which = 7");
  HULA_EXPECT_ERROR(rosenbrock(1), Errc::InvalidOption, "rosenbrock dimension = 1 must be >= 2");
  HULA_EXPECT_ERROR(dtlz2(1), Errc::InvalidOption, "dtlz2 objectives = 1");
}

}  // namespace
}  // namespace hula::optim
