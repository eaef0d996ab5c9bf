// SPDX-License-Identifier: MIT
// checks: round trip random NURBS → κ(s), τ(s) (laws of arc length) → curve from
// natural equations reproduces the NURBS up to a rigid motion, against the
// original curve evaluated at t = nurbs::parameter_at_length(s).
//
// κ(s), τ(s) are built as laws: t(s) is a quintic Hermite NURBS through
// (s_i, t_i) with t_i from parameter_at_length and the exact derivatives
// dt/ds = 1/|C'|, d²t/ds² = −(C'·C'')/|C'|⁴, and the Frenet laws of the curve
// (diffgeom::frenet_laws of law::from_nurbs) are composed with it. The
// reconstruction starts at C(0) with the original's T(0), N(0), so the rigid
// motion is the identity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/diffgeom/frenet_law.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/convert.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::intrinsic {
namespace {

using law::Law;

struct RoundTrip {
  double length = 0.0;
  double size = 0.0;           // bounding-box diagonal of the control polygon
  double fit_error = 0.0;      // max |t_fit(s) − t(s)| at `checks` points, t(s) by parameter_at_length
  double max_deviation = 0.0;  // max |reconstructed(s) − C(t(s))|
};

// t(s) as a quintic Hermite NURBS of u = s / L ∈ [0, 1], with `segments` breakpoints uniform in t (so
// they crowd in s where the curve is slow and t(s) bends most) at s_i = arc_length(t0, t_i).
nurbs::NurbsCurve arc_length_inverse(const nurbs::NurbsCurve& c, double length, int segments) {
  const nurbs::Interval dom = c.domain();
  std::vector<Vec3> q, d1, d2;
  std::vector<double> u;
  double s = 0.0, t_prev = dom.start;
  for (int i = 0; i <= segments; ++i) {
    const double t = i == segments ? dom.end : dom.start + dom.length() * i / segments;
    if (i > 0) s += nurbs::arc_length(c, t_prev, t);
    t_prev = t;
    const std::vector<Vec3> d = c.derivatives(t, 2);
    const double v = norm(d[1]);
    q.push_back({t, 0.0, 0.0});
    d1.push_back({length / v, 0.0, 0.0});                                           // dt/du = L dt/ds
    d2.push_back({-length * length * dot(d[1], d[2]) / std::pow(v, 4), 0.0, 0.0});  // d²t/du²
    u.push_back(i == segments ? 1.0 : s / length);
  }
  return nurbs::hermite_quintic(q, d1, d2, u, 2);
}

RoundTrip round_trip(const nurbs::NurbsCurve& c, int segments, int checks) {
  RoundTrip r;
  r.length = nurbs::arc_length(c);
  Vec3 lo = c.control_points().front(), hi = lo;
  for (const Vec3& p : c.control_points()) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  r.size = norm(hi - lo);
  const nurbs::NurbsCurve t_of_u = arc_length_inverse(c, r.length, segments);
  for (int i = 0; i < checks; ++i) {
    const double u = (i + 0.5) / checks;
    r.fit_error = std::max(r.fit_error, std::abs(t_of_u.evaluate(u).x - nurbs::parameter_at_length(c, u * r.length)));
  }

  law::Context ctx;
  const diffgeom::FrenetLaws f = diffgeom::frenet_laws(law::from_nurbs(c, ctx, "t"), "t");
  const Law s = ctx.parameter("s");
  // Clamped to the domain: the fit reproduces t0 and t1 at the ends only to rounding, and the curve
  // leaf is undefined (NaN) a rounding error outside its domain.
  const Law t_of_s = law::max(ctx.constant(c.domain().start),
                              law::min(ctx.constant(c.domain().end), law::term(ctx.curve(t_of_u, s / r.length), 1)));
  const Law kappa = law::substitute(f.curvature, "t", t_of_s);
  const Law tau = law::substitute(f.torsion, "t", t_of_s);

  const double t0 = c.domain().start;
  const std::vector<Vec3> d = c.derivatives(t0, 2);
  const Vec3 tangent = normalized(d[1]);
  const StartFrame start{d[0], tangent, d[2] - tangent * dot(d[2], tangent)};
  ReconstructionOptions opt;
  opt.tolerance = 1e-10;
  const IntrinsicCurve rc = reconstruct(kappa, tau, "s", r.length, start, opt);
  for (int i = 0; i <= checks; ++i) {
    const double at = r.length * i / checks;
    const double t = i == 0 ? t0 : (i == checks ? c.domain().end : nurbs::parameter_at_length(c, at));
    r.max_deviation = std::max(r.max_deviation, distance(rc.evaluate(at).position, c.evaluate(t)));
  }
  return r;
}

// checks: random clamped Bézier curves of degree 3, 4, 5, polynomial and rational (one span, so κ and τ are
// smooth in s) come back from their natural equations within 1e-10 × the size of the control polygon, against
// C(t(s)) with t(s) from nurbs::parameter_at_length.
TEST(NaturalEquationsRoundTrip, RandomBezierDegree3To5) {
  Rng rng(20261123);
  for (int degree = 3; degree <= 5; ++degree) {
    for (int k = 0; k < 2; ++k) {
      const nurbs::NurbsCurve c =
          testing::random_curve(rng, {.degree = degree, .rational = k == 1, .clamped = true, .extra_points = 0});
      const RoundTrip r = round_trip(c, 1024, 1000);
      // The reference t(s) = parameter_at_length carries the arc-length tolerance 1e-12 × L (L ≈ 20 … 30 here);
      // observed fit errors ≤ 4.3e-11 for domains of length ≤ 10.
      EXPECT_LT(r.fit_error, 1e-10 * c.domain().length()) << "degree " << degree << " rational " << k;
      // Positions: integration tolerance 1e-10 absolute plus the fit error carried by κ, τ; observed ≤ 6.6e-12 ×
      // size (1.7e-10 absolute), so 1e-10 × size leaves a margin of 15 and is 100 times tighter than the 1e-8 aim.
      EXPECT_LT(r.max_deviation, 1e-10 * r.size) << "degree " << degree << " rational " << k;
      std::printf("degree %d rational %d: L = %.3g, size = %.3g, t(s) fit %.2e, max deviation %.2e (%.2e relative)\n",
                  degree, k, r.length, r.size, r.fit_error, r.max_deviation, r.max_deviation / r.size);
    }
  }
}

}  // namespace
}  // namespace hula::intrinsic
