// SPDX-License-Identifier: MIT
// Clothoid segments, Fresnel integrals and G1 Hermite clothoid interpolation (intrinsic/clothoid.hpp)
// against independent references: the Fresnel integrals of mpmath 1.3.0 at 40 digits, the closed form
// of a clothoid through C and S, the Euler spiral (C(s), S(s)), lines and circular arcs, the exact-angle
// natural-equation integrator, and Bertolazzi–Frego's published test configurations; G2 Hermite
// interpolation by three clothoids against the same closed forms, known clothoids and circles.
#include "hula/intrinsic/clothoid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "hula/testing/clothoid_check.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::intrinsic {
namespace {

// Reference values: python3 -c "import mpmath as mp; mp.mp.dps = 40; print(mp.fresnelc(mp.mpf(x)), mp.fresnels(...))"
// at the double x (mpmath's C, S use the π t²/2 normalisation of A&S 7.3.1–2; C(1) also in A&S Table 7.7).
constexpr std::array<std::array<double, 3>, 17> kFresnel{{
    {0.1, 0.0999975326270850736, 0.0005235895476122106867},
    {0.5, 0.4923442258714463929, 0.06473243285999927761},
    {1.0, 0.7798934003768228295, 0.4382591473903547661},
    {1.5, 0.4452611760398215351, 0.6975049600820930131},
    {2.0, 0.4882534060753407545, 0.3434156783636982422},
    {2.5, 0.4574130096417770452, 0.6191817558195929361},
    {3.0, 0.6057207892976856296, 0.4963129989673750361},
    {4.0, 0.4984260330381776155, 0.4205157542469284244},
    {5.0, 0.5636311887040122311, 0.4991913819171168868},
    {5.9, 0.4485919531698299986, 0.5163306915041534263},
    {6.0, 0.4995314678555011202, 0.4469607612369302776},
    {6.1, 0.5495022012639654272, 0.516477082795103675},
    {8.0, 0.4998021803771971356, 0.4602142143930144839},
    {10.0, 0.4998986942055157236, 0.4681699785848822404},
    {25.5, 0.4952287107867888338, 0.511534878686147459},
    {100.0, 0.4999998986788178976, 0.4968169011478375533},
    {1000.3, 0.5000448367037948115, 0.4996849601798649916},
}};

// checks: C(x), S(x) against mpmath at 17 abscissae across the quadrature (|x| ≤ 6) and asymptotic (> 6) ranges,
// to 1e-14 absolute (the header's bound; the issue asks 1e-12), and the odd symmetry and the limits ±1/2.
TEST(Fresnel, MatchesMpmathTo1e14) {
  for (const auto& [x, c, s] : kFresnel) {
    const FresnelValues v = fresnel(x);
    EXPECT_NEAR(v.c, c, 1e-14) << "x = " << x;
    EXPECT_NEAR(v.s, s, 1e-14) << "x = " << x;
    const FresnelValues m = fresnel(-x);
    EXPECT_EQ(m.c, -v.c) << x;
    EXPECT_EQ(m.s, -v.s) << x;
  }
  EXPECT_EQ(fresnel(0.0).c, 0.0);
  EXPECT_EQ(fresnel(std::numeric_limits<double>::infinity()).c, 0.5);
  EXPECT_EQ(fresnel(-std::numeric_limits<double>::infinity()).s, -0.5);
  HULA_EXPECT_ERROR(fresnel(std::nan("")), Errc::NonFiniteInput, "x");
}

// checks: the Euler spiral θ = π s²/2 from the origin is (C(s), S(s)) (its definition), to 1e-14.
TEST(ClothoidSegment, EulerSpiralIsFresnel) {
  const ClothoidSegment e{.dkappa = std::numbers::pi, .length = 3.0};
  for (double s = 0.0; s <= 3.0; s += 0.125) {
    const FresnelValues v = fresnel(s);
    const Vec3 p = e.point(s);
    EXPECT_NEAR(p.x, v.c, 1e-14) << s;
    EXPECT_NEAR(p.y, v.s, 1e-14) << s;
  }
}

// checks: a general segment against the closed form by completing the square,
// x + i y = z0 + sqrt(π/κ′) e^{iω} [(C(u1) − C(u0)) + i (S(u1) − S(u0))], ω = θ0 − κ0²/(2κ′), u = sqrt(κ′/π)(t +
// κ0/κ′), to 1e-12; and the curvature and angle laws.
TEST(ClothoidSegment, PointMatchesFresnelClosedForm) {
  const ClothoidSegment c{.start = {1.0, -2.0, 0.0}, .theta0 = 0.7, .kappa0 = -0.4, .dkappa = 0.9, .length = 6.0};
  const double w = c.theta0 - c.kappa0 * c.kappa0 / (2 * c.dkappa), k = std::sqrt(c.dkappa / std::numbers::pi);
  const FresnelValues f0 = fresnel(k * c.kappa0 / c.dkappa);
  for (double s = 0.0; s <= c.length; s += 0.25) {
    const FresnelValues f1 = fresnel(k * (s + c.kappa0 / c.dkappa));
    const double dc = f1.c - f0.c, ds = f1.s - f0.s, scale = std::sqrt(std::numbers::pi / c.dkappa);
    const Vec3 p = c.point(s);
    EXPECT_NEAR(p.x, 1.0 + scale * (std::cos(w) * dc - std::sin(w) * ds), 1e-12) << s;
    EXPECT_NEAR(p.y, -2.0 + scale * (std::sin(w) * dc + std::cos(w) * ds), 1e-12) << s;
    EXPECT_DOUBLE_EQ(c.curvature(s), -0.4 + 0.9 * s);
    EXPECT_DOUBLE_EQ(c.angle(s), 0.7 - 0.4 * s + 0.45 * s * s);
  }
}

// checks: to_intrinsic() (the exact-angle natural-equation integrator, an independent route) gives the same
// points as the quadrature of point() to 1e-10.
TEST(ClothoidSegment, IntrinsicCurveAgrees) {
  const ClothoidSegment c{.start = {0.5, 0.0, 0.0}, .theta0 = 1.0, .kappa0 = 2.0, .dkappa = -3.0, .length = 2.0};
  const IntrinsicCurve ic = c.to_intrinsic();
  for (double s = 0.0; s <= 2.0; s += 0.1) EXPECT_LT(distance(ic.evaluate(s).position, c.point(s)), 1e-10) << s;
}

// checks: G1 closed forms: a straight segment (κ0 = κ′ = 0, L = r) and the quarter circle of radius 1 from (0,0)
// heading +x to (1,1) heading +y (κ0 = 1, κ′ = 0, L = π/2), to 1e-12.
TEST(ClothoidG1, LineAndCircleClosedForms) {
  const ClothoidG1Result line = fit_clothoid_g1({1, 1, 0}, std::atan2(4.0, 3.0), {4, 5, 0}, std::atan2(4.0, 3.0));
  EXPECT_NEAR(line.segment.kappa0, 0.0, 1e-12);
  EXPECT_NEAR(line.segment.dkappa, 0.0, 1e-12);
  EXPECT_NEAR(line.segment.length, 5.0, 1e-12);
  const ClothoidG1Result arc = fit_clothoid_g1({0, 0, 0}, 0.0, {1, 1, 0}, std::numbers::pi / 2);
  EXPECT_NEAR(arc.segment.kappa0, 1.0, 1e-12);
  EXPECT_NEAR(arc.segment.dkappa, 0.0, 1e-12);
  EXPECT_NEAR(arc.segment.length, std::numbers::pi / 2, 1e-12);
}

// checks: Bertolazzi–Frego's test configurations (their Clothoids toolbox scripts test_1.m / test_1b.m /
// test_G2_1.m end data: (0.5, 0, 1) → (0.5, 0.5, 1); (0, 0.1, 1.571) → (0.085, 0.035, 2.356); (−2, 3, π/3) →
// (3, 2, −π/4)) are interpolated: the end point, re-computed by the independent exact-angle integrator, within
// 1e-12 of the target and the end angle exact to 1e-12; total turning below 2π (their uniqueness condition).
TEST(ClothoidG1, PublishedConfigurationsAreInterpolated) {
  struct Case {
    Vec3 p0;
    double t0;
    Vec3 p1;
    double t1;
  };
  for (const Case& c : {Case{{0.5, 0, 0}, 1.0, {0.5, 0.5, 0}, 1.0}, Case{{0, 0.1, 0}, 1.571, {0.085, 0.035, 0}, 2.356},
                        Case{{-2, 3, 0}, std::numbers::pi / 3, {3, 2, 0}, -std::numbers::pi / 4}}) {
    const ClothoidG1Result r = fit_clothoid_g1(c.p0, c.t0, c.p1, c.t1);
    const ClothoidSegment& s = r.segment;
    ASSERT_GT(s.length, 0.0);
    const IntrinsicCurve ic = s.to_intrinsic();
    EXPECT_LT(distance(ic.evaluate(s.length).position, c.p1), 1e-12 * std::max(1.0, s.length));
    EXPECT_NEAR(std::remainder(s.angle(s.length) - c.t1, 2 * std::numbers::pi), 0.0, 1e-12);
    EXPECT_LT(std::abs(s.angle(s.length) - s.theta0), 2 * std::numbers::pi);
    EXPECT_LE(r.iterations, 6);
  }
}

// checks (seeded property, 2000 cases): a known clothoid with total turning |Δθ| < π and moderate curvature
// change is recovered from its own end data (κ0, κ′, L to 1e-9 relative), the round trip through point().
TEST(ClothoidG1, RecoversKnownClothoids) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    ClothoidSegment c{.start = {u(rng), u(rng), 0.0},
                      .theta0 = std::numbers::pi * u(rng),
                      .kappa0 = 1.5 * u(rng),
                      .dkappa = 2.0 * u(rng),
                      .length = 0.2 + std::abs(u(rng))};
    // Stay where the G1 solution is the one with the smaller turning: the angle varies by less than π/2
    // from the chord's direction at both ends.
    const double turn = c.angle(c.length) - c.theta0;
    if (std::abs(turn) > std::numbers::pi / 2) continue;
    const Vec3 end = c.point(c.length);
    const double chord = std::atan2(end.y - c.start.y, end.x - c.start.x);
    if (std::abs(std::remainder(c.theta0 - chord, 2 * std::numbers::pi)) > std::numbers::pi / 2 ||
        std::abs(std::remainder(c.angle(c.length) - chord, 2 * std::numbers::pi)) > std::numbers::pi / 2)
      continue;
    ++checked;
    const ClothoidG1Result r = fit_clothoid_g1(c.start, c.theta0, end, c.angle(c.length));
    EXPECT_NEAR(r.segment.length, c.length, 1e-9 * c.length) << i;
    EXPECT_NEAR(r.segment.kappa0, c.kappa0, 1e-9 * (1.0 + std::abs(c.kappa0)) / c.length) << i;
    EXPECT_NEAR(r.segment.dkappa, c.dkappa, 1e-9 * (1.0 + std::abs(c.dkappa)) / (c.length * c.length)) << i;
  }
  EXPECT_GT(checked, 500);
}

