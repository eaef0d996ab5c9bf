// SPDX-License-Identifier: MIT
// Symbolic antiderivatives: d/dt F = f (exact symbolic derivative, checked at
// sample points to 1e-12) for polynomials, piecewise polynomials, linear-argument
// trig/exp/power forms and vectors; continuity at piecewise switches; definite
// integrals against closed forms; and the numeric fallback (with its accuracy)
// for forms without a closed form.
#include "hula/law/antiderivative.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/simplify.hpp"
#include "hula/testing/fpe.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

using test::eval;

// checks: F' = f at sample points for every supported closed form (against the integrand itself).
TEST(LawAntiderivative, DerivativeGivesBackTheIntegrand) {
  struct Case {
    const char* f;
    double lo, hi;
  };
  const Case cases[] = {
      {"3*t^2 - 2*t + 1", -2, 2},
      {"(t - 1)*(t + 2)^3", -2, 2},
      {"t^7", -1.5, 1.5},
      {"sin(2*t + 1)", -3, 3},
      {"cos(3*t)", -3, 3},
      {"exp(0.5*t - 1)", -3, 3},
      {"5*sin(t) + 2*exp(t) - t/4", -3, 3},
      {"1/(2*t + 1)", 0, 3},
      {"(2*t + 1)^-2", 0, 3},
      {"(2*t + 1)^2.5", 0, 3},
      {"sqrt(3*t + 1)", 0, 3},
      {"abs(2*t - 1)", -2, 2},
      {"tan(t/2)", -2, 2},
      {"sinh(2*t) + cosh(t)", -2, 2},
      {"piecewise(t < 1, t^2, 2 - t)", -2, 3},
      {"piecewise(2*t + 1 >= 0, sin(t), t^3)", -2, 3},
      {"vec(cos(t), sin(t), 0.5*t)", -3, 3},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.f);
    Context ctx;
    const Law f = parse(c.f, ctx);
    const auto F = antiderivative(f, "t");
    ASSERT_TRUE(F.has_value());
    const Law dF = derivative(*F, "t");
    for (int i = 0; i <= 20; ++i) {
      const double t = c.lo + (c.hi - c.lo) * (i + 0.31) / 21.0;
      const auto want = eval(f, t);
      const auto got = eval(dF, t);
      for (std::size_t k = 0; k < want.size(); ++k)
        EXPECT_NEAR(got[k], want[k], 1e-12 * (1 + std::fabs(want[k]))) << "t = " << t;
    }
  }
}

// checks: the antiderivative of a piecewise law is continuous at the switch (left and right limits agree).
TEST(LawAntiderivative, PiecewiseIsContinuous) {
  Context ctx;
  const auto F = antiderivative(parse("piecewise(t < 1, t^2, 2 - t)", ctx), "t");
  ASSERT_TRUE(F);
  EXPECT_NEAR(test::eval1(*F, 1 - 1e-12), test::eval1(*F, 1 + 1e-12), 1e-11);
}

// checks: definite integrals by the symbolic path against closed forms, with a rounding-size error estimate.
TEST(LawAntiderivative, DefiniteSymbolic) {
  Context ctx;
  auto check = [&](const char* f, double a, double b, double want) {
    SCOPED_TRACE(f);
    const DefiniteIntegralResult r = definite_integral(parse(f, ctx), "t", a, b);
    EXPECT_EQ(r.method, IntegralMethod::Symbolic);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.value, want, 1e-13 * (1 + std::fabs(want)));
    EXPECT_LE(r.error_estimate, 1e-13 * (1 + std::fabs(want)));
  };
  check("t^3", 0, 2, 4.0);
  check("sin(t)", 0, 3.141592653589793, 2.0);
  check("exp(2*t)", 0, 1, (std::exp(2.0) - 1) / 2);
  check("piecewise(t < 1, t^2, 2 - t)", 0, 2, 1.0 / 3 + 0.5);
  check("1/t", 1, std::exp(1.0), 1.0);
}

