// SPDX-License-Identifier: MIT
#include "hula/studies/curvature_match.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/core/simd.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/counting_allocator.hpp"
#include "hula/testing/expect_error.hpp"

namespace {

using hula::Errc;
using hula::Vec3;
using hula::studies::CurvatureMatch;
using hula::studies::CurvatureMatchSetup;
using hula::studies::Profile;
using hula::studies::SplineProfileSampler;

// Checks the sampler's κ and τ against the NURBS interpolant (interpolate_cubic, Piegl-Tiller basis) and the
// Frenet code of diffgeom: two independent implementations of the same spline and the same formulas.
void expect_matches_nurbs(const std::vector<Vec3>& pts, int dim, std::optional<Vec3> start, std::optional<Vec3> end) {
  const auto u = hula::studies::uniform_abscissae(200);
  const SplineProfileSampler sampler(pts.size(), dim, u, start, end);
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(u.size()), tau(u.size());
  ASSERT_TRUE(sampler.sample(pts, ws, kappa, tau));
  const hula::nurbs::NurbsCurve curve = sampler.curve(pts);
  std::vector<double> k_ref(u.size()), t_ref(u.size());
  hula::diffgeom::curvature_torsion(curve, u, k_ref, t_ref);
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_NEAR(kappa[i], k_ref[i], 1e-12 * std::max(1.0, k_ref[i])) << "u = " << u[i];
    if (dim == 3 && std::isfinite(tau[i]) && std::isfinite(t_ref[i]) && k_ref[i] > 1e-6) {
      EXPECT_NEAR(tau[i], t_ref[i], 1e-12 * std::max(1.0, std::fabs(t_ref[i]))) << "u = " << u[i];
    }
  }
}

