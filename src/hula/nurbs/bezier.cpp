// SPDX-License-Identifier: MIT
// Bézier construction, de Casteljau subdivision and Bernstein evaluation.
//
// Notation (The NURBS Book ch. 1): n = degree, P_i control points, w_i weights,
// Pw_i = (w_i P_i, w_i); de Casteljau: Q^k_i = (1 - t) Q^{k-1}_i + t Q^{k-1}_{i+1}.
#include "hula/nurbs/bezier.hpp"

#include <array>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/homogeneous.hpp"

namespace hula::nurbs {

namespace {

void check_points(std::span<const Vec3> points) {
  if (points.size() < 2)
    throw Error(Errc::TooFewPoints,
                "control_points has " + std::to_string(points.size()) + " point(s); a Bézier curve needs at least 2",
                {.field = "control_points"});
  if (points.size() > static_cast<std::size_t>(kMaxDegree) + 1)
    throw Error(Errc::InvalidDegree,
                std::to_string(points.size()) + " control points give degree " + std::to_string(points.size() - 1) +
                    " above kMaxDegree = " + std::to_string(kMaxDegree),
                {.field = "control_points"});
}

void check_inputs(std::span<const Vec3> points, std::span<const double> weights, double t) {
  check_points(points);
  if (!weights.empty() && weights.size() != points.size())
    throw Error(
        Errc::InvalidWeight,
        std::to_string(weights.size()) + " weights given for " + std::to_string(points.size()) + " control points",
        {.field = "weights"});
  for (std::size_t i = 0; i < weights.size(); ++i)
    if (!(std::isfinite(weights[i]) && weights[i] > 0.0))
      throw Error(Errc::InvalidWeight,
                  "weights[" + std::to_string(i) + "] = " + format_number(weights[i]) + " must be finite and > 0",
                  {.field = "weights", .index = i});
  if (!std::isfinite(t))
    throw Error(Errc::NonFiniteInput, "t = " + format_number(t) + " is not finite", {.field = "t"});
  if (t < 0.0 || t > 1.0)
    throw Error(Errc::OutOfDomain, "t = " + format_number(t) + " is outside the Bézier domain [0, 1]", {.field = "t"});
}

}  // namespace

NurbsCurve make_bezier(std::span<const Vec3> control_points, std::span<const double> weights, int dimension) {
  check_points(control_points);
  const std::size_t n = control_points.size();
  std::vector<double> knots(2 * n, 0.0);
  std::fill(knots.begin() + static_cast<std::ptrdiff_t>(n), knots.end(), 1.0);
  return NurbsCurve(static_cast<int>(n) - 1, std::move(knots), {control_points.begin(), control_points.end()},
                    {weights.begin(), weights.end()}, dimension);
}

DeCasteljauResult de_casteljau(std::span<const Vec3> control_points, std::span<const double> weights, double t) {
  check_inputs(control_points, weights, t);
  const std::size_t n = control_points.size() - 1;
  const bool rational = !weights.empty();
  std::vector<detail::Hpoint> Q(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    const double w = rational ? weights[i] : 1.0;
    Q[i] = {w * control_points[i].x, w * control_points[i].y, w * control_points[i].z, w};
  }
  std::vector<detail::Hpoint> left(n + 1), right(n + 1);
  left[0] = Q[0];
  right[n] = Q[n];
  // Level k overwrites Q[0 .. n-k]; its first and last entries are polygon points of the halves.
  for (std::size_t k = 1; k <= n; ++k) {
    for (std::size_t i = 0; i + k <= n; ++i) Q[i] = detail::combine(1.0 - t, Q[i], t, Q[i + 1]);
    left[k] = Q[0];
    right[n - k] = Q[n - k];
  }
  DeCasteljauResult result;
  const auto project = [](const detail::Hpoint& h) { return Vec3{h[0] / h[3], h[1] / h[3], h[2] / h[3]}; };
  result.point = project(Q[0]);
  result.left.resize(n + 1);
  result.right.resize(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    result.left[i] = project(left[i]);
    result.right[i] = project(right[i]);
  }
  // Pin the shared ends exactly.
  result.left[n] = result.point;
  result.right[0] = result.point;
  result.left[0] = control_points[0];
  result.right[n] = control_points[n];
  if (rational) {
    result.left_weights.resize(n + 1);
    result.right_weights.resize(n + 1);
    for (std::size_t i = 0; i <= n; ++i) {
      result.left_weights[i] = left[i][3];
      result.right_weights[i] = right[i][3];
    }
  }
  return result;
}

Vec3 evaluate_bernstein(std::span<const Vec3> control_points, std::span<const double> weights, double t) {
  check_inputs(control_points, weights, t);
  const int n = static_cast<int>(control_points.size()) - 1;
  std::array<double, kMaxDegree + 1> B{};
  bernstein_all(n, t, std::span<double>(B.data(), control_points.size()));
  Vec3 sum;
  double wsum = 0.0;
  for (std::size_t i = 0; i < control_points.size(); ++i) {
    const double bw = B[i] * (weights.empty() ? 1.0 : weights[i]);
    sum += bw * control_points[i];
    wsum += bw;
  }
  return weights.empty() ? sum : sum / wsum;
}

}  // namespace hula::nurbs
