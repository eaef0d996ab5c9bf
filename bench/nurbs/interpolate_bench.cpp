// SPDX-License-Identifier: MIT
// Global cubic interpolation through N points, ours beside Open CASCADE's
// GeomAPI_Interpolate in the same run, for N = 10 … 100 000. Both compute
// chord-length parameters and use OCCT's end convention (no tangents given).
// The natural-end rows are judged against the hand-written reference
// (bench/reference/interpolate.hpp: the same curve, checked before timing).
// Items processed = points.
#include <benchmark/benchmark.h>

#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "reference/interpolate.hpp"

namespace {

using hula::Vec3;

std::vector<Vec3> points(std::size_t n) {
  hula::Rng rng(1234);
  std::vector<Vec3> p(n);
  double x = 0;
  for (auto& q : p) {
    x += rng.uniform(0.5, 1.5);
    q = {x, 10 * std::sin(0.1 * x) + rng.uniform(-0.2, 0.2), rng.uniform(-1, 1)};
  }
  return p;
}

void BM_nurbs_interpolate_cubic(benchmark::State& state) {
  const auto p = points(static_cast<std::size_t>(state.range(0)));
  const hula::nurbs::InterpolationOptions options{.start = hula::nurbs::EndCondition::occt(),
                                                  .end = hula::nurbs::EndCondition::occt()};
  for (auto _ : state) {
    auto c = hula::nurbs::interpolate_cubic(p, options);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_nurbs_interpolate_cubic)->RangeMultiplier(10)->Range(10, 100000)->Complexity(benchmark::oN);

void BM_nurbs_interpolate_natural(benchmark::State& state) {
  const auto p = points(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    auto c = hula::nurbs::interpolate_cubic(p);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_nurbs_interpolate_natural)->Arg(10)->RangeMultiplier(10)->Range(100, 10000);

// The hand-written natural cubic (reference/interpolate.hpp); its control points are checked against
// interpolate_cubic's (1e-12 of the data's size) before timing.
void BM_reference_interpolate_natural(benchmark::State& state) {
  const auto p = points(static_cast<std::size_t>(state.range(0)));
  const auto ref = hula::bench::interpolate_natural(p);
  const auto ours = hula::nurbs::interpolate_cubic(p);
  double diff = 0.0, size = 0.0;
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    diff = std::max(diff, hula::max_abs(ref.points[i] - ours.control_points()[i]));
    size = std::max(size, hula::max_abs(ref.points[i]));
  }
  if (!(diff <= 1e-12 * size)) {
    state.SkipWithError(("control points differ from interpolate_cubic's by " + std::to_string(diff)).c_str());
    return;
  }
  for (auto _ : state) {
    auto c = hula::bench::interpolate_natural(p);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_reference_interpolate_natural)->Arg(10)->Arg(64);

void BM_occt_GeomAPI_Interpolate(benchmark::State& state) {
  const auto p = points(static_cast<std::size_t>(state.range(0)));
  Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, static_cast<int>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) pts->SetValue(static_cast<int>(i) + 1, gp_Pnt(p[i].x, p[i].y, p[i].z));
  for (auto _ : state) {
    GeomAPI_Interpolate interp(pts, Standard_False, 1e-9);
    interp.Perform();
    Handle(Geom_BSplineCurve) c = interp.Curve();
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_occt_GeomAPI_Interpolate)->RangeMultiplier(10)->Range(10, 100000)->Complexity(benchmark::oN);

}  // namespace
