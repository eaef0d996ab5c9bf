// SPDX-License-Identifier: MIT
// Integrals of closed forms to 1e-12 relative: helix arc length
// sqrt(a² + b²)·L, ∫sin, Fresnel integrals S(1), C(1) (Abramowitz & Stegun
// 7.3, table 7.7), a Gaussian against erf, and a kinked integrand split at
// its kink; the reported error estimate bounds the true error.
#include "hula/law/integrate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"

namespace hula::law {
namespace {

void expect_integral(const char* text, double a, double b, double want) {
  SCOPED_TRACE(text);
  Context ctx;
  const IntegrationResult r = integrate(parse(text, ctx), "t", a, b);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.value, want, 1e-12 * std::fabs(want));
  EXPECT_LE(std::fabs(r.value - want), std::max(r.error_estimate, 4e-16 * std::fabs(want)) * 10);
}

// checks: helix arc length ∫|r'| = sqrt(4 + 0.25)·L against the closed form.
TEST(LawIntegrate, HelixArcLength) {
  const double L = 4 * std::numbers::pi;
  expect_integral("norm(vec(-2*sin(t), 2*cos(t), 0.5))", 0, L, std::sqrt(4.25) * L);
  Context ctx;
  const Law r = parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx);
  const IntegrationResult res = integrate(norm(derivative(r, "t")), "t", 0, L);
  EXPECT_NEAR(res.value, std::sqrt(4.25) * L, 1e-12 * std::sqrt(4.25) * L);
}

// checks: ∫sin, ∫exp, polynomials, Fresnel S(1), C(1) and ∫exp(−t²) = √π/2·erf(2) against known values.
TEST(LawIntegrate, ClosedForms) {
  expect_integral("sin(t)", 0, 2, 1 - std::cos(2.0));
  expect_integral("sin(3*t + 1)", -1, 4, (std::cos(-3.0 + 1) - std::cos(12.0 + 1)) / 3);
  expect_integral("exp(0.5*t)", 0, 3, 2 * (std::exp(1.5) - 1));
  expect_integral("t^5 - 2*t", -1, 2, (64.0 - 1) / 6 - (4.0 - 1));
  expect_integral("sin(pi*t^2/2)", 0, 1, 0.43825914739035476607);  // Fresnel S(1)
  expect_integral("cos(pi*t^2/2)", 0, 1, 0.77989340037682282947);  // Fresnel C(1)
  expect_integral("exp(-t^2)", 0, 2, std::sqrt(std::numbers::pi) / 2 * std::erf(2.0));
  expect_integral("1/(1+t^2)", 0, 1, std::numbers::pi / 4);
}

// checks: kinks and switches are split so ∫|t − 0.3| and a piecewise law reach 1e-12; a > b negates.
TEST(LawIntegrate, NonSmoothAndReversed) {
  expect_integral("abs(t - 0.3)", 0, 1, 0.3 * 0.3 / 2 + 0.7 * 0.7 / 2);
  expect_integral("piecewise(t < 1, t^2, 2 - t)", 0, 2, 1.0 / 3 + 0.5);
  Context ctx;
  const IntegrationResult r = integrate(parse("abs(t - 0.3)", ctx), "t", 0, 1);
  EXPECT_EQ(r.pieces, 2U);
  expect_integral("t", 1, 0, -0.5);
}

// checks: undefined integrands and bad options are errors naming the parameter value or the field.
TEST(LawIntegrate, Errors) {
  testing::FpeGuard guard;
  Context ctx;
  HULA_EXPECT_ERROR(integrate(parse("sqrt(t)", ctx), "t", -1, 1, {.split_at_singularities = false}),
                    Errc::NumericalFailure, "integrand is undefined at t = -");
  HULA_EXPECT_ERROR(integrate(parse("vec(t, t)", ctx), "t", 0, 1), Errc::InvalidArgument, "expects a scalar law");
  HULA_EXPECT_ERROR(integrate(parse("t", ctx), "t", 0, std::nan("")), Errc::InvalidArgument, "bounds must be numbers");
  IntegrationOptions o;
  o.relative_tolerance = 0;
  HULA_EXPECT_ERROR(integrate(parse("t", ctx), "t", 0, 1, o), Errc::InvalidOption,
                    "IntegrationOptions::relative_tolerance");
}

}  // namespace
}  // namespace hula::law
