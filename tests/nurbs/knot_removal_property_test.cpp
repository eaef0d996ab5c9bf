// SPDX-License-Identifier: MIT
// Property tests (label `property`) of knot_removal.hpp on seeded random curves: the reported bound holds
// against the densely sampled distance between the input and the reduced curve at equal parameters, and stays
// within the tolerance.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "hula/nurbs/knot_removal.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: a random curve, refined with up to 12 knots whose control points then move by up to 1e-7 … 1e-4 of the
// size: remove_knots at a random tolerance (1e-4 … 1e-1 of the size) keeps max |C_new(t) − C(t)| on 4001
// samples within its reported bound, the bound within the tolerance, and the domain unchanged.
RC_GTEST_PROP(KnotRemovalProperty, BoundHoldsAgainstSampledDistance, ()) {
  const NurbsCurve base = testing::arbitrary_curve();
  const Interval d = base.domain();
  std::vector<double> X;
  const int count = *rc::gen::inRange(1, 13);
  for (int j = 1; j <= count; ++j) {
    const double u = d.start + d.length() * j / (count + 1.0);
    if (base.knots().multiplicity(u) == 0) X.push_back(u);
  }
  const NurbsCurve refined = refine_knots(base, X);
  const double size = base.model_size();
  const double move = size * std::pow(10.0, -*rc::gen::inRange(4, 8));
  std::vector<Vec3> points(refined.control_points().begin(), refined.control_points().end());
  for (Vec3& q : points)
    q = q + Vec3{*rc::gen::inRange(-100, 101) / 100.0, *rc::gen::inRange(-100, 101) / 100.0,
                 refined.dimension() == 2 ? 0.0 : *rc::gen::inRange(-100, 101) / 100.0} *
                move;
  const NurbsCurve c(refined.knots(), points, {refined.weights().begin(), refined.weights().end()},
                     refined.dimension());
  const double tol = size * std::pow(10.0, -*rc::gen::inRange(1, 5));
  const KnotRemovalResult r = remove_knots(c, tol);
  RC_CLASSIFY(r.removed > 0, "knots removed");
  RC_ASSERT(r.error_bound <= tol);
  RC_ASSERT(r.curve.control_points().size() + r.removed == c.control_points().size());
  RC_ASSERT(r.curve.domain().start == c.domain().start);
  RC_ASSERT(r.curve.domain().end == c.domain().end);
  RC_ASSERT(testing::max_deviation(c, r.curve, 4000) <= r.error_bound + 1e-12 * size);
}

}  // namespace
}  // namespace hula::nurbs
