// SPDX-License-Identifier: MIT
// Curve–curve intersection, self-intersection and distance on closed forms:
// circles and lines (secants, tangents, tangent circles), a curve against a
// piece of itself (overlaps, both directions), loops with known crossings,
// distances between circles. Random corpora against Open CASCADE:
// intersect_occt_test.cpp.
#include "hula/nurbs/intersect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/nurbs/bezier.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

NurbsCurve translated(const NurbsCurve& c, const Vec3& v) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p += v;
  return NurbsCurve(c.knots(), std::move(P), {c.weights().begin(), c.weights().end()}, c.dimension());
}

NurbsCurve circle(double R, const Vec3& centre, double angle = 0.3) {
  return translated(testing::rational_circle(R, angle), centre);
}

NurbsCurve segment(const Vec3& a, const Vec3& b) {
  const std::vector<Vec3> P = {a, b};
  return make_bezier(P, {}, a.z == 0.0 && b.z == 0.0 ? 2 : 3);
}

// checks: a circle of radius 1 and the line y = 1/2 cross at (±√3/2, 1/2) at π/3 (closed form).
TEST(Intersect, CircleAndSecantCrossTwice) {
  const IntersectionResult r = intersect(circle(1.0, {}), segment({-2, 0.5, 0}, {2, 0.5, 0}));
  ASSERT_EQ(r.points.size(), 2U);
  EXPECT_TRUE(r.overlaps.empty());
  std::vector<double> xs = {r.points[0].point.x, r.points[1].point.x};
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -std::sqrt(3.0) / 2, 1e-14);
  EXPECT_NEAR(xs[1], std::sqrt(3.0) / 2, 1e-14);
  for (const CurveIntersection& p : r.points) {
    EXPECT_NEAR(p.point.y, 0.5, 1e-14);
    EXPECT_EQ(p.kind, IntersectionKind::Crossing);
    EXPECT_NEAR(p.angle, std::numbers::pi / 3, 1e-12);
    EXPECT_LE(p.distance, 1e-14);
  }
}

// checks: the line y = R touches a circle of radius R once at (0, R), reported as a tangent point (closed form).
TEST(Intersect, CircleAndTangentLineTouchOnce) {
  for (const double R : {1.0, 0.01, 250.0}) {
    const IntersectionResult r = intersect(circle(R, {}), segment({-3 * R, R, 0}, {2 * R, R, 0}));
    ASSERT_EQ(r.points.size(), 1U) << "R = " << R;
    EXPECT_TRUE(r.overlaps.empty());
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent);
    EXPECT_LT(distance(r.points[0].point, {0, R, 0}), 1e-12 * std::fmax(1.0, R)) << "R = " << R;
    EXPECT_LT(r.points[0].angle, 1e-7);
  }
}

// checks: circles tangent outside ((1, 0) for radii 1 and 2, centres 3 apart) and inside ((−1, 0)) (closed form).
TEST(Intersect, TangentCirclesTouchOnce) {
  const IntersectionResult outside = intersect(circle(1.0, {}), circle(2.0, {3, 0, 0}, 1.1));
  ASSERT_EQ(outside.points.size(), 1U);
  EXPECT_EQ(outside.points[0].kind, IntersectionKind::Tangent);
  EXPECT_LT(distance(outside.points[0].point, {1, 0, 0}), 1e-12);
  const IntersectionResult inside = intersect(circle(1.0, {}), circle(2.0, {1, 0, 0}, 2.0));
  ASSERT_EQ(inside.points.size(), 1U);
  EXPECT_EQ(inside.points[0].kind, IntersectionKind::Tangent);
  EXPECT_LT(distance(inside.points[0].point, {-1, 0, 0}), 1e-12);
}

// checks: circles of radius 1 and 2 with centres 2 apart cross at x = 1/4, y = ±√15/4 (closed form:
// x² + y² = 1 and (x − 2)² + y² = 4 give 4 − 4x = 3).
TEST(Intersect, CirclesCrossTwice) {
  const IntersectionResult r = intersect(circle(1.0, {}), circle(2.0, {2, 0, 0}, 0.7));
  ASSERT_EQ(r.points.size(), 2U);
  for (const CurveIntersection& p : r.points) {
    EXPECT_NEAR(p.point.x, 0.25, 1e-14);
    EXPECT_NEAR(std::fabs(p.point.y), std::sqrt(15.0) / 4, 1e-14);
    EXPECT_EQ(p.kind, IntersectionKind::Crossing);
  }
}

