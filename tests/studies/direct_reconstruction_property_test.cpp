// SPDX-License-Identifier: MIT
// Property tests of direct reconstruction on seeded random planar cubic Bézier
// curves (x-monotone control polygons, so no cusps): the curve is recovered
// from its own tabulated curvature; held to its own end it needs (almost) no
// correction; held to a moved end it meets it, and the minimum-norm correction
// never grows when the correction space grows (Bernstein degree n ⊂ n + 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/studies/direct_reconstruction.hpp"
#include "hula/testing/curvature_target.hpp"

namespace hula::studies {
namespace {

constexpr int kCases = 8;
constexpr std::uint64_t kSeed = 20261123;

nurbs::NurbsCurve random_bezier(Rng& rng) {
  std::vector<Vec3> p{{0.0, 0.0, 0.0}};
  for (int i = 1; i <= 3; ++i)
    p.push_back({static_cast<double>(i) + rng.uniform(-0.3, 0.3), rng.uniform(-1.0, 1.0), 0.0});
  return nurbs::NurbsCurve(3, {0, 0, 0, 0, 1, 1, 1, 1}, p);
}

// ‖δκ‖_{L²(0,1)} of Bernstein coefficients, by the midpoint rule on 4000 cells (exact enough for
// a comparison with slack 1e-6).
double l2_norm(const std::vector<double>& c) {
  const int n = static_cast<int>(c.size()) - 1;
  double sum = 0.0;
  constexpr int kCells = 4000;
  for (int i = 0; i < kCells; ++i) {
    const double u = (i + 0.5) / kCells;
    double v = 0.0;
    for (int k = 0; k <= n; ++k) {
      double b = 1.0;
      for (int j = 1; j <= k; ++j) b = b * (n - k + j) / j;
      v += c[static_cast<std::size_t>(k)] * b * std::pow(u, k) * std::pow(1.0 - u, n - k);
    }
    sum += v * v;
  }
  return std::sqrt(sum / kCells);
}

// property: for random Béziers, IVP recovery within 1e-5 L; own end met with correction < 1e-4;
// a moved end (tangent turned 0.05 rad, point shifted 1% of L) met to 1e-9 L, with an L² correction
// norm that does not grow from degree 5 to degree 7.
TEST(DirectReconstructionProperty, RandomBeziers) {
  Rng rng(kSeed);
  DirectReconstructionOptions o;
  o.fit = false;
  for (int c = 0; c < kCases; ++c) {
    SCOPED_TRACE("case " + std::to_string(c) + " of seed " + std::to_string(kSeed));
    const nurbs::NurbsCurve bez = random_bezier(rng);
    const hula::testing::CurvatureTarget t = hula::testing::planar_curvature_target(bez, 201);
    const double L = t.length;
    const DirectReconstructionResult ivp =
        reconstruct_direct({.curvature = t.profile, .length = L, .start = t.start}, o);
    EXPECT_LT(hula::testing::max_distance_at_equal_length(ivp.curve, bez, 40), 1e-5 * L);

    const DirectReconstructionResult own = reconstruct_direct(
        {.curvature = t.profile, .length = L, .start = t.start, .end_point = t.end_point, .end_tangent = t.end_tangent},
        o);
    EXPECT_LE(own.end_point_error, 1e-9 * L);
    EXPECT_LE(own.end_tangent_error, 1e-9);
    EXPECT_LT(own.max_curvature_deviation, 1e-4);

    const double turn = 0.05;
    const Vec3 moved_tangent{t.end_tangent.x * std::cos(turn) - t.end_tangent.y * std::sin(turn),
                             t.end_tangent.x * std::sin(turn) + t.end_tangent.y * std::cos(turn), 0.0};
    const Vec3 moved_point = t.end_point + Vec3{-0.006, 0.008, 0.0} * L;
    const DirectReconstructionProblem moved{
        .curvature = t.profile, .length = L, .start = t.start, .end_point = moved_point, .end_tangent = moved_tangent};
    const DirectReconstructionResult r5 = reconstruct_direct(moved, o);
    DirectReconstructionOptions o7 = o;
    o7.correction_degree = 7;
    const DirectReconstructionResult r7 = reconstruct_direct(moved, o7);
    EXPECT_LE(r5.end_point_error, 1e-9 * L);
    EXPECT_LE(r5.end_tangent_error, 1e-9);
    EXPECT_LE(r7.end_point_error, 1e-9 * L);
    EXPECT_GT(r5.mean_curvature_deviation, 1e-4);
    EXPECT_LE(l2_norm(r7.curvature_correction), l2_norm(r5.curvature_correction) * (1.0 + 1e-6));
  }
}

}  // namespace
}  // namespace hula::studies
