// SPDX-License-Identifier: MIT
// Planar offsets against closed forms: the concentric circle, the offsets of
// an ellipse (cusps where dκ = 1, swallowtail crossings on the axis) and of
// the parabola y = x² (cusps, the crossing on the axis), the curvature of an
// offset law curve κ / (1 − dκ) to rounding, and trimming checked with the
// self-intersection code and by the distance of the kept points to the curve.
#include "hula/diffgeom/offset.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/intersect.hpp"

namespace hula::diffgeom {
namespace {

double signed_curvature(const std::vector<Vec3>& d) {
  return (d[1].x * d[2].y - d[1].y * d[2].x) / std::pow(d[1].x * d[1].x + d[1].y * d[1].y, 1.5);
}

// Every point of every trimmed piece lies |d| from the curve, and no piece crosses itself.
void expect_trimmed_at_distance(const PlanarOffset& o, const curve::Curve& c, double d, double tol) {
  for (const OffsetPiece& piece : o.trimmed) {
    const Interval dom = piece.curve.domain();
    for (int i = 0; i <= 400; ++i) {
      const double t = dom.start + (dom.end - dom.start) * i / 400.0;
      EXPECT_NEAR(nurbs::closest_point(c.nurbs(), piece.curve.evaluate(t)).distance, std::abs(d), tol) << "t=" << t;
    }
    EXPECT_TRUE(nurbs::self_intersect(piece.curve).points.empty());
  }
}

// Checks a circle law's offset is the concentric circle, exactly a law, closed, without cusps or loops.
TEST(PlanarOffset, CircleIsConcentricCircleAsExactLaw) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  const PlanarOffset o = planar_offset(c, 0.5);
  ASSERT_TRUE(o.exact);
  EXPECT_EQ(o.raw.kind(), curve::Kind::Law);
  EXPECT_LE(o.deviation, 1e-6);
  for (int i = 0; i <= 100; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 100.0;
    const std::vector<Vec3> d = o.raw.derivatives(t, 2);
    EXPECT_NEAR(norm(d[0]), 1.5, 1e-14);
    EXPECT_NEAR(signed_curvature(d), 1.0 / 1.5, 1e-14);
  }
  EXPECT_TRUE(o.cusps.empty());
  EXPECT_TRUE(o.loops.empty());
  ASSERT_EQ(o.trimmed.size(), 1U);
  EXPECT_TRUE(o.trimmed[0].closed);
  ASSERT_EQ(o.trimmed[0].spans.size(), 1U);
  EXPECT_EQ(o.trimmed[0].spans[0].start, 0.0);
  EXPECT_EQ(o.trimmed[0].spans[0].end, 2.0 * std::numbers::pi);
}

// Checks the outward offset (d < 0) of a circle and that an inward offset beyond the radius trims to nothing.
TEST(PlanarOffset, CircleOutwardAndBeyondTheRadius) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  const PlanarOffset out = planar_offset(c, -1.0);
  EXPECT_NEAR(norm(out.raw.point(0.3)), 3.0, 1e-14);
  ASSERT_EQ(out.trimmed.size(), 1U);
  const PlanarOffset in = planar_offset(c, 3.0);
  EXPECT_NEAR(norm(in.raw.point(0.3)), 1.0, 1e-14);  // the raw offset: radius 1, run backwards
  EXPECT_TRUE(in.cusps.empty());
  EXPECT_TRUE(in.trimmed.empty());
}

// Checks the offset law's curvature is κ / (1 − dκ) of the ellipse (3 cos t, sin t) to rounding.
TEST(PlanarOffset, LawOffsetCurvatureIsExact) {
  const curve::Curve c = curve::Curve::from_law("vec(3*cos(t), sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  for (double d : {-0.5, 0.2}) {
    const PlanarOffset o = planar_offset(c, d);
    ASSERT_TRUE(o.exact);
    for (int i = 0; i <= 200; ++i) {
      const double t = 2.0 * std::numbers::pi * i / 200.0;
      const double s = std::sin(t);
      const double k = 3.0 / std::pow(9.0 * s * s + std::cos(t) * std::cos(t), 1.5);
      EXPECT_NEAR(signed_curvature(o.raw.derivatives(t, 2)), k / (1.0 - d * k), 1e-12) << "d=" << d << " t=" << t;
    }
  }
}

