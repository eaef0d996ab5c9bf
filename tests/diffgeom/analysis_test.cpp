// SPDX-License-Identifier: MIT
// Unit tests of diffgeom::analyse_curve: the features of the conformance
// corpus's named curves against closed forms (inflections of a planar cubic,
// the curvature maxima of y = x³, a circle's and a helix's constant κ, the
// extrema of the natural curve κ(s) = sin s), the knots of the kinds that
// have them, the fins at the samples against diffgeom::fins, and the feature
// lists of seeded random curves from two generators.
#include "hula/diffgeom/analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

AnalysisOptions with_features(int samples = 50) {
  AnalysisOptions o;
  o.samples = samples;
  o.features = true;
  return o;
}

// checks the planar cubic Bézier (0,0), (1,1), (2,−1), (3,0): x' = 3, y'' = 6(6t − 3), so r' × r'' = 0
// at t = 1/2 only: one inflection there, found about the plane the analysis finds (+Z)
TEST(AnalyseCurve, PlanarCubicHasItsOneInflection) {
  const curve::Curve c = curve::Curve::bezier(
      {.control_points = {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0}}, .weights = {}, .dimension = 2});
  const CurveAnalysis a = analyse_curve(c, with_features());
  ASSERT_TRUE(a.planarity.planar);
  ASSERT_TRUE(a.planarity.normal.has_value());
  EXPECT_EQ(*a.planarity.normal, (Vec3{0, 0, 1}));
  ASSERT_EQ(a.features->inflections.size(), 1u);
  EXPECT_NEAR(a.features->inflections[0].t, 0.5, 1e-12);
  EXPECT_TRUE(a.features->knots.empty());  // a Bézier curve has no interior knot
}

// checks y = x³ on [−1, 1] (a law): κ = 6|t| / (1 + 9t⁴)^{3/2} vanishes at 0 (the inflection) and has its
// maxima where 45 t⁴ = 1; κ = 0 is an inflection, not a curvature minimum
TEST(AnalyseCurve, LawWithZeroCurvatureHasInflectionAndTwoMaxima) {
  const curve::Curve c = curve::Curve::from_law("vec(t, t^3, 0)", "t", {-1.0, 1.0});
  const CurveAnalysis a = analyse_curve(c, with_features());
  ASSERT_TRUE(a.planarity.planar);
  ASSERT_EQ(a.features->inflections.size(), 1u);
  EXPECT_NEAR(a.features->inflections[0].t, 0.0, 1e-12);
  const double t_max = std::pow(45.0, -0.25);
  ASSERT_EQ(a.features->curvature_extrema.size(), 2u);
  EXPECT_EQ(a.features->curvature_extrema[0].kind, FeatureKind::CurvatureMaximum);
  EXPECT_EQ(a.features->curvature_extrema[1].kind, FeatureKind::CurvatureMaximum);
  EXPECT_NEAR(a.features->curvature_extrema[0].t, -t_max, 1e-9);
  EXPECT_NEAR(a.features->curvature_extrema[1].t, t_max, 1e-9);
  const double kmax = 6 * t_max / std::pow(1 + 9 * std::pow(t_max, 4), 1.5);
  EXPECT_NEAR(a.features->maximum_curvature.value, kmax, 1e-12);
  EXPECT_TRUE(a.features->knots.empty());  // a law has no knots, whatever its stand-in NURBS has
  EXPECT_TRUE(a.features->torsion_extrema.empty());
}

