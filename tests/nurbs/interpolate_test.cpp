// SPDX-License-Identifier: MIT
// Interpolation: the thesis's chord-length example (7.1.2, eq. 29), Lagrange
// coefficients (5.3.1), the global cubic spline's end conditions, C2
// continuity, polynomial reproduction, small-N fallbacks, extreme scales,
// Hermite cubic/quintic, and every documented error.
#include "hula/nurbs/interpolate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

using Kind = EndCondition::Kind;

constexpr double kRel = 1e-12;
const EvalOptions kLeft{.side = Side::Left};
const EvalOptions kRight{.side = Side::Right};

std::vector<Vec3> thesis_points() { return {{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}}; }

std::vector<Vec3> random_points(std::size_t n, std::uint64_t seed, double scale = 1.0, bool planar = false) {
  Rng rng(seed);
  std::vector<Vec3> p(n);
  for (auto& q : p) q = Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), planar ? 0.0 : rng.uniform(-1, 1)} * scale;
  return p;
}

double size_of(const std::vector<Vec3>& pts) {
  Box3 b;
  for (const auto& p : pts) b.add(p);
  return b.diagonal();
}

std::vector<EndCondition> all_ends(const Vec3& clamp) {
  return {EndCondition::natural(), EndCondition::clamped(clamp), EndCondition::bessel(), EndCondition::not_a_knot(),
          EndCondition::occt()};
}

// Derivative of the Lagrange polynomial through (t_j, q_j), j in [first, first + count), at t_at (test-side formula).
Vec3 lagrange_derivative(const std::vector<Vec3>& q, const std::vector<double>& t, std::size_t first, std::size_t count,
                         double at) {
  Vec3 d{};
  for (std::size_t j = first; j < first + count; ++j) {
    // l_j'(x) = Σ_{m≠j} [Π_{r≠j,m} (x - t_r)] / Π_{r≠j} (t_j - t_r)
    double den = 1.0;
    for (std::size_t r = first; r < first + count; ++r)
      if (r != j) den *= t[j] - t[r];
    double num = 0.0;
    for (std::size_t m = first; m < first + count; ++m) {
      if (m == j) continue;
      double prod = 1.0;
      for (std::size_t r = first; r < first + count; ++r)
        if (r != j && r != m) prod *= at - t[r];
      num += prod;
    }
    d += (num / den) * q[j];
  }
  return d;
}

void expect_interpolates(const NurbsCurve& c, const std::vector<Vec3>& pts, const std::vector<double>& t,
                         const std::string& label) {
  const double tol = kRel * size_of(pts);
  for (std::size_t i = 0; i < pts.size(); ++i)
    EXPECT_LE(distance(c.evaluate(t[i]), pts[i]), tol) << label << " point " << i;
}

void expect_breakpoints(const NurbsCurve& c, const std::vector<double>& t, const std::string& label) {
  EXPECT_EQ(c.knots().breakpoints(), t) << label;
}

// Largest |C^(k)| over the data parameters and span midpoints: the scale for relative checks of order k.
double derivative_scale(const NurbsCurve& c, int k) {
  double s = 0.0;
  const auto b = c.knots().breakpoints();
  for (std::size_t i = 0; i + 1 < b.size(); ++i)
    for (double t : {b[i], 0.5 * (b[i] + b[i + 1])}) s = std::max(s, norm(c.derivatives(t, k)[k]));
  return s;
}

void expect_c2_at_interior_knots(const NurbsCurve& c, const std::string& label) {
  const auto b = c.knots().breakpoints();
  for (int k = 0; k <= 2; ++k) {
    const double scale = derivative_scale(c, k);
    for (std::size_t i = 1; i + 1 < b.size(); ++i) {
      const Vec3 l = c.derivatives(b[i], k, kLeft)[k];
      const Vec3 r = c.derivatives(b[i], k, kRight)[k];
      EXPECT_LE(distance(l, r), 1e-11 * scale) << label << " order " << k << " knot " << b[i];
    }
  }
}

// ---------------------------------------------------------------- parameterisation

// checks: thesis 7.1.2 / eq. 29 — chord lengths 47.17, 111.20, 158.37 and parameters = L / 158.37.
TEST(Parameterise, ThesisChordLengthExample) {
  const auto pts = thesis_points();
  const auto L = cumulative_chord_lengths(pts);
  ASSERT_EQ(L.size(), 4u);
  EXPECT_EQ(L[0], 0.0);
  EXPECT_NEAR(L[1], 47.17, 0.005);
  EXPECT_NEAR(L[2], 111.20, 0.005);
  EXPECT_NEAR(L[3], 158.37, 0.005);
  const auto t = parameterise(pts, Parameterisation::ChordLength);
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(t[i], L[i] / L[3], 1e-15) << i;
  EXPECT_NEAR(t[1], 47.17 / 158.37, 1e-4);
  EXPECT_NEAR(t[2], 111.20 / 158.37, 1e-4);
  EXPECT_EQ(t[3], 1.0);
}

// checks: uniform is i/(N-1); centripetal is the normalised cumulative sqrt of chords (Lee 1989).
TEST(Parameterise, UniformAndCentripetalValues) {
  const auto pts = thesis_points();
  const auto u = parameterise(pts, Parameterisation::Uniform);
  EXPECT_EQ(u, (std::vector<double>{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0}));
  const auto c = parameterise(pts, Parameterisation::Centripetal);
  const double a = std::sqrt(std::hypot(40.0, 25.0)), b = std::sqrt(std::hypot(40.0, 50.0));
  EXPECT_NEAR(c[1], a / (2 * a + b), 1e-15);
  EXPECT_NEAR(c[2], (a + b) / (2 * a + b), 1e-15);
  EXPECT_EQ(c[3], 1.0);
}

