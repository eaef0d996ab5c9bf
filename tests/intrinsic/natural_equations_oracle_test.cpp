// SPDX-License-Identifier: MIT
// Oracle tests of the natural-equation reconstruction (thesis 8.2.2, eq. 34)
// against closed forms and independent integrations: circle (κ = 1/R),
// circular helix (constant κ, τ), Euler spiral κ = s/a² against Fresnel
// integrals by their power series in long double, the log-aesthetic curve
// with α = 1 (ρ = 1 + Λs, a logarithmic spiral, closed form in complex
// arithmetic), a general κ = 1 + 0.5 sin s, τ = 0.3 cos 2s against classical
// RK4 in long double with Richardson-checked step, the round trip
// curve → (κ, τ) → curve up to a rigid motion, and frame orthonormality.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"

namespace hula::intrinsic {
namespace {

using law::Law;

struct Laws {
  law::Context ctx;
  Law parse(const std::string& text) {
    law::ParseOptions po;
    po.parameters = {"s"};
    return law::parse(text, ctx, po);
  }
};

// Largest deviation of {T, N, B} from an orthonormal right-handed frame.
double frame_defect(const FramePoint& p) {
  double worst = 0.0;
  const Vec3 f[3] = {p.tangent, p.normal, p.binormal};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(dot(f[i], f[j]) - (i == j ? 1.0 : 0.0)));
  return std::max(worst, max_abs(cross(p.tangent, p.normal) - p.binormal));
}

// Circular helix r(s) = (a cos(s/c), a sin(s/c), b s/c), c = sqrt(a² + b²).
struct HelixOfNaturalEquations {
  double a, b;
  [[nodiscard]] double c() const { return std::sqrt(a * a + b * b); }
  [[nodiscard]] Vec3 position(double s) const { return {a * std::cos(s / c()), a * std::sin(s / c()), b * s / c()}; }
  [[nodiscard]] Vec3 tangent(double s) const { return Vec3{-a * std::sin(s / c()), a * std::cos(s / c()), b} / c(); }
  [[nodiscard]] Vec3 normal(double s) const { return {-std::cos(s / c()), -std::sin(s / c()), 0.0}; }
};

// checks: κ = 1/R, τ = 0 gives the circle of radius R to 1e-10 (planar exact-angle and Frenet–Serret paths).
TEST(NaturalEquationsOracle, CircleBothMethods) {
  Laws l;
  const double R = 2.5, L = 2.0 * std::numbers::pi * R * 1.5;
  for (ReconstructionMethod m : {ReconstructionMethod::Auto, ReconstructionMethod::FrenetSerret}) {
    ReconstructionOptions o;
    o.method = m;
    const IntrinsicCurve c = reconstruct(l.parse("1/2.5"), l.parse("0"), "s", L, {}, o);
    EXPECT_EQ(c.method(),
              m == ReconstructionMethod::Auto ? IntegrationKind::PlanarExactAngle : IntegrationKind::FrenetSerret);
    for (int i = 0; i <= 50; ++i) {
      const double s = L * i / 50.0;
      const FramePoint p = c.evaluate(s);
      const Vec3 exact{R * std::sin(s / R), R * (1.0 - std::cos(s / R)), 0.0};
      EXPECT_LT(distance(p.position, exact), 1e-10) << "s = " << s;
      EXPECT_LT(frame_defect(p), 1e-12) << "s = " << s;
      EXPECT_LT(distance(p.tangent, Vec3{std::cos(s / R), std::sin(s / R), 0.0}), 1e-10);
    }
  }
}

// checks: constant κ, τ from a = 2, b = 0.7 give the circular helix (position and frame) to 1e-9 over 3 turns.
TEST(NaturalEquationsOracle, HelixMatchesClosedForm) {
  Laws l;
  const HelixOfNaturalEquations h{2.0, 0.7};
  const double k = h.a / (h.c() * h.c()), t = h.b / (h.c() * h.c());
  const double L = 3.0 * 2.0 * std::numbers::pi * h.c();
  const StartFrame start{h.position(0), h.tangent(0), h.normal(0)};
  const IntrinsicCurve c = reconstruct(l.ctx.constant(k), l.ctx.constant(t), "s", L, start);
  double worst = 0.0, worst_frame = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double s = L * i / 400.0;
    const FramePoint p = c.evaluate(s);
    worst = std::max(worst, distance(p.position, h.position(s)));
    worst_frame = std::max(worst_frame, distance(p.tangent, h.tangent(s)) + distance(p.normal, h.normal(s)));
    EXPECT_LT(frame_defect(p), 1e-12) << "s = " << s;
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(worst_frame, 1e-9);
}

// Fresnel integrals C(z) = ∫0^z cos(πt²/2) dt, S(z) = ∫0^z sin(πt²/2) dt by their power series
// in long double (terms (π/2)^k z^(2k+1) / (k! (2k+1)) with alternating signs per parity).
std::array<long double, 2> fresnel_cs(long double z) {
  const long double x = std::numbers::pi_v<long double> / 2.0L * z * z;
  long double c = 0.0L, s = 0.0L, term = z;  // term_k = x^k z / k!
  for (int k = 0; k < 200; ++k) {
    const long double v = term / (2 * k + 1);
    switch (k % 4) {
      case 0:
        c += v;
        break;
      case 1:
        s += v;
        break;
      case 2:
        c -= v;
        break;
      default:
        s -= v;
        break;
    }
    term *= x / (k + 1);
    if (std::abs(term) < 1e-30L) break;
  }
  return {c, s};
}

// checks: the Euler spiral κ = s/a² (a = 1.3) follows a√π (C, S)(s / (a√π)) to 1e-9 (Fresnel series reference).
TEST(NaturalEquationsOracle, EulerSpiralMatchesFresnel) {
  Laws l;
  const double a = 1.3, L = 4.0;
  const IntrinsicCurve c = reconstruct(l.parse("s/1.69"), l.parse("0"), "s", L);
  EXPECT_EQ(c.method(), IntegrationKind::PlanarExactAngle);
  const long double scale = a * std::sqrt(std::numbers::pi_v<long double>);
  for (int i = 0; i <= 80; ++i) {
    const double s = L * i / 80.0;
    const auto f = fresnel_cs(s / scale);
    const Vec3 exact{static_cast<double>(scale * f[0]), static_cast<double>(scale * f[1]), 0.0};
    EXPECT_LT(distance(c.evaluate(s).position, exact), 1e-9) << "s = " << s;
  }
}

// checks: the log-aesthetic curve with α = 1 (ρ = 1 + Λs, κ = 1/(1 + Λs)) equals the closed form
// z(s) = ((1 + Λs)^(1 + i/Λ) − 1) / (Λ + i) to 1e-9, with the angle from the exact antiderivative.
TEST(NaturalEquationsOracle, LogAestheticAlphaOne) {
  Laws l;
  const double lambda = 0.4, L = 12.0;
  const IntrinsicCurve c = reconstruct_planar(l.parse("1/(1 + 0.4*s)"), "s", L);
  EXPECT_EQ(c.method(), IntegrationKind::PlanarExactAngle);
  for (int i = 0; i <= 60; ++i) {
    const double s = L * i / 60.0;
    const std::complex<double> z =
        (std::pow(std::complex<double>(1.0 + lambda * s, 0.0), std::complex<double>(1.0, 1.0 / lambda)) - 1.0) /
        std::complex<double>(lambda, 1.0);
    EXPECT_LT(distance(c.evaluate(s).position, Vec3{z.real(), z.imag(), 0.0}), 1e-9) << "s = " << s;
  }
}

// checks: a sign-changing κ = cos(s) exp(−0.1 s²) (numeric-angle path) agrees with the Frenet–Serret path
// to 1e-9, and κ = cos s (exact angle θ = sin s) gives T = (cos θ, sin θ) to 1e-14.
TEST(NaturalEquationsOracle, SignChangingCurvaturePlanarPaths) {
  Laws l;
  const double L = 10.0;
  const Law kappa = l.parse("cos(s)*exp(-0.1*s^2)");  // no closed-form antiderivative: numeric angle
  const IntrinsicCurve planar = reconstruct_planar(kappa, "s", L);
  EXPECT_EQ(planar.method(), IntegrationKind::PlanarNumericAngle);
  ReconstructionOptions o;
  o.method = ReconstructionMethod::FrenetSerret;
  const IntrinsicCurve space = reconstruct(kappa, l.parse("0"), "s", L, {}, o);
  const IntrinsicCurve exact = reconstruct_planar(l.parse("cos(s)"), "s", L);
  EXPECT_EQ(exact.method(), IntegrationKind::PlanarExactAngle);
  for (int i = 0; i <= 100; ++i) {
    const double s = L * i / 100.0;
    const FramePoint a = planar.evaluate(s), b = space.evaluate(s);
    EXPECT_LT(distance(a.position, b.position), 1e-9) << "s = " << s;
    EXPECT_LT(distance(a.normal, b.normal), 1e-9) << "s = " << s;
    EXPECT_NEAR(a.position.z, 0.0, 0.0);
    // κ = cos s: θ = sin s, so T = (cos(sin s), sin(sin s)).
    const FramePoint e = exact.evaluate(s);
    EXPECT_LT(distance(e.tangent, Vec3{std::cos(std::sin(s)), std::sin(std::sin(s)), 0.0}), 1e-14);
  }
}

// Classical RK4 on the Frenet–Serret system in long double with n steps over [0, L]; returns r(L).
std::array<long double, 3> rk4_reference(long double L, int n) {
  using S = std::array<long double, 12>;
  auto f = [](long double s, const S& y) {
    const long double k = 1.0L + 0.5L * std::sin(s), t = 0.3L * std::cos(2.0L * s);
    S d{};
    for (int c = 0; c < 3; ++c) {
      d[c] = y[3 + c];
      d[3 + c] = k * y[6 + c];
      d[6 + c] = -k * y[3 + c] + t * y[9 + c];
      d[9 + c] = -t * y[6 + c];
    }
    return d;
  };
  S y{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const long double h = L / n;
  for (int i = 0; i < n; ++i) {
    const long double s = h * i;
    auto axpy = [](const S& a, long double w, const S& b) {
      S r;
      for (int c = 0; c < 12; ++c) r[c] = a[c] + w * b[c];
      return r;
    };
    const S k1 = f(s, y), k2 = f(s + h / 2, axpy(y, h / 2, k1)), k3 = f(s + h / 2, axpy(y, h / 2, k2)),
            k4 = f(s + h, axpy(y, h, k3));
    for (int c = 0; c < 12; ++c) y[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
  }
  return {y[0], y[1], y[2]};
}

// checks: κ = 1 + 0.5 sin s, τ = 0.3 cos 2s on [0, 8] matches RK4 in long double (step 8/8000, its own error
// bounded by comparison with step 8/4000: Richardson, (e_h − e_h/2)/15) to 1e-8.
TEST(NaturalEquationsOracle, GeneralCurvatureTorsionMatchesIndependentRk4) {
  Laws l;
  const double L = 8.0;
  const IntrinsicCurve c = reconstruct(l.parse("1 + 0.5*sin(s)"), l.parse("0.3*cos(2*s)"), "s", L);
  const auto fine = rk4_reference(L, 8000), coarse = rk4_reference(L, 4000);
  const FramePoint p = c.evaluate(L);
  for (int k = 0; k < 3; ++k) {
    // Richardson: the 4th-order error of the fine solution is about (fine − coarse) / 15.
    const long double richardson = fine[k] + (fine[k] - coarse[k]) / 15.0L;
    EXPECT_LT(std::abs(fine[k] - coarse[k]) / 15.0L, 1e-10L) << "reference not converged, component " << k;
    EXPECT_NEAR(p.position[static_cast<std::size_t>(k)], static_cast<double>(richardson), 1e-8) << "component " << k;
  }
  for (int i = 0; i <= 200; ++i) EXPECT_LT(frame_defect(c.evaluate(L * i / 200.0)), 1e-12);
}

// checks: the requested tolerance is honoured at every level from 1e-5 to 1e-10 (position at L against the
// Richardson-extrapolated long-double RK4 reference), and a looser tolerance takes fewer steps.
TEST(NaturalEquationsOracle, ToleranceIsHonoured) {
  Laws l;
  const double L = 8.0;
  const auto fine = rk4_reference(L, 8000), coarse = rk4_reference(L, 4000);
  std::size_t previous_steps = 0;
  for (const double tol : {1e-5, 1e-7, 1e-9, 1e-10}) {
    ReconstructionOptions o;
    o.tolerance = tol;
    const IntrinsicCurve c = reconstruct(l.parse("1 + 0.5*sin(s)"), l.parse("0.3*cos(2*s)"), "s", L, {}, o);
    const FramePoint p = c.evaluate(L);
    double err = 0.0;
    for (int k = 0; k < 3; ++k)
      err = std::max(err, std::abs(p.position[static_cast<std::size_t>(k)] -
                                   static_cast<double>(fine[k] + (fine[k] - coarse[k]) / 15.0L)));
    EXPECT_LE(err, tol) << "tolerance " << tol;
    EXPECT_GE(c.nodes().size(), previous_steps) << "tolerance " << tol;
    previous_steps = c.nodes().size();
  }
}

// checks: round trip helix → (κ, τ) laws computed from its parametrisation by a local formula →
// curve, started from a rotated and translated frame, equals the rigidly moved helix to 1e-9.
TEST(NaturalEquationsOracle, RoundTripHelixUpToRigidMotion) {
  Laws l;
  const HelixOfNaturalEquations h{1.5, 0.4};
  // r(t) with t = s/c, and κ = |r'×r''|/|r'|³, τ = (r'×r'')·r'''/|r'×r''|² as laws of s.
  const Law s = l.ctx.parameter("s");
  const Law r = law::vec(1.5 * law::cos(s / h.c()), 1.5 * law::sin(s / h.c()), 0.4 * s / h.c());
  const Law d1 = law::derivative(r, "s"), d2 = law::derivative(r, "s", 2), d3 = law::derivative(r, "s", 3);
  const Law kappa = law::norm(law::cross(d1, d2)) / law::pow(law::norm(d1), 3.0);
  const Law tau = law::dot(law::cross(d1, d2), d3) / law::pow(law::norm(law::cross(d1, d2)), 2.0);
  // Rigid motion Q: rotation about (1, 2, 2)/3 by 0.7 rad, then translation by p.
  const Vec3 axis = Vec3{1, 2, 2} / 3.0, p{3, -1, 5};
  const double ang = 0.7;
  auto rotate = [&](const Vec3& v) {
    return v * std::cos(ang) + cross(axis, v) * std::sin(ang) + axis * (dot(axis, v) * (1 - std::cos(ang)));
  };
  const StartFrame start{p + rotate(h.position(0)), rotate(h.tangent(0)) * 3.0,
                         rotate(h.normal(0)) + rotate(h.tangent(0))};
  const double L = 25.0;
  const IntrinsicCurve c = reconstruct(kappa, tau, "s", L, start);
  for (int i = 0; i <= 100; ++i) {
    const double at = L * i / 100.0;
    EXPECT_LT(distance(c.evaluate(at).position, p + rotate(h.position(at))), 1e-9) << "s = " << at;
  }
}

// checks: the other direction of the round trip: κ and τ of the fitted NURBS (local formulas
// κ = |C'×C''|/|C'|³, τ = (C'×C'')·C'''/|C'×C''|² at generic points, where C''' exists) and its speed
// |C'| (arc-length parameter) agree with the prescribed κ = 1 + 0.5 sin s, τ = 0.3 cos 2s.
TEST(NaturalEquationsOracle, FittedNurbsCarriesThePrescribedCurvatureAndTorsion) {
  Laws l;
  const double L = 8.0;
  const IntrinsicCurve c = reconstruct(l.parse("1 + 0.5*sin(s)"), l.parse("0.3*cos(2*s)"), "s", L);
  NurbsFitOptions o;
  o.tolerance = 1e-10;
  const NurbsFitResult fit = fit_nurbs(c, o);
  ASSERT_TRUE(fit.converged);
  double worst_k = 0.0, worst_t = 0.0, worst_speed = 0.0;
  for (int i = 0; i < 997; ++i) {
    const double s = L * (i + 0.5) / 997.0;  // generic points, away from the breakpoints
    const std::vector<Vec3> d = fit.curve.derivatives(s, 3);
    const Vec3 c12 = cross(d[1], d[2]);
    const double speed = norm(d[1]);
    worst_speed = std::max(worst_speed, std::abs(speed - 1.0));
    worst_k = std::max(worst_k, std::abs(norm(c12) / (speed * speed * speed) - (1 + 0.5 * std::sin(s))));
    worst_t = std::max(worst_t, std::abs(dot(c12, d[3]) / norm_squared(c12) - 0.3 * std::cos(2 * s)));
  }
  // Observed: speed 1e-9, kappa 7e-8, tau 1.3e-5 (tau needs the third derivative, fitted least well).
  EXPECT_LT(worst_speed, 1e-8);
  EXPECT_LT(worst_k, 1e-6);
  EXPECT_LT(worst_t, 1e-4);
}

// checks: the fitted NURBS of a 2-turn helix stays within its tolerance when re-measured against the closed form.
TEST(NaturalEquationsOracle, FittedNurbsWithinTolerance) {
  Laws l;
  const HelixOfNaturalEquations h{1.0, 0.3};
  const double L = 2.0 * 2.0 * std::numbers::pi * h.c();
  const StartFrame start{h.position(0), h.tangent(0), h.normal(0)};
  const IntrinsicCurve c =
      reconstruct(l.ctx.constant(h.a / (h.c() * h.c())), l.ctx.constant(h.b / (h.c() * h.c())), "s", L, start);
  NurbsFitOptions o;
  o.tolerance = 1e-8;
  const NurbsFitResult fit = fit_nurbs(c, o);
  EXPECT_TRUE(fit.converged);
  EXPECT_LE(fit.max_deviation, 1e-8);
  EXPECT_EQ(fit.curve.degree(), 5);
  double worst = 0.0;
  for (int i = 0; i <= 5000; ++i) {
    const double s = L * i / 5000.0;
    worst = std::max(worst, distance(fit.curve.derivatives(s, 0)[0], h.position(s)));
  }
  EXPECT_LT(worst, 1e-8);
}

}  // namespace
}  // namespace hula::intrinsic
