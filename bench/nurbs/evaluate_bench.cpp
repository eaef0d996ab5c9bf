// SPDX-License-Identifier: MIT
// Evaluation cost per point of a cubic with 64 control points (issue 27's judged figures): ours
// (NurbsCurve batch evaluation) beside the hand-written power-basis reference kernel
// (bench/reference/power_basis.hpp) and Open CASCADE's cached GeomAdaptor_Curve, in the same run, on
// the same 65,536 distinct parameters, sorted or shuffled. The parameters are evaluated in chunks of
// 1,024 into one reused output buffer, so the figures measure evaluation, not memory traffic, and a
// shuffled run cannot be memorised by the branch predictor (issue 27: 4,096 repeated parameters were).
// Before timing, every row's outputs are compared with the reference's; a disagreement beyond 1e-9
// (relative to the curve's derivative scale) stops the row with an error instead of timing it.
// Items processed = points, so "items_per_second" reads as points/s.
#include <benchmark/benchmark.h>

#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/core/simd.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
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

// Runs a row at SIMD level `simd` (0 = scalar: one point at a time; 3 = the widest the CPU has) and
// restores the level afterwards.
struct SimdScope {
  hula::SimdLevel saved;
  explicit SimdScope(std::int64_t simd) : saved(hula::set_simd_level(static_cast<hula::SimdLevel>(simd))) {}
  ~SimdScope() { hula::set_simd_level(saved); }
};

NurbsCurve make_curve(bool rational) {
  Rng rng(64);
  std::vector<Vec3> P(64);
  for (auto& p : P) p = {rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
  std::vector<double> w;
  if (rational)
    for (int i = 0; i < 64; ++i) w.push_back(rng.uniform(0.5, 2.0));
  return NurbsCurve(hula::nurbs::KnotVector::uniform_clamped(64, 3), P, w);
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

// Largest |a − b| over the first `n` vectors, relative to the largest |b|.
double relative_difference(const Vec3* a, const Vec3* b, std::size_t n) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    diff = std::max(diff, hula::max_abs(a[i] - b[i]));
    scale = std::max(scale, hula::max_abs(b[i]));
  }
  return diff / scale;
}

// The reference's outputs {C} or {C, C', C'', C'''} at every parameter.
template <bool R>
std::vector<Vec3> reference_values(const NurbsCurve& c, const std::vector<double>& t, int order) {
  const hula::bench::PowerBasisCurve<3, R> ref(c);
  std::vector<Vec3> out(t.size() * static_cast<std::size_t>(order + 1));
  std::size_t s = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (order == 0)
      out[i] = ref.d0(t[i], s);
    else
      ref.d3(t[i], s, &out[4 * i]);
  }
  return out;
}

// Checks `values` (same layout as reference_values) against the reference; false = the row errs.
bool agrees(benchmark::State& state, const NurbsCurve& c, const std::vector<double>& t, int order,
            const std::vector<Vec3>& values) {
  const std::vector<Vec3> ref =
      c.is_rational() ? reference_values<true>(c, t, order) : reference_values<false>(c, t, order);
  const std::size_t stride = static_cast<std::size_t>(order + 1);
  for (std::size_t k = 0; k < stride; ++k) {
    std::vector<Vec3> a(t.size()), b(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      a[i] = values[i * stride + k];
      b[i] = ref[i * stride + k];
    }
    const double d = relative_difference(a.data(), b.data(), t.size());
    if (!(d <= 1e-9)) {
      state.SkipWithError(
          ("derivative " + std::to_string(k) + " differs from the reference by " + std::to_string(d) + " (relative)")
              .c_str());
      return false;
    }
  }
  return true;
}

void finish(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kDistinct));
}

// --- position ---------------------------------------------------------------------------------

void BM_nurbs_d0_ours(benchmark::State& state) {
  const SimdScope simd(state.range(2));
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  std::vector<Vec3> all(t.size());
  c.evaluate(t, all);
  if (!agrees(state, c, t, 0, all)) return;
  std::vector<Vec3> out(kChunk);
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      c.evaluate(std::span<const double>(t).subspan(i, kChunk), out);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}

template <bool R>
void reference_d0(benchmark::State& state, const NurbsCurve& c, const std::vector<double>& t) {
  const hula::bench::PowerBasisCurve<3, R> ref(c);
  std::vector<Vec3> out(kChunk);
  std::size_t s = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      for (std::size_t j = 0; j < kChunk; ++j) out[j] = ref.d0(t[i + j], s);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
}

void BM_nurbs_d0_reference(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  if (c.is_rational())
    reference_d0<true>(state, c, t);
  else
    reference_d0<false>(state, c, t);
  finish(state);
}