// checks: Foley on the U shape (0,1), (0,0), (1,0), (1,1) against Foley–Nielson's span formula by hand (unit
// chords, right turns θ = π/2 at both inner points): spans 1 + 3π/8, 1 + 3π/4, 1 + 3π/8; collinear points give chord
// length.
TEST(Parameterise, FoleyClosedForm) {
  const std::vector<Vec3> u = {{0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  const auto t = parameterise(u, Parameterisation::Foley);
  const double pi = std::numbers::pi, a = 1 + 3 * pi / 8, b = 1 + 3 * pi / 4, total = 2 * a + b;
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0], 0.0);
  EXPECT_NEAR(t[1], a / total, 1e-15);
  EXPECT_NEAR(t[2], (a + b) / total, 1e-15);
  EXPECT_EQ(t[3], 1.0);
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {6, 0, 0}};
  const auto f = parameterise(line, Parameterisation::Foley), c = parameterise(line, Parameterisation::ChordLength);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(f[i], c[i], 1e-15) << i;
}

// checks: chord lengths at 1e-200 and 1e200 scale are the scaled lengths (overflow-safe norms).
TEST(Parameterise, ExtremeScalesKeepLengthsAndParameters) {
  const auto ref = parameterise(thesis_points(), Parameterisation::ChordLength);
  for (double s : {1e-200, 1e200}) {
    auto pts = thesis_points();
    for (auto& p : pts) p *= s;
    const auto L = cumulative_chord_lengths(pts);
    EXPECT_NEAR(L[3] / s, 158.37, 0.005) << s;
    for (auto rule : {Parameterisation::ChordLength, Parameterisation::Centripetal}) {
      const auto t = parameterise(pts, rule);
      const auto t1 = parameterise(thesis_points(), rule);
      for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(t[i], t1[i], 1e-14) << s;
    }
  }
}

// checks: too few points, non-finite coordinates (point and coordinate named), coincident neighbours (indices named).
TEST(Parameterise, ErrorsNameTheInput) {
  const std::vector<Vec3> one{{1, 2, 3}};
  HULA_EXPECT_ERROR(parameterise(one, Parameterisation::ChordLength), Errc::TooFewPoints, "got 1");
  auto pts = thesis_points();
  pts[2].y = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(parameterise(pts, Parameterisation::Uniform), Errc::NonFiniteInput, "points[2][1]");
  HULA_EXPECT_ERROR(cumulative_chord_lengths(pts), Errc::NonFiniteInput, "points[2][1]");
  pts = thesis_points();
  pts[1].z = HUGE_VAL;
  HULA_EXPECT_ERROR(parameterise(pts, Parameterisation::ChordLength), Errc::NonFiniteInput, "points[1][2] = inf");
  pts = thesis_points();
  pts[3] = pts[2];
  for (auto rule : {Parameterisation::ChordLength, Parameterisation::Centripetal})
    HULA_EXPECT_ERROR(parameterise(pts, rule), Errc::CoincidentPoints, "points[2] and points[3]");
  // Uniform needs no distance: coincident neighbours are accepted.
  EXPECT_NO_THROW((void)parameterise(pts, Parameterisation::Uniform));
  // A gap far below the model's relative resolution counts as coincident, at any scale.
  for (double s : {1e-200, 1.0, 1e200}) {
    auto q = thesis_points();
    for (auto& p : q) p *= s;
    q[2] = q[1] + Vec3{1e-16 * s, 0, 0};
    HULA_EXPECT_ERROR(parameterise(q, Parameterisation::ChordLength), Errc::CoincidentPoints,
                      "points[1] and points[2]");
  }
}

// ---------------------------------------------------------------- global cubic spline

// checks: every end condition × parameterisation passes through the points at their parameters, and the
// breakpoints are the data parameters; the spline is C2 at every interior knot.
TEST(InterpolateCubic, PassesThroughPointsWithBreakpointsAtDataParameters) {
  for (std::size_t n : {2u, 3u, 4u, 5u, 9u, 40u}) {
    const auto pts = random_points(n, 100 + n, 10.0);
    for (auto rule : {Parameterisation::Uniform, Parameterisation::ChordLength, Parameterisation::Centripetal}) {
      const auto t = parameterise(pts, rule);
      for (const auto& s : all_ends({1, 2, 3}))
        for (const auto& e : all_ends({-3, 0, 1})) {
          const std::string label = "n=" + std::to_string(n) + " rule=" + std::to_string(static_cast<int>(rule)) +
                                    " start=" + std::to_string(static_cast<int>(s.kind)) +
                                    " end=" + std::to_string(static_cast<int>(e.kind));
          const NurbsCurve c = interpolate_cubic(pts, {.parameterisation = rule, .start = s, .end = e});
          EXPECT_EQ(c.degree(), 3) << label;
          EXPECT_EQ(c.control_points().size(), n + 2) << label;
          expect_interpolates(c, pts, t, label);
          expect_breakpoints(c, t, label);
          expect_c2_at_interior_knots(c, label);
        }
    }
  }
}

// checks: natural ends have C''(0) = C''(1) = 0 (relative to the largest |C''|).
TEST(InterpolateCubic, NaturalEndsHaveZeroSecondDerivative) {
  for (std::size_t n : {2u, 3u, 6u, 25u}) {
    const auto pts = random_points(n, 7 * n, 3.0);
    const NurbsCurve c = interpolate_cubic(pts);
    const double scale = std::max(derivative_scale(c, 2), size_of(pts));
    EXPECT_LE(norm(c.derivatives(0.0, 2)[2]), kRel * scale) << n;
    EXPECT_LE(norm(c.derivatives(1.0, 2)[2]), kRel * scale) << n;
  }
}