// checks: forms without a closed form use quadrature and report its accuracy (Fresnel S(1), erf);
// a pole inside the interval never goes through the symbolic path.
TEST(LawAntiderivative, NumericFallback) {
  testing::FpeGuard guard;
  Context ctx;
  EXPECT_FALSE(antiderivative(parse("sin(t^2)", ctx), "t").has_value());
  const DefiniteIntegralResult s = definite_integral(parse("sin(pi*t^2/2)", ctx), "t", 0, 1);
  EXPECT_EQ(s.method, IntegralMethod::Numeric);
  EXPECT_TRUE(s.converged);
  EXPECT_NEAR(s.value, 0.43825914739035476607, 1e-12);
  EXPECT_GT(s.error_estimate, 0.0);
  EXPECT_LT(s.error_estimate, 1e-12);
  const DefiniteIntegralResult p = definite_integral(parse("1/t", ctx), "t", -1, 2);
  EXPECT_EQ(p.method, IntegralMethod::Numeric);
  EXPECT_FALSE(p.converged);  // divergent: said so, not a log|t| difference
}

// checks: symbolic_definite_integral is the symbolic branch alone: ∫_0^2 3t² = 8 exactly as definite_integral, and no
// value (no quadrature) for forms without a closed form (Fresnel integrand, a kinked max) or with a pole inside.
TEST(LawAntiderivative, SymbolicOnly) {
  Context ctx;
  const std::optional<DefiniteIntegralResult> cubic = symbolic_definite_integral(parse("3*t^2", ctx), "t", 0, 2);
  ASSERT_TRUE(cubic.has_value());
  EXPECT_EQ(cubic->method, IntegralMethod::Symbolic);
  EXPECT_NEAR(cubic->value, 8.0, 1e-14);
  EXPECT_EQ(cubic->value, definite_integral(parse("3*t^2", ctx), "t", 0, 2).value);
  EXPECT_FALSE(symbolic_definite_integral(parse("sin(pi*t^2/2)", ctx), "t", 0, 1).has_value());
  EXPECT_FALSE(symbolic_definite_integral(parse("max(0, 1 - abs(t - 1))", ctx), "t", 0, 2).has_value());
  EXPECT_FALSE(symbolic_definite_integral(parse("1/t", ctx), "t", -1, 2).has_value());
}

struct Rule {
  const char* f;
  double lo, hi;  // an interval where f is defined and finite
  bool identity;  // simplify(F' − f) is exactly 0 (ring identities suffice)
};

// One integrand per rule of antiderivative.cpp, the five among them.
// clang-format off
const Rule kRules[] = {
    // by parts, tabular
    {"t*exp(t)", -2, 2, true},
    {"t*sin(t)", -3, 3, true},
    {"t^3*exp(-2*t + 1)", -1, 2, true},
    {"(t^2 + 1)*cos(3*t)", -2, 2, true},
    {"t*sinh(t)", -2, 2, true},
    {"t^2*cosh(0.5*t)", -2, 2, true},
    // by parts with an inverse function
    {"log(t)", 0.1, 3, false},
    {"t^2*log(t)", 0.1, 3, false},
    {"log(2*t + 1)", 0, 3, false},
    {"atan(t)", -3, 3, false},
    {"t*atan(t)", -3, 3, false},
    {"asin(t)", -0.9, 0.9, false},
    {"acos(t)", -0.9, 0.9, false},
    {"log(1 + t^2)", -2, 2, false},
    // substitution
    {"2*t*cos(t^2)", -2, 2, true},
    {"t*exp(t^2)", -1.5, 1.5, true},
    {"sin(t)^2*cos(t)", -3, 3, true},
    {"exp(t)/(1 + exp(t))", -3, 3, true},
    {"log(t)/t", 0.2, 3, true},
    {"cos(t)/sin(t)", 0.2, 3, true},
    {"t/(1 + t^2)^2", -2, 2, true},
    {"t*sqrt(1 + t^2)", -2, 2, true},
    {"exp(sin(t))*cos(t)", -3, 3, true},
    {"t^2*(t^3 + 1)^4", -0.9, 1, true},
    // rational
    {"1/(1 + t^2)", -3, 3, true},
    {"1/(t^2 + 2*t + 5)", -3, 3, false},
    {"(3*t + 2)/(t^2 + 4)", -3, 3, false},
    {"1/(t^2 - 4)", 2.5, 5, false},
    {"1/(t*(t + 1))", 0.5, 3, false},
    {"(t^3 + 1)/(t^2 + 1)", -2, 2, false},
    {"1/(2*t + 1)^2", 0, 3, true},
    // polynomial times a power of a linear factor
    {"t*(2*t + 1)^2.5", 0, 3, false},
    {"t^2/sqrt(t + 1)", 0, 3, false},
    // trigonometric powers and products
    {"cos(t)^2", -3, 3, true},
    {"sin(t)^4", -3, 3, true},
    {"sin(t)^3*cos(t)^2", -3, 3, true},
    {"sin(2*t)^2*cos(2*t)^4", -3, 3, false},
    {"sin(t)*cos(3*t)", -3, 3, false},
    {"cos(2*t)*cos(5*t + 1)", -3, 3, false},
    {"exp(2*t)*sin(3*t)", -2, 2, true},
    {"exp(-t)*cos(t + 1)", -2, 2, true},
    // square roots of quadratics (asin, log forms)
    {"1/sqrt(1 - t^2)", -0.9, 0.9, false},
    {"1/sqrt(t^2 + 1)", -2, 2, false},
    {"sqrt(4 - t^2)", -1.9, 1.9, false},
    {"(t + 1)/sqrt(t^2 + 2*t + 3)", -2, 2, false},
    {"t^(-1/2)", 0.1, 3, true},
};
// clang-format on

