// SPDX-License-Identifier: MIT
// Match and Blend checked from each curve's own derivatives (frenet at the
// joint), not from the construction: after Match at Gk the position, unit
// tangent, curvature vector and (G3) torsion and dκ/ds of A's end equal B's at
// the target to 1e-9 relative, and only the last k + 1 poles moved; Blend is
// checked the same way at both ends, its scale search against the unscaled
// Hermite and its curvature-extrema count against dense sampling of dκ/ds.
// Curves come from two seeded generators (random B-splines with random knot
// multiplicities, cubic interpolants through random points), planar and space.
#include "hula/diffgeom/match_blend.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

nurbs::NurbsCurve planar(const nurbs::NurbsCurve& c) {
  std::vector<Vec3> p(c.control_points().begin(), c.control_points().end());
  for (Vec3& q : p) q.z = 0.0;
  return nurbs::NurbsCurve(c.knots(), std::move(p), {}, 2);
}

// Generator 1: random non-rational clamped B-spline (random interior knot multiplicities), degree 3 … 5.
nurbs::NurbsCurve random_spline(Rng& rng, bool plane) {
  testing::RandomCurveSpec spec;
  spec.degree = 3 + static_cast<int>(rng.uniform() * 3.0) % 3;
  spec.extra_points = 3;
  const nurbs::NurbsCurve c = testing::random_curve(rng, spec);
  return plane ? planar(c) : c;
}

// Generator 2: the cubic spline through 6 random points with random end tangents.
nurbs::NurbsCurve random_interpolant(Rng& rng, bool plane) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 6; ++i)
    pts.push_back({rng.uniform(-5, 5) + 3.0 * i, rng.uniform(-5, 5), plane ? 0.0 : rng.uniform(-5, 5)});
  nurbs::InterpolationOptions o;
  o.dimension = plane ? 2 : 3;
  // Clamped end tangents (a natural end has κ = 0 there, no frame to match at G3).
  o.start = nurbs::EndCondition::direction({1.0, rng.uniform(-1, 1), plane ? 0.0 : rng.uniform(-1, 1)});
  o.end = nurbs::EndCondition::direction({1.0, rng.uniform(-1, 1), plane ? 0.0 : rng.uniform(-1, 1)});
  return nurbs::interpolate_cubic(pts, o);
}

// Compares the Frenet data of x at tx with y's at ty, x's direction being `sign` times y's, up to `order`.
void expect_geometric(const nurbs::NurbsCurve& x, double tx, const nurbs::NurbsCurve& y, double ty, double sign,
                      int order, double size, const std::string& what) {
  const FrenetPoint fx = frenet(x, tx);
  const FrenetPoint fy = frenet(y, ty);
  const double eps = 1e-9;
  EXPECT_LE(distance(fx.position, fy.position), eps * size) << what;
  if (order < 1) return;
  EXPECT_LE(distance(fx.tangent, fy.tangent * sign), eps) << what;
  if (order < 2) return;
  const Vec3 kx = fx.frame_defined ? fx.normal * fx.curvature : Vec3{};
  const Vec3 ky = fy.frame_defined ? fy.normal * fy.curvature : Vec3{};
  EXPECT_LE(distance(kx, ky), eps * std::max({fx.curvature, fy.curvature, 1.0 / size})) << what;
  if (order < 3) return;
  ASSERT_TRUE(fx.frame_defined && fy.frame_defined) << what;
  EXPECT_LE(std::fabs(fx.torsion - fy.torsion), eps * std::max({std::fabs(fy.torsion), 1.0 / size})) << what;
  EXPECT_LE(std::fabs(fx.curvature_derivative - sign * fy.curvature_derivative),
            eps * std::max({std::fabs(fy.curvature_derivative), 1.0 / (size * size)}))
      << what;
}

using Generator = nurbs::NurbsCurve (*)(Rng&, bool);

