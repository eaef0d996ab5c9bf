// SPDX-License-Identifier: MIT
// Issue 21 item 2: the scan fit on data the project did not generate. Each test is a failure the
// issue reports, on the independent generator (hula/testing/scan_simulator.hpp) or on a real
// airfoil file (tests/data/real), checked against the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "hula/diffgeom/features.hpp"
#include "hula/io/points_file.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/studies/scan_fit.hpp"
#include "hula/testing/scan_simulator.hpp"

namespace hula::studies {
namespace {

using testing::ScanNoise;
using testing::ScanOrder;
using testing::ScanShape;

testing::ScanSpec cubic_cloud(ScanShape shape, ScanOrder order) {
  // About 100 units long, 2,000 points, noise σ = 0.05 in every direction, 1 % strays.
  return {.shape = shape,
          .size = 100.0,
          .points = 1980,
          .sigma = 0.05,
          .noise = ScanNoise::Uniform,
          .order = order,
          .strays = 20,
          .stray_min = 0.5,
          .stray_max = 10.0,
          .seed = 21};
}

std::size_t inliers_called_strays(const testing::Scan& scan, const ScanFitResult& r) {
  std::size_t n = 0;
  for (const std::size_t s : r.strays)
    if (!std::binary_search(scan.strays.begin(), scan.strays.end(), s)) ++n;
  return n;
}

// The issue: a cubic cloud in curve order, fitted without --ordered, lost its last 32 good points as
// strays and came back with 8 inflections. Now the file order is taken, no good point is a stray,
// every stray is found and the S-cubic keeps its one inflection.
TEST(Issue21, InOrderCloudKeepsItsEndPoints) {
  const testing::ScanSpec spec = cubic_cloud(ScanShape::SCubic, ScanOrder::InOrder);
  const testing::Scan scan = testing::simulate_scan(spec);
  const ScanFitResult r = fit_scan(scan.points);
  EXPECT_EQ(r.ordering, OrderSource::File);
  EXPECT_EQ(r.strays, scan.strays);
  EXPECT_EQ(inliers_called_strays(scan, r), 0u);
  EXPECT_EQ(r.after.inflections, 1u);
}

// The issue: a convex planar cloud failed with "no fit with up to 200 control points", in order and
// shuffled. Now both fit, with no inflection.
TEST(Issue21, ConvexCloudFitsInOrderAndShuffled) {
  for (const ScanOrder order : {ScanOrder::InOrder, ScanOrder::Shuffled}) {
    const testing::ScanSpec spec = cubic_cloud(ScanShape::Convex, order);
    const testing::Scan scan = testing::simulate_scan(spec);
    const ScanFitResult r = fit_scan(scan.points);
    EXPECT_EQ(r.strays, scan.strays) << static_cast<int>(order);
    EXPECT_EQ(r.after.inflections, 0u) << static_cast<int>(order);
    EXPECT_LE(r.after.max_deviation, kClassATolerance);
  }
}

// The issue: on a space curve 231 good points were strays and the strays lay 0.33 from the known
// curve. Now no good point is a stray and every kept point is within the tolerance.
TEST(Issue21, SpaceCloudKeepsItsGoodPoints) {
  const testing::ScanSpec spec = cubic_cloud(ScanShape::TwistedCubic, ScanOrder::Shuffled);
  const testing::Scan scan = testing::simulate_scan(spec);
  const ScanFitResult r = fit_scan(scan.points);
  EXPECT_EQ(r.faired.dimension(), 3);
  EXPECT_EQ(r.strays, scan.strays);
  for (std::size_t i = 0; i < scan.points.size(); i += 7)
    if (!std::binary_search(r.strays.begin(), r.strays.end(), i)) {
      EXPECT_LE(nurbs::closest_point(r.faired, scan.points[i]).distance, kClassATolerance * (1 + 1e-9));
    }
}

// The issue: 31 of the 62 exact design points of an airfoil were strays at tolerance 1e-3, and at 2e-4
// the fit failed ("only 2 points are kept"). Now every point is kept, within the tolerance.
TEST(Issue21, AirfoilDesignPointsAreNeverStrays) {
  const char* root = std::getenv("HULA_TEST_DATA");
  ASSERT_NE(root, nullptr);
  const std::vector<Vec3> pts = io::read_points_file(std::filesystem::path(root) / "real" / "nlf416.dat").points;
  ASSERT_EQ(pts.size(), 62u);
  for (const double tolerance : {1e-3, 2e-4, 1e-4}) {
    const ScanFitResult r = fit_scan(pts, ScanFitOptions{.tolerance = tolerance, .ordered = true});
    EXPECT_TRUE(r.strays.empty()) << tolerance;
    double worst = 0.0;
    for (const Vec3& q : pts) worst = std::max(worst, nurbs::closest_point(r.faired, q).distance);
    EXPECT_LE(worst, tolerance * (1 + 1e-9)) << tolerance;
  }
}

}  // namespace
}  // namespace hula::studies
