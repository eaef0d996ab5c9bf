// SPDX-License-Identifier: MIT
// Energies against closed forms and an independent dense quadrature: a circle of
// radius R has ∫κ² ds = 2π/R and ∫(dκ/ds)² ds = 0; on a random cubic both agree
// with a composite Simpson rule on 200001 points.
#include "hula/diffgeom/energy.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "hula/core/error.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

// checks ∫κ² ds = 2π/R and ∫κ'² ds = 0 on the rational circle.
TEST(Energy, Circle) {
  for (double R : {0.5, 4.0}) {
    const nurbs::NurbsCurve c = testing::rational_circle(R);
    const EnergyResult e = bending_energy(c);
    EXPECT_TRUE(e.converged);
    EXPECT_NEAR(e.value, 2 * std::numbers::pi / R, 1e-10);
    EXPECT_NEAR(curvature_variation_energy(c).value, 0.0, 1e-12);
  }
}

// checks both energies of a random cubic against composite Simpson per span (independent of the GK code path).
TEST(Energy, RandomCubicAgainstSimpson) {
  Rng rng(5);
  const nurbs::NurbsCurve c = testing::random_curve(rng, {.degree = 3, .clamped = true, .extra_points = 3});
  const std::vector<double> bp = c.knots().breakpoints();
  double e1 = 0.0, e2 = 0.0;
  for (std::size_t s = 0; s + 1 < bp.size(); ++s) {
    const int n = 20000;
    const double h = (bp[s + 1] - bp[s]) / n;
    for (int i = 0; i <= n; ++i) {
      FrenetOptions side;  // the span's own polynomial at its right end (the curve may be C0 at a knot)
      side.eval.side = i == n ? nurbs::Side::Left : nurbs::Side::Right;
      const FrenetPoint p = frenet(c, i == n ? bp[s + 1] : bp[s] + h * i, side);
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      e1 += w * h / 3 * p.curvature * p.curvature * p.speed;
      if (p.frame_defined) e2 += w * h / 3 * p.curvature_derivative * p.curvature_derivative * p.speed;
    }
  }
  EXPECT_NEAR(bending_energy(c).value, e1, 1e-8 * e1);
  EXPECT_NEAR(curvature_variation_energy(c).value, e2, 1e-7 * e2);
  EnergyOptions o;
  o.max_depth = 0;
  EXPECT_THROW((void)bending_energy(c, o), Error);
}

}  // namespace
}  // namespace hula::diffgeom