// checks: clamped ends meet the given dC/dt exactly (1e-12 relative), magnitude included.
TEST(InterpolateCubic, ClampedEndsMeetGivenDerivative) {
  const Vec3 d0{3, -1, 2}, d1{-0.5, 4, 0.25};
  for (std::size_t n : {2u, 3u, 4u, 12u}) {
    const auto pts = random_points(n, 11 * n, 2.0);
    const NurbsCurve c = interpolate_cubic(pts, {.start = EndCondition::clamped(d0), .end = EndCondition::clamped(d1)});
    EXPECT_LE(distance(c.derivatives(0.0, 1)[1], d0), kRel * norm(d0)) << n;
    EXPECT_LE(distance(c.derivatives(1.0, 1)[1], d1), kRel * norm(d1)) << n;
  }
}

// checks: Bessel ends take dC/dt from the quadratic through the three end points at their parameters.
TEST(InterpolateCubic, BesselEndsMatchEndQuadratic) {
  for (std::size_t n : {3u, 4u, 10u}) {
    const auto pts = random_points(n, 13 * n, 5.0);
    const auto t = parameterise(pts, Parameterisation::ChordLength);
    const NurbsCurve c = interpolate_cubic(pts, {.start = EndCondition::bessel(), .end = EndCondition::bessel()});
    const Vec3 a = lagrange_derivative(pts, t, 0, 3, 0.0);
    const Vec3 b = lagrange_derivative(pts, t, n - 3, 3, 1.0);
    EXPECT_LE(distance(c.derivatives(0.0, 1)[1], a), kRel * norm(a)) << n;
    EXPECT_LE(distance(c.derivatives(1.0, 1)[1], b), kRel * norm(b)) << n;
  }
}

// checks: occt ends take dC/dt from the cubic through the four end points at their parameters.
TEST(InterpolateCubic, OcctEndsMatchEndCubic) {
  for (std::size_t n : {4u, 5u, 10u}) {
    const auto pts = random_points(n, 17 * n, 5.0);
    const auto t = parameterise(pts, Parameterisation::ChordLength);
    const NurbsCurve c = interpolate_cubic(pts, {.start = EndCondition::occt(), .end = EndCondition::occt()});
    const Vec3 a = lagrange_derivative(pts, t, 0, 4, 0.0);
    const Vec3 b = lagrange_derivative(pts, t, n - 4, 4, 1.0);
    EXPECT_LE(distance(c.derivatives(0.0, 1)[1], a), 1e-11 * norm(a)) << n;
    EXPECT_LE(distance(c.derivatives(1.0, 1)[1], b), 1e-11 * norm(b)) << n;
  }
}

// checks: not-a-knot makes C''' continuous at t_1 and t_{N-2} (left == right limit).
TEST(InterpolateCubic, NotAKnotHasContinuousThirdDerivative) {
  for (std::size_t n : {4u, 5u, 8u, 30u}) {
    const auto pts = random_points(n, 19 * n, 4.0);
    const auto t = parameterise(pts, Parameterisation::ChordLength);
    const NurbsCurve c =
        interpolate_cubic(pts, {.start = EndCondition::not_a_knot(), .end = EndCondition::not_a_knot()});
    const double scale = derivative_scale(c, 3);
    for (double u : {t[1], t[n - 2]}) {
      const Vec3 l = c.derivatives(u, 3, kLeft)[3];
      const Vec3 r = c.derivatives(u, 3, kRight)[3];
      EXPECT_LE(distance(l, r), 1e-10 * scale) << n << " at " << u;
    }
    // The breakpoints stay at the data parameters (t_1 and t_{N-2} are kept as knots).
    expect_breakpoints(c, t, "not-a-knot");
  }
}

// checks: not-a-knot and occt ends reproduce a cubic polynomial exactly; Bessel reproduces a quadratic;
// natural ends reproduce a straight line (an independent closed-form reference).
TEST(InterpolateCubic, ReproducesPolynomials) {
  auto cubic = [](double u) { return Vec3{1 + 2 * u - 3 * u * u + 4 * u * u * u, -u * u * u + u, 2 - u * u}; };
  auto quad = [](double u) { return Vec3{1 + 2 * u - 3 * u * u, u, 2 - u * u}; };
  auto line = [](double u) { return Vec3{1 + 2 * u, 3 - u, 0.5 * u}; };
  Rng rng(5);
  std::vector<double> t{0.0};
  for (int i = 0; i < 8; ++i) t.push_back(t.back() + rng.uniform(0.2, 1.0));
  for (auto& u : t) u /= t.back();
  auto sample = [&](auto f) {
    std::vector<Vec3> p;
    for (double u : t) p.push_back(f(u));
    return p;
  };
  auto check = [&](auto f, EndCondition e, const char* what) {
    const NurbsCurve c = interpolate_cubic(sample(f), {.parameters = t, .start = e, .end = e});
    for (int i = 0; i <= 100; ++i) {
      const double u = i / 100.0;
      EXPECT_LE(distance(c.evaluate(u), f(u)), 1e-13 * 8) << what << " u=" << u;
    }
  };
  check(cubic, EndCondition::not_a_knot(), "not-a-knot");
  check(cubic, EndCondition::occt(), "occt");
  check(quad, EndCondition::bessel(), "bessel");
  check(line, EndCondition::natural(), "natural");
}

