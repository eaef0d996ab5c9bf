// SPDX-License-Identifier: MIT
// Fins (thesis 6.3.2) against their definitions: on a circle of radius R the
// curvature fin tips lie at R + s/R from the centre and the normal fin at R + s;
// on a helix the torsion fin is s τ B; at the S-curve's inflection the curvature
// fin has length 0; Bishop fins are normal to T; log scale; options validate.
#include "hula/diffgeom/fins.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

// checks the torsion fin of the helix (2 cos t, 2 sin t, 0.5 t): tip − P = s τ B with τ = 0.5/4.25.
TEST(Fins, HelixTorsion) {
  law::Context ctx;
  const LawFrenet h(law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), "t", {0.0, 6.0});
  FinOptions o;
  o.kind = FinKind::Torsion;
  o.scale = 10.0;
  const Fins f = fins(h, {0.0, 6.0}, o);
  for (std::size_t i = 0; i < f.tip.size(); ++i) {
    const FrenetPoint p = h.at(f.t[i]);
    EXPECT_LT(norm(f.tip[i] - f.base[i] - p.binormal * (10.0 * 0.5 / 4.25)), 1e-12);
  }
  o.kind = FinKind::BishopU;
  const Fins b = fins(h, {0.0, 6.0}, o);
  for (std::size_t i = 0; i < b.tip.size(); ++i) {
    EXPECT_NEAR(dot(b.tip[i] - b.base[i], h.at(b.t[i]).tangent), 0.0, 1e-12);
    EXPECT_NEAR(norm(b.tip[i] - b.base[i]), 10.0, 1e-12);
  }
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
