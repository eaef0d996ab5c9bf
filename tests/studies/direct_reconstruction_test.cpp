// SPDX-License-Identifier: MIT
// Tests of direct reconstruction from prescribed profiles against closed forms:
// circle arcs, the Euler spiral (Fresnel integrals by their power series) and
// the helix, as initial-value problems and as boundary-value problems whose end
// comes from the same curve (zero correction); a perturbed arc target held to
// the unperturbed arc's end; a target tabulated from a known cubic Bézier
// curve's κ(s); and the documented errors.
#include "hula/studies/direct_reconstruction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hula/io/match_study_file.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/curvature_target.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

struct Laws {
  law::Context ctx;
  Profile profile(const std::string& text) {
    law::ParseOptions po;
    po.parameters = {"u"};
    return Profile::from_law(law::parse(text, ctx, po), "u");
  }
};

DirectReconstructionOptions no_fit() {
  DirectReconstructionOptions o;
  o.fit = false;
  return o;
}

double max_abs(const std::vector<double>& c) {
  double m = 0.0;
  for (const double v : c) m = std::max(m, std::abs(v));
  return m;
}

// Circle of radius R from the origin heading +X, turning left (centre (0, R)).
Vec3 arc_point(double R, double s) { return {R * std::sin(s / R), R * (1.0 - std::cos(s / R)), 0.0}; }
Vec3 arc_tangent(double R, double s) { return {std::cos(s / R), std::sin(s / R), 0.0}; }

// checks: κ* = 1/R as an initial-value problem gives the circle arc at every s (closed form), no correction.
TEST(DirectReconstruction, CircleInitialValueIsTheArc) {
  Laws l;
  const double R = 2.5, L = 7.0;
  const DirectReconstructionResult r =
      reconstruct_direct({.curvature = l.profile("1/2.5"), .length = L}, DirectReconstructionOptions{});
  EXPECT_TRUE(r.planar);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.mean_curvature_deviation, 0.0);
  for (double s = 0.0; s <= L; s += 0.35)
    EXPECT_LT(distance(r.curve.evaluate(s).position, arc_point(R, s)), 1e-10) << s;
  ASSERT_TRUE(r.nurbs.has_value());
  EXPECT_TRUE(r.nurbs->converged);
  EXPECT_LT(distance(r.nurbs->curve.evaluate(L), arc_point(R, L)), 1e-9);
}

// checks: end point and tangent taken from the arc itself need zero correction (to rounding).
TEST(DirectReconstruction, CircleWithItsOwnEndNeedsNoCorrection) {
  Laws l;
  const double R = 2.5, L = 7.0;
  const DirectReconstructionResult r = reconstruct_direct(
      {.curvature = l.profile("0.4"), .length = L, .end_point = arc_point(R, L), .end_tangent = arc_tangent(R, L)},
      no_fit());
  EXPECT_LE(r.end_point_error, 1e-9 * L);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  EXPECT_LT(max_abs(r.curvature_correction), 1e-9);
  EXPECT_LT(r.mean_curvature_deviation, 1e-10);
  EXPECT_LE(r.iterations, 2);
}

// Euler spiral κ(s) = s / a² from the origin heading +X: x + iy = ∫₀ˢ exp(i t² / (2a²)) dt, by
// the power series Σ (i / (2a²))ⁿ s^{2n+1} / (n! (2n + 1)) (Fresnel integrals).
Vec3 spiral_point(double a, double s) {
  double re = 0.0, im = 0.0;
  double term = s;  // (1/(2a²))ⁿ s^{2n+1} / n!
  for (int n = 0; n < 80; ++n) {
    const double v = term / (2.0 * n + 1.0);
    switch (n % 4) {
      case 0:
        re += v;
        break;
      case 1:
        im += v;
        break;
      case 2:
        re -= v;
        break;
      default:
        im -= v;
        break;
    }
    term *= s * s / (2.0 * a * a) / (n + 1.0);
  }
  return {re, im, 0.0};
}

