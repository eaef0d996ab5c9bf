// SPDX-License-Identifier: MIT
// Curvature + torsion per point of a cubic with 64 control points over 4096
// sorted parameters (target ≤ 15 ns/point single-threaded): our fast
// path curvature_torsion, the full Frenet batch, the bare derivative batch they
// build on, and Open CASCADE's GeomLProp_CLProps curvature (it has no torsion)
// in the same run. Items processed = points.
#include <benchmark/benchmark.h>

#include <GeomLProp_CLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/testing/occt_curve.hpp"

namespace {

using hula::Rng;
using hula::Vec3;
using hula::nurbs::NurbsCurve;

constexpr std::size_t kPoints = 4096;

NurbsCurve make_curve() {
  Rng rng(64);
  std::vector<Vec3> P(64);
  for (auto& p : P) p = {rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
  return NurbsCurve(hula::nurbs::KnotVector::uniform_clamped(64, 3), P);
}

std::vector<double> sorted_params() {
  Rng rng(7);
  std::vector<double> t(kPoints);
  for (auto& x : t) x = rng.uniform();
  std::sort(t.begin(), t.end());
  return t;
}

void BM_diffgeom_curvature_torsion(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto t = sorted_params();
  std::vector<double> kappa(t.size()), tau(t.size());
  hula::diffgeom::curvature_torsion(c, t, kappa, tau);  // builds the span cache outside the timed loop
  for (auto _ : state) {
    hula::diffgeom::curvature_torsion(c, t, kappa, tau);
    benchmark::DoNotOptimize(kappa.data());
    benchmark::DoNotOptimize(tau.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_diffgeom_curvature_torsion);

void BM_diffgeom_frenet_batch(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto t = sorted_params();
  std::vector<hula::diffgeom::FrenetPoint> out(t.size());
  hula::diffgeom::frenet(c, t, out);
  for (auto _ : state) {
    hula::diffgeom::frenet(c, t, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_diffgeom_frenet_batch);

void BM_diffgeom_derivatives3_only(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto t = sorted_params();
  std::vector<Vec3> out(t.size() * 4);
  c.derivatives(t, 3, out);
  for (auto _ : state) {
    c.derivatives(t, 3, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_diffgeom_derivatives3_only);

void BM_diffgeom_occt_clprops_curvature(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto t = sorted_params();
  const Handle(Geom_BSplineCurve) oc = hula::testing::to_occt(c);
  GeomLProp_CLProps props(oc, 2, 1e-12);
  std::vector<double> kappa(t.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      props.SetParameter(t[i]);
      kappa[i] = props.Curvature();
    }
    benchmark::DoNotOptimize(kappa.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.size()));
}
BENCHMARK(BM_diffgeom_occt_clprops_curvature);

}  // namespace
