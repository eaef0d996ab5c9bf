// SPDX-License-Identifier: MIT
// Fins (thesis 6.3.2) against their definitions: on a circle of radius R the
// curvature fin tips lie at R + s/R from the centre and the normal fin at R + s;
// on a helix the torsion fin is s τ B; at the S-curve's inflection the curvature
// fin has length 0; Bishop fins are normal to T; log scale; options validate.
#include "hula/diffgeom/fins.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

// checks curvature, normal and log-scaled curvature fins of a circle of radius 2 (centre at the origin).
TEST(Fins, Circle) {
  const nurbs::NurbsCurve c = testing::rational_circle(2.0);
  FinOptions o;
  o.scale = 3.0;
  o.density = 101;
  const Fins k = fins(c, o);
  ASSERT_EQ(k.tip.size(), 101U);
  for (std::size_t i = 0; i < k.tip.size(); ++i) {
    EXPECT_EQ(k.defined[i], 1);
    EXPECT_NEAR(norm(k.tip[i]), 2.0 + 3.0 / 2.0, 1e-12);
  }
  o.kind = FinKind::Normal;
  for (const Vec3& t : fins(c, o).tip) EXPECT_NEAR(norm(t), 5.0, 1e-12);
  o.kind = FinKind::Curvature;
  o.log_scale = true;
  for (const Vec3& t : fins(c, o).tip) EXPECT_NEAR(norm(t), 2.0 + std::log1p(1.5), 1e-12);
}

// checks fins built from frames already evaluated at the fin parameters equal fins(curve) bit for bit,
// for every kind (the server's analysis builds its combs this way)
TEST(Fins, FromFramesEqualFromCurve) {
  const nurbs::NurbsCurve c = testing::rational_circle(2.0);
  for (const FinKind kind :
       {FinKind::Curvature, FinKind::Torsion, FinKind::Normal, FinKind::Binormal, FinKind::BishopU, FinKind::BishopV}) {
    FinOptions o;
    o.kind = kind;
    o.scale = 0.7;
    o.density = 37;
    const Fins expected = fins(c, o);
    std::vector<FrenetPoint> frames(expected.t.size());
    frenet(c, expected.t, frames);
    const Fins got = fins(frames, o);
    ASSERT_EQ(got.t.size(), expected.t.size());
    for (std::size_t i = 0; i < got.t.size(); ++i) {
      EXPECT_EQ(got.t[i], expected.t[i]);
      EXPECT_EQ(got.defined[i], expected.defined[i]) << fin_kind_name(kind) << " fin " << i;
      EXPECT_EQ(got.base[i], expected.base[i]);
      if (expected.defined[i]) {
        EXPECT_EQ(got.tip[i], expected.tip[i]) << fin_kind_name(kind) << " fin " << i;
      }
    }
  }
}

// checks the torsion fin of the helix (2 cos t, 2 sin t, 0.5 t): tip − P = s τ B with τ = 0.5/4.25.
TEST(Fins, HelixTorsion) {
  law::Context ctx;
  const LawFrenet h(law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), "t", {0.0, 6.0});
  FinOptions o;
  o.kind = FinKind::Torsion;
  o.scale = 10.0;
  const curve::Curve helix = curve::Curve::from_law("vec(2*cos(t), 2*sin(t), 0.5*t)", "t", {0.0, 6.0});
  const Fins f = fins(helix, o);
  for (std::size_t i = 0; i < f.tip.size(); ++i) {
    const FrenetPoint p = h.at(f.t[i]);
    EXPECT_LT(norm(f.tip[i] - f.base[i] - p.binormal * (10.0 * 0.5 / 4.25)), 1e-12);
  }
  o.kind = FinKind::BishopU;
  const Fins b = fins(helix, o);
  for (std::size_t i = 0; i < b.tip.size(); ++i) {
    EXPECT_NEAR(dot(b.tip[i] - b.base[i], h.at(b.t[i]).tangent), 0.0, 1e-12);
    EXPECT_NEAR(norm(b.tip[i] - b.base[i]), 10.0, 1e-12);
  }
}

