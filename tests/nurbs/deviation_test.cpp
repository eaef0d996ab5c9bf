// SPDX-License-Identifier: MIT
// Curve-to-curve deviation (thesis 10.2.2 position distance) against closed
// forms: a curve against itself is 0, a translated copy is the translation in
// every statistic and axis, and the closest-point mode sees through a
// reparameterisation that the parameter mode reports.
#include "hula/nurbs/deviation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

NurbsCurve shifted_by(const NurbsCurve& c, const Vec3& d) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p += d;
  const auto U = c.knots().values();
  return NurbsCurve(c.degree(), std::vector<double>(U.begin(), U.end()), P,
                    std::vector<double>(c.weights().begin(), c.weights().end()));
}

// checks: deviation of random curves with themselves is exactly 0 (parameter mode) and at
// rounding level (closest mode).
TEST(Deviation, CurveAgainstItselfIsZero) {
  Rng rng(5);
  for (int i = 0; i < 10; ++i) {
    const NurbsCurve c = testing::random_curve(rng, {.degree = 1 + i % 5, .rational = i % 2 == 1});
    const DeviationResult r = deviation(c, c);
    EXPECT_EQ(r.max, 0.0);
    EXPECT_EQ(r.mean, 0.0);
    EXPECT_EQ(r.mean_axis, Vec3{});
    EXPECT_LE(deviation(c, c, {.samples = 101, .mode = DeviationMode::Closest}).max, 1e-12 * c.model_size());
  }
}

// checks: a copy translated by d = (3, -4, 12) (|d| = 13) deviates by 13 everywhere, with mean
// per-axis deviations (3, 4, 12), in both modes for a line-free random cubic.
TEST(Deviation, TranslationIsMeasuredExactlyPerAxis) {
  Rng rng(9);
  const NurbsCurve c = testing::random_curve(rng, {});
  const Vec3 d{3, -4, 12};
  const DeviationResult r = deviation(c, shifted_by(c, d), {.samples = 257});
  EXPECT_NEAR(r.max, 13.0, 1e-12);
  EXPECT_NEAR(r.mean, 13.0, 1e-12);
  EXPECT_NEAR(r.rms, 13.0, 1e-12);
  EXPECT_NEAR(r.mean_axis.x, 3.0, 1e-12);
  EXPECT_NEAR(r.mean_axis.y, 4.0, 1e-12);
  EXPECT_NEAR(r.max_axis.z, 12.0, 1e-12);
  EXPECT_EQ(r.samples, 257U);
}

// checks: the same curve on another domain is 0 in both modes (normalised parameters), and
// the options are validated.
TEST(Deviation, NormalisedParametersAndErrors) {
  Rng rng(2);
  const NurbsCurve c = testing::random_curve(rng, {});
  const NurbsCurve moved = reparameterise(c, Interval{-7, 40});
  EXPECT_LE(deviation(c, moved).max, 1e-12 * c.model_size());
  HULA_EXPECT_ERROR((void)deviation(c, c, {.samples = 1}), Errc::InvalidOption, "samples = 1");
}

}  // namespace
}  // namespace hula::nurbs
