// SPDX-License-Identifier: MIT
// Property tests (label `property`) of arc_length.hpp: the length of a random
// curve is invariant under the shape-preserving operations of refine, elevate
// and reparam, and additive under split; parameter_at_length inverts it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: length(C) equals the lengths after reverse, reparameterise, elevate and the sum over split halves (1e-11
// rel).
RC_GTEST_PROP(ArcLengthProperty, LengthIsInvariant, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const double L = arc_length(c);
  RC_ASSERT(L > 0.0);
  // The transformed curves match C to 1e-12 × model size pointwise, so their
  // lengths may differ by a multiple of that as well as by the quadrature tolerance.
  const double tol = 1e-11 * (L + c.model_size());
  const Interval d = c.domain();
  const double t = d.start + d.length() * *rc::gen::inRange(1, 100) / 100.0;
  const SplitResult s = split(c, t);
  RC_ASSERT(std::fabs(arc_length(s.before) + arc_length(s.after) - L) <= tol);
  RC_ASSERT(std::fabs(arc_length(c, d.start, t) + arc_length(c, t, d.end) - L) <= tol);
  RC_ASSERT(std::fabs(arc_length(reverse(c)) - L) <= tol);
  RC_ASSERT(std::fabs(arc_length(reparameterise(c, {-3.0, 40.0})) - L) <= tol);
  RC_ASSERT(std::fabs(arc_length(elevate_degree(c, 1)) - L) <= tol);
}

// checks: arc_length(t0, parameter_at_length(s)) = s to 1e-10 × L on random curves.
RC_GTEST_PROP(ArcLengthProperty, ParameterAtLengthInverts, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const double L = arc_length(c);
  const double s = L * *rc::gen::inRange(0, 1001) / 1000.0;
  const double t = parameter_at_length(c, s);
  RC_ASSERT(std::fabs(arc_length(c, c.domain().start, t) - s) <= 1e-10 * L);
}

}  // namespace
}  // namespace hula::nurbs