// checks: disjoint curves have no intersection.
TEST(Intersect, DisjointCurvesNone) {
  const IntersectionResult r = intersect(circle(1.0, {}), circle(1.0, {2.5, 0, 0}));
  EXPECT_TRUE(r.points.empty());
  EXPECT_TRUE(r.overlaps.empty());
}

// checks: a cubic and the piece of it on [0.2, 0.7] overlap exactly there, in either direction (construction).
TEST(Intersect, CurveAndItsPieceOverlap) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 2, 0.5}, {3, -1, 0}, {4, 1, 1}};
  const NurbsCurve c = make_bezier(P);
  const NurbsCurve piece = split(split(c, 0.2).after, 0.7).before;  // on [0.2, 0.7]
  for (const bool reversed : {false, true}) {
    const NurbsCurve b = reversed ? reverse(piece) : piece;
    const IntersectionResult r = intersect(c, b);
    EXPECT_TRUE(r.points.empty()) << r.points.size() << " points, reversed " << reversed;
    ASSERT_EQ(r.overlaps.size(), 1U) << "reversed " << reversed;
    const CurveOverlap& o = r.overlaps[0];
    EXPECT_NEAR(o.s0, 0.2, 1e-12);
    EXPECT_NEAR(o.s1, 0.7, 1e-12);
    EXPECT_LT(distance(o.start, c.evaluate(0.2)), 1e-12);
    EXPECT_LT(distance(o.end, c.evaluate(0.7)), 1e-12);
    EXPECT_LT(distance(b.evaluate(o.t0), c.evaluate(0.2)), 1e-12);
    EXPECT_LT(distance(b.evaluate(o.t1), c.evaluate(0.7)), 1e-12);
    EXPECT_EQ(o.t1 < o.t0, reversed);
  }
}

// checks: a curve against itself is one overlap over its whole domain.
TEST(Intersect, CurveAgainstItselfIsOneOverlap) {
  const NurbsCurve c = circle(3.0, {1, 2, 0});
  const IntersectionResult r = intersect(c, c);
  EXPECT_TRUE(r.points.empty());
  ASSERT_EQ(r.overlaps.size(), 1U);
  EXPECT_EQ(r.overlaps[0].s0, c.domain().start);
  EXPECT_EQ(r.overlaps[0].s1, c.domain().end);
}

// checks: two polylines sharing a stretch of the x axis and crossing elsewhere give one overlap and one crossing.
TEST(Intersect, SharedStretchAndCrossing) {
  // A: (0,0) → (4,0) → (4,4); B: (1,0) → (3,0) → (3,1) → (5,2): B runs along A from x = 1 to 3, leaves it
  // upwards, and its last leg crosses A's vertical leg at (4, 1.5).
  const NurbsCurve a(1, {0, 0, 1, 2, 2}, {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}}, {}, 2);
  const NurbsCurve b(1, {0, 0, 1, 2, 3, 3}, {{1, 0, 0}, {3, 0, 0}, {3, 1, 0}, {5, 2, 0}}, {}, 2);
  const IntersectionResult r = intersect(a, b);
  ASSERT_EQ(r.overlaps.size(), 1U);
  EXPECT_NEAR(r.overlaps[0].s0, 0.25, 1e-12);
  EXPECT_NEAR(r.overlaps[0].s1, 0.75, 1e-12);
  EXPECT_NEAR(r.overlaps[0].t0, 0.0, 1e-12);
  EXPECT_NEAR(r.overlaps[0].t1, 1.0, 1e-12);
  ASSERT_EQ(r.points.size(), 1U);
  EXPECT_LT(distance(r.points[0].point, {4, 1.5, 0}), 1e-14);
  EXPECT_NEAR(r.points[0].s, 1.375, 1e-14);
  EXPECT_EQ(r.points[0].kind, IntersectionKind::Crossing);
}

