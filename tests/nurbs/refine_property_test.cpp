// SPDX-License-Identifier: MIT
// Property tests (label `property`) of refine.hpp: insertion, refinement and Bézier decomposition leave seeded random
// curves unchanged.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/nurbs/refine.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

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

}  // namespace
}  // namespace hula::nurbs