// Checks the inward offset of the ellipse (3 cos t, sin t) by 0.5 > 1/3 (its smallest radius of curvature):
// four cusps where κ = 2, two swallowtail crossings on the x axis at x = ±(8/3) cos t*, 1 + 8 sin² t* = 9/4,
// and one closed trimmed piece with two corners, every point 0.5 from the ellipse.
TEST(PlanarOffset, EllipseSwallowtailsAreTrimmed) {
  const curve::Curve c = curve::Curve::from_law("vec(3*cos(t), sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  const PlanarOffset o = planar_offset(c, 0.5);
  const double sc = std::sqrt((std::pow(1.5, 2.0 / 3.0) - 1.0) / 8.0);
  const std::vector<double> cusps{std::asin(sc), std::numbers::pi - std::asin(sc), std::numbers::pi + std::asin(sc),
                                  2 * std::numbers::pi - std::asin(sc)};
  ASSERT_EQ(o.cusps.size(), 4U);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(o.cusps[i], cusps[i], 1e-12);
  const double xc = (8.0 / 3.0) * std::sqrt(1.0 - 1.25 / 8.0);
  ASSERT_EQ(o.loops.size(), 2U);
  std::vector<double> xs{o.loops[0].point.x, o.loops[1].point.x};
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -xc, 1e-6);
  EXPECT_NEAR(xs[1], xc, 1e-6);
  for (const auto& x : o.loops) EXPECT_NEAR(x.point.y, 0.0, 1e-6);
  ASSERT_EQ(o.trimmed.size(), 1U);
  EXPECT_TRUE(o.trimmed[0].closed);
  EXPECT_EQ(o.trimmed[0].spans.size(), 2U);
  expect_trimmed_at_distance(o, c, 0.5, 1e-5);
}

// Checks the offset of the parabola y = x² (a quadratic Bézier, offset through its NURBS) by d = 1 towards its
// focus against the closed form (x − 2dx/√(1+4x²), x² + d/√(1+4x²)): cusps at 1 + 4x² = 2^(2/3), the crossing at
// (0, 5/4), and one trimmed piece of two spans.
TEST(PlanarOffset, ParabolaAgainstClosedForm) {
  const std::vector<Vec3> poles{{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}};
  const curve::Curve c(nurbs::make_bezier(poles, {}, 2));
  OffsetOptions opt;
  opt.tolerance = 1e-9;
  const PlanarOffset o = planar_offset(c, 1.0, opt);
  EXPECT_FALSE(o.exact);
  EXPECT_LE(o.deviation, 1e-9);
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    const double x = 2 * t - 1;
    const double w = std::sqrt(1 + 4 * x * x);
    const Vec3 p = o.raw.point(t);
    EXPECT_NEAR(p.x, x - 2 * x / w, 1e-8);
    EXPECT_NEAR(p.y, x * x + 1 / w, 1e-8);
  }
  const double xc = std::sqrt((std::pow(2.0, 2.0 / 3.0) - 1.0) / 4.0);
  ASSERT_EQ(o.cusps.size(), 2U);
  EXPECT_NEAR(o.cusps[0], (1 - xc) / 2, 1e-12);
  EXPECT_NEAR(o.cusps[1], (1 + xc) / 2, 1e-12);
  ASSERT_EQ(o.loops.size(), 1U);
  EXPECT_NEAR(o.loops[0].point.x, 0.0, 1e-9);
  EXPECT_NEAR(o.loops[0].point.y, 1.25, 1e-9);
  EXPECT_NEAR(o.loops[0].s, (1 - std::sqrt(3.0) / 2) / 2, 1e-8);
  ASSERT_EQ(o.trimmed.size(), 1U);
  EXPECT_FALSE(o.trimmed[0].closed);
  EXPECT_EQ(o.trimmed[0].spans.size(), 2U);
  expect_trimmed_at_distance(o, c, 1.0, 1e-8);
  // Offsetting away from the focus meets no cusp, no loop.
  const PlanarOffset away = planar_offset(c, -1.0, opt);
  EXPECT_TRUE(away.cusps.empty());
  EXPECT_TRUE(away.loops.empty());
  ASSERT_EQ(away.trimmed.size(), 1U);
  EXPECT_EQ(away.trimmed[0].spans.size(), 1U);
}