// checks: every rule differentiates back to its integrand: F' simplified (law::simplify), then compared
// with f at 100 points to 1e-12 relative; where the simplifier's identities suffice (rings, sin² + cos² = 1;
// not polynomial division nor atan/asin arguments), simplify(F' − f) is exactly 0.
TEST(LawAntiderivative, EveryRuleDifferentiatesBack) {
  for (const Rule& r : kRules) {
    SCOPED_TRACE(r.f);
    Context ctx;
    const Law f = parse(r.f, ctx);
    const std::optional<Law> F = antiderivative(f, "t");
    ASSERT_TRUE(F.has_value());
    const Law dF = simplify(derivative(*F, "t"));
    for (int i = 0; i < 100; ++i) {
      const double t = r.lo + (r.hi - r.lo) * (i + 0.5) / 100.0;
      const double want = test::eval1(f, t);
      EXPECT_NEAR(test::eval1(dF, t), want, 1e-12 * (1 + std::fabs(want))) << "t = " << t;
    }
    if (r.identity) {
      SimplifyOptions identities;
      identities.trig_identities = true;
      const Law difference = simplify(derivative(*F, "t") - f, identities);
      EXPECT_TRUE(difference.is_zero()) << print(difference);
    }
  }
}

// checks: what stays numeric says why: the blocking term of a sum, a pole the antiderivative cannot span;
// an antiderivative without a finite limit at an integrable end.
TEST(LawAntiderivative, NumericSaysWhy) {
  testing::FpeGuard guard;
  Context ctx;
  const AntiderivativeReport rep = antiderivative_report(parse("t + sin(t^2)", ctx), "t");
  EXPECT_FALSE(rep.antiderivative.has_value());
  EXPECT_EQ(print(rep.blocking_term), "sin(t^2)");
  const DefiniteIntegralResult n = definite_integral(parse("t + sin(t^2)", ctx), "t", 0, 1);
  EXPECT_EQ(n.method, IntegralMethod::Numeric);
  EXPECT_EQ(n.numeric_reason, "no closed-form antiderivative of sin(t^2)");
  const DefiniteIntegralResult p = definite_integral(parse("1/t", ctx), "t", -1, 2);
  EXPECT_EQ(p.method, IntegralMethod::Numeric);
  EXPECT_EQ(p.numeric_reason, "the integrand is not integrable at t = 0");
  EXPECT_TRUE(p.divergent);
  // log(t)/sqrt(t) at 0: integrable (t^(−1/2) log t), closed form 2√t (log t − 2) with the limit 0.
  const DefiniteIntegralResult q = definite_integral(parse("log(t)/sqrt(t)", ctx), "t", 0, 1);
  EXPECT_NEAR(q.value, -4.0, 1e-13);
}

}  // namespace
}  // namespace hula::law