// checks Gk at A's end or start to B's start, end or a parameter, from both generators, planar and space, and that
// exactly the last (first) k + 1 poles moved.
TEST(Match, ReachesOrderFromOwnDerivatives) {
  Rng rng(20261207);
  const std::array<Generator, 2> gens{random_spline, random_interpolant};
  int cases = 0;
  for (const Generator gen : gens) {
    for (const bool plane : {true, false}) {
      for (int rep = 0; rep < 6; ++rep) {
        const nurbs::NurbsCurve a = gen(rng, plane);
        const nurbs::NurbsCurve b = gen(rng, plane);
        for (int k = 0; k <= 3; ++k) {
          MatchOptions o;
          o.continuity = k;
          o.end = rep % 2 == 0 ? CurveEnd::End : CurveEnd::Start;
          o.target_end = rep % 3 == 0 ? CurveEnd::End : CurveEnd::Start;
          o.use_parameter = rep >= 4;
          o.at = b.domain().start + rng.uniform(0.2, 0.8) * b.domain().length();
          const MatchResult r = match_end(a, b, o);
          const std::string what =
              "k=" + std::to_string(k) + " rep=" + std::to_string(rep) + (plane ? " planar" : " space");
          ASSERT_EQ(r.inserted_knots, 0) << what;
          ASSERT_EQ(r.degree_elevation, 0) << what;
          // Only the expected poles moved (all others bit for bit).
          const std::size_t n = a.control_points().size() - 1;
          std::vector<int> expected;
          for (int i = 0; i <= k; ++i) expected.push_back(o.end == CurveEnd::End ? static_cast<int>(n) - i : i);
          std::sort(expected.begin(), expected.end());
          EXPECT_EQ(r.moved, expected) << what;
          for (std::size_t i = 0; i <= n; ++i) {
            if (std::find(expected.begin(), expected.end(), static_cast<int>(i)) != expected.end()) continue;
            EXPECT_EQ(r.curve.control_points()[i], a.control_points()[i]) << what << " pole " << i;
          }
          // The joint from each curve's own derivatives. Direction: B continues A (to B's start), runs back (to B's
          // end) or follows A's own end tangent (at a parameter); at A's start the roles flip.
          const double ta = o.end == CurveEnd::End ? a.domain().end : a.domain().start;
          const double tb = o.use_parameter                   ? o.at
                            : o.target_end == CurveEnd::Start ? b.domain().start
                                                              : b.domain().end;
          double s = o.target_end == CurveEnd::Start ? 1.0 : -1.0;
          if (o.use_parameter) {
            const Vec3 da = a.derivatives(ta, 1)[1] * (o.end == CurveEnd::End ? 1.0 : -1.0);
            s = dot(da, b.derivatives(tb, 1)[1]) < 0.0 ? -1.0 : 1.0;
          }
          const double sign = o.end == CurveEnd::End ? s : -s;
          const double size = std::max(a.model_size(), b.model_size());
          expect_geometric(r.curve, ta, b, tb, sign, k, size, what);
          EXPECT_GE(r.continuity.geometric, k) << what;
          ++cases;
        }
      }
    }
  }
  EXPECT_EQ(cases, 96);
}

