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
#include "hula/law/parser.hpp"
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

namespace hula::diffgeom {
namespace {

// checks law-curve plots on the helix (2 cos t, 2 sin t, 0.5 t): κ = 2/4.25 and τ = 0.5/4.25 constant,
// s = √4.25 t against arc length, speed √4.25, and a log torsion graph undefined everywhere (dτ/ds = 0).
TEST(Plot, LawHelixConstant) {
  law::Context ctx;
  const law::Law helix = law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx);
  const nurbs::Interval dom{0.0, 10.0};
  PlotOptions o;
  o.samples = 101;
  o.quantity = PlotQuantity::Torsion;
  o.abscissa = PlotAbscissa::ArcLength;
  const Plot tau = plot(helix, "t", dom, o);
  ASSERT_EQ(tau.y.size(), 101U);
  for (std::size_t i = 0; i < tau.y.size(); ++i) {
    EXPECT_NEAR(tau.y[i], 0.5 / 4.25, 1e-12) << i;
    EXPECT_NEAR(tau.x[i], std::sqrt(4.25) * tau.t[i], 1e-11) << i;
  }
  o.quantity = PlotQuantity::Curvature;
  for (const double k : plot(helix, "t", dom, o).y) EXPECT_NEAR(k, 2.0 / 4.25, 1e-12);
  o.quantity = PlotQuantity::Speed;
  for (const double v : plot(helix, "t", dom, o).y) EXPECT_NEAR(v, std::sqrt(4.25), 1e-12);
  o.quantity = PlotQuantity::LogTorsionGraph;
  const Plot g = plot(helix, "t", dom, o);
  for (const std::uint8_t d : g.defined) EXPECT_EQ(d, 0);
}

// checks the log torsion graph of the twisted cubic (t, t², t³), as a law and as the Bézier curve with the
// same parametrisation: with w = 1 + 9t² + 9t⁴, τ = 3/w, v = √(1 + 4t² + 9t⁴), dτ/ds = −3 w'/(w² v),
// so x = log10(w/3) and y = log10(v w / |w'|).
TEST(Plot, TwistedCubicLogTorsionGraphClosedForm) {
  law::Context ctx;
  const law::Law cubic = law::parse("vec(t, t^2, t^3)", ctx);
  const nurbs::NurbsCurve bezier(3, {0, 0, 0, 0, 1, 1, 1, 1},
                                 {{0, 0, 0}, {1.0 / 3, 0, 0}, {2.0 / 3, 1.0 / 3, 0}, {1, 1, 1}}, {}, 3);
  PlotOptions o;
  o.samples = 41;
  o.quantity = PlotQuantity::LogTorsionGraph;
  for (int pass = 0; pass < 2; ++pass) {
    const Plot g = pass == 0 ? plot(cubic, "t", {0.0, 1.0}, o) : plot(bezier, o);
    ASSERT_EQ(g.t.size(), 41U);
    EXPECT_EQ(g.defined[0], 0) << pass;  // t = 0: dτ/ds = 0
    for (std::size_t i = 1; i < g.t.size(); ++i) {
      const double t = g.t[i];
      const double w = 1 + 9 * t * t + 9 * t * t * t * t;
      const double w1 = 18 * t + 36 * t * t * t;
      const double v = std::sqrt(1 + 4 * t * t + 9 * t * t * t * t);
      ASSERT_EQ(g.defined[i], 1) << pass << " " << i;
      EXPECT_NEAR(g.x[i], std::log10(w / 3), 1e-12) << pass << " " << i;
      EXPECT_NEAR(g.y[i], std::log10(v * w / w1), 1e-10) << pass << " " << i;
    }
  }
  o.quantity = PlotQuantity::Torsion;
  const Plot tau = plot(cubic, "t", {-1.0, 1.0}, o);
  for (std::size_t i = 0; i < tau.t.size(); ++i) {
    const double t = tau.t[i];
    EXPECT_NEAR(tau.y[i], 3 / (1 + 9 * t * t + 9 * t * t * t * t), 1e-12) << i;
  }
}

// checks the law form names a scalar law ("law") and a bad domain ("domain").
TEST(Plot, LawErrorsNameTheInput) {
  law::Context ctx;
  try {
    (void)plot(law::parse("t^2", ctx), "t", {0.0, 1.0});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "law");
  }
  try {
    (void)plot(law::parse("vec(t, t^2)", ctx), "t", {1.0, 0.0});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "domain");
  }
}

}  // namespace
}  // namespace hula::diffgeom
