// SPDX-License-Identifier: MIT
#include "hula/studies/curvature_torsion_match.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "hula/testing/counting_allocator.hpp"
#include "hula/testing/expect_error.hpp"

namespace {

using hula::Errc;
using hula::Vec3;
using hula::studies::CurvatureMatch;
using hula::studies::CurvatureMatchSetup;
using hula::studies::Profile;
using hula::studies::SplineProfileSampler;

// Points on a helix of radius 10 and pitch 2π·4: κ and τ both non-zero everywhere on the spline.
std::vector<Vec3> helix_points(std::size_t n) {
  std::vector<Vec3> p(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 1.6 * static_cast<double>(k) / static_cast<double>(n - 1) * M_PI;
    p[k] = {10 * std::sin(a), 10 * (1 - std::cos(a)), 4 * a};
  }
  return p;
}

// A matching problem whose targets are the κ(u) and τ(u) of the spline through `truth`, started from a
// perturbed copy with every coordinate of the points after the first free within ±3.
CurvatureMatch known_curve_problem(const std::vector<Vec3>& truth, std::size_t samples) {
  const auto u = hula::studies::uniform_abscissae(samples);
  // Clamped at both ends: a natural end has κ = 0 there and τ undefined.
  const Vec3 end_tangent{10 * std::cos(1.6 * M_PI), 10 * std::sin(1.6 * M_PI), 4};
  const SplineProfileSampler sampler(truth.size(), 3, u, Vec3{1, 0, 0}, end_tangent);
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(samples), tau(samples);
  EXPECT_TRUE(sampler.sample(truth, ws, kappa, tau));
  CurvatureMatchSetup s;
  s.dimension = 3;
  s.points = truth;
  const Vec3 shift[] = {{0, 0, 0}, {0.8, -0.6, 0.5}, {-0.7, 0.9, -0.4}, {0.6, 0.5, -0.8}, {-0.5, -0.7, 0.6}};
  for (std::size_t k = 0; k < truth.size(); ++k) s.points[k] = truth[k] + shift[k % 5];
  s.lower.assign(truth.size(), Vec3{3, 3, 3});
  s.upper.assign(truth.size(), Vec3{3, 3, 3});
  s.lower[0] = s.upper[0] = Vec3{0, 0, 0};
  s.start_tangent = Vec3{1, 0, 0};
  s.end_tangent = end_tangent;
  s.samples = samples;
  s.target = Profile::from_samples(u, kappa);
  s.torsion_target = Profile::from_samples(u, tau);
  return CurvatureMatch(std::move(s));
}

TEST(CurvatureTorsionMatch, ObjectivesVanishOnTheKnownCurveAndAllocateNothing) {
  const auto truth = helix_points(5);
  const CurvatureMatch match = known_curve_problem(truth, 200);
  std::vector<double> x;
  for (std::size_t k = 1; k < truth.size(); ++k)
    for (int c = 0; c < 3; ++c) x.push_back(truth[k][c]);
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> points(truth.size());
  std::vector<double> kappa(200), tau(200);
  auto d = match.mean_distances(x, ws, points, kappa, tau);
  EXPECT_LT(d.mean, 1e-14);
  EXPECT_LT(d.torsion_mean, 1e-13);
  const std::vector<double> start = match.start_variables();
  const long before = hula::testing::allocation_count();
  d = match.mean_distances(start, ws, points, kappa, tau);
  EXPECT_EQ(hula::testing::allocation_count(), before);
  EXPECT_GT(d.mean, 1e-3);
  EXPECT_GT(d.torsion_mean, 1e-3);
  // The Flexo problem's objectives are the same two numbers.
  const hula::optim::Problem p = hula::studies::curvature_torsion_problem(match);
  std::vector<double> values(2);
  p.evaluate(start, values);
  EXPECT_EQ(values[0], d.mean);
  EXPECT_EQ(values[1], d.torsion_mean);
}

// Issue 6: on a space curve whose κ and τ are both prescribed from a known curve, the Pareto set contains a
// curve that matches both within 1e-3.
TEST(CurvatureTorsionMatch, ParetoSetContainsACurveMatchingBoth) {
  const auto truth = helix_points(5);
  const CurvatureMatch match = known_curve_problem(truth, 200);
  hula::studies::TorsionMatchSettings settings;
  settings.population = 60;
  settings.generations = 120;
  const auto result = hula::studies::run_curvature_torsion_match(match, settings, 7);
  ASSERT_FALSE(result.front.empty());
  for (std::size_t i = 1; i < result.front.size(); ++i) {
    EXPECT_LE(result.front[i - 1].curvature, result.front[i].curvature);
    // Non-dominated: sorted by curvature error, torsion error must not increase along it.
    EXPECT_GE(result.front[i - 1].torsion, result.front[i].torsion);
  }
  const auto& best = result.front[result.compromise];
  std::printf("NSGA-II + polish: compromise %.3g / %.3g (polished %d), front %zu\n", best.curvature, best.torsion,
              static_cast<int>(best.polished), result.front.size());
  EXPECT_TRUE(best.polished);
  EXPECT_LT(best.curvature, 1e-3);
  EXPECT_LT(best.torsion, 1e-3);
  EXPECT_LT(std::max(best.curvature, best.torsion), 0.01 * std::max(result.start_curvature, result.start_torsion));
  ASSERT_EQ(result.best_curvature.size(), settings.generations + 1);
  // NSGA-II's own front is kept: a spread of trade-offs, each with both errors.
  ASSERT_GT(result.nsga2_front.size(), 5u);
  for (std::size_t i = 1; i < result.nsga2_front.size(); ++i) {
    EXPECT_LE(result.nsga2_front[i - 1].curvature, result.nsga2_front[i].curvature);
    EXPECT_GE(result.nsga2_front[i - 1].torsion, result.nsga2_front[i].torsion);
  }
}

// checks: with boxes of ±0.5 around a start moved by up to 0.9 from the known helix (closed-form truth outside the
// first box), the re-centred rounds (thesis 7.4.1) centre each box on the previous round's best compromise with the
// same widths and end with a compromise matching both profiles to 1e-3; the map's nodes are both objectives at those
// designs (CurvatureMatch::distances evaluated here).
TEST(CurvatureTorsionMatch, RecentredRoundsAndMap) {
  const auto truth = helix_points(5);
  CurvatureMatchSetup s = known_curve_problem(truth, 100).setup();
  for (std::size_t k = 1; k < s.points.size(); ++k) s.lower[k] = s.upper[k] = Vec3{0.5, 0.5, 0.5};
  const CurvatureMatch match(s);
  hula::studies::TorsionMatchSettings settings;
  settings.population = 40;
  settings.generations = 40;
  settings.max_recentres = 6;
  hula::studies::MatchMapSettings m;
  m.variables = {"points[1].x", "points[2].z"};
  m.grid = 3;
  settings.map = m;
  const auto r = hula::studies::run_curvature_torsion_match(match, settings, 3);
  ASSERT_GE(r.rounds.size(), 2U);
  EXPECT_FALSE(r.rounds.front().on_bound.empty());
  for (std::size_t k = 1; k < r.rounds.size(); ++k)
    for (std::size_t j = 0; j < match.dimension(); ++j) {
      EXPECT_NEAR(r.rounds[k].variables[j].lower, r.rounds[k - 1].best[j] - 0.5, 1e-12);
      EXPECT_NEAR(r.rounds[k].variables[j].upper, r.rounds[k - 1].best[j] + 0.5, 1e-12);
    }
  const auto& best = r.front[r.compromise];
  EXPECT_EQ(best.variables, r.rounds.back().best);
  EXPECT_LT(best.curvature, 1e-3);
  EXPECT_LT(best.torsion, 1e-3);
  EXPECT_DOUBLE_EQ(r.start_curvature, match.distances(match.start_variables()).mean);
  ASSERT_TRUE(r.map.has_value());
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t col = 0; col < 3; ++col) {
      std::vector<double> x = best.variables;
      x[0] = r.map->x_values[col];
      x[5] = r.map->y_values[row];
      const auto d = match.distances(x);
      EXPECT_NEAR(r.map->values[(row * 3 + col) * 2], d.mean, 1e-12);
      EXPECT_NEAR(r.map->values[(row * 3 + col) * 2 + 1], d.torsion_mean, 1e-12);
    }
}

