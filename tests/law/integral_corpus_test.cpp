// SPDX-License-Identifier: MIT
// A corpus of definite integrals with known closed-form values (computed here
// from the C library: log, atan, exp, π, …, never from the law engine),
// improper ones included — integrable end and interior singularities (√t,
// log t, t^(−1/2), 1/√(1 − t²), log sin t), infinite ranges (e^(−t), the
// Gaussian, 1/(1 + t⁴)) — each through law::definite_integral to 1e-12
// relative, and a corpus of divergent integrals that must be reported
// divergent (and only those).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "hula/law/antiderivative.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/simplify.hpp"
#include "hula/testing/fpe.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

constexpr double kInf = HUGE_VAL;
const double kE = std::exp(1.0);

struct Known {
  const char* f;
  double a, b;
  double value;
};

// clang-format off
const std::vector<Known> kCorpus = {
    {"t^3", 0, 2, 4.0},
    {"sin(t)", 0, std::numbers::pi, 2.0},
    {"exp(2*t)", 0, 1, (std::exp(2.0) - 1) / 2},
    {"1/t", 1, kE, 1.0},
    {"t*exp(t)", 0, 1, 1.0},
    {"t*sin(t)", 0, std::numbers::pi, std::numbers::pi},
    {"2*t*cos(t^2)", 0, std::sqrt(std::numbers::pi / 2), 1.0},
    {"1/(1 + t^2)", 0, 1, std::numbers::pi / 4},
    {"cos(t)^2", 0, std::numbers::pi, std::numbers::pi / 2},
    {"sin(t)^2", 0, std::numbers::pi / 2, std::numbers::pi / 4},
    {"atan(t)", 0, 1, std::numbers::pi / 4 - std::log(2.0) / 2},
    {"asin(t)", 0, 1, std::numbers::pi / 2 - 1},
    {"t^2*cos(t)", 0, std::numbers::pi / 2, std::numbers::pi * std::numbers::pi / 4 - 2},
    {"exp(t)*sin(t)", 0, std::numbers::pi, (std::exp(std::numbers::pi) + 1) / 2},
    {"exp(-t)*cos(2*t)", 0, std::numbers::pi, (1 - std::exp(-std::numbers::pi)) / 5},
    {"sin(t)^3", 0, std::numbers::pi, 4.0 / 3},
    {"sin(t)^2*cos(t)^2", 0, 2 * std::numbers::pi, std::numbers::pi / 4},
    {"sin(t)*cos(3*t)", 0, std::numbers::pi / 2, -0.5},
    {"1/(t^2 - 4)", 3, 4, std::log(5.0 / 3) / 4},
    {"t/(1 + t^2)", 0, 1, std::log(2.0) / 2},
    {"1/(t^2 + 2*t + 5)", -1, 1, std::numbers::pi / 8},
    {"1/(t*(t + 1))", 1, 2, std::log(4.0 / 3)},
    {"sqrt(1 - t^2)", -1, 1, std::numbers::pi / 2},
    {"1/sqrt(t^2 + 1)", 0, 1, std::log(1 + std::sqrt(2.0))},
    {"t*sqrt(1 + t^2)", 0, 1, (2 * std::sqrt(2.0) - 1) / 3},
    {"exp(t)/(1 + exp(t))", 0, 1, std::log((1 + kE) / 2)},
    {"tan(t)", 0, std::numbers::pi / 4, std::log(2.0) / 2},
    {"t*cosh(t)", 0, 1, 1 - std::exp(-1.0)},
    {"(2*t + 1)^2.5", 0, 1, (std::pow(3.0, 3.5) - 1) / 7},
    {"t^3*log(t)", 0, 1, -1.0 / 16},
    {"log(t)^2", 0, 1, 2.0},
    {"t*log(t)", 0, 1, -0.25},
    {"exp(-t^2)", 0, 2, std::sqrt(std::numbers::pi) / 2 * std::erf(2.0)},
    {"sin(pi*t^2/2)", 0, 1, 0.43825914739035476607},  // Fresnel S(1), A&S table 7.7
    // Improper: integrable singularities at an end, inside, and infinite ranges.
    {"sqrt(t)", 0, 1, 2.0 / 3},
    {"log(t)", 0, 1, -1.0},
    {"t^(-1/2)", 0, 1, 2.0},
    {"t^(-1/3)", 0, 1, 1.5},
    {"1/sqrt(1 - t^2)", 0, 1, std::numbers::pi / 2},
    {"1/sqrt(t - 1)", 1, 2, 2.0},
    {"log(1 - t)", 0, 1, -1.0},
    {"1/sqrt(abs(t))", -1, 1, 4.0},
    {"log(sin(t))", 0, std::numbers::pi / 2, -std::numbers::pi / 2 * std::log(2.0)},
    {"log(t)/sqrt(t)", 0, 1, -4.0},
    {"exp(-t)", 0, kInf, 1.0},
    {"1/(1 + t^2)", -kInf, kInf, std::numbers::pi},
    {"exp(-t^2)", -kInf, kInf, std::sqrt(std::numbers::pi)},
    {"t^2*exp(-t)", 0, kInf, 2.0},
    {"t^(-1/2)*exp(-t)", 0, kInf, std::sqrt(std::numbers::pi)},
    {"1/(1 + t^4)", 0, kInf, std::numbers::pi / (2 * std::sqrt(2.0))},
    {"1/t^2", 1, kInf, 1.0},
};
// clang-format on

