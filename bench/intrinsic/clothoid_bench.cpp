// SPDX-License-Identifier: MIT
// Benchmark of G1 and G2 Hermite clothoid interpolation (Bertolazzi–Frego, intrinsic/clothoid.hpp;
// target: at most 1 µs per G1 segment). A ring of 1024 seeded problems (end angles relative to the
// chord uniform in (−π/2, π/2), chords of length 0.5–2 in any direction, for G2 end curvatures with
// |κ| · chord ≤ 5) is solved round-robin; every problem's end point is checked once outside the timed loop
// (the last segment's quadrature end within 1e-12 of the target).
//
// Run: cmake --preset bench && cmake --build --preset bench --target bench_intrinsic_clothoid
//      ./build/bench/bench/intrinsic/bench_intrinsic_clothoid
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "hula/intrinsic/clothoid.hpp"

namespace {

using namespace hula;
using namespace hula::intrinsic;

struct Problem {
  Vec3 p0, p1;
  double theta0 = 0.0, theta1 = 0.0, kappa0 = 0.0, kappa1 = 0.0;
};

std::vector<Problem> problems() {
  std::mt19937_64 rng(2014);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Problem> out(1024);
  for (Problem& p : out) {
    const double dir = 2.0 * std::numbers::pi * u(rng), r = 0.5 + 1.5 * u(rng);
    p.p0 = {u(rng), u(rng), 0.0};
    p.p1 = p.p0 + Vec3{r * std::cos(dir), r * std::sin(dir), 0.0};
    p.theta0 = dir + std::numbers::pi * (u(rng) - 0.5);
    p.theta1 = dir + std::numbers::pi * (u(rng) - 0.5);
    p.kappa0 = 10.0 * (u(rng) - 0.5) / r;
    p.kappa1 = 10.0 * (u(rng) - 0.5) / r;
    const ClothoidSegment s = fit_clothoid_g1(p.p0, p.theta0, p.p1, p.theta1).segment;
    if (distance(s.point(s.length), p.p1) > 1e-12 * std::max(1.0, s.length))
      throw std::runtime_error("clothoid bench: a G1 fit misses its end point");
    const ClothoidG2Result g2 = fit_clothoid_g2(p.p0, p.theta0, p.kappa0, p.p1, p.theta1, p.kappa1);
    const ClothoidSegment& last = g2.segments[2];
    if (distance(last.point(last.length), p.p1) > 1e-12 * std::max(1.0, g2.length()))
      throw std::runtime_error("clothoid bench: a G2 fit misses its end point");
  }
  return out;
}

void BM_intrinsic_clothoid_g1_fit(benchmark::State& state) {
  const std::vector<Problem> ring = problems();
  std::size_t i = 0;
  for (auto _ : state) {
    const Problem& p = ring[i++ & 1023];
    benchmark::DoNotOptimize(fit_clothoid_g1(p.p0, p.theta0, p.p1, p.theta1));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_intrinsic_clothoid_g1_fit);

// One G2 fit: the G1 start, then Newton on the reduced 2×2 system (about 4 iterations, 3 arcs each).
void BM_intrinsic_clothoid_g2_fit(benchmark::State& state) {
  const std::vector<Problem> ring = problems();
  std::size_t i = 0;
  for (auto _ : state) {
    const Problem& p = ring[i++ & 1023];
    benchmark::DoNotOptimize(fit_clothoid_g2(p.p0, p.theta0, p.kappa0, p.p1, p.theta1, p.kappa1));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_intrinsic_clothoid_g2_fit);

// Splines through N points of a seeded closed loop (the three-lobed r = 1 + 0.25 cos 3t at angles jittered by
// ±0.3 of the spacing; noise of the order of the spacing makes zigzag data, on which G2 Newton may fail): the time
// per segment is the reported time divided by N (items = segments). G2 is Newton on the N tangent angles (each
// iteration N G1 fits and their end-curvature derivatives, one cyclic tridiagonal solve); G1 is the N
// three-point-circle angles and N G1 fits; biarcs the same angles and 2N arcs in closed form.
std::vector<Vec3> loop(int n) {
  std::mt19937 rng(26);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (i + 0.3 * u(rng)) / n, rho = 1.0 + 0.25 * std::cos(3 * t);
    p.push_back({rho * std::cos(t), rho * std::sin(t), 0.0});
  }
  return p;
}

void spline_bench(benchmark::State& state, int continuity, bool biarc) {
  const std::vector<Vec3> pts = loop(static_cast<int>(state.range(0)));
  hula::intrinsic::ClothoidSplineOptions o;
  o.closed = true;
  o.continuity = continuity;
  int iterations = 0;
  for (auto _ : state) {
    const hula::intrinsic::ClothoidSplineResult r = biarc ? fit_biarc_spline(pts, o) : fit_clothoid_spline(pts, o);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.segments.data());
  }
  state.counters["newton"] = iterations;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}

void BM_intrinsic_clothoid_spline_g2_closed(benchmark::State& state) { spline_bench(state, 2, false); }
BENCHMARK(BM_intrinsic_clothoid_spline_g2_closed)->Arg(16)->Arg(128)->Arg(1024);
void BM_intrinsic_clothoid_spline_g1_closed(benchmark::State& state) { spline_bench(state, 1, false); }
BENCHMARK(BM_intrinsic_clothoid_spline_g1_closed)->Arg(128);
void BM_intrinsic_biarc_spline_closed(benchmark::State& state) { spline_bench(state, 1, true); }
BENCHMARK(BM_intrinsic_biarc_spline_closed)->Arg(128);

void BM_intrinsic_fresnel(benchmark::State& state) {
  double x = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fresnel(x));
    x = x > 8.0 ? 0.0 : x + 0.01;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_intrinsic_fresnel);

}  // namespace