// Checks a peanut (two lobes joined by a waist 0.5 wide) offset inwards by 0.35 > 0.25 falls into two closed
// pieces, one per lobe (the right one runs on through the closure at t = 0), every point 0.35 from the curve.
TEST(PlanarOffset, PeanutSplitsIntoTwoClosedPieces) {
  const curve::Curve c =
      curve::Curve::from_law("vec(2*cos(t), sin(t)*(0.25 + cos(t)^2))", "t", {0.0, 2.0 * std::numbers::pi});
  const PlanarOffset o = planar_offset(c, 0.35);
  ASSERT_EQ(o.trimmed.size(), 2U);
  for (const OffsetPiece& p : o.trimmed) EXPECT_TRUE(p.closed);
  const double x0 = o.trimmed[0].curve.evaluate(o.trimmed[0].curve.domain().start).x;
  const double x1 = o.trimmed[1].curve.evaluate(o.trimmed[1].curve.domain().start).x;
  EXPECT_LT(x0 * x1, 0.0);  // one on each side of the waist
  expect_trimmed_at_distance(o, c, 0.35, 1e-5);
}

// Checks that trimming off returns the raw offset alone, and that bad input is refused naming the input.
TEST(PlanarOffset, NoTrimAndBadInput) {
  const curve::Curve c = curve::Curve::from_law("vec(3*cos(t), sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  OffsetOptions opt;
  opt.trim = false;
  const PlanarOffset o = planar_offset(c, 0.5, opt);
  EXPECT_TRUE(o.trimmed.empty());
  EXPECT_TRUE(o.cusps.empty());
  const curve::Curve space = curve::Curve::from_law("vec(cos(t), sin(t), t)", "t", {0.0, 1.0});
  try {
    (void)planar_offset(space, 0.5);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::InvalidArgument);
    EXPECT_EQ(e.where().field, "curve");
  }
  try {
    (void)planar_offset(c, std::nan(""));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "distance");
  }
  opt.tolerance = 0.5;
  try {
    (void)planar_offset(c, 0.5, opt);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::InvalidOption);
    EXPECT_EQ(e.where().field, "tolerance");
  }
}

// κ and τ of a curve from its first three derivatives (thesis eq. 11, 17).
std::pair<double, double> curvature_torsion(const Vec3& d1, const Vec3& d2, const Vec3& d3) {
  const Vec3 a = cross(d1, d2);
  return {norm(a) / std::pow(norm(d1), 3), dot(a, d3) / dot(a, a)};
}

