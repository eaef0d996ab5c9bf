// SPDX-License-Identifier: MIT
// Property tests (label `property`) of bounding_box.hpp: the box of random curves lies in control_box and contains
// dense samples.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/nurbs/bounding_box.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: random-curve box ⊆ control_box, ⊇ 1001 samples per span (1e-13 × size), within 1e-4 × size of them.
RC_GTEST_PROP(BoundingBoxProperty, ContainsSamplesInsideControlBox, ()) {
  const NurbsCurve c = testing::arbitrary_curve();
  const Box3 b = bounding_box(c);
  const Box3 hull = c.control_box();
  const double tol = 1e-13 * c.model_size();
  Box3 samples;
  const auto breaks = c.knots().breakpoints();
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s)
    for (int i = 0; i <= 1000; ++i)
      samples.add(c.evaluate(i == 1000 ? breaks[s + 1] : breaks[s] + (breaks[s + 1] - breaks[s]) * i / 1000.0));
  for (std::size_t k = 0; k < 3; ++k) {
    RC_ASSERT(b.min[k] >= hull.min[k]);
    RC_ASSERT(b.max[k] <= hull.max[k]);
    RC_ASSERT(b.min[k] <= samples.min[k] + tol);
    RC_ASSERT(b.max[k] >= samples.max[k] - tol);
    // Tight: no face is farther out than the dense samples by more than their spacing allows.
    RC_ASSERT(samples.min[k] - b.min[k] <= 1e-4 * c.model_size());
    RC_ASSERT(b.max[k] - samples.max[k] <= 1e-4 * c.model_size());
  }
}

}  // namespace
}  // namespace hula::nurbs