// checks: N = 2 gives the straight segment C(t) = Q0 + t (Q1 - Q0) for natural, Bessel, not-a-knot and occt
// ends; N = 3 with not-a-knot (both ends) or occt gives the parabola through the 3 points (C''' = 0).
TEST(InterpolateCubic, SmallPointCountsFallBackAsDocumented) {
  const std::vector<Vec3> two{{1, 2, 3}, {4, -2, 5}};
  for (const auto& e :
       {EndCondition::natural(), EndCondition::bessel(), EndCondition::not_a_knot(), EndCondition::occt()}) {
    const NurbsCurve c = interpolate_cubic(two, {.start = e, .end = e});
    for (double u : {0.0, 0.25, 0.5, 0.9, 1.0}) {
      const auto d = c.derivatives(u, 2);
      EXPECT_LE(distance(d[0], two[0] + u * (two[1] - two[0])), 1e-14 * 10) << u;
      EXPECT_LE(distance(d[1], two[1] - two[0]), 1e-13) << u;
      EXPECT_LE(norm(d[2]), 1e-12) << u;
    }
  }
  const std::vector<Vec3> three{{0, 0, 0}, {1, 2, 0}, {3, 1, 1}};
  const auto t = parameterise(three, Parameterisation::ChordLength);
  for (const auto& e : {EndCondition::not_a_knot(), EndCondition::occt(), EndCondition::bessel()}) {
    const NurbsCurve c = interpolate_cubic(three, {.start = e, .end = e});
    expect_interpolates(c, three, t, "N=3");
    expect_breakpoints(c, t, "N=3");
    for (double u : {0.1, 0.5, 0.9}) EXPECT_LE(norm(c.derivatives(u, 3)[3]), 1e-11) << u;
  }
  // Mixed: not-a-knot at one end of 3 points is a well-posed system of its own.
  const NurbsCurve m = interpolate_cubic(three, {.start = EndCondition::not_a_knot(), .end = EndCondition::natural()});
  expect_interpolates(m, three, t, "N=3 mixed");
  EXPECT_LE(distance(m.derivatives(t[1], 3, kLeft)[3], m.derivatives(t[1], 3, kRight)[3]), 1e-10);
}

// checks: given parameters are mapped affinely to [0, 1] and become the breakpoints.
TEST(InterpolateCubic, GivenParametersMappedToUnitInterval) {
  const auto pts = thesis_points();
  const NurbsCurve c = interpolate_cubic(pts, {.parameters = {10, 12, 15, 20}});
  const std::vector<double> t{0.0, 0.2, 0.5, 1.0};
  expect_breakpoints(c, t, "given");
  expect_interpolates(c, pts, t, "given");
  EXPECT_EQ(c.domain().start, 0.0);
  EXPECT_EQ(c.domain().end, 1.0);
}

// checks: dimension 2 builds a planar curve; a point with z ≠ 0 is rejected naming its index.
TEST(InterpolateCubic, PlanarDimension) {
  auto pts = thesis_points();
  const NurbsCurve c = interpolate_cubic(pts, {.dimension = 2});
  EXPECT_EQ(c.dimension(), 2);
  pts[2].z = 0.5;
  HULA_EXPECT_ERROR(interpolate_cubic(pts, {.dimension = 2}), Errc::InvalidArgument, "points[2]");
  HULA_EXPECT_ERROR(interpolate_cubic(thesis_points(), {.start = EndCondition::clamped({1, 0, 1}), .dimension = 2}),
                    Errc::InvalidOption, "start.derivative");
}

// checks: the same points at 1e-200 and 1e200 scale interpolate: finite curve through the points (relative
// to the scale), never NaN, the same shape as at unit scale.
TEST(InterpolateCubic, ExtremeScales) {
  const auto base = random_points(12, 4242, 1.0);
  for (double s : {1e-200, 1e200}) {
    std::vector<Vec3> pts = base;
    for (auto& p : pts) p *= s;
    for (auto rule : {Parameterisation::ChordLength, Parameterisation::Centripetal, Parameterisation::Uniform})
      for (const auto& e : all_ends(Vec3{1, -1, 0.5} * s)) {
        const NurbsCurve c = interpolate_cubic(pts, {.parameterisation = rule, .start = e, .end = e});
        const NurbsCurve ref =
            interpolate_cubic(base, {.parameterisation = rule,
                                     .start = e.kind == Kind::Clamped ? EndCondition::clamped({1, -1, 0.5}) : e,
                                     .end = e.kind == Kind::Clamped ? EndCondition::clamped({1, -1, 0.5}) : e});
        for (const Vec3& p : c.control_points()) ASSERT_TRUE(is_finite(p)) << s;
        expect_interpolates(c, pts, parameterise(pts, rule), "scale");
        for (int i = 0; i <= 50; ++i) {
          const double u = i / 50.0;
          const Vec3 q = c.evaluate(u);
          ASSERT_TRUE(is_finite(q));
          EXPECT_LE(distance(q / s, ref.evaluate(u)), 1e-12 * size_of(base)) << s << " " << u;
        }
      }
  }
}

