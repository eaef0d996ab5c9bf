// SPDX-License-Identifier: MIT
// The curvature-matching fitness evaluation (thesis 8.2.1, eq. 31): interpolate
// a cubic through N data points, sample κ at 200 parameters, compare with the
// target — ours (studies::CurvatureMatch, allocation-free) beside Open CASCADE
// doing the same (GeomAPI_Interpolate + GeomLProp_CLProps) in the same run;
// then the thesis's whole 50 x 50 GA run, a 20-variable hybrid run and the
// curvature + torsion NSGA-II run (with and without the LM polish).
// Items processed = fitness evaluations.
#include <benchmark/benchmark.h>

#include <GeomAPI_Interpolate.hxx>
#include <GeomLProp_CLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/core/simd.hpp"
#include "hula/studies/curvature_match.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/match_study.hpp"
#include "reference/fitness.hpp"

namespace {

using hula::Vec3;
using hula::studies::CurvatureMatch;
using hula::studies::CurvatureMatchSetup;

constexpr std::size_t kSamples = 200;

// The instruction set in the JSON context (docs/benchmarks.md names it with each figure).
const bool kSimdContext = [] {
  benchmark::AddCustomContext("simd", std::string(hula::simd_level_name(hula::simd_level())));
  return true;
}();

std::vector<Vec3> wave(std::size_t n) {
  std::vector<Vec3> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n - 1);
    p[i] = {40.0 * s, 12.0 * std::sin(2.5 * s) + 3.0 * s * s, 0.0};
  }
  return p;
}

// N planar points, every coordinate after the start point free by +-2; the target is the known curve's profile.
CurvatureMatchSetup setup(std::size_t n) {
  CurvatureMatchSetup s;
  s.points = wave(n);
  s.dimension = 2;
  s.lower.assign(n, Vec3{2, 2, 0});
  s.upper = s.lower;
  s.lower[0] = s.upper[0] = Vec3{};
  s.target = hula::studies::Profile::from_samples(hula::studies::uniform_abscissae(kSamples),
                                                  hula::studies::curvature_profile_of(s.points, 2, kSamples));
  for (std::size_t i = 1; i < n; ++i) s.points[i].y += 0.5;
  return s;
}