// checks: bad input is refused, naming it.
TEST(ClothoidG1, RefusesBadInput) {
  HULA_EXPECT_ERROR(fit_clothoid_g1({0, 0, 0}, 0.0, {0, 0, 0}, 1.0), Errc::CoincidentPoints, "p1");
  HULA_EXPECT_ERROR(fit_clothoid_g1({0, 0, 0}, std::nan(""), {1, 0, 0}, 1.0), Errc::NonFiniteInput, "theta0");
  ClothoidG1Options o;
  o.max_iterations = 0;
  HULA_EXPECT_ERROR(fit_clothoid_g1({0, 0, 0}, 0.0, {1, 0, 0}, 0.0, o), Errc::InvalidOption, "max_iterations");
}

// checks: Bertolazzi–Frego's G2 test data (Clothoids toolbox test_G2_1.m: (−2, 3, π/3, κ −0.2) → (3, 2, −π/4,
// κ 0.5); testG2.m: (−1, 0, 0.9π, κ 0.2) → (1, 0, −1.001π, κ 0.2)) and an S-shaped case give three arcs of
// positive length whose joins are G2 and whose end meets p1, θ1, κ1, all within 1e-10 by closed-form Fresnel.
TEST(ClothoidG2, PublishedDataJoinG2AndMeetTheEnd) {
  struct Case {
    Vec3 p0;
    double t0, k0;
    Vec3 p1;
    double t1, k1;
  };
  for (const Case& c : {Case{{-2, 3, 0}, std::numbers::pi / 3, -0.2, {3, 2, 0}, -std::numbers::pi / 4, 0.5},
                        Case{{-1, 0, 0}, 0.9 * std::numbers::pi, 0.2, {1, 0, 0}, -1.001 * std::numbers::pi, 0.2},
                        Case{{0, 0, 0}, 0.0, 2.0, {4, 1, 0}, 0.0, -3.0}}) {
    const ClothoidG2Result r = fit_clothoid_g2(c.p0, c.t0, c.k0, c.p1, c.t1, c.k1);
    for (const ClothoidSegment& s : r.segments) EXPECT_GT(s.length, 0.0);
    EXPECT_LT(testing::g2_violation(r, c.p0, c.t0, c.k0, c.p1, c.t1, c.k1), 1e-10) << c.p0.x;
    EXPECT_LE(r.iterations, 10);
  }
}

