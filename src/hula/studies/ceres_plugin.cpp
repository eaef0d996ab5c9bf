// SPDX-License-Identifier: MIT
// The Ceres plugin (libhula_ceres.so): LsqSolver::Ceres's bounded trust-region Levenberg–Marquardt, the only
// code of HulaHoops that links Ceres Solver. Loaded by refine_levenberg_marquardt through
// hula/core/plugin.hpp (detail/ceres_plugin.hpp holds the entry point's type).
#include "hula/studies/detail/ceres_plugin.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <chrono>
#include <cstdint>
#include <vector>

#include "hula/studies/detail/difference_column.hpp"

namespace hula::studies {
namespace {

double elapsed_seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The least-squares problem as one Ceres cost function over one parameter block, with the Jacobian of
// difference_column (Ceres's own numeric differentiation would step outside the bounds).
class CeresResiduals final : public ceres::CostFunction {
 public:
  CeresResiduals(const LeastSquaresProblem& problem, double step, bool forward, std::size_t& evaluations)
      : problem_(problem), step_(step), forward_(forward), evaluations_(evaluations) {
    set_num_residuals(static_cast<int>(problem.residual_count));
    mutable_parameter_block_sizes()->push_back(static_cast<std::int32_t>(problem.variables.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::size_t n = problem_.variables.size(), m = problem_.residual_count;
    const std::span<const double> x(parameters[0], n);
    auto eval = [&](std::span<const double> at, Eigen::VectorXd& out) {
      ++evaluations_;
      return problem_.residuals(at, std::span<double>(out.data(), m));
    };
    Eigen::VectorXd r(static_cast<Eigen::Index>(m));
    if (jacobians != nullptr && jacobians[0] != nullptr && problem_.jacobian) {
      ++evaluations_;
      if (!problem_.jacobian(x, std::span<double>(r.data(), m), std::span<double>(jacobians[0], m * n))) return false;
      std::copy(r.data(), r.data() + m, residuals);
      return true;
    }
    if (!eval(x, r)) return false;
    std::copy(r.data(), r.data() + m, residuals);
    if (jacobians == nullptr || jacobians[0] == nullptr) return true;
    // Ceres wants the Jacobian row-major, m x n.
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
        jacobians[0], static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
    Eigen::VectorXd r_plus(r.size()), r_minus(r.size()), column(r.size());
    std::vector<double> x_fd;
    for (std::size_t j = 0; j < n; ++j) {
      (void)detail::difference_column(problem_.variables, x, j, step_, x_fd, r_plus, r_minus, eval, column,
                                      forward_ ? &r : nullptr);
      J.col(static_cast<Eigen::Index>(j)) = column;
    }
    return true;
  }

 private:
  const LeastSquaresProblem& problem_;
  double step_;
  bool forward_;
  std::size_t& evaluations_;
};

// Stops Ceres once the mean |r| reaches the target (Ceres's own tolerances are relative), or once the time
// budget (0 = none) has run out after an accepted step.
class TargetCallback final : public ceres::IterationCallback {
 public:
  TargetCallback(double cost_target, double budget_seconds, std::size_t max_accepted,
                 std::chrono::steady_clock::time_point start)
      : cost_target_(cost_target), budget_seconds_(budget_seconds), max_accepted_(max_accepted), start_(start) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.cost <= cost_target_) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    if (summary.iteration > 0 && summary.step_is_successful) ++accepted_;
    if (accepted_ > 0 && budget_seconds_ > 0.0 && elapsed_seconds(start_) >= budget_seconds_) {
      out_of_time_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (max_accepted_ > 0 && accepted_ >= max_accepted_) {
      out_of_steps_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  [[nodiscard]] bool out_of_time() const noexcept { return out_of_time_; }
  [[nodiscard]] bool out_of_steps() const noexcept { return out_of_steps_; }

 private:
  double cost_target_;
  double budget_seconds_;
  std::size_t max_accepted_;
  std::chrono::steady_clock::time_point start_;
  std::size_t accepted_ = 0;
  bool out_of_time_ = false;
  bool out_of_steps_ = false;
};

}  // namespace
}  // namespace hula::studies

HULA_PLUGIN_EXPORT void hula_ceres_solve(const hula::studies::LeastSquaresProblem& problem,
                                         const hula::studies::LmOptions& options, std::span<const int> fixed,
                                         std::chrono::steady_clock::time_point start, std::vector<double>& x,
                                         std::size_t& evaluations, hula::studies::detail::CeresRun& run) {
  using hula::optim::Termination;
  using hula::studies::CeresResiduals;
  using hula::studies::TargetCallback;
  const std::size_t n = problem.variables.size(), m = problem.residual_count;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem cp(problem_options);
  cp.AddResidualBlock(new CeresResiduals(problem, options.difference_step, options.forward_differences, evaluations),
                      nullptr, x.data());
  std::size_t next_fixed = 0;
  for (std::size_t j = 0; j < n; ++j) {
    // Ceres wants lower < upper; a zero-width box is a fixed coordinate.
    if (next_fixed < fixed.size() && static_cast<std::size_t>(fixed[next_fixed]) == j) {
      ++next_fixed;
      continue;
    }
    cp.SetParameterLowerBound(x.data(), static_cast<int>(j), problem.variables[j].lower);
    cp.SetParameterUpperBound(x.data(), static_cast<int>(j), problem.variables[j].upper);
  }
  if (!fixed.empty())
    cp.SetManifold(x.data(),
                   new ceres::SubsetManifold(static_cast<int>(n), std::vector<int>(fixed.begin(), fixed.end())));
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.use_nonmonotonic_steps = true;
  so.max_num_iterations = static_cast<int>(options.max_iterations);
  so.initial_trust_region_radius = 1.0 / options.initial_lambda;
  so.function_tolerance = options.relative_tolerance;
  so.parameter_tolerance = 1e-14;
  so.gradient_tolerance = 0.0;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.num_threads = 1;
  // mean |r| <= rms |r| = √(‖r‖² / m): a cost ½‖r‖² <= ½ m t² guarantees the target; the true mean is reported.
  const double t = options.target_mean;
  TargetCallback stop(0.5 * static_cast<double>(m) * t * t, options.time_budget_seconds, options.max_accepted_steps,
                      start);
  so.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &cp, &summary);
  run.iterations = summary.iterations.empty() ? 0 : summary.iterations.size() - 1;
  run.out_of_time = stop.out_of_time();
  run.out_of_steps = stop.out_of_steps();
  if (summary.termination_type == ceres::CONVERGENCE) {
    run.termination = Termination::Converged;
    run.message = summary.message;
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    run.termination = Termination::MaxGenerations;
    run.message = summary.message;
  } else {
    run.termination = Termination::Stagnation;
    run.message = "Ceres failed: " + summary.message;
  }
}
