// SPDX-License-Identifier: MIT
// The Levenberg–Marquardt stage reports the shared optim::Termination with a
// message, on least-squares problems built to end each way: a linear residual
// whose first Gauss–Newton step hits the target exactly, an inconsistent pair
// (x − 1, x + 1) whose minimum 2 is not 0 (converged), Rosenbrock's residuals
// with one step allowed (iteration budget) or a spent time budget (wall time),
// and residuals undefined off the start (no step is ever accepted: the damping
// overflows).
#include "hula/studies/hybrid_refine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

using optim::Termination;

LeastSquaresProblem problem(std::size_t n, std::size_t m,
                            std::function<bool(std::span<const double>, std::span<double>)> residuals) {
  LeastSquaresProblem p;
  for (std::size_t j = 0; j < n; ++j) p.variables.push_back({"x" + std::to_string(j), -10.0, 10.0, 0.0});
  p.residual_count = m;
  p.residuals = std::move(residuals);
  return p;
}

const LeastSquaresProblem kLinear = problem(1, 1, [](std::span<const double> x, std::span<double> r) {
  r[0] = x[0] - 1.0;
  return true;
});
const LeastSquaresProblem kInconsistent = problem(1, 2, [](std::span<const double> x, std::span<double> r) {
  r[0] = x[0] - 1.0;
  r[1] = x[0] + 1.0;
  return true;
});
const LeastSquaresProblem kRosenbrock = problem(2, 2, [](std::span<const double> x, std::span<double> r) {
  r[0] = 10.0 * (x[1] - x[0] * x[0]);
  r[1] = 1.0 - x[0];
  return true;
});

LmOptions with(LsqSolver solver) {
  LmOptions o;
  o.solver = solver;
  return o;
}

class LmTermination : public ::testing::TestWithParam<LsqSolver> {};

// checks: r = x − 1 from 3: the target mean 1e-10 is reached (the residual is linear, so the steps are exact)
TEST_P(LmTermination, TargetReached) {
  const LmResult r = refine_levenberg_marquardt(kLinear, std::vector<double>{3.0}, with(GetParam()));
  EXPECT_EQ(r.termination, Termination::TargetReached) << r.message;
  EXPECT_NEAR(r.variables[0], 1.0, 1e-9);
  EXPECT_FALSE(r.message.empty());
}

// checks: (x − 1, x + 1) from 3 has its least-squares minimum at x = 0 with mean |r| = 1 > target: the run ends
// Converged there
TEST_P(LmTermination, Converged) {
  const LmResult r = refine_levenberg_marquardt(kInconsistent, std::vector<double>{3.0}, with(GetParam()));
  EXPECT_EQ(r.termination, Termination::Converged) << r.message;
  EXPECT_NEAR(r.variables[0], 0.0, 1e-6);
  EXPECT_NEAR(r.mean_after, 1.0, 1e-9);
}

// checks: Rosenbrock's residuals from (−1.2, 1) with max_iterations = 1: one step cannot reach (1, 1), the run
// ends on its iteration budget (MaxGenerations)
TEST_P(LmTermination, IterationBudget) {
  LmOptions o = with(GetParam());
  o.max_iterations = 1;
  const LmResult r = refine_levenberg_marquardt(kRosenbrock, std::vector<double>{-1.2, 1.0}, o);
  EXPECT_EQ(r.termination, Termination::MaxGenerations) << r.message;
  EXPECT_GT(r.mean_after, 1e-3);
}

