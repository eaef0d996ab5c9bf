// SPDX-License-Identifier: MIT
// Tests of the downhill simplex: known minima of Rosenbrock's function and of
// a shifted quadratic in 6 variables, the budget, and the documented errors.
#include "hula/optim/nelder_mead.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

double rosenbrock(std::span<const double> x) {
  return 100.0 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1.0 - x[0]) * (1.0 - x[0]);
}

// checks: Rosenbrock from the classic start (-1.2, 1) reaches its minimum (1, 1), f = 0
TEST(OptimNelderMead, RosenbrockReachesKnownMinimum) {
  const std::vector<double> start{-1.2, 1.0};
  const NelderMeadResult r = nelder_mead(rosenbrock, start);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.x[0], 1.0, 1e-7);
  EXPECT_NEAR(r.x[1], 1.0, 1e-7);
  EXPECT_LT(r.value, 1e-14);
  EXPECT_GT(r.evaluations, 50u);
  EXPECT_FALSE(r.history.empty());
}

// checks: a 6-variable quadratic sum (i+1)(x_i - i/10)^2 has its minimum at x_i = i/10
TEST(OptimNelderMead, QuadraticInSixVariables) {
  auto f = [](std::span<const double> x) {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) s += (i + 1.0) * (x[i] - 0.1 * i) * (x[i] - 0.1 * i);
    return s;
  };
  const std::vector<double> start(6, 1.0);
  const NelderMeadResult r = nelder_mead(f, start);
  EXPECT_TRUE(r.converged);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(r.x[i], 0.1 * i, 1e-6) << i;
}

// checks: NaN values rank worst, so a wall of NaN keeps the search inside x > 0
TEST(OptimNelderMead, NanRanksWorst) {
  auto f = [](std::span<const double> x) {
    return x[0] <= 0.0 ? std::numeric_limits<double>::quiet_NaN() : x[0] - std::log(x[0]);
  };
  const std::vector<double> start{3.0};
  const NelderMeadResult r = nelder_mead(f, start);
  EXPECT_NEAR(r.x[0], 1.0, 1e-6);  // d/dx (x - ln x) = 0 at x = 1
  EXPECT_NEAR(r.value, 1.0, 1e-12);
}

// checks: the evaluation budget is honoured (stops unconverged)
TEST(OptimNelderMead, BudgetStops) {
  NelderMeadOptions o;
  o.max_evaluations = 20;
  const std::vector<double> start{-1.2, 1.0};
  const NelderMeadResult r = nelder_mead(rosenbrock, start, o);
  EXPECT_FALSE(r.converged);
  EXPECT_LE(r.evaluations, 22u);  // the last iteration may add its reflection and expansion
}

// checks: the documented errors name the input at fault
TEST(OptimNelderMead, Errors) {
  NelderMeadOptions o;
  o.initial_step = 0.0;
  const std::vector<double> start{1.0, 2.0};
  HULA_EXPECT_ERROR((void)nelder_mead(rosenbrock, start, o), Errc::InvalidOption, "initial_step = 0");
  const std::vector<double> bad{1.0, std::numeric_limits<double>::quiet_NaN()};
  HULA_EXPECT_ERROR((void)nelder_mead(rosenbrock, bad), Errc::NonFiniteInput, "start[1]");
  HULA_EXPECT_ERROR((void)nelder_mead(rosenbrock, std::vector<double>{}), Errc::InvalidArgument, "empty");
  auto inf = [](std::span<const double>) { return std::numeric_limits<double>::infinity(); };
  HULA_EXPECT_ERROR((void)nelder_mead(inf, start), Errc::NumericalFailure, "not finite at the start");
}

}  // namespace
}  // namespace hula::optim
