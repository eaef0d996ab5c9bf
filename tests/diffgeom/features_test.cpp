// SPDX-License-Identifier: MIT
// Inflections and curvature extrema (thesis 6.3.1) against exact positions:
// the S-curve (x, x³ − x) has its only inflection at x = 0; the ellipse
// (3 cos t, 1.25 sin t) has curvature maxima at t = π, 2π and minima at π/2, 3π/2.
#include "hula/diffgeom/features.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

// checks the exact inflection of the Bézier S-curve (on a sample) and of the law S-curve (between samples).
TEST(Features, SCurveInflection) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1},
                            {{-1, 0, 0}, {-1.0 / 3, 4.0 / 3, 0}, {1.0 / 3, -4.0 / 3, 0}, {1, 0, 0}}, {}, 2);
  const std::vector<Feature> f = inflections(c);
  ASSERT_EQ(f.size(), 1U);
  EXPECT_EQ(f[0].kind, FeatureKind::Inflection);
  EXPECT_NEAR(f[0].t, 0.5, 1e-14);
  law::Context ctx;
  const nurbs::Interval dom{-1.0, 2.0};
  const LawFrenet s(law::parse("vec(t, t^3 - t)", ctx), "t", dom);
  const std::vector<Feature> g = inflections(s, dom);
  ASSERT_EQ(g.size(), 1U);
  // Between samples the bisection stops at the curvature resolution (κ · size ≤ angular = 1e-10).
  EXPECT_NEAR(g[0].t, 0.0, 1e-10);
  EXPECT_LT(norm(g[0].position), 1e-10);
}

// checks curvature maxima at π, 2π (κ = a/b²) and minima at π/2, 3π/2 (κ = b/a²) of an ellipse.
TEST(Features, EllipseCurvatureExtrema) {
  law::Context ctx;
  const nurbs::Interval dom{0.1, 2 * std::numbers::pi + 0.1};
  const LawFrenet e(law::parse("vec(3*cos(t), 1.25*sin(t))", ctx), "t", dom);
  const std::vector<Feature> f = curvature_extrema(e, dom);
  ASSERT_EQ(f.size(), 4U);
  const double pi = std::numbers::pi;
  const double want[4] = {pi / 2, pi, 3 * pi / 2, 2 * pi};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(f[i].t, want[i], 1e-9);
    EXPECT_EQ(f[i].kind, i % 2 == 0 ? FeatureKind::CurvatureMinimum : FeatureKind::CurvatureMaximum);
    EXPECT_NEAR(f[i].curvature, i % 2 == 0 ? 1.25 / 9.0 : 3.0 / (1.25 * 1.25), 1e-12);
  }
  EXPECT_TRUE(inflections(e, dom).empty());  // convex
}

// checks the twisted cubic (t, t², t³) on [−1, 1] (Bézier by blossoms): τ = 3/(9t⁴ + 9t² + 1) has its only
// extremum, a maximum τ = 3, at t = 0.
TEST(Features, TwistedCubicTorsionMaximum) {
  const nurbs::NurbsCurve c(3, {-1, -1, -1, -1, 1, 1, 1, 1},
                            {{-1, 1, -1}, {-1.0 / 3, -1.0 / 3, 1}, {1.0 / 3, -1.0 / 3, -1}, {1, 1, 1}});
  const std::vector<Feature> f = torsion_extrema(c);
  ASSERT_EQ(f.size(), 1U);
  EXPECT_EQ(f[0].kind, FeatureKind::TorsionMaximum);
  EXPECT_NEAR(f[0].t, 0.0, 1e-12);
  EXPECT_NEAR(f[0].torsion, 3.0, 1e-12);
}

// checks no features on a circle (constant κ: no sign change of dκ/ds, none of κ_s) and a bad option.
TEST(Features, CircleHasNoneAndOptionsValidate) {
  const nurbs::NurbsCurve c = testing::rational_circle(2.0);
  EXPECT_TRUE(inflections(c).empty());
  FeatureOptions o;
  o.samples_per_span = 1;
  EXPECT_THROW((void)curvature_extrema(c, o), Error);
}

}  // namespace
}  // namespace hula::diffgeom
