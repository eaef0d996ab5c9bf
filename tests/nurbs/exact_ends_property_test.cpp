// SPDX-License-Identifier: MIT
// Property tests (label `property`) of exact ends (issue 10, item 9): a clamped curve evaluates
// to its first and last control points exactly (==, not within a tolerance) at the domain ends,
// a knot of multiplicity p gives its control point exactly, and an interpolating spline gives its
// first and last data points exactly — what the maths says (one basis function equals 1 there),
// checked against the control points and data points themselves.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks (issue 10 defect): this clamped cubic gave C(0) = P0 + 7.1e-15 through the span
// polynomial; it must return P0 and Pn bit for bit, in the single and the batch evaluators.
TEST(ExactEnds, ClampedCurveReturnsItsEndControlPointsBitForBit) {
  const std::vector<Vec3> P = {{0.1, 0.7, -0.3}, {1.3, 2.9, 0.7}, {2.2, -1.1, 0.4}, {3.7, 0.3, 2.9}, {4.1, 1.7, -0.6}};
  const NurbsCurve c(3, {0.3, 0.3, 0.3, 0.3, 0.77, 1.9, 1.9, 1.9, 1.9}, P);
  EXPECT_EQ(c.evaluate(0.3), P.front());
  EXPECT_EQ(c.evaluate(1.9), P.back());
  const std::vector<double> ts = {0.3, 1.0, 1.9};
  std::vector<Vec3> out(3);
  c.evaluate(ts, out);
  EXPECT_EQ(out[0], P.front());
  EXPECT_EQ(out[2], P.back());
  EXPECT_EQ(c.evaluate(-5.0, {.domain = Domain::Clamp}), P.front());  // clamped to the end: exact too
}

// checks: random clamped curves (degree 1-12, so the direct path above degree 9 too, rational or
// not) return P0 and Pn exactly at their domain ends, in single and batch evaluation.
RC_GTEST_PROP(ExactEndsProperty, ClampedEndsAreEndControlPoints, ()) {
  Rng rng(*rc::gen::arbitrary<std::uint64_t>());
  testing::RandomCurveSpec spec;
  spec.degree = *rc::gen::inRange(1, 13);
  spec.rational = *rc::gen::arbitrary<bool>();
  spec.clamped = true;
  const NurbsCurve c = testing::random_curve(rng, spec);
  const auto P = c.control_points();
  const Interval d = c.domain();
  RC_ASSERT(c.evaluate(d.start) == P.front());
  RC_ASSERT(c.evaluate(d.end) == P.back());
  const std::vector<double> ts = {d.end, d.start};
  std::vector<Vec3> out(2 * 3);
  c.derivatives(ts, 2, out);
  RC_ASSERT(out[0] == P.back());
  RC_ASSERT(out[3] == P.front());
}

// checks: after inserting an interior knot u to multiplicity p, C(u) is the control point
// P[k − 1] (k = index of u's first copy) exactly, as the partition of unity says.
RC_GTEST_PROP(ExactEndsProperty, KnotOfMultiplicityDegreeIsItsControlPoint, ()) {
  const NurbsCurve c0 = testing::arbitrary_curve(5);
  const Interval d = c0.domain();
  const double u = d.start + d.length() * *rc::gen::inRange(1, 1000) / 1000.0;
  const int room = c0.degree() - c0.knots().multiplicity(u);
  RC_PRE(room >= 1);
  const NurbsCurve c = insert_knot(c0, u, room);
  const auto U = c.knots().values();
  std::size_t k = 0;
  while (U[k] < u) ++k;
  RC_ASSERT(c.evaluate(u) == c.control_points()[k - 1]);
}

// checks: the interpolating cubic spline returns its first and last data points exactly at t = 0
// and t = 1 (P0 = Q0 and Pn = Q_{N−1} by construction), for every end condition.
RC_GTEST_PROP(ExactEndsProperty, InterpolantEndsAreDataEnds, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(2, 30);
  Rng rng(*rc::gen::arbitrary<std::uint64_t>());
  std::vector<Vec3> q(n);
  for (std::size_t i = 0; i < n; ++i)
    q[i] = Vec3{static_cast<double>(i) + rng.uniform(0.1, 0.9), rng.uniform(-50, 50), rng.uniform(-1e3, 1e3)};
  const auto kind = *rc::gen::inRange(0, 5);
  const EndCondition ends[] = {EndCondition::natural(), EndCondition::bessel(), EndCondition::not_a_knot(),
                               EndCondition::occt(), EndCondition::direction({1, 2, 3})};
  const NurbsCurve c = interpolate_cubic(q, {.start = ends[kind], .end = ends[kind]});
  RC_ASSERT(c.evaluate(0.0) == q.front());
  RC_ASSERT(c.evaluate(1.0) == q.back());
}

}  // namespace
}  // namespace hula::nurbs