// checks: a segment ending on a circle meets it at its end at a right angle (a T junction), exactly.
TEST(Intersect, EndOnCurve) {
  const IntersectionResult r = intersect(segment({0, 0, 0}, {1, 0, 0}), circle(1.0, {}));
  ASSERT_EQ(r.points.size(), 1U);
  EXPECT_EQ(r.points[0].s, 1.0);
  EXPECT_LT(distance(r.points[0].point, {1, 0, 0}), 1e-14);
  EXPECT_EQ(r.points[0].kind, IntersectionKind::Crossing);
  EXPECT_NEAR(r.points[0].angle, std::numbers::pi / 2, 1e-12);
}

// checks: y = x³ (a cubic Bézier) crosses its inflection tangent y = 0 once at the origin, tangentially,
// located to rounding (the gap changes sign there; |D| vanishes to third order).
TEST(Intersect, InflectionTangentCrossing) {
  const std::vector<Vec3> P = {{-1, -1, 0}, {-1.0 / 3, 1, 0}, {1.0 / 3, -1, 0}, {1, 1, 0}};  // x = 2u − 1, y = x³
  const IntersectionResult r = intersect(make_bezier(P, {}, 2), segment({-2, 0, 0}, {2, 0, 0}));
  ASSERT_EQ(r.points.size(), 1U);
  EXPECT_TRUE(r.overlaps.empty());
  EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent);
  EXPECT_LT(norm(r.points[0].point), 1e-12);
  EXPECT_NEAR(r.points[0].s, 0.5, 1e-12);
}

// checks: a parabola dipping 1e-9 below a line crosses it twice, closer together than tol allows to separate:
// one tangent point at the vertex (within tol everywhere between); 1e-3 below, two crossings at ±√1e-3.
TEST(Intersect, ShallowDoubleCrossing) {
  const auto parabola = [](double depth) {  // y = x² − depth on x ∈ [−1, 1]
    const std::vector<Vec3> P = {{-1, 1 - depth, 0}, {0, -1 - depth, 0}, {1, 1 - depth, 0}};
    return make_bezier(P, {}, 2);
  };
  const NurbsCurve line = segment({-2, 0, 0}, {2, 0, 0});
  const IntersectionResult close = intersect(parabola(1e-9), line);
  ASSERT_EQ(close.points.size(), 1U);
  EXPECT_EQ(close.points[0].kind, IntersectionKind::Tangent);
  EXPECT_LT(norm(close.points[0].point - Vec3{0, -0.5e-9, 0}), 1e-12);
  const IntersectionResult apart = intersect(parabola(1e-3), line);
  ASSERT_EQ(apart.points.size(), 2U);
  for (const CurveIntersection& p : apart.points) {
    EXPECT_NEAR(std::fabs(p.point.x), std::sqrt(1e-3), 1e-14);
    EXPECT_EQ(p.kind, IntersectionKind::Crossing);
  }
}

// checks: space curves crossing at a designed point; skew lines none (construction).
TEST(Intersect, SpaceCurves) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 2, 1}, {2, -1, 2}, {3, 0, 0}};
  const NurbsCurve c = make_bezier(P);
  const Vec3 m = c.evaluate(0.37);
  const IntersectionResult r = intersect(c, segment(m - Vec3{1, 1, -2}, m + Vec3{1, 1, -2}));
  ASSERT_EQ(r.points.size(), 1U);
  EXPECT_LT(distance(r.points[0].point, m), 1e-14);
  EXPECT_NEAR(r.points[0].s, 0.37, 1e-13);
  EXPECT_TRUE(intersect(segment({0, 0, 0}, {1, 0, 0}), segment({0.5, -1, 1}, {0.5, 1, 1})).points.empty());
}

