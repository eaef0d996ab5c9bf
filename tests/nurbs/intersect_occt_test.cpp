// SPDX-License-Identifier: MIT
// Oracle: curve–curve intersection, self-intersection and curve distance
// against Open CASCADE 7.6 on seeded corpora from two independent generators
// (random B-splines with random knot multiplicities and weights, as
// testing::random_curve draws them; and interpolated cubic splines, rational
// circles and rational Béziers), planar and spatial:
//   - planar: Geom2dAPI_InterCurveCurve (points and segments, and its
//     self-intersection form); every point it finds is one of ours within
//     1e-10, every point of ours lies on both curves by OCCT's own evaluator
//     (Geom2d_BSplineCurve::Value) within 1e-10, and every crossing of dense
//     polylines of the two curves, refined by a Newton iteration on OCCT's
//     derivatives (written here, independent of ours), is one of ours within
//     1e-10 — so a point both libraries miss is caught too;
//   - spatial: GeomAPI_ExtremaCurveCurve's zero-distance extrema and the
//     crossings built into the corpus (a spline interpolating points of the
//     other curve);
//   - distance: GeomAPI_ExtremaCurveCurve::LowerDistance, ours never larger
//     by more than 1e-10 and, where smaller, confirmed by OCCT's evaluator;
//     and never above the minimum over dense samples.
// OCCT misses intersections of some of these curves (its points are a strict
// subset of ours on the planar corpus); the counts are printed. OCCT's
// self-intersection form is replaced by pairwise intersection of the curve's
// pieces (see occt_points).
#include <gtest/gtest.h>

#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomAPI_ExtremaCurveCurve.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/intersect.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/occt_curve.hpp"

namespace hula::nurbs {
namespace {

using testing::to_occt;
using testing::to_occt_2d;
using testing::to_vec3;

// The curve with z dropped, as a 2-D curve.
NurbsCurve planar(const NurbsCurve& c) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p.z = 0.0;
  return NurbsCurve(c.knots(), std::move(P), {c.weights().begin(), c.weights().end()}, 2);
}

NurbsCurve transformed(const NurbsCurve& c, double scale, const Vec3& shift) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p = scale * p + shift;
  return NurbsCurve(c.knots(), std::move(P), {c.weights().begin(), c.weights().end()}, c.dimension());
}

// Generator 1: random B-splines (degree 1–5, random interior multiplicities, half of them rational).
NurbsCurve generator1(Rng& rng, int dimension, int extra) {
  const NurbsCurve c = testing::random_curve(
      rng, {.degree = 1 + static_cast<int>(rng.below(5)), .rational = rng.below(2) == 0, .extra_points = extra});
  return dimension == 2 ? planar(c) : c;
}

// Generator 2: a chord-length cubic spline through random points, a rational circle, or a rational Bézier.
NurbsCurve generator2(Rng& rng, int dimension, int extra) {
  const auto kind = rng.below(3);
  const auto point = [&] {
    return Vec3{rng.uniform(-8.0, 8.0), rng.uniform(-8.0, 8.0), dimension == 3 ? rng.uniform(-8.0, 8.0) : 0.0};
  };
  if (kind == 0) {
    std::vector<Vec3> P(static_cast<std::size_t>(4 + extra));
    for (Vec3& p : P) p = point();
    InterpolationOptions o;
    o.dimension = dimension;
    return interpolate_cubic(P, o);
  }
  if (kind == 1) {
    const NurbsCurve c = testing::rational_circle(1.0, rng.uniform(0.0, 6.0));
    const NurbsCurve c3 = dimension == 2 ? c
                                         : NurbsCurve(c.knots(), {c.control_points().begin(), c.control_points().end()},
                                                      {c.weights().begin(), c.weights().end()}, 3);
    return transformed(c3, rng.uniform(0.5, 6.0), point());
  }
  std::vector<Vec3> P(static_cast<std::size_t>(3 + rng.below(4)));
  std::vector<double> w(P.size());
  for (Vec3& p : P) p = point();
  for (double& x : w) x = rng.uniform(0.3, 3.0);
  return make_bezier(P, w, dimension);
}

