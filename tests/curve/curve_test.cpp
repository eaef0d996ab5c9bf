// SPDX-License-Identifier: MIT
// The curve value type: each kind's factory against closed forms (Bernstein
// form, interpolation conditions, Hermite conditions, the exact helix), the
// validation of bad data, equality and copies, and concurrent evaluation.
#include "hula/curve/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::curve {
namespace {

// checks: a quadratic Bézier's midpoint is (P0 + 2 P1 + P2) / 4 (Bernstein form) and the data are kept.
TEST(Curve, BezierMatchesBernsteinForm) {
  const Curve c = Curve::bezier({{{0, 0, 0}, {1, 2, 0}, {2, 0, 0}}, {}, 2});
  EXPECT_EQ(c.kind(), Kind::Bezier);
  EXPECT_EQ(c.kind_name(), "bezier");
  EXPECT_EQ(c.dimension(), 2);
  EXPECT_EQ(c.nurbs().degree(), 2);
  EXPECT_EQ(c.point(0.5), (Vec3{1.0, 1.0, 0.0}));
  EXPECT_EQ(c.approximation_deviation(), 0.0);
  EXPECT_EQ(c.law(), nullptr);
  EXPECT_EQ(std::get<BezierData>(c.data()).control_points.size(), 3U);
}

// checks: the interpolated kind passes through its points at its given parameters and honours a clamped end.
TEST(Curve, InterpolatedPassesThroughItsPoints) {
  InterpolatedData d;
  d.points = {{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}};
  d.parameters = {0.0, 1.0, 2.0, 4.0};
  d.end = nurbs::EndCondition::clamped({100, 0, 0});
  const Curve c = Curve::interpolated(d);
  EXPECT_EQ(c.kind(), Kind::Interpolated);
  const double t[4] = {0.0, 0.25, 0.5, 1.0};  // the parameters mapped to [0, 1]
  for (int i = 0; i < 4; ++i) EXPECT_LT(distance(c.point(t[i]), d.points[static_cast<std::size_t>(i)]), 1e-12);
  EXPECT_LT(distance(c.derivatives(1.0, 1)[1], Vec3{100, 0, 0}), 1e-9);
}

// checks: cubic Hermite meets its points and tangents; quintic also its second derivatives.
TEST(Curve, HermiteMeetsPointsAndDerivatives) {
  HermiteData h;
  h.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 1}};
  h.tangents = {{1, 0, 0}, {2, 0, 0}, {0, -1, 1}};
  h.parameters = {0.0, 0.5, 1.0};
  const Curve cubic = Curve::hermite(h);
  EXPECT_EQ(cubic.kind(), Kind::Hermite);
  EXPECT_EQ(cubic.nurbs().degree(), 3);
  h.second_derivatives = {{0, 1, 0}, {0, 0, 0}, {1, 0, 0}};
  const Curve quintic = Curve::hermite(h);
  EXPECT_EQ(quintic.nurbs().degree(), 5);
  for (std::size_t i = 0; i < 3; ++i) {
    const nurbs::Side side = i == 2 ? nurbs::Side::Left : nurbs::Side::Right;
    const auto d3 = cubic.derivatives(h.parameters[i], 1, {.side = side});
    EXPECT_LT(distance(d3[0], h.points[i]), 1e-14);
    EXPECT_LT(distance(d3[1], h.tangents[i]), 1e-12);
    const auto d5 = quintic.derivatives(h.parameters[i], 2, {.side = side});
    EXPECT_LT(distance(d5[1], h.tangents[i]), 1e-12);
    EXPECT_LT(distance(d5[2], h.second_derivatives[i]), 1e-10);
  }
}

// checks: the law kind evaluates the helix (2 cos t, 2 sin t, t/2) exactly, its NURBS within the
// tolerance, and its arc length is sqrt(4.25) t (closed form) with the inverse to 1e-12.
TEST(Curve, LawEvaluatesExactlyWithVerifiedNurbs) {
  const Curve c = Curve::from_law("vec(2*cos(t), 2*sin(t), 0.5*t)", "t", {0.0, 6.0});
  EXPECT_EQ(c.kind(), Kind::Law);
  ASSERT_NE(c.law(), nullptr);
  EXPECT_EQ(c.law_parameter(), "t");
  EXPECT_LE(c.approximation_deviation(), kApproximationTolerance);
  EXPECT_EQ(c.domain().end, 6.0);
  for (const double t : {0.0, 0.7, 3.1, 6.0}) {
    const auto d = c.derivatives(t, 2);
    EXPECT_NEAR(distance(d[0], Vec3{2 * std::cos(t), 2 * std::sin(t), 0.5 * t}), 0.0, 1e-15);
    EXPECT_NEAR(distance(d[1], Vec3{-2 * std::sin(t), 2 * std::cos(t), 0.5}), 0.0, 1e-15);
    EXPECT_NEAR(distance(d[2], Vec3{-2 * std::cos(t), -2 * std::sin(t), 0.0}), 0.0, 1e-15);
    EXPECT_LT(distance(c.nurbs().evaluate(t), d[0]), 1e-6);
    EXPECT_NEAR(c.length_to(t), std::sqrt(4.25) * t, 1e-12);
  }
  EXPECT_NEAR(c.parameter_at_length(std::sqrt(4.25) * 2.5), 2.5, 1e-12);
  EXPECT_NEAR(c.length(), std::sqrt(4.25) * 6.0, 1e-12);
}

