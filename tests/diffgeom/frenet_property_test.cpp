// SPDX-License-Identifier: MIT
// Property: on seeded random NURBS curves (any degree ≥ 1, rational or not), the
// Frenet frame is orthonormal and right-handed wherever it is defined, κ ≥ 0,
// and every undefined quantity is NaN (STYLE.md invariant kits).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "hula/diffgeom/frenet.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

// checks orthonormality, right-handedness and NaN-where-undefined against the FrenetPoint contract.
RC_GTEST_PROP(FrenetProperty, FrameOrthonormalRightHanded, ()) {
  const nurbs::NurbsCurve c = testing::arbitrary_curve(5);
  const nurbs::Interval d = c.domain();
  std::vector<double> ts(64);
  for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = d.start + d.length() * static_cast<double>(i) / 63.0;
  std::vector<FrenetPoint> out(ts.size());
  frenet(c, ts, out);
  for (const FrenetPoint& p : out) {
    if (p.tangent_defined) {
      RC_ASSERT(std::fabs(norm(p.tangent) - 1.0) < 1e-12);
      RC_ASSERT(p.curvature >= 0.0);
    } else {
      RC_ASSERT(std::isnan(p.tangent.x) && std::isnan(p.curvature));
    }
    if (p.frame_defined) {
      RC_ASSERT(std::fabs(norm(p.normal) - 1.0) < 1e-12);
      RC_ASSERT(std::fabs(norm(p.binormal) - 1.0) < 1e-12);
      RC_ASSERT(std::fabs(dot(p.tangent, p.normal)) < 1e-12);
      RC_ASSERT(norm(cross(p.tangent, p.normal) - p.binormal) < 1e-12);
      RC_ASSERT(std::isfinite(p.torsion) && std::isfinite(p.curvature_derivative));
    } else {
      RC_ASSERT(std::isnan(p.torsion) && std::isnan(p.normal.x) && std::isnan(p.binormal.x));
    }
  }
}

}  // namespace
}  // namespace hula::diffgeom
