// SPDX-License-Identifier: MIT
// Property tests (label `property`) of reparam.hpp: reparameterisation (chain rule), reversal (C' sign) and split keep
// seeded random curves.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

double rel(const Vec3& a, const Vec3& b) { return distance(a, b) / std::max(1.0, std::max(norm(a), norm(b))); }

// checks: reparameterise keeps the points (≤ 1e-12 × size) and scales the k-th derivative by (L/L')^k (chain rule).
RC_GTEST_PROP(ReparamProperty, ReparameteriseKeepsShapeAndChainRule, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const double a = *rc::gen::inRange(-100, 100) / 7.0;
  const double len = *rc::gen::inRange(1, 1000) / 13.0;
  const NurbsCurve r = reparameterise(c, {a, a + len});
  RC_ASSERT(r.domain().start == a);
  RC_ASSERT(r.domain().end == a + len);
  const Interval d = c.domain();
  const double ratio = d.length() / len;
  for (int i = 0; i <= 200; ++i) {
    // Parameters off the knots (i + 0.5), so one-sided limits do not matter.
    const double x = (i + 0.37) / 201.0;
    const double t = d.start + d.length() * x;
    const double tr = a + len * x;
    const auto dc = c.derivatives(t, 2);
    const auto dr = r.derivatives(tr, 2);
    RC_ASSERT(distance(dc[0], dr[0]) <= 1e-12 * c.model_size());
    RC_ASSERT(rel(dr[1], dc[1] * ratio) <= 1e-9);
    RC_ASSERT(rel(dr[2], dc[2] * (ratio * ratio)) <= 1e-8);
  }
}

// checks: reverse gives R(t) = C(a + b - t) (≤ 1e-12 × size) and R'(t) = -C'(a + b - t).
RC_GTEST_PROP(ReparamProperty, ReverseFlipsDirection, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const NurbsCurve r = reverse(c);
  const Interval d = c.domain();
  RC_ASSERT(r.domain().start == d.start);
  RC_ASSERT(r.domain().end == d.end);
  RC_ASSERT(distance(r.evaluate(d.start), c.evaluate(d.end)) <= 1e-12 * c.model_size());
  for (int i = 0; i <= 200; ++i) {
    const double t = d.start + d.length() * (i + 0.37) / 201.0;
    const auto dc = c.derivatives(d.start + d.end - t, 1);
    const auto dr = r.derivatives(t, 1);
    RC_ASSERT(distance(dc[0], dr[0]) <= 1e-12 * c.model_size());
    RC_ASSERT(rel(dr[1], -dc[1]) <= 1e-9);
  }
}

// checks: split halves equal the curve on [a, t] and [t, b] (≤ 1e-12 × size) and meet at C(t).
RC_GTEST_PROP(ReparamProperty, SplitHalvesReproduceCurve, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const Interval d = c.domain();
  const auto breaks = c.knots().breakpoints();
  double t = d.start + d.length() * *rc::gen::inRange(1, 1000) / 1000.0;
  if (breaks.size() > 2 && *rc::gen::arbitrary<bool>())
    t = breaks[*rc::gen::inRange<std::size_t>(1, breaks.size() - 1)];
  const SplitResult s = split(c, t);
  RC_ASSERT(s.before.domain().start == d.start);
  RC_ASSERT(s.before.domain().end == t);
  RC_ASSERT(s.after.domain().start == t);
  RC_ASSERT(s.after.domain().end == d.end);
  RC_ASSERT(s.before.control_points().back() == s.after.control_points().front());
  RC_ASSERT(testing::max_deviation(s.before, c, 300) <= 1e-12 * c.model_size());
  RC_ASSERT(testing::max_deviation(s.after, c, 300) <= 1e-12 * c.model_size());
}

}  // namespace
}  // namespace hula::nurbs
