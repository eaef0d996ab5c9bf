// SPDX-License-Identifier: MIT
#include "hula/studies/hybrid_refine.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>

#include "hula/core/error.hpp"
#include "hula/core/plugin.hpp"
#include "hula/studies/detail/ceres_plugin.hpp"
#include "hula/studies/detail/difference_column.hpp"

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
            (void)detail::difference_column(vars, x, j, options.difference_step, x_fd, r_plus, r_minus, eval,
                                            J.col(static_cast<Eigen::Index>(j)),
                                            options.forward_differences ? &r : nullptr);
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
    // Ceres: bounded trust-region LM on the same residuals and Jacobian, in the Ceres plugin
    // (detail/ceres_plugin.hpp), loaded on the first Ceres solve only; a failed load is retried next time.
    std::vector<int> fixed;
    for (std::size_t j = 0; j < n; ++j)
      if (!(vars[j].upper > vars[j].lower)) fixed.push_back(static_cast<int>(j));  // Ceres wants lower < upper
    if (fixed.size() == n) {
      end_with(Termination::Converged, "every variable is fixed");
    } else {
      static const auto ceres_solve =
          reinterpret_cast<detail::CeresSolveFunction>(plugin_symbol("ceres", detail::kCeresSolveSymbol));
      detail::CeresRun run;
      ceres_solve(problem, options, fixed, clock_start, x, result.evaluations, run);
      result.iterations = run.iterations;
      if (!eval(x, r))
        throw Error(Errc::NumericalFailure, "the residuals are undefined at the solver's result", {.field = "start"});
      if (mean_abs(r) <= options.target_mean)
        end_with(Termination::TargetReached, "target_mean reached");
      else if (run.out_of_time)
        end_with(Termination::WallTime, "time_budget_seconds ran out");
      else if (run.out_of_steps)
        end_with(Termination::MaxGenerations,
                 "max_accepted_steps = " + std::to_string(options.max_accepted_steps) + " steps accepted");
      else
        end_with(run.termination, std::move(run.message));
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
