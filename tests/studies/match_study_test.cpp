// SPDX-License-Identifier: MIT
// The thesis's validation method (8.2.1): a target profile taken from a known
// curve must be recovered. GA alone to the thesis's accuracy (Table 9), the
// hybrid GA + Levenberg-Marquardt to 1e-6 in mean curvature distance with
// 4, 9, 20 and 50 free coordinates.
#include "hula/studies/match_study.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"

namespace {

using hula::Errc;
using hula::Vec3;
using hula::studies::CurvatureMatch;
using hula::studies::CurvatureMatchSetup;
using hula::studies::MatchMethod;
using hula::studies::MatchStudy;
using hula::studies::Profile;

// A known curve through `truth`; the first `free` coordinates after the start point are moved by up to `delta`
// (seeded) and bounded by `bound` around the moved start value; the target is the known curve's profile.
CurvatureMatchSetup known_curve_setup(const std::vector<Vec3>& truth, int dim, std::size_t free, double delta,
                                      double bound, std::uint64_t seed, std::optional<Vec3> start_tangent) {
  CurvatureMatchSetup s;
  s.dimension = dim;
  s.points = truth;
  s.lower.assign(truth.size(), Vec3{});
  s.upper.assign(truth.size(), Vec3{});
  s.start_tangent = start_tangent;
  hula::Rng rng(seed);
  std::size_t k = 0;
  for (std::size_t i = 1; i < truth.size() && k < free; ++i)
    for (std::size_t c = 0; c < static_cast<std::size_t>(dim) && k < free; ++c, ++k) {
      s.points[i][c] += rng.uniform(-delta, delta);
      s.lower[i][c] = bound;
      s.upper[i][c] = bound;
    }
  s.target = Profile::from_samples(hula::studies::uniform_abscissae(200),
                                   hula::studies::curvature_profile_of(truth, dim, 200, start_tangent, std::nullopt));
  return s;
}

std::vector<Vec3> planar_wave(std::size_t n) {
  std::vector<Vec3> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n - 1);
    p[i] = {40.0 * s, 12.0 * std::sin(2.5 * s) + 3.0 * s * s, 0.0};
  }
  return p;
}

// A convex planar arc without inflection (turning angle 1.5 s + s^2 over length 40): unsigned κ then determines
// the curve (at an inflection the unsigned profile cannot tell a curve from its reflection, which with a fixed end
// point leaves spurious local minima).
std::vector<Vec3> convex_arc(std::size_t n) {
  std::vector<Vec3> p(n);
  Vec3 q{0, 0, 0};
  const int steps = 400;
  std::size_t next = 1;
  p[0] = q;
  for (int k = 0; k < steps; ++k) {
    const double s0 = static_cast<double>(k) / steps, s1 = static_cast<double>(k + 1) / steps;
    const double sm = 0.5 * (s0 + s1);
    auto theta = [](double s) { return 1.5 * s + s * s; };
    // Simpson on [s0, s1] of 40 (cos θ, sin θ) ds.
    const double w = 40.0 * (s1 - s0) / 6.0;
    q.x += w * (std::cos(theta(s0)) + 4.0 * std::cos(theta(sm)) + std::cos(theta(s1)));
    q.y += w * (std::sin(theta(s0)) + 4.0 * std::sin(theta(sm)) + std::sin(theta(s1)));
    if (next < n && (k + 1) * static_cast<int>(n - 1) == static_cast<int>(next) * steps) p[next++] = q;
  }
  return p;
}

std::vector<Vec3> space_wave(std::size_t n) {
  std::vector<Vec3> p = planar_wave(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n - 1);
    p[i].z = 8.0 * s * s - 2.0 * std::sin(3.0 * s);
  }
  return p;
}

MatchStudy ga_study(MatchMethod method) {
  MatchStudy st;
  st.method = method;
  st.header.seed = 7;
  st.ga.population = 50;
  st.ga.generations = 50;
  return st;
}

