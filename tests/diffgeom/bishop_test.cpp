// SPDX-License-Identifier: MIT
// Bishop frame by double reflection (thesis 6.4; Wang et al. 2008): on a helix
// it equals the Frenet frame rotated by −τs; fourth-order convergence when the
// step halves; defined through an inflection without flipping; closed by the
// rotation correction on a closed space curve; orthonormal on random curves.
#include "hula/diffgeom/bishop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

std::vector<double> bishop_parameters(double a, double b, int n) {
  std::vector<double> ts(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ts[static_cast<std::size_t>(i)] = a + (b - a) * i / (n - 1);
  return ts;
}

// Angle of U from N, measured about T (towards B).
double angle_from_normal(const FrenetPoint& p, const BishopFrame& f) {
  return std::atan2(dot(f.u, p.binormal), dot(f.u, p.normal));
}

// Largest error of the helix Bishop angle against φ(s) = −τ s over n samples of [0, 4π].
double helix_error(int n) {
  law::Context ctx;
  const LawFrenet helix(law::parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), "t", {0.0, 4 * std::numbers::pi});
  const std::vector<double> ts = bishop_parameters(0.0, 4 * std::numbers::pi, n);
  const BishopResult r = bishop_frame(helix, ts);
  const double c = std::sqrt(4.25), tau = 0.5 / 4.25;
  double worst = 0.0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const FrenetPoint p = helix.at(ts[i]);
    const double want = -tau * c * ts[i];
    const double got = angle_from_normal(p, r.frames[i]);
    worst = std::max(worst, std::fabs(std::remainder(got - want, 2 * std::numbers::pi)));
  }
  return worst;
}

// checks U = N rotated by −τs about T on the helix (a = 2, b = 0.5), and orthonormality.
TEST(Bishop, HelixIsFrenetRotatedByMinusTauS) { EXPECT_LT(helix_error(4001), 1e-9); }

// checks the global error falls by 2⁴ each time the step halves (Wang et al.: O(h⁴)).
TEST(Bishop, FourthOrderConvergence) {
  const double e1 = helix_error(101), e2 = helix_error(201), e3 = helix_error(401);
  const double order1 = std::log2(e1 / e2), order2 = std::log2(e2 / e3);
  EXPECT_NEAR(order1, 4.0, 0.2) << e1 << " " << e2;
  EXPECT_NEAR(order2, 4.0, 0.2) << e2 << " " << e3;
}

// checks the planar S-curve: U stays the continuous signed normal z × T through the inflection and
// V = +z, while Frenet N flips.
TEST(Bishop, ThroughInflection) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1},
                            {{-1, 0, 0}, {-1.0 / 3, 4.0 / 3, 0}, {1.0 / 3, -4.0 / 3, 0}, {1, 0, 0}}, {}, 2);
  const std::vector<double> ts = bishop_parameters(0.0, 1.0, 201);
  const BishopResult r = bishop_frame(c, ts);
  std::vector<FrenetPoint> f(ts.size());
  frenet(c, ts, f);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    ASSERT_TRUE(r.frames[i].defined);
    EXPECT_NEAR(dot(r.frames[i].u, f[i].signed_normal), -1.0, 1e-12);  // starts at N = −(z × T) (κ_s < 0)
    EXPECT_LT(norm(r.frames[i].v - Vec3{0, 0, -1}), 1e-12);
  }
}

// checks the closing correction on the (closed, non-planar) trefoil: U at the end equals U at the start,
// the frame stays orthonormal and right-handed, and a non-closed curve with close = true is refused.
TEST(Bishop, ClosingCorrection) {
  law::Context ctx;
  const LawFrenet k(law::parse("vec(sin(t) + 2*sin(2*t), cos(t) - 2*cos(2*t), -sin(3*t))", ctx), "t",
                    {0.0, 2 * std::numbers::pi});
  const std::vector<double> ts = bishop_parameters(0.0, 2 * std::numbers::pi, 2001);
  const BishopResult open = bishop_frame(k, ts);
  EXPECT_GT(norm(open.frames.back().u - open.frames.front().u), 1e-3);  // the trefoil's RMF does not close
  BishopOptions o;
  o.close = true;
  const BishopResult closed = bishop_frame(k, ts, o);
  EXPECT_NE(closed.closing_angle, 0.0);
  EXPECT_LT(norm(closed.frames.back().u - closed.frames.front().u), 1e-12);
  for (const BishopFrame& f : closed.frames) {
    EXPECT_NEAR(norm(f.u), 1.0, 1e-12);
    EXPECT_NEAR(dot(f.u, f.tangent), 0.0, 1e-12);
    EXPECT_LT(norm(cross(f.tangent, f.u) - f.v), 1e-12);
  }
  const std::vector<double> half = bishop_parameters(0.0, 3.0, 50);
  EXPECT_THROW((void)bishop_frame(k, half, o), Error);
}

// checks orthonormality and right-handedness on seeded random curves (rational, unclamped, any degree).
TEST(Bishop, RandomCurvesOrthonormal) {
  Rng rng(11);
  for (int k = 0; k < 20; ++k) {
    const nurbs::NurbsCurve c =
        testing::random_curve(rng, {.degree = 1 + k % 5, .rational = k % 2 == 0, .clamped = k % 3 != 0});
    const std::vector<double> ts = bishop_parameters(c.domain().start, c.domain().end, 300);
    const BishopResult r = bishop_frame(c, ts);
    for (const BishopFrame& f : r.frames) {
      if (!f.defined) continue;
      EXPECT_NEAR(norm(f.u), 1.0, 1e-12);
      EXPECT_NEAR(dot(f.u, f.tangent), 0.0, 1e-12);
      EXPECT_LT(norm(cross(f.tangent, f.u) - f.v), 1e-12);
    }
  }
}

// checks the errors: fewer than two samples, decreasing parameters (named index), initial_u along T.
TEST(Bishop, Errors) {
  const nurbs::NurbsCurve c = testing::rational_circle(1.0);
  const std::vector<double> one = {0.5};
  EXPECT_THROW((void)bishop_frame(c, one), Error);
  const std::vector<double> bad = {0.1, 0.3, 0.2};
  try {
    (void)bishop_frame(c, bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().index, 2U);
  }
  BishopOptions o;
  o.initial_u = frenet(c, 0.0).tangent;
  const std::vector<double> ok = {0.0, 0.5};
  EXPECT_THROW((void)bishop_frame(c, ok, o), Error);
}

}  // namespace
}  // namespace hula::diffgeom