// checks: every documented error of interpolate_cubic has its code and names the input at fault.
TEST(InterpolateCubic, ErrorsNameTheInput) {
  const std::vector<Vec3> none;
  const std::vector<Vec3> one{{1, 1, 1}};
  HULA_EXPECT_ERROR(interpolate_cubic(none), Errc::TooFewPoints, "got 0");
  HULA_EXPECT_ERROR(interpolate_cubic(one), Errc::TooFewPoints, "got 1");
  auto pts = thesis_points();
  pts[3].x = -HUGE_VAL;
  HULA_EXPECT_ERROR(interpolate_cubic(pts), Errc::NonFiniteInput, "points[3][0] = -inf");
  pts = thesis_points();
  pts[1].y = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(interpolate_cubic(pts), Errc::NonFiniteInput, "points[1][1]");
  pts = thesis_points();
  pts[1] = pts[0];
  HULA_EXPECT_ERROR(interpolate_cubic(pts), Errc::CoincidentPoints, "points[0] and points[1]");
  HULA_EXPECT_ERROR(interpolate_cubic(pts, {.parameterisation = Parameterisation::Centripetal}), Errc::CoincidentPoints,
                    "points[0] and points[1]");
  const auto good = thesis_points();
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.parameters = {0, 1, 1, 2}}), Errc::InvalidArgument, "parameters[2] = 1");
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.parameters = {0, 2, 1, 3}}), Errc::InvalidArgument, "parameters[2]");
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.parameters = {0, 1, 2}}), Errc::InvalidArgument,
                    "parameters has 3 values but there are 4 points");
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.parameters = {0, 1, std::numeric_limits<double>::quiet_NaN(), 3}}),
                    Errc::NonFiniteInput, "parameters[2]");
  HULA_EXPECT_ERROR(
      interpolate_cubic(good, {.start = EndCondition::clamped({1, std::numeric_limits<double>::quiet_NaN(), 0})}),
      Errc::InvalidOption, "start.derivative[1] = nan");
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.end = EndCondition::clamped({HUGE_VAL, 0, 0})}), Errc::InvalidOption,
                    "end.derivative[0] = inf");
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.dimension = 4}), Errc::InvalidOption, "dimension = 4");
  HULA_EXPECT_ERROR(interpolate_cubic(good, {.tolerance = {.resabs = -1.0}}), Errc::InvalidOption, "resabs");
}

// ---------------------------------------------------------------- Lagrange

// checks: thesis 5.3.1 — through 3 points at 0, 1/2, 1 the power coefficients are a = x1,
// b = -3x1 + 4x2 - x3, c = 2x1 - 4x2 + 2x3, i.e. C(0) = a, C'(0) = b, C''(0)/2 = c.
TEST(InterpolateLagrange, ThesisThreePointCoefficients) {
  const std::vector<Vec3> P{{1, 2, 0}, {3, 7, 0}, {4, -1, 0}};
  const NurbsCurve c = interpolate_lagrange(P, {}, 2);
  EXPECT_EQ(c.degree(), 2);
  const auto d = c.derivatives(0.0, 2);
  const Vec3 a = P[0], b = -3.0 * P[0] + 4.0 * P[1] - P[2], cc = 2.0 * P[0] - 4.0 * P[1] + 2.0 * P[2];
  EXPECT_LE(distance(d[0], a), 1e-14);
  EXPECT_LE(distance(d[1], b), 1e-13);
  EXPECT_LE(distance(0.5 * d[2], cc), 1e-13);
}

// checks: the Lagrange polynomial passes through its points at uniform and at given parameters.
TEST(InterpolateLagrange, PassesThroughPoints) {
  for (std::size_t n : {2u, 3u, 5u, 8u}) {
    const auto pts = random_points(n, 31 * n, 2.0);
    const NurbsCurve c = interpolate_lagrange(pts);
    EXPECT_EQ(c.degree(), static_cast<int>(n) - 1);
    expect_interpolates(c, pts, parameterise(pts, Parameterisation::Uniform), "lagrange uniform");
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) u[i] = 3.0 + std::sqrt(static_cast<double>(i));
    const NurbsCurve g = interpolate_lagrange(pts, u);
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = (u[i] - u[0]) / (u[n - 1] - u[0]);
    t[n - 1] = 1.0;
    expect_interpolates(g, pts, t, "lagrange given");
  }
}

// checks: Lagrange errors: too few points, too many for kMaxDegree, bad dimension, bad parameters.
TEST(InterpolateLagrange, ErrorsNameTheInput) {
  const std::vector<Vec3> one{{0, 0, 0}};
  HULA_EXPECT_ERROR(interpolate_lagrange(one), Errc::TooFewPoints, "got 1");
  const auto many = random_points(static_cast<std::size_t>(kMaxDegree) + 2, 3);
  HULA_EXPECT_ERROR(interpolate_lagrange(many), Errc::InvalidDegree, "degree 65");
  HULA_EXPECT_ERROR(interpolate_lagrange(thesis_points(), {}, 5), Errc::InvalidArgument, "dimension = 5");
  const std::vector<double> bad{0, 1, 0.5, 2};
  HULA_EXPECT_ERROR(interpolate_lagrange(thesis_points(), bad), Errc::InvalidArgument, "parameters[2]");
}

// ---------------------------------------------------------------- Hermite

// checks: the cubic Hermite curve passes through the points with the given dC/dt on both sides of every
// double interior knot (so it is C1), and its breakpoints are the data parameters.
TEST(HermiteCubic, MeetsPointsAndDerivatives) {
  for (std::size_t n : {2u, 3u, 7u}) {
    const auto pts = random_points(n, 41 * n, 3.0);
    const auto der = random_points(n, 43 * n, 5.0);
    const auto t = parameterise(pts, Parameterisation::ChordLength);
    const NurbsCurve c = hermite_cubic(pts, der);
    EXPECT_EQ(c.degree(), 3);
    expect_breakpoints(c, t, "hermite cubic");
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& side : {kLeft, kRight}) {
        const auto d = c.derivatives(t[i], 1, side);
        EXPECT_LE(distance(d[0], pts[i]), kRel * size_of(pts)) << n << " " << i;
        EXPECT_LE(distance(d[1], der[i]), 1e-11 * 5) << n << " " << i;
      }
      if (i > 0 && i + 1 < n) {
        EXPECT_EQ(c.knots().multiplicity(t[i]), 2);
      }
    }
  }
}