// Hybrid: GA then LM reaches 1e-6 in mean curvature distance with start point and tangent fixed.
void expect_hybrid_recovers(const std::vector<Vec3>& truth, int dim, std::size_t free, double move) {
  // Start points moved by up to `move` x the point spacing, bounds of 5 x that: the known curve lies inside.
  const double spacing = 40.0 / static_cast<double>(truth.size() - 1);
  const Vec3 tangent = truth[1] - truth[0];
  const CurvatureMatch match(known_curve_setup(truth, dim, free, move * spacing, 5.0 * move * spacing, 11, tangent));
  ASSERT_EQ(match.dimension(), free);
  MatchStudy st = ga_study(MatchMethod::Hybrid);
  st.ga.generations = 20;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = hula::studies::run_curvature_match(match, st);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("hybrid %zu variables: before %.3g after GA %.3g after LM %.3g (%zu LM steps, %.3f s)\n", free,
              r.before.mean, r.after_ga.mean, r.after.mean, r.lm->iterations, seconds);
  EXPECT_GT(r.before.mean, 1e-3);
  EXPECT_LE(r.after.mean, 1e-6) << free << " variables, LM " << r.lm->message;
  EXPECT_LE(r.after.mean, r.after_ga.mean);
}

// 4 and 9 free coordinates from starts 15% of the spacing away; 20 and 50 from 2% (far starts, 15 %:
// FarStartReaches1e6With20Variables, FarStartReaches1e6With35Variables, ...With50Variables).
TEST(MatchHybrid, Recovers4Variables) { expect_hybrid_recovers(planar_wave(4), 2, 4, 0.15); }
TEST(MatchHybrid, Recovers9Variables) { expect_hybrid_recovers(space_wave(4), 3, 9, 0.15); }
TEST(MatchHybrid, Recovers20Variables) { expect_hybrid_recovers(convex_arc(11), 2, 20, 0.02); }
TEST(MatchHybrid, Recovers50Variables) { expect_hybrid_recovers(convex_arc(26), 2, 50, 0.02); }

// A seeded convex planar arc of length 40 (turning angle a s + b s², a in [1, 1.8], b in [0.3, 1.2]) through n
// points equally spaced in arc length: the far-start targets (issue 14 item 1).
std::vector<Vec3> seeded_arc(std::size_t n, std::uint64_t seed) {
  hula::Rng rng(seed);
  const double a = rng.uniform(1.0, 1.8), b = rng.uniform(0.3, 1.2);
  std::vector<Vec3> p(n);
  Vec3 q{0, 0, 0};
  const int per = 40;
  const int steps = per * static_cast<int>(n - 1);
  p[0] = q;
  auto theta = [&](double s) { return a * s + b * s * s; };
  for (int k = 0; k < steps; ++k) {
    const double s0 = static_cast<double>(k) / steps, s1 = static_cast<double>(k + 1) / steps;
    const double sm = 0.5 * (s0 + s1);
    const double w = 40.0 * (s1 - s0) / 6.0;
    q.x += w * (std::cos(theta(s0)) + 4.0 * std::cos(theta(sm)) + std::cos(theta(s1)));
    q.y += w * (std::sin(theta(s0)) + 4.0 * std::sin(theta(sm)) + std::sin(theta(s1)));
    if ((k + 1) % per == 0) p[static_cast<std::size_t>((k + 1) / per)] = q;
  }
  return p;
}

struct FarStart {
  double before = 0.0, after = 0.0;
  std::size_t iterations = 0, evaluations = 0;
  std::string termination, start;
};

