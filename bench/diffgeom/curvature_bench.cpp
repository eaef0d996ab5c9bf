// SPDX-License-Identifier: MIT
// Curvature + torsion per point of a cubic with 64 control points (issue 27's judged figures): our fast
// path curvature_torsion beside the hand-written power-basis reference (bench/reference/power_basis.hpp:
// D3, then kappa = sqrt(|a|^2 / |C'|^6) and tau = (a . C''') / |a|^2 with a = C' x C''), on the same
// 65,536 distinct parameters, sorted or shuffled, evaluated in chunks of 1,024 into reused outputs; the
// full Frenet batch; and Open CASCADE's GeomLProp_CLProps curvature (it has no torsion) in the same run.
// Outputs are checked against the reference (1e-9 relative) before timing. Items processed = points.
#include <benchmark/benchmark.h>

#include <GeomLProp_CLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/core/simd.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/testing/occt_curve.hpp"
#include "reference/power_basis.hpp"

namespace {

using hula::Rng;
using hula::Vec3;
using hula::nurbs::NurbsCurve;

constexpr std::size_t kDistinct = 65536;
constexpr std::size_t kChunk = 1024;

// The instruction set in the JSON context (docs/benchmarks.md names it with each figure).
const bool kSimdContext = [] {
  benchmark::AddCustomContext("simd", std::string(hula::simd_level_name(hula::simd_level())));
  return true;
}();

NurbsCurve make_curve() {
  Rng rng(64);
  std::vector<Vec3> P(64);
  for (auto& p : P) p = {rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
  return NurbsCurve(hula::nurbs::KnotVector::uniform_clamped(64, 3), P);
}

const std::vector<double>& params(bool sorted) {
  static const std::array<std::vector<double>, 2> t = [] {
    Rng rng(7);
    std::vector<double> v(kDistinct);
    for (auto& x : v) x = rng.uniform();
    std::vector<double> s = v;
    std::sort(s.begin(), s.end());
    return std::array<std::vector<double>, 2>{v, s};
  }();
  return t[sorted ? 1 : 0];
}

// Checks kappa (and tau unless empty) against the reference; false = the row errs.
bool agrees(benchmark::State& state, const NurbsCurve& c, const std::vector<double>& t,
            const std::vector<double>& kappa, const std::vector<double>& tau) {
  const hula::bench::PowerBasisCurve<3, false> ref(c);
  std::size_t s = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    double k = 0.0, w = 0.0;
    ref.curvature_torsion(t[i], s, k, w);
    worst = std::max(worst, std::fabs(kappa[i] - k) / k);
    if (!tau.empty()) worst = std::max(worst, std::fabs(tau[i] - w) / std::max(std::fabs(w), k));
  }
  if (!(worst <= 1e-9)) {
    state.SkipWithError(("differs from the reference by " + std::to_string(worst) + " (relative)").c_str());
    return false;
  }
  return true;
}

void finish(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kDistinct));
}

void BM_diffgeom_curvature_torsion_ours(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto& t = params(state.range(0) != 0);
  std::vector<double> all_k(t.size()), all_t(t.size());
  hula::diffgeom::curvature_torsion(c, t, all_k, all_t);
  if (!agrees(state, c, t, all_k, all_t)) return;
  std::vector<double> kappa(kChunk), tau(kChunk);
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      hula::diffgeom::curvature_torsion(c, std::span<const double>(t).subspan(i, kChunk), kappa, tau);
      benchmark::DoNotOptimize(kappa.data());
      benchmark::DoNotOptimize(tau.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}
BENCHMARK(BM_diffgeom_curvature_torsion_ours)->ArgName("sorted")->Arg(1)->Arg(0);

void BM_diffgeom_curvature_torsion_reference(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto& t = params(state.range(0) != 0);
  const hula::bench::PowerBasisCurve<3, false> ref(c);
  std::vector<double> kappa(kChunk), tau(kChunk);
  std::size_t s = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      for (std::size_t j = 0; j < kChunk; ++j) ref.curvature_torsion(t[i + j], s, kappa[j], tau[j]);
      benchmark::DoNotOptimize(kappa.data());
      benchmark::DoNotOptimize(tau.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}
BENCHMARK(BM_diffgeom_curvature_torsion_reference)->ArgName("sorted")->Arg(1)->Arg(0);

void BM_diffgeom_frenet_batch(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto& t = params(state.range(0) != 0);
  std::vector<hula::diffgeom::FrenetPoint> out(kChunk);
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      hula::diffgeom::frenet(c, std::span<const double>(t).subspan(i, kChunk), out);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}
BENCHMARK(BM_diffgeom_frenet_batch)->ArgName("sorted")->Arg(1)->Arg(0);

void BM_diffgeom_curvature_occt(benchmark::State& state) {
  const NurbsCurve c = make_curve();
  const auto& t = params(state.range(0) != 0);
  const Handle(Geom_BSplineCurve) oc = hula::testing::to_occt(c);
  GeomLProp_CLProps props(oc, 2, 1e-12);
  std::vector<double> all(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    props.SetParameter(t[i]);
    all[i] = props.Curvature();
  }
  if (!agrees(state, c, t, all, {})) return;
  std::vector<double> kappa(kChunk);
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      for (std::size_t j = 0; j < kChunk; ++j) {
        props.SetParameter(t[i + j]);
        kappa[j] = props.Curvature();
      }
      benchmark::DoNotOptimize(kappa.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}
BENCHMARK(BM_diffgeom_curvature_occt)->ArgName("sorted")->Arg(1)->Arg(0);

}  // namespace