// A symmetric cubic with a loop: P0 = (0, 0), P1 = (a, h), P2 = (1 − a, h), P3 = (1, 0), a > 1. By symmetry
// C(1 − u) is C(u) mirrored in x = 1/2, so the loop closes at x(s) = 1/2 with t = 1 − s;
// x(u) = 3a u (1 − u)² + 3 (1 − a) u² (1 − u) + u³ is solved for s by bisection.
TEST(SelfIntersect, SymmetricLoopClosesOnTheAxis) {
  const double a = 2.0;
  const std::vector<Vec3> P = {{0, 0, 0}, {a, 1, 0}, {1 - a, 1, 0}, {1, 0, 0}};
  const NurbsCurve c = make_bezier(P, {}, 2);
  const auto x = [a](double u) { return 3 * a * u * (1 - u) * (1 - u) + 3 * (1 - a) * u * u * (1 - u) + u * u * u; };
  // x rises from 0 above 1/2 before the middle: the crossing's s is the first root of x = 1/2.
  double u_peak = 0.0;
  for (int k = 1; k < 1000; ++k)
    if (x(k / 2000.0) > x(u_peak)) u_peak = k / 2000.0;
  double lo = 0.0, hi = u_peak;
  for (int k = 0; k < 200; ++k) ((x(0.5 * (lo + hi)) < 0.5) ? lo : hi) = 0.5 * (lo + hi);
  const double s = 0.5 * (lo + hi);
  const IntersectionResult r = self_intersect(c);
  ASSERT_EQ(r.points.size(), 1U);
  EXPECT_NEAR(r.points[0].s, s, 1e-13);
  EXPECT_NEAR(r.points[0].t, 1 - s, 1e-13);
  EXPECT_NEAR(r.points[0].point.x, 0.5, 1e-14);
  EXPECT_EQ(r.points[0].kind, IntersectionKind::Crossing);
}

// checks: a circle (closed, four arcs) and an open arc do not meet themselves; a figure eight meets itself once at its
// centre.
TEST(SelfIntersect, ClosedCurvesAndFigureEight) {
  EXPECT_TRUE(self_intersect(circle(2.0, {1, 1, 0})).points.empty());
  EXPECT_TRUE(self_intersect(circle(2.0, {1, 1, 0})).overlaps.empty());
  // A lemniscate-like closed curve through the origin twice, interpolated (periodic by repeating the start).
  std::vector<Vec3> P;
  for (int k = 0; k <= 16; ++k) {
    const double th = 2 * std::numbers::pi * k / 16.0;
    P.push_back({std::sin(th), std::sin(th) * std::cos(th), 0});
  }
  // Symmetric under (x, y) → (−x, −y) and (x, −y) → mirror: the self-crossing is at the origin.
  std::vector<double> knots = {0, 0, 0, 0};
  for (int k = 1; k <= 13; ++k) knots.push_back(k / 14.0);
  knots.insert(knots.end(), {1, 1, 1, 1});
  const NurbsCurve eight(3, knots, P, {}, 2);
  const IntersectionResult r = self_intersect(eight);
  ASSERT_GE(r.points.size(), 1U);
  bool at_origin = false;
  for (const CurveIntersection& p : r.points) at_origin = at_origin || norm(p.point) < 1e-2;
  EXPECT_TRUE(at_origin);
}

// checks: a polyline that runs back over itself overlaps itself on the doubled stretch.
TEST(SelfIntersect, DoublingBackIsAnOverlap) {
  const NurbsCurve c(1, {0, 0, 1, 2, 2}, {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}}, {}, 2);
  const IntersectionResult r = self_intersect(c);
  EXPECT_TRUE(r.points.empty());
  ASSERT_EQ(r.overlaps.size(), 1U);
  EXPECT_NEAR(r.overlaps[0].s0, 0.5, 1e-12);
  EXPECT_NEAR(r.overlaps[0].s1, 1.0, 1e-9);
  EXPECT_NEAR(r.overlaps[0].t0, 2.0, 1e-12);
  EXPECT_NEAR(r.overlaps[0].t1, 1.0, 1e-9);
}

// checks: distance between disjoint circles is |c1 − c2| − R1 − R2 at the centre line (closed form); 0 where they meet.
TEST(CurveDistance, CirclesClosedForm) {
  const CurveDistanceResult d = curve_distance(circle(1.0, {}), circle(2.0, {5, 1, 0}));
  EXPECT_NEAR(d.distance, std::sqrt(26.0) - 3.0, 1e-14);
  EXPECT_NEAR(distance(d.point_a, d.point_b), d.distance, 1e-15);
  EXPECT_LT(std::fabs(norm(d.point_a) - 1.0), 1e-14);
  EXPECT_EQ(curve_distance(circle(1.0, {}), circle(1.0, {1, 0, 0})).distance <= 1e-14, true);
  // Concentric circles: every pair on a ray is nearest; the distance is R2 − R1.
  const CurveDistanceResult concentric = curve_distance(circle(1.0, {}), circle(1.5, {}, 2.0));
  EXPECT_NEAR(concentric.distance, 0.5, 1e-14);
  EXPECT_GE(concentric.lower_bound, concentric.distance - 1e-6);
  EXPECT_LE(concentric.lower_bound, concentric.distance);
}