// Checks the toroidal round helix (thesis 6.5.2): the circle (2 cos t, 2 sin t) offset by d = 0.5 with twist 8t
// in its Frenet frame is ((2 − 0.5 cos 8t) cos t, (2 − 0.5 cos 8t) sin t, 0.5 sin 8t), an exact law curve whose
// κ and τ equal those of the closed form's derivatives (written out by hand here) to 1e-12.
TEST(HelicalOffset, CircleGivesTheToroidalHelix) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 2.0 * std::numbers::pi});
  const HelicalOffset h = helical_offset(c, "0.5", "8*t");
  ASSERT_TRUE(h.exact);
  EXPECT_EQ(h.curve.kind(), curve::Kind::Law);
  EXPECT_LE(h.deviation, 1e-6);
  for (int i = 0; i <= 200; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 200.0;
    // ρ = 2 − 0.5 cos 8t and its derivatives; P = (ρ cos t, ρ sin t, 0.5 sin 8t).
    const double r0 = 2 - 0.5 * std::cos(8 * t), r1 = 4 * std::sin(8 * t), r2 = 32 * std::cos(8 * t),
                 r3 = -256 * std::sin(8 * t);
    const double c1 = std::cos(t), s1 = std::sin(t);
    const Vec3 p{r0 * c1, r0 * s1, 0.5 * std::sin(8 * t)};
    const Vec3 d1{r1 * c1 - r0 * s1, r1 * s1 + r0 * c1, 4 * std::cos(8 * t)};
    const Vec3 d2{r2 * c1 - 2 * r1 * s1 - r0 * c1, r2 * s1 + 2 * r1 * c1 - r0 * s1, -32 * std::sin(8 * t)};
    const Vec3 d3{r3 * c1 - 3 * r2 * s1 - 3 * r1 * c1 + r0 * s1, r3 * s1 + 3 * r2 * c1 - 3 * r1 * s1 - r0 * c1,
                  -256 * std::cos(8 * t)};
    const std::vector<Vec3> ours = h.curve.derivatives(t, 3);
    EXPECT_LE(norm(ours[0] - p), 1e-14) << "t=" << t;
    const auto [k, tau] = curvature_torsion(d1, d2, d3);
    const auto [k_ours, tau_ours] = curvature_torsion(ours[1], ours[2], ours[3]);
    EXPECT_NEAR(k_ours, k, 1e-12 * k) << "t=" << t;
    EXPECT_NEAR(tau_ours, tau, 1e-12 * std::max(1.0, std::abs(tau))) << "t=" << t;
  }
}

// Checks the helical offset of a straight line in its Bishop frame (the Frenet frame is undefined there) is the
// circular helix of radius d and pitch 2π/ω: κ = dω²/(1 + d²ω²), τ = ω/(1 + d²ω²), exactly; Frenet is refused
// naming the frame.
TEST(HelicalOffset, StraightLineGivesTheCircularHelix) {
  const curve::Curve line = curve::Curve::from_law("vec(t, 0, 0)", "t", {0.0, 4.0});
  HelicalOffsetOptions o;
  o.frame = OffsetFrame::Bishop;
  const HelicalOffset h = helical_offset(line, "0.5", "3*t", o);
  ASSERT_TRUE(h.exact);
  ASSERT_TRUE(h.plane_normal.has_value());
  const double d = 0.5, w = 3.0;
  for (int i = 0; i <= 100; ++i) {
    const double t = 4.0 * i / 100.0;
    const std::vector<Vec3> ours = h.curve.derivatives(t, 3);
    EXPECT_NEAR(ours[0].x, t, 1e-15);
    EXPECT_NEAR(std::hypot(ours[0].y, ours[0].z), d, 1e-15);
    const auto [k, tau] = curvature_torsion(ours[1], ours[2], ours[3]);
    EXPECT_NEAR(k, d * w * w / (1 + d * d * w * w), 1e-13);
    EXPECT_NEAR(std::abs(tau), w / (1 + d * d * w * w), 1e-13);
  }
  try {
    (void)helical_offset(line, "0.5", "3*t");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "frame");
  }
}

// Checks the Bishop frame of a space curve: on the helix (cos t, sin t, t) (τ = 1/2, |C'| = √2) the Bishop angle is
// φ = −t/√2, so the Bishop offset with twist θ is the Frenet offset with twist θ + φ (a law, exact), within 1e-8.
TEST(HelicalOffset, BishopOfHelixIsFrenetTurnedByTheIntegratedTorsion) {
  const curve::Curve helix = curve::Curve::from_law("vec(cos(t), sin(t), t)", "t", {0.0, 6.0});
  HelicalOffsetOptions o;
  o.frame = OffsetFrame::Bishop;
  o.tolerance = 1e-9;
  const HelicalOffset bishop = helical_offset(helix, "0.3 + 0.05*t", "2*t", o);
  EXPECT_FALSE(bishop.exact);
  EXPECT_FALSE(bishop.plane_normal.has_value());
  const HelicalOffset frenet = helical_offset(helix, "0.3 + 0.05*t", "2*t - t/sqrt(2)");
  ASSERT_TRUE(frenet.exact);
  for (int i = 0; i <= 1000; ++i) {
    const double t = 6.0 * i / 1000.0;
    EXPECT_LE(norm(bishop.curve.point(t) - frenet.curve.point(t)), 1e-8) << "t=" << t;
  }
}

