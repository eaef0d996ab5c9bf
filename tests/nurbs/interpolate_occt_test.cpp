// SPDX-License-Identifier: MIT
// Oracle: the global cubic spline against Open CASCADE's GeomAPI_Interpolate
// (OCCT 7.6) on seeded random point sets.
//
//  - Clamped ends vs GeomAPI_Interpolate(points, parameters, false, tol) with
//    Load(d0, d1, Standard_False) (tangents used as given, no scaling).
//  - EndCondition::occt() vs GeomAPI_Interpolate without tangents. OCCT's
//    convention (GeomAPI_Interpolate::PerformNonPeriodic / BuildTangents):
//    N = 2 gives a degree-1 segment, N = 3 a degree-2 Bézier through the three
//    points at their parameters, N ≥ 4 a clamped cubic with simple knots at the
//    parameters whose end derivatives are those of the cubic Lagrange
//    polynomial through the first (last) four points (PLib::EvalLagrange).
//    Our occt end reproduces all three as a cubic with breakpoints at the data
//    parameters (the same curve, degree-elevated / with t_1 as a knot).
//
// Rebuild (nurbs::rebuild): its reported deviation, measured with our
// closest_point onto the original, is measured again with Open CASCADE's
// GeomAPI_ProjectPointOnCurve onto the original converted to a
// Geom_BSplineCurve, at the same samples of the rebuilt curve.
//
// Comparison rule: for derivative order k = 0 … 3, scale_k = max over the
// sample parameters of |C^(k)| (ours), raised to at least scale_{k-1} (a
// derivative that vanishes identically, as C'' of the N = 2 segment or C'''
// of the N = 3 parabola, is judged against the next lower order, since on the
// unit domain all orders share the model's units); every sample must satisfy
// |ours^(k)(t) - occt^(k)(t)| ≤ 1e-12 · max(|ours^(k)(t)|, scale_k), i.e. 1e-12
// relative to the typical size of that derivative on the curve. Samples are
// the span midpoints plus random parameters, never exactly a knot (where C'''
// is one-sided and the two libraries may pick different sides).
#include <gtest/gtest.h>

#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <algorithm>
#include <array>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/approximate.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/occt_curve.hpp"

namespace hula::nurbs {
namespace {

constexpr double kRel = 1e-12;

std::vector<Vec3> random_points(std::size_t n, Rng& rng, double scale) {
  std::vector<Vec3> p(n);
  for (auto& q : p) q = Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)} * scale;
  return p;
}

Vec3 to_vec(const gp_XYZ& v) { return {v.X(), v.Y(), v.Z()}; }

Handle(Geom_BSplineCurve)
    occt_interpolate(const std::vector<Vec3>& pts, const std::vector<double>& t, const Vec3* d0, const Vec3* d1) {
  const int n = static_cast<int>(pts.size());
  Handle(TColgp_HArray1OfPnt) P = new TColgp_HArray1OfPnt(1, n);
  Handle(TColStd_HArray1OfReal) T = new TColStd_HArray1OfReal(1, n);
  for (int i = 0; i < n; ++i) {
    const auto& q = pts[static_cast<std::size_t>(i)];
    P->SetValue(i + 1, gp_Pnt(q.x, q.y, q.z));
    T->SetValue(i + 1, t[static_cast<std::size_t>(i)]);
  }
  GeomAPI_Interpolate interp(P, T, Standard_False, 1e-9);
  if (d0 != nullptr && d1 != nullptr)
    interp.Load(gp_Vec(d0->x, d0->y, d0->z), gp_Vec(d1->x, d1->y, d1->z), Standard_False);
  interp.Perform();
  EXPECT_TRUE(interp.IsDone());
  return interp.Curve();
}

