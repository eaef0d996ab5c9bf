// SPDX-License-Identifier: MIT
// Tests of the downhill simplex: known minima of Rosenbrock's function and of
// a shifted quadratic in 6 variables, each termination reason on a run that
// provably ends that way, and the documented errors.
#include "hula/optim/nelder_mead.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

double rosenbrock_value(std::span<const double> x) {
  return 100.0 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1.0 - x[0]) * (1.0 - x[0]);
}

// checks: Rosenbrock from the classic start (-1.2, 1) reaches its minimum (1, 1), f = 0
TEST(OptimNelderMead, RosenbrockReachesKnownMinimum) {
  const std::vector<double> start{-1.2, 1.0};
  const NelderMeadResult r = nelder_mead(rosenbrock_value, start);
  EXPECT_EQ(r.report.termination, Termination::Converged) << r.report.message;
  EXPECT_NEAR(r.x[0], 1.0, 1e-7);
  EXPECT_NEAR(r.x[1], 1.0, 1e-7);
  EXPECT_LT(r.value, 1e-14);
  EXPECT_GT(r.report.evaluations, 50u);
  EXPECT_EQ(r.report.failed_evaluations, 0u);
  EXPECT_FALSE(r.history.empty());
  EXPECT_EQ(r.report.generations, r.history.size());
  EXPECT_NE(r.report.message.find("x_tolerance"), std::string::npos) << r.report.message;
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
  EXPECT_EQ(r.report.termination, Termination::Converged) << r.report.message;
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
  EXPECT_GT(r.report.failed_evaluations, 0u);  // the NaN wall was hit and counted
}

// checks: 20 evaluations cannot solve Rosenbrock from (-1.2, 1) (it needs > 50 above): the run ends
// MaxEvaluations with the budget honoured
TEST(OptimNelderMead, BudgetStops) {
  NelderMeadOptions o;
  o.max_evaluations = 20;
  const std::vector<double> start{-1.2, 1.0};
  const NelderMeadResult r = nelder_mead(rosenbrock_value, start, o);
  EXPECT_EQ(r.report.termination, Termination::MaxEvaluations) << r.report.message;
  EXPECT_LE(r.report.evaluations, 22u);  // the last iteration may add its reflection and expansion
  EXPECT_NE(r.report.message.find("max_evaluations = 20"), std::string::npos) << r.report.message;
}

// checks: a token cancelled before the run ends it at the first iteration check with Cancelled and the
// start (the only point seen besides the first simplex) as its best
TEST(OptimNelderMead, CancelledBeforeTheFirstIteration) {
  CancellationToken token;
  token.cancel();
  NelderMeadOptions o;
  o.cancel = &token;
  const std::vector<double> start{-1.2, 1.0};
  const NelderMeadResult r = nelder_mead(rosenbrock_value, start, o);
  EXPECT_EQ(r.report.termination, Termination::Cancelled) << r.report.message;
  EXPECT_EQ(r.report.generations, 0u);
  EXPECT_EQ(r.report.evaluations, 3u);  // the start and the two other simplex vertices
  EXPECT_LE(r.value, rosenbrock_value(start));
}

// checks: an objective that sleeps 1 ms per call against a 1 µs wall-time limit: the limit has passed
// by the first iteration check (after three calls), so the run ends WallTime with no iteration
TEST(OptimNelderMead, WallTimeEndsTheRun) {
  NelderMeadOptions o;
  o.wall_time_seconds = 1e-6;
  const auto slow = [](std::span<const double> x) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return rosenbrock_value(x);
  };
  const std::vector<double> start{-1.2, 1.0};
  const NelderMeadResult r = nelder_mead(slow, start, o);
  EXPECT_EQ(r.report.termination, Termination::WallTime) << r.report.message;
  EXPECT_EQ(r.report.generations, 0u);
}

// checks: the progress callback sees generations 0..report.generations in order with increasing evaluation
// counts; each generation's best is the history's value of that iteration (the simplex's lowest vertex,
// recomputed from the reported vertices), the last generation holds the result (x, value) after every
// evaluation; and the run with the callback is bit for bit the run without it
TEST(OptimNelderMead, ProgressCallbackReportsEverySimplexAndChangesNothing) {
  const std::vector<double> start{-1.2, 1.0};
  std::vector<GenerationLog> seen;
  NelderMeadOptions o;
  o.on_generation = [&seen](const GenerationLog& g) { seen.push_back(g); };
  const NelderMeadResult with = nelder_mead(rosenbrock_value, start, o);
  const NelderMeadResult without = nelder_mead(rosenbrock_value, start);
  EXPECT_EQ(with.x, without.x);
  EXPECT_EQ(with.value, without.value);
  EXPECT_EQ(with.history, without.history);
  EXPECT_EQ(with.report.evaluations, without.report.evaluations);
  ASSERT_EQ(seen.size(), with.report.generations + 1);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const GenerationLog& g = seen[i];
    ASSERT_EQ(g.generation, i);
    ASSERT_EQ(g.size(), 3u);
    ASSERT_EQ(g.dimension, 2u);
    if (i > 0) {
      EXPECT_GE(g.evaluations, seen[i - 1].evaluations) << i;
    }
    // every reported value is f at its reported vertex
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(g.objective_values[k], rosenbrock_value(std::span<const double>(g.variables.data() + 2 * k, 2))) << i;
    if (i < with.history.size()) {
      EXPECT_EQ(statistics(g).best, with.history[i]) << i;
    }
  }
  EXPECT_GT(seen.back().evaluations, seen.front().evaluations);
  EXPECT_EQ(seen.back().evaluations, with.report.evaluations);
  EXPECT_EQ(statistics(seen.back()).best, with.value);
}

// checks: the documented errors name the input at fault
TEST(OptimNelderMead, Errors) {
  NelderMeadOptions o;
  o.initial_step = 0.0;
  const std::vector<double> start{1.0, 2.0};
  HULA_EXPECT_ERROR((void)nelder_mead(rosenbrock_value, start, o), Errc::InvalidOption, "initial_step = 0");
  const std::vector<double> bad{1.0, std::numeric_limits<double>::quiet_NaN()};
  HULA_EXPECT_ERROR((void)nelder_mead(rosenbrock_value, bad), Errc::NonFiniteInput, "start[1]");
  HULA_EXPECT_ERROR((void)nelder_mead(rosenbrock_value, std::vector<double>{}), Errc::InvalidArgument, "empty");
  auto inf = [](std::span<const double>) { return std::numeric_limits<double>::infinity(); };
  HULA_EXPECT_ERROR((void)nelder_mead(inf, start), Errc::NumericalFailure, "not finite at the start");
}

}  // namespace
}  // namespace hula::optim