// checks the Combescure fin of the helix (a cos t, a sin t, b t), a = 2, b = 0.5, against the closed form
// Q − P = C (b/a T + B) = (0, 0, C √(a² + b²) / a) (eq. 44, τ/κ = b/a), from the law and from its NURBS,
// its law form against the same shift, and that it is undefined everywhere on a planar circle (8.3).
TEST(Fins, CombescureHelixAndCircle) {
  const curve::Curve helix = curve::Curve::from_law("vec(2*cos(t), 2*sin(t), 0.5*t)", "t", {0.0, 6.0});
  FinOptions o;
  o.kind = FinKind::Combescure;
  o.scale = 3.0;
  o.density = 61;
  const Vec3 shift{0.0, 0.0, 3.0 * std::sqrt(4.25) / 2.0};
  const Fins f = fins(helix, o);
  for (std::size_t i = 0; i < f.tip.size(); ++i) {
    EXPECT_EQ(f.defined[i], 1) << i;
    EXPECT_LT(norm(f.tip[i] - f.base[i] - shift), 1e-12) << f.t[i];
  }
  // The stand-in NURBS (fitted to the law within a position tolerance) gives the shift within 1e-3.
  const Fins n = fins(helix.nurbs(), o);
  for (std::size_t i = 0; i < n.tip.size(); ++i) EXPECT_LT(norm(n.tip[i] - n.base[i] - shift), 1e-3) << n.t[i];
  law::Context ctx;
  const LawFrenet q(fin_law(law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), "t", o), "t", {0.0, 6.0});
  for (const double t : {0.0, 1.3, 4.0})
    EXPECT_LT(norm(q.at(t).position - Vec3{2.0 * std::cos(t), 2.0 * std::sin(t), 0.5 * t} - shift), 1e-12) << t;
  o.log_scale = true;
  const Fins l = fins(helix, o);
  EXPECT_NEAR(norm(l.tip[7] - l.base[7]), std::log1p(norm(shift)), 1e-12);
  o.log_scale = false;
  const Fins c = fins(testing::rational_circle(2.0), o);
  EXPECT_TRUE(std::all_of(c.defined.begin(), c.defined.end(), [](std::uint8_t d) { return d == 0; }));
  EXPECT_EQ(fin_kind_from_name("combescure"), FinKind::Combescure);
  EXPECT_EQ(fin_kind_from_name("compound"), std::nullopt);
}

// checks the S-curve: curvature fin of length 0 at the inflection (defined), torsion fin undefined (NaN) there.
TEST(Fins, InflectionAndUndefined) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1},
                            {{-1, 0, 0}, {-1.0 / 3, 4.0 / 3, 0}, {1.0 / 3, -4.0 / 3, 0}, {1, 0, 0}}, {}, 2);
  FinOptions o;
  o.density = 3;  // t = 0, 0.5, 1
  const Fins k = fins(c, o);
  EXPECT_EQ(k.defined[1], 1);
  EXPECT_EQ(norm(k.tip[1] - k.base[1]), 0.0);
  o.kind = FinKind::Torsion;
  const Fins t = fins(c, o);
  EXPECT_EQ(t.defined[1], 0);
  EXPECT_TRUE(std::isnan(t.tip[1].x));
  o.density = 1;
  EXPECT_THROW((void)fins(c, o), Error);
}

}  // namespace
}  // namespace hula::diffgeom

