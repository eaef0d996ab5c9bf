// SPDX-License-Identifier: MIT
// Tight bounding box: circle (also rotated, extrema inside spans) and a
// parabola against closed forms. Random-curve containment:
// bounding_box_property_test.cpp.
#include "hula/nurbs/bounding_box.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: a circle of radius R at the origin (axis-aligned and rotated by 0.3 rad) gives [-R, R]² × {0} (closed form).
TEST(BoundingBox, CircleIsSquare) {
  for (double R : {1.0, 12.5}) {
    for (double angle : {0.0, 0.3}) {
      const Box3 b = bounding_box(testing::rational_circle(R, angle));
      EXPECT_NEAR(b.min.x, -R, 1e-12 * R) << angle;
      EXPECT_NEAR(b.min.y, -R, 1e-12 * R) << angle;
      EXPECT_NEAR(b.max.x, R, 1e-12 * R) << angle;
      EXPECT_NEAR(b.max.y, R, 1e-12 * R) << angle;
      EXPECT_EQ(b.min.z, 0.0);
      EXPECT_EQ(b.max.z, 0.0);
    }
  }
}

// checks: the parabola with control points (0,0), (1,2), (2,0) peaks at y = 1 (closed form), not at the hull's 2.
TEST(BoundingBox, ParabolaInteriorExtremum) {
  const Box3 b = bounding_box(NurbsCurve(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}}));
  EXPECT_EQ(b.min.x, 0.0);
  EXPECT_EQ(b.max.x, 2.0);
  EXPECT_EQ(b.min.y, 0.0);
  EXPECT_NEAR(b.max.y, 1.0, 1e-15);
}

}  // namespace
}  // namespace hula::nurbs