// Newton on A(s) − B(t) = 0 with OCCT's first derivatives (2-D), from a seed; the test's own solver.
struct Refined {
  double s = 0.0, t = 0.0;
  bool converged = false;
};
Refined refine_with_occt(const Handle(Geom2d_BSplineCurve) & a, const Handle(Geom2d_BSplineCurve) & b, double s,
                         double t) {
  for (int it = 0; it < 60; ++it) {
    gp_Pnt2d pa, pb;
    gp_Vec2d da, db;
    a->D1(s, pa, da);
    b->D1(t, pb, db);
    const double rx = pa.X() - pb.X(), ry = pa.Y() - pb.Y();
    const double det = -da.X() * db.Y() + da.Y() * db.X();  // J = [da, −db]
    if (det == 0.0) return {s, t, false};
    const double ds = -(-db.Y() * rx + db.X() * ry) / det;  // −J⁻¹ r, J⁻¹ = [[−db.y, db.x], [−da.y, da.x]] / det
    const double dt = -(-da.Y() * rx + da.X() * ry) / det;
    s = std::clamp(s + ds, a->FirstParameter(), a->LastParameter());
    t = std::clamp(t + dt, b->FirstParameter(), b->LastParameter());
    if (a->Value(s).Distance(b->Value(t)) <= 1e-13) return {s, t, true};
  }
  return {s, t, false};
}

// Crossings of dense polylines of the two curves (of one curve with itself when `self`, the closure of a
// closed curve left out), refined by refine_with_occt. Blocks of 16 segments are culled by their boxes.
std::vector<Vec3> polyline_crossings(const NurbsCurve& a, const NurbsCurve& b, bool self, int n = 1024) {
  const auto samples = [n](const NurbsCurve& c) {
    std::vector<double> ts(static_cast<std::size_t>(n) + 1);
    for (int k = 0; k <= n; ++k)
      ts[static_cast<std::size_t>(k)] = k == n ? c.domain().end : c.domain().start + c.domain().length() * k / n;
    return ts;
  };
  const std::vector<double> ta = samples(a), tb = samples(b);
  std::vector<Vec3> pa(ta.size()), pb(tb.size());
  a.evaluate(ta, pa);
  b.evaluate(tb, pb);
  constexpr std::size_t kBlock = 16;
  const auto blocks = [](const std::vector<Vec3>& p) {
    std::vector<Box3> out;
    for (std::size_t k = 0; k + 1 < p.size(); k += kBlock) {
      Box3 box;
      for (std::size_t j = k; j <= std::min(k + kBlock, p.size() - 1); ++j) box.add(p[j]);
      out.push_back(box);
    }
    return out;
  };
  const std::vector<Box3> ba = blocks(pa), bb = blocks(pb);
  const Handle(Geom2d_BSplineCurve) oa = to_occt_2d(a), ob = to_occt_2d(b);
  const bool closed = self && distance(pa.front(), pa.back()) <= 1e-12;
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < ba.size(); ++i)
    for (std::size_t j = self ? i : 0; j < bb.size(); ++j) {
      if (ba[i].min.x > bb[j].max.x || bb[j].min.x > ba[i].max.x || ba[i].min.y > bb[j].max.y ||
          bb[j].min.y > ba[i].max.y)
        continue;
      for (std::size_t x = i * kBlock; x < std::min((i + 1) * kBlock, pa.size() - 1); ++x)
        for (std::size_t y = j * kBlock; y < std::min((j + 1) * kBlock, pb.size() - 1); ++y) {
          if (self && y < x + 2) continue;
          const Vec3 d1 = pa[x + 1] - pa[x], d2 = pb[y + 1] - pb[y], r0 = pb[y] - pa[x];
          const double den = d1.x * d2.y - d1.y * d2.x;
          if (den == 0.0) continue;
          const double u = (r0.x * d2.y - r0.y * d2.x) / den, v = (r0.x * d1.y - r0.y * d1.x) / den;
          if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) continue;
          const Refined r = refine_with_occt(oa, ob, ta[x] + u * (ta[x + 1] - ta[x]), tb[y] + v * (tb[y + 1] - tb[y]));
          if (!r.converged) continue;
          if (self && (std::fabs(r.s - r.t) < 1e-9 || (closed && std::fmin(r.s, r.t) - a.domain().start < 1e-9 &&
                                                       a.domain().end - std::fmax(r.s, r.t) < 1e-9)))
            continue;
          out.push_back(to_vec3(oa->Value(r.s)));
        }
    }
  return out;
}

double nearest_point(const IntersectionResult& r, const Vec3& q) {
  double best = HUGE_VAL;
  for (const CurveIntersection& p : r.points) best = std::min(best, distance(p.point, q));
  return best;
}

struct Tally {
  int occt = 0, ours = 0, polyline = 0;
};

