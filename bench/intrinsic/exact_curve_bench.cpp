// SPDX-License-Identifier: MIT
// Benchmarks of exact intrinsic curves (issue 26): the Frenet analysis of a
// natural curve from its exact evaluator (κ, κ', τ from the laws, frame
// integrated) against the same analysis of its NURBS stand-in, both over the
// same ring of arc lengths, for a log-aesthetic curve (planar, exact angle)
// and a helix (Frenet–Serret); and the construction of the curve value
// (integration + the 1e-6 stand-in fit). Each benchmark reports the error of
// κ' against the closed form, measured once outside the timed loop, so a fast
// wrong answer shows.
//
// Run: cmake --preset bench && cmake --build build/bench -j1 --target bench_intrinsic_exact_curve
//      taskset -c 1 ./build/bench/bench/intrinsic/bench_intrinsic_exact_curve
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "hula/diffgeom/frenet.hpp"
#include "hula/intrinsic/log_aesthetic.hpp"
#include "hula/intrinsic/natural_curve.hpp"

namespace {

using namespace hula;

// κ = 1/(1.5 + 0.4 s): the log-aesthetic curve (α = 1), L = 6.
const intrinsic::LogAestheticCurve kSpiral{1.0, 1.5, 0.4, 6.0};

curve::Curve spiral() { return intrinsic::natural_curve(kSpiral.natural_data(), curve::kApproximationTolerance); }

curve::Curve helix() {
  curve::NaturalData d;
  d.curvature = "0.8";
  d.torsion = "0.4";
  d.length = 20.0;
  return intrinsic::natural_curve(d, curve::kApproximationTolerance);
}

// A ring of 8 batches of n seeded arc lengths in [0, L] (no cache flattery from one sorted batch).
std::vector<std::vector<double>> rings(double length, std::size_t n) {
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(0.0, length);
  std::vector<std::vector<double>> out(8, std::vector<double>(n));
  for (auto& r : out)
    for (double& s : r) s = u(rng);
  return out;
}

// Largest relative error of κ' against −λ κ² (α = 1) over a batch.
double kappa_prime_error(const std::vector<diffgeom::FrenetPoint>& f) {
  double worst = 0.0;
  for (const auto& p : f) {
    const double k = 1.0 / (1.5 + 0.4 * p.t), want = -0.4 * k * k;
    worst = std::max(worst, std::fabs(p.curvature_derivative - want) / std::fabs(want));
  }
  return worst;
}

template <class Subject>
void frenet_loop(benchmark::State& state, const Subject& subject, double length, bool check_spiral) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto ss = rings(length, n);
  std::vector<diffgeom::FrenetPoint> out(n);
  if (check_spiral) {
    diffgeom::frenet(subject, ss[0], out);
    state.counters["kappa_prime_rel_error"] = kappa_prime_error(out);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    diffgeom::frenet(subject, ss[k++ % ss.size()], out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

void BM_intrinsic_exact_frenet_spiral(benchmark::State& state) {
  const curve::Curve c = spiral();
  frenet_loop(state, c, kSpiral.length, true);
}
BENCHMARK(BM_intrinsic_exact_frenet_spiral)->Arg(1000);

void BM_intrinsic_standin_frenet_spiral(benchmark::State& state) {
  const curve::Curve c = spiral();
  frenet_loop(state, c.nurbs(), kSpiral.length, true);
}
BENCHMARK(BM_intrinsic_standin_frenet_spiral)->Arg(1000);

void BM_intrinsic_exact_frenet_helix(benchmark::State& state) {
  const curve::Curve c = helix();
  frenet_loop(state, c, 20.0, false);
}
BENCHMARK(BM_intrinsic_exact_frenet_helix)->Arg(1000);

void BM_intrinsic_standin_frenet_helix(benchmark::State& state) {
  const curve::Curve c = helix();
  frenet_loop(state, c.nurbs(), 20.0, false);
}
BENCHMARK(BM_intrinsic_standin_frenet_helix)->Arg(1000);

// The curve value: parse, integrate, exact evaluator, and the 1e-6 stand-in fit.
void BM_intrinsic_natural_curve_spiral(benchmark::State& state) {
  const curve::NaturalData d = kSpiral.natural_data();
  for (auto _ : state) {
    curve::Curve c = intrinsic::natural_curve(d, curve::kApproximationTolerance);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_intrinsic_natural_curve_spiral)->Unit(benchmark::kMillisecond);

void BM_intrinsic_natural_curve_helix(benchmark::State& state) {
  for (auto _ : state) {
    curve::Curve c = helix();
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_intrinsic_natural_curve_helix)->Unit(benchmark::kMillisecond);

}  // namespace
