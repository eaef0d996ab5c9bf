// SPDX-License-Identifier: MIT
// One Jacobian column by finite differences inside the bounds, shared by the clamped Levenberg–Marquardt
// (hybrid_refine.cpp) and the Ceres cost function of the Ceres plugin (ceres_plugin.cpp).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "hula/optim/problem.hpp"

namespace hula::studies::detail {

/// Jacobian column j at x by central differences (one-sided where a bound is within the step), or, given the
/// residuals r_at of x (LmOptions::forward_differences), by a one-sided difference to the side that is inside
/// the bounds; false (and a zero column) if the residuals are undefined there.
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

}  // namespace hula::studies::detail
