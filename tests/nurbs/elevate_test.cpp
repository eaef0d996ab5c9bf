// SPDX-License-Identifier: MIT
// Degree elevation: a line and a circle by hand / closed form, and errors.
// Shape invariance on random curves: elevate_property_test.cpp.
#include "hula/nurbs/elevate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: a degree-1 segment elevated once has the midpoint as middle control point (Bézier elevation formula).
TEST(Elevate, LineToQuadraticByHand) {
  const NurbsCurve c(1, {0, 0, 1, 1}, {{1, 2, 3}, {5, 6, 7}});
  const NurbsCurve e = elevate_degree(c, 1);
  ASSERT_EQ(e.degree(), 2);
  ASSERT_EQ(e.control_points().size(), 3u);
  EXPECT_LT(distance(e.control_points()[0], {1, 2, 3}), 1e-15);
  EXPECT_LT(distance(e.control_points()[1], {3, 4, 5}), 1e-14);
  EXPECT_LT(distance(e.control_points()[2], {5, 6, 7}), 1e-14);
}

// checks: the rational quadratic circle elevated to degree 3 and 4 keeps radius R (closed form) and knot multiplicities
// +t.
TEST(Elevate, CircleStaysCircle) {
  const double w = std::sqrt(0.5);
  const double R = 2.5;
  const NurbsCurve c(
      2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
      {{R, 0, 0}, {R, R, 0}, {0, R, 0}, {-R, R, 0}, {-R, 0, 0}, {-R, -R, 0}, {0, -R, 0}, {R, -R, 0}, {R, 0, 0}},
      {1, w, 1, w, 1, w, 1, w, 1}, 2);
  for (int times : {1, 2}) {
    const NurbsCurve e = elevate_degree(c, times);
    EXPECT_EQ(e.degree(), 2 + times);
    EXPECT_EQ(e.knots().multiplicity(0.5), 2 + times);
    EXPECT_EQ(e.knots().multiplicity(0.0), 3 + times);
    EXPECT_EQ(e.dimension(), 2);
    for (int i = 0; i <= 400; ++i) EXPECT_NEAR(norm(e.evaluate(i / 400.0)), R, 1e-14 * R);
  }
}

// checks: documented errors name the offending value.
TEST(Elevate, ErrorsNameTheInput) {
  const NurbsCurve c(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}});
  HULA_EXPECT_ERROR(elevate_degree(c, -1), Errc::InvalidArgument, "times = -1");
  HULA_EXPECT_ERROR(elevate_degree(c, kMaxDegree), Errc::InvalidDegree, "times = 64");
  EXPECT_EQ(elevate_degree(c, 0), c);
}

}  // namespace
}  // namespace hula::nurbs