// checks a constant-κ helix law vec(cos t, sin t, t/4): κ = 16/17, τ = 4/17 everywhere, so no curvature or
// torsion extremum, no knot and (a space curve) no inflection
TEST(AnalyseCurve, HelixHasNoExtremumNoKnotNoInflection) {
  const curve::Curve c = curve::Curve::from_law("vec(cos(t), sin(t), t/4)", "t", {0.0, 4 * std::numbers::pi});
  const CurveAnalysis a = analyse_curve(c, with_features(200));
  EXPECT_FALSE(a.planarity.planar);
  for (const FrenetPoint& p : a.samples) {
    EXPECT_NEAR(p.curvature, 16.0 / 17.0, 1e-12);
    EXPECT_NEAR(p.torsion, 4.0 / 17.0, 1e-12);
  }
  EXPECT_TRUE(a.features->inflections.empty());
  EXPECT_TRUE(a.features->curvature_extrema.empty());
  EXPECT_TRUE(a.features->torsion_extrema.empty());
  EXPECT_TRUE(a.features->knots.empty());
  EXPECT_TRUE(a.features->monotonicity.monotone());
  EXPECT_NEAR(a.features->maximum_curvature.value, 16.0 / 17.0, 1e-12);
}

// checks the rational circle of radius 3 (four quadratic arcs, double knots): κ = 1/3 to rounding gives no
// curvature extremum, no inflection; its knots are reported (C1, G2: κ is continuous across the joins)
TEST(AnalyseCurve, CircleHasNoCurvatureExtremumAndItsKnots) {
  const curve::Curve c = testing::rational_circle(3.0);
  const CurveAnalysis a = analyse_curve(c, with_features());
  ASSERT_TRUE(a.planarity.planar);
  EXPECT_TRUE(a.features->inflections.empty());
  EXPECT_TRUE(a.features->curvature_extrema.empty());
  ASSERT_EQ(a.features->knots.size(), 3u);
  for (const Continuity& k : a.features->knots) {
    EXPECT_EQ(k.multiplicity, 2);
    EXPECT_GE(k.geometric, 2);
  }
  EXPECT_NEAR(a.features->maximum_curvature.value, 1.0 / 3.0, 1e-12);
}

// checks the natural curve κ(s) = sin s, τ = 0 on [0, 2π]: the inflection at s = π, and |κ| maxima at π/2
// and 3π/2 (the minimum of |κ| at π is the inflection), all from the natural equations
TEST(AnalyseCurve, NaturalCurveFeaturesFromItsEquations) {
  curve::NaturalData d;
  d.curvature = "sin(s)";
  d.length = 2 * std::numbers::pi;
  const curve::Curve c = intrinsic::natural_curve(d, 1e-7);
  const CurveAnalysis a = analyse_curve(c, with_features());
  ASSERT_TRUE(a.planarity.planar);
  ASSERT_EQ(a.features->inflections.size(), 1u);
  EXPECT_NEAR(a.features->inflections[0].t, std::numbers::pi, 1e-9);
  ASSERT_EQ(a.features->curvature_extrema.size(), 2u);
  EXPECT_NEAR(a.features->curvature_extrema[0].t, std::numbers::pi / 2, 1e-7);
  EXPECT_NEAR(a.features->curvature_extrema[1].t, 3 * std::numbers::pi / 2, 1e-7);
  for (const Feature& f : a.features->curvature_extrema) {
    EXPECT_EQ(f.kind, FeatureKind::CurvatureMaximum);
    EXPECT_NEAR(f.curvature, 1.0, 1e-12);
  }
  EXPECT_TRUE(a.features->knots.empty());
}

// checks the space Bézier of issue 22 (a curve out of any plane): no inflection is reported, where the old
// rule (the sign of κ about +Z on every curve) found one near t = 0.3266
TEST(AnalyseCurve, SpaceBezierHasNoInflection) {
  const curve::Curve c = curve::Curve::bezier(
      {.control_points = {{-155.86, 108.91, 0}, {-20, 60, 0}, {-4.14, 88.22, 0}, {85.52, 0, 115.21}},
       .weights = {},
       .dimension = 3});
  const CurveAnalysis a = analyse_curve(c, with_features());
  EXPECT_FALSE(a.planarity.planar);
  EXPECT_TRUE(a.features->inflections.empty());
  const std::vector<Feature> about_z = inflections(c.nurbs());
  ASSERT_EQ(about_z.size(), 1u);  // what the sign about +Z says: a sign change that is no inflection
  EXPECT_NEAR(about_z[0].t, 0.3266, 1e-4);
  EXPECT_GT(frenet(c.nurbs(), about_z[0].t).curvature, 1e-3);  // κ ≈ 0.0045 there: no inflection
}

