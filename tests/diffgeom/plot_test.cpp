// SPDX-License-Identifier: MIT
// Curvature plots (thesis 6.3.1) against closed forms: on a circle of radius R,
// κ = 1/R, ρ = R (hidden beyond radius_limit), speed = |r'|, arc-length abscissa
// ends at 2πR, log scale log10(1/R); on the S-curve the signed curvature plot
// matches 6x/(1 + (3x² − 1)²)^{3/2}.
#include "hula/diffgeom/plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/core/error.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

// checks κ, ρ, range limit, speed, arc length and log scale on the rational circle.
TEST(Plot, Circle) {
  const double R = 2.5;
  const nurbs::NurbsCurve c = testing::rational_circle(R);
  PlotOptions o;
  o.samples = 51;
  const Plot k = plot(c, o);
  for (double y : k.y) EXPECT_NEAR(y, 1 / R, 1e-12);
  o.quantity = PlotQuantity::Radius;
  for (double y : plot(c, o).y) EXPECT_NEAR(y, R, 1e-10);
  o.radius_limit = 2.0;
  for (std::uint8_t d : plot(c, o).defined) EXPECT_EQ(d, 0);
  o.radius_limit = 10.0;
  o.quantity = PlotQuantity::Curvature;
  o.abscissa = PlotAbscissa::ArcLength;
  o.log_scale = true;
  const Plot l = plot(c, o);
  EXPECT_NEAR(l.x.back(), 2 * std::numbers::pi * R, 1e-9);
  for (double y : l.y) EXPECT_NEAR(y, std::log10(1 / R), 1e-12);
  o.samples = 1;
  EXPECT_THROW((void)plot(c, o), Error);
}

// checks the signed curvature plot of the Bézier S-curve (x, x³ − x) against its closed form.
TEST(Plot, SCurveSigned) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1},
                            {{-1, 0, 0}, {-1.0 / 3, 4.0 / 3, 0}, {1.0 / 3, -4.0 / 3, 0}, {1, 0, 0}}, {}, 2);
  PlotOptions o;
  o.quantity = PlotQuantity::SignedCurvature;
  o.samples = 41;
  const Plot p = plot(c, o);
  for (std::size_t i = 0; i < p.t.size(); ++i) {
    const double x = 2 * p.t[i] - 1, yp = 3 * x * x - 1;
    EXPECT_NEAR(p.y[i], 6 * x / std::pow(1 + yp * yp, 1.5), 1e-10);
  }
}

}  // namespace
}  // namespace hula::diffgeom