// Checks a plane NURBS S-curve (an inflection, where Frenet fails) in its Bishop frame with no twist is its
// planar offset by d (U = Z × T is the left normal), within the tolerances.
TEST(HelicalOffset, PlaneCurveBishopWithoutTwistIsThePlanarOffset) {
  const std::vector<Vec3> poles{{0, 0, 0}, {1, 2, 0}, {2, -2, 0}, {3, 0, 0}};
  const curve::Curve s(nurbs::make_bezier(poles, {}, 2));
  HelicalOffsetOptions o;
  o.frame = OffsetFrame::Bishop;
  o.tolerance = 1e-9;
  const HelicalOffset h = helical_offset(s, "0.2", "0", o);
  OffsetOptions po;
  po.tolerance = 1e-9;
  po.trim = false;
  const PlanarOffset p = planar_offset(s, 0.2, po);
  for (int i = 0; i <= 500; ++i) EXPECT_LE(norm(h.curve.point(i / 500.0) - p.raw.point(i / 500.0)), 3e-9);
  EXPECT_THROW((void)helical_offset(s, "0.2", "0"), Error);  // Frenet: undefined at the inflection
}

// Checks the Bishop frame of a C2 cubic space NURBS, whose torsion jumps at every interior knot: the offset
// is found (it used to refine its quadrature without end across the jumps) and, with no twist, H − C is d U with
// U a unit normal that only turns with the tangent (U' has no part along T × U: rotation-minimising), to the
// accuracy the options ask, at 200 parameters.
TEST(HelicalOffset, BishopOfCubicSpaceNurbsIsRotationMinimisingAcrossKnots) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1},
                            {{0, 0, 0}, {1, 2, 0.5}, {2, 1, 2}, {3, -1, 1}, {4, 0, -1}, {5, 2, 0}, {6, 1, 1}});
  HelicalOffsetOptions o;
  o.frame = OffsetFrame::Bishop;
  o.tolerance = 1e-6;
  const double d = 0.1;
  const HelicalOffset h = helical_offset(curve::Curve(c), "0.1", "0", o);
  double worst_distance = 0.0, worst_normal = 0.0, worst_turn = 0.0;
  for (int i = 1; i < 200; ++i) {
    const double t = i / 200.0;
    const auto dc = c.derivatives(t, 1);
    const auto dh = h.curve.nurbs().derivatives(t, 1);
    const Vec3 T = normalized(dc[1]);
    const Vec3 U = (dh[0] - dc[0]) / d;
    const Vec3 dU = (dh[1] - dc[1]) / d;
    worst_distance = std::max(worst_distance, std::abs(norm(dh[0] - dc[0]) - d));
    worst_normal = std::max(worst_normal, std::abs(dot(U, T)));
    worst_turn = std::max(worst_turn, std::abs(dot(dU, cross(T, U))) / norm(dc[1]));
  }
  EXPECT_LE(worst_distance, 2 * o.tolerance);
  EXPECT_LE(worst_normal, 2 * o.tolerance / d);
  // The Frenet frame of this curve turns about T at |τ| up to ~1: a rotation-minimising frame does not.
  EXPECT_LE(worst_turn, 1e-3);
}

// Checks bad laws are refused naming the option.
TEST(HelicalOffset, BadLawsNameTheOption) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t))", "t", {0.0, 1.0});
  for (const auto& [d, tw, field] : {std::tuple{"0.5 +", "t", "distance"}, std::tuple{"0.5", "vec(t, t)", "twist"},
                                     std::tuple{"u", "t", "distance"}}) {
    try {
      (void)helical_offset(c, d, tw);
      FAIL() << d << " " << tw;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::ParseError);
      EXPECT_EQ(e.where().field, field);
    }
  }
}

}  // namespace
}  // namespace hula::diffgeom