// checks: the Euler spiral (κ linear in u) against the Fresnel series, IVP and BVP with its own end.
TEST(DirectReconstruction, EulerSpiralMatchesFresnelAndNeedsNoCorrection) {
  Laws l;
  const double a_eff = std::sqrt(2.0), L = 4.0;  // κ(s) = s / a², κ(u) = u L / a² = 2u
  const Profile k = l.profile("2*u");
  const DirectReconstructionResult ivp = reconstruct_direct({.curvature = k, .length = L}, no_fit());
  for (double s = 0.0; s <= L; s += 0.25)
    EXPECT_LT(distance(ivp.curve.evaluate(s).position, spiral_point(a_eff, s)), 1e-10) << s;
  const double theta_end = L * L / (2.0 * a_eff * a_eff);
  const DirectReconstructionResult bvp =
      reconstruct_direct({.curvature = k,
                          .length = L,
                          .end_point = spiral_point(a_eff, L),
                          .end_tangent = Vec3{std::cos(theta_end), std::sin(theta_end), 0.0}},
                         no_fit());
  EXPECT_LE(bvp.end_point_error, 1e-9 * L);
  EXPECT_LE(bvp.end_tangent_error, 1e-9);
  EXPECT_LT(max_abs(bvp.curvature_correction), 1e-8);
}

// Helix with curvature κ and torsion τ: radius ρ = κ/(κ²+τ²), pitch h = τ/(κ²+τ²), c = √(ρ²+h²);
// r(s) = (ρ cos(s/c), ρ sin(s/c), h s/c), T(0) = (0, ρ, h)/c, N(0) = (−1, 0, 0).
struct Helix {
  double kappa, tau;
  double rho() const { return kappa / (kappa * kappa + tau * tau); }
  double h() const { return tau / (kappa * kappa + tau * tau); }
  double c() const { return std::hypot(rho(), h()); }
  Vec3 point(double s) const { return {rho() * std::cos(s / c()), rho() * std::sin(s / c()), h() * s / c()}; }
  Vec3 tangent(double s) const { return Vec3{-rho() * std::sin(s / c()), rho() * std::cos(s / c()), h()} / c(); }
  intrinsic::StartFrame start() const { return {point(0.0), tangent(0.0), Vec3{-1.0, 0.0, 0.0}}; }
  // N(s) = (−cos(s/c), −sin(s/c), 0): towards the axis.
  Vec3 normal(double s) const { return {-std::cos(s / c()), -std::sin(s / c()), 0.0}; }
};

// checks: constant κ, τ reconstruct the helix (closed form) and its own end needs no correction.
TEST(DirectReconstruction, HelixInitialAndBoundaryValue) {
  Laws l;
  const Helix hx{0.8, 0.4};
  const double L = 20.0;
  const DirectReconstructionResult ivp = reconstruct_direct(
      {.curvature = l.profile("0.8"), .torsion = l.profile("0.4"), .length = L, .start = hx.start()}, no_fit());
  EXPECT_FALSE(ivp.planar);
  for (double s = 0.0; s <= L; s += 1.0) EXPECT_LT(distance(ivp.curve.evaluate(s).position, hx.point(s)), 1e-9) << s;
  const DirectReconstructionResult bvp = reconstruct_direct({.curvature = l.profile("0.8"),
                                                             .torsion = l.profile("0.4"),
                                                             .length = L,
                                                             .start = hx.start(),
                                                             .end_point = hx.point(L),
                                                             .end_tangent = hx.tangent(L)},
                                                            no_fit());
  EXPECT_LE(bvp.end_point_error, 1e-9 * L);
  EXPECT_LE(bvp.end_tangent_error, 1e-9);
  EXPECT_LT(max_abs(bvp.curvature_correction), 1e-9);
  EXPECT_LT(max_abs(bvp.torsion_correction), 1e-9);
}

