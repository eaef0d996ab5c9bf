// SPDX-License-Identifier: MIT
// Bézier curves: hand-computed de Casteljau (polynomial and rational) and
// documented errors. Evaluator agreement and subdivision on random curves:
// bezier_property_test.cpp.
#include "hula/nurbs/bezier.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: the quadratic (0,0), (1,2), (2,0) at t = 1/2 gives (1, 1) and halves (0,0),(0.5,1),(1,1) /
// (1,1),(1.5,1),(2,0) by hand.
TEST(Bezier, QuadraticByHand) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}};
  const DeCasteljauResult r = de_casteljau(P, {}, 0.5);
  EXPECT_EQ(r.point, Vec3(1, 1, 0));
  EXPECT_EQ(r.left[1], Vec3(0.5, 1, 0));
  EXPECT_EQ(r.right[1], Vec3(1.5, 1, 0));
  EXPECT_TRUE(r.left_weights.empty());
  // Rational quarter circle (weights 1, √½, 1): the midpoint is at 45°.
  const std::vector<Vec3> Q = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<double> W = {1, std::sqrt(0.5), 1};
  const Vec3 m = de_casteljau(Q, W, 0.5).point;
  EXPECT_NEAR(m.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(m.y, std::sqrt(0.5), 1e-15);
}

// checks: documented errors carry their code and name the offending value or count.
TEST(Bezier, ErrorsNameTheInput) {
  const std::vector<Vec3> one = {{0, 0, 0}};
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}};
  HULA_EXPECT_ERROR(make_bezier(one), Errc::TooFewPoints, "1 point");
  HULA_EXPECT_ERROR(de_casteljau(one, {}, 0.5), Errc::TooFewPoints, "1 point");
  HULA_EXPECT_ERROR(de_casteljau(P, {}, 1.5), Errc::OutOfDomain, "t = 1.5");
  HULA_EXPECT_ERROR(evaluate_bernstein(P, {}, -0.25), Errc::OutOfDomain, "t = -0.25");
  HULA_EXPECT_ERROR(de_casteljau(P, {}, NAN), Errc::NonFiniteInput, "t = nan");
  const std::vector<double> two = {1, 1};
  HULA_EXPECT_ERROR(de_casteljau(P, two, 0.5), Errc::InvalidWeight, "2 weights");
  const std::vector<double> negative = {1, -3, 1};
  HULA_EXPECT_ERROR(evaluate_bernstein(P, negative, 0.5), Errc::InvalidWeight, "weights[1] = -3");
  HULA_EXPECT_ERROR(make_bezier(P, negative), Errc::InvalidWeight, "weights[1] = -3");
  const std::vector<Vec3> many(static_cast<std::size_t>(kMaxDegree) + 2);
  HULA_EXPECT_ERROR(make_bezier(many), Errc::InvalidDegree, "66 control points");
}

}  // namespace
}  // namespace hula::nurbs
