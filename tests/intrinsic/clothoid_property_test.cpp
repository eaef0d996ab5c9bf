// SPDX-License-Identifier: MIT
// Property tests (label `property`) of fit_clothoid_g2() (intrinsic/clothoid.hpp): on random admissible G2
// Hermite data the three arcs join with continuous position, tangent angle and curvature and meet the end
// conditions, checked with closed-form Fresnel ends (testing/clothoid_check.hpp).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/intrinsic/clothoid.hpp"
#include "hula/testing/clothoid_check.hpp"

namespace hula::intrinsic {
namespace {

// A double in [lo, hi] at a resolution of (hi − lo) / 10^6, uniform whatever the test's size (inRange alone
// narrows its range at small sizes, which would crowd the data at lo).
double in(double lo, double hi) { return lo + (hi - lo) * *rc::gen::resize(100, rc::gen::inRange(0, 1000001)) / 1e6; }

// checks: admissible data — chord 0.1 … 10 in any direction from anywhere in [−10, 10]², end angles within
// 0.99π of the chord (either side), curvatures |κ| · chord ≤ 10 — give three arcs of positive length whose
// joins and ends are G2 within 1e-10 (scale-free, testing::g2_violation) against closed-form Fresnel ends.
RC_GTEST_PROP(ClothoidG2Property, JoinsAndEndsAreG2, ()) {
  const double chord = std::pow(10.0, in(-1.0, 1.0)), dir = in(-std::numbers::pi, std::numbers::pi);
  const Vec3 p0{in(-10.0, 10.0), in(-10.0, 10.0), 0.0};
  const Vec3 p1 = p0 + chord * Vec3{std::cos(dir), std::sin(dir), 0.0};
  const double theta0 = dir + in(-0.99, 0.99) * std::numbers::pi, theta1 = dir + in(-0.99, 0.99) * std::numbers::pi;
  const double kappa0 = in(-10.0, 10.0) / chord, kappa1 = in(-10.0, 10.0) / chord;
  const ClothoidG2Result r = fit_clothoid_g2(p0, theta0, kappa0, p1, theta1, kappa1);
  for (const ClothoidSegment& s : r.segments) RC_ASSERT(s.length > 0.0);
  const double violation = testing::g2_violation(r, p0, theta0, kappa0, p1, theta1, kappa1);
  RC_TAG(violation < 1e-12 ? "below 1e-12" : "1e-12 to 1e-10");
  RC_ASSERT(violation < 1e-10);
}

}  // namespace
}  // namespace hula::intrinsic