// checks: a perturbed helix target held to the helix's end meets it to 1e-9 L with a correction
// of the size of the perturbation, and the fitted NURBS ends there too.
TEST(DirectReconstruction, PerturbedHelixMeetsTheEnd) {
  Laws l;
  const Helix hx{0.8, 0.4};
  const double L = 10.0;
  const DirectReconstructionResult r = reconstruct_direct({.curvature = l.profile("0.8 + 0.05*sin(2*pi*u)"),
                                                           .torsion = l.profile("0.4 - 0.05*u"),
                                                           .length = L,
                                                           .start = hx.start(),
                                                           .end_point = hx.point(L),
                                                           .end_tangent = hx.tangent(L)},
                                                          DirectReconstructionOptions{});
  EXPECT_LE(r.end_point_error, 1e-9 * L);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  EXPECT_GT(r.mean_curvature_deviation + r.mean_torsion_deviation, 1e-4);
  EXPECT_LT(r.max_curvature_deviation, 0.2);
  EXPECT_LT(r.max_torsion_deviation, 0.2);
  ASSERT_TRUE(r.nurbs.has_value());
  EXPECT_LT(distance(r.nurbs->curve.evaluate(L), hx.point(L)), 1e-9 * L + r.nurbs->max_deviation);
}

// checks: κ = 1/R + 0.1 sin(2πu) held to the unperturbed arc's end point and tangent: the
// constraints hold to 1e-9 L, the correction is small and smooth (a quintic whose size is that of
// the perturbation's effect), the curve stays close to the target's curvature.
TEST(DirectReconstruction, PerturbedArcMeetsTheArcEnd) {
  Laws l;
  const double R = 2.0, L = 5.0;
  const DirectReconstructionResult r = reconstruct_direct({.curvature = l.profile("0.5 + 0.1*sin(2*pi*u)"),
                                                           .length = L,
                                                           .end_point = arc_point(R, L),
                                                           .end_tangent = arc_tangent(R, L)},
                                                          DirectReconstructionOptions{});
  EXPECT_LE(r.end_point_error, 1e-9 * L);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  // The exact answer −0.1 sin(2πu) is not a quintic, so a correction remains but stays below the
  // perturbation's amplitude; smooth: its Bernstein coefficients are bounded too.
  EXPECT_GT(r.mean_curvature_deviation, 1e-3);
  EXPECT_LT(r.max_curvature_deviation, 0.1);
  EXPECT_LT(max_abs(r.curvature_correction), 0.5);
  EXPECT_EQ(r.curve.method(), intrinsic::IntegrationKind::PlanarExactAngle);
  // The fitted NURBS (independently evaluated) ends at the arc's end.
  ASSERT_TRUE(r.nurbs.has_value());
  EXPECT_TRUE(r.nurbs->converged);
  EXPECT_LT(distance(r.nurbs->curve.evaluate(L), arc_point(R, L)), 1e-9 * L + r.nurbs->max_deviation);
  // Only the point: fewer constraints, a smaller (never larger) minimum-norm correction.
  const DirectReconstructionResult point_only = reconstruct_direct(
      {.curvature = l.profile("0.5 + 0.1*sin(2*pi*u)"), .length = L, .end_point = arc_point(R, L)}, no_fit());
  EXPECT_LE(point_only.end_point_error, 1e-9 * L);
  EXPECT_LE(point_only.mean_curvature_deviation, r.mean_curvature_deviation * (1.0 + 1e-6));
}

// checks: with vary_length and a tiny length weight, a circle target held to a point a quarter
// turn away recovers the quarter arc: L → πR/2 and δκ → 0.
TEST(DirectReconstruction, VaryLengthFindsTheQuarterArc) {
  Laws l;
  const double R = 1.0;
  DirectReconstructionOptions o = no_fit();
  o.vary_length = true;
  o.length_weight = 1e-6;
  const DirectReconstructionResult r =
      reconstruct_direct({.curvature = l.profile("1"), .length = 1.2, .end_point = arc_point(R, kPi / 2.0)}, o);
  EXPECT_LE(r.end_point_error, 1e-9 * r.length);
  EXPECT_NEAR(r.length, kPi / 2.0, 1e-3);
  EXPECT_LT(r.mean_curvature_deviation, 1e-3);
}