// checks: end data sampled from one known clothoid (p, θ, κ at s = a and s = b, with and without an inflection)
// give that clothoid back: the same total length b − a and the same κ(s) along it (at 41 arc lengths across
// the three arcs), to 1e-10.
TEST(ClothoidG2, ReproducesASingleClothoid) {
  for (const ClothoidSegment& c :
       {ClothoidSegment{.start = {1, -2, 0}, .theta0 = 0.7, .kappa0 = -0.4, .dkappa = 0.9, .length = 3.0},
        ClothoidSegment{.start = {0, 0, 0}, .theta0 = 0.0, .kappa0 = 0.5, .dkappa = -0.3, .length = 2.5},
        ClothoidSegment{
            .start = {5, 5, 0}, .theta0 = -2.0, .kappa0 = 0.0, .dkappa = std::numbers::pi, .length = 1.0}}) {
    const double a = 0.1 * c.length, b = 0.9 * c.length;
    const ClothoidG2Result r =
        fit_clothoid_g2(c.point(a), c.angle(a), c.curvature(a), c.point(b), c.angle(b), c.curvature(b));
    EXPECT_NEAR(r.length(), b - a, 1e-10);
    for (int i = 0; i <= 40; ++i) {
      double s = (b - a) * i / 40.0;
      const double at = a + s;
      std::size_t j = 0;
      while (j < 2 && s > r.segments[j].length) s -= r.segments[j++].length;
      EXPECT_NEAR(r.segments[j].curvature(s), c.curvature(at), 1e-10) << i;
    }
  }
}

