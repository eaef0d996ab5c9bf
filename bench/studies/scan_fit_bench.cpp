// SPDX-License-Identifier: MIT
// studies::fit_scan, the whole pipeline of `hula fit` (ordering, noise estimate, the tolerance fit
// with stray rejection, fairing, the before/after figures), beside Open CASCADE's
// GeomAPI_PointsToBSpline (degree 3–8, C2, the same tolerance) in the same run:
//  - a 171-point airfoil (tests/data/real/rae101.dat, read as shipped) at 1e-4, ordered;
//  - scanned clouds (hula/testing/point_clouds.hpp: a ring of the three known curves, noise 0.1,
//    1 % strays) at the A-class 0.3: ours gets the cloud shuffled with its strays, OCCT (which
//    neither orders nor rejects) the inliers in curve order.
// Inputs are read or generated outside the timed loops.
#include <benchmark/benchmark.h>

#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAbs_Shape.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <vector>

#include "hula/io/points_file.hpp"
#include "hula/studies/scan_fit.hpp"
#include "hula/testing/point_clouds.hpp"

namespace {

std::vector<hula::Vec3> airfoil() {
  return hula::io::read_points_file(std::string(HULA_SOURCE_DIR) + "/tests/data/real/rae101.dat").points;
}

TColgp_Array1OfPnt occt_points(const std::vector<hula::Vec3>& pts) {
  TColgp_Array1OfPnt a(1, static_cast<int>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
    a.SetValue(static_cast<int>(i) + 1, gp_Pnt(pts[i].x, pts[i].y, pts[i].z));
  return a;
}

void BM_studies_scan_fit_airfoil(benchmark::State& state) {
  const std::vector<hula::Vec3> pts = airfoil();
  for (auto _ : state) {
    const hula::studies::ScanFitResult r =
        hula::studies::fit_scan(pts, hula::studies::ScanFitOptions{.tolerance = 1e-4, .ordered = true});
    benchmark::DoNotOptimize(r.faired.control_points().data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pts.size()));
}
BENCHMARK(BM_studies_scan_fit_airfoil)->Unit(benchmark::kMillisecond);

void BM_occt_points_to_bspline_airfoil(benchmark::State& state) {
  const std::vector<hula::Vec3> pts = airfoil();
  const TColgp_Array1OfPnt a = occt_points(pts);
  for (auto _ : state) {
    const GeomAPI_PointsToBSpline occt(a, 3, 8, GeomAbs_C2, 1e-4);
    benchmark::DoNotOptimize(occt.Curve().get());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pts.size()));
}
BENCHMARK(BM_occt_points_to_bspline_airfoil)->Unit(benchmark::kMillisecond);

std::vector<hula::testing::Cloud> clouds(std::size_t n, bool shuffle) {
  using hula::testing::KnownCurve;
  std::vector<hula::testing::Cloud> ring;
  for (KnownCurve c : {KnownCurve::Arc, KnownCurve::SCurve, KnownCurve::Wave})
    ring.push_back(
        hula::testing::scanned_cloud({.curve = c, .points = n, .noise = 0.1, .shuffle = shuffle, .seed = 1}));
  return ring;
}

void BM_studies_scan_fit(benchmark::State& state) {
  const std::vector<hula::testing::Cloud> ring = clouds(static_cast<std::size_t>(state.range(0)), true);
  std::size_t k = 0;
  for (auto _ : state) {
    const hula::studies::ScanFitResult r = hula::studies::fit_scan(ring[k].points);
    benchmark::DoNotOptimize(r.faired.control_points().data());
    k = (k + 1) % ring.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_studies_scan_fit)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_occt_points_to_bspline_scan(benchmark::State& state) {
  std::vector<TColgp_Array1OfPnt> ring;
  for (const hula::testing::Cloud& c : clouds(static_cast<std::size_t>(state.range(0)), false)) {
    std::vector<hula::Vec3> inliers;
    for (std::size_t i = 0; i < c.points.size(); ++i)
      if (!std::binary_search(c.strays.begin(), c.strays.end(), i)) inliers.push_back(c.points[i]);
    ring.push_back(occt_points(inliers));
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const GeomAPI_PointsToBSpline occt(ring[k], 3, 8, GeomAbs_C2, hula::studies::kClassATolerance);
    benchmark::DoNotOptimize(occt.Curve().get());
    k = (k + 1) % ring.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_occt_points_to_bspline_scan)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
