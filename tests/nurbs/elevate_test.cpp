// SPDX-License-Identifier: MIT
// Degree elevation: a line and a circle by hand / closed form, and errors;
// degree reduction: elevated curves back, the cubic Bézier closed form, the
// bound on random quartics; rational reduction: an elevated conic back, the
// Euclidean bound on random rational curves, a negative reduced weight refused.
// Shape invariance on random curves: elevate_property_test.cpp.
#include "hula/nurbs/elevate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/core/rng.hpp"
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

// checks: reducing an elevated random cubic gives the cubic back (its knots and control points to 1e-12 of its
// size), the bound at rounding level, on 20 seeded curves with interior knots of random multiplicity.
TEST(ReduceDegree, ElevatedCurveComesBack) {
  Rng rng(26, 3);
  for (int k = 0; k < 20; ++k) {
    testing::RandomCurveSpec spec;
    spec.degree = 2 + k % 3;
    const NurbsCurve c = testing::random_curve(rng, spec);
    const DegreeReductionResult r = reduce_degree(elevate_degree(c, 1), 0.0);
    const double size = c.model_size();
    ASSERT_EQ(r.curve.degree(), c.degree());
    ASSERT_EQ(r.curve.knots().values().size(), c.knots().values().size()) << k;
    for (std::size_t i = 0; i < c.control_points().size(); ++i)
      EXPECT_LE(distance(r.curve.control_points()[i], c.control_points()[i]), 1e-12 * size) << k;
    EXPECT_LE(r.error_bound, 1e-12 * size);
  }
}

// checks the cubic Bézier's reduction against its closed form: Q = (P0, (3P1 − P0)/2, P3), bound |Δ³P|/3 and the
// true largest change 4|Δ³P|/27 (at t = 2/3), measured at 3,001 samples.
TEST(ReduceDegree, CubicBezierClosedForm) {
  const std::vector<Vec3> P{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}};
  const NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, P);
  const Vec3 d3 = P[3] - 3.0 * P[2] + 3.0 * P[1] - P[0];
  const DegreeReductionResult r = reduce_degree(c, 10.0);
  ASSERT_EQ(r.curve.degree(), 2);
  ASSERT_EQ(r.curve.control_points().size(), 3U);
  EXPECT_LE(distance(r.curve.control_points()[1], 0.5 * (3.0 * P[1] - P[0])), 1e-15);
  EXPECT_NEAR(r.bezier_bound, norm(d3) / 3.0, 1e-15);
  double worst = 0.0;
  for (int i = 0; i <= 3000; ++i)
    worst = std::max(worst, distance(c.evaluate(i / 3000.0), r.curve.evaluate(i / 3000.0)));
  EXPECT_NEAR(worst, 4.0 * norm(d3) / 27.0, 1e-9);
  EXPECT_LE(worst, r.error_bound);
}

