// SPDX-License-Identifier: MIT
// Property tests (label `property`) of elevate.hpp: elevation by 1 and 2 leaves seeded random curves unchanged.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "hula/nurbs/elevate.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: elevation by 1 and 2 leaves random curves (degrees 1–5, rational or not) unchanged to 1e-12 × model size.
RC_GTEST_PROP(ElevateProperty, ElevationKeepsShape, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const int times = *rc::gen::inRange(1, 3);
  const NurbsCurve e = elevate_degree(c, times);
  RC_ASSERT(e.degree() == c.degree() + times);
  RC_ASSERT(e.domain().start == c.domain().start);
  RC_ASSERT(e.domain().end == c.domain().end);
  RC_ASSERT(e.is_rational() == c.is_rational());
  for (const double u : c.knots().breakpoints())
    if (u != c.domain().start && u != c.domain().end)
      RC_ASSERT(e.knots().multiplicity(u) == c.knots().multiplicity(u) + times);
  RC_ASSERT(testing::max_deviation(c, e) <= 1e-12 * c.model_size());
}

}  // namespace
}  // namespace hula::nurbs
