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

// checks the log curvature graph of the twisted cubic (t, t², t³) against x = −log10 κ, y = log10(κ/|dκ/ds|)
// from the closed forms κ = |a|/v³ and dκ/ds (chain rule), a = (6t², −6t, 2), v² = 1 + 4t² + 9t⁴.
TEST(Plot, LogCurvatureGraphTwistedCubic) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1},
                            {{0, 0, 0}, {1.0 / 3, 0, 0}, {2.0 / 3, 1.0 / 3, 0}, {1, 1, 1}});
  PlotOptions o;
  o.quantity = PlotQuantity::LogCurvatureGraph;
  o.samples = 21;
  const Plot p = plot(c, o);
  for (std::size_t i = 0; i < p.t.size(); ++i) {
    const double t = p.t[i], t2 = t * t;
    const double v2 = 1 + 4 * t2 + 9 * t2 * t2, a2 = 36 * t2 * t2 + 36 * t2 + 4;
    const double k = std::sqrt(a2) / std::pow(v2, 1.5);
    const double da2 = 144 * t2 * t + 72 * t, dv2 = 8 * t + 36 * t2 * t;
    const double dk = (0.5 * da2 / std::sqrt(a2)) / std::pow(v2, 1.5) - 1.5 * std::sqrt(a2) * dv2 / std::pow(v2, 2.5);
    const double kp = dk / std::sqrt(v2);
    if (kp == 0.0) {
      EXPECT_EQ(p.defined[i], 0);
      continue;
    }
    EXPECT_NEAR(p.x[i], -std::log10(k), 1e-10);
    EXPECT_NEAR(p.y[i], std::log10(k / std::fabs(kp)), 1e-8);
  }
}

}  // namespace
}  // namespace hula::diffgeom