TEST(CurvatureTorsionMatch, PlanarOrTorsionlessProblemsAreRefused) {
  CurvatureMatchSetup s;
  s.dimension = 3;
  s.points = {{0, 0, 0}, {10, 5, 1}, {20, 0, 3}};
  s.lower.assign(3, Vec3{1, 1, 1});
  s.upper.assign(3, Vec3{1, 1, 1});
  s.lower[0] = s.upper[0] = Vec3{0, 0, 0};
  const std::vector<double> u = {0, 1}, v = {0.1, 0.1};
  s.target = Profile::from_samples(u, v);
  const CurvatureMatch no_tau(s);
  HULA_EXPECT_ERROR(hula::studies::curvature_torsion_problem(no_tau), Errc::InvalidArgument, "torsion target");
  hula::studies::TorsionMatchSettings bad;
  bad.population = 5;
  s.torsion_target = Profile::from_samples(u, v);
  const CurvatureMatch with_tau(s);
  HULA_EXPECT_ERROR(hula::studies::run_curvature_torsion_match(with_tau, bad, 1), Errc::InvalidOption,
                    "nsga2.population");
}

}  // namespace

namespace {
// NSGA-II alone (no polish) moves the front towards the known curve: over seeds 1-5, the median of its best
// compromise's improvement on each error is at least 3 times (the polish does the rest). One seed is not a claim
// about the algorithm: over seeds 1-80 the curvature improvement ranged 3.0-15x (2.5-26x after issue 27's
// operators), below 5x for 25 (31) seeds, and the median of five consecutive seeds never fell below 4.0x (3.8x).
TEST(CurvatureTorsionMatch, Nsga2AloneApproachesTheKnownCurve) {
  const auto truth = helix_points(5);
  const CurvatureMatch match = known_curve_problem(truth, 200);
  hula::studies::TorsionMatchSettings settings;
  settings.population = 60;
  settings.generations = 120;
  settings.polish = false;
  std::vector<double> curvature_gain, torsion_gain;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto result = hula::studies::run_curvature_torsion_match(match, settings, seed);
    ASSERT_FALSE(result.front.empty());
    EXPECT_FALSE(result.lm.has_value());
    const auto& best = result.front[result.compromise];
    std::printf("NSGA-II alone, seed %llu: start %.3g / %.3g, compromise %.3g / %.3g, front %zu\n",
                static_cast<unsigned long long>(seed), result.start_curvature, result.start_torsion, best.curvature,
                best.torsion, result.front.size());
    curvature_gain.push_back(result.start_curvature / best.curvature);
    torsion_gain.push_back(result.start_torsion / best.torsion);
  }
  std::sort(curvature_gain.begin(), curvature_gain.end());
  std::sort(torsion_gain.begin(), torsion_gain.end());
  EXPECT_GT(curvature_gain[2], 3.0);
  EXPECT_GT(torsion_gain[2], 3.0);
}
}  // namespace