// checks the bound holds on seeded random quartics (measured at 2,000 samples), with C0 joints healed where the
// tolerance allows, and a tolerance below the reachable bound is refused naming it; degree 1 and a bad tolerance too.
TEST(ReduceDegree, BoundHoldsAndBadInputNamed) {
  Rng rng(27, 3);
  for (int k = 0; k < 10; ++k) {
    testing::RandomCurveSpec spec;
    spec.degree = 4;
    const NurbsCurve c = testing::random_curve(rng, spec);
    const DegreeReductionResult r = reduce_degree(c, 1e3);
    double worst = 0.0;
    const Interval d = c.domain();
    for (int i = 0; i <= 2000; ++i) {
      const double t = d.start + (d.end - d.start) * i / 2000.0;
      worst = std::max(worst, distance(c.evaluate(t), r.curve.evaluate(t)));
    }
    EXPECT_LE(worst, r.error_bound * (1 + 1e-12)) << k;
    EXPECT_LE(r.error_bound, 1e3);
    HULA_EXPECT_ERROR((void)reduce_degree(c, 1e-9 * r.bezier_bound), Errc::NumericalFailure, "tolerance");
  }
  const NurbsCurve line(1, {0, 0, 1, 1}, std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
  HULA_EXPECT_ERROR((void)reduce_degree(line, 1.0), Errc::InvalidDegree, "degree 1");
  HULA_EXPECT_ERROR((void)reduce_degree(line, -1.0), Errc::InvalidArgument, "tolerance");
}

// checks a degree-elevated rational conic reduces back exactly: the circle (four rational quadratic arcs, weights
// 1, √½, 1) elevated once or twice and reduced as often gives its knots, weights and control points to 1e-12, a
// bound at rounding level, and |C(t)| = R at 1,001 samples (the closed form).
TEST(ReduceDegree, ElevatedRationalConicComesBack) {
  for (double R : {1.0, 7.5}) {
    const NurbsCurve circle = testing::rational_circle(R, 0.3);
    for (int times : {1, 2}) {
      NurbsCurve c = elevate_degree(circle, times);
      double bound = 0.0;
      for (int k = 0; k < times; ++k) {
        const DegreeReductionResult r = reduce_degree(c, 0.0);
        bound += r.error_bound;
        c = r.curve;
      }
      ASSERT_EQ(c.degree(), 2);
      ASSERT_TRUE(c.is_rational());
      ASSERT_EQ(c.knots().values().size(), circle.knots().values().size());
      for (std::size_t i = 0; i < c.knots().values().size(); ++i)
        EXPECT_NEAR(c.knots()[i], circle.knots()[i], 1e-15) << i;
      // A rational curve's weights are defined up to one common factor: compare w_i / w_0.
      const double scale = c.weights()[0] / circle.weights()[0];
      for (std::size_t i = 0; i < circle.control_points().size(); ++i) {
        EXPECT_LE(distance(c.control_points()[i], circle.control_points()[i]), 1e-12 * R) << times << " " << i;
        EXPECT_NEAR(c.weights()[i] / scale, circle.weights()[i], 1e-12) << times << " " << i;
      }
      EXPECT_LE(bound, 1e-12 * std::max(1.0, 2 * R));
      for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(norm(c.evaluate(i / 1000.0)), R, 1e-12 * R) << i;
    }
  }
}

// checks the Euclidean bound of a rational reduction holds on seeded random rational quartics and quintics
// (weights in [0.2, 5]): the largest |C_new(t) − C(t)| at 2,001 samples stays within error_bound, or the
// reduction is refused for a non-positive weight (naming the curve) — both outcomes are counted so the test sees
// real reductions.
TEST(ReduceDegree, RationalBoundHoldsOnRandomCurves) {
  Rng rng(26, 4);
  int reduced = 0;
  for (int k = 0; k < 20; ++k) {
    testing::RandomCurveSpec spec;
    spec.degree = 4 + k % 2;
    spec.rational = true;
    const NurbsCurve c = testing::random_curve(rng, spec);
    DegreeReductionResult r{c};
    try {
      r = reduce_degree(c, 1e6);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::NumericalFailure);
      EXPECT_EQ(e.where().field, "curve") << e.what();
      continue;
    }
    ++reduced;
    EXPECT_TRUE(r.curve.is_rational());
    double worst = 0.0;
    const Interval d = c.domain();
    for (int i = 0; i <= 2000; ++i) {
      const double t = d.start + (d.end - d.start) * i / 2000.0;
      worst = std::max(worst, distance(c.evaluate(t), r.curve.evaluate(t)));
    }
    EXPECT_LE(worst, r.error_bound * (1 + 1e-12)) << k;
    EXPECT_GE(r.error_bound, r.bezier_bound);
  }
  EXPECT_GE(reduced, 5);
}

// checks the weight-positivity check: the cubic Bézier with weights 1, 0.1, 1, 1 has the reduced middle weight
// (3 w1 − w0) / 2 = −0.35 < 0 (left inversion, The NURBS Book 5.6), refused as NumericalFailure naming the
// curve and the weight; with weights 1, 2, 2, 1 the reduced weights (1, 2.5, 1) are positive and accepted.
TEST(ReduceDegree, RationalNegativeWeightIsRefused) {
  const std::vector<Vec3> P{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
  const NurbsCurve bad(3, {0, 0, 0, 0, 1, 1, 1, 1}, P, {1, 0.1, 1, 1});
  HULA_EXPECT_ERROR((void)reduce_degree(bad, 1e6), Errc::NumericalFailure, "reduced weight 1 is -0.3499");
  const NurbsCurve good(3, {0, 0, 0, 0, 1, 1, 1, 1}, P, {1, 2, 2, 1});
  const DegreeReductionResult r = reduce_degree(good, 1e6);
  ASSERT_EQ(r.curve.weights().size(), 3U);
  EXPECT_NEAR(r.curve.weights()[1] / r.curve.weights()[0], 2.5, 1e-15);
}

}  // namespace
}  // namespace hula::nurbs
