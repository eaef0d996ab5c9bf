// SPDX-License-Identifier: MIT
// The airfoil files of tests/data/real (read as shipped) fitted by `hula fit --ordered
// --tolerance 1e-4` (studies::fit_scan) and by `hula approximate --tolerance 1e-4`
// (studies::fit_within_tolerance, degree 3, ends on the first and last point), measured by
// Open CASCADE: every point's distance to our curve by GeomAPI_ProjectPointOnCurve (not the
// fit's own residuals); beside them the same tolerance given to a plain least-squares fit
// (nurbs::approximate_to_tolerance: chord-length parameters, averaged knots, no parameter
// correction) and to OCCT's GeomAPI_PointsToBSpline (degree 3–8, C2). The rows are printed
// for docs/studies.md.
#include <gtest/gtest.h>

#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAbs_Shape.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "hula/diffgeom/features.hpp"
#include "hula/io/points_file.hpp"
#include "hula/nurbs/approximate.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/studies/scan_fit.hpp"
#include "hula/studies/tolerance_fit.hpp"
#include "hula/testing/occt_curve.hpp"

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

// Largest distance of the points from an OCCT curve: its orthogonal projections and its two ends
// (OCCT's extrema omit an end the point lies beyond).
double occt_max_distance(const Handle(Geom_Curve) & curve, const std::vector<Vec3>& points) {
  const gp_Pnt a = curve->Value(curve->FirstParameter()), b = curve->Value(curve->LastParameter());
  double worst = 0.0;
  for (const Vec3& q : points) {
    const gp_Pnt p(q.x, q.y, q.z);
    double d = std::min(p.Distance(a), p.Distance(b));
    GeomAPI_ProjectPointOnCurve projection(p, curve);
    if (projection.NbPoints() > 0) d = std::min(d, projection.LowerDistance());
    worst = std::max(worst, d);
  }
  return worst;
}

double milliseconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Checks, on every airfoil file: `hula fit` keeps every point, each within 1e-4 of the faired
// curve by OCCT's projection, with at most 40 control points and no more than either the plain
// least-squares fit or OCCT's GeomAPI_PointsToBSpline (same tolerance) needs, and fewer curvature
// extrema than the cubic spline through the same points; `hula approximate`'s engine (cubic, its
// curve through the first and last point) within the tolerance with no more control points than the
// plain least-squares fit.
TEST(RealAirfoilsOcct, FitAndApproximateBesideGeomApiPointsToBSpline) {
  const std::vector<std::filesystem::path> files = airfoil_files();
  ASSERT_GE(files.size(), 10u);
  std::printf(
      "| airfoil | points | hula fit: control points (degree) | max dev (OCCT-measured) | curvature extrema (cubic "
      "interpolant) | ms | hula approximate (cubic): control points | max dev | extrema | plain least squares: control "
      "points | OCCT GeomAPI_PointsToBSpline: control points (degree) | its max dev | its extrema | OCCT ms |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const std::vector<Vec3> pts = io::read_points_file(file).points;
    const std::size_t interpolant_extrema =
        diffgeom::curvature_extrema(nurbs::interpolate_cubic(pts, nurbs::InterpolationOptions{})).size();

    auto t0 = std::chrono::steady_clock::now();
    const ScanFitResult fit = fit_scan(pts, ScanFitOptions{.tolerance = kTolerance, .ordered = true});
    const double fit_ms = milliseconds_since(t0);
    const double fit_dev = occt_max_distance(testing::to_occt(fit.faired), pts);
    const std::size_t fit_extrema = diffgeom::curvature_extrema(fit.faired).size();
    EXPECT_TRUE(fit.strays.empty()) << fit.strays.size() << " strays";
    EXPECT_LE(fit_dev, kTolerance * (1.0 + 1e-9));
    EXPECT_LE(fit.faired.control_points().size(), 40u);
    EXPECT_LT(fit_extrema, interpolant_extrema);

    ToleranceFitOptions a;
    a.tolerance = kTolerance;
    a.degree = 3;
    a.min_degree = 3;
    a.ends = FitEnds::Interpolated;
    a.max_control_points = pts.size();
    const ToleranceFit approx =
        fit_within_tolerance(pts, nurbs::parameterise(pts, nurbs::Parameterisation::ChordLength), {}, a);
    const double approx_dev = occt_max_distance(testing::to_occt(approx.faired), pts);
    EXPECT_TRUE(approx.outliers.empty());
    EXPECT_LE(approx_dev, kTolerance * (1.0 + 1e-9));
    EXPECT_EQ(approx.faired.evaluate(0.0), pts.front());
    EXPECT_EQ(approx.faired.evaluate(1.0), pts.back());
    // A cubic's curvature has a kink at every knot: approximate's extrema are reported, not bounded.
    const std::size_t approx_extrema = diffgeom::curvature_extrema(approx.faired).size();

    const nurbs::ToleranceFitResult plain = nurbs::approximate_to_tolerance(pts, kTolerance);
    EXPECT_LE(fit.faired.control_points().size(), plain.fit.curve.control_points().size());
    EXPECT_LE(approx.faired.control_points().size(), plain.fit.curve.control_points().size());

    TColgp_Array1OfPnt array(1, static_cast<int>(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i)
      array.SetValue(static_cast<int>(i) + 1, gp_Pnt(pts[i].x, pts[i].y, pts[i].z));
    t0 = std::chrono::steady_clock::now();
    const GeomAPI_PointsToBSpline occt(array, 3, 8, GeomAbs_C2, kTolerance);
    const double occt_ms = milliseconds_since(t0);
    ASSERT_TRUE(occt.IsDone());
    const Handle(Geom_BSplineCurve) oc = occt.Curve();
    EXPECT_LE(fit.faired.control_points().size(), static_cast<std::size_t>(oc->NbPoles()));
    const double occt_dev = occt_max_distance(oc, pts);
    std::vector<double> knots;
    for (int i = 1; i <= oc->NbKnots(); ++i)
      for (int k = 0; k < oc->Multiplicity(i); ++k) knots.push_back(oc->Knot(i));
    std::vector<Vec3> poles;
    for (int i = 1; i <= oc->NbPoles(); ++i) poles.push_back(testing::to_vec3(oc->Pole(i)));
    const std::size_t occt_extrema =
        diffgeom::curvature_extrema(nurbs::NurbsCurve(oc->Degree(), knots, poles, {}, 2)).size();

    std::printf(
        "| %s | %zu | %zu (%d) | %.3g | %zu (%zu) | %.0f | %zu | %.3g | %zu | %zu | %d (%d) | %.3g | %zu | %.1f |\n",
        file.filename().string().c_str(), pts.size(), fit.faired.control_points().size(), fit.faired.degree(), fit_dev,
        fit_extrema, interpolant_extrema, fit_ms, approx.faired.control_points().size(), approx_dev, approx_extrema,
        plain.fit.curve.control_points().size(), oc->NbPoles(), oc->Degree(), occt_dev, occt_extrema, occt_ms);
  }
}

}  // namespace
}  // namespace hula::studies
