// SPDX-License-Identifier: MIT
// NurbsCurve construction, validation errors and evaluation against closed
// forms (rational circle), the thesis's Table 3 and A2.3-based direct sums.
#include "hula/nurbs/nurbs_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/core/error.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: a rational quadratic circle has radius exactly R everywhere (closed form).
TEST(NurbsCurve, RationalCircleHasConstantRadius) {
  for (double R : {1.0, 25.0, 1e-150, 1e150}) {
    const NurbsCurve c = testing::rational_circle(R);
    for (int i = 0; i <= 1000; ++i) {
      const double t = i / 1000.0;
      EXPECT_NEAR(norm(c.evaluate(t)) / R, 1.0, 1e-14) << "R=" << R << " t=" << t;
    }
  }
}

// checks: curvature of the rational circle from derivatives |C'×C''|/|C'|^3 = 1/R (closed form).
TEST(NurbsCurve, RationalCircleCurvatureFromDerivatives) {
  const double R = 3.0;
  const NurbsCurve c = testing::rational_circle(R);
  for (int i = 0; i <= 200; ++i) {
    const double t = i / 200.0;
    const auto d = c.derivatives(t, 2);
    const double k = norm(cross(d[1], d[2])) / std::pow(norm(d[1]), 3);
    EXPECT_NEAR(k * R, 1.0, 1e-12) << t;
    EXPECT_NEAR(dot(d[0], d[1]), 0.0, 1e-12 * norm(d[1]) * R) << t;
  }
}

// checks: the thesis's 7.1.2 internal double knot (Table 3): C1 but not C2 at the knot.
TEST(NurbsCurve, ThesisDoubleKnotIsC1NotC2) {
  const std::vector<Vec3> P = {{0, 0, 0}, {10, 25, 0}, {25, 25, 0}, {40, -10, 0}, {60, 0, 0}, {60, 10, 0}};
  const std::vector<double> acis = {0, 0, 0, 0.33, 0.33, 1, 1, 1};
  const NurbsCurve c(KnotVector::from_acis(acis, 3), P);
  const auto left = c.derivatives(0.33, 3, {.side = Side::Left});
  const auto right = c.derivatives(0.33, 3, {.side = Side::Right});
  EXPECT_NEAR(distance(left[0], right[0]), 0.0, 1e-12);
  EXPECT_NEAR(distance(left[1], right[1]), 0.0, 1e-10);
  EXPECT_GT(distance(left[2], right[2]), 100.0);
}

// checks: out-of-domain parameters are refused by name, clamped or extrapolated only when asked.
TEST(NurbsCurve, DomainPolicy) {
  const NurbsCurve c = testing::rational_circle(1.0);
  HULA_EXPECT_ERROR(c.evaluate(1.5), Errc::OutOfDomain, "1.5");
  HULA_EXPECT_ERROR(c.evaluate(std::nan("")), Errc::NonFiniteInput, "nan");
  EXPECT_EQ(c.evaluate(1.5, {.domain = Domain::Clamp}), c.evaluate(1.0));
  const Vec3 e = c.evaluate(1.01, {.domain = Domain::Extrapolate});
  EXPECT_GT(distance(e, c.evaluate(1.0)), 0.0);
  std::vector<double> ts = {0.1, 0.2, -0.5};
  std::vector<Vec3> out(3);
  HULA_EXPECT_ERROR(c.evaluate(ts, out), Errc::OutOfDomain, "t[2]");
}

// checks: every constructor error names the offending field, index and value.
TEST(NurbsCurve, ConstructionErrorsNameTheInput) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}};
  const std::vector<double> U = {0, 0, 0, 0, 1, 1, 1, 1};
  HULA_EXPECT_ERROR(NurbsCurve(0, U, P), Errc::InvalidDegree, "degree = 0");
  HULA_EXPECT_ERROR(NurbsCurve(4, {0, 0, 0, 0, 0, 1, 1, 1, 1, 1}, P), Errc::InvalidDegree, "degree = 4");
  HULA_EXPECT_ERROR(NurbsCurve(3, {0, 0, 0, 1, 1, 1, 1}, P), Errc::InvalidKnots, "7 knots");
  HULA_EXPECT_ERROR(NurbsCurve(3, {0, 0, 0, 0, 1, 0.5, 1, 1}, P), Errc::InvalidKnots, "knots[5] = 0.5");
  HULA_EXPECT_ERROR(NurbsCurve(3, {0, 0, 0, 0, NAN, 1, 1, 1}, P), Errc::NonFiniteInput, "knots[4]");
  auto bad = P;
  bad[2].y = INFINITY;
  HULA_EXPECT_ERROR(NurbsCurve(3, U, bad), Errc::NonFiniteInput, "control_points[2][1]");
  HULA_EXPECT_ERROR(NurbsCurve(3, U, P, {1, 1, -2, 1}), Errc::InvalidWeight, "weights[2] = -2");
  HULA_EXPECT_ERROR(NurbsCurve(3, U, P, {1, 0, 1, 1}), Errc::InvalidWeight, "weights[1] = 0");
  HULA_EXPECT_ERROR(NurbsCurve(3, U, P, {1, 1, 1}), Errc::InvalidWeight, "3 weights");
  bad = P;
  bad[3].x = 1e305;
  HULA_EXPECT_ERROR(NurbsCurve(3, U, bad), Errc::ScaleOutOfRange, "control_points[3][0]");
  bad = P;
  bad[1].z = 0.5;
  HULA_EXPECT_ERROR(NurbsCurve(3, U, bad, {}, 2), Errc::InvalidArgument, "control_points[1]");
  try {
    (void)NurbsCurve(3, {0, 0, 0, 0, 1, 0.5, 1, 1}, P);
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "knots");
    EXPECT_EQ(e.where().index, 5u);
  }
}

// checks: evaluator argument errors name the argument (negative order, output span too small).
TEST(NurbsCurve, EvaluatorArgumentErrors) {
  const NurbsCurve c = testing::rational_circle(1.0);
  HULA_EXPECT_ERROR(c.derivatives(0.5, -1), Errc::InvalidArgument, "order = -1");
  std::vector<Vec3> small(2);
  HULA_EXPECT_ERROR(c.derivatives(0.5, 3, std::span<Vec3>(small)), Errc::InvalidArgument, "needs 4");
  const std::vector<double> ts = {0.1, 0.2};
  HULA_EXPECT_ERROR(c.derivatives(ts, 1, std::span<Vec3>(small)), Errc::InvalidArgument, "need 4");
  HULA_EXPECT_ERROR(c.derivatives(ts, -2, std::span<Vec3>(small)), Errc::InvalidArgument, "order = -2");
}

// checks: derivatives of order above the degree are exactly zero for polynomial curves and
// follow the quotient rule (non-zero) for rational ones.
TEST(NurbsCurve, HighOrderDerivatives) {
  const NurbsCurve line(1, {0, 0, 1, 1}, {{0, 0, 0}, {2, 4, 6}});
  const auto d = line.derivatives(0.3, 5);
  EXPECT_EQ(d[1], (Vec3{2, 4, 6}));
  for (std::size_t k = 2; k <= 5; ++k) EXPECT_EQ(d[k], Vec3{});
  // Circle x = cos θ with θ(t): fourth derivative is finite and non-zero.
  const auto r = testing::rational_circle(1.0).derivatives(0.1, 6);
  EXPECT_GT(norm(r[6]), 0.0);
}

}  // namespace
}  // namespace hula::nurbs
