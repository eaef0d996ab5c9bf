// SPDX-License-Identifier: MIT
// Curve–curve intersection, self-intersection and curve distance, ours beside
// Open CASCADE in the same run: Geom2dAPI_InterCurveCurve (two curves, and its
// self-intersection form) and GeomAPI_ExtremaCurveCurve (distance). Inputs are
// a ring of 8 seeded pairs of cubic splines through N random points (N − 1
// spans each; planar ones in [0, 100]², space ones offset so they do not
// meet). Items processed = curve pairs (or curves).
#include <benchmark/benchmark.h>

#include <Geom2dAPI_InterCurveCurve.hxx>
#include <GeomAPI_ExtremaCurveCurve.hxx>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/intersect.hpp"
#include "hula/testing/occt_curve.hpp"

namespace {

using hula::Vec3;
using hula::nurbs::NurbsCurve;

constexpr std::size_t kRing = 8;

NurbsCurve spline(hula::Rng& rng, std::size_t n, int dimension, double dz) {
  std::vector<Vec3> p(n);
  for (Vec3& q : p)
    q = {rng.uniform(0.0, 100.0), rng.uniform(0.0, 100.0), dimension == 3 ? rng.uniform(0.0, 100.0) + dz : 0.0};
  hula::nurbs::InterpolationOptions o;
  o.dimension = dimension;
  return hula::nurbs::interpolate_cubic(p, o);
}

struct Pairs {
  std::vector<NurbsCurve> a, b;
};

Pairs pairs(std::size_t n, int dimension) {
  hula::Rng rng(4242 + n);
  Pairs out;
  for (std::size_t i = 0; i < kRing; ++i) {
    out.a.push_back(spline(rng, n, dimension, 0.0));
    out.b.push_back(spline(rng, n, dimension, dimension == 3 ? 150.0 : 0.0));
  }
  return out;
}

void BM_nurbs_intersect_planar(benchmark::State& state) {
  const Pairs p = pairs(static_cast<std::size_t>(state.range(0)), 2);
  std::size_t i = 0, found = 0;
  for (auto _ : state) {
    const auto r = hula::nurbs::intersect(p.a[i % kRing], p.b[i % kRing]);
    found += r.points.size();
    benchmark::DoNotOptimize(r);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["points"] = static_cast<double>(found) / static_cast<double>(i);
}
BENCHMARK(BM_nurbs_intersect_planar)->Arg(4)->Arg(10)->Arg(30)->Arg(100);

void BM_occt_Geom2dAPI_InterCurveCurve(benchmark::State& state) {
  const Pairs p = pairs(static_cast<std::size_t>(state.range(0)), 2);
  std::vector<Handle(Geom2d_BSplineCurve)> a, b;
  for (std::size_t k = 0; k < kRing; ++k) {
    a.push_back(hula::testing::to_occt_2d(p.a[k]));
    b.push_back(hula::testing::to_occt_2d(p.b[k]));
  }
  std::size_t i = 0, found = 0;
  for (auto _ : state) {
    Geom2dAPI_InterCurveCurve inter(a[i % kRing], b[i % kRing], 1e-6);
    found += static_cast<std::size_t>(inter.NbPoints());
    benchmark::DoNotOptimize(inter);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["points"] = static_cast<double>(found) / static_cast<double>(i);
}
BENCHMARK(BM_occt_Geom2dAPI_InterCurveCurve)->Arg(4)->Arg(10)->Arg(30)->Arg(100);

void BM_nurbs_self_intersect(benchmark::State& state) {
  const Pairs p = pairs(static_cast<std::size_t>(state.range(0)), 2);
  std::size_t i = 0, found = 0;
  for (auto _ : state) {
    const auto r = hula::nurbs::self_intersect(p.a[i % kRing]);
    found += r.points.size();
    benchmark::DoNotOptimize(r);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["points"] = static_cast<double>(found) / static_cast<double>(i);
}
BENCHMARK(BM_nurbs_self_intersect)->Arg(10)->Arg(30)->Arg(100);

void BM_occt_Geom2dAPI_InterCurveCurve_self(benchmark::State& state) {
  const Pairs p = pairs(static_cast<std::size_t>(state.range(0)), 2);
  std::vector<Handle(Geom2d_BSplineCurve)> a;
  for (std::size_t k = 0; k < kRing; ++k) a.push_back(hula::testing::to_occt_2d(p.a[k]));
  std::size_t i = 0, found = 0;
  for (auto _ : state) {
    Geom2dAPI_InterCurveCurve inter(a[i % kRing], 1e-6);
    found += static_cast<std::size_t>(inter.NbPoints());
    benchmark::DoNotOptimize(inter);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["points"] = static_cast<double>(found) / static_cast<double>(i);
}
BENCHMARK(BM_occt_Geom2dAPI_InterCurveCurve_self)->Arg(10)->Arg(30)->Arg(100);

void BM_nurbs_curve_distance(benchmark::State& state) {
  const Pairs p = pairs(static_cast<std::size_t>(state.range(0)), 3);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = hula::nurbs::curve_distance(p.a[i % kRing], p.b[i % kRing]);
    benchmark::DoNotOptimize(r);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_nurbs_curve_distance)->Arg(4)->Arg(10)->Arg(30)->Arg(100);

void BM_occt_GeomAPI_ExtremaCurveCurve(benchmark::State& state) {
  const Pairs p = pairs(static_cast<std::size_t>(state.range(0)), 3);
  std::vector<Handle(Geom_BSplineCurve)> a, b;
  for (std::size_t k = 0; k < kRing; ++k) {
    a.push_back(hula::testing::to_occt(p.a[k]));
    b.push_back(hula::testing::to_occt(p.b[k]));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    GeomAPI_ExtremaCurveCurve ext(a[i % kRing], b[i % kRing]);
    double d = ext.NbExtrema() > 0 ? ext.LowerDistance() : 0.0;
    benchmark::DoNotOptimize(d);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_occt_GeomAPI_ExtremaCurveCurve)->Arg(4)->Arg(10)->Arg(30)->Arg(100);

}  // namespace