// checks: IVP of a straight line with vary_length and an end point straight ahead: L becomes the distance.
TEST(DirectReconstruction, VaryLengthStraightLine) {
  Laws l;
  DirectReconstructionOptions o = no_fit();
  o.vary_length = true;
  const DirectReconstructionResult r =
      reconstruct_direct({.curvature = l.profile("0"), .length = 1.5, .end_point = Vec3{2.0, 0.0, 0.0}}, o);
  EXPECT_NEAR(r.length, 2.0, 1e-9);
  EXPECT_LT(r.mean_curvature_deviation, 1e-9);
}

// checks: a target tabulated from a cubic Bézier's κ(s) (201 samples, natural cubic spline
// through them as a B-spline profile) recovers the Bézier: positions at equal arc length within
// 1e-6 L (spline error h⁴·|κ⁗|-sized), and, held to the Bézier's end point and tangent, the end
// to 1e-9 L with a correction below 1e-5.
TEST(DirectReconstruction, RecoversABezierFromItsCurvature) {
  const nurbs::NurbsCurve bez(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2.5, -0.5, 0}, {3.5, 1, 0}});
  const hula::testing::CurvatureTarget target = hula::testing::planar_curvature_target(bez, 201);
  const double L = target.length;
  const DirectReconstructionResult ivp =
      reconstruct_direct({.curvature = target.profile, .length = L, .start = target.start}, no_fit());
  EXPECT_LT(hula::testing::max_distance_at_equal_length(ivp.curve, bez, 50), 1e-6 * L);
  const DirectReconstructionResult bvp = reconstruct_direct({.curvature = target.profile,
                                                             .length = L,
                                                             .start = target.start,
                                                             .end_point = target.end_point,
                                                             .end_tangent = target.end_tangent},
                                                            no_fit());
  EXPECT_LE(bvp.end_point_error, 1e-9 * L);
  EXPECT_LE(bvp.end_tangent_error, 1e-9);
  EXPECT_LT(bvp.max_curvature_deviation, 1e-5);
}

// checks: the JSON summary carries the measured numbers.
TEST(DirectReconstruction, SummaryJson) {
  Laws l;
  const DirectReconstructionResult r = reconstruct_direct(
      {.curvature = l.profile("0.5"), .length = 5.0, .end_point = arc_point(2.0, 5.0)}, DirectReconstructionOptions{});
  const io::json::Json j = io::direct_reconstruction_summary(r);
  EXPECT_EQ(j.at("planar").get<bool>(), true);
  EXPECT_EQ(j.at("end_point_error").get<double>(), r.end_point_error);
  EXPECT_EQ(j.at("curvature_correction").size(), 6U);
  EXPECT_EQ(j.at("nurbs").at("degree").get<int>(), 5);
  EXPECT_TRUE(j.at("nurbs").at("converged").get<bool>());
}

// checks: bad lengths, unreachable or off-plane ends, NaN, too few unknowns and options are
// rejected before any run, naming the input.
TEST(DirectReconstruction, RejectsBadInputNamingIt) {
  Laws l;
  const Profile k = l.profile("0.5");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 0.0}), Errc::InvalidArgument, "length = 0");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = -1.0}), Errc::InvalidArgument, "length = -1");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = kNan}), Errc::NonFiniteInput, "length");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 2.0, .end_point = Vec3{3.0, 0.0, 0.0}}),
                    Errc::InvalidArgument, "farther");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 2.0, .end_point = Vec3{1.0, 0.0, 0.5}}),
                    Errc::InvalidArgument, "off the plane");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 2.0, .end_point = Vec3{kNan, 0.0, 0.0}}),
                    Errc::NonFiniteInput, "end_point[0]");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 2.0, .end_tangent = Vec3{}}), Errc::InvalidArgument,
                    "end_tangent");
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 2.0, .end_tangent = Vec3{0.0, 0.0, 1.0}}),
                    Errc::InvalidArgument, "end_tangent");
  DirectReconstructionOptions o;
  o.correction_degree = 1;
  o.correct_torsion = false;
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k,
                                        .torsion = l.profile("0.1"),
                                        .length = 2.0,
                                        .end_point = Vec3{1.0, 1.0, 0.1},
                                        .end_tangent = Vec3{0.0, 1.0, 0.0}},
                                       o),
                    Errc::InvalidOption, "correction_degree = 1");
  o = {};
  o.end_tolerance = 0.0;
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .length = 2.0}, o), Errc::InvalidOption, "end_tolerance");
  law::Context other;
  law::ParseOptions po;
  po.parameters = {"u"};
  const Profile foreign = Profile::from_law(law::parse("0.1", other, po));
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = k, .torsion = foreign, .length = 2.0}), Errc::InvalidArgument,
                    "torsion");
}

