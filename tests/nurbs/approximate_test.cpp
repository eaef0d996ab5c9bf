// SPDX-License-Identifier: MIT
// Least-squares approximation with fixed end points (The NURBS Book 9.4.1):
// recovery of a B-spline from its own samples, end-point interpolation, the
// reported maximum deviation, knots by averaging (eq. 9.69), and option errors;
// the fit on given parameters and knots; rebuild: curves of the new spline
// space reproduced, the circle's deviation against its closed form.
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

// The full circle of radius R as four rational quadratic arcs (The NURBS Book ex. 7.2), domain [0, 1].
NurbsCurve circle(double R) {
  const double h = std::sqrt(0.5);
  std::vector<Vec3> P{{R, 0, 0},   {R, R, 0},  {0, R, 0},  {-R, R, 0}, {-R, 0, 0},
                      {-R, -R, 0}, {0, -R, 0}, {R, -R, 0}, {R, 0, 0}};
  return NurbsCurve(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, std::move(P), {1, h, 1, h, 1, h, 1, h, 1},
                    2);
}

// checks: curves of the new spline space come back to rounding — seeded random cubic Béziers on [2, 5] rebuilt
// as cubics with 4, 7 and 12 control points, a quadratic as a cubic, a cubic with a knot at 1/2 with 5 and 7
// (uniform knots contain 1/2) — at 1,001 parameters (1e-12 of the size), ends exact, reported deviation at
// rounding level, same domain and dimension.
void expect_same_curve(const NurbsCurve& a, const NurbsCurve& b, const char* what) {
  const double tol = 1e-12 * std::max(1.0, b.model_size());
  const Interval d = b.domain();
  ASSERT_EQ(a.domain().start, d.start) << what;
  ASSERT_EQ(a.domain().end, d.end) << what;
  for (int i = 0; i <= 1000; ++i) {
    const double t = d.start + (d.end - d.start) * i / 1000.0;
    EXPECT_LE(distance(a.evaluate(t), b.evaluate(t)), tol) << what << " t = " << t;
  }
}

TEST(Rebuild, ReproducesCurvesOfItsSplineSpace) {
  Rng rng(26, 11);
  for (int k = 0; k < 4; ++k) {
    std::vector<Vec3> cp(4);
    for (auto& q : cp) q = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
    const NurbsCurve bezier(3, {2, 2, 2, 2, 5, 5, 5, 5}, cp);
    for (std::size_t n : {4u, 7u, 12u}) {
      const RebuildResult r = rebuild(bezier, {.degree = 3, .control_points = n});
      ASSERT_EQ(r.curve.degree(), 3);
      ASSERT_EQ(r.curve.control_points().size(), n);
      EXPECT_FALSE(r.curve.is_rational());
      EXPECT_EQ(r.curve.control_points().front(), cp.front());
      EXPECT_EQ(r.curve.control_points().back(), cp.back());
      EXPECT_EQ(r.samples, std::max<std::size_t>(201, 10 * n));
      EXPECT_LE(r.max_deviation, 1e-12 * bezier.model_size()) << k << " " << n;
      expect_same_curve(r.curve, bezier, "bezier");
    }
  }
  const NurbsCurve quadratic(2, {0, 0, 0, 1, 1, 1}, std::vector<Vec3>{{0, 0, 0}, {1, 2, 0}, {3, 0, 0}}, {}, 2);
  const RebuildResult q = rebuild(quadratic, {.degree = 3, .control_points = 6});
  EXPECT_EQ(q.curve.dimension(), 2);
  expect_same_curve(q.curve, quadratic, "quadratic");
  const NurbsCurve spline(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                          std::vector<Vec3>{{0, 0, 0}, {1, 3, 1}, {2, -1, 0}, {4, 2, -1}, {5, 0, 0}});
  for (std::size_t n : {5u, 7u}) expect_same_curve(rebuild(spline, {.control_points = n}).curve, spline, "spline");
}