// The hybrid from a start 15 % of the point spacing away (every coordinate after the start point free, bounds of
// 5 x that), `free` variables, target and start from `seed`.
FarStart far_start(std::size_t free, std::uint64_t seed, hula::studies::LmOptions lm, std::size_t generations) {
  const std::size_t n = (free + 1) / 2 + 1;
  const std::vector<Vec3> truth = seeded_arc(n, seed);
  const double spacing = 40.0 / static_cast<double>(n - 1);
  const Vec3 tangent = truth[1] - truth[0];
  const CurvatureMatch match(known_curve_setup(truth, 2, free, 0.15 * spacing, 0.75 * spacing, 100 + seed, tangent));
  MatchStudy st = ga_study(MatchMethod::Hybrid);
  st.ga.generations = generations;
  st.lm = lm;
  const auto r = hula::studies::run_curvature_match(match, st);
  return {r.before.mean, r.after.mean, r.lm->iterations, r.lm->evaluations, r.lm->message, r.lm_start};
}

// checks: from starts 15 % of the point spacing away with 20 free variables, on five seeded known convex arcs, the
// hybrid (GA, then Ceres from the direct start) reaches 1e-6 mean curvature distance of the known curve's profile.
TEST(MatchHybrid, FarStartReaches1e6With20Variables) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const FarStart f = far_start(20, seed, {}, 10);
    EXPECT_GT(f.before, 1e-2) << "seed " << seed;
    EXPECT_LE(f.after, 1e-6) << "seed " << seed << ": " << f.termination;
    EXPECT_EQ(f.start, "direct") << "seed " << seed;
  }
}

// Far starts with 35 or 50 free variables on five seeded known convex arcs: the hybrid reaches 1e-6 mean curvature
// distance of the known curve's profile from the direct start through the data parameters read off the target
// (spline_profile_breaks), its length found by the scan and, with 50 (the end free to slide along the curve), by
// the golden-section search over refined lengths.
void expect_far_start_reaches_1e6(std::size_t free) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const FarStart f = far_start(free, seed, {}, 10);
    EXPECT_GT(f.before, 1e-2) << free << " variables, seed " << seed;
    EXPECT_LE(f.after, 1e-6) << free << " variables, seed " << seed << ": " << f.termination;
    EXPECT_EQ(f.start, "direct") << free << " variables, seed " << seed;
  }
}

// checks: 35 variables from 15 % far starts reach 1e-6 on five seeded known arcs.
TEST(MatchHybrid, FarStartReaches1e6With35Variables) { expect_far_start_reaches_1e6(35); }
// checks: 50 variables from 15 % far starts reach 1e-6 on five seeded known arcs.
TEST(MatchHybrid, FarStartReaches1e6With50Variables) { expect_far_start_reaches_1e6(50); }

// checks: with an arc-length target (the profile over normalised arc length, abscissa "arclength": central
// differences, no exact Jacobian) the data parameters read off it are arc-length fractions, and 20 variables from 15 %
// far starts on two seeded arcs still reach 1e-6 from the direct start.
TEST(MatchHybrid, FarStartArcLengthTargetReaches1e6) {
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    const std::vector<Vec3> truth = seeded_arc(11, seed);
    const Vec3 tangent = truth[1] - truth[0];
    CurvatureMatchSetup s = known_curve_setup(truth, 2, 20, 0.15 * 4.0, 0.75 * 4.0, 100 + seed, tangent);
    s.abscissa = hula::studies::ProfileAbscissa::ArcLength;
    s.target = Profile::from_samples(hula::studies::uniform_abscissae(200),
                                     hula::studies::curvature_profile_of(truth, 2, 200, tangent, std::nullopt,
                                                                         hula::studies::ProfileAbscissa::ArcLength));
    const CurvatureMatch match(s);
    MatchStudy st = ga_study(MatchMethod::Hybrid);
    st.ga.generations = 10;
    const auto r = hula::studies::run_curvature_match(match, st);
    EXPECT_GT(r.before.mean, 1e-2) << "seed " << seed;
    EXPECT_LE(r.after.mean, 1e-6) << "seed " << seed << ": " << r.lm->message;
    EXPECT_EQ(r.lm_start, "direct") << "seed " << seed;
  }
}

