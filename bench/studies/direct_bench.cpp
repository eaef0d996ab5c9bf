// SPDX-License-Identifier: MIT
// Benchmarks of direct reconstruction from prescribed profiles
// (studies/direct_reconstruction): the initial-value problem (one
// natural-equation solve) and the boundary-value problem (minimum-norm
// Gauss–Newton on Bernstein corrections until the end point and tangent hold to
// 1e-9 L), planar and space, with and without the NURBS fit. Each benchmark
// runs once outside the timed loop and reports what it achieved (end errors,
// iterations, mean |κ − κ*|), so a fast wrong answer cannot pass unnoticed.
//
// Run: cmake --preset bench && cmake --build build/bench -j 1 --target bench_studies_direct
//      ./build/bench/bench/studies/bench_studies_direct
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

// The target-from-a-known-curve helper shared with the tests (thesis 8.2.1 validation method).
#include "hula/law/parser.hpp"
#include "hula/studies/direct_reconstruction.hpp"
#include "hula/testing/curvature_target.hpp"

namespace {

using namespace hula;
using namespace hula::studies;

// Planar target: κ*(u) = 0.5 + 0.1 sin(2πu) on L = 5; the end of the unperturbed arc R = 2.
// Space target: κ*(u) = 0.8 + 0.05 sin(2πu), τ*(u) = 0.4 − 0.05u on L = 10; the end of the helix
// κ = 0.8, τ = 0.4.
struct Targets {
  law::Context ctx;
  Profile profile(const std::string& text) {
    law::ParseOptions po;
    po.parameters = {"u"};
    return Profile::from_law(law::parse(text, ctx, po), "u");
  }
  DirectReconstructionProblem planar(bool constrained) {
    const double R = 2.0, L = 5.0;
    DirectReconstructionProblem p{.curvature = profile("0.5 + 0.1*sin(2*pi*u)"), .length = L};
    if (constrained) {
      p.end_point = Vec3{R * std::sin(L / R), R * (1.0 - std::cos(L / R)), 0.0};
      p.end_tangent = Vec3{std::cos(L / R), std::sin(L / R), 0.0};
    }
    return p;
  }
  DirectReconstructionProblem space(bool constrained) {
    const double k = 0.8, t = 0.4, L = 10.0;
    const double rho = k / (k * k + t * t), h = t / (k * k + t * t), c = std::hypot(rho, h);
    const auto point = [&](double s) { return Vec3{rho * std::cos(s / c), rho * std::sin(s / c), h * s / c}; };
    const auto tangent = [&](double s) { return Vec3{-rho * std::sin(s / c), rho * std::cos(s / c), h} / c; };
    DirectReconstructionProblem p{.curvature = profile("0.8 + 0.05*sin(2*pi*u)"),
                                  .torsion = profile("0.4 - 0.05*u"),
                                  .length = L,
                                  .start = {point(0.0), tangent(0.0), Vec3{-1.0, 0.0, 0.0}}};
    if (constrained) {
      p.end_point = point(L);
      p.end_tangent = tangent(L);
    }
    return p;
  }
};

void run(benchmark::State& state, const DirectReconstructionProblem& problem, bool fit) {
  DirectReconstructionOptions o;
  o.fit = fit;
  const DirectReconstructionResult check = reconstruct_direct(problem, o);
  state.counters["iterations"] = check.iterations;
  state.counters["reconstructions"] = check.reconstructions;
  state.counters["end_point_error_rel"] = check.end_point_error / check.length;
  state.counters["end_tangent_error"] = check.end_tangent_error;
  state.counters["mean_dkappa"] = check.mean_curvature_deviation;
  if (!check.planar) state.counters["mean_dtau"] = check.mean_torsion_deviation;
  if (check.nurbs) state.counters["nurbs_deviation"] = check.nurbs->max_deviation;
  for (auto _ : state) {
    DirectReconstructionResult r = reconstruct_direct(problem, o);
    benchmark::DoNotOptimize(r);
  }
}

void BM_studies_direct_ivp_planar(benchmark::State& state) {
  Targets t;
  run(state, t.planar(false), false);
}
void BM_studies_direct_bvp_planar(benchmark::State& state) {
  Targets t;
  run(state, t.planar(true), false);
}
void BM_studies_direct_bvp_planar_fit(benchmark::State& state) {
  Targets t;
  run(state, t.planar(true), true);
}
void BM_studies_direct_ivp_space(benchmark::State& state) {
  Targets t;
  run(state, t.space(false), false);
}
void BM_studies_direct_bvp_space(benchmark::State& state) {
  Targets t;
  run(state, t.space(true), false);
}
void BM_studies_direct_bvp_space_fit(benchmark::State& state) {
  Targets t;
  run(state, t.space(true), true);
}

// Target from a known curve (the thesis's validation method, 8.2.1): the cubic Bézier of the unit
// test tabulated at 201 arc-length samples (natural cubic spline profile), reconstructed freely and
// held to the Bézier's own end.
DirectReconstructionProblem bezier_problem(bool constrained) {
  const nurbs::NurbsCurve bez(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2.5, -0.5, 0}, {3.5, 1, 0}});
  const hula::testing::CurvatureTarget t = hula::testing::planar_curvature_target(bez, 201);
  DirectReconstructionProblem p{.curvature = t.profile, .length = t.length, .start = t.start};
  if (constrained) {
    p.end_point = t.end_point;
    p.end_tangent = t.end_tangent;
  }
  return p;
}
void BM_studies_direct_ivp_bezier_target(benchmark::State& state) { run(state, bezier_problem(false), false); }
void BM_studies_direct_bvp_bezier_target(benchmark::State& state) { run(state, bezier_problem(true), false); }

BENCHMARK(BM_studies_direct_ivp_bezier_target)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_bvp_bezier_target)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_ivp_planar)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_bvp_planar)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_bvp_planar_fit)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_ivp_space)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_bvp_space)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_studies_direct_bvp_space_fit)->Unit(benchmark::kMillisecond);

}  // namespace