// checks: a segment above a circle is nearest at the circle's top (closed form), a segment end when it points away.
TEST(CurveDistance, SegmentAndCircle) {
  const CurveDistanceResult d = curve_distance(segment({-2, 3, 0}, {2, 3, 0}), circle(1.0, {}));
  EXPECT_NEAR(d.distance, 2.0, 1e-14);
  EXPECT_LT(distance(d.point_b, {0, 1, 0}), 1e-7);
  const CurveDistanceResult e = curve_distance(segment({3, 0, 0}, {5, 0, 0}), circle(1.0, {}));
  EXPECT_NEAR(e.distance, 2.0, 1e-14);
  EXPECT_EQ(e.s, 0.0);
}

// checks: the same circle and secant at 1e200 and 1e-200 scale cross where the unit ones do, scaled (the solvers
// work on copies scaled by a power of two; nothing overflows or underflows).
TEST(Intersect, ExtremeScales) {
  for (const double k : {1e200, 1e-200}) {
    const IntersectionResult r = intersect(circle(k, {}), segment({-2 * k, 0.5 * k, 0}, {2 * k, 0.5 * k, 0}));
    ASSERT_EQ(r.points.size(), 2U) << "scale " << k;
    for (const CurveIntersection& p : r.points) {
      EXPECT_NEAR(std::fabs(p.point.x) / k, std::sqrt(3.0) / 2, 1e-14) << "scale " << k;
      EXPECT_LE(p.distance, 1e-14 * k);
    }
    const CurveDistanceResult d = curve_distance(circle(k, {}), circle(k, {3 * k, 0, 0}));
    EXPECT_NEAR(d.distance / k, 1.0, 1e-14) << "scale " << k;
  }
}

// checks: a curve collapsed to a point meets a line through it once and itself never.
TEST(Intersect, PointCurve) {
  const std::vector<Vec3> P = {{1, 1, 0}, {1, 1, 0}, {1, 1, 0}};
  const NurbsCurve point = make_bezier(P, {}, 2);
  const IntersectionResult r = intersect(point, segment({0, 0, 0}, {2, 2, 0}));
  ASSERT_EQ(r.points.size(), 1U);
  EXPECT_LT(distance(r.points[0].point, {1, 1, 0}), 1e-15);
  EXPECT_TRUE(self_intersect(point).points.empty());
  EXPECT_NEAR(curve_distance(point, segment({0, 3, 0}, {4, 3, 0})).distance, 2.0, 1e-15);
}

// checks: circles 3e-12 apart at a tolerance of 1e-12 cannot be told apart within the work limit: refused naming
// the tolerance, not hours of subdivision.
TEST(Intersect, RefusesNearCoincidenceBeyondTheWorkLimit) {
  IntersectOptions o;
  o.tolerance.resabs = 1e-12;
  HULA_EXPECT_ERROR(static_cast<void>(intersect(circle(1.0, {}), circle(1.0 + 3e-12, {}, 0.5), o)),
                    Errc::NumericalFailure, "tolerance");
}

// checks: invalid options name the field.
TEST(Intersect, RejectsBadOptions) {
  const NurbsCurve c = circle(1.0, {});
  IntersectOptions o;
  o.max_iterations = 0;
  HULA_EXPECT_ERROR(static_cast<void>(intersect(c, c, o)), Errc::InvalidOption, "max_iterations");
  o = {};
  o.tolerance.resabs = -1;
  HULA_EXPECT_ERROR(static_cast<void>(curve_distance(c, c, o)), Errc::InvalidOption, "resabs");
}

}  // namespace
}  // namespace hula::nurbs
