// SPDX-License-Identifier: MIT
// Singularity reports against the points where each construct is known to be
// undefined or not smooth: poles, sqrt/log boundaries with their undefined
// intervals, abs kinks, piecewise switches, tan poles, and NURBS knots.
#include "hula/law/singularities.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/law/parser.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"

namespace hula::law {
namespace {

bool has(const SingularityReport& r, SingularityKind k, double t, double tol = 1e-10) {
  for (const auto& s : r.points)
    if (s.kind == k && std::fabs(s.t - t) <= tol) return true;
  return false;
}

// checks: each construct reports its known point and kind, and nothing for a smooth law.
TEST(LawSingularities, KnownPoints) {
  testing::FpeGuard guard;
  Context ctx;
  const auto r = singularities(parse("1/(t - 1) + abs(t + 0.5) + piecewise(t < 2, t, t^2)", ctx), "t", -3, 3);
  EXPECT_TRUE(has(r, SingularityKind::DivisionByZero, 1.0));
  EXPECT_TRUE(has(r, SingularityKind::AbsKink, -0.5));
  EXPECT_TRUE(has(r, SingularityKind::PiecewiseSwitch, 2.0));
  EXPECT_EQ(r.points.size(), 3U);
  EXPECT_TRUE(r.undefined.empty());  // an isolated pole is a point, not an interval
  EXPECT_EQ(r.points[0].expression, "abs(t + 0.5)");

  const auto s = singularities(parse("sqrt(t) + log(t + 2)", ctx), "t", -3, 3);
  EXPECT_TRUE(has(s, SingularityKind::SqrtBoundary, 0.0));
  EXPECT_TRUE(has(s, SingularityKind::LogBoundary, -2.0));
  ASSERT_EQ(s.undefined.size(), 1U);
  EXPECT_EQ(s.undefined[0].start, -3.0);
  EXPECT_NEAR(s.undefined[0].end, 0.0, 1e-11);

  const auto tn = singularities(parse("tan(t)", ctx), "t", 0, 5);
  EXPECT_TRUE(has(tn, SingularityKind::TanPole, std::numbers::pi / 2));
  EXPECT_TRUE(has(tn, SingularityKind::TanPole, 3 * std::numbers::pi / 2));

  const auto n = singularities(parse("normalize(vec(t - 1, 0, 0)) + norm(vec(t, t, 0))*vec(1,1,1)", ctx), "t", -2, 2);
  EXPECT_TRUE(has(n, SingularityKind::NormalizeZero, 1.0, 1e-7));
  EXPECT_TRUE(has(n, SingularityKind::NormKink, 0.0, 1e-7));

  EXPECT_TRUE(singularities(parse("vec(cos(t), sin(t), t)", ctx), "t", -5, 5).smooth());
}

// checks: a NURBS leaf reports its interior knots (mapped through the argument) and its domain ends.
TEST(LawSingularities, NurbsKnots) {
  const nurbs::NurbsCurve curve =
      nurbs::interpolate_cubic(std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}, {4, 2, 0}});
  Context ctx;
  const Law t = ctx.parameter("t");
  const auto r = singularities(ctx.curve(curve, 2.0 * t), "t", -0.5, 1);
  const auto bp = curve.knots().breakpoints();
  for (std::size_t i = 1; i + 1 < bp.size(); ++i) EXPECT_TRUE(has(r, SingularityKind::CurveKnot, bp[i] / 2)) << bp[i];
  EXPECT_TRUE(has(r, SingularityKind::CurveDomainEnd, 0.0));
  EXPECT_TRUE(has(r, SingularityKind::CurveDomainEnd, 0.5));
  ASSERT_EQ(r.undefined.size(), 2U);  // t < 0 and t > 0.5 are outside the curve's domain [0, 1]
}

// checks: bad interval and options are errors naming the problem.
TEST(LawSingularities, Errors) {
  Context ctx;
  HULA_EXPECT_ERROR(singularities(parse("t", ctx), "t", 1, 1), Errc::InvalidArgument, "finite interval a < b");
  SingularityOptions o;
  o.samples = 0;
  HULA_EXPECT_ERROR(singularities(parse("t", ctx), "t", 0, 1, o), Errc::InvalidOption, "SingularityOptions::samples");
}

// checks: explain_undefined names the innermost undefined subexpression and the reason, ignores an
// unselected piecewise branch, and returns nothing where the law is defined.
TEST(LawSingularities, ExplainUndefined) {
  testing::FpeGuard guard;
  Context ctx;
  auto cause = explain_undefined(parse("sin(t) + 1/t", ctx), "t", 0.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_EQ(cause->expression, "1/t");
  EXPECT_EQ(cause->reason, "division by zero");
  cause = explain_undefined(parse("exp(sqrt(t - 1)) * 2", ctx), "t", 0.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_EQ(cause->expression, "sqrt(t - 1)");
  EXPECT_EQ(cause->reason, "sqrt of a negative number");
  cause = explain_undefined(parse("vec(t, log(t))", ctx), "t", -1.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_EQ(cause->reason, "log of a number <= 0");
  EXPECT_FALSE(explain_undefined(parse("piecewise(t > 0, log(t), t)", ctx), "t", -1.0).has_value());
  // the cause is in the selected branch, not in the undefined unselected one
  cause = explain_undefined(parse("piecewise(t > 0, log(t), 1/(t + 1))", ctx), "t", -1.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_EQ(cause->expression, "1/(t + 1)");
  EXPECT_FALSE(explain_undefined(parse("1/t", ctx), "t", 2.0).has_value());
}

}  // namespace
}  // namespace hula::law