// checks: a circular arc (radius 2, centre (1, −1), from polar angle −0.3 to 2.2, κ0 = κ1 = 1/2) comes out with
// constant curvature 1/2 (κ′ = 0 on every arc, to 1e-12) and the arc's length 2 × 2.5, to 1e-10.
TEST(ClothoidG2, CircularArcHasConstantCurvature) {
  const double radius = 2.0, a0 = -0.3, a1 = 2.2;
  const Vec3 centre{1, -1, 0};
  const auto on = [&](double a) { return centre + radius * Vec3{std::cos(a), std::sin(a), 0.0}; };
  const ClothoidG2Result r =
      fit_clothoid_g2(on(a0), a0 + std::numbers::pi / 2, 1.0 / radius, on(a1), a1 + std::numbers::pi / 2, 1.0 / radius);
  for (const ClothoidSegment& s : r.segments) {
    EXPECT_NEAR(s.kappa0, 0.5, 1e-12);
    EXPECT_NEAR(s.dkappa, 0.0, 1e-12);
  }
  EXPECT_NEAR(r.length(), radius * (a1 - a0), 1e-10);
  EXPECT_LT(testing::g2_violation(r, on(a0), a0 + std::numbers::pi / 2, 0.5, on(a1), a1 + std::numbers::pi / 2, 0.5),
            1e-10);
}

// checks: bad input is refused, naming it: coincident points, NaN curvature and angle, options out of range,
// and (with a one-iteration budget, so that Newton cannot finish) the numerical failure naming the end
// curvature furthest from the G1 clothoid's.
TEST(ClothoidG2, RefusesBadInputNamingIt) {
  HULA_EXPECT_ERROR(fit_clothoid_g2({1, 2, 0}, 0.0, 1.0, {1, 2, 0}, 1.0, 0.0), Errc::CoincidentPoints, "p1");
  HULA_EXPECT_ERROR(fit_clothoid_g2({0, 0, 0}, 0.0, std::nan(""), {1, 0, 0}, 1.0, 0.0), Errc::NonFiniteInput, "kappa0");
  HULA_EXPECT_ERROR(fit_clothoid_g2({0, 0, 0}, 0.0, 0.0, {1, 0, 0}, 1.0, std::numeric_limits<double>::infinity()),
                    Errc::NonFiniteInput, "kappa1");
  HULA_EXPECT_ERROR(fit_clothoid_g2({0, 0, 0}, 0.0, 0.0, {1, 0, 0}, std::nan(""), 0.0), Errc::NonFiniteInput, "theta1");
  ClothoidG2Options o;
  o.tolerance = 0.1;
  HULA_EXPECT_ERROR(fit_clothoid_g2({0, 0, 0}, 0.0, 0.0, {1, 0, 0}, 0.0, 0.0, o), Errc::InvalidOption, "tolerance");
  o = {};
  o.max_iterations = 1;
  HULA_EXPECT_ERROR(fit_clothoid_g2({0, 0, 0}, 0.0, 0.5, {1, 0, 0}, 1.0, -40.0, o), Errc::NumericalFailure, "kappa1");
}

// --- Splines through N points and biarcs ----------------------------------------------------------------

// Largest mismatch at the joints of a spline (and its closing joint): end position of segment i by the closed
// form (not point()'s quadrature) against the start of segment i + 1 and against the data point, tangent angle
// modulo 2π, curvature; with `g2` false the curvature is not compared.
struct JointGaps {
  double position = 0.0, angle = 0.0, curvature = 0.0, interpolation = 0.0;
};

JointGaps joint_gaps(const ClothoidSplineResult& r, const std::vector<Vec3>& points, bool closed, int per_interval) {
  JointGaps g;
  const std::size_t m = r.segments.size();
  for (std::size_t i = 0; i < m; ++i) {
    const ClothoidSegment& a = r.segments[i];
    const Vec3 end = testing::closed_form_end(a);
    if ((i + 1) % static_cast<std::size_t>(per_interval) == 0) {
      const std::size_t k = (i + 1) / static_cast<std::size_t>(per_interval);
      g.interpolation = std::max(g.interpolation, distance(end, points[k % points.size()]));
    }
    if (i + 1 == m && !closed) break;
    const ClothoidSegment& b = r.segments[(i + 1) % m];
    g.position = std::max(g.position, distance(end, b.start));
    g.angle = std::max(g.angle, std::abs(std::remainder(a.angle(a.length) - b.theta0, 2 * std::numbers::pi)));
    g.curvature = std::max(g.curvature, std::abs(a.curvature(a.length) - b.kappa0));
  }
  return g;
}

// Two seeded generators: a closed star-shaped loop (radius 1 ± 0.3 at angles with jitter) and an open random walk
// (steps 0.5–1.5 long, turns within ±1 rad).
std::vector<Vec3> loop_points(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (i + 0.3 * u(rng)) / n, rho = 1.0 + 0.3 * u(rng);
    p.push_back({rho * std::cos(t), rho * std::sin(t), 0.0});
  }
  return p;
}

std::vector<Vec3> walk_points(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p{{0, 0, 0}};
  double heading = std::numbers::pi * u(rng);
  for (int i = 1; i < n; ++i) {
    heading += u(rng);
    const double step = 1.0 + 0.5 * u(rng);
    p.push_back(p.back() + step * Vec3{std::cos(heading), std::sin(heading), 0.0});
  }
  return p;
}