// checks: on the 20-variable far starts, the exact Jacobian (default) and central differences both reach 1e-6
// from the direct start, the exact one with at most half the residual evaluations (one per Jacobian instead of
// 2 x 20 + 1).
TEST(MatchHybrid, FarStartExactJacobianNeedsFewerEvaluations) {
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    hula::studies::LmOptions differences;
    differences.exact_jacobian = false;
    const FarStart exact = far_start(20, seed, {}, 10), fd = far_start(20, seed, differences, 10);
    EXPECT_LE(exact.after, 1e-6) << "seed " << seed;
    EXPECT_LE(fd.after, 1e-6) << "seed " << seed;
    EXPECT_LE(2 * exact.evaluations, fd.evaluations) << "seed " << seed;
  }
}

// The table of docs/studies.md ("Far starts", issue 14): both solvers, with and without the direct start, 20/35/50
// variables x 5 seeds; it prints, it checks nothing (the checks are above). Run by hand:
// test_studies_match_study --gtest_also_run_disabled_tests --gtest_filter=*FarStartTable
TEST(MatchHybrid, DISABLED_FarStartTable) {
  std::printf(
      "| variables | seed | start mean | clamped LM | it | Ceres | it | clamped LM + direct start | it | Ceres + "
      "direct start | it |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::size_t free : {20, 35, 50})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      std::printf("| %zu | %lu |", free, static_cast<unsigned long>(seed));
      bool first = true;
      for (const bool direct : {false, true})
        for (const auto solver : {hula::studies::LsqSolver::ClampedLm, hula::studies::LsqSolver::Ceres}) {
          hula::studies::LmOptions lm;
          lm.solver = solver;
          lm.direct_start = direct;
          const FarStart f = far_start(free, seed, lm, 10);
          if (first) std::printf(" %.3g |", f.before);
          first = false;
          std::printf(" %.2g | %zu |", f.after, f.iterations);
        }
      std::printf("\n");
    }
}

// Table 9 (GA performance against the number of variables: best 0.08, 0.1, 0.9, 10 for 2, 4, 6, 9), on targets
// from known curves: our binary GA (thesis settings: 50 x 50, roulette, boost 3 -> 5) must do at least as well.
struct Table9Case {
  std::vector<Vec3> truth;
  int dim;
  std::size_t free;
  double thesis;
};

