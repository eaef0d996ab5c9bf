// SPDX-License-Identifier: MIT
// Log-aesthetic curves (intrinsic/log_aesthetic.hpp) against closed forms: κ(s) of the special slopes
// α = −1 (clothoid), 0 (exponential radius), 1 (logarithmic spiral), 2 (circle involute); the positions of
// α = −1 against the Fresnel-based clothoid and of α = 1 against the logarithmic spiral's closed form; and
// monotone curvature as a seeded property (exact law derivative, and diffgeom::curvature_monotonicity on
// the curve's NURBS).
#include "hula/intrinsic/log_aesthetic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <random>
#include <string>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/monotonicity.hpp"
#include "hula/intrinsic/clothoid.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/tape.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::intrinsic {
namespace {

// κ and dκ/ds of the curve's law at s (compiled tape).
std::array<double, 2> law_values(const LogAestheticCurve& c, double s) {
  law::Context ctx;
  const law::Law k = c.curvature_law(ctx);
  const law::Law outs[2] = {k, law::derivative(k, "s")};
  const std::string in[1] = {"s"};
  const law::Tape tape = law::Tape::compile(outs, in);
  law::Workspace w = tape.make_workspace();
  std::array<double, 2> out{};
  EXPECT_TRUE(tape.evaluate(std::span<const double>(&s, 1), out, w));
  return out;
}

// checks: the exact law κ(s) equals the closed form of each special slope, and its derivative −λ ρ^{−1−α}.
TEST(LogAesthetic, CurvatureLawMatchesClosedForms) {
  const double rho0 = 2.0, lambda = 0.3;
  for (double s : {0.0, 0.5, 1.7, 3.0}) {
    const auto k = [&](double alpha) { return law_values({alpha, rho0, lambda, 4.0}, s); };
    EXPECT_NEAR(k(-1.0)[0], 1.0 / rho0 - lambda * s, 1e-15) << s;                       // clothoid
    EXPECT_NEAR(k(0.0)[0], std::exp(-lambda * s) / rho0, 1e-15) << s;                   // exponential radius
    EXPECT_NEAR(k(1.0)[0], 1.0 / (rho0 + lambda * s), 1e-15) << s;                      // logarithmic spiral
    EXPECT_NEAR(k(2.0)[0], 1.0 / std::sqrt(rho0 * rho0 + 2 * lambda * s), 1e-15) << s;  // circle involute
    EXPECT_NEAR(k(1.0)[1], -lambda / std::pow(rho0 + lambda * s, 2.0), 1e-15) << s;
    const LogAestheticCurve c{0.7, rho0, lambda, 4.0};
    EXPECT_NEAR(law_values(c, s)[0], c.curvature(s), 1e-15);
    EXPECT_NEAR(law_values(c, s)[1], c.curvature_rate(s), 1e-14);
  }
}

// checks: α = −1 is the clothoid κ = 1/ρ0 − λ s (up to its inflection at s = 1/(ρ0 λ), where ρ leaves the family's
// domain): its reconstruction equals the Fresnel-quadrature clothoid to 1e-10.
TEST(LogAesthetic, SlopeMinusOneIsTheClothoid) {
  const LogAestheticCurve lac{-1.0, 2.0, 0.3, 1.6};
  const IntrinsicCurve c = lac.to_intrinsic();
  const ClothoidSegment cl{.kappa0 = 0.5, .dkappa = -0.3, .length = 1.6};
  for (double s = 0.0; s <= 1.6; s += 0.1) EXPECT_LT(distance(c.evaluate(s).position, cl.point(s)), 1e-10) << s;
}

// checks: α = 1 is the logarithmic spiral ρ = ρ0 + λ s, θ(s) = ln(1 + λ s/ρ0)/λ, whose position is
// x + i y = ρ0 (e^{(λ + i) θ} − 1)/(λ + i) from the origin heading +x, to 1e-10.
TEST(LogAesthetic, SlopeOneIsTheLogarithmicSpiral) {
  const double rho0 = 1.5, lambda = 0.4;
  const LogAestheticCurve lac{1.0, rho0, lambda, 6.0};
  const IntrinsicCurve c = lac.to_intrinsic();
  for (double s = 0.0; s <= 6.0; s += 0.5) {
    const double theta = std::log1p(lambda * s / rho0) / lambda;
    const std::complex<double> li(lambda, 1.0);
    const std::complex<double> z = rho0 * (std::exp(li * theta) - 1.0) / li;
    const Vec3 p = c.evaluate(s).position;
    EXPECT_NEAR(p.x, z.real(), 1e-10) << s;
    EXPECT_NEAR(p.y, z.imag(), 1e-10) << s;
  }
}

// checks (seeded property, 30 curves): for α ∈ [−3, 3], ρ0 ∈ [0.5, 3], λ ≠ 0 the exact dκ/ds has the sign of
// −λ at 101 points, and the analysis of the curve's fitted NURBS finds one monotone piece and no violation.
TEST(LogAesthetic, CurvatureIsMonotone) {
  std::mt19937_64 rng(1414);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 30; ++i) {
    LogAestheticCurve c{-3.0 + 6.0 * u(rng), 0.5 + 2.5 * u(rng), (u(rng) < 0.5 ? -1.0 : 1.0) * (0.05 + 0.3 * u(rng)),
                        0.0};
    c.length = std::min(4.0, 0.8 * c.max_length());
    const double sign = c.lambda > 0 ? -1.0 : 1.0;
    for (int k = 0; k <= 100; ++k) EXPECT_GT(sign * law_values(c, c.length * k / 100.0)[1], 0.0) << i << " " << k;
    NurbsFitOptions fo;
    fo.tolerance = 1e-8;
    const NurbsFitResult fit = fit_nurbs(c.to_intrinsic(), fo);
    const diffgeom::CurvatureMonotonicity m = diffgeom::curvature_monotonicity(curve::Curve(fit.curve), true);
    EXPECT_TRUE(m.monotone()) << i << ": alpha " << c.alpha << " lambda " << c.lambda;
    ASSERT_EQ(m.pieces.size(), 1u) << i;
    EXPECT_EQ(m.pieces[0].trend,
              c.lambda > 0 ? diffgeom::CurvatureTrend::Decreasing : diffgeom::CurvatureTrend::Increasing)
        << i;
  }
}

// checks: a length past the end of the family (ρ reaches 0) and a non-positive radius are refused, naming them.
TEST(LogAesthetic, RefusesBadParameters) {
  const LogAestheticCurve past{1.0, 1.0, -0.5, 3.0};  // ρ = 1 − 0.5 s reaches 0 at s = 2
  EXPECT_DOUBLE_EQ(past.max_length(), 2.0);
  HULA_EXPECT_ERROR((void)past.to_intrinsic(), Errc::InvalidArgument, "length");
  HULA_EXPECT_ERROR((void)LogAestheticCurve({1.0, 0.0, 0.1, 1.0}).to_intrinsic(), Errc::InvalidArgument, "rho0");
  HULA_EXPECT_ERROR((void)LogAestheticCurve({std::nan(""), 1.0, 0.1, 1.0}).to_intrinsic(), Errc::NonFiniteInput,
                    "alpha");
}

}  // namespace
}  // namespace hula::intrinsic