// checks that fins standing at the samples (parameter grid, as many fins as samples) equal diffgeom::fins of
// the curve on the same grid bit for bit, and that the automatic scale makes the longest curvature fin a fifth
// of the box diagonal (an open curve turning less than two turns, box not thin)
TEST(AnalyseCurve, FinsAtTheSamplesAndTheAutomaticScale) {
  const curve::Curve c = curve::Curve::bezier(
      {.control_points = {{0, 0, 0}, {1, 2, 0.5}, {3, 3, 1}, {4, 1, 2}}, .weights = {}, .dimension = 3});
  AnalysisOptions o;
  o.samples = 64;
  o.fins = {FinKind::Curvature, FinKind::Torsion};
  const CurveAnalysis a = analyse_curve(c, o);
  ASSERT_EQ(a.fins.size(), 2u);
  for (const AnalysedFins& comb : a.fins) {
    FinOptions f;
    f.kind = comb.kind;
    f.scale = comb.scale;
    f.density = 64;
    const Fins expected = fins(c, f);
    ASSERT_EQ(comb.fins.t, expected.t);
    for (std::size_t i = 0; i < expected.t.size(); ++i) {
      EXPECT_EQ(comb.fins.base[i], expected.base[i]);
      if (expected.defined[i]) {
        EXPECT_EQ(comb.fins.tip[i], expected.tip[i]);
      }
    }
  }
  Box3 box;
  double longest = 0.0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    box.add(a.samples[i].position);
    longest = std::max(longest, norm(a.fins[0].fins.tip[i] - a.fins[0].fins.base[i]));
  }
  EXPECT_NEAR(longest, 0.2 * box.diagonal(), 1e-12 * box.diagonal());
}

// checks on seeded random curves of two generators (random NURBS, cubic splines through random points) that
// every feature list is strictly increasing in t (no extremum reported twice) and the extrema alternate
TEST(AnalyseCurve, FeatureListsOfRandomCurvesAreStrictlyIncreasing) {
  Rng rng(20260207);
  for (int k = 0; k < 24; ++k) {
    curve::Curve c = testing::random_curve(rng, {});
    if (k % 2 == 1) {
      std::vector<Vec3> points;
      for (int i = 0; i < 8; ++i)
        points.push_back({rng.uniform(-10, 10), rng.uniform(-10, 10), k % 4 == 1 ? 0.0 : rng.uniform(-10, 10)});
      c = nurbs::interpolate_cubic(points);
    }
    const CurveAnalysis a = analyse_curve(c, with_features(20));
    for (const auto* list : {&a.features->inflections, &a.features->curvature_extrema, &a.features->torsion_extrema})
      for (std::size_t i = 1; i < list->size(); ++i)
        EXPECT_LT((*list)[i - 1].t, (*list)[i].t) << "curve " << k << ", feature " << i;
  }
}

// checks the options' validation names the field
TEST(AnalyseCurve, RefusesBadOptionsNamingTheField) {
  const curve::Curve c = testing::rational_circle(1.0);
  AnalysisOptions o;
  o.samples = 0;
  EXPECT_THROW((void)analyse_curve(c, o), Error);
  o = {};
  o.fin_density = 1;
  try {
    (void)analyse_curve(c, o);
    FAIL() << "fin_density = 1 accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "fin_density");
  }
  o = {};
  o.by = SampleBy::ArcLength;
  o.at = {0.0, 100.0};
  try {
    (void)analyse_curve(c, o);
    FAIL() << "s = 100 accepted on a circle of length 2π";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::OutOfDomain);
    EXPECT_EQ(e.where().field, "s");
    EXPECT_EQ(e.where().index, 1u);
  }
}

}  // namespace
}  // namespace hula::diffgeom