// checks: a budget too small to meet a far end is a NumericalFailure that reports what was reached.
TEST(DirectReconstruction, NonConvergenceReportsWhatWasReached) {
  Laws l;
  DirectReconstructionOptions o = no_fit();
  o.max_iterations = 1;
  HULA_EXPECT_ERROR(reconstruct_direct({.curvature = l.profile("0.5 + 2*sin(3*pi*u)"),
                                        .length = 5.0,
                                        .end_point = Vec3{3.0, -2.0, 0.0},
                                        .end_tangent = Vec3{0.0, -1.0, 0.0}},
                                       o),
                    Errc::NumericalFailure, "reached end point error");
}

}  // namespace
}  // namespace hula::studies

namespace hula::studies {
namespace {

// checks: the same problem built twice (fresh law contexts) gives bit-identical corrections and
// end errors, so a study run repeats exactly.
TEST(DirectReconstruction, RepeatsExactly) {
  const auto solve = [] {
    Laws l;
    return reconstruct_direct({.curvature = l.profile("0.8 + 0.05*sin(2*pi*u)"),
                               .torsion = l.profile("0.4 - 0.05*u"),
                               .length = 10.0,
                               .end_point = Vec3{1.0, 2.0, 3.0},
                               .end_tangent = Vec3{0.0, 0.0, 1.0}},
                              no_fit());
  };
  const DirectReconstructionResult a = solve(), b = solve();
  EXPECT_EQ(a.curvature_correction, b.curvature_correction);
  EXPECT_EQ(a.torsion_correction, b.torsion_correction);
  EXPECT_EQ(a.end_point_error, b.end_point_error);
  EXPECT_EQ(a.iterations, b.iterations);
}

}  // namespace
}  // namespace hula::studies

namespace hula::studies {
namespace {

// checks: the header's example meets its end to 1e-9 L (end point 3.2 from the start, L = 4).
TEST(DirectReconstruction, HeaderExampleMeetsItsEnd) {
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {"u"};
  const DirectReconstructionProblem p{.curvature = Profile::from_law(law::parse("0.5 + 0.1*sin(6*u)", ctx, po)),
                                      .length = 4.0,
                                      .end_point = Vec3{2.5, 2.0, 0.0}};
  const DirectReconstructionResult r = reconstruct_direct(p);
  EXPECT_LE(r.end_point_error, 4e-9);
  EXPECT_GT(r.mean_curvature_deviation, 0.0);
  EXPECT_GT(r.seconds, 0.0);
  EXPECT_GE(r.reconstructions,
            r.iterations);  // one per trial step plus the start; the last linearisation may only confirm
}

}  // namespace
}  // namespace hula::studies

