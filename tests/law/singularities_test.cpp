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

namespace hula::law {
namespace {

// checks: explain_non_finite names the subexpression that overflows (exp(1000 t) at t = 1, whose
// value exceeds DBL_MAX ≈ 1.8e308 since 1000 > log(DBL_MAX) ≈ 709.8), finds the overflow under an
// inf − inf that became NaN, and still explains undefined values as explain_undefined does.
TEST(LawSingularities, ExplainNonFiniteNamesTheOverflow) {
  testing::FpeGuard guard;
  Context ctx;
  auto cause = explain_non_finite(parse("vec(exp(1000*t), 0, 0)", ctx), "t", 1.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_TRUE(cause->overflow);
  EXPECT_EQ(cause->expression, "exp(1000*t)");
  cause = explain_non_finite(parse("exp(1000*t) - exp(1000*t)*2", ctx), "t", 1.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_TRUE(cause->overflow);
  EXPECT_EQ(cause->expression, "exp(1000*t)");
  cause = explain_non_finite(parse("sin(t) + 1/t", ctx), "t", 0.0);
  ASSERT_TRUE(cause.has_value());
  EXPECT_FALSE(cause->overflow);
  EXPECT_EQ(cause->reason, "division by zero");
  EXPECT_FALSE(explain_non_finite(parse("exp(1000*t)", ctx), "t", 0.5).has_value());    // e^500 is finite
  EXPECT_FALSE(explain_non_finite(parse("1/exp(1000*t)", ctx), "t", 1.0).has_value());  // 1/inf = 0 is finite
}

// checks: nonsmooth_at against the kinks known in closed form: |t| at 0 (first derivative), |sin t|
// at π (sin(π) rounds to 1.2e-16), min/max ties, a piecewise join, t·|t|·|t| (= t³, smooth, but the
// kink condition of abs is met: the report is conservative), and no report away from the kink,
// below the order asked, or for a smooth law.
TEST(LawSingularities, NonsmoothAtKnownKinks) {
  testing::FpeGuard guard;
  Context ctx;
  auto k = nonsmooth_at(parse("abs(t)", ctx), "t", 0.0, 1);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->order, 1);
  EXPECT_EQ(k->kind, SingularityKind::AbsKink);
  EXPECT_EQ(k->expression, "abs(t)");
  EXPECT_FALSE(nonsmooth_at(parse("abs(t)", ctx), "t", 0.0, 0).has_value());
  EXPECT_FALSE(nonsmooth_at(parse("abs(t)", ctx), "t", 1e-3, 4).has_value());
  k = nonsmooth_at(parse("abs(sin(t))", ctx), "t", std::numbers::pi, 2);  // sin(pi) = 1.2e-16, not 0
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->order, 1);
  k = nonsmooth_at(parse("max(t, 1 - t)", ctx), "t", 0.5, 1);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->kind, SingularityKind::MinMaxSwitch);
  k = nonsmooth_at(parse("piecewise(t < 1, t^2, 2*t - 1)", ctx), "t", 1.0, 3);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->order, 1);  // conservative: a join is a join, even a C1 one
  k = nonsmooth_at(parse("t*abs(t)*abs(t)", ctx), "t", 0.0, 3);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->order, 1);  // the kink condition of abs(t) in f itself
  EXPECT_FALSE(nonsmooth_at(parse("t^3", ctx), "t", 0.0, 5).has_value());
}

// checks: a NURBS leaf at a simple interior knot of a cubic (C2 there) keeps its first and second
// derivatives and loses the third, as the B-spline continuity p − m = 2 says.
TEST(LawSingularities, NonsmoothAtNurbsKnotFollowsContinuity) {
  const nurbs::NurbsCurve curve =
      nurbs::interpolate_cubic(std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}, {4, 2, 0}});
  Context ctx;
  const Law c = ctx.curve(curve, ctx.parameter("t"));
  const double knot = curve.knots().breakpoints()[1];
  EXPECT_FALSE(nonsmooth_at(c, "t", knot, 2).has_value());
  const auto k = nonsmooth_at(c, "t", knot, 3);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->order, 3);
  EXPECT_EQ(k->kind, SingularityKind::CurveKnot);
}

}  // namespace
}  // namespace hula::law
