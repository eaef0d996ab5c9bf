// SPDX-License-Identifier: MIT
// Curvature monotonicity (diffgeom/monotonicity.hpp) on the sine curve against its closed form: the signed
// curvature κ = −sin t / (1 + cos² t)^{3/2} has its extrema at t = π/2 (−1) and 3π/2 (+1) and passes through 0
// at the inflections t = 0, π, 2π.
#include "hula/diffgeom/monotonicity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace hula::diffgeom {
namespace {

// checks: signed (planar) analysis: three pieces split at π/2 and 3π/2 (to 1e-6), decreasing / increasing /
// decreasing with κ = −1, +1 at the cuts; the inflections are not violations.
TEST(CurvatureMonotonicity, SineCurveSigned) {
  const curve::Curve c = curve::Curve::from_law("vec(t, sin(t))", "t", {-0.5, 2 * std::numbers::pi + 0.5});
  const CurvatureMonotonicity m = curvature_monotonicity(c, true);
  EXPECT_FALSE(m.monotone());
  ASSERT_EQ(m.violations.size(), 2u);
  EXPECT_NEAR(m.violations[0].t, std::numbers::pi / 2, 1e-6);
  EXPECT_NEAR(m.violations[1].t, 3 * std::numbers::pi / 2, 1e-6);
  ASSERT_EQ(m.pieces.size(), 3u);
  EXPECT_EQ(m.pieces[0].trend, CurvatureTrend::Decreasing);
  EXPECT_EQ(m.pieces[1].trend, CurvatureTrend::Increasing);
  EXPECT_EQ(m.pieces[2].trend, CurvatureTrend::Decreasing);
  EXPECT_NEAR(m.pieces[1].kappa0, -1.0, 1e-9);
  EXPECT_NEAR(m.pieces[1].kappa1, 1.0, 1e-9);
  EXPECT_EQ(m.pieces.front().t0, -0.5);
  EXPECT_EQ(m.pieces.back().t1, 2 * std::numbers::pi + 0.5);
}

// checks: unsigned analysis (space-curve mode): the minima of |κ| that curvature_extrema reports at the inflections
// (0, π, 2π) are violations too, besides the maxima at π/2 and 3π/2; one piece more than violations.
TEST(CurvatureMonotonicity, SineCurveUnsigned) {
  const curve::Curve c = curve::Curve::from_law("vec(t, sin(t))", "t", {-0.5, 2 * std::numbers::pi + 0.5});
  const CurvatureMonotonicity m = curvature_monotonicity(c, false);
  int maxima = 0, minima = 0;
  for (const Feature& f : m.violations) {
    if (f.kind == FeatureKind::CurvatureMaximum) {
      ++maxima;
      EXPECT_NEAR(std::remainder(f.t - std::numbers::pi / 2, std::numbers::pi), 0.0, 1e-6);
    } else {
      ++minima;
      EXPECT_NEAR(std::remainder(f.t, std::numbers::pi), 0.0, 1e-6);
    }
  }
  EXPECT_EQ(maxima, 2);
  EXPECT_GE(minima, 2);
  EXPECT_EQ(m.pieces.size(), m.violations.size() + 1);
}

// checks: a circular arc is one constant piece (κ = 1/2 at both ends), monotone.
TEST(CurvatureMonotonicity, ArcIsOneConstantPiece) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 2.0});
  const CurvatureMonotonicity m = curvature_monotonicity(c, true);
  EXPECT_TRUE(m.monotone());
  ASSERT_EQ(m.pieces.size(), 1u);
  EXPECT_EQ(m.pieces[0].trend, CurvatureTrend::Constant);
  EXPECT_NEAR(m.pieces[0].kappa0, 0.5, 1e-12);
}

}  // namespace
}  // namespace hula::diffgeom