namespace hula::diffgeom {
namespace {

// Largest distance between the fitted fin NURBS and the fin tips of a dense comb (fins() polyline).
double deviation_from_comb(const law::ToNurbsResult& fit, const Fins& comb) {
  double worst = 0.0;
  for (std::size_t i = 0; i < comb.t.size(); ++i) {
    EXPECT_EQ(comb.defined[i], 1) << i;
    worst = std::max(worst, norm(fit.curve.evaluate(comb.t[i]) - comb.tip[i]));
  }
  return worst;
}

// checks the curvature fin of the helix (2 cos t, 2 sin t, 0.5 t) as a NURBS: closed form
// ((2 + s κ) cos t, (2 + s κ) sin t, 0.5 t) with κ = 2/4.25, and within the tolerance of a dense comb.
TEST(Fins, HelixCurvatureFinAsNurbs) {
  law::Context ctx;
  const law::Law helix = law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx);
  const nurbs::Interval dom{0.0, 6.0};
  FinOptions o;
  o.kind = FinKind::Curvature;
  o.scale = 1.5;
  o.density = 2001;
  law::ToNurbsOptions fit;
  fit.tolerance = 1e-8;
  const law::ToNurbsResult r = fin_nurbs(helix, "t", dom, o, fit);
  EXPECT_LE(r.max_deviation, 1e-8);
  const double radius = 2.0 + 1.5 * 2.0 / 4.25;
  for (int i = 0; i <= 60; ++i) {
    const double t = dom.start + dom.length() * i / 60.0;
    const Vec3 want{radius * std::cos(t), radius * std::sin(t), 0.5 * t};
    EXPECT_LT(norm(r.curve.evaluate(t) - want), 1e-8) << t;
  }
  EXPECT_LT(deviation_from_comb(r, fins(curve::Curve::from_law(law::print(helix), "t", dom), o)), 1e-8);
}

// checks the torsion fin P + s τB of the twisted cubic (t, t², t³) and the curvature fin of the planar
// S-curve (t, t³ − t) through its inflection, each as a NURBS within 1e-7 of a dense comb.
TEST(Fins, TwistedCubicTorsionAndSCurveCurvatureFinsAsNurbs) {
  law::Context ctx;
  const nurbs::Interval dom{-1.0, 1.0};
  law::ToNurbsOptions fit;
  fit.tolerance = 1e-7;
  FinOptions o;
  o.density = 4001;
  o.kind = FinKind::Torsion;
  o.scale = 0.2;
  const law::Law cubic = law::parse("vec(t, t^2, t^3)", ctx);
  const law::ToNurbsResult tor = fin_nurbs(cubic, "t", dom, o, fit);
  EXPECT_LE(tor.max_deviation, 1e-7);
  EXPECT_LT(deviation_from_comb(tor, fins(curve::Curve::from_law("vec(t, t^2, t^3)", "t", dom), o)), 1e-7);
  // At t = 0: P = 0, τ = 3, B = (0, 0, 1).
  EXPECT_LT(norm(tor.curve.evaluate(0.0) - Vec3{0, 0, 0.6}), 1e-7);
  o.kind = FinKind::Curvature;
  o.scale = 0.3;
  const law::Law s_curve = law::parse("vec(t, t^3 - t)", ctx);
  const law::ToNurbsResult cur = fin_nurbs(s_curve, "t", dom, o, fit);
  EXPECT_LE(cur.max_deviation, 1e-7);
  EXPECT_LT(deviation_from_comb(cur, fins(curve::Curve::from_law("vec(t, t^3 - t)", "t", dom), o)), 1e-7);
}

// checks the errors name the input: Bishop fins ("kind"), log scale ("log_scale"), a scalar law ("law").
TEST(Fins, FinLawErrorsNameTheInput) {
  law::Context ctx;
  const law::Law c = law::parse("vec(t, t^2, t^3)", ctx);
  auto field_of = [&](const law::Law& l, const FinOptions& o) {
    try {
      (void)fin_law(l, "t", o);
    } catch (const Error& e) {
      return e.where().field;
    }
    return std::string("no error");
  };
  FinOptions o;
  o.kind = FinKind::BishopU;
  EXPECT_EQ(field_of(c, o), "kind");
  o.kind = FinKind::Curvature;
  o.log_scale = true;
  EXPECT_EQ(field_of(c, o), "log_scale");
  EXPECT_EQ(field_of(law::parse("t^2", ctx), FinOptions{}), "law");
}

}  // namespace
}  // namespace hula::diffgeom
