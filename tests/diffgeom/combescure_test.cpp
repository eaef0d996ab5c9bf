// SPDX-License-Identifier: MIT
// Combescure transform (thesis 8.3, eq. 38–44): the compound curve of a helix
// and of the twisted cubic keeps the parent's tangents, the inverse applied to
// the compound curve gives the parent back; planar points and κ = 0 are flagged.
#include "hula/diffgeom/combescure.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"

namespace hula::diffgeom {
namespace {

// checks round trip P → Q (exact law) → P with Q's own frame, T_Q ∥ T_P, and the pointwise form equals the law.
TEST(Combescure, RoundTripHelixAndTwistedCubic) {
  struct Case {
    const char* expression;
    double c;
    nurbs::Interval domain;
  };
  for (const Case& k :
       {Case{"vec(2*cos(t), 2*sin(t), 0.5*t)", 0.7, {0.0, 6.0}}, Case{"vec(t, t^2, t^3)", 0.05, {0.1, 1.0}}}) {
    law::Context ctx;
    const law::Law p = law::parse(k.expression, ctx);
    const LawFrenet fp(p, "t", k.domain);
    const LawFrenet fq(combescure_law(p, "t", k.c), "t", k.domain);
    for (int i = 0; i <= 20; ++i) {
      const double t = k.domain.start + k.domain.length() * i / 20.0;
      const FrenetPoint a = fp.at(t), q = fq.at(t);
      const CombescurePoint fwd = combescure(a, k.c);
      ASSERT_TRUE(fwd.defined);
      EXPECT_LT(distance(fwd.point, q.position), 1e-12) << k.expression << " t=" << t;
      EXPECT_NEAR(dot(a.tangent, q.tangent), 1.0, 1e-12);
      const CombescurePoint back = combescure_inverse(q, k.c);
      ASSERT_TRUE(back.defined);
      EXPECT_LT(distance(back.point, a.position), 1e-10) << k.expression << " t=" << t;
    }
  }
}

// checks the undefined flags: a planar curve (τ = 0) and a straight line (κ = 0); C must be finite.
TEST(Combescure, UndefinedFlags) {
  law::Context ctx;
  const LawFrenet ellipse(law::parse("vec(3*cos(t), sin(t), 0)", ctx), "t", {0.0, 6.0});
  const CombescurePoint e = combescure(ellipse.at(1.0), 1.0);
  EXPECT_FALSE(e.defined);
  EXPECT_TRUE(std::isnan(e.point.x));
  const LawFrenet line(law::parse("vec(t, 2*t, 3*t)", ctx), "t", {0.0, 1.0});
  const CombescurePoint l = combescure(line.at(0.5), 1.0);
  EXPECT_FALSE(l.defined);
  EXPECT_EQ(l.reason, Undefined::ZeroCurvature);
  EXPECT_THROW((void)combescure(ellipse.at(1.0), std::nan("")), Error);
}

}  // namespace
}  // namespace hula::diffgeom
