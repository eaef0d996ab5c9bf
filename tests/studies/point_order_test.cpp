// SPDX-License-Identifier: MIT
// studies::order_points' file-order detection and spanning-tree order on clouds from three generators
// independent of the code: scan_test_clouds.hpp's tail clouds (density varying 1:3 with two or three empty
// gaps, contaminated-normal noise) and wave/Laplace clouds (sorted uniform random parameters: clusters and
// gaps), and hula::testing's simulate_scan (±60 % density). Seeded. Judged against what the generators know:
// the order the points were made in and where each lies on the known curve.
#include "hula/studies/point_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "scan_test_clouds.hpp"

namespace hula::studies {
namespace {

using test_clouds::Order;
using test_clouds::TailCase;
using test_clouds::TailShape;
using test_clouds::TestCloud;

// Clouds made in curve order, each from a different generator, size, density, noise and end stray.
std::vector<TestCloud> in_order_clouds(Order order) {
  std::vector<TestCloud> out;
  std::uint64_t seed = 700;
  for (const TailShape shape : {TailShape::Spiral, TailShape::Step, TailShape::ConicalHelix})
    for (const double sigma : {0.01, 0.1}) {
      out.push_back(test_clouds::make_tail_cloud({shape, order, shape == TailShape::Step ? 1.0 : 1000.0,
                                                  sigma < 0.05 ? 2000u : 1000u, sigma, 4.0 + 10.0 * sigma, true},
                                                 ++seed));
      out.back().name += " σ/tol " + std::to_string(sigma);
    }
  for (const bool planar : {true, false}) {
    out.push_back(test_clouds::foreign_cloud(
        {test_clouds::Generator::WaveLaplace, planar, false, order, planar ? 10.0 : 100.0, 1500, 0.03, 6.0, false},
        ++seed));
  }
  out.push_back(test_clouds::simulated_test_cloud(testing::ScanShape::Convex, testing::ScanNoise::StudentT, 100.0, 1000,
                                                  0.03, order, 5.0, false, ++seed));
  out.push_back(test_clouds::simulated_test_cloud(testing::ScanShape::Helix, testing::ScanNoise::Anisotropic, 1.0, 800,
                                                  0.1, order, 0.0, false, ++seed));
  return out;
}

// The largest step between points consecutive in the file over the median step (the gaps a cloud has).
double widest_step_over_median(const std::vector<Vec3>& p) {
  std::vector<double> steps;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) steps.push_back(distance(p[i], p[i + 1]));
  const double widest = *std::max_element(steps.begin(), steps.end());
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  return widest / steps[steps.size() / 2];
}

// Checks that a cloud given in curve order (or reversed), with its gaps, its clusters and a stray at an
// end, is taken in file order, and that it leaves out (as suspects) at most 1 % of the points that are not generated
// strays (the isolation test, by the cloud's median spread, leaves out a few points at the edge of a gap in a sparse
// stretch; fit_scan keeps them when the curve passes them within the tolerance).
TEST(PointOrder, FileOrderWithGapsAndEndStraysIsTaken) {
  for (const Order order : {Order::InOrder, Order::Reversed}) {
    std::size_t with_gaps = 0;
    for (const TestCloud& cloud : in_order_clouds(order)) {
      SCOPED_TRACE(cloud.name + ", " + test_clouds::order_name(order));
      with_gaps += widest_step_over_median(cloud.points) > 10.0;
      const CurveOrder o = order_points(cloud.points, false);
      EXPECT_EQ(o.source, OrderSource::File);
      std::size_t good_left_out = 0;
      for (const std::size_t i : o.suspects)
        good_left_out += !std::binary_search(cloud.strays.begin(), cloud.strays.end(), i);
      EXPECT_LE(good_left_out * 100, cloud.points.size());
    }
    EXPECT_GE(with_gaps, 6u);  // the tail clouds' gaps are there: a step at least 10 median steps long
  }
}

// Checks that the same clouds shuffled are not taken in file order, and that the spanning-tree order keeps
// both ends where they are: along the known curve, points 1 % of its parameter apart have monotone
// parameters (one way or the other), and the points nearest the known ends take parameters within 0.01 of 0
// and 1.
TEST(PointOrder, ShuffledIsOrderedByTheTreeEndsInPlace) {
  for (const TestCloud& cloud : in_order_clouds(Order::Shuffled)) {
    SCOPED_TRACE(cloud.name);
    const CurveOrder o = order_points(cloud.points, false);
    EXPECT_EQ(o.source, OrderSource::SpanningTree);
    std::vector<std::pair<double, double>> t_param;  // (known foot, parameter) of the generated inliers
    for (std::size_t i = 0; i < cloud.points.size(); ++i)
      if (!std::binary_search(cloud.strays.begin(), cloud.strays.end(), i))
        t_param.emplace_back(cloud.known_foot(cloud.points[i]).t, o.parameters[i]);
    std::sort(t_param.begin(), t_param.end());
    const double sign = t_param.back().second > t_param.front().second ? 1.0 : -1.0;
    std::size_t reversals = 0;
    double last_t = -1.0, last_p = 0.0;
    for (const auto& [t, p] : t_param) {
      if (t < last_t + 0.01) continue;
      if (last_t >= 0.0 && sign * (p - last_p) <= 0.0) ++reversals;
      last_t = t, last_p = p;
    }
    EXPECT_EQ(reversals, 0u);
    EXPECT_NEAR(t_param.front().second, sign > 0.0 ? 0.0 : 1.0, 0.01);
    EXPECT_NEAR(t_param.back().second, sign > 0.0 ? 1.0 : 0.0, 0.01);
  }
}

// Checks that a file whose order is inconsistent is refused: the two halves swapped (the second half of
// the curve first), and the middle third reversed.
TEST(PointOrder, SwappedHalvesOrAReversedStretchAreNotTheFileOrder) {
  for (const TestCloud& cloud : in_order_clouds(Order::InOrder)) {
    SCOPED_TRACE(cloud.name);
    const std::size_t n = cloud.points.size();
    std::vector<Vec3> swapped(cloud.points.begin() + static_cast<std::ptrdiff_t>(n / 2), cloud.points.end());
    swapped.insert(swapped.end(), cloud.points.begin(), cloud.points.begin() + static_cast<std::ptrdiff_t>(n / 2));
    EXPECT_EQ(order_points(swapped, false).source, OrderSource::SpanningTree) << "halves swapped";
    std::vector<Vec3> turned = cloud.points;
    std::reverse(turned.begin() + static_cast<std::ptrdiff_t>(n / 3),
                 turned.begin() + static_cast<std::ptrdiff_t>(2 * n / 3));
    EXPECT_EQ(order_points(turned, false).source, OrderSource::SpanningTree) << "middle third reversed";
  }
}

}  // namespace
}  // namespace hula::studies