// checks: G2 splines through seeded open walks and closed loops interpolate every point and join with position,
// tangent and curvature equal to 1e-9 (the closing joint of a closed one included), positions by the Fresnel closed
// form; G1 splines join in position and tangent but not in curvature.
TEST(ClothoidSpline, G2JointsAgreeOnTwoGenerators) {
  std::mt19937 rng(2611);
  for (int trial = 0; trial < 12; ++trial) {
    const bool closed = trial % 2 == 0;
    const int n = 4 + trial;
    const std::vector<Vec3> pts = closed ? loop_points(rng, n) : walk_points(rng, n);
    ClothoidSplineOptions o;
    o.closed = closed;
    const ClothoidSplineResult r = fit_clothoid_spline(pts, o);
    ASSERT_EQ(r.segments.size(), static_cast<std::size_t>(closed ? n : n - 1));
    const JointGaps g = joint_gaps(r, pts, closed, 1);
    EXPECT_LT(g.position, 1e-9) << trial;
    EXPECT_LT(g.angle, 1e-9) << trial;
    EXPECT_LT(g.curvature, 1e-9) << trial;
    EXPECT_LT(g.interpolation, 1e-9) << trial;
    EXPECT_LE(r.iterations, 20) << trial;
    if (!closed) {  // free ends: circular end segments
      EXPECT_LT(std::abs(r.segments.front().dkappa) * r.segments.front().length, 1e-9);
      EXPECT_LT(std::abs(r.segments.back().dkappa) * r.segments.back().length, 1e-9);
    }
    o.continuity = 1;
    const ClothoidSplineResult g1 = fit_clothoid_spline(pts, o);
    const JointGaps h = joint_gaps(g1, pts, closed, 1);
    EXPECT_LT(std::max({h.position, h.angle, h.interpolation}), 1e-9) << trial;
    EXPECT_GT(h.curvature, 1e-3) << trial;  // G1 only: the curvature jumps somewhere
    EXPECT_EQ(g1.iterations, 0);
  }
}

// checks: points on one circle (uneven spacing) give that circle, G1 and G2, open and closed: κ = 1/R and κ′ = 0 on
// every segment, total length R times the angle swept.
TEST(ClothoidSpline, PointsOnACircleGiveTheCircle) {
  const double radius = 2.5;
  const std::vector<double> at{0.0, 0.7, 1.1, 2.0, 2.9, 3.3, 4.4, 5.2};
  std::vector<Vec3> pts;
  for (const double t : at) pts.push_back({1.0 + radius * std::cos(t), -2.0 + radius * std::sin(t), 0.0});
  for (const bool closed : {false, true})
    for (const int continuity : {1, 2}) {
      ClothoidSplineOptions o;
      o.closed = closed;
      o.continuity = continuity;
      const ClothoidSplineResult r = fit_clothoid_spline(pts, o);
      for (const ClothoidSegment& s : r.segments) {
        EXPECT_NEAR(s.kappa0, 1.0 / radius, 1e-11) << closed << continuity;
        EXPECT_NEAR(s.dkappa, 0.0, 1e-11) << closed << continuity;
      }
      EXPECT_NEAR(r.length(), radius * (closed ? 2 * std::numbers::pi : at.back()), 1e-10) << closed << continuity;
    }
}

// checks: given end angles are kept (open), the spline still G2 inside; the closed list given with its first point
// repeated is the same spline as without it.
TEST(ClothoidSpline, GivenEndAnglesAndAClosedListRepeatingItsStart) {
  std::mt19937 rng(77);
  const std::vector<Vec3> pts = walk_points(rng, 7);
  ClothoidSplineOptions o;
  o.start_angle = 0.3;
  o.end_angle = -2.0;
  const ClothoidSplineResult r = fit_clothoid_spline(pts, o);
  EXPECT_DOUBLE_EQ(r.segments.front().theta0, 0.3);
  const ClothoidSegment& last = r.segments.back();
  EXPECT_LT(std::abs(std::remainder(last.angle(last.length) + 2.0, 2 * std::numbers::pi)), 1e-12);
  const JointGaps g = joint_gaps(r, pts, false, 1);
  EXPECT_LT(std::max({g.position, g.angle, g.curvature, g.interpolation}), 1e-9);

  std::vector<Vec3> loop = loop_points(rng, 6);
  ClothoidSplineOptions c;
  c.closed = true;
  const ClothoidSplineResult a = fit_clothoid_spline(loop, c);
  loop.push_back(loop.front());
  const ClothoidSplineResult b = fit_clothoid_spline(loop, c);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  EXPECT_NEAR(a.length(), b.length(), 1e-14);
}

