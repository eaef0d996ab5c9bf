// SPDX-License-Identifier: MIT
// Inflections and curvature extrema (thesis 6.3.1) against exact positions:
// the S-curve (x, x³ − x) has its only inflection at x = 0; the ellipse
// (3 cos t, 1.25 sin t) has curvature maxima at t = π, 2π and minima at π/2, 3π/2.
#include "hula/diffgeom/features.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
  const curve::Curve s = curve::Curve::from_law("vec(t, t^3 - t)", "t", {-1.0, 2.0});
  const std::vector<Feature> g = inflections(s);
  ASSERT_EQ(g.size(), 1U);
  // Between samples the bisection stops at the curvature resolution (κ · size ≤ angular = 1e-10).
  EXPECT_NEAR(g[0].t, 0.0, 1e-10);
  EXPECT_LT(norm(g[0].position), 1e-10);
}

// checks curvature maxima at π, 2π (κ = a/b²) and minima at π/2, 3π/2 (κ = b/a²) of an ellipse.
TEST(Features, EllipseCurvatureExtrema) {
  const curve::Curve e = curve::Curve::from_law("vec(3*cos(t), 1.25*sin(t))", "t", {0.1, 2 * std::numbers::pi + 0.1});
  const std::vector<Feature> f = curvature_extrema(e);
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

namespace hula::diffgeom {
namespace {

// checks the exact law searches (law::roots / law::extrema on derivative laws, no sampling of the curve) on
// the sine curve (t, sin t): inflections at π, 2π, 3π; κ = |sin t| / (1 + cos² t)^{3/2} has maxima at
// π/2, 3π/2, 5π/2 (κ = 1) and minima at the inflections (κ = 0).
TEST(Features, LawSineInflectionsAndCurvatureExtremaExact) {
  law::Context ctx;
  const law::Law c = law::parse("vec(t, sin(t))", ctx);
  const nurbs::Interval dom{0.5, 9.0};
  const double pi = std::numbers::pi;
  const std::vector<Feature> f = inflections(c, "t", dom);
  ASSERT_EQ(f.size(), 2U);
  EXPECT_NEAR(f[0].t, pi, 1e-12);
  EXPECT_NEAR(f[1].t, 2 * pi, 1e-12);
  EXPECT_EQ(f[0].kind, FeatureKind::Inflection);
  EXPECT_NEAR(f[1].position.y, 0.0, 1e-12);
  const std::vector<Feature> e = curvature_extrema(c, "t", dom);
  const std::vector<double> want = {pi / 2, pi, 3 * pi / 2, 2 * pi, 5 * pi / 2};
  ASSERT_EQ(e.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(e[i].t, want[i], 1e-9) << i;
    EXPECT_EQ(e[i].kind, i % 2 == 0 ? FeatureKind::CurvatureMaximum : FeatureKind::CurvatureMinimum) << i;
    if (i % 2 == 0) {
      EXPECT_NEAR(e[i].curvature, 1.0, 1e-12) << i;
    }
  }
}

// checks torsion and curvature extrema of the twisted cubic (t, t², t³): τ = 3 / (1 + 9t² + 9t⁴) has its
// only maximum at t = 0 (τ = 3), κ = 2 √(1 + 9t² + 9t⁴) / (1 + 4t² + 9t⁴)^{3/2} its maximum at t = 0 (κ = 2).
TEST(Features, LawTwistedCubicTorsionExtremumExact) {
  law::Context ctx;
  const law::Law c = law::parse("vec(t, t^2, t^3)", ctx);
  const nurbs::Interval dom{-1.0, 1.5};
  const std::vector<Feature> tx = torsion_extrema(c, "t", dom);
  ASSERT_EQ(tx.size(), 1U);
  EXPECT_EQ(tx[0].kind, FeatureKind::TorsionMaximum);
  EXPECT_NEAR(tx[0].t, 0.0, 1e-12);
  EXPECT_NEAR(tx[0].torsion, 3.0, 1e-12);
  const std::vector<Feature> kx = curvature_extrema(c, "t", dom);
  ASSERT_GE(kx.size(), 1U);
  const auto it = std::find_if(kx.begin(), kx.end(), [](const Feature& x) { return std::fabs(x.t) < 1e-9; });
  ASSERT_NE(it, kx.end());
  EXPECT_EQ(it->kind, FeatureKind::CurvatureMaximum);
  EXPECT_NEAR(it->curvature, 2.0, 1e-12);
  // A helix has constant torsion: no torsion extremum.
  EXPECT_TRUE(torsion_extrema(law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), "t", {0.0, 10.0}).empty());
}

// checks the errors name the input: a scalar law ("law") and an empty domain ("domain").
TEST(Features, LawErrorsNameTheInput) {
  law::Context ctx;
  try {
    (void)inflections(law::parse("t^2", ctx), "t", {0.0, 1.0});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "law");
  }
  try {
    (void)torsion_extrema(law::parse("vec(t, t^2, t^3)", ctx), "t", {1.0, 1.0});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "domain");
  }
}

}  // namespace
}  // namespace hula::diffgeom
