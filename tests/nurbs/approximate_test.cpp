// SPDX-License-Identifier: MIT
// Least-squares approximation with fixed end points (The NURBS Book 9.4.1):
// recovery of a B-spline from its own samples, end-point interpolation, the
// reported maximum deviation, knots by averaging (eq. 9.69), and option errors.
#include "hula/nurbs/approximate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

std::vector<Vec3> noisy_curve_points(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec3> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / static_cast<double>(n - 1);
    p[i] = {std::cos(3 * u) + 0.01 * rng.normal(), std::sin(2 * u) + 0.01 * rng.normal(), u * u};
  }
  return p;
}

// checks: points sampled from a cubic B-spline on the knots the fit chooses are recovered exactly
// (max deviation < 1e-10, same control points), for several sizes and degrees.
TEST(Approximate, RecoversBSplineWithSameKnotStructure) {
  for (int degree : {2, 3, 4}) {
    for (std::size_t m : {20u, 57u}) {
      for (std::size_t ncp : {static_cast<std::size_t>(degree) + 1, std::size_t{8}, std::size_t{15}}) {
        // With uniform data parameters the knots depend only on (m, n, p): fit once to learn them.
        std::vector<Vec3> pts = noisy_curve_points(m, 3);
        const ApproximationOptions opt{
            .control_points = ncp, .degree = degree, .parameterisation = Parameterisation::Uniform};
        const ApproximationResult first = approximate(pts, opt);
        Rng rng(ncp * 31 + m);
        std::vector<Vec3> cp(ncp);
        for (auto& q : cp) q = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
        const NurbsCurve truth(first.curve.knots(), cp);
        truth.evaluate(first.parameters, pts);
        const ApproximationResult fit = approximate(pts, opt);
        EXPECT_LT(fit.max_deviation, 1e-10) << degree << " " << m << " " << ncp;
        ASSERT_EQ(fit.curve.control_points().size(), ncp);
        for (std::size_t i = 0; i < ncp; ++i)
          EXPECT_LT(distance(fit.curve.control_points()[i], cp[i]), 1e-9) << degree << " " << m << " " << i;
      }
    }
  }
}

// checks: the end points are interpolated exactly, the reported maximum deviation and its index equal the
// recomputed maximum of |C(t_k) - Q_k|, and the interior knots follow eq. 9.69.
TEST(Approximate, ReportsMaximumDeviationAndFixesEnds) {
  const auto pts = noisy_curve_points(40, 9);
  for (auto rule : {Parameterisation::ChordLength, Parameterisation::Centripetal, Parameterisation::Uniform}) {
    const ApproximationResult r = approximate(pts, {.control_points = 9, .parameterisation = rule});
    EXPECT_EQ(r.curve.control_points().front(), pts.front());
    EXPECT_EQ(r.curve.control_points().back(), pts.back());
    EXPECT_LE(distance(r.curve.evaluate(0.0), pts.front()), 1e-15);
    EXPECT_LE(distance(r.curve.evaluate(1.0), pts.back()), 1e-15);
    EXPECT_EQ(r.parameters, parameterise(pts, rule));
    double worst = 0.0;
    std::size_t at = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const double e = distance(r.curve.evaluate(r.parameters[k]), pts[k]);
      if (e > worst) worst = e, at = k;
    }
    EXPECT_EQ(r.max_deviation, worst);
    EXPECT_EQ(r.max_deviation_index, at);
    EXPECT_GT(r.max_deviation, 0.0);
    // eq. 9.69: d = (m + 1) / (n - p + 1), U_{p+j} = (1 - α) t_{i-1} + α t_i, i = floor(j d).
    const double d = 40.0 / 6.0;
    for (int j = 1; j <= 5; ++j) {
      const double jd = j * d;
      const auto i = static_cast<std::size_t>(std::floor(jd));
      const double a = jd - static_cast<double>(i);
      EXPECT_DOUBLE_EQ(r.curve.knots()[static_cast<std::size_t>(3 + j)],
                       (1 - a) * r.parameters[i - 1] + a * r.parameters[i]);
    }
  }
}

// checks: more control points lower the residual; as many control points as points interpolates.
TEST(Approximate, MoreControlPointsFitBetterUpToInterpolation) {
  const auto pts = noisy_curve_points(30, 5);
  double previous = HUGE_VAL;
  for (std::size_t n : {4u, 8u, 16u, 30u}) {
    const ApproximationResult r = approximate(pts, {.control_points = n});
    EXPECT_LE(r.max_deviation, previous * (1 + 1e-12)) << n;
    previous = r.max_deviation;
  }
  EXPECT_LT(previous, 1e-10);
}