// OCCT's meeting points of two curves, or of one curve with itself. OCCT 7.6's own self-intersection
// form returns spurious "segments" along the diagonal u = v from the curve's start, so a curve is cut
// (Geom2d_TrimmedCurve) at its breakpoints and the quarters of each span, and the pieces are intersected
// pairwise with the two-curve form; the point shared by neighbouring pieces (and the closure of a closed
// curve) is left out.
std::vector<Vec3> occt_points(const NurbsCurve& a, const NurbsCurve& b, bool self, int* segments) {
  const Handle(Geom2d_BSplineCurve) oa = to_occt_2d(a), ob = to_occt_2d(b);
  std::vector<Vec3> out;
  *segments = 0;
  if (!self) {
    const Geom2dAPI_InterCurveCurve occt(oa, ob, 1e-9);
    for (int k = 1; k <= occt.NbPoints(); ++k) out.push_back(to_vec3(occt.Point(k)));
    *segments = occt.NbSegments();
    return out;
  }
  std::vector<double> cuts;
  const std::vector<double> breaks = a.knots().breakpoints();
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
    for (int q = 0; q < 4; ++q) cuts.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * q / 4.0);
  cuts.push_back(breaks.back());
  const bool closed = distance(a.evaluate(breaks.front()), a.evaluate(breaks.back())) <= 1e-12;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    for (std::size_t j = i + 1; j + 1 < cuts.size(); ++j) {
      const Handle(Geom2d_TrimmedCurve) pi = new Geom2d_TrimmedCurve(oa, cuts[i], cuts[i + 1]);
      const Handle(Geom2d_TrimmedCurve) pj = new Geom2d_TrimmedCurve(oa, cuts[j], cuts[j + 1]);
      const Geom2dAPI_InterCurveCurve occt(pi, pj, 1e-9);
      *segments += occt.NbSegments();
      for (int k = 1; k <= occt.NbPoints(); ++k) {
        const Vec3 q = to_vec3(occt.Point(k));
        if (j == i + 1 && distance(q, a.evaluate(cuts[j])) <= 1e-9) continue;
        if (closed && i == 0 && j + 2 == cuts.size() && distance(q, a.evaluate(cuts[0])) <= 1e-9) continue;
        out.push_back(q);
      }
    }
  return out;
}

// The planar checks of one pair (or of one curve, `self`).
void check_planar(const NurbsCurve& a, const NurbsCurve& b, bool self, int index, Tally& tally) {
  const Handle(Geom2d_BSplineCurve) oa = to_occt_2d(a), ob = to_occt_2d(b);
  int segments = 0;
  const std::vector<Vec3> occt = occt_points(a, b, self, &segments);
  const IntersectionResult r = self ? self_intersect(a) : intersect(a, b);
  ASSERT_EQ(segments, 0) << "case " << index;  // no coincident stretches in random corpora
  EXPECT_TRUE(r.overlaps.empty()) << "case " << index;
  tally.occt += static_cast<int>(occt.size());
  tally.ours += static_cast<int>(r.points.size());
  for (std::size_t k = 0; k < occt.size(); ++k)
    EXPECT_LE(nearest_point(r, occt[k]), 1e-10) << "case " << index << ": OCCT point " << k << " missed";
  for (const CurveIntersection& p : r.points) {
    const double gap = oa->Value(p.s).Distance(ob->Value(p.t));
    EXPECT_LE(gap, 1e-10) << "case " << index << ": s = " << p.s << ", t = " << p.t << " is not on both curves";
    if (self) {
      EXPECT_LT(p.s, p.t) << "case " << index;
    }
  }
  for (const Vec3& q : polyline_crossings(a, b, self)) {
    ++tally.polyline;
    EXPECT_LE(nearest_point(r, q), 1e-10)
        << "case " << index << ": polyline crossing (" << q.x << ", " << q.y << ") missed";
  }
}

// checks: planar intersections of both generators' curves, against Geom2dAPI_InterCurveCurve and refined
// polyline crossings (1e-10, none missed).
TEST(IntersectOcct, PlanarPairsOfBothGenerators) {
  Rng rng(2026);
  Tally tally;
  for (int i = 0; i < 180; ++i) {
    const int extra = static_cast<int>(rng.below(6));
    const NurbsCurve a = i % 3 == 1 ? generator2(rng, 2, extra) : generator1(rng, 2, extra);
    const NurbsCurve b = i % 3 == 0 ? generator1(rng, 2, extra) : generator2(rng, 2, extra);
    check_planar(a, b, false, i, tally);
  }
  std::printf("planar pairs: OCCT %d points, ours %d, refined polyline crossings %d\n", tally.occt, tally.ours,
              tally.polyline);
  EXPECT_GE(tally.ours, tally.occt);
  EXPECT_GT(tally.occt, 300);  // the corpus does cross
}

