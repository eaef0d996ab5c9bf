// SPDX-License-Identifier: MIT
// Property tests (label `property`) of closest_point.hpp: points on random curves return themselves; never worse than
// dense sampling.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "hula/nurbs/closest_point.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: points on random curves return themselves (distance < 1e-9 × model size).
RC_GTEST_PROP(ClosestPointProperty, PointsOnTheCurveReturnThemselves, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const Interval d = c.domain();
  const double t = d.start + d.length() * *rc::gen::inRange(0, 1001) / 1000.0;
  const Vec3 p = c.evaluate(t);
  const ClosestPointResult res = closest_point(c, p);
  RC_ASSERT(res.distance < 1e-9 * c.model_size());
  RC_ASSERT(distance(res.point, p) < 1e-9 * c.model_size());
}

// checks: the result is never farther than the nearest of 20001 dense samples (brute force).
RC_GTEST_PROP(ClosestPointProperty, NeverWorseThanDenseSampling, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  Rng rng(*rc::gen::arbitrary<std::uint64_t>());
  const Vec3 p{rng.uniform(-30, 30), rng.uniform(-30, 30), rng.uniform(-30, 30)};
  const ClosestPointResult res = closest_point(c, p);
  const Interval d = c.domain();
  double brute = HUGE_VAL;
  for (int i = 0; i <= 20000; ++i)
    brute = std::min(brute, distance(c.evaluate(i == 20000 ? d.end : d.start + d.length() * i / 20000.0), p));
  RC_ASSERT(res.distance <= brute + 1e-12 * c.model_size());
  RC_ASSERT(res.t >= d.start);
  RC_ASSERT(res.t <= d.end);
  RC_ASSERT(std::fabs(res.distance - distance(res.point, p)) <= 1e-14 * (res.distance + c.model_size()));
}

}  // namespace
}  // namespace hula::nurbs
