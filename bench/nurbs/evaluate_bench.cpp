// SPDX-License-Identifier: MIT
// Evaluation cost per point of a cubic with 64 control points, ours beside
// Open CASCADE in the same run (Geom_BSplineCurve::D3 and the cached
// GeomAdaptor_Curve). Inputs come from fixed seeds outside the timed loop.
// Items processed = points, so the "items_per_second" column reads as points/s.
#include <benchmark/benchmark.h>

#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/testing/occt_curve.hpp"

namespace {

using hula::Rng;
using hula::Vec3;
using hula::nurbs::NurbsCurve;

constexpr std::size_t kPoints = 4096;

NurbsCurve make_curve(bool rational) {
  Rng rng(64);
  std::vector<Vec3> P(64);
  for (auto& p : P) p = {rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
  std::vector<double> w;
  if (rational)
    for (int i = 0; i < 64; ++i) w.push_back(rng.uniform(0.5, 2.0));
  return NurbsCurve(hula::nurbs::KnotVector::uniform_clamped(64, 3), P, w);
}

std::vector<double> params(bool sorted) {
  Rng rng(7);
  std::vector<double> t(kPoints);
  for (auto& x : t) x = rng.uniform();
  if (sorted) std::sort(t.begin(), t.end());
  return t;
}

// args: 0 = rational?, 1 = sorted?
void BM_nurbs_evaluate_batch(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto t = params(state.range(1) != 0);
  std::vector<Vec3> out(t.size());
  c.evaluate(t, out);  // builds the span cache outside the timed loop
  for (auto _ : state) {
    c.evaluate(t, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_nurbs_evaluate_batch)->ArgNames({"rational", "sorted"})->ArgsProduct({{0, 1}, {1, 0}});

void BM_nurbs_derivatives3_batch(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto t = params(state.range(1) != 0);
  std::vector<Vec3> out(t.size() * 4);
  c.derivatives(t, 3, out);
  for (auto _ : state) {
    c.derivatives(t, 3, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_nurbs_derivatives3_batch)->ArgNames({"rational", "sorted"})->ArgsProduct({{0, 1}, {1, 0}});

void BM_nurbs_derivatives3_single(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto t = params(true);
  std::array<Vec3, 4> out;
  for (auto _ : state) {
    for (double x : t) {
      c.derivatives(x, 3, out);
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_nurbs_derivatives3_single)->ArgNames({"rational"})->Arg(0)->Arg(1);

void BM_occt_bspline_D3(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  Handle(Geom_BSplineCurve) occ = hula::testing::to_occt(c);
  const auto t = params(true);
  gp_Pnt p;
  gp_Vec v1, v2, v3;
  for (auto _ : state) {
    for (double x : t) {
      occ->D3(x, p, v1, v2, v3);
      benchmark::DoNotOptimize(p);
      benchmark::DoNotOptimize(v3);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_occt_bspline_D3)->ArgNames({"rational"})->Arg(0)->Arg(1);

void BM_occt_adaptor(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  GeomAdaptor_Curve adaptor(hula::testing::to_occt(c));
  const auto t = params(true);
  gp_Pnt p;
  gp_Vec v1, v2, v3;
  for (auto _ : state) {
    if (state.range(1) == 0) {
      for (double x : t) {
        adaptor.D0(x, p);
        benchmark::DoNotOptimize(p);
      }
    } else {
      for (double x : t) {
        adaptor.D3(x, p, v1, v2, v3);
        benchmark::DoNotOptimize(p);
        benchmark::DoNotOptimize(v3);
      }
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_occt_adaptor)->ArgNames({"rational", "d3"})->ArgsProduct({{0, 1}, {0, 1}});

}  // namespace