// checks: planar self-intersections against Geom2dAPI_InterCurveCurve's self form and refined polyline
// self-crossings (1e-10, none missed).
TEST(IntersectOcct, PlanarSelfIntersections) {
  Rng rng(2027);
  Tally tally;
  for (int i = 0; i < 80; ++i) {
    const int extra = 4 + static_cast<int>(rng.below(8));
    const NurbsCurve c = i % 2 == 0 ? generator1(rng, 2, extra) : generator2(rng, 2, extra);
    check_planar(c, c, true, i, tally);
  }
  std::printf("self: OCCT %d points, ours %d, refined polyline crossings %d\n", tally.occt, tally.ours, tally.polyline);
  EXPECT_GE(tally.ours, tally.occt);
  EXPECT_GT(tally.occt, 50);
}

// checks: space curves crossing at built-in points: each built-in crossing and each zero-distance extremum of
// GeomAPI_ExtremaCurveCurve is one of ours (1e-10), each of ours lies on both curves by OCCT's evaluator.
TEST(IntersectOcct, SpaceCurvesWithBuiltInCrossings) {
  Rng rng(2028);
  int built = 0, occt_zero = 0;
  for (int i = 0; i < 60; ++i) {
    const NurbsCurve a = i % 2 == 0 ? generator1(rng, 3, 3) : generator2(rng, 3, 3);
    const Interval d = a.domain();
    std::vector<Vec3> through, crossings;
    through.push_back({rng.uniform(-8.0, 8.0), rng.uniform(-8.0, 8.0), rng.uniform(-8.0, 8.0)});
    for (int k = 0; k < 3; ++k) {
      crossings.push_back(a.evaluate(d.start + d.length() * (0.15 + 0.3 * k + rng.uniform(0.0, 0.1))));
      through.push_back(crossings.back());
      through.push_back({rng.uniform(-8.0, 8.0), rng.uniform(-8.0, 8.0), rng.uniform(-8.0, 8.0)});
    }
    const NurbsCurve b = interpolate_cubic(through);
    const IntersectionResult r = intersect(a, b);
    const Handle(Geom_BSplineCurve) oa = to_occt(a), ob = to_occt(b);
    for (const Vec3& q : crossings) {
      ++built;
      EXPECT_LE(nearest_point(r, q), 1e-10) << "case " << i << ": built-in crossing missed";
    }
    GeomAPI_ExtremaCurveCurve ext(oa, ob);
    for (int k = 1; k <= ext.NbExtrema(); ++k)
      if (ext.Distance(k) <= 1e-9) {
        ++occt_zero;
        gp_Pnt p1, p2;
        ext.Points(k, p1, p2);
        EXPECT_LE(nearest_point(r, to_vec3(p1)), 1e-10) << "case " << i << ": OCCT extremum " << k << " missed";
      }
    for (const CurveIntersection& p : r.points)
      EXPECT_LE(oa->Value(p.s).Distance(ob->Value(p.t)), 1e-10) << "case " << i << ": not on both curves";
  }
  std::printf("space: %d built-in crossings, %d zero-distance OCCT extrema\n", built, occt_zero);
}

// checks: tangent contacts (circles and lines, two circles) are found by OCCT as points or short segments
// near the closed-form contact, and by us as one tangent point within 1e-10 of it.
TEST(IntersectOcct, TangentContacts) {
  Rng rng(2029);
  for (int i = 0; i < 40; ++i) {
    const double R1 = rng.uniform(0.5, 5.0), R2 = rng.uniform(0.5, 5.0), phi = rng.uniform(0.0, 6.28);
    const Vec3 c1{rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), 0};
    const Vec3 dir{std::cos(phi), std::sin(phi), 0};
    const bool inner = i % 2 == 1 && R1 != R2;
    const double gap = inner ? std::fabs(R1 - R2) : R1 + R2;
    const Vec3 c2 = c1 + gap * dir;
    const Vec3 contact = inner && R1 < R2 ? c1 - R1 * dir : c1 + R1 * dir;
    const NurbsCurve a = transformed(testing::rational_circle(1.0, rng.uniform(0.0, 6.0)), R1, c1);
    const NurbsCurve b = transformed(testing::rational_circle(1.0, rng.uniform(0.0, 6.0)), R2, c2);
    const IntersectionResult r = intersect(a, b);
    ASSERT_EQ(r.points.size(), 1U) << "case " << i;
    EXPECT_EQ(r.points[0].kind, IntersectionKind::Tangent) << "case " << i;
    EXPECT_LE(distance(r.points[0].point, contact), 1e-10) << "case " << i;
    const Geom2dAPI_InterCurveCurve occt(to_occt_2d(a), to_occt_2d(b), 1e-7);
    double occt_best = HUGE_VAL;
    for (int k = 1; k <= occt.NbPoints(); ++k)
      occt_best = std::min(occt_best, distance(to_vec3(occt.Point(k)), contact));
    for (int k = 1; k <= occt.NbSegments(); ++k) {
      const IntRes2d_IntersectionSegment& seg = occt.Intersector().Segment(k);
      if (seg.HasFirstPoint()) occt_best = std::min(occt_best, distance(to_vec3(seg.FirstPoint().Value()), contact));
    }
    EXPECT_LE(occt_best, 1e-3) << "case " << i << ": OCCT sees no contact";
  }
}