// checks: the quintic Hermite curve meets points, dC/dt and d²C/dt² on both sides of every triple knot (C2).
TEST(HermiteQuintic, MeetsPointsAndTwoDerivatives) {
  for (std::size_t n : {2u, 3u, 6u}) {
    const auto pts = random_points(n, 51 * n, 3.0);
    const auto der = random_points(n, 53 * n, 5.0);
    const auto sec = random_points(n, 57 * n, 20.0);
    const std::vector<double> given = [&] {
      std::vector<double> u(n);
      for (std::size_t i = 0; i < n; ++i) u[i] = static_cast<double>(i * i + i);
      return u;
    }();
    const NurbsCurve c = hermite_quintic(pts, der, sec, given);
    EXPECT_EQ(c.degree(), 5);
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = given[i] / given[n - 1];
    expect_breakpoints(c, t, "hermite quintic");
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& side : {kLeft, kRight}) {
        const auto d = c.derivatives(t[i], 2, side);
        EXPECT_LE(distance(d[0], pts[i]), kRel * size_of(pts)) << n << " " << i;
        EXPECT_LE(distance(d[1], der[i]), 1e-11 * 5) << n << " " << i;
        EXPECT_LE(distance(d[2], sec[i]), 1e-10 * 20) << n << " " << i;
      }
      if (i > 0 && i + 1 < n) {
        EXPECT_EQ(c.knots().multiplicity(t[i]), 3);
      }
    }
  }
}

// checks: Lagrange and Hermite curves at 1e-200 and 1e200 scale are finite and pass through the points
// (relative to the scale), derivatives scaling with the data.
TEST(Hermite, ExtremeScales) {
  const auto base = random_points(6, 606, 1.0);
  const auto dbase = random_points(6, 607, 2.0);
  const auto t = parameterise(base, Parameterisation::ChordLength);
  for (double s : {1e-200, 1e200}) {
    std::vector<Vec3> pts = base, der = dbase;
    for (auto& p : pts) p *= s;
    for (auto& d : der) d *= s;
    const NurbsCurve h3 = hermite_cubic(pts, der);
    const NurbsCurve h5 = hermite_quintic(pts, der, der);
    const NurbsCurve lg = interpolate_lagrange(pts);
    const auto tu = parameterise(pts, Parameterisation::Uniform);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      EXPECT_LE(distance(h3.evaluate(t[i]), pts[i]), kRel * s * size_of(base)) << s;
      EXPECT_LE(distance(h5.evaluate(t[i]), pts[i]), kRel * s * size_of(base)) << s;
      EXPECT_LE(distance(lg.evaluate(tu[i]), pts[i]), kRel * s * size_of(base)) << s;
      EXPECT_LE(distance(h3.derivatives(t[i], 1)[1], der[i]), 1e-11 * s * 2) << s;
    }
  }
}

// checks: Hermite errors: derivative count mismatch, non-finite derivative (index and coordinate), planar z.
TEST(Hermite, ErrorsNameTheInput) {
  const auto pts = thesis_points();
  const std::vector<Vec3> three(3, Vec3{1, 0, 0});
  HULA_EXPECT_ERROR(hermite_cubic(pts, three), Errc::InvalidArgument, "derivatives has 3 values");
  std::vector<Vec3> der(4, Vec3{1, 0, 0});
  der[2].y = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR(hermite_cubic(pts, der), Errc::NonFiniteInput, "derivatives[2][1]");
  const std::vector<Vec3> ok(4, Vec3{1, 0, 0});
  HULA_EXPECT_ERROR(hermite_quintic(pts, ok, three), Errc::InvalidArgument, "second_derivatives has 3 values");
  std::vector<Vec3> zd(4, Vec3{1, 0, 0});
  zd[3].z = 1.0;
  HULA_EXPECT_ERROR(hermite_quintic(pts, ok, zd, {}, 2), Errc::InvalidArgument, "second_derivatives[3]");
  const std::vector<Vec3> single{{0, 0, 0}};
  HULA_EXPECT_ERROR(hermite_cubic(single, single), Errc::TooFewPoints, "got 1");
  const std::vector<double> bad{0, 1, 1, 2};
  HULA_EXPECT_ERROR(hermite_cubic(pts, ok, bad), Errc::InvalidArgument, "parameters[2]");
}

}  // namespace
}  // namespace hula::nurbs

