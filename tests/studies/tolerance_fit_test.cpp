// SPDX-License-Identifier: MIT
// Tests of studies::fit_within_tolerance against closed forms: exact samples of a cubic Bézier come
// back as that cubic; samples of a circle (no polynomial reproduces it) come back within the
// tolerance with knots only where needed; a closed ellipse gives a periodic curve whose ends meet
// with C^(p−1) continuity; interpolated ends hold the end points exactly; a budget too small for the
// tolerance is an error naming the best deviation reached; and the bad-input contract.
#include "hula/studies/tolerance_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> chord(const std::vector<Vec3>& pts) {
  return nurbs::parameterise(pts, nurbs::Parameterisation::ChordLength);
}

double max_closest(const nurbs::NurbsCurve& c, const std::vector<Vec3>& pts) {
  double worst = 0.0;
  for (const Vec3& q : pts) worst = std::max(worst, nurbs::closest_point(c, q).distance);
  return worst;
}

// Checks: 200 exact points of a planar cubic Bézier are reproduced by a single cubic piece (4 control
// points) whose distance to the Bézier (sampled, closest point on the fit) is below 1e-8 of its size; the
// faired curve keeps the points within the tolerance.
TEST(ToleranceFit, ExactCubicComesBackAsThatCubic) {
  const std::array<Vec3, 4> b{Vec3{0, 0, 0}, Vec3{30, 40, 0}, Vec3{70, -40, 0}, Vec3{100, 0, 0}};
  auto bezier = [&](double u) {
    const double v = 1.0 - u;
    return v * v * v * b[0] + 3 * v * v * u * b[1] + 3 * v * u * u * b[2] + u * u * u * b[3];
  };
  std::vector<Vec3> pts;
  for (int i = 0; i < 200; ++i) pts.push_back(bezier(0.5 - 0.5 * std::cos(kPi * i / 199.0)));
  ToleranceFitOptions o;
  o.tolerance = 1e-3;
  o.degree = 3;
  const ToleranceFit f = fit_within_tolerance(pts, chord(pts), {}, o);
  EXPECT_EQ(f.fit.control_points().size(), 4u);
  EXPECT_TRUE(f.outliers.empty());
  std::vector<Vec3> samples;
  for (int i = 0; i <= 100; ++i) samples.push_back(bezier(i / 100.0));
  EXPECT_LE(max_closest(f.fit, samples), 1e-6);              // 1e-8 of its size: the polish stops at a 0.1 % gain
  EXPECT_LE(max_closest(f.faired, pts), 1e-3 * (1 + 1e-9));  // the fairing may use the tolerance
}

// Checks: a quarter circle of radius 50 (300 exact points) within 1e-4: every point within the
// tolerance by closest point, far fewer control points than points, no outlier.
TEST(ToleranceFit, CircleWithinTolerance) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 300; ++i) {
    const double a = 0.5 * kPi * i / 299.0;
    pts.push_back({50 * std::cos(a), 50 * std::sin(a), 0});
  }
  ToleranceFitOptions o;
  o.tolerance = 1e-4;
  const ToleranceFit f = fit_within_tolerance(pts, chord(pts), {}, o);
  EXPECT_LE(max_closest(f.faired, pts), 1e-4 * (1 + 1e-9));
  EXPECT_LE(f.max_deviation, 1e-4);
  EXPECT_LT(f.faired.control_points().size(), 15u);
  EXPECT_TRUE(f.outliers.empty());
}

// Checks: a closed ellipse (400 exact points, none repeated) gives a curve whose ends coincide and
// whose first and second derivatives agree at the seam (a periodic spline), within the tolerance.
TEST(ToleranceFit, ClosedEllipseIsPeriodic) {
  std::vector<Vec3> pts;
  std::vector<double> t;
  for (int i = 0; i < 400; ++i) {
    const double u = i / 400.0;
    pts.push_back({40 * std::cos(2 * kPi * u), 25 * std::sin(2 * kPi * u), 0});
    t.push_back(u);
  }
  ToleranceFitOptions o;
  o.tolerance = 1e-3;
  o.closed = true;
  const ToleranceFit f = fit_within_tolerance(pts, t, {}, o);
  EXPECT_LE(max_closest(f.faired, pts), 1e-3 * (1 + 1e-9));
  const auto start = f.faired.derivatives(0.0, 2), end = f.faired.derivatives(1.0, 2);
  for (int k = 0; k <= 2; ++k)
    EXPECT_LE(norm(start[static_cast<std::size_t>(k)] - end[static_cast<std::size_t>(k)]),
              1e-7 * std::max(1.0, norm(start[static_cast<std::size_t>(k)])))
        << "derivative " << k;
}

// Checks: with interpolated ends the curve starts and ends exactly at the first and last points.
TEST(ToleranceFit, InterpolatedEndsAreExact) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 80; ++i) {
    const double x = i / 79.0;
    pts.push_back({x * 10, std::sin(3 * x) + 0.001 * std::cos(40 * x), x * x});
  }
  ToleranceFitOptions o;
  o.tolerance = 1e-2;
  o.degree = 3;
  o.min_degree = 3;
  o.ends = FitEnds::Interpolated;
  const ToleranceFit f = fit_within_tolerance(pts, chord(pts), {}, o);
  EXPECT_EQ(f.faired.evaluate(0.0), pts.front());
  EXPECT_EQ(f.faired.evaluate(1.0), pts.back());
  EXPECT_EQ(f.faired.dimension(), 3);
  EXPECT_LE(max_closest(f.faired, pts), 1e-2 * (1 + 1e-9));
}

// Checks: a budget of 5 control points for a wavy curve at 1e-6 is a NumericalFailure that names the
// best deviation reached, the point and the control points it took.
TEST(ToleranceFit, ShortBudgetSaysWhy) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 100; ++i) pts.push_back({i * 0.1, std::sin(i * 0.3), 0});
  ToleranceFitOptions o;
  o.tolerance = 1e-6;
  o.degree = 3;
  o.max_control_points = 5;
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(pts, chord(pts), {}, o)), Errc::NumericalFailure,
                    "the closest (degree 3, 5 control points) leaves point");
}

// Checks the documented bad input: option fields, array sizes, parameters outside [0, 1], non-finite
// points, too few points.
TEST(ToleranceFit, RejectsBadInputNamingIt) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 10; ++i) pts.push_back({static_cast<double>(i), 0, 0});
  const std::vector<double> t = chord(pts);
  ToleranceFitOptions o;
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(pts, t, {}, o)), Errc::InvalidOption, "tolerance");
  o.tolerance = 0.1;
  o.min_degree = 6;
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(pts, t, {}, o)), Errc::InvalidOption, "min_degree");
  o.min_degree = 3;
  o.noise = -1;
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(pts, t, {}, o)), Errc::InvalidOption, "noise");
  o.noise = 0;
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(pts, std::vector<double>(9, 0.5), {}, o)),
                    Errc::InvalidArgument, "9 values for 10 points");
  std::vector<double> bad = t;
  bad[4] = 1.5;
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(pts, bad, {}, o)), Errc::InvalidArgument,
                    "parameter 4 = 1.5");
  std::vector<Vec3> nan_pts = pts;
  nan_pts[7].y = std::nan("");
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(nan_pts, t, {}, o)), Errc::NonFiniteInput, "point 7");
  const std::vector<Vec3> few(pts.begin(), pts.begin() + 3);
  HULA_EXPECT_ERROR(static_cast<void>(fit_within_tolerance(few, chord(few), {}, o)), Errc::TooFewPoints, "got 3");
}

}  // namespace
}  // namespace hula::studies
