// SPDX-License-Identifier: MIT
// studies::fit_scan on clouds made by two generators of scan_test_clouds.hpp, independent of hula::testing
// (neither its known curves, nor its noise, nor its distances are used):
//
//  - Bézier clouds: a random cubic Bézier (a C or an S in the plane, or lifted into space), points at
//    equal parameter steps (dense where the curve is slow), Gaussian noise in every direction;
//  - wave clouds: a sine wave (planar) or a wavy helix (space) with random phase and frequency, points
//    at sorted uniform random parameters (clusters and gaps), Laplace (double-exponential) noise.
//
// Both are fitted in order, shuffled and reversed, at σ = 0.01, 0.03 and 0.1 of the tolerance, the
// tolerance 0.003 × size (A-class 0.3 at 100 units), sizes 1 to 1,000 units, 300 to 3,000 points,
// 1 % strays 1.2 to 30 tolerances from the curve. Distances to the known curve are measured by the
// header's own closest-point search on the analytic curve (sampling, then golden-section refinement);
// inflections of the known curve by the sign changes of x'y'' − y'x'' from its analytic derivatives.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "hula/diffgeom/features.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/studies/scan_fit.hpp"
#include "scan_test_clouds.hpp"

namespace hula::studies {
namespace {

using test_clouds::Case;
using test_clouds::Cloud;
using test_clouds::foot;
using test_clouds::Foot;
using test_clouds::Generator;
using test_clouds::known_inflections;
using test_clouds::KnownCurve;
using test_clouds::make_cloud;
using test_clouds::noise;
using test_clouds::Order;
using test_clouds::wave_curve;

// 24 clouds: each generator, planar and space, in each order, σ, sizes and densities cycled through.
std::vector<Case> cases() {
  const double sizes[] = {1.0, 10.0, 100.0, 1000.0};
  const std::size_t counts[] = {300, 1000, 3000};
  const double sigmas[] = {0.01, 0.03, 0.1};
  std::vector<Case> out;
  std::size_t k = 0;
  for (const Generator g : {Generator::BezierGaussian, Generator::WaveLaplace})
    for (const bool planar : {true, false})
      for (const Order order : {Order::InOrder, Order::Shuffled, Order::Reversed})
        for (int rep = 0; rep < 2; ++rep) {
          out.push_back({g, planar, rep == 1, order, sizes[k % 4], counts[k % 3], sigmas[(k / 2) % 3]});
          ++k;
        }
  return out;
}

std::string describe(const Case& c) {
  static const char* orders[] = {"in order", "shuffled", "reversed"};
  return std::string(c.generator == Generator::BezierGaussian ? "Bézier/Gaussian" : "wave/Laplace") +
         (c.planar ? " planar" : " space") + (c.s_shape && c.generator == Generator::BezierGaussian ? " S" : "") +
         ", " + orders[static_cast<int>(c.order)] + ", size " + std::to_string(c.size) + ", " +
         std::to_string(c.points) + " points, σ/tol " + std::to_string(c.sigma_over_tolerance);
}

// Checks on each cloud: every generated stray is found; no point within 0.25 / 0.3 of the tolerance
// of the known curve is called a stray; every kept point is within the tolerance of the faired curve;
// the faired curve is within 3 σ of the known curve (its points whose foot is inside the known curve's
// domain); the closed flag is off; and planar clouds keep the known curve's inflection count.
void check_cloud(std::size_t index) {
  const Case c = cases()[index];
  SCOPED_TRACE(describe(c));
  const double tolerance = 0.003 * c.size;
  const Cloud cloud = make_cloud(c, 1000 + index);
  const ScanFitResult r = fit_scan(cloud.points, ScanFitOptions{.tolerance = tolerance});

  for (const std::size_t s : cloud.strays)
    EXPECT_TRUE(std::binary_search(r.strays.begin(), r.strays.end(), s)) << "stray " << s << " kept";
  for (const std::size_t s : r.strays)
    EXPECT_GE(foot(cloud.curve, cloud.points[s]).distance, 0.25 / 0.3 * tolerance)
        << "point " << s << " called a stray";
  for (std::size_t i = 0; i < cloud.points.size(); i += 7)
    if (!std::binary_search(r.strays.begin(), r.strays.end(), i)) {
      EXPECT_LE(nurbs::closest_point(r.faired, cloud.points[i]).distance, tolerance * (1.0 + 1e-9)) << "point " << i;
    }

  const auto dom = r.faired.domain();
  double far = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const Foot f = foot(cloud.curve, r.faired.evaluate(dom.start + (dom.end - dom.start) * k / 400.0));
    if (f.t <= 1e-9 || f.t >= 1.0 - 1e-9) continue;  // beyond the known curve's ends: noise at the end points
    far = std::max(far, f.distance);
  }
  EXPECT_LE(far, 3.0 * cloud.sigma) << "σ = " << cloud.sigma;
  EXPECT_FALSE(r.closed);
  if (c.planar) {
    EXPECT_EQ(diffgeom::inflections(r.faired).size(), known_inflections(cloud.curve));
  }
}

// The shuffled 300-point wavy helix (index 21) has a gap before its last point, which the ordering's
// tree leaves out as isolated: the fit must take it back in as the curve's end, not call it a stray.
std::vector<std::size_t> all_clouds() {
  std::vector<std::size_t> out(cases().size());
  std::iota(out.begin(), out.end(), std::size_t{0});
  return out;
}

class ScanFitForeignClouds : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ScanFitForeignClouds, StraysFoundCurveWithinThreeSigmaInflectionsKept) { check_cloud(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Clouds, ScanFitForeignClouds, ::testing::ValuesIn(all_clouds()));

// Checks a stray at an end of the cloud, on the wave generator (planar sine, sorted uniform random
// parameters, Laplace noise σ = 0.03 tolerance, no other stray): the first or the last point (t = 0 or
// 1) moved 4, 10 or 30 tolerances off the curve along its normal, away from the centre of curvature, is
// the one stray, at sizes 1 and 1,000 units, in curve order and shuffled; every other point is within
// the tolerance of the faired curve (nurbs::closest_point), and the faired curve within 3 σ of the
// known curve.
TEST(ScanFitForeignClouds, AStrayAtEitherEndIsFound) {
  for (const double size : {1.0, 1000.0})
    for (const Order order : {Order::InOrder, Order::Shuffled})
      for (const bool last : {false, true})
        for (const double off : {4.0, 10.0, 30.0}) {
          const Case c{Generator::WaveLaplace, true, false, order, size, 600, 0.03};
          SCOPED_TRACE(describe(c) + ", " + std::to_string(off) + " tolerances off the " + (last ? "last" : "first"));
          const double tolerance = 0.003 * size;
          std::mt19937_64 rng(77 + static_cast<std::uint64_t>(size) + (last ? 1 : 0));
          const KnownCurve curve = wave_curve(size, true, rng);
          std::uniform_real_distribution<double> u(0.0, 1.0);
          std::vector<double> ts(c.points);
          for (double& t : ts) t = u(rng);
          std::sort(ts.begin(), ts.end());
          ts.front() = 0.0, ts.back() = 1.0;
          std::vector<Vec3> pts;
          for (const double t : ts)
            pts.push_back(curve.at(t) + noise(c.generator, true, c.sigma_over_tolerance * tolerance, rng));
          const double te = last ? 1.0 : 0.0;
          const Vec3 d1 = curve.d1(te), d2 = curve.d2(te);
          Vec3 normal = Vec3{-d1.y, d1.x, 0.0} * (1.0 / norm(d1));
          if (dot(normal, d2) > 0.0) normal = normal * -1.0;
          std::size_t stray = last ? pts.size() - 1 : 0;
          pts[stray] = curve.at(te) + normal * (off * tolerance);
          if (order == Order::Shuffled) {
            std::vector<std::size_t> perm(pts.size());
            std::iota(perm.begin(), perm.end(), std::size_t{0});
            std::shuffle(perm.begin(), perm.end(), rng);
            std::vector<Vec3> mixed(pts.size());
            std::size_t at = 0;
            for (std::size_t k = 0; k < perm.size(); ++k) {
              mixed[k] = pts[perm[k]];
              if (perm[k] == stray) at = k;
            }
            pts = std::move(mixed);
            stray = at;
          }
          const ScanFitResult r = fit_scan(pts, ScanFitOptions{.tolerance = tolerance});
          EXPECT_EQ(r.strays, std::vector<std::size_t>{stray});
          double worst = 0.0;
          for (std::size_t i = 0; i < pts.size(); ++i)
            if (i != stray) worst = std::max(worst, nurbs::closest_point(r.faired, pts[i]).distance);
          EXPECT_LE(worst, tolerance * (1.0 + 1e-9));
          const auto dom = r.faired.domain();
          double far = 0.0;
          for (int k = 0; k <= 200; ++k) {
            const Foot f = foot(curve, r.faired.evaluate(dom.start + (dom.end - dom.start) * k / 200.0));
            if (f.t > 1e-9 && f.t < 1.0 - 1e-9) far = std::max(far, f.distance);
          }
          EXPECT_LE(far, 3.0 * c.sigma_over_tolerance * tolerance);
        }
}

// Checks the generators themselves: the Bézier S has one inflection and the C none, the planar wave
// as many as the zeros of its sine inside the domain, each stray is 1.2–30 tolerances from its curve
// and no other point farther than 8 σ (Gaussian) or 12 σ (Laplace).
TEST(ScanFitForeignClouds, GeneratorsMakeWhatTheySay) {
  for (const std::size_t i : {0u, 1u}) {
    const Case c = cases()[i];
    const Cloud cloud = make_cloud(c, 1000 + i);
    EXPECT_EQ(known_inflections(cloud.curve), c.s_shape ? 1u : 0u);
  }
  for (std::size_t i = 0; i < cases().size(); ++i) {
    const Case c = cases()[i];
    const Cloud cloud = make_cloud(c, 1000 + i);
    const double tolerance = 0.003 * c.size;
    for (std::size_t j = 0; j < cloud.points.size(); ++j) {
      const double d = foot(cloud.curve, cloud.points[j]).distance;
      if (std::binary_search(cloud.strays.begin(), cloud.strays.end(), j)) {
        EXPECT_GE(d, 1.2 * tolerance);
        EXPECT_LE(d, 30.0 * tolerance * (1.0 + 1e-9));
      } else {
        EXPECT_LE(d, (c.generator == Generator::BezierGaussian ? 8.0 : 12.0) * cloud.sigma) << describe(c);
      }
    }
  }
}

}  // namespace
}  // namespace hula::studies