void BM_match_fitness(benchmark::State& state) {
  const CurvatureMatch match(setup(static_cast<std::size_t>(state.range(0))));
  hula::studies::SplineProfileSampler::Workspace ws;
  std::vector<Vec3> pts(match.setup().points.size());
  std::vector<double> kappa(kSamples);
  std::vector<double> x = match.start_variables();
  hula::Rng rng(1);
  for (auto& v : x) v += rng.uniform(-0.1, 0.1);
  double sign = 1e-9;
  for (auto _ : state) {
    x[0] += sign;
    sign = -sign;
    benchmark::DoNotOptimize(match.mean_distance(x, ws, pts, kappa));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_match_fitness)->Arg(4)->Arg(7)->Arg(10);

// The hand-written fitness loop (reference/fitness.hpp) on the same points (after the same x[0] change);
// its e is checked against mean_distance's (1e-12 relative) before timing.
void BM_reference_fitness(benchmark::State& state) {
  const CurvatureMatch match(setup(static_cast<std::size_t>(state.range(0))));
  hula::studies::SplineProfileSampler::Workspace ws;
  std::vector<Vec3> pts(match.setup().points.size());
  std::vector<double> kappa(kSamples);
  std::vector<double> x = match.start_variables();
  hula::Rng rng(1);
  for (auto& v : x) v += rng.uniform(-0.1, 0.1);
  const std::vector<double>& u = match.sampler().abscissae();
  const std::vector<double>& target = match.target_samples();
  const double ours = match.mean_distance(x, ws, pts, kappa);
  match.points_from(x, pts);
  const double ref = hula::bench::reference_fitness(pts, u, target);
  if (!(std::fabs(ours - ref) <= 1e-12 * std::fabs(ref))) {
    state.SkipWithError(("reference fitness " + std::to_string(ref) + " != ours " + std::to_string(ours)).c_str());
    return;
  }
  double sign = 1e-9;
  for (auto _ : state) {
    pts[1].x += sign;
    sign = -sign;
    benchmark::DoNotOptimize(hula::bench::reference_fitness(pts, u, target));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_reference_fitness)->Arg(4)->Arg(7)->Arg(10);

// The same with the arc-length abscissa (span lengths by Gauss-Legendre, Newton per sample).
void BM_match_fitness_arclength(benchmark::State& state) {
  CurvatureMatchSetup s = setup(static_cast<std::size_t>(state.range(0)));
  s.abscissa = hula::studies::ProfileAbscissa::ArcLength;
  const CurvatureMatch match(s);
  hula::studies::SplineProfileSampler::Workspace ws;
  std::vector<Vec3> pts(match.setup().points.size());
  std::vector<double> kappa(kSamples);
  std::vector<double> x = match.start_variables();
  double sign = 1e-9;
  for (auto _ : state) {
    x[0] += sign;
    sign = -sign;
    benchmark::DoNotOptimize(match.mean_distance(x, ws, pts, kappa));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_match_fitness_arclength)->Arg(7);

// Open CASCADE: the same points, GeomAPI_Interpolate (its own chord-length parameters and ends), κ from
// GeomLProp_CLProps at 200 parameters spread over the curve's domain, mean |κ - κ*|.
void BM_occt_fitness(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const CurvatureMatch match(setup(n));
  const auto& target = match.target_samples();
  const auto& pts = match.setup().points;
  Handle(TColgp_HArray1OfPnt) arr = new TColgp_HArray1OfPnt(1, static_cast<int>(n));
  double sign = 1e-9;
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) arr->SetValue(static_cast<int>(i) + 1, gp_Pnt(pts[i].x, pts[i].y + sign, 0.0));
    sign = -sign;
    GeomAPI_Interpolate interp(arr, Standard_False, 1e-9);
    interp.Perform();
    const Handle(Geom_BSplineCurve) c = interp.Curve();
    const double t0 = c->FirstParameter(), t1 = c->LastParameter();
    GeomLProp_CLProps props(c, 2, 1e-9);
    double sum = 0.0;
    for (std::size_t i = 0; i < kSamples; ++i) {
      props.SetParameter(t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(kSamples - 1));
      sum += std::fabs(props.Curvature() - target[i]);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_occt_fitness)->Arg(4)->Arg(7)->Arg(10);

// The thesis's run: binary GA, population 50, 50 generations, roulette, boost 3 -> 5, on the 4-point test curve.
void BM_match_ga_50x50(benchmark::State& state) {
  CurvatureMatchSetup s;
  s.points = {{0, 0, 0}, {13, 23, 0}, {23, 27, 0}, {40, 0, 0}};
  s.dimension = 2;
  s.lower = {{0, 0, 0}, {5, 5, 0}, {5, 5, 0}, {0, 0, 0}};
  s.upper = s.lower;
  s.target = hula::studies::Profile::from_samples(
      hula::studies::uniform_abscissae(kSamples),
      hula::studies::curvature_profile_of(std::vector<Vec3>{{0, 0, 0}, {16, 20, 0}, {20, 30, 0}, {40, 0, 0}}, 2,
                                          kSamples));
  const CurvatureMatch match(s);
  hula::studies::MatchStudy study;
  double mean = 0.0;
  for (auto _ : state) {
    const auto r = hula::studies::run_curvature_match(match, study);
    // (DoNotOptimize on a non-const double lvalue may hand it back through a general register under GCC.)
    benchmark::DoNotOptimize(r.best.data());
    mean = r.after.mean;
  }
  state.counters["mean_distance"] = mean;
}
BENCHMARK(BM_match_ga_50x50)->Unit(benchmark::kMillisecond);

// Hybrid with 20 free coordinates (12 points, the start and end points fixed), GA 50 x 20 then LM to 1e-10.
void BM_match_hybrid_20(benchmark::State& state) {
  constexpr std::size_t kPoints = 12;
  CurvatureMatchSetup s = setup(kPoints);
  for (std::size_t i = 1; i < kPoints; ++i) s.points[i].y -= 0.45;  // 0.05 from the known curve
  s.lower.assign(kPoints, Vec3{0.5, 0.5, 0});
  s.upper = s.lower;
  s.lower[0] = s.upper[0] = s.lower[kPoints - 1] = s.upper[kPoints - 1] = Vec3{};
  s.points[kPoints - 1] = wave(kPoints)[kPoints - 1];  // the fixed end point is the known curve's
  s.start_tangent = Vec3{1, 0.75, 0};
  s.target = hula::studies::Profile::from_samples(
      hula::studies::uniform_abscissae(kSamples),
      hula::studies::curvature_profile_of(wave(kPoints), 2, kSamples, s.start_tangent));
  const CurvatureMatch match(s);
  hula::studies::MatchStudy study;
  study.method = hula::studies::MatchMethod::Hybrid;
  study.ga.generations = 20;
  double mean = 0.0;
  for (auto _ : state) {
    const auto r = hula::studies::run_curvature_match(match, study);
    // (DoNotOptimize on a non-const double lvalue may hand it back through a general register under GCC.)
    benchmark::DoNotOptimize(r.best.data());
    mean = r.after.mean;
  }
  state.counters["variables"] = static_cast<double>(match.dimension());
  state.counters["mean_distance"] = mean;
}
BENCHMARK(BM_match_hybrid_20)->Unit(benchmark::kMillisecond);

// A convex planar arc of length 40 (turning angle a s + b s², a in [1, 1.8], b in [0.3, 1.2] from `seed`) through n
// points equally spaced in arc length (Simpson on 40 steps per span): the far-start targets, as
// tests/studies/match_study_test.cpp builds them.
std::vector<Vec3> seeded_arc(std::size_t n, std::uint64_t seed) {
  hula::Rng rng(seed);
  const double a = rng.uniform(1.0, 1.8), b = rng.uniform(0.3, 1.2);
  std::vector<Vec3> p(n);
  Vec3 q{0, 0, 0};
  const int per = 40;
  const int steps = per * static_cast<int>(n - 1);
  auto theta = [&](double s) { return a * s + b * s * s; };
  for (int k = 0; k < steps; ++k) {
    const double s0 = static_cast<double>(k) / steps, s1 = static_cast<double>(k + 1) / steps;
    const double w = 40.0 * (s1 - s0) / 6.0;
    q.x += w * (std::cos(theta(s0)) + 4.0 * std::cos(theta(0.5 * (s0 + s1))) + std::cos(theta(s1)));
    q.y += w * (std::sin(theta(s0)) + 4.0 * std::sin(theta(0.5 * (s0 + s1))) + std::sin(theta(s1)));
    if ((k + 1) % per == 0) p[static_cast<std::size_t>((k + 1) / per)] = q;
  }
  return p;
}

// The far-start hybrid at 50 free variables (docs/studies.md, "Far starts", variables 50 / seed 1): 26 points of a
// seeded arc moved by up to 15 % of the spacing, bounds of 75 %, start point and tangent fixed; GA 50 x 10, then
// Ceres from the direct start through the data parameters read off the target (with the length search of
// knot_refine, match_study.cpp). Arg 0 = finite-difference Jacobian, 1 = exact Jacobian.
void BM_match_hybrid_far_50(benchmark::State& state) {
  constexpr std::size_t kPoints = 26;
  constexpr std::uint64_t kSeed = 1;
  const std::vector<Vec3> truth = seeded_arc(kPoints, kSeed);
  const double spacing = 40.0 / static_cast<double>(kPoints - 1);
  CurvatureMatchSetup s;
  s.points = truth;
  s.start_tangent = truth[1] - truth[0];
  s.lower.assign(kPoints, Vec3{0.75 * spacing, 0.75 * spacing, 0});
  s.lower[0] = Vec3{};
  s.upper = s.lower;
  hula::Rng rng(100 + kSeed);
  for (std::size_t i = 1; i < kPoints; ++i)
    for (std::size_t c = 0; c < 2; ++c) s.points[i][c] += rng.uniform(-0.15 * spacing, 0.15 * spacing);
  s.target = hula::studies::Profile::from_samples(
      hula::studies::uniform_abscissae(kSamples),
      hula::studies::curvature_profile_of(truth, 2, kSamples, s.start_tangent, std::nullopt));
  const CurvatureMatch match(s);
  hula::studies::MatchStudy study;
  study.method = hula::studies::MatchMethod::Hybrid;
  study.header.seed = 7;
  study.ga.generations = 10;
  study.lm.exact_jacobian = state.range(0) == 1;
  double mean = 0.0;
  std::size_t iterations = 0;
  for (auto _ : state) {
    const auto r = hula::studies::run_curvature_match(match, study);
    benchmark::DoNotOptimize(r.best.data());
    mean = r.after.mean;
    iterations = r.lm->iterations;
  }
  state.counters["variables"] = static_cast<double>(match.dimension());
  state.counters["mean_distance"] = mean;
  state.counters["lm_iterations"] = static_cast<double>(iterations);
}
BENCHMARK(BM_match_hybrid_far_50)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Curvature + torsion (NSGA-II 60 x 120, 12 free coordinates) on five helix points with clamped ends: the
// set-up of examples/studies/match-curvature-torsion-helix.json. Arg 1 = with the LM polish.
void BM_match_curvature_torsion(benchmark::State& state) {
  std::vector<Vec3> truth(5);
  for (std::size_t k = 0; k < 5; ++k) {
    const double a = 1.6 * static_cast<double>(k) / 4.0 * M_PI;
    truth[k] = {10 * std::sin(a), 10 * (1 - std::cos(a)), 4 * a};
  }
  CurvatureMatchSetup s;
  s.dimension = 3;
  s.start_tangent = Vec3{1, 0, 0};
  s.end_tangent = Vec3{10 * std::cos(1.6 * M_PI), 10 * std::sin(1.6 * M_PI), 4};
  s.target = hula::studies::Profile::from_samples(
      hula::studies::uniform_abscissae(kSamples),
      hula::studies::curvature_profile_of(truth, 3, kSamples, s.start_tangent, s.end_tangent));
  s.torsion_target = hula::studies::Profile::from_samples(
      hula::studies::uniform_abscissae(kSamples),
      hula::studies::torsion_profile_of(truth, kSamples, s.start_tangent, s.end_tangent));
  const Vec3 shift[] = {{0, 0, 0}, {0.8, -0.6, 0.5}, {-0.7, 0.9, -0.4}, {0.6, 0.5, -0.8}, {-0.5, -0.7, 0.6}};
  s.points = truth;
  for (std::size_t k = 0; k < 5; ++k) s.points[k] = truth[k] + shift[k];
  s.lower.assign(5, Vec3{3, 3, 3});
  s.upper = s.lower;
  s.lower[0] = s.upper[0] = Vec3{};
  const CurvatureMatch match(s);
  hula::studies::TorsionMatchSettings settings;
  settings.population = 60;
  settings.generations = 120;
  settings.polish = state.range(0) != 0;
  double worst = 0.0;
  for (auto _ : state) {
    const auto r = hula::studies::run_curvature_torsion_match(match, settings, 1);
    benchmark::DoNotOptimize(r.front.data());
    worst = std::max(r.front[r.compromise].curvature, r.front[r.compromise].torsion);
  }
  state.counters["compromise_max_error"] = worst;
}
BENCHMARK(BM_match_curvature_torsion)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
