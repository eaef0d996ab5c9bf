// SPDX-License-Identifier: MIT
// Knot insertion, refinement and Bézier decomposition: The NURBS Book ex. 5.1
// by hand, and errors. Shape invariance on random curves: refine_property_test.cpp.
#include "hula/nurbs/refine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: insert_knot on The NURBS Book ex. 5.1 (p = 3, u = 5/2) against the hand-computed alphas 5/6, 1/2, 1/6.
TEST(Refine, NurbsBookExample51) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 2, 0}, {2, 3, 1}, {4, 3, 0}, {5, 1, 2}, {6, 0, 0}, {7, 2, 1}, {9, 0, 0}};
  const NurbsCurve c(3, {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5}, P);
  const NurbsCurve q = insert_knot(c, 2.5);
  const std::vector<double> expected_knots = {0, 0, 0, 0, 1, 2, 2.5, 3, 4, 5, 5, 5, 5};
  ASSERT_EQ(q.knots().size(), expected_knots.size());
  for (std::size_t i = 0; i < expected_knots.size(); ++i) EXPECT_EQ(q.knots()[i], expected_knots[i]) << i;
  const auto Q = q.control_points();
  ASSERT_EQ(Q.size(), 9u);
  for (std::size_t i = 0; i <= 2; ++i) EXPECT_EQ(Q[i], P[i]);
  const auto near = [](const Vec3& a, const Vec3& b) { return distance(a, b) < 1e-14; };
  EXPECT_TRUE(near(Q[3], 5.0 / 6.0 * P[3] + 1.0 / 6.0 * P[2]));
  EXPECT_TRUE(near(Q[4], 0.5 * P[4] + 0.5 * P[3]));
  EXPECT_TRUE(near(Q[5], 1.0 / 6.0 * P[5] + 5.0 / 6.0 * P[4]));
  for (std::size_t i = 6; i <= 8; ++i) EXPECT_EQ(Q[i], P[i - 1]);
}

// checks: inserting to multiplicity p makes the curve interpolate a control point (C(u) = Q[k-p]) against evaluate.
TEST(Refine, FullMultiplicityInterpolates) {
  const NurbsCurve c(2, {0, 0, 0, 1, 2, 3, 3, 3}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}},
                     {1, 2, 1, 3, 1});
  const NurbsCurve q = insert_knot(c, 1.5, 2);
  EXPECT_LT(distance(q.control_points()[3], c.evaluate(1.5)), 1e-14);
}

// checks: every documented insert/refine error carries its code and names the offending value or index.
TEST(Refine, ErrorsNameTheInput) {
  const NurbsCurve c(2, {0, 0, 0, 0.5, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}});
  HULA_EXPECT_ERROR(insert_knot(c, 1.25), Errc::OutOfDomain, "u = 1.25");
  HULA_EXPECT_ERROR(insert_knot(c, -0.5), Errc::OutOfDomain, "u = -0.5");
  HULA_EXPECT_ERROR(insert_knot(c, NAN), Errc::NonFiniteInput, "u = nan");
  HULA_EXPECT_ERROR(insert_knot(c, 0.5, 2), Errc::InvalidKnots, "u = 0.5 has multiplicity 1");
  HULA_EXPECT_ERROR(insert_knot(c, 0.0), Errc::InvalidKnots, "u = 0 has multiplicity 3");
  HULA_EXPECT_ERROR(insert_knot(c, 0.25, -1), Errc::InvalidArgument, "times = -1");
  const std::vector<double> unsorted = {0.2, 0.1};
  HULA_EXPECT_ERROR(refine_knots(c, unsorted), Errc::InvalidArgument, "knots[1] = 0.1");
  const std::vector<double> outside = {0.2, 3.0};
  HULA_EXPECT_ERROR(refine_knots(c, outside), Errc::OutOfDomain, "knots[1] = 3");
  const std::vector<double> too_many = {0.1, 0.5, 0.5};
  HULA_EXPECT_ERROR(refine_knots(c, too_many), Errc::InvalidKnots, "knots[1] = 0.5");
  const std::vector<double> nan = {NAN};
  HULA_EXPECT_ERROR(refine_knots(c, nan), Errc::NonFiniteInput, "knots[0]");
  EXPECT_EQ(insert_knot(c, 0.25, 0), c);
  EXPECT_EQ(refine_knots(c, {}), c);
}

}  // namespace
}  // namespace hula::nurbs