std::vector<double> sample_parameters(const std::vector<double>& t, Rng& rng) {
  std::vector<double> s;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) s.push_back(0.5 * (t[i] + t[i + 1]));
  for (int i = 0; i < 200; ++i) {
    const double u = rng.uniform(1e-9, 1.0 - 1e-9);
    if (!std::binary_search(t.begin(), t.end(), u)) s.push_back(u);
  }
  s.push_back(0.0);
  s.push_back(1.0);
  return s;
}

void compare(const NurbsCurve& ours, const Handle(Geom_BSplineCurve) & theirs, const std::vector<double>& samples,
             const std::string& label) {
  std::vector<std::array<Vec3, 4>> a(samples.size()), b(samples.size());
  std::array<double, 4> scale{};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto d = ours.derivatives(samples[i], 3);
    gp_Pnt p;
    gp_Vec v1, v2, v3;
    theirs->D3(samples[i], p, v1, v2, v3);
    a[i] = {d[0], d[1], d[2], d[3]};
    b[i] = {to_vec(p.XYZ()), to_vec(v1.XYZ()), to_vec(v2.XYZ()), to_vec(v3.XYZ())};
    for (std::size_t k = 0; k < 4; ++k) scale[k] = std::max(scale[k], norm(a[i][k]));
  }
  for (std::size_t k = 1; k < 4; ++k) scale[k] = std::max(scale[k], scale[k - 1]);
  for (std::size_t i = 0; i < samples.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k) {
      const double tol = kRel * std::max(norm(a[i][k]), scale[k]);
      EXPECT_LE(distance(a[i][k], b[i][k]), tol)
          << label << " order " << k << " at t = " << samples[i] << " (scale " << scale[k] << ")";
    }
}

// checks: clamped ends equal GeomAPI_Interpolate with Load(d0, d1, no scaling): positions and derivatives to order 3.
TEST(InterpolateOcct, ClampedMatchesGeomApiInterpolateWithTangents) {
  for (std::size_t n : {2u, 3u, 4u, 10u, 100u}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      Rng rng(seed, n);
      const auto pts = random_points(n, rng, 10.0);
      const Vec3 d0 = Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)} * 30.0;
      const Vec3 d1 = Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)} * 30.0;
      for (auto rule : {Parameterisation::ChordLength, Parameterisation::Centripetal, Parameterisation::Uniform}) {
        const auto t = parameterise(pts, rule);
        const NurbsCurve ours = interpolate_cubic(
            pts, {.parameterisation = rule, .start = EndCondition::clamped(d0), .end = EndCondition::clamped(d1)});
        compare(ours, occt_interpolate(pts, t, &d0, &d1), sample_parameters(t, rng),
                "clamped n=" + std::to_string(n) + " seed=" + std::to_string(seed));
      }
    }
  }
}

// checks: EndCondition::occt() equals GeomAPI_Interpolate without tangents (including N = 2 and 3, where OCCT
// returns degree 1 and 2 curves), positions and derivatives to order 3.
TEST(InterpolateOcct, OcctEndMatchesGeomApiInterpolateWithoutTangents) {
  for (std::size_t n : {2u, 3u, 4u, 5u, 10u, 100u}) {
    for (std::uint64_t seed : {11u, 12u, 13u}) {
      Rng rng(seed, n);
      const auto pts = random_points(n, rng, 10.0);
      for (auto rule : {Parameterisation::ChordLength, Parameterisation::Centripetal}) {
        const auto t = parameterise(pts, rule);
        const NurbsCurve ours = interpolate_cubic(
            pts, {.parameterisation = rule, .start = EndCondition::occt(), .end = EndCondition::occt()});
        compare(ours, occt_interpolate(pts, t, nullptr, nullptr), sample_parameters(t, rng),
                "occt n=" + std::to_string(n) + " seed=" + std::to_string(seed));
      }
    }
  }
}