TEST(MatchGa, ReachesTable9AccuracyInWellUnderASecond) {
  const std::vector<Table9Case> cases = {
      {{{0, 0, 0}, {5, 20, 0}, {40, 0, 0}}, 2, 2, 0.08},
      {{{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2, 4, 0.1},
      {{{0, 0, 0}, {16, 20, 0}, {20, -30, 0}, {40, 0, 0}}, 2, 6, 0.9},
      {{{0, 0, 0}, {10, 10, 0}, {20, -10, 2}, {40, 0, 8}}, 3, 9, 10.0},
  };
  for (const auto& c : cases) {
    const CurvatureMatch match(known_curve_setup(c.truth, c.dim, c.free, 3.0, 5.0, 3, std::nullopt));
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = hula::studies::run_curvature_match(match, ga_study(MatchMethod::Ga));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("GA %zu variables: before %.4g after %.4g (thesis %.3g) in %.3f s\n", c.free, r.before.mean,
                r.after.mean, c.thesis, seconds);
    EXPECT_LT(r.after.mean, c.thesis) << c.free << " variables";
    EXPECT_LT(r.after.mean, r.before.mean);
    EXPECT_LT(seconds, 1.0);
  }
}

// Same seed, same result on 1 and 2 threads (Flexo's reproducibility contract carries through).
TEST(MatchGa, ResultDoesNotDependOnThreads) {
  const CurvatureMatch match(known_curve_setup(planar_wave(5), 2, 6, 2.0, 4.0, 5, std::nullopt));
  MatchStudy st = ga_study(MatchMethod::Ga);
  st.ga.generations = 10;
  const auto a = hula::studies::run_curvature_match(match, st);
  st.header.threads = 2;
  const auto b = hula::studies::run_curvature_match(match, st);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(a.convergence, b.convergence);
  ASSERT_EQ(a.convergence.size(), 11U);
  for (std::size_t g = 1; g < a.convergence.size(); ++g) EXPECT_LE(a.convergence[g], a.convergence[g - 1]);
}

// The real-coded GA is the alternative route; on the 4-variable test curve it also beats the thesis's 0.1.
TEST(MatchGa, RealCodedGaAlsoMatches) {
  const CurvatureMatch match(
      known_curve_setup({{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2, 4, 3.0, 5.0, 3, std::nullopt));
  MatchStudy st = ga_study(MatchMethod::Ga);
  st.ga.algorithm = hula::studies::MatchGaSettings::Algorithm::Real;
  const auto r = hula::studies::run_curvature_match(match, st);
  EXPECT_LT(r.after.mean, 0.1);
}

// checks: ga.seed_start puts the start design into generation 0 (its best is no worse than the start, up to the
// binary coding's 1e-3 grid), and ga.distinct returns that many designs, best first, pairwise farther apart than the
// niche radius (normalised by the bounds), the first being the GA's best.
TEST(MatchGa, SeededStartAndDistinctDesigns) {
  const CurvatureMatch match(
      known_curve_setup({{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2, 4, 3.0, 5.0, 3, std::nullopt));
  MatchStudy st = ga_study(MatchMethod::Ga);
  st.ga.generations = 20;
  st.ga.seed_start = true;
  st.ga.distinct = 3;
  const auto r = hula::studies::run_curvature_match(match, st);
  EXPECT_LE(r.convergence.front(), r.before.mean + 1e-4);
  ASSERT_EQ(r.distinct.size(), 3U);
  EXPECT_NEAR(r.distinct[0].objectives[0], r.after_ga.mean, 1e-12);
  const auto vars = match.variables();
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = a + 1; b < 3; ++b) {
      double sum = 0.0;
      for (std::size_t j = 0; j < vars.size(); ++j) {
        const double d = (r.distinct[a].variables[j] - r.distinct[b].variables[j]) / (vars[j].upper - vars[j].lower);
        sum += d * d;
      }
      EXPECT_GT(std::sqrt(sum / static_cast<double>(vars.size())), st.ga.distinct_radius) << a << " " << b;
      EXPECT_LE(r.distinct[a].objectives[0], r.distinct[b].objectives[0]);
    }
  EXPECT_TRUE(r.log.generations().empty());  // collected for the niches only, not kept
}

// The thesis's bounds experiment (8.2.1 "Variable bounds"): the test curve (0, 0), (16, 20), (20, 30), (40, 0) as
// listed, the GA started at pt2 = (10, 28), pt3 = (23, 22) with bounds of ±5, which exclude the solution (pt2.x <= 15,
// pt2.y >= 23, pt3.y <= 27); pt4.x free by ±5 too. The target is the known curve's own profile (closed-form truth).
CurvatureMatchSetup thesis_bounds_experiment() {
  const std::vector<Vec3> truth{{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}};
  CurvatureMatchSetup s;
  s.points = {{0, 0, 0}, {10, 28, 0}, {23, 22, 0}, {40, 0, 0}};
  s.lower = {{0, 0, 0}, {5, 5, 0}, {5, 5, 0}, {5, 0, 0}};
  s.upper = s.lower;
  s.target =
      Profile::from_samples(hula::studies::uniform_abscissae(200), hula::studies::curvature_profile_of(truth, 2, 200));
  return s;
}

// checks: the first run ends on a bound; each re-centred round's box is centred on the previous round's result with
// the first box's widths (10), leaving the first box; the rounds stop once the result is off every bound and the last
// round's result is the known curve (the closed-form truth) to 1e-6 in the points, 1e-8 in mean curvature distance.
TEST(MatchRecentre, RoundsReachTheOptimumOutsideTheFirstBox) {
  const CurvatureMatch match(thesis_bounds_experiment());
  MatchStudy st = ga_study(MatchMethod::Hybrid);
  st.ga.generations = 20;
  st.max_recentres = 5;
  const auto r = hula::studies::run_curvature_match(match, st);
  ASSERT_GE(r.rounds.size(), 2U);
  EXPECT_FALSE(r.rounds.front().on_bound.empty());
  const auto first = match.variables();
  for (std::size_t k = 0; k < r.rounds.size(); ++k) {
    const auto& round = r.rounds[k];
    for (std::size_t j = 0; j < first.size(); ++j) {
      const double centre = k == 0 ? match.start_variables()[j] : r.rounds[k - 1].best[j];
      EXPECT_NEAR(round.variables[j].lower, centre - 5.0, 1e-12) << k << " " << j;
      EXPECT_NEAR(round.variables[j].upper, centre + 5.0, 1e-12) << k << " " << j;
      EXPECT_GE(round.best[j], round.variables[j].lower);
      EXPECT_LE(round.best[j], round.variables[j].upper);
    }
    if (k + 1 < r.rounds.size()) {
      EXPECT_FALSE(round.on_bound.empty()) << k;
    }
    EXPECT_GT(round.evaluations, 0U);
  }
  EXPECT_TRUE(r.rounds.back().on_bound.empty());
  EXPECT_EQ(r.best, r.rounds.back().best);
  EXPECT_EQ(r.variables[0].lower, r.rounds.back().variables[0].lower);
  EXPECT_LT(r.after.mean, 1e-8);
  const std::vector<double> truth{16, 20, 20, 30, 40};
  for (std::size_t j = 0; j < truth.size(); ++j) EXPECT_NEAR(r.best[j], truth[j], 1e-6) << j;
  EXPECT_GT(r.best[0], first[0].upper);  // pt2.x = 16 lies outside the first box [5, 15]
  EXPECT_EQ(r.start, match.start_variables());
  EXPECT_DOUBLE_EQ(r.before.mean, match.distances(r.start).mean);
}

// checks: without max_recentres the same study stops on the bound after one round (the thesis's "intermediate
// solution"), and the result's box is the study's own.
TEST(MatchRecentre, NoRoundsWithoutMaxRecentres) {
  const CurvatureMatch match(thesis_bounds_experiment());
  MatchStudy st = ga_study(MatchMethod::Hybrid);
  st.ga.generations = 20;
  const auto r = hula::studies::run_curvature_match(match, st);
  ASSERT_EQ(r.rounds.size(), 1U);
  EXPECT_FALSE(r.rounds[0].on_bound.empty());
  EXPECT_GT(r.after.mean, 1e-4);
  EXPECT_EQ(r.variables[0].upper, match.variables()[0].upper);
}

// checks: recentred_setup moves the data points to the design and keeps offsets, targets and the proximity centre
// (the designer's start) — against the setup's own values.
TEST(MatchRecentre, RecentredSetupKeepsWidthsAndProximityCentre) {
  CurvatureMatchSetup s = thesis_bounds_experiment();
  s.proximity = {0, 0.1, 0.1, 0.1};
  const CurvatureMatch match(s);
  const std::vector<double> x{14, 24, 19, 27, 41};
  const CurvatureMatchSetup r = hula::studies::recentred_setup(match, x);
  EXPECT_EQ(r.points[1], (Vec3{14, 24, 0}));
  EXPECT_EQ(r.points[2], (Vec3{19, 27, 0}));
  EXPECT_EQ(r.points[3], (Vec3{41, 0, 0}));
  EXPECT_EQ(r.lower[1], s.lower[1]);
  EXPECT_EQ(r.proximity_centre[1], s.points[1]);
  const CurvatureMatch moved(r);
  // The penalty is measured from the designer's start (10, 28), (23, 22), (40, 0): 0.1 (4² + 4²) + 0.1 (4² + 5²) +
  // 0.1 · 1² at x.
  const hula::optim::Problem p = moved.problem();
  std::vector<double> v(1);
  p.evaluate(x, v);
  EXPECT_NEAR(v[0] - moved.distances(x).mean, 0.1 * 32 + 0.1 * 41 + 0.1 * 1, 1e-9);
  EXPECT_EQ(moved.proximity_variables(), match.start_variables());
}

// checks: every map node's objective and fitness equal the study's fitness evaluated directly at that design (mean
// curvature distance by CurvatureMatch::distances, plus Σ w |p − p⁰|² computed here, fitness 1/(1 + e), eq. 32), and
// the node at the result's coordinates (grid centred on it) equals the result's own value.
TEST(MatchMap, NodesAreTheFitnessAtThoseDesigns) {
  CurvatureMatchSetup s = thesis_bounds_experiment();
  s.proximity = {0, 0.001, 0, 0};
  const CurvatureMatch match(s);
  MatchStudy st = ga_study(MatchMethod::Ga);
  st.ga.generations = 5;
  hula::studies::MatchMapSettings m;
  m.variables = {"points[2].x", "points[1].y"};
  m.grid = 5;
  st.map = m;
  const auto r = hula::studies::run_curvature_match(match, st);
  ASSERT_TRUE(r.map.has_value());
  ASSERT_EQ(r.map->x_values.size(), 5U);
  ASSERT_EQ(r.map->y_values.size(), 5U);
  EXPECT_DOUBLE_EQ(r.map->x_values.front(), r.variables[2].lower);
  EXPECT_DOUBLE_EQ(r.map->y_values.back(), r.variables[1].upper);
  for (std::size_t row = 0; row < 5; ++row)
    for (std::size_t col = 0; col < 5; ++col) {
      std::vector<double> x = r.best;
      x[2] = r.map->x_values[col];
      x[1] = r.map->y_values[row];
      const double dx = x[0] - 10.0, dy = x[1] - 28.0;
      const double e = match.distances(x).mean + 0.001 * (dx * dx + dy * dy);
      EXPECT_NEAR(r.map->objective[row * 5 + col], e, 1e-12) << row << " " << col;
      EXPECT_NEAR(r.map->fitness[row * 5 + col], 1.0 / (1.0 + e), 1e-12);
    }
  // A grid centred on the result: its middle node is the result.
  st.map->from = std::array<double, 2>{r.best[2] - 1.0, r.best[1] - 2.0};
  st.map->to = std::array<double, 2>{r.best[2] + 1.0, r.best[1] + 2.0};
  const auto c = hula::studies::run_curvature_match(match, st);
  const double dx = c.best[0] - 10.0, dy = c.best[1] - 28.0;
  EXPECT_NEAR(c.map->objective[2 * 5 + 2], c.after.mean + 0.001 * (dx * dx + dy * dy), 1e-12);
}

// checks: map settings are refused before any run, naming the member and the variables there are.
TEST(MatchMap, BadSettingsAreRefused) {
  const CurvatureMatch match(thesis_bounds_experiment());
  MatchStudy st = ga_study(MatchMethod::Ga);
  hula::studies::MatchMapSettings m;
  m.variables = {"points[0].x", "points[1].y"};
  st.map = m;
  HULA_EXPECT_ERROR((void)hula::studies::run_curvature_match(match, st), Errc::InvalidOption,
                    "map.variables[0] = \"points[0].x\" is not a free design variable (points[1].x, points[1].y");
  st.map->variables = {"points[1].y", "points[1].y"};
  HULA_EXPECT_ERROR((void)hula::studies::run_curvature_match(match, st), Errc::InvalidOption, "twice");
  st.map->variables = {"points[1].x", "points[1].y"};
  st.map->grid = 1;
  HULA_EXPECT_ERROR((void)hula::studies::run_curvature_match(match, st), Errc::InvalidOption, "map.grid = 1");
}

// LM options are checked before any work, naming the field.
TEST(MatchHybrid, RejectsBadOptions) {
  hula::studies::LmOptions o;
  o.difference_step = 0.5;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "lm.difference_step = 0.5");
  o = {};
  o.max_iterations = 0;
  HULA_EXPECT_ERROR(o.validate(), Errc::InvalidOption, "lm.max_iterations");
}

}  // namespace
