// SPDX-License-Identifier: MIT
// Property tests of derivative identities (seeded RapidCheck, after Ceres'
// jet_test.cc): chain rule d/dt f(g(t)) = f'(g)·g', product and quotient
// rules against their textbook forms, and sqrt(x²) = |x| with equal
// derivatives away from 0, on random smooth expressions.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "hula/law/derive.hpp"
#include "hula/testing/fpe.hpp"
#include "law_generators.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

bool close(double a, double b, double scale) {
  if (std::isnan(a) || std::isnan(b) || std::isinf(a) || std::isinf(b) || scale > 1e12) return true;  // out of scope
  return std::fabs(a - b) <= 1e-10 * (1.0 + scale);
}

// checks: chain rule: d/dt substitute(f, t ← g) = f'(g(t)) · g'(t) at random t.
RC_GTEST_PROP(LawDeriveProperty, ChainRule, ()) {
  const auto fr = *test::gen_recipe(12, true);
  const auto gr = *test::gen_recipe(12, true);
  Context ctx;
  const Law f = test::build(fr, ctx);
  const Law g = test::build(gr, ctx);
  const Law lhs = derivative(substitute(f, "t", g), "t");
  const Law rhs = substitute(derivative(f, "t"), "t", g) * derivative(g, "t");
  const double t = *rc::gen::inRange(-2000, 2000) / 1000.0;
  const double a = test::eval1(lhs, t);
  const double b = test::eval1(rhs, t);
  RC_ASSERT(close(a, b, std::fabs(a) + std::fabs(b)));
}

// checks: product rule (fg)' = f'g + fg' and quotient rule (f/g)' = (f'g − fg')/g² at random t.
RC_GTEST_PROP(LawDeriveProperty, ProductAndQuotientRules, ()) {
  testing::FpeGuard guard;
  const auto fr = *test::gen_recipe(12, true);
  const auto gr = *test::gen_recipe(12, true);
  Context ctx;
  const Law f = test::build(fr, ctx);
  const Law g = test::build(gr, ctx);
  const Law df = derivative(f, "t");
  const Law dg = derivative(g, "t");
  const double t = *rc::gen::inRange(-2000, 2000) / 1000.0;
  const double p = test::eval1(derivative(f * g, "t"), t);
  const double p_ref = test::eval1(df * g + f * dg, t);
  RC_ASSERT(close(p, p_ref, std::fabs(p) + std::fabs(p_ref)));
  const double gv = test::eval1(g, t);
  RC_PRE(std::fabs(gv) > 1e-3);
  const double q = test::eval1(derivative(f / g, "t"), t);
  const double q_ref = test::eval1((df * g - f * dg) / (g * g), t);
  RC_ASSERT(close(q, q_ref, std::fabs(q) + std::fabs(q_ref)));
}

// checks: sqrt(x²) = |x| and d/dt sqrt(x²) = d/dt |x| where |x| > 1e-3.
RC_GTEST_PROP(LawDeriveProperty, SqrtOfSquareIsAbs, ()) {
  const auto xr = *test::gen_recipe(12, true);
  Context ctx;
  const Law x = test::build(xr, ctx);
  const double t = *rc::gen::inRange(-2000, 2000) / 1000.0;
  const double xv = test::eval1(x, t);
  RC_PRE(std::fabs(xv) > 1e-3 && std::fabs(xv) < 1e100);
  const Law s = sqrt(x * x);
  const Law a = abs(x);
  RC_ASSERT(close(test::eval1(s, t), test::eval1(a, t), std::fabs(xv)));
  const double ds = test::eval1(derivative(s, "t"), t);
  const double da = test::eval1(derivative(a, "t"), t);
  RC_ASSERT(close(ds, da, std::fabs(ds) + std::fabs(da)));
}

}  // namespace
}  // namespace hula::law
