// SPDX-License-Identifier: MIT
// Degree elevation: a line and a circle by hand / closed form, and shape
// invariance on seeded random curves elevated once and twice (property).
#include "hula/nurbs/elevate.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

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

// checks: the rational quadratic circle elevated to degree 3 and 4 keeps radius R (closed form) and knot multiplicities +t.
TEST(Elevate, CircleStaysCircle) {
  const double w = std::sqrt(0.5);
  const double R = 2.5;
  const NurbsCurve c(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                     {{R, 0, 0}, {R, R, 0}, {0, R, 0}, {-R, R, 0}, {-R, 0, 0}, {-R, -R, 0}, {0, -R, 0}, {R, -R, 0},
                      {R, 0, 0}},
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

// checks: elevation by 1 and 2 leaves random curves (degrees 1–5, rational or not) unchanged to 1e-12 × model size.
RC_GTEST_PROP(ElevateProperty, ElevationKeepsShape, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const int times = *rc::gen::inRange(1, 3);
  const NurbsCurve e = elevate_degree(c, times);
  RC_ASSERT(e.degree() == c.degree() + times);
  RC_ASSERT(e.domain().start == c.domain().start);
  RC_ASSERT(e.domain().end == c.domain().end);
  RC_ASSERT(e.is_rational() == c.is_rational());
  for (const double u : c.knots().breakpoints())
    if (u != c.domain().start && u != c.domain().end)
      RC_ASSERT(e.knots().multiplicity(u) == c.knots().multiplicity(u) + times);
  RC_ASSERT(testing::max_deviation(c, e) <= 1e-12 * c.model_size());
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