namespace hula::studies {
namespace {

// checks: held end curvatures (a G2 join) fix the correction's end coefficients: κ(0) and κ(L) are the held values
// to rounding, the end point and tangent of the arc (closed form) still hold to 1e-9.
TEST(DirectReconstruction, HeldEndCurvaturesAreExact) {
  Laws l;
  const double R = 2.0, L = 5.0;
  DirectReconstructionProblem p{.curvature = l.profile("0.5 + 0.1*sin(2*pi*u)")};
  p.length = L;
  p.end_point = arc_point(R, L);
  p.end_tangent = arc_tangent(R, L);
  p.start_curvature = 0.45;
  p.end_curvature = 0.6;
  const DirectReconstructionResult r = reconstruct_direct(p, no_fit());
  EXPECT_LE(r.end_point_error, 1e-9 * L);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  EXPECT_NEAR(r.curve.evaluate(0.0).curvature, 0.45, 1e-12);
  EXPECT_NEAR(r.curve.evaluate(L).curvature, 0.6, 1e-12);
  EXPECT_NEAR(r.curvature_correction.front(), 0.45 - 0.5, 1e-15);
}

// checks: with the target as its own envelope (a relative correction) the target's zero (an inflection at u = 1/2)
// stays exactly where it is, and the sign on either side, while the end of another curve is met.
TEST(DirectReconstruction, RelativeEnvelopeKeepsTheInflection) {
  Laws l;
  const double L = 4.0;
  const Profile target = l.profile("0.6*(u - 0.5)");
  const DirectReconstructionResult free =
      reconstruct_direct({.curvature = l.profile("0.66*(u - 0.5)"), .length = L}, no_fit());
  DirectReconstructionProblem p{.curvature = target};
  p.length = L;
  p.end_point = free.curve.evaluate(L).position;
  p.end_tangent = free.curve.evaluate(L).tangent;
  p.curvature_envelope = target;
  const DirectReconstructionResult r = reconstruct_direct(p, no_fit());
  EXPECT_LE(r.end_point_error, 1e-9 * L);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  EXPECT_GT(r.max_curvature_deviation, 1e-4);
  EXPECT_LT(std::abs(r.curve.evaluate(0.5 * L).curvature), 1e-12);
  for (int i = 1; i < 20; ++i) {
    const double s = L * i / 20.0;
    if (i == 10) continue;
    EXPECT_GT(r.curve.evaluate(s).curvature * (s - 0.5 * L), 0.0) << s;
  }
}

// checks: a space curve held to the helix's end frame — point, tangent and normal (closed form) — meets all three.
TEST(DirectReconstruction, EndNormalHoldsTheSpaceFrame) {
  Laws l;
  const Helix hx{0.8, 0.4};
  const double L = 10.0;
  DirectReconstructionProblem p{.curvature = l.profile("0.8 + 0.05*sin(2*pi*u)")};
  p.torsion = l.profile("0.4 - 0.05*u");
  p.length = L;
  p.start = hx.start();
  p.end_point = hx.point(L);
  p.end_tangent = hx.tangent(L);
  p.end_normal = hx.normal(L);
  const DirectReconstructionResult r = reconstruct_direct(p, no_fit());
  EXPECT_LE(r.end_point_error, 1e-9 * L);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  const intrinsic::FramePoint e = r.curve.evaluate(L);
  EXPECT_LT(distance(e.normal, hx.normal(L)), 1e-8);
}

// checks: the new inputs' errors name them.
TEST(DirectReconstruction, RejectsBadEndFrameAndCurvatures) {
  Laws l;
  DirectReconstructionProblem planar{.curvature = l.profile("0.5")};
  planar.length = 2.0;
  planar.end_tangent = Vec3{0, 1, 0};
  planar.end_normal = Vec3{1, 0, 0};
  HULA_EXPECT_ERROR(static_cast<void>(reconstruct_direct(planar, no_fit())), Errc::InvalidArgument, "end_normal");
  DirectReconstructionProblem zero{.curvature = l.profile("0.5*(1 - u)")};
  zero.length = 2.0;
  zero.end_point = Vec3{1.5, 0.1, 0};
  zero.curvature_envelope = zero.curvature;
  zero.end_curvature = 0.3;
  HULA_EXPECT_ERROR(static_cast<void>(reconstruct_direct(zero, no_fit())), Errc::InvalidArgument, "end_curvature");
  DirectReconstructionProblem at_zero{.curvature = l.profile("0.5 - u")};
  at_zero.length = 2.0;
  at_zero.end_point = Vec3{1.5, 0.1, 0};
  at_zero.curvature_envelope = at_zero.curvature;
  at_zero.start_curvature = 0.2;  // the envelope is 0.5 there: allowed
  at_zero.end_curvature = std::nan("");
  HULA_EXPECT_ERROR(static_cast<void>(reconstruct_direct(at_zero, no_fit())), Errc::NonFiniteInput, "end_curvature");
}

}  // namespace
}  // namespace hula::studies