// checks: Rosenbrock's residuals from (−1.2, 1) with a budget that is spent before the solve starts
// (1e-9 s): the first accepted step still runs (the cost drops below the start's), then the run ends
// WallTime at the next check, long before (1, 1); a negative or NaN budget is refused naming it
TEST_P(LmTermination, TimeBudget) {
  LmOptions o = with(GetParam());
  o.time_budget_seconds = 1e-9;
  const LmResult r = refine_levenberg_marquardt(kRosenbrock, std::vector<double>{-1.2, 1.0}, o);
  EXPECT_EQ(r.termination, Termination::WallTime) << r.message;
  const auto rosenbrock = [](const std::vector<double>& x) {
    return 100.0 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1.0 - x[0]) * (1.0 - x[0]);
  };
  EXPECT_LT(rosenbrock(r.variables), rosenbrock({-1.2, 1.0}));
  EXPECT_GT(std::hypot(r.variables[0] - 1.0, r.variables[1] - 1.0), 1e-3);
  EXPECT_LT(r.iterations, 40U);  // the default 200 would run on to (1, 1)
  for (const double bad : {-1.0, std::nan("")}) {
    o.time_budget_seconds = bad;
    HULA_EXPECT_ERROR(static_cast<void>(refine_levenberg_marquardt(kRosenbrock, std::vector<double>{-1.2, 1.0}, o)),
                      Errc::InvalidOption, "time_budget_seconds");
  }
}

// checks: one-sided differences (forward_differences) still take Rosenbrock's residuals from (−1.2, 1) to
// (1, 1) (the closed-form minimum), with fewer residual evaluations than central differences need
TEST_P(LmTermination, ForwardDifferences) {
  LmOptions central = with(GetParam());
  central.target_mean = 1e-8;
  LmOptions forward = central;
  forward.forward_differences = true;
  const LmResult c = refine_levenberg_marquardt(kRosenbrock, std::vector<double>{-1.2, 1.0}, central);
  const LmResult f = refine_levenberg_marquardt(kRosenbrock, std::vector<double>{-1.2, 1.0}, forward);
  EXPECT_EQ(f.termination, Termination::TargetReached) << f.message;
  EXPECT_NEAR(f.variables[0], 1.0, 1e-6);
  EXPECT_NEAR(f.variables[1], 1.0, 1e-6);
  EXPECT_LT(static_cast<double>(f.evaluations) / static_cast<double>(f.iterations),
            static_cast<double>(c.evaluations) / static_cast<double>(c.iterations));
}

// checks: Rosenbrock's residuals from (−1.2, 1) with max_accepted_steps = 2 and room for 200 steps: the
// run ends MaxGenerations after its second accepted step, lower than the start but not at (1, 1)
TEST_P(LmTermination, AcceptedStepBudget) {
  LmOptions o = with(GetParam());
  o.max_accepted_steps = 2;
  const LmResult r = refine_levenberg_marquardt(kRosenbrock, std::vector<double>{-1.2, 1.0}, o);
  EXPECT_EQ(r.termination, Termination::MaxGenerations) << r.message;
  const auto rosenbrock = [](const std::vector<double>& x) {
    return 100.0 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1.0 - x[0]) * (1.0 - x[0]);
  };
  EXPECT_LT(rosenbrock(r.variables), rosenbrock({-1.2, 1.0}));
  EXPECT_GT(std::hypot(r.variables[0] - 1.0, r.variables[1] - 1.0), 1e-3);
  EXPECT_LT(r.iterations, 200U);
}

INSTANTIATE_TEST_SUITE_P(Solvers, LmTermination, ::testing::Values(LsqSolver::ClampedLm, LsqSolver::Ceres),
                         [](const auto& solver) { return std::string(lsq_solver_name(solver.param)); });

// checks: residuals defined only at the start x = 3: every step is rejected and the damping grows 4× per step
// until it overflows 1e16 (about 32 steps from 1e-3), so the clamped LM ends Stagnation
TEST(LmTermination, DampingOverflowIsStagnation) {
  const LeastSquaresProblem only_start = problem(1, 1, [](std::span<const double> x, std::span<double> r) {
    r[0] = x[0] - 1.0;
    return x[0] == 3.0;
  });
  const LmResult r = refine_levenberg_marquardt(only_start, std::vector<double>{3.0}, with(LsqSolver::ClampedLm));
  EXPECT_EQ(r.termination, Termination::Stagnation) << r.message;
  EXPECT_EQ(r.variables[0], 3.0);
  EXPECT_LT(r.iterations, 40U);
}

}  // namespace
}  // namespace hula::studies
