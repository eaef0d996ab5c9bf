// SPDX-License-Identifier: MIT
// Benchmarks of definite integrals (issue 26): the symbolic path (antiderivative
// found, its limits checked at the poles of the integrand), the improper
// numeric path (tanh-sinh on the integrand re-expanded about its singular end)
// and the smooth numeric path (Gauss–Kronrod), each checked once against its
// closed form outside the timed loop.
//
// Run: cmake --preset bench && cmake --build build/bench -j1 --target bench_law_integrate
//      taskset -c 1 ./build/bench/bench/law/bench_law_integrate
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "hula/law/antiderivative.hpp"
#include "hula/law/parser.hpp"

namespace {

using namespace hula::law;

void run(benchmark::State& state, const char* text, double a, double b, double want) {
  Context ctx;
  const Law f = parse(text, ctx);
  const DefiniteIntegralResult check = definite_integral(f, "t", a, b);
  state.counters["rel_error"] = std::fabs(check.value - want) / std::fabs(want);
  state.counters["symbolic"] = check.method == IntegralMethod::Symbolic ? 1 : 0;
  for (auto _ : state) {
    DefiniteIntegralResult r = definite_integral(f, "t", a, b);
    benchmark::DoNotOptimize(r.value);
  }
  state.SetItemsProcessed(state.iterations());
}

// By parts, closed form (t − 1)eᵗ.
void BM_law_integral_symbolic_by_parts(benchmark::State& state) { run(state, "t*exp(t)", 0, 1, 1.0); }
BENCHMARK(BM_law_integral_symbolic_by_parts)->Unit(benchmark::kMicrosecond);

// Improper, closed form t log t − t with its limit at 0.
void BM_law_integral_symbolic_improper(benchmark::State& state) { run(state, "log(t)", 0, 1, -1.0); }
BENCHMARK(BM_law_integral_symbolic_improper)->Unit(benchmark::kMicrosecond);

// Improper without a closed form: tanh-sinh at t = 0.
void BM_law_integral_tanh_sinh(benchmark::State& state) {
  run(state, "log(sin(t))", 0, std::numbers::pi / 2, -std::numbers::pi / 2 * std::log(2.0));
}
BENCHMARK(BM_law_integral_tanh_sinh)->Unit(benchmark::kMicrosecond);

// Smooth without a closed form: Gauss–Kronrod.
void BM_law_integral_gauss_kronrod(benchmark::State& state) {
  run(state, "exp(-t^2)", 0, 2, std::sqrt(std::numbers::pi) / 2 * std::erf(2.0));
}
BENCHMARK(BM_law_integral_gauss_kronrod)->Unit(benchmark::kMicrosecond);

}  // namespace