// checks: given end curvatures, each end on its own or with an angle at the other end. Points on a circle of radius
// R with κ = 1/R given give that circle (κ ≡ 1/R, κ′ = 0 on every segment); points on one clothoid (κ = κ0 + κ′ s)
// with its end curvatures give that clothoid: every segment's κ0 and κ′ equal the closed form at its arc length.
TEST(ClothoidSpline, GivenEndCurvaturesReproduceCirclesAndClothoids) {
  const double radius = 1.7;
  std::vector<Vec3> arc;
  for (const double t : {0.2, 0.9, 1.3, 2.2, 2.8, 3.9})
    arc.push_back({radius * std::cos(t), radius * std::sin(t), 0.0});
  const double tangent_end = 3.9 + std::numbers::pi / 2;
  for (int variant = 0; variant < 4; ++variant) {
    ClothoidSplineOptions o;
    if (variant != 1) o.start_curvature = 1.0 / radius;  // 0: both ends, 1: end only, 2: start only
    if (variant != 2) o.end_curvature = 1.0 / radius;
    if (variant == 3) {  // 3: start curvature, end angle
      o.end_curvature.reset();
      o.end_angle = tangent_end;
    }
    const ClothoidSplineResult r = fit_clothoid_spline(arc, o);
    for (const ClothoidSegment& s : r.segments) {
      EXPECT_NEAR(s.kappa0, 1.0 / radius, 1e-11) << variant;
      EXPECT_NEAR(s.dkappa, 0.0, 1e-11) << variant;
    }
    EXPECT_NEAR(r.length(), radius * (3.9 - 0.2), 1e-10) << variant;
  }
  // Off the circle's curvature the ends take the given values and the joints stay G2.
  ClothoidSplineOptions o;
  o.start_curvature = 0.0;
  o.end_curvature = -0.3;
  const ClothoidSplineResult r = fit_clothoid_spline(arc, o);
  EXPECT_NEAR(r.segments.front().kappa0, 0.0, 1e-12);
  EXPECT_NEAR(r.segments.back().curvature(r.segments.back().length), -0.3, 1e-12);
  const JointGaps g = joint_gaps(r, arc, false, 1);
  EXPECT_LT(std::max({g.position, g.angle, g.curvature, g.interpolation}), 1e-9);

  // One clothoid, sampled at uneven arc lengths, its end curvatures given.
  const ClothoidSegment one{.start = {0.5, -1.0, 0.0}, .theta0 = 0.4, .kappa0 = -0.6, .dkappa = 0.35, .length = 6.0};
  const std::vector<double> at{0.0, 0.8, 1.9, 2.5, 3.6, 4.4, 5.1, 6.0};
  std::vector<Vec3> pts;
  for (const double s : at) {
    ClothoidSegment part = one;
    part.length = s;
    pts.push_back(s == 0.0 ? one.start : testing::closed_form_end(part));
  }
  o = {};
  o.start_curvature = one.curvature(0.0);
  o.end_curvature = one.curvature(one.length);
  const ClothoidSplineResult c = fit_clothoid_spline(pts, o);
  ASSERT_EQ(c.segments.size(), at.size() - 1);
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    EXPECT_NEAR(c.segments[i].kappa0, one.curvature(at[i]), 1e-10) << i;
    EXPECT_NEAR(c.segments[i].dkappa, one.dkappa, 1e-10) << i;
    EXPECT_NEAR(c.segments[i].length, at[i + 1] - at[i], 1e-10) << i;
    EXPECT_NEAR(c.segments[i].theta0, one.angle(at[i]), 1e-10) << i;
  }
  // Two points with both angles and both curvatures: the G2 Hermite problem, fit_clothoid_g2's three arcs.
  const std::vector<Vec3> two{{-2, 3, 0}, {3, 2, 0}};
  o = {};
  o.start_angle = std::numbers::pi / 3;
  o.start_curvature = -0.2;
  o.end_angle = -std::numbers::pi / 4;
  o.end_curvature = 0.5;
  const ClothoidSplineResult h = fit_clothoid_spline(two, o);
  const ClothoidG2Result direct =
      fit_clothoid_g2(two[0], std::numbers::pi / 3, -0.2, two[1], -std::numbers::pi / 4, 0.5);
  ASSERT_EQ(h.segments.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(h.segments[i].kappa0, direct.segments[i].kappa0);
    EXPECT_EQ(h.segments[i].length, direct.segments[i].length);
  }
}

// Points that turn back and forth: (i, (-1)^i) for i = 0..10 and seeded zigzags (jittered spacing, amplitude from
// 0.05 to 20 times the spacing). Curvature continuity is measured on the result by the closed-form clothoid ends:
// κ equal at every joint to 1e-9 relative (of max(1, |κ|)).
double relative_curvature_gap(const ClothoidSplineResult& r) {
  double gap = 0.0;
  for (std::size_t i = 0; i + 1 < r.segments.size(); ++i) {
    const ClothoidSegment& a = r.segments[i];
    const double k = a.curvature(a.length);
    gap = std::max(gap, std::abs(k - r.segments[i + 1].kappa0) / std::max(1.0, std::abs(k)));
  }
  return gap;
}

std::vector<Vec3> zigzag_points(std::mt19937& rng, int n, double amplitude) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i)
    p.push_back({i + 0.4 * u(rng), (i % 2 == 0 ? 1.0 : -1.0) * amplitude * (1.0 + 0.5 * u(rng)), 0.0});
  return p;
}