// checks: a degree-1 fit with 2 control points is the chord; a planar fit stays planar: points in z = 0 fitted in
// 3-D give control points with z = 0 exactly (the least-squares solution of zero data is zero), and fitted in 2-D
// the same x and y.
TEST(Approximate, EdgeCases) {
  const auto pts = noisy_curve_points(10, 2);
  const ApproximationResult line = approximate(pts, {.control_points = 2, .degree = 1});
  EXPECT_EQ(line.curve.control_points()[0], pts.front());
  EXPECT_EQ(line.curve.control_points()[1], pts.back());
  std::vector<Vec3> flat = pts;
  for (auto& p : flat) p.z = 0.0;
  const ApproximationResult r = approximate(flat, {.control_points = 5, .dimension = 2});
  EXPECT_EQ(r.curve.dimension(), 2);
  const ApproximationResult r3 = approximate(flat, {.control_points = 5});
  ASSERT_EQ(r3.curve.control_points().size(), r.curve.control_points().size());
  for (std::size_t i = 0; i < r3.curve.control_points().size(); ++i) {
    EXPECT_EQ(r3.curve.control_points()[i].z, 0.0) << i;
    EXPECT_NEAR(r3.curve.control_points()[i].x, r.curve.control_points()[i].x, 1e-12) << i;
    EXPECT_NEAR(r3.curve.control_points()[i].y, r.curve.control_points()[i].y, 1e-12) << i;
  }
}

// checks: extreme scales fit without NaN and with deviations that scale with the data.
TEST(Approximate, ExtremeScales) {
  const auto base = noisy_curve_points(25, 4);
  const double ref = approximate(base, {.control_points = 7}).max_deviation;
  for (double s : {1e-200, 1e200}) {
    std::vector<Vec3> pts = base;
    for (auto& p : pts) p *= s;
    const ApproximationResult r = approximate(pts, {.control_points = 7});
    EXPECT_TRUE(std::isfinite(r.max_deviation));
    EXPECT_NEAR(r.max_deviation / s, ref, 1e-10 * ref) << s;
  }
}

// checks: option errors name the field and value; data errors as parameterise.
TEST(Approximate, ErrorsNameTheInput) {
  const auto pts = noisy_curve_points(10, 1);
  HULA_EXPECT_ERROR(approximate(pts, {}), Errc::InvalidOption, "control_points = 0");
  HULA_EXPECT_ERROR(approximate(pts, {.control_points = 3, .degree = 3}), Errc::InvalidOption,
                    "control_points = 3 must be at least degree + 1 = 4");
  HULA_EXPECT_ERROR(approximate(pts, {.control_points = 11}), Errc::InvalidOption,
                    "control_points = 11 exceeds the number of points 10");
  HULA_EXPECT_ERROR(approximate(pts, {.control_points = 5, .degree = 0}), Errc::InvalidOption, "degree = 0");
  HULA_EXPECT_ERROR(approximate(pts, {.control_points = 5, .dimension = 1}), Errc::InvalidOption, "dimension = 1");
  HULA_EXPECT_ERROR(approximate(pts, {.control_points = 5, .dimension = 2}), Errc::InvalidArgument, "points[1]");
  const std::vector<Vec3> one{{0, 0, 0}};
  HULA_EXPECT_ERROR(approximate(one, {.control_points = 1, .degree = 0}), Errc::InvalidOption, "degree");
  HULA_EXPECT_ERROR(approximate(one, {.control_points = 2, .degree = 1}), Errc::TooFewPoints, "got 1");
  auto bad = pts;
  bad[4].x = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(approximate(bad, {.control_points = 5}), Errc::NonFiniteInput, "points[4][0]");
  bad = pts;
  bad[6] = bad[5];
  HULA_EXPECT_ERROR(approximate(bad, {.control_points = 5}), Errc::CoincidentPoints, "points[5] and points[6]");
}

}  // namespace
}  // namespace hula::nurbs

namespace hula::nurbs {
namespace {

// checks: approximate_to_tolerance meets each tolerance at the data points (re-measured here
// from the curve, not taken from the result), and one control point fewer misses it (the count
// is the fewest the documented search can stand on), for a range of tolerances.
TEST(ApproximateToTolerance, MeetsToleranceWithFewestControlPoints) {
  const auto pts = noisy_curve_points(200, 77);
  for (double tol : {0.2, 0.05, 0.02}) {
    const ToleranceFitResult r = approximate_to_tolerance(pts, tol);
    const NurbsCurve& c = r.fit.curve;
    double worst = 0.0;
    for (std::size_t i = 0; i < pts.size(); ++i)
      worst = std::max(worst, distance(c.evaluate(r.fit.parameters[i]), pts[i]));
    EXPECT_LE(worst, tol) << tol;
    EXPECT_NEAR(worst, r.fit.max_deviation, 1e-12) << tol;
    const std::size_t n = c.control_points().size();
    if (n > 4) {
      ApproximationOptions o;
      o.control_points = n - 1;
      EXPECT_GT(approximate(pts, o).max_deviation, tol) << tol;
    }
    EXPECT_LT(r.fits, 30U) << tol;  // O(log N) fits, not a scan of all counts
  }
}

// checks: a tolerance that is not positive, or below the rounding of interpolation, is refused.
TEST(ApproximateToTolerance, ErrorsNameTheTolerance) {
  const auto pts = noisy_curve_points(20, 3);
  HULA_EXPECT_ERROR(approximate_to_tolerance(pts, 0.0), Errc::InvalidArgument, "tolerance = 0");
  HULA_EXPECT_ERROR(approximate_to_tolerance(pts, 1e-300), Errc::NumericalFailure, "rounding");
}

}  // namespace
}  // namespace hula::nurbs