// checks: every integral of the corpus against its closed-form value to 1e-12 relative, with an error
// estimate that covers the true error (within a factor 100, at least rounding).
TEST(LawIntegralCorpus, KnownValues) {
  testing::FpeGuard guard;
  ASSERT_GE(kCorpus.size(), 40U);
  int symbolic = 0;
  for (const Known& k : kCorpus) {
    SCOPED_TRACE(std::string(k.f) + " on [" + std::to_string(k.a) + ", " + std::to_string(k.b) + "]");
    Context ctx;
    const DefiniteIntegralResult r = definite_integral(parse(k.f, ctx), "t", k.a, k.b);
    EXPECT_TRUE(r.converged) << r.numeric_reason;
    EXPECT_FALSE(r.divergent);
    EXPECT_NEAR(r.value, k.value, 1e-12 * std::fabs(k.value))
        << "method " << (r.method == IntegralMethod::Symbolic ? "symbolic" : "numeric");
    EXPECT_LE(std::fabs(r.value - k.value), 100 * std::max(r.error_estimate, 1e-15 * std::fabs(k.value)));
    if (r.method == IntegralMethod::Symbolic) {
      ++symbolic;
    } else {
      EXPECT_FALSE(r.numeric_reason.empty());
    }
  }
  // Most of the corpus has a closed form: the rules cover it.
  EXPECT_GE(symbolic, 35);
}

// checks: every antiderivative the rules find for an integrand of the corpus (not only one per rule) differentiates
// back to it: F' simplified, then compared with f at 100 interior points of the range (an infinite end cut at
// ±8) to 1e-12 relative (absolute 1e-12 where |f| < 1).
TEST(LawIntegralCorpus, EverySymbolicAntiderivativeDifferentiatesBack) {
  testing::FpeGuard guard;
  int checked = 0;
  for (const Known& k : kCorpus) {
    SCOPED_TRACE(k.f);
    Context ctx;
    const Law f = parse(k.f, ctx);
    const std::optional<Law> F = antiderivative(f, "t");
    if (!F) continue;
    ++checked;
    const Law dF = simplify(derivative(*F, "t"));
    const double lo = std::max(k.a, -8.0), hi = std::min(k.b, 8.0);
    for (int i = 0; i < 100; ++i) {
      const double t = lo + (hi - lo) * (i + 0.5) / 100.0;
      const double want = test::eval1(f, t), got = test::eval1(dF, t);
      EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::fabs(want))) << "t = " << t;
    }
  }
  EXPECT_GE(checked, 35);
}

// checks: the integrals the issue names are closed forms now (√t, log t with its limit 0 at t = 0, t^(−1/2)).
TEST(LawIntegralCorpus, IssueExamplesAreSymbolic) {
  for (const char* f :
       {"sqrt(t)", "log(t)", "t^(-1/2)", "t*exp(t)", "t*sin(t)", "2*t*cos(t^2)", "1/(1+t^2)", "cos(t)^2"}) {
    SCOPED_TRACE(f);
    Context ctx;
    const DefiniteIntegralResult r = definite_integral(parse(f, ctx), "t", 0, 1);
    EXPECT_EQ(r.method, IntegralMethod::Symbolic);
    EXPECT_TRUE(r.antiderivative.valid());
  }
}

struct Divergent {
  const char* f;
  double a, b;
  double where;  // the non-integrable point
};

// checks: non-integrable singularities (poles of order ≥ 1 at an end or inside, slow decay at infinity) are
// reported divergent with the point, never given a value; integrable ones next to them are not.
TEST(LawIntegralCorpus, DivergentOnlyWhenNotIntegrable) {
  testing::FpeGuard guard;
  const Divergent cases[] = {
      {"1/t", 0, 1, 0},
      {"1/t", -1, 2, 0},
      {"1/(t - 1)^2", 0, 2, 1},
      {"tan(t)", 0, 2, std::numbers::pi / 2},
      {"1/t", 1, kInf, kInf},
      {"1/sqrt(t)", 0, kInf, kInf},
      {"1/(t*log(2 + t))^1.5", 0, 1, 0},
      {"cos(t)/t", 0, 1, 0},
  };
  for (const Divergent& d : cases) {
    SCOPED_TRACE(d.f);
    Context ctx;
    const DefiniteIntegralResult r = definite_integral(parse(d.f, ctx), "t", d.a, d.b);
    EXPECT_TRUE(r.divergent);
    EXPECT_FALSE(r.converged);
    EXPECT_TRUE(std::isnan(r.value));
    bool named = false;
    for (const SingularPoint& p : r.singular_points)
      named = named || ((p.t == d.where || std::fabs(p.t - d.where) <= 1e-9) && !p.integrable);
    EXPECT_TRUE(named);
  }
  // t^(−0.9) grows like a non-integrable pole but is integrable: not divergent, value 10.
  Context ctx;
  const DefiniteIntegralResult r = definite_integral(parse("t^(-0.9)", ctx), "t", 0, 1);
  EXPECT_FALSE(r.divergent);
  EXPECT_NEAR(r.value, 10.0, 1e-11);
}

}  // namespace
}  // namespace hula::law