// checks a cubic Bézier (4 poles) matched at G3 first gets a knot so that its start pole stays, and a quadratic is
// raised to degree 3.
TEST(Match, InsertsKnotsAndElevatesWhenNeeded) {
  const nurbs::NurbsCurve a(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
  const nurbs::NurbsCurve b(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{4, 1, 0}, {5, 2, 1}, {6, 1, 0}, {7, 3, 1}});
  MatchOptions o;
  o.continuity = 3;
  const MatchResult r = match_end(a, b, o);
  EXPECT_GE(r.inserted_knots, 1);
  EXPECT_EQ(r.curve.control_points().front(), a.control_points().front());
  expect_geometric(r.curve, 1.0, b, 0.0, 1.0, 3, 8.0, "bezier");
  const nurbs::NurbsCurve q(2, {0, 0, 0, 0.5, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
  const MatchResult rq = match_end(q, b, o);
  EXPECT_EQ(rq.degree_elevation, 1);
  EXPECT_EQ(rq.curve.degree(), 3);
  expect_geometric(rq.curve, 1.0, b, 0.0, 1.0, 3, 8.0, "quadratic");
}

// checks the tangent length of A's end is kept by default and scaled by tangent_scale.
TEST(Match, KeepsEndSpeed) {
  Rng rng(7);
  const nurbs::NurbsCurve a = random_interpolant(rng, false);
  const nurbs::NurbsCurve b = random_interpolant(rng, false);
  const double v = norm(a.derivatives(a.domain().end, 1)[1]);
  MatchOptions o;
  o.continuity = 2;
  EXPECT_NEAR(norm(match_end(a, b, o).curve.derivatives(a.domain().end, 1)[1]), v, 1e-9 * v);
  o.tangent_scale = 2.0;
  EXPECT_NEAR(norm(match_end(a, b, o).curve.derivatives(a.domain().end, 1)[1]), 2.0 * v, 1e-9 * v);
}

// checks bad input is refused with the field named.
TEST(Match, RefusesBadInput) {
  const nurbs::NurbsCurve a(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
  MatchOptions o;
  o.continuity = 4;
  EXPECT_THROW((void)match_end(a, a, o), Error);
  o.continuity = 2;
  o.use_parameter = true;
  o.at = 2.0;
  try {
    (void)match_end(a, a, o);
    ADD_FAILURE() << "no throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::OutOfDomain);
  }
  const nurbs::NurbsCurve w(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {1, 2, 1});
  EXPECT_THROW((void)match_end(w, a, {}), Error);
}

// Sign changes of dκ/ds over 20,000 samples (an upper bound of the significant extrema).
int sampled_extrema(const nurbs::NurbsCurve& c) {
  int changes = 0;
  double prev = 0.0;
  for (int i = 1; i < 20000; ++i) {
    const double t = c.domain().start + c.domain().length() * i / 20000.0;
    const double d = frenet(c, t).curvature_derivative;
    if (d != 0.0 && prev != 0.0 && (d > 0.0) != (prev > 0.0)) ++changes;
    if (d != 0.0) prev = d;
  }
  return changes;
}

// checks the blend is Gk at both ends from its own derivatives, its ∫κ'² ds is no higher than the unscaled (m = 1)
// Hermite's, and its extrema count agrees with sampling.
TEST(Blend, BothEndsAndFairness) {
  Rng rng(4242);
  const std::array<Generator, 2> gens{random_spline, random_interpolant};
  for (const Generator gen : gens) {
    for (const bool plane : {true, false}) {
      for (int rep = 0; rep < 2; ++rep) {
        const nurbs::NurbsCurve a = gen(rng, plane);
        nurbs::NurbsCurve b = gen(rng, plane);
        for (int k = 1; k <= 3; ++k) {
          BlendOptions o;
          o.continuity = k;
          o.iterations = 20;
          const BlendResult r = blend(a, b, o);
          const std::string what = "k=" + std::to_string(k) + (plane ? " planar" : " space");
          const double size = std::max({a.model_size(), b.model_size(), r.curve.model_size()});
          expect_geometric(r.curve, 0.0, a, a.domain().end, 1.0, k, size, what + " start");
          expect_geometric(r.curve, 1.0, b, b.domain().start, 1.0, k, size, what + " end");
          EXPECT_GE(r.start.geometric, k) << what;
          EXPECT_GE(r.end.geometric, k) << what;
          BlendOptions unit = o;
          unit.min_scale = 0.999999;
          unit.max_scale = 1.000001;
          unit.iterations = 1;
          const BlendResult u = blend(a, b, unit);
          EXPECT_LE(r.curvature_variation.value, u.curvature_variation.value * (1.0 + 1e-6)) << what;
          EXPECT_GT(r.curvature_variation.value, 0.0) << what;
          const int sampled = sampled_extrema(r.curve);
          EXPECT_LE(r.curvature_extrema, sampled) << what;
          EXPECT_GE(r.curvature_extrema, std::min(sampled, 1)) << what;
        }
      }
    }
  }
}

// checks a blend from A's start or to B's end is the blend of the reversed curves, bit for bit, and that it leaves
// A's start outwards (its start tangent against A's) and reaches B's end inwards (its end tangent along B's).
TEST(Blend, EitherEndOfEachCurve) {
  const nurbs::NurbsCurve a(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
  const nurbs::NurbsCurve b(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {{6, 3, 0}, {7, 4, 0}, {8, 3, 1}, {9, 2, 0}, {9, 1, 0}});
  for (const CurveEnd from : {CurveEnd::Start, CurveEnd::End}) {
    for (const CurveEnd to : {CurveEnd::Start, CurveEnd::End}) {
      BlendOptions o;
      o.continuity = 3;
      o.iterations = 12;
      o.end = from;
      o.target_end = to;
      const BlendResult r = blend(a, b, o);
      const nurbs::NurbsCurve ra = from == CurveEnd::Start ? nurbs::reverse(a) : a;
      const nurbs::NurbsCurve rb = to == CurveEnd::End ? nurbs::reverse(b) : b;
      BlendOptions forward = o;
      forward.end = CurveEnd::End;
      forward.target_end = CurveEnd::Start;
      const BlendResult f = blend(ra, rb, forward);
      const auto poles = [](const nurbs::NurbsCurve& c) {
        return std::vector<Vec3>(c.control_points().begin(), c.control_points().end());
      };
      EXPECT_EQ(poles(r.curve), poles(f.curve));
      EXPECT_EQ(r.scale, f.scale);
      EXPECT_GE(r.start.geometric, 3);
      EXPECT_GE(r.end.geometric, 3);
      const double ta = from == CurveEnd::Start ? a.domain().start : a.domain().end;
      const double tb = to == CurveEnd::Start ? b.domain().start : b.domain().end;
      const auto da = a.derivatives(ta, 1);
      const auto db = b.derivatives(tb, 1);
      const auto d0 = r.curve.derivatives(0.0, 1);
      const auto d1 = r.curve.derivatives(1.0, 1);
      EXPECT_LT(distance(d0[0], da[0]), 1e-12);
      EXPECT_LT(distance(d1[0], db[0]), 1e-12);
      // Leaving A: along A' at its end, against it at its start; reaching B: along B' at its start.
      EXPECT_GT(dot(d0[1], da[1]) * (from == CurveEnd::End ? 1.0 : -1.0), 0.0);
      EXPECT_GT(dot(d1[1], db[1]) * (to == CurveEnd::Start ? 1.0 : -1.0), 0.0);
    }
  }
}

// checks coincident ends and a bad order are refused.
TEST(Blend, RefusesBadInput) {
  const nurbs::NurbsCurve a(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
  const nurbs::NurbsCurve b(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{3, 0, 0}, {4, 1, 0}, {5, 1, 0}, {6, 0, 0}});
  EXPECT_THROW((void)blend(a, b, {}), Error);
  BlendOptions o;
  o.continuity = 0;
  EXPECT_THROW((void)blend(a, a, o), Error);
}

}  // namespace
}  // namespace hula::diffgeom