void BM_nurbs_d0_occt(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  GeomAdaptor_Curve adaptor(hula::testing::to_occt(c));
  std::vector<Vec3> all(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const gp_Pnt p = adaptor.Value(t[i]);
    all[i] = {p.X(), p.Y(), p.Z()};
  }
  if (!agrees(state, c, t, 0, all)) return;
  std::vector<Vec3> out(kChunk);
  gp_Pnt p;
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      for (std::size_t j = 0; j < kChunk; ++j) {
        adaptor.D0(t[i + j], p);
        out[j] = {p.X(), p.Y(), p.Z()};
      }
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}

// --- position and three derivatives -----------------------------------------------------------

void BM_nurbs_d3_ours(benchmark::State& state) {
  const SimdScope simd(state.range(2));
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  std::vector<Vec3> all(t.size() * 4);
  c.derivatives(t, 3, all);
  if (!agrees(state, c, t, 3, all)) return;
  std::vector<Vec3> out(kChunk * 4);
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      c.derivatives(std::span<const double>(t).subspan(i, kChunk), 3, out);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}

template <bool R>
void reference_d3(benchmark::State& state, const NurbsCurve& c, const std::vector<double>& t) {
  const hula::bench::PowerBasisCurve<3, R> ref(c);
  std::vector<Vec3> out(kChunk * 4);
  std::size_t s = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      for (std::size_t j = 0; j < kChunk; ++j) ref.d3(t[i + j], s, &out[4 * j]);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
}

void BM_nurbs_d3_reference(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  if (c.is_rational())
    reference_d3<true>(state, c, t);
  else
    reference_d3<false>(state, c, t);
  finish(state);
}

void BM_nurbs_d3_occt(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  GeomAdaptor_Curve adaptor(hula::testing::to_occt(c));
  gp_Pnt p;
  gp_Vec v1, v2, v3;
  auto to_vec = [](const gp_XYZ& q) { return Vec3{q.X(), q.Y(), q.Z()}; };
  std::vector<Vec3> all(t.size() * 4);
  for (std::size_t i = 0; i < t.size(); ++i) {
    adaptor.D3(t[i], p, v1, v2, v3);
    all[4 * i] = to_vec(p.XYZ());
    all[4 * i + 1] = to_vec(v1.XYZ());
    all[4 * i + 2] = to_vec(v2.XYZ());
    all[4 * i + 3] = to_vec(v3.XYZ());
  }
  if (!agrees(state, c, t, 3, all)) return;
  std::vector<Vec3> out(kChunk * 4);
  for (auto _ : state) {
    for (std::size_t i = 0; i < t.size(); i += kChunk) {
      for (std::size_t j = 0; j < kChunk; ++j) {
        adaptor.D3(t[i + j], p, v1, v2, v3);
        out[4 * j] = to_vec(p.XYZ());
        out[4 * j + 1] = to_vec(v1.XYZ());
        out[4 * j + 2] = to_vec(v2.XYZ());
        out[4 * j + 3] = to_vec(v3.XYZ());
      }
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  finish(state);
}

// --- one call per point ------------------------------------------------------------------------

void BM_nurbs_d3_single_ours(benchmark::State& state) {
  const NurbsCurve c = make_curve(state.range(0) != 0);
  const auto& t = params(state.range(1) != 0);
  std::array<Vec3, 4> out;
  for (auto _ : state) {
    for (const double x : t) {
      c.derivatives(x, 3, out);
      benchmark::DoNotOptimize(out.data());
    }
  }
  finish(state);
}

#define HULA_EVAL_ARGS ArgNames({"rational", "sorted"})->ArgsProduct({{0, 1}, {1, 0}})
// simd: 3 = the widest instruction set the CPU has (the default), 0 = the scalar path (one point at a time).
#define HULA_EVAL_SIMD_ARGS ArgNames({"rational", "sorted", "simd"})->ArgsProduct({{0, 1}, {1, 0}, {3, 0}})
BENCHMARK(BM_nurbs_d0_ours)->HULA_EVAL_SIMD_ARGS;
BENCHMARK(BM_nurbs_d0_reference)->HULA_EVAL_ARGS;
BENCHMARK(BM_nurbs_d0_occt)->HULA_EVAL_ARGS;
BENCHMARK(BM_nurbs_d3_ours)->HULA_EVAL_SIMD_ARGS;
BENCHMARK(BM_nurbs_d3_reference)->HULA_EVAL_ARGS;
BENCHMARK(BM_nurbs_d3_occt)->HULA_EVAL_ARGS;
BENCHMARK(BM_nurbs_d3_single_ours)->HULA_EVAL_ARGS;

}  // namespace
