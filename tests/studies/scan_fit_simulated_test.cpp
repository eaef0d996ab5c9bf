// SPDX-License-Identifier: MIT
// studies::fit_scan on clouds of the second, independent generator (hula/testing/scan_simulator.hpp:
// other curves, planar and space, open and closed; uniform, heavy-tailed, anisotropic and depth
// noise; in order, reversed, shuffled, partly shuffled and in passes; uniform and varying density;
// sizes 1, 100 and 1,000 units), with the tolerance at 0.003 × size (A-class 0.3 at 100 units) and
// σ from 0 to a third of it. Checked against the generator's truth, measured on the analytic curves:
// every generated stray (1.2 to 30 tolerances away) is found, no point within 0.25 / 0.3 of the
// tolerance of the known curve is called a stray, every kept point is within the tolerance of the
// faired curve (closest point), the curve stays within max(3 σ, 0.1 tolerance) of the known curve
// (orthogonal distance, the ends beyond the known curve's aside), and it has the known inflections.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "hula/diffgeom/features.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/studies/scan_fit.hpp"
#include "hula/testing/scan_simulator.hpp"

namespace hula::studies {
namespace {

using testing::ScanNoise;
using testing::ScanOrder;
using testing::ScanShape;

struct Case {
  ScanShape shape;
  ScanNoise noise;
  ScanOrder order;
  double size;
  double sigma_over_tolerance;
  bool varying_density;
};

// 35 clouds: each shape in each order, the noise models, sizes and noise levels cycled through.
std::vector<Case> cases() {
  const ScanShape shapes[] = {ScanShape::SCubic, ScanShape::Convex,  ScanShape::Quartic,    ScanShape::TwistedCubic,
                              ScanShape::Helix,  ScanShape::Ellipse, ScanShape::ClosedSpace};
  const ScanNoise noises[] = {ScanNoise::Uniform, ScanNoise::StudentT, ScanNoise::Anisotropic, ScanNoise::Depth};
  const ScanOrder orders[] = {ScanOrder::InOrder, ScanOrder::Shuffled, ScanOrder::Reversed, ScanOrder::PartlyShuffled,
                              ScanOrder::Passes};
  const double sizes[] = {1.0, 100.0, 1000.0};
  const double sigmas[] = {0.0, 0.033, 0.1, 0.33};
  std::vector<Case> out;
  std::size_t k = 0;
  for (const ScanShape shape : shapes)
    for (const ScanOrder order : orders) {
      out.push_back({shape, noises[k % 4], order, sizes[k % 3], sigmas[k % 4], k % 2 == 1});
      ++k;
    }
  return out;
}

class ScanFitSimulated : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ScanFitSimulated, StraysFoundCurveWithinNoiseInflectionsKept) {
  const Case c = cases()[GetParam()];
  const double tolerance = 0.003 * c.size;
  const testing::ScanSpec spec{.shape = c.shape,
                               .size = c.size,
                               .points = 2000,
                               .sigma = c.sigma_over_tolerance * tolerance,
                               .noise = c.noise,
                               .varying_density = c.varying_density,
                               .order = c.order,
                               .strays = 20,
                               .stray_min = 1.2 * tolerance,
                               .stray_max = 30.0 * tolerance,
                               .seed = 7 + GetParam()};
  const testing::Scan scan = testing::simulate_scan(spec);
  SCOPED_TRACE(testing::scan_shape_name(c.shape) + " size " + std::to_string(c.size) + " sigma/tol " +
               std::to_string(c.sigma_over_tolerance) + " noise " + std::to_string(static_cast<int>(c.noise)) +
               " order " + std::to_string(static_cast<int>(c.order)));
  const ScanFitResult r = fit_scan(scan.points, ScanFitOptions{.tolerance = tolerance});

  for (const std::size_t s : scan.strays)
    EXPECT_TRUE(std::binary_search(r.strays.begin(), r.strays.end(), s)) << "stray " << s << " kept";
  for (const std::size_t s : r.strays)
    EXPECT_GE(testing::distance_to_scan_curve(spec, scan.points[s]), 0.25 / 0.3 * tolerance)
        << "point " << s << " called a stray";
  for (std::size_t i = 0; i < scan.points.size(); i += 3)
    if (!std::binary_search(r.strays.begin(), r.strays.end(), i)) {
      EXPECT_LE(nurbs::closest_point(r.faired, scan.points[i]).distance, tolerance * (1.0 + 1e-9)) << "point " << i;
    }

  const auto dom = r.faired.domain();
  double far = 0.0;
  for (int k = 0; k <= 300; ++k) {
    const testing::ScanFoot f =
        testing::foot_on_scan_curve(spec, r.faired.evaluate(dom.start + (dom.end - dom.start) * k / 300.0));
    if (!testing::scan_shape_closed(c.shape) && (f.u <= 0.0 || f.u >= 1.0)) continue;
    far = std::max(far, f.distance);
  }
  EXPECT_LE(far, std::max(3.0 * spec.sigma, 0.1 * tolerance));
  EXPECT_EQ(r.closed, testing::scan_shape_closed(c.shape));
  if (testing::scan_shape_planar(c.shape)) {
    EXPECT_EQ(diffgeom::inflections(r.faired).size(), testing::scan_shape_inflections(c.shape));
  }
}

INSTANTIATE_TEST_SUITE_P(Clouds, ScanFitSimulated, ::testing::Range<std::size_t>(0, 35));

}  // namespace
}  // namespace hula::studies