// checks the reported deviation against the circle's closed form: the distance of a point X to the circle of
// radius R about the origin is ||X| − R|, so at the deviation samples (1,001, uniform in the new curve's
// parameter) max ||C_new(s_i)| − R| must equal max_deviation (closest-point projection onto the rational original)
// to 1e-9 R; and more control points give a closer curve (12, 20, 40 cubic control points; 2 and 5 in degree).
TEST(Rebuild, CircleDeviationMatchesClosedForm) {
  for (double R : {1.0, 40.0}) {
    const NurbsCurve c = circle(R);
    double previous = std::numeric_limits<double>::infinity();
    for (std::size_t n : {12u, 20u, 40u}) {
      for (int degree : {3, 5}) {
        const RebuildResult r = rebuild(c, {.degree = degree, .control_points = n});
        double worst = 0.0;
        double at = 0.0;
        for (int i = 0; i <= 1000; ++i) {
          const double s = i == 1000 ? 1.0 : i / 1000.0;
          const double e = std::abs(norm(r.curve.evaluate(s)) - R);
          if (e > worst) worst = e, at = s;
        }
        EXPECT_NEAR(r.max_deviation, worst, 1e-9 * R) << R << " " << n << " " << degree;
        EXPECT_NEAR(r.at, at, 1e-12) << R << " " << n << " " << degree;
        EXPECT_GT(r.max_deviation, 1e-9 * R);  // a circle is not a polynomial curve
        if (degree == 3) {
          EXPECT_LT(r.max_deviation, previous);
          previous = r.max_deviation;
        }
      }
    }
    EXPECT_LT(previous, 1e-4 * R);
  }
}

// checks least_squares_fit's errors name the input, and the Schoenberg–Whitney failure (every parameter in one
// knot span) is a NumericalFailure naming the knots; rebuild's options name the field.
TEST(Rebuild, ErrorsNameTheInput) {
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}, {5, 1, 0}};
  const std::vector<double> t{0, 0.2, 0.4, 0.6, 0.8, 1};
  const KnotVector kv = KnotVector::uniform_clamped(4, 2);
  EXPECT_EQ(least_squares_fit(pts, t, kv).control_points().size(), 4U);
  HULA_EXPECT_ERROR((void)least_squares_fit(pts, std::vector<double>{0, 1}, kv), Errc::InvalidArgument,
                    "2 parameters for 6 points");
  HULA_EXPECT_ERROR((void)least_squares_fit(pts, std::vector<double>{0, 0.2, 0.5, 0.4, 0.8, 1}, kv),
                    Errc::InvalidArgument, "parameters[3] = 0.4");
  HULA_EXPECT_ERROR((void)least_squares_fit(pts, std::vector<double>{0, 0.2, 0.4, 0.6, 0.8, 1.5}, kv),
                    Errc::InvalidArgument, "parameters[5] = 1.5");
  HULA_EXPECT_ERROR((void)least_squares_fit(pts, t, KnotVector({0, 1, 2, 3, 4, 5, 6}, 2)), Errc::InvalidArgument,
                    "clamped");
  HULA_EXPECT_ERROR((void)least_squares_fit(pts, t, KnotVector::uniform_clamped(7, 2)), Errc::InvalidArgument,
                    "7 control points");
  std::vector<Vec3> lifted = pts;
  lifted[2].z = 1.0;
  HULA_EXPECT_ERROR((void)least_squares_fit(lifted, t, kv, 2), Errc::InvalidArgument, "points[2] has z = 1");
  HULA_EXPECT_ERROR(
      (void)least_squares_fit(pts, std::vector<double>{0, 0.1, 0.1, 0.2, 0.2, 1}, KnotVector::uniform_clamped(6, 2)),
      Errc::NumericalFailure, "singular");
  const NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, std::vector<Vec3>{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}});
  HULA_EXPECT_ERROR((void)rebuild(c, {.degree = 3, .control_points = 3}), Errc::InvalidOption, "control_points = 3");
  HULA_EXPECT_ERROR((void)rebuild(c, {.degree = 0, .control_points = 5}), Errc::InvalidOption, "degree = 0");
  HULA_EXPECT_ERROR((void)rebuild(c, {.control_points = 9, .samples = 8}), Errc::InvalidOption, "samples = 8");
  HULA_EXPECT_ERROR((void)rebuild(c, {.control_points = 9, .deviation_samples = 1}), Errc::InvalidOption,
                    "deviation_samples = 1");
}

}  // namespace
}  // namespace hula::nurbs