// checks: the zigzag (i, (-1)^i) gives a G2 spline with free ends and with horizontal end angles (then the symmetric
// solution: every segment an S of κ0 = ∓κ1, no iteration needed); seeded zigzags with given end angles always
// converge G2 (≤ 10 iterations); with free ends or end curvatures each either converges G2 or is refused with a
// NumericalFailure naming the points (never anything else), and steep ones are refused.
TEST(ClothoidSpline, ZigzagsConvergeOrAreRefusedNamingThePoints) {
  std::vector<Vec3> zig;
  for (int i = 0; i <= 10; ++i) zig.push_back({static_cast<double>(i), i % 2 == 0 ? 1.0 : -1.0, 0.0});
  for (const bool given : {false, true}) {
    ClothoidSplineOptions o;
    if (given) o.start_angle = o.end_angle = 0.0;
    const ClothoidSplineResult r = fit_clothoid_spline(zig, o);
    const JointGaps g = joint_gaps(r, zig, false, 1);
    EXPECT_LT(std::max({g.position, g.angle, g.interpolation}), 1e-9) << given;
    EXPECT_LT(relative_curvature_gap(r), 1e-9) << given;
    if (given)
      for (const ClothoidSegment& s : r.segments) {
        EXPECT_NEAR(s.kappa0, -s.curvature(s.length), 1e-9);
        EXPECT_NEAR(std::remainder(s.theta0, 2 * std::numbers::pi), 0.0, 1e-9);
      }
  }
  std::mt19937 rng(2626);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int refused = 0, converged = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 3 + trial % 20;
    const double amplitude = 0.05 * std::pow(400.0, 0.5 * (u(rng) + 1.0));
    const std::vector<Vec3> pts = zigzag_points(rng, n, amplitude);
    for (int mode = 0; mode < 3; ++mode) {
      ClothoidSplineOptions o;
      if (mode == 0) o.start_angle = o.end_angle = 0.1 * u(rng);
      if (mode == 2) o.start_curvature = o.end_curvature = 0.0;
      try {
        const ClothoidSplineResult r = fit_clothoid_spline(pts, o);
        const JointGaps g = joint_gaps(r, pts, false, 1);
        EXPECT_LT(std::max({g.position, g.angle, g.interpolation}), 1e-9) << trial << " " << mode;
        EXPECT_LT(relative_curvature_gap(r), 1e-9) << trial << " " << mode;
        if (mode == 0) {
          EXPECT_LE(r.iterations, 10) << trial;
        }
        ++converged;
      } catch (const Error& e) {
        EXPECT_NE(mode, 0) << trial << ": " << e.what();
        EXPECT_EQ(e.code(), Errc::NumericalFailure) << e.what();
        EXPECT_EQ(e.where().field, "points") << e.what();
        EXPECT_NE(std::string(e.what()).find("give both end angles"), std::string::npos) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GT(converged, 100);  // every given-angle case and the gentle free ones
  EXPECT_GT(refused, 0);      // steep zigzags with free ends exist that have no such spline nearby
}

TEST(ClothoidSpline, RefusesBadInputNamingIt) {
  const std::vector<Vec3> one{{0, 0, 0}};
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(one), Errc::TooFewPoints, "points");
  const std::vector<Vec3> twice{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(twice), Errc::CoincidentPoints, "points[2]");
  const std::vector<Vec3> nan{{0, 0, 0}, {std::nan(""), 0, 0}, {2, 1, 0}};
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(nan), Errc::NonFiniteInput, "points[1]");
  const std::vector<Vec3> two{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  ClothoidSplineOptions o;
  o.closed = true;
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(two, o), Errc::TooFewPoints, "closed spline needs at least 3");
  const std::vector<Vec3> three{{0, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  o = {};
  o.start_angle = 1.0;
  o.start_curvature = 0.5;
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(three, o), Errc::InvalidArgument,
                    "start_curvature is given with the angle");
  o = {};
  o.end_curvature = 0.5;
  o.continuity = 1;
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(three, o), Errc::InvalidArgument, "end_curvature is given for a G1");
  HULA_EXPECT_ERROR((void)fit_biarc_spline(three, o), Errc::InvalidArgument, "end_curvature is given for a biarc");
  o.continuity = 2;
  o.end_curvature = std::numeric_limits<double>::infinity();
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(three, o), Errc::NonFiniteInput, "end_curvature");
  o = {};
  o.start_curvature = 0.5;
  o.closed = true;
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(three, o), Errc::InvalidArgument,
                    "start_curvature is given for a closed");
  o = {};
  o.start_angle = 1.0;
  o.end_angle = 1.0;
  o.closed = true;
  HULA_EXPECT_ERROR((void)fit_biarc_spline(three, o), Errc::InvalidArgument, "closed spline");
  o.continuity = 3;
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(three, o), Errc::InvalidOption, "continuity");
  HULA_EXPECT_ERROR((void)fit_biarc({1, 1, 0}, 0.0, {1, 1, 0}, 1.0), Errc::CoincidentPoints, "p1");
  // A G2 iteration cut short is a NumericalFailure naming the points and the curvature jump left.
  const std::vector<Vec3> loop{{2, 0, 0}, {1, 1.6, 0}, {-1, 1.9, 0}, {-2.2, 0.2, 0}, {-1, -1.7, 0}, {1.2, -1.5, 0}};
  o = {};
  o.closed = true;
  o.max_iterations = 1;
  HULA_EXPECT_ERROR((void)fit_clothoid_spline(loop, o), Errc::NumericalFailure, "curvature jump");
}

