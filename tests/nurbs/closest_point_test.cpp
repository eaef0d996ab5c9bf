// SPDX-License-Identifier: MIT
// Closest point: points around a circle project radially (closed form), far
// and out-of-plane points, allocation-free Newton, errors. Random-curve
// properties: closest_point_property_test.cpp.
#include "hula/nurbs/closest_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
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

// checks: points off a circle project radially: foot R(cos θ, sin θ), distance |r - R| (closed form).
TEST(ClosestPoint, CircleProjectsRadially) {
  const double R = 4.0;
  const NurbsCurve c = testing::rational_circle(R);
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
  const NurbsCurve c = testing::rational_circle(1.0);
  const ClosestPointResult far = closest_point(c, {0, -1e12, 0});
  EXPECT_LT(distance(far.point, {0, -1, 0}), 1e-9);
  EXPECT_NEAR(far.distance, 1e12 - 1.0, 1e-3);
  const ClosestPointResult above = closest_point(c, {3, 4, 12});
  EXPECT_LT(distance(above.point, {0.6, 0.8, 0}), 1e-9);
  EXPECT_NEAR(above.distance, std::hypot(4.0, 12.0), 1e-12);
}

// checks: documented errors carry their code and name the offending field.
TEST(ClosestPoint, ErrorsNameTheInput) {
  const NurbsCurve c = testing::rational_circle(1.0);
  HULA_EXPECT_ERROR(closest_point(c, {0, NAN, 0}), Errc::NonFiniteInput, "point[1]");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.samples_per_span = 1}), Errc::InvalidOption,
                    "options.samples_per_span = 1");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.max_iterations = 0}), Errc::InvalidOption,
                    "options.max_iterations = 0");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.tolerance = {.resabs = -1.0}}), Errc::InvalidOption, "resabs");
}

// checks: Newton iterations do not allocate: 1 and 50 iterations per start make the same number
// of allocations (counting allocator).
TEST(ClosestPoint, NewtonLoopIsAllocationFree) {
  const NurbsCurve c = testing::rational_circle(2.0);
  (void)closest_point(c, {1, 1, 0});  // builds the evaluation cache
  const auto count = [&](int iterations) {
    const long before = testing::allocation_count();
    (void)closest_point(c, {3, 1, 0.5}, {.max_iterations = iterations});
    return testing::allocation_count() - before;
  };
  EXPECT_EQ(count(1), count(50));
}

}  // namespace
}  // namespace hula::nurbs
