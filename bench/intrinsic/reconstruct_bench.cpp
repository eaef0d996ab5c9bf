// SPDX-License-Identifier: MIT
// Benchmarks of curves from natural equations: reconstruction of a 10-turn
// circular helix (a = 1, b = 0.25: κ = a/(a²+b²), τ = b/(a²+b²)) to 1e-9 by
// the Frenet–Serret integration (target: under 5 ms), the NURBS fit
// of that curve within 1e-9, and a planar Euler spiral κ = s (exact angle,
// adaptive Gauss–Legendre). Each iteration checks its own accuracy once
// outside the timed loop, so a fast wrong answer cannot pass unnoticed.
//
// Run: cmake --preset bench && cmake --build --preset bench --target bench_intrinsic_reconstruct
//      ./build/bench/bench/intrinsic/bench_intrinsic_reconstruct
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/parser.hpp"

namespace {

using namespace hula;
using namespace hula::intrinsic;

constexpr double kA = 1.0, kB = 0.25;

struct HelixInput {
  // Declaration order matters: kappa and tau are initialised from c.
  double c = std::sqrt(kA * kA + kB * kB);
  double length = 10.0 * 2.0 * std::numbers::pi * c;
  StartFrame start{{kA, 0.0, 0.0}, Vec3{0.0, kA, kB} / c, {-1.0, 0.0, 0.0}};
  law::Context ctx;
  law::Law kappa, tau;
  HelixInput() : kappa(ctx.constant(kA / (c * c))), tau(ctx.constant(kB / (c * c))) {}
  [[nodiscard]] Vec3 exact(double s) const { return {kA * std::cos(s / c), kA * std::sin(s / c), kB * s / c}; }
};

ReconstructionOptions options() {
  ReconstructionOptions o;
  o.tolerance = 1e-9;
  return o;
}

double max_error(const HelixInput& in, const IntrinsicCurve& curve) {
  double worst = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const double s = in.length * i / 2000.0;
    worst = std::max(worst, distance(curve.evaluate(s).position, in.exact(s)));
  }
  return worst;
}

void BM_intrinsic_reconstruct_helix(benchmark::State& state) {
  const HelixInput in;
  const IntrinsicCurve check = reconstruct(in.kappa, in.tau, "s", in.length, in.start, options());
  state.counters["max_error"] = max_error(in, check);
  state.counters["steps"] = static_cast<double>(check.nodes().size() - 1);
  for (auto _ : state) {
    IntrinsicCurve c = reconstruct(in.kappa, in.tau, "s", in.length, in.start, options());
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_intrinsic_reconstruct_helix)->Unit(benchmark::kMillisecond);

void BM_intrinsic_reconstruct_and_fit_helix(benchmark::State& state) {
  const HelixInput in;
  NurbsFitOptions fo;
  fo.tolerance = 1e-9;
  {
    const NurbsFitResult f = fit_nurbs(reconstruct(in.kappa, in.tau, "s", in.length, in.start, options()), fo);
    state.counters["control_points"] = static_cast<double>(f.curve.control_points().size());
    state.counters["max_deviation"] = f.max_deviation;
  }
  for (auto _ : state) {
    NurbsFitResult f = fit_nurbs(reconstruct(in.kappa, in.tau, "s", in.length, in.start, options()), fo);
    benchmark::DoNotOptimize(f);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_intrinsic_reconstruct_and_fit_helix)->Unit(benchmark::kMillisecond);

void BM_intrinsic_reconstruct_euler_spiral(benchmark::State& state) {
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {"s"};
  const law::Law kappa = law::parse("s", ctx, po);
  for (auto _ : state) {
    IntrinsicCurve c = reconstruct_planar(kappa, "s", 5.0, {}, options());
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_intrinsic_reconstruct_euler_spiral)->Unit(benchmark::kMillisecond);

}  // namespace
