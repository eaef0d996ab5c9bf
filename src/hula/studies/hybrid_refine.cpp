// SPDX-License-Identifier: MIT
#include "hula/studies/hybrid_refine.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "hula/core/error.hpp"

namespace hula::studies {

namespace {

void check_range(bool ok, const char* field, double value, const char* range) {
  if (!ok)
    throw Error(Errc::InvalidOption, std::string("lm.") + field + " = " + format_number(value) + " must be " + range,
                {.field = std::string("lm.") + field});
}

}  // namespace

void LmOptions::validate() const {
  check_range(max_iterations >= 1, "max_iterations", static_cast<double>(max_iterations), ">= 1");
  check_range(std::isfinite(target_mean) && target_mean >= 0.0, "target_mean", target_mean, "finite and >= 0");
  check_range(std::isfinite(relative_tolerance) && relative_tolerance >= 0.0, "relative_tolerance", relative_tolerance,
              "finite and >= 0");
  check_range(std::isfinite(initial_lambda) && initial_lambda > 0.0, "initial_lambda", initial_lambda,
              "finite and > 0");
  check_range(difference_step > 0.0 && difference_step <= 1e-2, "difference_step", difference_step, "in (0, 1e-2]");
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

  // Damped Gauss-Newton steps from x until `target` or `budget` steps.
  auto solve = [&](double target, std::size_t budget) {
    if (!eval(x, r)) return std::string("degenerate");
    double cost = r.squaredNorm();
    double lambda = options.initial_lambda;
    bool need_jacobian = true;
    for (std::size_t step = 0; step < budget; ++step) {
      if (mean_abs(r) <= target) return std::string("target reached");
      if (need_jacobian) {
        x_fd = x;
        for (std::size_t j = 0; j < n; ++j) {
          const double h = options.difference_step * std::max(1.0, std::fabs(x[j]));
          const double hi = std::min(x[j] + h, vars[j].upper);
          const double lo = std::max(x[j] - h, vars[j].lower);
          x_fd[j] = hi;
          const bool ok_hi = eval(x_fd, r_plus);
          x_fd[j] = lo;
          const bool ok_lo = eval(x_fd, r_minus);
          x_fd[j] = x[j];
          if (!ok_hi || !ok_lo || !(hi > lo)) {
            J.col(static_cast<Eigen::Index>(j)).setZero();
            continue;
          }
          J.col(static_cast<Eigen::Index>(j)) = (r_plus - r_minus) / (hi - lo);
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
        if (reduction < options.relative_tolerance) return std::string("converged");
      } else {
        lambda *= 4.0;
        if (lambda > 1e16) return std::string("damping overflow");
      }
    }
    return mean_abs(r) <= target ? std::string("target reached") : std::string("max iterations");
  };

  result.termination = solve(options.target_mean, options.max_iterations);
  result.mean_after = mean_abs(r);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

LmResult refine_levenberg_marquardt(const CurvatureMatch& match, std::span<const double> start,
                                    const LmOptions& options) {
  LeastSquaresProblem problem;
  problem.variables = match.variables();
  problem.residual_count = match.target_samples().size();
  auto ws = std::make_shared<SplineProfileSampler::Workspace>();
  auto points = std::make_shared<std::vector<Vec3>>(match.setup().points.size());
  problem.residuals = [&match, ws, points](std::span<const double> x, std::span<double> r) {
    return match.residuals(x, *ws, *points, r);
  };
  return refine_levenberg_marquardt(problem, start, options);
}

}  // namespace hula::studies
