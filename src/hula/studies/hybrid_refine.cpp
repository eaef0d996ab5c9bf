// SPDX-License-Identifier: MIT
#include "hula/studies/hybrid_refine.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>

#include "hula/core/error.hpp"

namespace hula::studies {

namespace {

double elapsed_seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check_range(bool ok, const char* field, double value, const char* range) {
  if (!ok)
    throw Error(Errc::InvalidOption, std::string("lm.") + field + " = " + format_number(value) + " must be " + range,
                {.field = std::string("lm.") + field});
}

// Jacobian column j at x by central differences (one-sided where a bound is within the step), or, given the
// residuals r_at of x (LmOptions::forward_differences), by a one-sided difference to the side that is inside
// the bounds; false if the residuals are undefined there.
template <class Eval>
bool difference_column(const std::vector<optim::Variable>& vars, std::span<const double> x, std::size_t j, double step,
                       std::vector<double>& x_fd, Eigen::VectorXd& r_plus, Eigen::VectorXd& r_minus, Eval&& eval,
                       Eigen::Ref<Eigen::VectorXd> column, const Eigen::VectorXd* r_at = nullptr) {
  const double h = step * std::max(1.0, std::fabs(x[j]));
  const double hi = std::min(x[j] + h, vars[j].upper);
  const double lo = std::max(x[j] - h, vars[j].lower);
  x_fd.assign(x.begin(), x.end());
  if (r_at != nullptr) {
    const double to = hi > x[j] ? hi : lo;
    x_fd[j] = to;
    if (!(to != x[j]) || !eval(x_fd, r_plus)) {
      column.setZero();
      return false;
    }
    column = (r_plus - *r_at) / (to - x[j]);
    return true;
  }
  x_fd[j] = hi;
  const bool ok_hi = eval(x_fd, r_plus);
  x_fd[j] = lo;
  const bool ok_lo = eval(x_fd, r_minus);
  if (!ok_hi || !ok_lo || !(hi > lo)) {
    column.setZero();
    return false;
  }
  column = (r_plus - r_minus) / (hi - lo);
  return true;
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
      (void)difference_column(problem_.variables, x, j, step_, x_fd, r_plus, r_minus, eval, column,
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

std::string_view lsq_solver_name(LsqSolver s) noexcept { return s == LsqSolver::Ceres ? "ceres" : "clamped"; }

LsqSolver lsq_solver_from_name(std::string_view name, std::string_view field) {
  if (name == "ceres") return LsqSolver::Ceres;
  if (name == "clamped") return LsqSolver::ClampedLm;
  throw Error(Errc::ParseError,
              std::string(field) + " = \"" + std::string(name) + "\" must be \"ceres\" or \"clamped\"",
              {.field = std::string(field)});
}

void LmOptions::validate() const {
  check_range(max_iterations >= 1, "max_iterations", static_cast<double>(max_iterations), ">= 1");
  check_range(std::isfinite(target_mean) && target_mean >= 0.0, "target_mean", target_mean, "finite and >= 0");
  check_range(std::isfinite(relative_tolerance) && relative_tolerance >= 0.0, "relative_tolerance", relative_tolerance,
              "finite and >= 0");
  check_range(std::isfinite(initial_lambda) && initial_lambda > 0.0, "initial_lambda", initial_lambda,
              "finite and > 0");
  check_range(difference_step > 0.0 && difference_step <= 1e-2, "difference_step", difference_step, "in (0, 1e-2]");
  check_range(std::isfinite(time_budget_seconds) && time_budget_seconds >= 0.0, "time_budget_seconds",
              time_budget_seconds, "finite and >= 0");
}

LmResult refine_levenberg_marquardt(const LeastSquaresProblem& problem, std::span<const double> start,
                                    const LmOptions& options) {
  options.validate();
  if (problem.residual_count == 0 || !problem.residuals)
    throw Error(Errc::InvalidArgument, "a least-squares problem needs residuals (residual_count >= 1 and a function)");
  const auto clock_start = std::chrono::steady_clock::now();
  const std::size_t n = problem.variables.size();
  const std::size_t m = problem.residual_count;
  const std::vector<optim::Variable>& vars = problem.variables;
  if (start.size() != n)
    throw Error(
        Errc::InvalidArgument,
        "start has " + std::to_string(start.size()) + " values, the problem " + std::to_string(n) + " variables",
        {.field = "start"});
  for (std::size_t j = 0; j < n; ++j)
    if (!(start[j] >= vars[j].lower && start[j] <= vars[j].upper))
      throw Error(Errc::InvalidArgument,
                  "start value of " + vars[j].name + " = " + format_number(start[j]) + " is outside its bounds [" +
                      format_number(vars[j].lower) + ", " + format_number(vars[j].upper) + "]",
                  {.field = "start", .index = j});

  LmResult result;
  result.variables.assign(start.begin(), start.end());
  const auto M = static_cast<Eigen::Index>(m);
  const auto Nv = static_cast<Eigen::Index>(n);
  Eigen::VectorXd r(M), r_try(M), r_plus(M), r_minus(M);
  auto eval = [&](std::span<const double> x, Eigen::VectorXd& out) {
    ++result.evaluations;
    return problem.residuals(x, std::span<double>(out.data(), m));
  };
  auto mean_abs = [&](const Eigen::VectorXd& v) { return v.cwiseAbs().sum() / static_cast<double>(m); };

  std::vector<double>& x = result.variables;
  if (!eval(x, r))
    throw Error(Errc::NumericalFailure, "the residuals are undefined at the start (a degenerate curve)",
                {.field = "start"});
  result.mean_before = mean_abs(r);
  Eigen::MatrixXd J(M, Nv);
  Eigen::MatrixXd A(M + Nv, Nv);
  Eigen::VectorXd b(M + Nv);
  std::vector<double> x_try(n), x_fd(n);
  std::vector<double> jacobian_rows(problem.jacobian ? m * n : 0);

  // Damped Gauss-Newton steps from x until `target` or `budget` steps.
  using optim::Termination;
  const auto end_with = [&](Termination termination, std::string message) {
    result.termination = termination;
    result.message = std::move(message);
  };
  auto solve = [&](double target, std::size_t budget) {
    (void)eval(x, r);  // the start, checked above
    double cost = r.squaredNorm();
    double lambda = options.initial_lambda;
    bool need_jacobian = true;
    std::size_t accepted = 0;
    for (std::size_t step = 0; step < budget; ++step) {
      if (mean_abs(r) <= target) return end_with(Termination::TargetReached, "target_mean reached");
      if (need_jacobian) {
        if (problem.jacobian) {
          ++result.evaluations;
          if (!problem.jacobian(x, std::span<double>(r_plus.data(), m), jacobian_rows))
            return end_with(Termination::Stagnation,
                            "the exact Jacobian is undefined at the current design (degenerate)");
          J = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
              jacobian_rows.data(), M, Nv);
        } else {
          for (std::size_t j = 0; j < n; ++j)
            (void)difference_column(vars, x, j, options.difference_step, x_fd, r_plus, r_minus, eval,
                                    J.col(static_cast<Eigen::Index>(j)), options.forward_differences ? &r : nullptr);
        }
        need_jacobian = false;
      }
      ++result.iterations;
      // Damped least squares with Marquardt's scaling.
      A.topRows(M) = J;
      A.bottomRows(Nv).setZero();
      for (std::size_t j = 0; j < n; ++j) {
        const double dj = std::max(J.col(static_cast<Eigen::Index>(j)).norm(), 1e-12);
        A(M + static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)) = std::sqrt(lambda) * dj;
      }
      b.head(M) = -r;
      b.tail(Nv).setZero();
      const Eigen::VectorXd delta = A.householderQr().solve(b);
      for (std::size_t j = 0; j < n; ++j)
        x_try[j] = std::clamp(x[j] + delta(static_cast<Eigen::Index>(j)), vars[j].lower, vars[j].upper);
      const bool ok = eval(x_try, r_try);
      const double cost_try = ok ? r_try.squaredNorm() : std::numeric_limits<double>::infinity();
      if (ok && cost_try < cost) {
        const double reduction = (cost - cost_try) / cost;
        x.swap(x_try);
        r.swap(r_try);
        cost = cost_try;
        lambda = std::max(lambda / 3.0, 1e-15);
        need_jacobian = true;
        if (reduction < options.relative_tolerance)
          return end_with(Termination::Converged, "a step lowered the cost by less than relative_tolerance");
        if (options.time_budget_seconds > 0.0 && elapsed_seconds(clock_start) >= options.time_budget_seconds)
          return end_with(Termination::WallTime, "time_budget_seconds ran out");
        if (options.max_accepted_steps > 0 && ++accepted >= options.max_accepted_steps)
          return end_with(Termination::MaxGenerations,
                          "max_accepted_steps = " + std::to_string(options.max_accepted_steps) + " steps accepted");
      } else {
        lambda *= 4.0;
        if (lambda > 1e16) return end_with(Termination::Stagnation, "damping overflow: no step lowers the cost");
      }
    }
    if (mean_abs(r) <= target) return end_with(Termination::TargetReached, "target_mean reached");
    end_with(Termination::MaxGenerations, "max_iterations = " + std::to_string(budget) + " steps run");
  };

  if (options.solver == LsqSolver::ClampedLm) {
    solve(options.target_mean, options.max_iterations);
  } else {
    // Ceres: bounded trust-region LM on the same residuals and Jacobian.
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
    ceres::Problem cp(problem_options);
    cp.AddResidualBlock(
        new CeresResiduals(problem, options.difference_step, options.forward_differences, result.evaluations), nullptr,
        x.data());
    std::vector<int> fixed;
    for (std::size_t j = 0; j < n; ++j) {
      // Ceres wants lower < upper; a zero-width box is a fixed coordinate.
      if (!(vars[j].upper > vars[j].lower)) {
        fixed.push_back(static_cast<int>(j));
        continue;
      }
      cp.SetParameterLowerBound(x.data(), static_cast<int>(j), vars[j].lower);
      cp.SetParameterUpperBound(x.data(), static_cast<int>(j), vars[j].upper);
    }
    if (fixed.size() == n) {
      end_with(Termination::Converged, "every variable is fixed");
    } else {
      if (!fixed.empty()) cp.SetManifold(x.data(), new ceres::SubsetManifold(static_cast<int>(n), fixed));
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
                          clock_start);
      so.callbacks.push_back(&stop);
      ceres::Solver::Summary summary;
      ceres::Solve(so, &cp, &summary);
      result.iterations = summary.iterations.empty() ? 0 : summary.iterations.size() - 1;
      if (!eval(x, r))
        throw Error(Errc::NumericalFailure, "the residuals are undefined at the solver's result", {.field = "start"});
      if (mean_abs(r) <= t)
        end_with(Termination::TargetReached, "target_mean reached");
      else if (stop.out_of_time())
        end_with(Termination::WallTime, "time_budget_seconds ran out");
      else if (stop.out_of_steps())
        end_with(Termination::MaxGenerations,
                 "max_accepted_steps = " + std::to_string(options.max_accepted_steps) + " steps accepted");
      else if (summary.termination_type == ceres::CONVERGENCE)
        end_with(Termination::Converged, summary.message);
      else if (summary.termination_type == ceres::NO_CONVERGENCE)
        end_with(Termination::MaxGenerations, summary.message);
      else
        end_with(Termination::Stagnation, "Ceres failed: " + summary.message);
    }
  }
  result.mean_after = mean_abs(r);
  result.seconds = elapsed_seconds(clock_start);
  return result;
}

LmResult refine_levenberg_marquardt(const CurvatureMatch& match, std::span<const double> start,
                                    const LmOptions& options) {
  LeastSquaresProblem problem;
  problem.variables = match.variables();
  const std::size_t m = match.target_samples().size();
  // Proximity residuals √w_i (x_j − x_j⁰) after the curvature ones (CurvatureMatchSetup::proximity).
  const std::vector<double>& w = match.setup().proximity;
  std::vector<double> root_weight, x0;
  if (!w.empty()) {
    x0 = match.proximity_variables();
    for (std::size_t j = 0; j < x0.size(); ++j) root_weight.push_back(std::sqrt(w[match.variable_point(j)]));
  }
  problem.residual_count = m + root_weight.size();
  auto ws = std::make_shared<SplineProfileSampler::Workspace>();
  auto points = std::make_shared<std::vector<Vec3>>(match.setup().points.size());
  problem.residuals = [&match, ws, points, m, root_weight, x0](std::span<const double> x, std::span<double> r) {
    if (!match.residuals(x, *ws, *points, r.first(m))) return false;
    for (std::size_t j = 0; j < root_weight.size(); ++j) r[m + j] = root_weight[j] * (x[j] - x0[j]);
    return true;
  };
  if (options.exact_jacobian && match.has_exact_jacobian()) {
    auto jws = std::make_shared<SplineProfileSampler::Workspace>();
    auto jpoints = std::make_shared<std::vector<Vec3>>(match.setup().points.size());
    const std::size_t n = problem.variables.size();
    problem.jacobian = [&match, jws, jpoints, m, n, root_weight, x0](std::span<const double> x, std::span<double> r,
                                                                     std::span<double> J) {
      if (!match.residuals_jacobian(x, *jws, *jpoints, r.first(m), J.first(m * n))) return false;
      // Proximity rows: ∂(√w (x_j − x_j⁰))/∂x_j = √w.
      std::fill(J.begin() + static_cast<std::ptrdiff_t>(m * n), J.end(), 0.0);
      for (std::size_t j = 0; j < root_weight.size(); ++j) {
        r[m + j] = root_weight[j] * (x[j] - x0[j]);
        J[(m + j) * n + j] = root_weight[j];
      }
      return true;
    };
  }
  return refine_levenberg_marquardt(problem, start, options);
}

}  // namespace hula::studies