// checks: a curve against a piece of itself: OCCT reports one segment, we report one overlap with the piece's
// ends to 1e-10.
TEST(IntersectOcct, OverlapWithAPieceOfItself) {
  Rng rng(2030);
  for (int i = 0; i < 30; ++i) {
    const NurbsCurve c = i % 2 == 0 ? generator1(rng, 2, 3) : generator2(rng, 2, 3);
    const Interval d = c.domain();
    const double u0 = d.start + d.length() * rng.uniform(0.05, 0.45),
                 u1 = d.start + d.length() * rng.uniform(0.55, 0.95);
    const NurbsCurve piece = split(split(c, u0).after, u1).before;
    const NurbsCurve b = i % 4 < 2 ? piece : reverse(piece);
    const IntersectionResult r = intersect(c, b);
    ASSERT_EQ(r.overlaps.size(), 1U) << "case " << i;
    EXPECT_LE(distance(r.overlaps[0].start, c.evaluate(u0)), 1e-10) << "case " << i;
    EXPECT_LE(distance(r.overlaps[0].end, c.evaluate(u1)), 1e-10) << "case " << i;
    for (const CurveIntersection& p : r.points)  // only points of c that b does not cover
      EXPECT_TRUE(p.s < u0 - 1e-9 || p.s > u1 + 1e-9) << "case " << i << " s = " << p.s;
    const Geom2dAPI_InterCurveCurve occt(to_occt_2d(c), to_occt_2d(b), 1e-7);
    EXPECT_GE(occt.NbSegments(), 1) << "case " << i;
  }
}

// checks: curve distance of disjoint space curves: never above GeomAPI_ExtremaCurveCurve::LowerDistance by
// 1e-10, confirmed by OCCT's evaluator, and never above the minimum over dense samples.
TEST(IntersectOcct, DistanceAgainstExtrema) {
  Rng rng(2031);
  int below = 0;
  for (int i = 0; i < 80; ++i) {
    const NurbsCurve a = i % 2 == 0 ? generator1(rng, 3, 2) : generator2(rng, 3, 2);
    const NurbsCurve b0 = i % 3 == 0 ? generator1(rng, 3, 2) : generator2(rng, 3, 2);
    const NurbsCurve b = transformed(b0, 1.0, {rng.uniform(-6.0, 6.0), rng.uniform(-6.0, 6.0), rng.uniform(-6.0, 6.0)});
    const CurveDistanceResult ours = curve_distance(a, b);
    const Handle(Geom_BSplineCurve) oa = to_occt(a), ob = to_occt(b);
    EXPECT_NEAR(oa->Value(ours.s).Distance(ob->Value(ours.t)), ours.distance, 1e-12) << "case " << i;
    GeomAPI_ExtremaCurveCurve ext(oa, ob);
    if (ext.NbExtrema() > 0) {
      EXPECT_LE(ours.distance, ext.LowerDistance() + 1e-10) << "case " << i;
      if (ours.distance < ext.LowerDistance() - 1e-10) ++below;
    }
    double sampled = HUGE_VAL;
    const int n = 400;
    std::vector<Vec3> pa(n + 1), pb(n + 1);
    for (int k = 0; k <= n; ++k) {
      pa[static_cast<std::size_t>(k)] =
          a.evaluate(k == n ? a.domain().end : a.domain().start + a.domain().length() * k / n);
      pb[static_cast<std::size_t>(k)] =
          b.evaluate(k == n ? b.domain().end : b.domain().start + b.domain().length() * k / n);
    }
    for (const Vec3& p : pa)
      for (const Vec3& q : pb) sampled = std::min(sampled, distance(p, q));
    EXPECT_LE(ours.distance, sampled + 1e-12) << "case " << i;
  }
  std::printf("distance: ours below OCCT's LowerDistance in %d of 80 cases\n", below);
}

}  // namespace
}  // namespace hula::nurbs