// The thesis's test curve (8.2.1) and a space S-bend (Example 4), natural and clamped ends.
TEST(SplineProfileSampler, MatchesNurbsInterpolantAndFrenetTo1e12) {
  expect_matches_nurbs({{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2, std::nullopt, std::nullopt);
  expect_matches_nurbs({{0, 0, 0}, {5, 20, 0}, {40, 0, 0}}, 2, Vec3{1, 1, 0}, std::nullopt);
  expect_matches_nurbs({{0, 0, 0}, {10, 10, 0}, {20, -10, 2}, {40, 0, 8}}, 3, std::nullopt, std::nullopt);
  expect_matches_nurbs({{0, 0, 0}, {10, 10, 0}, {20, -10, 2}, {30, 4, 5}, {40, 0, 8}}, 3, Vec3{1, 0, 0},
                       Vec3{0, -1, 1});
  expect_matches_nurbs({{0, 0, 0}, {3, 1, 0}}, 2, Vec3{0, 1, 0}, std::nullopt);
}

// Arc-length abscissa: κ where the arc length is u_i L, checked against the NURBS curve's parameter_at_length
// (adaptive quadrature to 1e-12) and diffgeom's curvature; to 1e-10.
TEST(SplineProfileSampler, ArcLengthAbscissaMatchesNurbsArcLength) {
  const std::vector<Vec3> pts = {{0, 0, 0}, {10, 10, 0}, {20, -10, 2}, {30, 4, 5}, {40, 0, 8}};
  const auto u = hula::studies::uniform_abscissae(101);
  const SplineProfileSampler sampler(pts.size(), 3, u, Vec3{1, 0, 0}, std::nullopt,
                                     hula::studies::ProfileAbscissa::ArcLength);
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(u.size());
  ASSERT_TRUE(sampler.sample(pts, ws, kappa));
  const long before = hula::testing::allocation_count();
  ASSERT_TRUE(sampler.sample(pts, ws, kappa));
  EXPECT_EQ(hula::testing::allocation_count(), before);  // no allocation in the arc-length path either
  const auto curve = sampler.curve(pts);
  const double length = hula::nurbs::arc_length(curve);
  std::vector<double> ts(u.size()), k_ref(u.size()), t_ref(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) ts[i] = hula::nurbs::parameter_at_length(curve, u[i] * length);
  hula::diffgeom::curvature_torsion(curve, ts, k_ref, t_ref);
  for (std::size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(kappa[i], k_ref[i], 1e-10) << "u = " << u[i];
  // Not the parameter profile: the abscissae differ in the interior.
  const auto by_parameter = hula::studies::curvature_profile_of(pts, 3, 101, Vec3{1, 0, 0});
  EXPECT_GT(std::fabs(by_parameter[30] - kappa[30]), 1e-4);
}

// A straight line has κ = 0 everywhere; a planar spline has τ = 0.
TEST(SplineProfileSampler, CollinearPointsHaveZeroCurvature) {
  const SplineProfileSampler sampler(4, 2, hula::studies::uniform_abscissae(50));
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(50), tau(50);
  ASSERT_TRUE(sampler.sample(std::vector<Vec3>{{0, 0, 0}, {1, 2, 0}, {3, 6, 0}, {4, 8, 0}}, ws, kappa, tau));
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_NEAR(kappa[i], 0.0, 1e-15);
    EXPECT_EQ(tau[i], 0.0);
  }
}

// Coincident points are a failed evaluation (NaN), never an exception in the GA's hot loop.
TEST(SplineProfileSampler, CoincidentPointsFailWithNaN) {
  const SplineProfileSampler sampler(3, 2, hula::studies::uniform_abscissae(10));
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(10);
  EXPECT_FALSE(sampler.sample(std::vector<Vec3>{{0, 0, 0}, {0, 0, 0}, {1, 1, 0}}, ws, kappa));
  EXPECT_TRUE(std::isnan(kappa[3]));
  HULA_EXPECT_ERROR(SplineProfileSampler(1, 2, hula::studies::uniform_abscissae(10)), Errc::TooFewPoints, "1");
  HULA_EXPECT_ERROR(SplineProfileSampler(3, 2, {0.0, 1.5}), Errc::InvalidArgument, "samples[1]");
  HULA_EXPECT_ERROR(SplineProfileSampler(3, 2, hula::studies::uniform_abscissae(3), Vec3{0, 0, 0}),
                    Errc::InvalidArgument, "start_tangent");
}

CurvatureMatchSetup thesis_test_setup() {
  CurvatureMatchSetup s;
  s.points = {{0, 0, 0}, {10, 28, 0}, {23, 22, 0}, {40, 0, 0}};
  s.dimension = 2;
  s.lower = {{0, 0, 0}, {5, 5, 0}, {5, 5, 0}, {5, 5, 0}};
  s.upper = s.lower;
  const auto k =
      hula::studies::curvature_profile_of(std::vector<Vec3>{{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2, 200);
  s.target = Profile::from_samples(hula::studies::uniform_abscissae(200), k);
  return s;
}

// Fitness evaluation of "interpolate a cubic through the points, sample κ at 200 parameters, compare" allocates
// checks: the vectorised sample kernel (issue 27) gives bit for bit the same κ and τ at every instruction
// set this CPU has as one sample at a time (SimdLevel::Scalar), planar and spatial, natural and clamped
// ends, spans shorter and longer than a vector, abscissae that fall on the data parameters.
TEST(SplineProfileSampler, EveryInstructionSetGivesTheSameSamples) {
  const hula::SimdLevel saved = hula::simd_level();
  hula::Rng rng(2702);
  int compared = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int dim = trial % 2 == 0 ? 2 : 3;
    const std::size_t n = 2 + static_cast<std::size_t>(trial) % 9 * 3;  // 2 … 26 points
    std::vector<Vec3> pts(n);
    double x = 0.0;
    for (auto& p : pts) {
      x += rng.uniform(0.5, 3.0);
      p = {x, rng.uniform(-3, 3), dim == 3 ? rng.uniform(-3, 3) : 0.0};
    }
    std::optional<Vec3> start, end;
    if (trial % 3 == 1) start = Vec3{1, 0.5, dim == 3 ? 0.25 : 0.0};
    if (trial % 4 == 2) end = Vec3{1, -0.5, 0};
    // Uniform abscissae plus, for some trials, a few repeated values (non-decreasing is allowed).
    std::vector<double> u = hula::studies::uniform_abscissae(37 + static_cast<std::size_t>(trial) * 7);
    if (trial % 5 == 0) {
      const std::vector<double> repeats(3, u[5]);  // (insert(pos, 3, u[5]) trips GCC 12's -Wnull-dereference)
      u.insert(u.begin() + 5, repeats.begin(), repeats.end());
    }
    const SplineProfileSampler sampler(n, dim, u, start, end);
    SplineProfileSampler::Workspace ws;
    for (const bool with_tau : {false, true}) {
      hula::set_simd_level(hula::SimdLevel::Scalar);
      // τ columns always allocated (a zero-length vector's fill trips GCC 12's -Wnull-dereference); an empty
      // span asks for κ only.
      std::vector<double> k0(u.size()), t0(u.size());
      const std::size_t nt = with_tau ? t0.size() : 0;
      ASSERT_TRUE(sampler.sample(pts, ws, k0, std::span<double>(t0.data(), nt)));
      for (int level = 1; level <= static_cast<int>(hula::supported_simd_level()); ++level) {
        hula::set_simd_level(static_cast<hula::SimdLevel>(level));
        std::vector<double> k1(u.size()), t1(u.size());
        ASSERT_TRUE(sampler.sample(pts, ws, k1, std::span<double>(t1.data(), nt)));
        ASSERT_EQ(std::memcmp(k0.data(), k1.data(), k0.size() * sizeof(double)), 0)
            << hula::simd_level_name(static_cast<hula::SimdLevel>(level)) << " trial " << trial;
        ASSERT_EQ(std::memcmp(t0.data(), t1.data(), nt * sizeof(double)), 0)
            << hula::simd_level_name(static_cast<hula::SimdLevel>(level)) << " trial " << trial;
        ++compared;
      }
    }
  }
  hula::set_simd_level(saved);
  EXPECT_GT(compared, 0);
}

// checks: the GA objective (mean_distance, four interleaved partial sums) equals the reports'
// distances().mean bit for bit and the plain sequential mean of |κ − κ*| to 1e-14 relative.
TEST(CurvatureMatch, MeanDistanceIsEquation31) {
  CurvatureMatchSetup s;
  s.points = {{0, 0, 0}, {13, 23, 0}, {23, 27, 0}, {40, 0, 0}};
  s.lower = {{0, 0, 0}, {5, 5, 0}, {5, 5, 0}, {0, 0, 0}};
  s.upper = s.lower;
  s.samples = 203;  // not a multiple of 4
  s.target =
      Profile::from_samples(hula::studies::uniform_abscissae(s.samples),
                            hula::studies::curvature_profile_of(
                                std::vector<Vec3>{{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2, s.samples));
  const CurvatureMatch match(s);
  const std::vector<double> x = match.start_variables();
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> pts(4);
  std::vector<double> kappa(s.samples);
  const double e = match.mean_distance(x, ws, pts, kappa);
  EXPECT_EQ(e, match.distances(x).mean);
  const std::vector<double> k = match.curvature_samples(x);
  double sum = 0.0;
  for (std::size_t i = 0; i < k.size(); ++i) sum += std::fabs(k[i] - match.target_samples()[i]);
  EXPECT_NEAR(e, sum / static_cast<double>(k.size()), 1e-14 * e);
  EXPECT_GT(e, 1e-4);  // the start is not the target
}

// nothing once the workspace is warm (DESIGN: no allocation in hot loops).
TEST(CurvatureMatch, EvaluationDoesNotAllocate) {
  const CurvatureMatch match(thesis_test_setup());
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> pts(4);
  std::vector<double> kappa(200);
  std::vector<double> x = match.start_variables();
  (void)match.mean_distance(x, ws, pts, kappa);
  const long before = hula::testing::allocation_count();
  double sum = 0.0;
  for (int i = 0; i < 100; ++i) {
    x[0] += 0.01;
    sum += match.mean_distance(x, ws, pts, kappa);
  }
  EXPECT_EQ(hula::testing::allocation_count(), before);
  EXPECT_GT(sum, 0.0);
  // The problem's evaluate (thread-local buffers) does not allocate either once warm.
  const hula::optim::Problem p = match.problem();
  double value = 0.0;
  p.evaluate(x, std::span<double>(&value, 1));
  const long before_problem = hula::testing::allocation_count();
  for (int i = 0; i < 100; ++i) p.evaluate(x, std::span<double>(&value, 1));
  EXPECT_EQ(hula::testing::allocation_count(), before_problem);
}

// The variables are the free coordinates with bounds [value - lower, value + upper] (appendix 5).
TEST(CurvatureMatch, VariablesAreFreeCoordinatesWithOffsetBounds) {
  const CurvatureMatch match(thesis_test_setup());
  const auto v = match.variables(1e-3);
  ASSERT_EQ(v.size(), 6U);
  EXPECT_EQ(v[0].name, "points[1].x");
  EXPECT_EQ(v[0].lower, 5.0);
  EXPECT_EQ(v[0].upper, 15.0);
  EXPECT_EQ(v[5].name, "points[3].y");
  EXPECT_EQ(v[5].precision, 1e-3);
  // The known curve's own points give distance 0 exactly.
  const std::vector<double> truth = {16, 20, 20, 30, 40, 0};
  EXPECT_NEAR(match.distances(truth).mean, 0.0, 1e-15);
  EXPECT_GT(match.distances(match.start_variables()).mean, 0.01);
}

// Bad setups are refused before any evaluation, naming the member at fault.
TEST(CurvatureMatch, RejectsBadSetupsNamingTheMember) {
  auto s = thesis_test_setup();
  s.lower[0].x = 1.0;
  HULA_EXPECT_ERROR(CurvatureMatch{s}, Errc::InvalidArgument, "lower[0].x");
  s = thesis_test_setup();
  s.upper[2].y = -1.0;
  HULA_EXPECT_ERROR(CurvatureMatch{s}, Errc::InvalidArgument, "upper[2].y = -1");
  s = thesis_test_setup();
  s.upper[2].z = 1.0;
  HULA_EXPECT_ERROR(CurvatureMatch{s}, Errc::InvalidArgument, "planar");
  s = thesis_test_setup();
  s.samples = 0;
  HULA_EXPECT_ERROR(CurvatureMatch{s}, Errc::InvalidArgument, "samples = 0");
  s = thesis_test_setup();
  s.points[2].x = std::nan("");
  HULA_EXPECT_ERROR(CurvatureMatch{s}, Errc::NonFiniteInput, "points[2].x");
  s = thesis_test_setup();
  s.lower.pop_back();
  HULA_EXPECT_ERROR(CurvatureMatch{s}, Errc::InvalidArgument, "lower has 3 entries");
}

// Curvature and torsion distances for the two-objective study: zero at the known space curve, both positive
// elsewhere, and no allocation per evaluation.
TEST(CurvatureMatch, CurvatureAndTorsionDistancesForTheTwoObjectiveStudy) {
  const std::vector<Vec3> truth = {{0, 0, 0}, {10, 10, 0}, {20, -10, 2}, {30, 4, 5}, {40, 0, 8}};
  CurvatureMatchSetup s;
  s.dimension = 3;
  s.points = truth;
  s.points[2].z += 1.0;
  s.lower.assign(truth.size(), Vec3{2, 2, 2});
  s.lower[0] = Vec3{};
  s.upper = s.lower;
  const SplineProfileSampler sampler(truth.size(), 3, hula::studies::uniform_abscissae(200));
  SplineProfileSampler::Workspace ws;
  std::vector<double> kappa(200), tau(200);
  ASSERT_TRUE(sampler.sample(truth, ws, kappa, tau));
  for (double& t : tau) t = std::isfinite(t) ? t : 0.0;
  s.target = Profile::from_samples(hula::studies::uniform_abscissae(200), kappa);
  s.torsion_target = Profile::from_samples(hula::studies::uniform_abscissae(200), tau);
  const CurvatureMatch match(s);
  std::vector<double> x = match.start_variables();
  const auto far = match.distances(x);
  EXPECT_GT(far.mean, 1e-3);
  EXPECT_GT(far.torsion_mean, 1e-3);
  x[5] -= 1.0;  // points[2].z back to the known curve's value
  EXPECT_EQ(match.variables()[5].name, "points[2].z");
  std::vector<Vec3> pts(truth.size());
  const auto at = match.mean_distances(x, ws, pts, kappa, tau);
  EXPECT_NEAR(at.mean, 0.0, 1e-15);
  EXPECT_NEAR(at.torsion_mean, 0.0, 1e-14);
  const long before = hula::testing::allocation_count();
  for (int i = 0; i < 50; ++i) (void)match.mean_distances(x, ws, pts, kappa, tau);
  EXPECT_EQ(hula::testing::allocation_count(), before);
}

}  // namespace

namespace {

// checks: the data parameters read off the curvature profile of a C2 cubic (200 samples) equal the chord-length
// parameters of its data points (nurbs::parameterise) to within 1.5 sample spacings (most to a tenth), on seeded convex
// point sets with uneven spacing, clamped start or natural ends.
TEST(SplineProfileBreaks, FindsTheDataParametersOfSeededSplines) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    hula::Rng rng(seed);
    const std::size_t n = 6 + static_cast<std::size_t>(rng.uniform(0.0, 8.0));
    std::vector<Vec3> pts(n);
    double s = 0.0;
    for (std::size_t k = 0; k < n; ++k, s += rng.uniform(0.7, 1.3))
      pts[k] = {10.0 * std::sin(0.15 * s), 10.0 * (1.0 - std::cos(0.15 * s)), 0.0};
    const std::optional<Vec3> tangent = seed % 2 == 0 ? std::optional<Vec3>(pts[1] - pts[0]) : std::nullopt;
    const std::vector<double> kappa = hula::studies::curvature_profile_of(pts, 2, 200, tangent);
    const auto breaks = hula::studies::spline_profile_breaks(kappa, n - 2);
    ASSERT_TRUE(breaks.has_value()) << "seed " << seed;
    const std::vector<double> t = hula::nurbs::parameterise(pts, hula::nurbs::Parameterisation::ChordLength);
    ASSERT_EQ(breaks->parameters.size(), n);
    for (std::size_t k = 0; k < n; ++k)
      EXPECT_NEAR(breaks->parameters[k], t[k], 1.5 / 199.0) << "seed " << seed << " k " << k;
  }
}

// checks: a smooth law profile has no data parameters to find (none returned), and the unsigned profile of an S-shaped
// spline (one inflection) comes back signed, changing sign once, where the spline's signed curvature does.
TEST(SplineProfileBreaks, SmoothProfilesHaveNoneAndInflectionsChangeTheSign) {
  std::vector<double> smooth(200);
  for (std::size_t i = 0; i < 200; ++i) smooth[i] = 0.05 + 0.02 * std::sin(3.0 * static_cast<double>(i) / 199.0);
  EXPECT_FALSE(hula::studies::spline_profile_breaks(smooth, 5).has_value());
  std::vector<Vec3> pts;
  for (int k = 0; k <= 6; ++k) pts.push_back({5.0 * k, 6.0 * std::sin(0.2 * M_PI * k), 0.0});
  const std::vector<double> kappa = hula::studies::curvature_profile_of(pts, 2, 200);
  const auto breaks = hula::studies::spline_profile_breaks(kappa, pts.size() - 2);
  ASSERT_TRUE(breaks.has_value());
  int changes = 0;
  for (std::size_t i = 1; i < 200; ++i)
    if ((breaks->signed_samples[i] < 0.0) != (breaks->signed_samples[i - 1] < 0.0)) ++changes;
  EXPECT_EQ(changes, 1);
  for (std::size_t i = 0; i < 200; ++i) EXPECT_EQ(std::fabs(breaks->signed_samples[i]), kappa[i]);
}

}  // namespace
