// SPDX-License-Identifier: MIT
// K-orthotomics and polar maps (thesis 6.3.2) against closed forms: the
// orthotomic of the parabola y = x² with respect to its focus is the directrix
// y = −1/4 and its pedal the vertex tangent y = 0; a circle's K-orthotomic
// about its centre is the circle of radius K R; the polar map of the parabola
// about the unit circle is the parabola y = −x²/4, of a circle about its
// centre the circle of radius ρ²/R; and an inflection of y = x³ is a cusp
// (zero speed) of both maps.
#include "hula/diffgeom/mapping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/bezier.hpp"

namespace hula::diffgeom {
namespace {

// Checks the parabola's orthotomic about its focus is its directrix and its pedal the vertex tangent, exactly for
// the law curve and within the tolerance for the same parabola as a Bézier curve.
TEST(Orthotomic, ParabolaAboutItsFocusIsTheDirectrix) {
  const curve::Curve law = curve::Curve::from_law("vec(t, t^2)", "t", {-2.0, 2.0});
  const MappedCurve o = orthotomic(law, {0.0, 0.25, 0.0}, 2.0);
  ASSERT_TRUE(o.exact);
  EXPECT_EQ(o.curve.dimension(), 2);
  const MappedCurve pedal = orthotomic(law, {0.0, 0.25, 0.0}, 1.0);
  for (int i = 0; i <= 200; ++i) {
    const double t = -2.0 + 4.0 * i / 200.0;
    EXPECT_NEAR(o.curve.point(t).y, -0.25, 1e-14) << "t=" << t;
    // The reflection of the focus in the tangent at (t, t²) lies on the directrix at x = t.
    EXPECT_NEAR(o.curve.point(t).x, t, 1e-14) << "t=" << t;
    EXPECT_NEAR(pedal.curve.point(t).y, 0.0, 1e-14) << "t=" << t;
  }
  const std::vector<Vec3> poles{{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}};  // y = x², x = 2u − 1
  MappingOptions opt;
  opt.tolerance = 1e-9;
  const MappedCurve b = orthotomic(curve::Curve(nurbs::make_bezier(poles, {}, 2)), {0.0, 0.25, 0.0}, 2.0, opt);
  EXPECT_FALSE(b.exact);
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    EXPECT_NEAR(b.curve.point(u).y, -0.25, 1e-9);
    EXPECT_NEAR(b.curve.point(u).x, 2 * u - 1, 1e-9);
  }
}

// Checks a circle's K-orthotomic about its centre is the concentric circle of radius K R, and about a point of it
// (K = 1) the cardioid r = R (1 + cos φ) about that point (a point at angle t maps to angle t/2 ... checked by its
// polar equation).
TEST(Orthotomic, CircleClosedForms) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t), 1)", "t", {0.0, 2.0 * std::numbers::pi});
  const MappedCurve o = orthotomic(c, {0.0, 0.0, 1.0}, 3.0);
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(norm(o.curve.point(0.06 * i) - Vec3{0, 0, 1}), 6.0, 1e-14);
  // Pedal of the circle about its point (−2, 0): the cardioid r = 2 (1 + cos φ), φ the angle about the pole.
  const curve::Curve plane = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  const MappedCurve cardioid = orthotomic(plane, {-2.0, 0.0, 0.0}, 1.0);
  for (int i = 1; i < 100; ++i) {
    const Vec3 q = cardioid.curve.point(0.0628 * i) - Vec3{-2, 0, 0};
    const double r = norm(q);
    if (r < 1e-9) continue;
    EXPECT_NEAR(r, 2.0 * (1.0 + q.x / r), 1e-13);
  }
}

// Checks the polar map of the parabola y = x² about the unit circle is the parabola y = −x²/4 (the pole of the
// tangent at (a, a²) is (2/a, −1/a²)), and of the circle of radius 2 about its centre the circle of radius ρ²/2.
TEST(PolarMap, ClosedForms) {
  const curve::Curve law = curve::Curve::from_law("vec(t, t^2)", "t", {0.5, 2.0});
  const MappedCurve q = polar_map(law, {0, 0, 0}, 1.0);
  ASSERT_TRUE(q.exact);
  for (int i = 0; i <= 100; ++i) {
    const double a = 0.5 + 1.5 * i / 100.0;
    const Vec3 p = q.curve.point(a);
    EXPECT_NEAR(p.x, 2.0 / a, 1e-14);
    EXPECT_NEAR(p.y, -1.0 / (a * a), 1e-14);
    EXPECT_NEAR(p.y, -p.x * p.x / 4.0, 1e-13);
  }
  const curve::Curve circle =
      curve::Curve::from_law("vec(1 + 2*cos(t), -1 + 2*sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  const MappedCurve c = polar_map(circle, {1, -1, 0}, 3.0);
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(norm(c.curve.point(0.06 * i) - Vec3{1, -1, 0}), 4.5, 1e-14);
}

// Checks the inflection of y = x³ at t = 0 is a cusp (zero speed, exactly) of its polar map and of its orthotomic,
// while away from it both move.
TEST(Mapping, InflectionIsACusp) {
  const curve::Curve cubic = curve::Curve::from_law("vec(t, t^3)", "t", {-1.0, 1.0});
  const MappedCurve q = polar_map(cubic, {0.3, -2.0, 0.0}, 1.0);
  const MappedCurve o = orthotomic(cubic, {0.3, -2.0, 0.0}, 2.0);
  EXPECT_LE(norm(q.curve.derivatives(0.0, 1)[1]), 1e-14);
  EXPECT_LE(norm(o.curve.derivatives(0.0, 1)[1]), 1e-14);
  for (double t : {-0.5, 0.5}) {
    EXPECT_GT(norm(q.curve.derivatives(t, 1)[1]), 0.1);
    EXPECT_GT(norm(o.curve.derivatives(t, 1)[1]), 0.1);
  }
}

// Checks bad input is refused naming it: a 3-D curve for the polar map, a tangent through the centre, K = 0.
TEST(Mapping, BadInputNamesIt) {
  const curve::Curve helix = curve::Curve::from_law("vec(cos(t), sin(t), t)", "t", {0.0, 1.0});
  const curve::Curve cubic = curve::Curve::from_law("vec(t, t^3)", "t", {-1.0, 1.0});
  const auto field_of = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return e.where().field;
    }
    return std::string("none");
  };
  EXPECT_EQ(field_of([&] { (void)polar_map(helix, {0, 0, 0}, 1.0); }), "curve");
  EXPECT_EQ(field_of([&] { (void)polar_map(cubic, {0, 0, 0}, 1.0); }), "centre");  // the tangent at 0 is y = 0
  EXPECT_EQ(field_of([&] { (void)polar_map(cubic, {0, 1, 0}, 0.0); }), "radius");
  EXPECT_EQ(field_of([&] { (void)orthotomic(cubic, {0, 1, 0}, 0.0); }), "k");
  EXPECT_EQ(field_of([&] { (void)orthotomic(cubic, {0, std::nan(""), 0}, 2.0); }), "pole");
}

}  // namespace
}  // namespace hula::diffgeom
