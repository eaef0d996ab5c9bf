// SPDX-License-Identifier: MIT
// Arc length against closed forms (straight line, rational circle, half
// quarter-arc) and an independent reference (Boost.Math's adaptive
// Gauss–Kronrod-61 on a hand-written Bézier hodograph); parameter_at_length
// inverts arc_length; documented errors.
#include "hula/nurbs/arc_length.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numbers>
#include <vector>

#include "hula/testing/counting_allocator.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

const std::vector<Vec3> kBezier = {{0, 0, 0}, {1, 3, 0}, {4, -2, 0}, {5, 1, 0}};

// Independent speed of the cubic Bézier kBezier: |3 Σ (P_{i+1} - P_i) B_{i,2}(t)|.
double bezier_speed(double t) {
  const double b[3] = {(1 - t) * (1 - t), 2 * t * (1 - t), t * t};
  double x = 0, y = 0;
  for (int i = 0; i < 3; ++i) {
    x += 3 * (kBezier[i + 1].x - kBezier[i].x) * b[i];
    y += 3 * (kBezier[i + 1].y - kBezier[i].y) * b[i];
  }
  return std::hypot(x, y);
}

// checks: a cubic with collinear, unevenly spaced control points has length |P3 - P0| (closed form).
TEST(ArcLength, StraightLine) {
  const NurbsCurve c(3, {0, 0, 0, 0, 0.3, 1, 1, 1, 1},
                     {{0, 0, 0}, {0.3, 0.4, 0}, {0.6, 0.8, 0}, {2.7, 3.6, 0}, {3, 4, 0}});
  EXPECT_NEAR(arc_length(c) / 5.0, 1.0, 1e-12);
}

// checks: the four-arc rational quadratic circle has length 2πR and its first eighth πR/4 (closed form).
TEST(ArcLength, RationalCircle) {
  for (double R : {1.0, 7.5, 1e-100, 1e100}) {
    const NurbsCurve c = testing::rational_circle(R);
    EXPECT_NEAR(arc_length(c) / (2 * std::numbers::pi * R), 1.0, 1e-12) << R;
    EXPECT_NEAR(arc_length(c, 0.0, 0.125) / (std::numbers::pi * R / 4), 1.0, 1e-12) << R;
    EXPECT_NEAR(arc_length(c, 0.1, 0.6) + arc_length(c, 0.6, 1.0), arc_length(c, 0.1, 1.0), 1e-12 * R) << R;
  }
}

// checks: a planar cubic Bézier against Boost.Math gauss_kronrod<61> of an independently coded hodograph.
TEST(ArcLength, CubicBezierAgainstBoost) {
  const NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, kBezier);
  double err = 0;
  const double reference =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(bezier_speed, 0.0, 1.0, 12, 1e-14, &err);
  ASSERT_LT(err, 1e-13 * reference);
  EXPECT_NEAR(arc_length(c) / reference, 1.0, 1e-12);
  const double part =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(bezier_speed, 0.2, 0.7, 12, 1e-14, &err);
  EXPECT_NEAR(arc_length(c, 0.2, 0.7) / part, 1.0, 1e-12);
  EXPECT_NEAR(arc_length(c, {.tolerance = 1e-6}) / reference, 1.0, 1e-6);
}

// checks: parameter_at_length inverts arc_length to 1e-10 (both directions) on the Bézier and the circle.
TEST(ArcLength, ParameterAtLengthInverts) {
  for (const NurbsCurve& c : {NurbsCurve(3, {0, 0, 0, 0, 1, 1, 1, 1}, kBezier), testing::rational_circle(3.0)}) {
    const double L = arc_length(c);
    for (int i = 0; i <= 40; ++i) {
      const double s = L * i / 40.0;
      const double t = parameter_at_length(c, s);
      EXPECT_NEAR(arc_length(c, 0.0, t), s, 1e-10 * L) << "s = " << s;
      const double t2 = (i + 0.5) / 41.0;
      EXPECT_NEAR(parameter_at_length(c, arc_length(c, 0.0, t2)), t2, 1e-10) << "t = " << t2;
    }
  }
  EXPECT_NEAR(parameter_at_length(testing::rational_circle(2.0), std::numbers::pi / 2), 0.125, 1e-12);
}

// checks: documented errors carry their code and name the offending value.
TEST(ArcLength, ErrorsNameTheInput) {
  const NurbsCurve c = testing::rational_circle(1.0);
  HULA_EXPECT_ERROR(parameter_at_length(c, -0.5), Errc::OutOfDomain, "s = -0.5");
  HULA_EXPECT_ERROR(parameter_at_length(c, 7.0), Errc::OutOfDomain, "s = 7");
  HULA_EXPECT_ERROR(parameter_at_length(c, NAN), Errc::NonFiniteInput, "s = nan");
  HULA_EXPECT_ERROR(arc_length(c, 0.5, 0.25), Errc::InvalidArgument, "a = 0.5");
  HULA_EXPECT_ERROR(arc_length(c, -1.0, 0.25), Errc::OutOfDomain, "a = -1");
  HULA_EXPECT_ERROR(arc_length(c, 0.0, 1.5), Errc::OutOfDomain, "b = 1.5");
  HULA_EXPECT_ERROR(arc_length(c, {.tolerance = 0.0}), Errc::InvalidOption, "options.tolerance = 0");
  HULA_EXPECT_ERROR(arc_length(c, {.tolerance = 0.5}), Errc::InvalidOption, "options.tolerance = 0.5");
  // A speed beyond double range (1e300 coordinates on a 1e-20 domain) is reported, not integrated.
  const NurbsCurve huge(1, {0, 0, 1e-20, 1e-20}, {{0, 0, 0}, {1e300, 0, 0}});
  HULA_EXPECT_ERROR(arc_length(huge), Errc::NumericalFailure, "overflow");
  EXPECT_EQ(parameter_at_length(c, 0.0), 0.0);
  EXPECT_NEAR(parameter_at_length(c, arc_length(c)), 1.0, 1e-12);
}

// checks: the integration loop does not allocate per evaluation: a 1e-6 and a 1e-14 run (many more
// speed evaluations) make the same number of allocations (counting allocator).
TEST(ArcLength, IntegrationLoopIsAllocationFree) {
  const NurbsCurve c(3, {0, 0, 0, 0, 0.2, 0.7, 1, 1, 1, 1},
                     {{0, 0, 0}, {1, 3, 0}, {4, -2, 1}, {5, 1, 0}, {7, 7, 2}, {8, 0, 0}});
  (void)arc_length(c);  // builds the evaluation cache
  const auto count = [&](double tolerance) {
    const long before = testing::allocation_count();
    (void)arc_length(c, {.tolerance = tolerance});
    return testing::allocation_count() - before;
  };
  EXPECT_GT(count(1e-6), 0);  // the counter is live
  EXPECT_EQ(count(1e-6), count(1e-14));
  const auto count_inverse = [&](double s) {
    const long before = testing::allocation_count();
    (void)parameter_at_length(c, s);
    return testing::allocation_count() - before;
  };
  EXPECT_EQ(count_inverse(1.0), count_inverse(7.0));
}

}  // namespace
}  // namespace hula::nurbs