namespace hula::nurbs {
namespace {

double end_curvature(const NurbsCurve& c, double t) {
  const std::vector<Vec3> d = c.derivatives(t, 2);
  return norm(cross(d[1], d[2])) / std::pow(norm(d[1]), 3);
}

// checks: a direction end has the sense of the given vector and the magnitude of the Bessel end
// derivative (the quadratic through the three end points), whatever length the vector has.
TEST(InterpolateCubic, DirectionEndTakesBesselMagnitude) {
  for (std::size_t n : {3u, 4u, 10u}) {
    const auto pts = random_points(n, 19 * n, 5.0);
    const auto t = parameterise(pts, Parameterisation::ChordLength);
    const Vec3 a = lagrange_derivative(pts, t, 0, 3, 0.0);
    const Vec3 b = lagrange_derivative(pts, t, n - 3, 3, 1.0);
    const Vec3 u{0.3, -2, 1}, v{-4, 0.5, 0.25};
    const NurbsCurve c =
        interpolate_cubic(pts, {.start = EndCondition::direction(u), .end = EndCondition::direction(1e-3 * v)});
    const Vec3 want0 = (norm(a) / norm(u)) * u;
    const Vec3 want1 = (norm(b) / norm(v)) * v;
    EXPECT_LE(distance(c.derivatives(0.0, 1)[1], want0), kRel * norm(want0)) << n;
    EXPECT_LE(distance(c.derivatives(1.0, 1)[1], want1), kRel * norm(want1)) << n;
  }
  // Two points: the Bessel derivative is the chord Q1 − Q0 (t from 0 to 1), so its length.
  const std::vector<Vec3> two{{0, 0, 0}, {3, 4, 0}};
  const NurbsCurve c = interpolate_cubic(two, {.start = EndCondition::direction({0, 1, 0})});
  EXPECT_NEAR(c.derivatives(0.0, 1)[1].y, 5.0, 1e-12);
}

// checks (issue 10 defect): the README's `--end clamped:1,0,0` on the thesis's points imposes
// |C'(1)| = 1 where the natural spline runs at ~150, bending the end into a hook (end curvature
// hundreds of times the natural spline's); the direction end along the same vector keeps the
// Bessel speed, and its end curvature stays within a few times the natural spline's.
TEST(InterpolateCubic, DirectionEndMakesNoHookWhereClampedDoes) {
  const auto pts = thesis_points();
  const NurbsCurve natural = interpolate_cubic(pts);
  const NurbsCurve clamped = interpolate_cubic(pts, {.end = EndCondition::clamped({1, 0, 0})});
  const NurbsCurve direction = interpolate_cubic(pts, {.end = EndCondition::direction({1, 0, 0})});
  double kappa_natural = 0.0;
  for (int i = 0; i <= 100; ++i) kappa_natural = std::max(kappa_natural, end_curvature(natural, i / 100.0));
  EXPECT_GT(end_curvature(clamped, 1.0), 100 * kappa_natural);
  EXPECT_LT(end_curvature(direction, 1.0), 3 * kappa_natural);
  EXPECT_GT(norm(direction.derivatives(1.0, 1)[1]), 100.0);
  EXPECT_NEAR(direction.derivatives(1.0, 1)[1].y, 0.0, 1e-12);
}

// checks: a zero or non-finite direction is refused by name before any work.
TEST(InterpolateCubic, DirectionEndErrorsNameTheEnd) {
  const auto pts = thesis_points();
  HULA_EXPECT_ERROR(interpolate_cubic(pts, {.start = EndCondition::direction({0, 0, 0})}), Errc::InvalidOption,
                    "start.derivative is a zero direction");
  HULA_EXPECT_ERROR(interpolate_cubic(pts, {.end = EndCondition::direction({std::nan(""), 1, 0})}), Errc::InvalidOption,
                    "end.derivative[0] = nan");
}

// checks the closed spline through the square's vertices (1, 0), (0, 1), (−1, 0), (0, −1) at uniform parameters
// against the closed form of its cyclic system: D_i = 6 × (P_i turned by 90°), so C(1/8) = (11/16, 11/16); C2 at
// the closure; a closed list (last = first) gives the same curve.
TEST(InterpolateClosedCubic, SquareClosedForm) {
  const std::vector<Vec3> sq{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  InterpolationOptions o;
  o.parameterisation = Parameterisation::Uniform;
  o.dimension = 2;
  const NurbsCurve c = interpolate_closed_cubic(sq, o);
  EXPECT_EQ(c.degree(), 3);
  EXPECT_EQ(c.control_points().size(), 7U);  // 4 spans, simple interior knots: 4 + 3
  const auto d0 = c.derivatives(0.0, 2);
  EXPECT_LE(distance(d0[0], {1, 0, 0}), 1e-15);
  EXPECT_LE(distance(d0[1], {0, 6, 0}), 1e-13);
  EXPECT_LE(distance(c.evaluate(0.125), {0.6875, 0.6875, 0}), 1e-15);
  const auto d1 = c.derivatives(1.0, 2);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_LE(distance(d0[k], d1[k]), 1e-12) << k;
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LE(distance(c.evaluate(0.25 * static_cast<double>(i)), sq[i]), 1e-15);
  std::vector<Vec3> again(sq);
  again.push_back(sq.front());
  const NurbsCurve c2 = interpolate_closed_cubic(again, o);
  for (int i = 0; i <= 20; ++i) EXPECT_LE(distance(c.evaluate(i / 20.0), c2.evaluate(i / 20.0)), 1e-15);
}

// checks the closed spline on seeded point sets of 3 … 40 points against what defines it uniquely (the C2 periodic
// cubic spline with simple knots at the data parameters): degree 3, C(t_i) = Q_i, and the left and right first and
// second derivatives equal at every knot and across the closure, all to 1e-12 of their size.
TEST(InterpolateClosedCubic, IsTheUniquePeriodicSpline) {
  Rng rng(2626);
  for (std::size_t n : {3U, 4U, 7U, 12U, 40U}) {
    std::vector<Vec3> pts(n);
    for (auto& q : pts) q = Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)} * 3.0;
    std::vector<Vec3> closed(pts);
    closed.push_back(pts.front());
    const std::vector<double> t = parameterise(closed, Parameterisation::ChordLength);
    const NurbsCurve c = interpolate_closed_cubic(pts);
    ASSERT_EQ(c.degree(), 3);
    ASSERT_EQ(c.control_points().size(), n + 3);
    std::array<double, 3> scale{};
    for (int i = 0; i <= 500; ++i) {
      const auto d = c.derivatives(i / 500.0, 2);
      for (std::size_t k = 0; k < 3; ++k) scale[k] = std::max(scale[k], norm(d[k]));
    }
    for (std::size_t i = 0; i < n; ++i) EXPECT_LE(distance(c.evaluate(t[i]), pts[i]), 1e-13 * scale[0]) << n;
    for (std::size_t i = 0; i < n; ++i) {
      // At t_0 the left side is the closure's: the end of the curve.
      const auto right = c.derivatives(t[i], 2);
      const auto left = i == 0 ? c.derivatives(1.0, 2) : c.derivatives(t[i], 2, {.side = Side::Left});
      for (std::size_t k = 0; k < 3; ++k) EXPECT_LE(distance(left[k], right[k]), 1e-12 * scale[k]) << n << " " << i;
    }
  }
}

// checks too few points and a parameter list of the wrong length are refused naming them.
TEST(InterpolateClosedCubic, BadInputNamesIt) {
  const std::vector<Vec3> two{{0, 0, 0}, {1, 0, 0}};
  HULA_EXPECT_ERROR(interpolate_closed_cubic(two), Errc::TooFewPoints, "got 2");
  const std::vector<Vec3> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  InterpolationOptions o;
  o.parameters = {0.0, 0.5, 1.0};  // needs 4: the closure's too
  try {
    (void)interpolate_closed_cubic(three, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "parameters");
  }
}

// κ and τ of a curve at t from its first three derivatives (thesis eq. 11, 17), written out here.
std::pair<double, double> kappa_tau(const NurbsCurve& c, double t) {
  const auto d = c.derivatives(t, 3);
  const Vec3 a = cross(d[1], d[2]);
  return {norm(a) / std::pow(norm(d[1]), 3), dot(a, d[3]) / dot(a, a)};
}

// checks the Frenet handles against the circular helix (a cos s, a sin s, b s), κ = a/(a² + b²), τ = b/(a² + b²):
// handles sampled from its exact T, N, κ, τ at 9 points of one turn give a curve with those κ, τ and N at every
// handle (1e-10) that stays within 1e-5 of the helix between them (O(h⁸), closed form at the same parameter).
TEST(HermiteFrenet, HelixHandles) {
  const double a = 2.0, b = 0.5, c2 = a * a + b * b;
  const double L = 2.0 * std::numbers::pi;  // s ∈ [0, 2π], t = s / L
  std::vector<FrenetHandle> handles;
  std::vector<double> ts;
  for (int i = 0; i <= 8; ++i) {
    const double s = L * i / 8.0;
    FrenetHandle h;
    h.point = {a * std::cos(s), a * std::sin(s), b * s};
    h.tangent = L * Vec3{-a * std::sin(s), a * std::cos(s), b};  // dC/dt = L dC/ds
    h.normal = {-std::cos(s), -std::sin(s), 0.0};
    h.curvature = a / c2;
    h.torsion = b / c2;
    handles.push_back(h);
    ts.push_back(i / 8.0);
  }
  const NurbsCurve c = hermite_frenet(handles, ts);
  EXPECT_EQ(c.degree(), 7);
  for (int i = 0; i <= 8; ++i) {
    const auto [k, tau] = kappa_tau(c, ts[static_cast<std::size_t>(i)]);
    EXPECT_NEAR(k, a / c2, 1e-10) << i;
    EXPECT_NEAR(tau, b / c2, 1e-10) << i;
    const auto d = c.derivatives(ts[static_cast<std::size_t>(i)], 2);
    const Vec3 n = d[2] - dot(d[2], d[1]) / dot(d[1], d[1]) * d[1];
    EXPECT_LE(distance(n / norm(n), handles[static_cast<std::size_t>(i)].normal), 1e-10) << i;
  }
  for (int i = 0; i <= 400; ++i) {
    const double t = i / 400.0, s = L * t;
    EXPECT_LE(distance(c.evaluate(t), {a * std::cos(s), a * std::sin(s), b * s}), 1e-5) << t;
  }
  // C3 everywhere: the derivatives of both sides of each handle agree.
  for (int i = 1; i < 8; ++i) {
    const auto left = c.derivatives(i / 8.0, 3, {.side = Side::Left});
    const auto right = c.derivatives(i / 8.0, 3);
    for (std::size_t k = 0; k <= 3; ++k) EXPECT_LE(distance(left[k], right[k]), 1e-9 * norm(right[k]) + 1e-9) << i;
  }
}

// checks a handle with zero tangent, a normal along the tangent and a negative curvature are refused naming them.
TEST(HermiteFrenet, BadHandlesNameThem) {
  std::vector<FrenetHandle> h(2);
  h[0].point = {0, 0, 0};
  h[0].tangent = {1, 0, 0};
  h[1].point = {1, 0, 0};
  h[1].tangent = {0, 0, 0};
  HULA_EXPECT_ERROR((void)hermite_frenet(h), Errc::InvalidArgument, "tangent[1]");
  h[1].tangent = {1, 0, 0};
  h[0].curvature = 1.0;
  h[0].normal = {2, 0, 0};
  HULA_EXPECT_ERROR((void)hermite_frenet(h), Errc::InvalidArgument, "normal[0]");
  h[0].curvature = -1.0;
  HULA_EXPECT_ERROR((void)hermite_frenet(h), Errc::InvalidArgument, "curvature[0]");
}

}  // namespace
}  // namespace hula::nurbs