// checks: a 2-vector law gives a 2-D curve; parameters other than t work.
TEST(Curve, PlanarLawWithItsOwnParameter) {
  const Curve c = Curve::from_law("vec(u, u^2)", "u", {-1.0, 1.0});
  EXPECT_EQ(c.dimension(), 2);
  EXPECT_EQ(c.point(0.5), (Vec3{0.5, 0.25, 0.0}));
}

// checks: evaluation outside the domain is refused naming t (Strict), clamped or extrapolated on request.
TEST(Curve, DomainPolicy) {
  const Curve c = Curve::from_law("vec(t, t^2, 0)", "t", {0.0, 1.0});
  HULA_EXPECT_ERROR(c.point(1.5), Errc::OutOfDomain, "t = 1.5");
  EXPECT_EQ(c.point(1.5, {.domain = nurbs::Domain::Clamp}), (Vec3{1, 1, 0}));
  EXPECT_EQ(c.point(2.0, {.domain = nurbs::Domain::Extrapolate}), (Vec3{2, 4, 0}));
  std::vector<Vec3> out(2);
  const std::vector<double> ts{0.5, -1.0};
  HULA_EXPECT_ERROR(c.derivatives(ts, 0, out), Errc::OutOfDomain, "t[1] = -1");
  const Curve n = nurbs::NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}});
  HULA_EXPECT_ERROR(n.point(2.0), Errc::OutOfDomain, "t = 2");
}

// checks: invalid data cannot make a curve; each error names the member at fault.
TEST(Curve, FactoriesRefuseBadDataByName) {
  HULA_EXPECT_ERROR(Curve::bezier({{{0, 0, 0}}, {}, 3}), Errc::TooFewPoints, "control_points");
  HULA_EXPECT_ERROR(Curve::bezier({{{0, 0, 0}, {1, 0, 0}}, {1.0, -1.0}, 3}), Errc::InvalidWeight, "weights");
  HermiteData h{{{0, 0, 0}, {1, 0, 0}}, {{1, 0, 0}}, {}, {}, 3};
  HULA_EXPECT_ERROR(Curve::hermite(h), Errc::InvalidArgument, "tangents");
  HULA_EXPECT_ERROR(Curve::from_law("t", "t", {0, 1}), Errc::ParseError, "scalar");
  HULA_EXPECT_ERROR(Curve::from_law("vec(t, sin(t)", "t", {0, 1}), Errc::ParseError, "expression");
  HULA_EXPECT_ERROR(Curve::from_law("vec(t, t)", "t", {1, 0}), Errc::InvalidArgument, "domain");
  HULA_EXPECT_ERROR(Curve::from_law("vec(t, 1/t)", "t", {-1, 1}), Errc::InvalidArgument, "domain");
  HULA_EXPECT_ERROR(Curve::from_law("vec(t, t)", "t", {0, 1}, 0.0), Errc::InvalidArgument, "tolerance");
  InterpolatedData d;
  d.points = {{0, 0, 0}};
  HULA_EXPECT_ERROR(Curve::interpolated(d), Errc::TooFewPoints, "");
}

// checks: copies share state and compare equal; equal data built twice compare equal; other data do not.
TEST(Curve, EqualityIsByConstructionData) {
  const Curve a = Curve::from_law("vec(t, t^2)", "t", {0, 1});
  const Curve b = a;  // NOLINT(performance-unnecessary-copy-initialization)
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, Curve::from_law("vec(t, t^2)", "t", {0, 1}));
  EXPECT_FALSE(a == Curve::from_law("vec(t, t^2)", "t", {0, 2}));
  const nurbs::NurbsCurve line(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}});
  EXPECT_FALSE(Curve(line) == Curve::bezier({{{0, 0, 0}, {1, 0, 0}}, {}, 3}));  // same NURBS, other kind
}

// checks: concurrent evaluation of one law curve from several threads gives the single-thread values.
TEST(Curve, LawEvaluationIsThreadSafe) {
  const Curve c = Curve::from_law("vec(cos(t), sin(t), t)", "t", {0.0, 10.0});
  std::vector<std::vector<Vec3>> results(4);
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < results.size(); ++k)
    threads.emplace_back([&c, &results, k] {
      for (int i = 0; i <= 100; ++i) results[k].push_back(c.derivatives(i / 10.0, 3 - static_cast<int>(k % 3))[0]);
    });
  for (auto& t : threads) t.join();
  for (const auto& r : results)
    for (int i = 0; i <= 100; ++i) EXPECT_EQ(r[static_cast<std::size_t>(i)], c.point(i / 10.0));
}

}  // namespace
}  // namespace hula::curve
