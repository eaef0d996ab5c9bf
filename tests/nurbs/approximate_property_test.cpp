// SPDX-License-Identifier: MIT
// Property tests (RapidCheck) for least-squares approximation: the reported
// maximum deviation is the recomputed maximum, the ends are fixed, and the
// fit is a least-squares optimum (perturbing an interior control point never
// lowers the sum of squared residuals).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/nurbs/approximate.hpp"

namespace hula::nurbs {
namespace {

std::vector<Vec3> gen_curve_points(std::size_t n) {
  std::vector<Vec3> p(n);
  const double a = *rc::gen::inRange(1, 40) / 10.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / static_cast<double>(n - 1);
    p[i] = {std::cos(a * u) + *rc::gen::inRange(-100, 101) * 1e-4, std::sin(a * u), u};
  }
  return p;
}

double sum_of_squares(const NurbsCurve& c, const std::vector<Vec3>& pts, const std::vector<double>& t) {
  double s = 0.0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const double e = distance(c.evaluate(t[k]), pts[k]);
    s += e * e;
  }
  return s;
}

// property: max_deviation and its index equal the recomputed maximum; P_0 = Q_0 and P_n = Q_m exactly.
RC_GTEST_PROP(ApproximateProperty, ReportsTrueMaximumAndFixesEnds, ()) {
  const auto m = *rc::gen::inRange<std::size_t>(5, 80);
  const auto pts = gen_curve_points(m);
  const int degree = *rc::gen::inRange(1, 6);
  RC_PRE(static_cast<std::size_t>(degree) + 1 <= m);
  const auto ncp = *rc::gen::inRange<std::size_t>(static_cast<std::size_t>(degree) + 1, m + 1);
  const auto rule = static_cast<Parameterisation>(*rc::gen::inRange(0, 3));
  const ApproximationResult r = approximate(pts, {.control_points = ncp, .degree = degree, .parameterisation = rule});
  RC_ASSERT(r.curve.control_points().front() == pts.front());
  RC_ASSERT(r.curve.control_points().back() == pts.back());
  double worst = 0.0;
  std::size_t at = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const double e = distance(r.curve.evaluate(r.parameters[k]), pts[k]);
    if (e > worst) {
      worst = e;
      at = k;
    }
  }
  RC_ASSERT(r.max_deviation == worst);
  RC_ASSERT(r.max_deviation_index == at);
}

// property: the fit minimises the sum of squares: moving one interior control point never lowers it.
RC_GTEST_PROP(ApproximateProperty, IsLeastSquaresOptimum, ()) {
  const auto m = *rc::gen::inRange<std::size_t>(10, 60);
  const auto pts = gen_curve_points(m);
  const auto ncp = *rc::gen::inRange<std::size_t>(5, m / 2 + 1);
  const ApproximationResult r = approximate(pts, {.control_points = ncp});
  const double best = sum_of_squares(r.curve, pts, r.parameters);
  const auto j = *rc::gen::inRange<std::size_t>(1, ncp - 1);
  std::vector<Vec3> P(r.curve.control_points().begin(), r.curve.control_points().end());
  P[j] += Vec3{*rc::gen::inRange(-10, 11) * 1e-3, *rc::gen::inRange(-10, 11) * 1e-3, 1e-3};
  const NurbsCurve moved(r.curve.knots(), P);
  RC_ASSERT(sum_of_squares(moved, pts, r.parameters) >= best * (1 - 1e-12));
}

}  // namespace
}  // namespace hula::nurbs
