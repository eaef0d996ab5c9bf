// SPDX-License-Identifier: MIT
// nurbs::cubic_beziers: exact cubic pieces of non-rational curves of degree ≤ 3 (each piece equals the curve
// on its knot span, checked by evaluating both), tolerance-bounded pieces of rational and high-degree curves
// (checked against the closed form |C| = R of a rational circle and against closest points), bad tolerances.
#include "hula/nurbs/cubic_bezier.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

Vec3 at(const CubicPiece& p, double x) {
  const double y = 1 - x;
  return p.points[0] * (y * y * y) + p.points[1] * (3 * y * y * x) + p.points[2] * (3 * y * x * x) +
         p.points[3] * (x * x * x);
}

// checks: for random non-rational curves of degree 1, 2 and 3 every piece is the curve on its span (evaluated at
// 21 points each), the pieces chain end to start, and the path says it is exact
TEST(CubicBeziers, NonRationalUpToCubicIsExact) {
  Rng rng(77);
  for (int degree = 1; degree <= 3; ++degree) {
    for (int trial = 0; trial < 5; ++trial) {
      const NurbsCurve c = testing::random_curve(rng, {.degree = degree, .clamped = trial % 2 == 0});
      const CubicPath path = cubic_beziers(c, 1e-6);
      EXPECT_TRUE(path.exact);
      EXPECT_EQ(path.max_deviation, 0.0);
      ASSERT_FALSE(path.pieces.empty());
      EXPECT_EQ(path.pieces.front().start, c.domain().start);
      EXPECT_EQ(path.pieces.back().end, c.domain().end);
      for (std::size_t k = 0; k < path.pieces.size(); ++k) {
        const CubicPiece& p = path.pieces[k];
        if (k > 0) {
          EXPECT_EQ(p.start, path.pieces[k - 1].end);
        }
        for (int s = 0; s <= 20; ++s) {
          const double x = s / 20.0;
          EXPECT_LT(distance(at(p, x), c.evaluate(p.start + x * (p.end - p.start))), 1e-12 * (1 + c.model_size()))
              << "degree " << degree << " piece " << k << " x " << x;
        }
      }
    }
  }
}

// checks: a rational circle of radius 3 comes out within the tolerance of the closed form |B(x)| = 3 (200 samples
// a piece, not only the 16 the approximation measures), and tighter tolerances give more pieces
TEST(CubicBeziers, RationalCircleWithinToleranceOfTheClosedForm) {
  const NurbsCurve circle = testing::rational_circle(3.0, 0.2);
  std::size_t previous = 0;
  for (double tolerance : {1e-3, 1e-6, 1e-9}) {
    const CubicPath path = cubic_beziers(circle, tolerance);
    EXPECT_FALSE(path.exact);
    EXPECT_LE(path.max_deviation, tolerance);
    EXPECT_GT(path.pieces.size(), previous);
    previous = path.pieces.size();
    for (const CubicPiece& p : path.pieces)
      for (int s = 0; s <= 200; ++s)
        EXPECT_LE(std::abs(norm(at(p, s / 200.0)) - 3.0), tolerance) << "tolerance " << tolerance;
  }
}

// checks: a quintic (no cubic form) is approximated within the tolerance of the curve (closest-point distance)
TEST(CubicBeziers, QuinticWithinToleranceOfTheCurve) {
  Rng rng(78);
  const NurbsCurve c = testing::random_curve(rng, {.degree = 5, .rational = true});
  const CubicPath path = cubic_beziers(c, 1e-7);
  EXPECT_FALSE(path.exact);
  for (const CubicPiece& p : path.pieces)
    for (int s = 0; s <= 40; ++s) EXPECT_LE(closest_point(c, at(p, s / 40.0)).distance, 1e-7);
}

// checks: a tolerance that is not finite and > 0 is refused naming it
TEST(CubicBeziers, RefusesBadTolerance) {
  const NurbsCurve circle = testing::rational_circle(1.0);
  HULA_EXPECT_ERROR(cubic_beziers(circle, 0.0), Errc::InvalidArgument, "tolerance = 0");
  HULA_EXPECT_ERROR(cubic_beziers(circle, std::nan("")), Errc::InvalidArgument, "tolerance");
}

}  // namespace
}  // namespace hula::nurbs
