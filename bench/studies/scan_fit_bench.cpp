// SPDX-License-Identifier: MIT
// studies::fit_scan on seeded scanned clouds (hula/testing/point_clouds.hpp): the
// whole pipeline (ordering, robust fit, fewest control points, fairing, the
// before/after figures) at the A-class tolerance. Target: 10,000
// points in ≤ 100 ms. Inputs: a ring of the three known curves, noise 0.1, 1 %
// strays, shuffled, generated outside the timed loop.
#include <benchmark/benchmark.h>

#include <vector>

#include "hula/studies/scan_fit.hpp"
#include "hula/testing/point_clouds.hpp"

namespace {

void BM_studies_scan_fit(benchmark::State& state) {
  using hula::testing::KnownCurve;
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<hula::testing::Cloud> ring;
  for (KnownCurve c : {KnownCurve::Arc, KnownCurve::SCurve, KnownCurve::Wave})
    ring.push_back(hula::testing::scanned_cloud({.curve = c, .points = n, .noise = 0.1, .seed = 1}));
  std::size_t k = 0;
  for (auto _ : state) {
    const hula::studies::ScanFitResult r = hula::studies::fit_scan(ring[k].points);
    benchmark::DoNotOptimize(r.faired.control_points().data());
    k = (k + 1) % ring.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_studies_scan_fit)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
