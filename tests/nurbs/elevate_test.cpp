// SPDX-License-Identifier: MIT
// Degree elevation: a line and a circle by hand / closed form, and errors;
// degree reduction: elevated curves back, the cubic Bézier closed form, the
// bound on random quartics.
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
// tolerance allows, and a tolerance below the reachable bound is refused naming it; rational and degree 1 too.
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
  HULA_EXPECT_ERROR((void)reduce_degree(testing::rational_circle(1.0), 1.0), Errc::InvalidArgument, "rational");
  const NurbsCurve line(1, {0, 0, 1, 1}, std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
  HULA_EXPECT_ERROR((void)reduce_degree(line, 1.0), Errc::InvalidDegree, "degree 1");
  HULA_EXPECT_ERROR((void)reduce_degree(line, -1.0), Errc::InvalidArgument, "tolerance");
}

}  // namespace
}  // namespace hula::nurbs
