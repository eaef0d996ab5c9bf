// SPDX-License-Identifier: MIT
// Benchmarks of the law evaluation tape: curvature κ = |r'×r''|/|r'|³ of the
// helix law vec(2cos t, 2sin t, 0.5t), compiled with its derivatives to one
// tape, against the same formula hand-written in C++ (target: within
// 3×), plus derivative evaluation through CurveEvaluator.
//
// Run: cmake --preset bench && cmake --build --preset bench --target bench_law_tape
//      ./build/bench/bench/law/bench_law_tape
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace {

std::vector<double> parameters(std::size_t n) {
  std::vector<double> ts(n);
  // fixed, non-uniform sample of [0, 4π] (no RNG needed: the formula has no data-dependent branches)
  for (std::size_t i = 0; i < n; ++i)
    ts[i] = 12.566370614359172 * std::fmod(0.6180339887498949 * static_cast<double>(i), 1.0);
  return ts;
}

void BM_law_tape_curvature(benchmark::State& state) {
  using namespace hula::law;
  Context ctx;
  const Law r = parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx);
  const Law d1 = derivative(r, "t");
  const Law d2 = derivative(r, "t", 2);
  const Law kappa[1] = {norm(cross(d1, d2)) / pow(norm(d1), 3.0)};
  const std::string in[1] = {"t"};
  const Tape tape = Tape::compile(kappa, in);
  Workspace w = tape.make_workspace();
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> ts = parameters(n);
  std::vector<double> out(n);
  for (auto _ : state) {
    tape.evaluate(ts, out, w, {});
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
  state.counters["instructions"] = static_cast<double>(tape.instruction_count());
}
BENCHMARK(BM_law_tape_curvature)->Arg(1024);

void BM_law_handwritten_curvature(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> ts = parameters(n);
  std::vector<double> out(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      const double t = ts[i];
      const double s = std::sin(t), c = std::cos(t);
      const double d1x = -2 * s, d1y = 2 * c, d1z = 0.5;
      const double d2x = -2 * c, d2y = -2 * s, d2z = 0.0;
      const double cx = d1y * d2z - d1z * d2y, cy = d1z * d2x - d1x * d2z, cz = d1x * d2y - d1y * d2x;
      const double num = std::sqrt(cx * cx + cy * cy + cz * cz);
      const double len = std::sqrt(d1x * d1x + d1y * d1y + d1z * d1z);
      out[i] = num / (len * len * len);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_law_handwritten_curvature)->Arg(1024);

void BM_law_curve_evaluator_d3(benchmark::State& state) {
  using namespace hula::law;
  Context ctx;
  const CurveEvaluator ev(parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), "t", 3);
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> ts = parameters(n);
  std::vector<hula::Vec3> out(n * 4);
  for (auto _ : state) {
    ev.derivatives(ts, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_law_curve_evaluator_d3)->Arg(1024);

}  // namespace
