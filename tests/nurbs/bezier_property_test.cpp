// SPDX-License-Identifier: MIT
// Property tests (label `property`) of bezier.hpp: de Casteljau, Bernstein and NurbsCurve agree; subdivision reproduces
// the curve.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/bezier.hpp"

namespace hula::nurbs {
namespace {

struct RandomBezier {
  std::vector<Vec3> points;
  std::vector<double> weights;
};

RandomBezier random_bezier() {
  Rng rng(*rc::gen::arbitrary<std::uint64_t>());
  const int degree = *rc::gen::inRange(1, 11);
  RandomBezier b;
  for (int i = 0; i <= degree; ++i) b.points.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
  if (*rc::gen::arbitrary<bool>())
    for (int i = 0; i <= degree; ++i) b.weights.push_back(rng.uniform(0.5, 2.0));
  return b;
}

// checks: de Casteljau, Bernstein form and NurbsCurve::evaluate agree to 1e-14 (degrees 1–10, rational or not).
RC_GTEST_PROP(BezierProperty, ThreeEvaluatorsAgree, ()) {
  const RandomBezier b = random_bezier();
  const NurbsCurve c = make_bezier(b.points, b.weights);
  RC_ASSERT(c.degree() + 1 == static_cast<int>(b.points.size()));
  for (int i = 0; i <= 64; ++i) {
    const double t = i / 64.0;
    const Vec3 dc = de_casteljau(b.points, b.weights, t).point;
    const Vec3 bern = evaluate_bernstein(b.points, b.weights, t);
    const Vec3 nurbs = c.evaluate(t);
    RC_ASSERT(distance(dc, bern) <= 1e-14);
    RC_ASSERT(distance(dc, nurbs) <= 1e-14);
  }
}

// checks: the left/right polygons of de Casteljau at t reproduce C on [0, t] and [t, 1] (to 1e-14).
RC_GTEST_PROP(BezierProperty, SubdivisionReproducesCurve, ()) {
  const RandomBezier b = random_bezier();
  const double t = *rc::gen::inRange(1, 100) / 100.0;
  const DeCasteljauResult r = de_casteljau(b.points, b.weights, t);
  RC_ASSERT(r.left.front() == b.points.front());
  RC_ASSERT(r.right.back() == b.points.back());
  RC_ASSERT(r.left.back() == r.point);
  RC_ASSERT(r.right.front() == r.point);
  RC_ASSERT(r.left_weights.size() == b.weights.size());
  for (int i = 0; i <= 32; ++i) {
    const double u = i / 32.0;
    const Vec3 whole_left = evaluate_bernstein(b.points, b.weights, t * u);
    const Vec3 whole_right = evaluate_bernstein(b.points, b.weights, t + (1 - t) * u);
    RC_ASSERT(distance(evaluate_bernstein(r.left, r.left_weights, u), whole_left) <= 1e-14);
    RC_ASSERT(distance(evaluate_bernstein(r.right, r.right_weights, u), whole_right) <= 1e-14);
  }
}

}  // namespace
}  // namespace hula::nurbs
