// SPDX-License-Identifier: MIT
// Knot insertion, refinement and Bézier decomposition: The NURBS Book ex. 5.1
// by hand, shape invariance on seeded random curves (property), and errors.
#include "hula/nurbs/refine.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

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
  const NurbsCurve c(2, {0, 0, 0, 1, 2, 3, 3, 3}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}}, {1, 2, 1, 3, 1});
  const NurbsCurve q = insert_knot(c, 1.5, 2);
  EXPECT_LT(distance(q.control_points()[3], c.evaluate(1.5)), 1e-14);
}

// checks: insert_knot leaves random curves unchanged (≤ 1e-12 × model size on 1001 samples) against the original.
RC_GTEST_PROP(RefineProperty, InsertKnotKeepsShape, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const int p = c.degree();
  const Interval d = c.domain();
  const auto breaks = c.knots().breakpoints();
  double u = d.start + d.length() * *rc::gen::inRange(0, 1000) / 1000.0;
  if (*rc::gen::arbitrary<bool>()) u = breaks[*rc::gen::inRange<std::size_t>(0, breaks.size())];
  const int room = p - c.knots().multiplicity(u);
  RC_PRE(room >= 1);
  const int times = *rc::gen::inRange(1, room + 1);
  const NurbsCurve q = insert_knot(c, u, times);
  RC_ASSERT(q.knots().multiplicity(u) == c.knots().multiplicity(u) + times);
  RC_ASSERT(q.control_points().size() == c.control_points().size() + static_cast<std::size_t>(times));
  RC_ASSERT(testing::max_deviation(c, q) <= 1e-12 * c.model_size());
}

// checks: refine_knots with random sorted knots leaves random curves unchanged against the original.
RC_GTEST_PROP(RefineProperty, RefineKnotsKeepsShape, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const int p = c.degree();
  const Interval d = c.domain();
  std::vector<double> X;
  const int count = *rc::gen::inRange(1, 12);
  for (int j = 0; j < count; ++j) {
    const double u = d.start + d.length() * *rc::gen::inRange(0, 64) / 64.0;
    const auto in_x = static_cast<int>(std::count(X.begin(), X.end(), u));
    if (c.knots().multiplicity(u) + in_x < p) X.push_back(u);
  }
  std::sort(X.begin(), X.end());
  const NurbsCurve q = refine_knots(c, X);
  RC_ASSERT(q.control_points().size() == c.control_points().size() + X.size());
  RC_ASSERT(testing::max_deviation(c, q) <= 1e-12 * c.model_size());
}

// checks: refine_knots gives the same curve as repeated insert_knot (control points to 1e-12 × size).
RC_GTEST_PROP(RefineProperty, RefineEqualsRepeatedInsertion, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const Interval d = c.domain();
  const std::vector<double> X = {d.start + 0.25 * d.length(), d.start + 0.5 * d.length(), d.start + 0.75 * d.length()};
  RC_PRE(std::all_of(X.begin(), X.end(), [&](double u) { return c.knots().multiplicity(u) < c.degree(); }));
  const NurbsCurve a = refine_knots(c, X);
  NurbsCurve b = c;
  for (const double u : X) b = insert_knot(b, u);
  RC_ASSERT(a.knots() == b.knots());
  for (std::size_t i = 0; i < a.control_points().size(); ++i)
    RC_ASSERT(distance(a.control_points()[i], b.control_points()[i]) <= 1e-12 * c.model_size());
}

// checks: Bézier segments reproduce the curve on their spans and have Bézier knots, against the original.
RC_GTEST_PROP(RefineProperty, DecomposeReproducesCurve, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const auto segments = decompose_to_bezier(c);
  const auto breaks = c.knots().breakpoints();
  RC_ASSERT(segments.size() + 1 == breaks.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const NurbsCurve& b = segments[s];
    RC_ASSERT(b.control_points().size() == static_cast<std::size_t>(c.degree()) + 1);
    RC_ASSERT(b.domain().start == breaks[s]);
    RC_ASSERT(b.domain().end == breaks[s + 1]);
    RC_ASSERT(b.is_rational() == c.is_rational());
    for (int i = 0; i <= 50; ++i) {
      const double t = i == 50 ? breaks[s + 1] : breaks[s] + (breaks[s + 1] - breaks[s]) * i / 50.0;
      RC_ASSERT(distance(b.evaluate(t), c.evaluate(t, {.side = Side::Left})) <= 1e-12 * c.model_size());
    }
  }
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
