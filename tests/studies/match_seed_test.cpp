// SPDX-License-Identifier: MIT
// Tests of matching setups seeded from a curve ("From selection", issue 21 item 5) against closed forms: a helix
// r(t) = (10 cos t, 10 sin t, 2t) has κ = 10/104, τ = 2/104 and T(0) = (0, 10, 2)/√104; points at uniform arc length
// are at uniform t. An interpolated curve gives its own points; a planar one a planar setup without torsion; the
// seeded spline starts close to its targets.
#include "hula/studies/match_seed.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

curve::Curve helix() { return curve::Curve::from_law("vec(10*cos(t), 10*sin(t), 2*t)", "t", {0.0, 3.0}); }

// checks: the helix's end tangents, points (closed form at uniform t) and constant κ, τ targets.
TEST(MatchSeed, HelixClosedForms) {
  const MatchSeed seed = seed_match_setup(helix(), {.points = 7});
  const CurvatureMatchSetup& s = seed.setup;
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.abscissa, ProfileAbscissa::ArcLength);
  const double c = std::sqrt(104.0);
  EXPECT_LT(distance(*s.start_tangent, Vec3{0, 10 / c, 2 / c}), 1e-6);
  EXPECT_LT(distance(*s.end_tangent, Vec3{-10 * std::sin(3.0) / c, 10 * std::cos(3.0) / c, 2 / c}), 1e-6);
  ASSERT_EQ(s.points.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    const double t = 3.0 * static_cast<double>(i) / 6.0;
    EXPECT_LT(distance(s.points[i], Vec3{10 * std::cos(t), 10 * std::sin(t), 2 * t}), 1e-5) << i;
  }
  for (std::size_t i = 0; i < seed.u.size(); ++i) {
    EXPECT_NEAR(seed.curvature[i], 10.0 / 104.0, 1e-4 * 10.0 / 104.0) << i;
    EXPECT_NEAR(seed.torsion[i], 2.0 / 104.0, 1e-3 * 2.0 / 104.0) << i;
  }
  EXPECT_NEAR((*s.target)(0.5), 10.0 / 104.0, 1e-4 * 10.0 / 104.0);
  EXPECT_NEAR((*s.torsion_target)(0.5), 2.0 / 104.0, 1e-3 * 2.0 / 104.0);
  // Bounds: the first point fixed, the others ± 0.1 × the size.
  EXPECT_EQ(s.lower[0], Vec3{});
  EXPECT_GT(s.upper[3].x, 0.0);
  // The spline through the seed starts close to its own targets (a few % of κ).
  const CurvatureMatch match(s);
  const MatchDistances d = match.distances(match.start_variables());
  EXPECT_LT(d.mean, 0.05 * 10.0 / 104.0);
  EXPECT_LT(d.torsion_mean, 0.2 * 2.0 / 104.0);
}

// checks: an interpolated planar curve gives its own data points, a planar setup (no torsion target, z fixed).
TEST(MatchSeed, InterpolatedPlanarCurveKeepsItsPoints) {
  curve::InterpolatedData data;
  data.points = {{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}};
  data.dimension = 2;
  const MatchSeed seed = seed_match_setup(curve::Curve::interpolated(data));
  EXPECT_EQ(seed.setup.points, data.points);
  EXPECT_EQ(seed.setup.dimension, 2);
  EXPECT_FALSE(seed.setup.torsion_target.has_value());
  EXPECT_TRUE(seed.torsion.empty());
  EXPECT_EQ(seed.setup.upper[2].z, 0.0);
}

// checks: bad options name their field.
TEST(MatchSeed, RejectsBadOptions) {
  HULA_EXPECT_ERROR(static_cast<void>(seed_match_setup(helix(), {.points = 1})), Errc::InvalidOption, "points");
  HULA_EXPECT_ERROR(static_cast<void>(seed_match_setup(helix(), {.bound = 0.0})), Errc::InvalidOption, "bound");
}

}  // namespace
}  // namespace hula::studies