// checks: OCCT's own chord-length parameters (GeomAPI_Interpolate(points, false, tol), parameters = cumulative
// chord lengths, not normalised) give the same curve as ours after the affine map to [0, 1].
TEST(InterpolateOcct, OcctOwnParametersAreChordLengths) {
  Rng rng(77);
  const auto pts = random_points(12, rng, 5.0);
  const int n = static_cast<int>(pts.size());
  Handle(TColgp_HArray1OfPnt) P = new TColgp_HArray1OfPnt(1, n);
  for (int i = 0; i < n; ++i) {
    const auto& q = pts[static_cast<std::size_t>(i)];
    P->SetValue(i + 1, gp_Pnt(q.x, q.y, q.z));
  }
  GeomAPI_Interpolate interp(P, Standard_False, 1e-9);
  interp.Perform();
  ASSERT_TRUE(interp.IsDone());
  const Handle(Geom_BSplineCurve) c = interp.Curve();
  const auto L = cumulative_chord_lengths(pts);
  EXPECT_NEAR(c->FirstParameter(), 0.0, 1e-15);
  EXPECT_NEAR(c->LastParameter(), L.back(), 1e-12 * L.back());
  const NurbsCurve ours = interpolate_cubic(pts, {.start = EndCondition::occt(), .end = EndCondition::occt()});
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const gp_Pnt p = c->Value(u * L.back());
    EXPECT_LE(distance(ours.evaluate(u), {p.X(), p.Y(), p.Z()}), 1e-12 * 10) << u;
  }
}

// checks rebuild's max_deviation and its parameter against Open CASCADE: the 1,001 samples of the rebuilt curve
// (uniform in its parameter) projected onto the original as a Geom_BSplineCurve (GeomAPI_ProjectPointOnCurve,
// LowerDistance) give the same largest distance to 1e-9 of the curve's size, on seeded random rational cubics and
// quartics with interior knots, rebuilt as cubics and quintics.
TEST(RebuildOcct, DeviationMatchesProjectionOntoTheOriginal) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    Rng rng(seed, 26);
    const int p = 3 + static_cast<int>(seed % 2);
    const std::size_t n = 8;
    std::vector<double> U(static_cast<std::size_t>(p) + 1, 0.0);
    std::vector<double> inner;
    for (std::size_t i = 0; i + static_cast<std::size_t>(p) + 1 < n; ++i) inner.push_back(rng.uniform(0.05, 0.95));
    std::sort(inner.begin(), inner.end());
    U.insert(U.end(), inner.begin(), inner.end());
    U.insert(U.end(), static_cast<std::size_t>(p) + 1, 1.0);
    std::vector<double> w(n);
    for (auto& x : w) x = rng.uniform(0.5, 2.0);
    const NurbsCurve original(p, U, random_points(n, rng, 10.0), w);
    const Handle(Geom_BSplineCurve) occ = testing::to_occt(original);
    for (auto [degree, count] : {std::pair{3, std::size_t{12}}, std::pair{5, std::size_t{16}}}) {
      const RebuildResult r = rebuild(original, {.degree = degree, .control_points = count});
      double worst = 0.0;
      double at = 0.0;
      for (int i = 0; i <= 1000; ++i) {
        const double s = i == 1000 ? 1.0 : i / 1000.0;
        const Vec3 x = r.curve.evaluate(s);
        GeomAPI_ProjectPointOnCurve proj(gp_Pnt(x.x, x.y, x.z), occ);
        ASSERT_GT(proj.NbPoints(), 0) << s;
        const double d = proj.LowerDistance();
        if (d > worst) worst = d, at = s;
      }
      const double size = original.model_size();
      EXPECT_NEAR(r.max_deviation, worst, 1e-9 * size) << seed << " " << degree;
      EXPECT_NEAR(r.at, at, 1e-12) << seed << " " << degree;
      EXPECT_GT(worst, 1e-9 * size) << seed;  // a rational cubic with random weights is not in the new space
    }
  }
}

}  // namespace
}  // namespace hula::nurbs