// checks: biarcs against closed forms over seeded end angles in (−π, π): the joint lies on the chord's
// perpendicular bisector at distance a = d / (2 cos((φ1 − φ0)/4)) from both ends; each arc's centre (start point
// plus the normal over κ) is 1/|κ| from both of its ends; the arc ends (by the circle formula) meet at the joint
// and at p1; the joint tangent is −(φ0 + φ1)/2 from the chord and perpendicular to both radii there.
TEST(Biarc, ClosedFormsOfTheEqualChordBiarc) {
  std::mt19937 rng(404);
  std::uniform_real_distribution<double> ang(-0.95 * std::numbers::pi, 0.95 * std::numbers::pi), pos(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p0{pos(rng), pos(rng), 0.0}, p1{pos(rng), pos(rng), 0.0};
    const double t0 = ang(rng), t1 = ang(rng);
    const std::array<ClothoidSegment, 2> b = fit_biarc(p0, t0, p1, t1);
    const double d = distance(p0, p1), chord = std::atan2(p1.y - p0.y, p1.x - p0.x);
    const double phi0 = std::remainder(t0 - chord, 2 * std::numbers::pi),
                 phi1 = std::remainder(t1 - chord, 2 * std::numbers::pi);
    const double a = d / (2 * std::cos((phi1 - phi0) / 4));
    const Vec3 joint = b[1].start;
    EXPECT_NEAR(distance(joint, p0), a, 1e-12 * (1 + a)) << trial;
    EXPECT_NEAR(distance(joint, p1), a, 1e-12 * (1 + a)) << trial;
    EXPECT_NEAR(std::remainder(b[1].theta0 - chord + (phi0 + phi1) / 2, 2 * std::numbers::pi), 0.0, 1e-12) << trial;
    for (int k = 0; k < 2; ++k) {
      const ClothoidSegment& s = b[k];
      EXPECT_EQ(s.dkappa, 0.0);
      const Vec3 end = testing::closed_form_end(s);
      EXPECT_LT(distance(end, k == 0 ? joint : p1), 1e-11 * (1 + a)) << trial << k;
      if (std::abs(s.kappa0) * a > 1e-6) {
        const Vec3 centre = s.start + Vec3{-std::sin(s.theta0), std::cos(s.theta0), 0.0} / s.kappa0;
        EXPECT_NEAR(distance(centre, end) * std::abs(s.kappa0), 1.0, 1e-11) << trial << k;
        // radius perpendicular to the end tangent
        const double te = s.angle(s.length);
        const Vec3 radial = end - centre;
        EXPECT_NEAR((radial.x * std::cos(te) + radial.y * std::sin(te)) * std::abs(s.kappa0), 0.0, 1e-10) << trial;
      }
    }
    EXPECT_NEAR(std::remainder(b[0].angle(b[0].length) - b[1].theta0, 2 * std::numbers::pi), 0.0, 1e-14);
    EXPECT_NEAR(std::remainder(b[1].angle(b[1].length) - t1, 2 * std::numbers::pi), 0.0, 1e-12);
  }
  // On one circle (φ1 = −φ0) both arcs have κ = −2 sin φ0 / d; φ0 = φ1 = 0 is the chord.
  const std::array<ClothoidSegment, 2> c = fit_biarc({0, 0, 0}, 0.4, {2, 0, 0}, -0.4);
  EXPECT_NEAR(c[0].kappa0, -std::sin(0.4), 1e-15);
  EXPECT_NEAR(c[1].kappa0, -std::sin(0.4), 1e-15);
  const std::array<ClothoidSegment, 2> line = fit_biarc({0, 0, 0}, 0.0, {3, 0, 0}, 0.0);
  EXPECT_EQ(line[0].kappa0, 0.0);
  EXPECT_DOUBLE_EQ(line[0].length + line[1].length, 3.0);
}

// checks: biarc splines through both generators interpolate every point with G1 joints (position by the circle
// formula, tangent angle) to 1e-10, closed ones closing with G1, two arcs per interval.
TEST(Biarc, SplinesAreG1ThroughThePoints) {
  std::mt19937 rng(5150);
  for (int trial = 0; trial < 8; ++trial) {
    const bool closed = trial % 2 == 1;
    const std::vector<Vec3> pts = closed ? loop_points(rng, 5 + trial) : walk_points(rng, 5 + trial);
    ClothoidSplineOptions o;
    o.closed = closed;
    const ClothoidSplineResult r = fit_biarc_spline(pts, o);
    ASSERT_EQ(r.segments.size(), 2 * (closed ? pts.size() : pts.size() - 1));
    const JointGaps g = joint_gaps(r, pts, closed, 2);
    EXPECT_LT(std::max({g.position, g.angle, g.interpolation}), 1e-10) << trial;
  }
}

}  // namespace
}  // namespace hula::intrinsic
