// SPDX-License-Identifier: MIT
// Tests of studies::fit_scan and order_along_curve on seeded clouds of known curves
// (hula/testing/point_clouds.hpp): strays found, inliers within the tolerance, the
// known curve's inflection count, and the bad-input contract.
#include "hula/studies/scan_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/point_clouds.hpp"

namespace hula::studies {
namespace {

using testing::CloudSpec;
using testing::KnownCurve;

struct CloudCase {
  KnownCurve curve;
  double noise;
};

// Largest distance of the faired curve from the known curve at the feet of the kept points.
double distance_from_known(const ScanFitResult& r, KnownCurve curve) {
  double worst = 0.0;
  for (std::size_t k = 0; k < r.order.size(); k += 5)
    worst = std::max(worst, testing::distance_to_known_curve(curve, r.faired.evaluate(r.parameters[r.order[k]])));
  return worst;
}

class ScanFitOnKnownCurves : public ::testing::TestWithParam<CloudCase> {};

// Checks the judged properties on three known curves × noise 0.05 / 0.1 × 1 % strays, three seeds
// each: every stray (by construction ≥ 2 from the curve) is rejected and no inlier is, every inlier
// lies within the A-class 0.3 of the faired curve, the faired curve stays within 3 σ of the known
// curve (the generator's noise is Gaussian per coordinate) and has its inflection count (the sine's
// / the arc's, by construction). How many control points the fit may use is checked against an
// independent reference, Open CASCADE's GeomAPI_PointsToBSpline on the same clouds, in the
// OCCT-linked scan_fit_occt_test.cpp.
TEST_P(ScanFitOnKnownCurves, FindsStraysKeepsInliersAndInflections) {
  const CloudCase c = GetParam();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const testing::Cloud cloud =
        testing::scanned_cloud(CloudSpec{.curve = c.curve, .points = 1000, .noise = c.noise, .seed = seed});
    const ScanFitResult r = fit_scan(cloud.points, ScanFitOptions{.tolerance = kClassATolerance});
    SCOPED_TRACE(std::string(testing::known_curve_name(c.curve)) + " noise " + std::to_string(c.noise) + " seed " +
                 std::to_string(seed));
    EXPECT_EQ(r.strays, cloud.strays);
    for (std::size_t i = 0; i < cloud.points.size(); ++i)
      if (!std::binary_search(cloud.strays.begin(), cloud.strays.end(), i)) {
        EXPECT_LE(r.deviations[i], kClassATolerance) << "inlier " << i;
      }
    EXPECT_LE(r.after.max_deviation, kClassATolerance);
    EXPECT_EQ(r.after.inflections, testing::known_curve_inflections(c.curve));
    // Fairing never makes the curvature variation worse than the tolerance fit's.
    EXPECT_LE(r.after.curvature_variation, r.before.curvature_variation * (1.0 + 1e-9));
    EXPECT_EQ(r.faired.dimension(), 2);
    EXPECT_LE(distance_from_known(r, c.curve), 3.0 * c.noise);
    EXPECT_EQ(r.faired.control_points().size(), r.fit.control_points().size());
  }
}

INSTANTIATE_TEST_SUITE_P(Clouds, ScanFitOnKnownCurves,
                         ::testing::Values(CloudCase{KnownCurve::Arc, 0.05}, CloudCase{KnownCurve::Arc, 0.1},
                                           CloudCase{KnownCurve::SCurve, 0.05}, CloudCase{KnownCurve::SCurve, 0.1},
                                           CloudCase{KnownCurve::Wave, 0.05}, CloudCase{KnownCurve::Wave, 0.1}));

// Checks that the faired curve stays near the known curve where there are data: at the foot of
// every kept point its distance to the sampled curve (dense polyline) is within the tolerance (the
// fairing may use the whole band), so the fit found the curve, not a curve through the noise.
TEST(ScanFit, FairedCurveFollowsTheKnownCurve) {
  const testing::Cloud cloud = testing::scanned_cloud(CloudSpec{.curve = KnownCurve::Wave, .noise = 0.1, .seed = 7});
  const ScanFitResult r = fit_scan(cloud.points);
  for (std::size_t k = 0; k < r.order.size(); k += 10) {
    const std::size_t i = r.order[k];
    const Vec3 c = r.faired.evaluate(r.parameters[i]);
    EXPECT_LT(testing::distance_to_known_curve(KnownCurve::Wave, c), kClassATolerance) << "point " << i;
  }
}

// Checks that given-order input (ordered = true) on an unshuffled cloud gives the same strays and
// inflections as the MST ordering on the shuffled one.
TEST(ScanFit, OrderedInputSkipsOrdering) {
  const testing::Cloud cloud =
      testing::scanned_cloud(CloudSpec{.curve = KnownCurve::SCurve, .noise = 0.05, .shuffle = false, .seed = 4});
  const ScanFitResult r = fit_scan(cloud.points, ScanFitOptions{.ordered = true});
  EXPECT_EQ(r.strays, cloud.strays);
  EXPECT_EQ(r.after.inflections, 1u);
}

// Checks that min_degree = degree fixes the degree: a quintic (and a cubic) within the tolerance,
// finding the same strays as the free choice of degree.
TEST(ScanFit, MinDegreeFixesTheDegree) {
  const testing::Cloud cloud = testing::scanned_cloud(CloudSpec{.curve = KnownCurve::SCurve, .noise = 0.1, .seed = 2});
  const ScanFitResult any = fit_scan(cloud.points);
  for (const int degree : {3, 5}) {
    const ScanFitResult fixed = fit_scan(cloud.points, ScanFitOptions{.degree = degree, .min_degree = degree});
    EXPECT_EQ(fixed.fit.degree(), degree);
    EXPECT_LE(fixed.after.max_deviation, kClassATolerance);
    EXPECT_EQ(fixed.strays, any.strays);
  }
  EXPECT_EQ(any.strays, cloud.strays);
}

// Checks the B-class tolerance 0.5 on the same cloud: every kept point within 0.5, the same strays
// (all ≥ 2 from the curve), and the curve as close to the known one as at A-class: a scan's curve
// follows its points to the noise whatever the tolerance.
TEST(ScanFit, LooserToleranceFollowsTheScanAsClosely) {
  const testing::Cloud cloud = testing::scanned_cloud(CloudSpec{.curve = KnownCurve::Wave, .noise = 0.1, .seed = 5});
  const ScanFitResult a = fit_scan(cloud.points, ScanFitOptions{.tolerance = kClassATolerance});
  const ScanFitResult b = fit_scan(cloud.points, ScanFitOptions{.tolerance = kClassBTolerance});
  EXPECT_LE(b.after.max_deviation, kClassBTolerance);
  EXPECT_EQ(b.strays, cloud.strays);
  EXPECT_LE(distance_from_known(b, KnownCurve::Wave), 0.3);
  EXPECT_LE(distance_from_known(a, KnownCurve::Wave), 0.3);
}

// Checks the MST ordering on a shuffled noise-free arc against the known order: keys increase
// (or decrease) with the curve parameter the generator used.
TEST(PointOrder, RecoversTheOrderOfAShuffledArc) {
  const testing::Cloud cloud = testing::scanned_cloud(
      CloudSpec{.curve = KnownCurve::Arc, .points = 300, .noise = 0.0, .stray_fraction = 0.0, .seed = 3});
  const PointOrder o = order_along_curve(cloud.points);
  // Sorted by key, the points' x (monotone along the arc) must be monotone.
  std::vector<double> xs;
  for (std::size_t i : o.order) xs.push_back(cloud.points[i].x);
  const bool up = std::is_sorted(xs.begin(), xs.end());
  const bool down = std::is_sorted(xs.rbegin(), xs.rend());
  EXPECT_TRUE(up || down);
  EXPECT_NEAR(o.path_length, 60.0 * 110.0 * std::acos(-1.0) / 180.0, 1e-2);
}

// A line of 25 units along x ending at the origin, then a quarter of the ellipse
// (2 sin θ, 1 − cos θ), θ ∈ [0, π/2]: its curvature rises to 2 (radius 0.5) at the end (2, 1),
// where the tangent is +y and the outward normal +x. `step` is the spacing on the line; the bend
// is sampled at equal steps of θ, `bend` samples.
std::vector<Vec3> line_then_bend(double step, std::size_t bend) {
  std::vector<Vec3> pts;
  for (double x = -25.0; x < -0.5 * step; x += step) pts.push_back({x, 0.0, 0.0});
  const double quarter = 0.5 * std::acos(-1.0);
  for (std::size_t k = 0; k <= bend; ++k) {
    const double th = quarter * static_cast<double>(k) / static_cast<double>(bend);
    pts.push_back({2.0 * std::sin(th), 1.0 - std::cos(th), 0.0});
  }
  return pts;
}

// Checks that exact points ending in a tight bend (4.5° of turn per sample, as the end of the real
// cage's curve 13, whose own test is ExchangeRealFiles.FitOfTheCagesCurve13) are all kept and all within the tolerance
// 1e-4 of the diagonal: exact design points are never strays, the last one included.
TEST(ScanFit, ExactPointsEndingInATightBendAreAllKept) {
  const std::vector<Vec3> pts = line_then_bend(0.25, 20);
  const double tol = 1e-4 * std::hypot(27.0, 1.0);
  const ScanFitResult r = fit_scan(pts, ScanFitOptions{.tolerance = tol, .ordered = true});
  EXPECT_TRUE(r.strays.empty()) << r.strays.size() << " strays";
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_LE(r.deviations[i], tol) << "point " << i;
}

// The dense scan of line_then_bend (spacing 0.01, Gaussian noise σ = 0.05 tolerance per coordinate,
// seeded) with its first or last point moved `off` tolerances off the curve (the first along the line's
// normal +y, the last along the bend's outward normal +x), in curve order or shuffled: that point must
// be the one stray and every other point within the tolerance of the returned curve (measured by
// nurbs::closest_point, not by the fit's own figures).
void expect_end_stray_found(double off, bool last, bool shuffle) {
  SCOPED_TRACE(std::to_string(off) + " tolerances off the " + (last ? "last" : "first") + " point" +
               (shuffle ? ", shuffled" : ", in order"));
  const double tol = 1e-4 * std::hypot(27.0, 1.0);
  std::vector<Vec3> pts = line_then_bend(0.01, 300);
  Rng rng(21);
  for (Vec3& q : pts) {
    q.x += 0.05 * tol * rng.normal();
    q.y += 0.05 * tol * rng.normal();
  }
  if (last) {
    pts.back().x += off * tol;
  } else {
    pts.front().y += off * tol;
  }
  std::size_t stray = last ? pts.size() - 1 : 0;
  if (shuffle) {
    std::vector<std::size_t> perm(pts.size());
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    for (std::size_t k = perm.size() - 1; k > 0; --k) std::swap(perm[k], perm[rng.below(k + 1)]);
    std::vector<Vec3> mixed(pts.size());
    const std::size_t moved = stray;
    for (std::size_t k = 0; k < perm.size(); ++k) {
      mixed[k] = pts[perm[k]];
      if (perm[k] == moved) stray = k;
    }
    pts = std::move(mixed);
  }
  const ScanFitResult r = fit_scan(pts, ScanFitOptions{.tolerance = tol, .ordered = !shuffle});
  EXPECT_EQ(r.strays, std::vector<std::size_t>{stray});
  EXPECT_GT(nurbs::closest_point(r.faired, pts[stray]).distance, tol);
  double worst = 0.0;
  for (std::size_t i = 0; i < pts.size(); i += 3)
    if (i != stray) worst = std::max(worst, nurbs::closest_point(r.faired, pts[i]).distance);
  EXPECT_LE(worst, tol * (1.0 + 1e-9));
}

// Checks the dense scan with a stray at either end: 4 tolerances off the first or the last point, and
// 10 off the first (on the line), in order and shuffled.
TEST(ScanFit, APointMovedOffEitherEndOfADenseScanIsTheOneStray) {
  for (const bool shuffle : {false, true}) {
    expect_end_stray_found(4.0, false, shuffle);
    expect_end_stray_found(4.0, true, shuffle);
    expect_end_stray_found(10.0, false, shuffle);
  }
}

// Checks the last point moved 8, 10 and 30 tolerances off the bend (outward): the refinement must not
// bend the end spans out to it, it is the one stray, in order and shuffled.
TEST(ScanFit, APointMovedFarOffTheBendAtTheEndIsTheOneStray) {
  for (const bool shuffle : {false, true})
    for (const double off : {8.0, 10.0, 30.0}) expect_end_stray_found(off, true, shuffle);
}

// Checks the documented errors: too few points, a non-finite point (named by index), bad options.
TEST(ScanFit, RejectsBadInputNamingIt) {
  std::vector<Vec3> few(5, Vec3{1, 2, 0});
  HULA_EXPECT_ERROR(static_cast<void>(fit_scan(few)), Errc::TooFewPoints, "5");
  const testing::Cloud cloud = testing::scanned_cloud(CloudSpec{.points = 100});
  std::vector<Vec3> bad = cloud.points;
  bad[17].y = std::nan("");
  HULA_EXPECT_ERROR(static_cast<void>(fit_scan(bad)), Errc::NonFiniteInput, "17");
  HULA_EXPECT_ERROR(static_cast<void>(fit_scan(cloud.points, ScanFitOptions{.tolerance = -1.0})), Errc::InvalidOption,
                    "tolerance");
  HULA_EXPECT_ERROR(static_cast<void>(fit_scan(cloud.points, ScanFitOptions{.degree = 2})), Errc::InvalidOption,
                    "degree");
  HULA_EXPECT_ERROR(static_cast<void>(fit_scan(cloud.points, ScanFitOptions{.degree = 4, .min_degree = 5})),
                    Errc::InvalidOption, "min_degree");
  std::vector<Vec3> same(20, Vec3{1, 1, 0});
  HULA_EXPECT_ERROR(static_cast<void>(order_along_curve(same)), Errc::CoincidentPoints, "coincide");
}

}  // namespace
}  // namespace hula::studies
