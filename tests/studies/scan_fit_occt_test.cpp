// SPDX-License-Identifier: MIT
// Open CASCADE's GeomAPI_PointsToBSpline beside studies::fit_scan on the same seeded clouds and
// tolerance (docs/studies.md "Scanned points to a class-A curve"): OCCT gets the inliers in curve
// order (it neither orders nor rejects), fit_scan the shuffled cloud with its strays. Both curves are
// measured by the same code (closest-point deviation of the inliers, control points, inflections,
// ∫κ'² ds). The table rows are printed for the docs.
#include <gtest/gtest.h>

#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAbs_Shape.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/studies/scan_fit.hpp"
#include "hula/testing/point_clouds.hpp"

namespace hula::studies {
namespace {

// Our NURBS of an OCCT B-spline (flat knots, poles, weights).
nurbs::NurbsCurve from_occt(const Geom_BSplineCurve& c, int dimension) {
  std::vector<double> knots;
  for (int i = 1; i <= c.NbKnots(); ++i)
    for (int k = 0; k < c.Multiplicity(i); ++k) knots.push_back(c.Knot(i));
  std::vector<Vec3> poles;
  for (int i = 1; i <= c.NbPoles(); ++i) poles.push_back({c.Pole(i).X(), c.Pole(i).Y(), c.Pole(i).Z()});
  std::vector<double> weights;
  if (c.IsRational())
    for (int i = 1; i <= c.NbPoles(); ++i) weights.push_back(c.Weight(i));
  return nurbs::NurbsCurve(c.Degree(), std::move(knots), std::move(poles), std::move(weights), dimension);
}

// The inliers of a cloud in curve order (OCCT neither orders nor rejects).
std::vector<Vec3> ordered_inliers(const testing::Cloud& ordered) {
  std::vector<Vec3> inliers;
  for (std::size_t i = 0; i < ordered.points.size(); ++i)
    if (!std::binary_search(ordered.strays.begin(), ordered.strays.end(), i)) inliers.push_back(ordered.points[i]);
  return inliers;
}

// Open CASCADE's approximation of `inliers` within `tolerance` (degree 3–8, C2).
Handle(Geom_BSplineCurve) occt_fit(const std::vector<Vec3>& inliers, double tolerance) {
  TColgp_Array1OfPnt pts(1, static_cast<int>(inliers.size()));
  for (std::size_t i = 0; i < inliers.size(); ++i)
    pts.SetValue(static_cast<int>(i) + 1, gp_Pnt(inliers[i].x, inliers[i].y, inliers[i].z));
  const GeomAPI_PointsToBSpline occt(pts, 3, 8, GeomAbs_C2, tolerance);
  if (!occt.IsDone()) return {};
  return occt.Curve();
}

// Most control points fit_scan may use where OCCT needs `occt` on the same inliers and tolerance:
// ours follows the scan to its noise (within 3 σ of the known curve) while OCCT stops at the first
// curve within the tolerance, which may cost two control points or half as many again.
std::size_t control_point_budget(std::size_t occt) { return std::max(occt + 2, (3 * occt + 1) / 2); }

struct Row {
  double max_dev = 0.0, mean_dev = 0.0, energy = 0.0, known = 0.0;
  std::size_t control_points = 0, inflections = 0;
  int degree = 0;
};

// Deviations of the inliers (closest point), and the curve's largest distance from the known curve
// at the inliers' feet (every tenth).
Row measure(const nurbs::NurbsCurve& c, const std::vector<Vec3>& inliers, testing::KnownCurve curve) {
  Row r;
  std::size_t k = 0;
  for (const Vec3& q : inliers) {
    const nurbs::ClosestPointResult foot = nurbs::closest_point(c, q);
    const double d = foot.distance;
    r.max_dev = std::max(r.max_dev, d);
    r.mean_dev += d;
    if (k++ % 10 == 0) r.known = std::max(r.known, testing::distance_to_known_curve(curve, c.evaluate(foot.t)));
  }
  r.mean_dev /= static_cast<double>(inliers.size());
  r.control_points = c.control_points().size();
  r.inflections = diffgeom::inflections(c).size();
  r.energy = diffgeom::curvature_variation_energy(c).value;
  r.degree = c.degree();
  return r;
}

// Checks that OCCT's approximation runs on every cloud (IsDone) and that fit_scan, on the same
// clouds shuffled and with strays, matches the known inflection count, keeps the inliers within
// the tolerance, stays within 3 σ of the known curve and uses at most control_point_budget of the
// control points OCCT uses on the clean ordered inliers;
// prints the rows of the docs table (OCCT, our tolerance fit before fairing, our faired curve).
TEST(ScanFitOcct, BesideGeomApiPointsToBSpline) {
  using testing::KnownCurve;
  std::printf(
      "| curve | noise | method | max dev | mean dev | from the known curve | degree | control points | inflections "
      "(known) | ∫κ'² ds |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (KnownCurve curve : {KnownCurve::Arc, KnownCurve::SCurve, KnownCurve::Wave})
    for (double noise : {0.05, 0.1}) {
      const testing::Cloud ordered =
          testing::scanned_cloud({.curve = curve, .points = 1000, .noise = noise, .shuffle = false, .seed = 1});
      const testing::Cloud shuffled =
          testing::scanned_cloud({.curve = curve, .points = 1000, .noise = noise, .shuffle = true, .seed = 1});
      const std::vector<Vec3> inliers = ordered_inliers(ordered);
      const Handle(Geom_BSplineCurve) occt = occt_fit(inliers, kClassATolerance);
      ASSERT_FALSE(occt.IsNull());
      const Row o = measure(from_occt(*occt, 2), inliers, curve);

      const ScanFitResult ours = fit_scan(shuffled.points);
      std::vector<Vec3> our_inliers;
      for (std::size_t i = 0; i < shuffled.points.size(); ++i)
        if (!std::binary_search(shuffled.strays.begin(), shuffled.strays.end(), i))
          our_inliers.push_back(shuffled.points[i]);
      const Row h = measure(ours.faired, our_inliers, curve);
      const Row b = measure(ours.fit, our_inliers, curve);
      EXPECT_EQ(ours.strays, shuffled.strays);
      EXPECT_LE(h.max_dev, kClassATolerance);
      EXPECT_EQ(h.inflections, testing::known_curve_inflections(curve));
      EXPECT_LE(h.known, 3.0 * noise);
      EXPECT_LE(h.control_points, control_point_budget(o.control_points));

      const std::size_t known = testing::known_curve_inflections(curve);
      const auto name = std::string(testing::known_curve_name(curve));
      std::printf(
          "| %s | %.2f | OCCT GeomAPI_PointsToBSpline (ordered inliers) | %.3f | %.3f | %.3f | %d | %zu | %zu (%zu) | "
          "%.3g |\n",
          name.c_str(), noise, o.max_dev, o.mean_dev, o.known, o.degree, o.control_points, o.inflections, known,
          o.energy);
      std::printf(
          "| %s | %.2f | hula fit, tolerance fit (shuffled, 1 %% strays) | %.3f | %.3f | %.3f | %d | %zu | %zu (%zu) | "
          "%.3g |\n",
          name.c_str(), noise, b.max_dev, b.mean_dev, b.known, b.degree, b.control_points, b.inflections, known,
          b.energy);
      std::printf(
          "| %s | %.2f | hula fit, faired (shuffled, 1 %% strays) | %.3f | %.3f | %.3f | %d | %zu | %zu (%zu) | %.3g "
          "|\n",
          name.c_str(), noise, h.max_dev, h.mean_dev, h.known, h.degree, h.control_points, h.inflections, known,
          h.energy);
    }
}

// Checks the control-point count of fit_scan (as scan_fit_test.cpp runs it: tolerance = A-class,
// shuffled cloud with strays) against the reference, OCCT's GeomAPI_PointsToBSpline at the same
// tolerance on the same cloud's ordered inliers, on every curve × noise of that test and seeds 1–3:
// at most control_point_budget(OCCT's count).
TEST(ScanFitOcct, ControlPointsWithinOcctReference) {
  using testing::KnownCurve;
  for (KnownCurve curve : {KnownCurve::Arc, KnownCurve::SCurve, KnownCurve::Wave})
    for (double noise : {0.05, 0.1})
      for (std::uint64_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(std::string(testing::known_curve_name(curve)) + " noise " + std::to_string(noise) + " seed " +
                     std::to_string(seed));
        const testing::Cloud ordered =
            testing::scanned_cloud({.curve = curve, .points = 1000, .noise = noise, .shuffle = false, .seed = seed});
        const Handle(Geom_BSplineCurve) occt = occt_fit(ordered_inliers(ordered), kClassATolerance);
        ASSERT_FALSE(occt.IsNull());
        const testing::Cloud shuffled =
            testing::scanned_cloud({.curve = curve, .points = 1000, .noise = noise, .shuffle = true, .seed = seed});
        const ScanFitResult r = fit_scan(shuffled.points, ScanFitOptions{.tolerance = kClassATolerance});
        const auto reference = static_cast<std::size_t>(occt->NbPoles());
        EXPECT_LE(r.fit.control_points().size(), control_point_budget(reference)) << "OCCT: " << reference;
      }
}

}  // namespace
}  // namespace hula::studies
