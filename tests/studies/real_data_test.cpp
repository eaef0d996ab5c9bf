// SPDX-License-Identifier: MIT
// The real airfoil files of tests/data/real, read as shipped, through the scan fit without being
// told they are ordered (the file order must be found consistent), in reverse, and through the
// fairing assistant. Deviations are measured by nurbs::closest_point on the result (a global
// search and Newton foot point), not by the fit's own residuals. real_data_occt_test.cpp measures
// the ordered fits with Open CASCADE beside GeomAPI_PointsToBSpline.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/io/points_file.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/studies/fairing_assistant.hpp"
#include "hula/studies/scan_fit.hpp"

namespace hula::studies {
namespace {

constexpr double kTolerance = 1e-4;

std::vector<std::filesystem::path> airfoil_files() {
  const char* root = std::getenv("HULA_TEST_DATA");
  std::vector<std::filesystem::path> out;
  if (root == nullptr) return out;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(root) / "real"))
    if (e.path().extension() == ".dat") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

double max_closest_distance(const nurbs::NurbsCurve& c, const std::vector<Vec3>& points) {
  double worst = 0.0;
  for (const Vec3& q : points) worst = std::max(worst, nurbs::closest_point(c, q).distance);
  return worst;
}

// Checks that without --ordered every airfoil's file order is recognised ("file", not the
// spanning tree), every point is kept and within 1e-4 of the curve, with at most 40 control points
// and fewer curvature extrema than the cubic interpolant; and the same for the points in reverse order.
TEST(RealAirfoils, FileOrderIsDetectedAndEveryPointKept) {
  const auto files = airfoil_files();
  ASSERT_GE(files.size(), 10u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    std::vector<Vec3> pts = io::read_points_file(file).points;
    const std::size_t interpolant =
        diffgeom::curvature_extrema(nurbs::interpolate_cubic(pts, nurbs::InterpolationOptions{})).size();
    for (const bool reversed : {false, true}) {
      SCOPED_TRACE(reversed ? "reversed" : "as shipped");
      if (reversed) std::reverse(pts.begin(), pts.end());
      const ScanFitResult r = fit_scan(pts, ScanFitOptions{.tolerance = kTolerance});
      EXPECT_EQ(r.ordering, OrderSource::File);
      EXPECT_FALSE(r.closed);  // the trailing edge is a corner (or a gap), not a smooth join
      EXPECT_TRUE(r.strays.empty()) << r.strays.size() << " strays";
      EXPECT_LE(max_closest_distance(r.faired, pts), kTolerance * (1.0 + 1e-9));
      EXPECT_LE(r.faired.control_points().size(), 40u);
      EXPECT_LT(diffgeom::curvature_extrema(r.faired).size(), interpolant);
    }
  }
}

// Checks the fairing assistant on the cubic spline through every airfoil's points: the ghost's
// ∫κ'² ds (re-measured) is lower, every data point of the file is within the tolerance of the ghost
// curve (closest point), and no point moved farther than the tolerance.
TEST(RealAirfoils, FairingAssistantStaysWithinTolerance) {
  for (const auto& file : airfoil_files()) {
    SCOPED_TRACE(file.filename().string());
    curve::InterpolatedData d;
    d.points = io::read_points_file(file).points;
    d.dimension = 2;
    const curve::Curve spline = curve::Curve::interpolated(d);
    const AssistantResult r = fair_within_tolerance(
        spline, {.method = AssistantMethod::MinimalVariation, .tolerance = kTolerance, .time_budget_seconds = 0.25});
    const double before = diffgeom::curvature_variation_energy(spline.nurbs()).value;
    const double after = diffgeom::curvature_variation_energy(r.curve.nurbs()).value;
    EXPECT_LT(after, before);
    EXPECT_LE(r.max_deviation, kTolerance);
    EXPECT_LE(max_closest_distance(r.curve.nurbs(), d.points), kTolerance * (1.0 + 1e-9));
  }
}

// Checks the fairing assistant on the curve `hula fit --ordered --tolerance 1e-4` returns for every
// airfoil, given what is left of the tolerance (1e-4 less the fit's own deviation, measured here by
// closest point): the ghost's ∫κ'² ds (re-measured) is lower than the fitted curve's, and every point of
// the file is within 1e-4 of the ghost (closest point) — the control points move by at most the rest,
// so the curve does too.
TEST(RealAirfoils, FairingAssistantOnTheFittedCurve) {
  const auto files = airfoil_files();
  ASSERT_GE(files.size(), 10u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const std::vector<Vec3> pts = io::read_points_file(file).points;
    const ScanFitResult fit = fit_scan(pts, ScanFitOptions{.tolerance = kTolerance, .ordered = true});
    const double rest = kTolerance - max_closest_distance(fit.faired, pts);
    ASSERT_GT(rest, 0.0);
    const curve::Curve fitted(fit.faired);
    const AssistantResult r = fair_within_tolerance(
        fitted, {.method = AssistantMethod::MinimalVariation, .tolerance = rest, .time_budget_seconds = 0.25});
    const double before = diffgeom::curvature_variation_energy(fit.faired).value;
    const double after = diffgeom::curvature_variation_energy(r.curve.nurbs()).value;
    EXPECT_LT(after, before);
    EXPECT_LE(r.max_deviation, rest);
    EXPECT_LE(max_closest_distance(r.curve.nurbs(), pts), kTolerance * (1.0 + 1e-9));
    std::printf("%s: fit %zu control points, rest %.3g, ∫κ'² ds %.6g -> %.6g\n", file.filename().string().c_str(),
                fit.faired.control_points().size(), rest, before, after);
  }
}

}  // namespace
}  // namespace hula::studies
