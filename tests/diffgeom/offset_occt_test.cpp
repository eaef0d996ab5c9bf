// SPDX-License-Identifier: MIT
// Oracle: planar offsets against Open CASCADE 7.6's Geom_OffsetCurve (offset
// direction V = −Z: OCCT offsets along T × V, so −Z gives our left normal) sampled at 1,000
// parameters, on seeded corpora from two independent generators: random C1
// planar B-splines (testing::random_curve, interior multiplicities below the
// degree, rational or not) and cubic splines interpolated through random
// points plus rational circles. The raw offset (tolerance 1e-9) of a regular
// offset (|d| below the smallest radius of curvature) lies within 1e-8 of
// OCCT's offset point at every sample; every point of the trimmed offset lies
// at |d| from the curve by OCCT's own extrema.
#include <gtest/gtest.h>

#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_OffsetCurve.hxx>
#include <cmath>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/diffgeom/offset.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/occt_curve.hpp"

namespace hula::diffgeom {
namespace {

using testing::to_occt;

// The curve with z dropped, as a 2-D curve.
nurbs::NurbsCurve planar(const nurbs::NurbsCurve& c) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p.z = 0.0;
  return nurbs::NurbsCurve(c.knots(), std::move(P), {c.weights().begin(), c.weights().end()}, 2);
}

// C1 everywhere: every interior knot's multiplicity is below the degree.
bool is_c1(const nurbs::NurbsCurve& c) {
  const auto U = c.knots().values();
  const Interval d = c.domain();
  for (double u : U)
    if (u > d.start && u < d.end && c.knots().multiplicity(u) >= c.degree()) return false;
  return true;
}

// Corpus: generator 1, random planar C1 B-splines; generator 2, interpolated cubics and rational circles.
std::vector<nurbs::NurbsCurve> corpus() {
  std::vector<nurbs::NurbsCurve> out;
  Rng rng(2026, 26);
  while (out.size() < 12) {
    testing::RandomCurveSpec spec;
    spec.degree = 2 + static_cast<int>(out.size() % 3);
    spec.rational = out.size() % 2 == 1;
    const nurbs::NurbsCurve c = planar(testing::random_curve(rng, spec));
    if (is_c1(c)) out.push_back(c);
  }
  for (int k = 0; k < 6; ++k) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 7; ++i) pts.push_back({3.0 * i + rng.uniform(-1, 1), rng.uniform(-3, 3), 0.0});
    nurbs::InterpolationOptions o;
    o.dimension = 2;
    out.push_back(nurbs::interpolate_cubic(pts, o));
  }
  out.push_back(testing::rational_circle(2.0, 0.3));
  out.push_back(testing::rational_circle(0.5));
  return out;
}

// The largest curvature over 2,000 samples (from the curve's own derivatives).
double max_curvature(const nurbs::NurbsCurve& c) {
  double k = 0.0;
  const Interval dom = c.domain();
  for (int i = 0; i <= 2000; ++i) {
    const auto d = c.derivatives(dom.start + (dom.end - dom.start) * i / 2000.0, 2);
    k = std::max(k, norm(cross(d[1], d[2])) / std::pow(norm(d[1]), 3));
  }
  return k;
}

// checks the raw offset against Geom_OffsetCurve at 1,000 samples (1e-8), for d of both signs, where the offset is
// regular (|d| below the smallest radius of curvature, so no cusp: cusps are checked against closed forms in
// offset_test.cpp).
TEST(PlanarOffsetOcct, RawOffsetMatchesGeomOffsetCurve) {
  Rng rng(7, 26);
  int cases = 0;
  for (const nurbs::NurbsCurve& c : corpus()) {
    const double radius = 1.0 / max_curvature(c);
    for (double sign : {1.0, -1.0}) {
      const double d = sign * rng.uniform(0.2, 0.9) * radius;
      OffsetOptions o;
      o.tolerance = 1e-9;
      o.trim = false;
      const PlanarOffset ours = planar_offset(curve::Curve(c), d, o);
      const Handle(Geom_OffsetCurve) occt = new Geom_OffsetCurve(to_occt(c), d, gp_Dir(0, 0, -1));
      const Interval dom = c.domain();
      double worst = 0.0;
      for (int i = 0; i <= 1000; ++i) {
        const double t = dom.start + (dom.end - dom.start) * i / 1000.0;
        worst = std::max(worst, norm(ours.raw.point(t) - testing::to_vec3(occt->Value(t))));
      }
      EXPECT_LE(worst, 1e-8) << "case " << cases << " d=" << d;
      EXPECT_LE(ours.deviation, 1e-8);
      ++cases;
    }
  }
  EXPECT_EQ(cases, 40);
}

// The distance from p to the curve by OCCT: the curve sampled at 1,000 parameters, then GeomAPI_ProjectPointOnCurve
// on the bracket of every sampled local minimum (over the whole domain it misses some feet of these many-span
// curves), the curve's ends as candidates.
double occt_distance(const Handle(Geom_BSplineCurve) & curve, const Vec3& p) {
  constexpr int kSamples = 1000;
  const gp_Pnt q(p.x, p.y, p.z);
  const double u0 = curve->FirstParameter();
  const double u1 = curve->LastParameter();
  auto u = [&](int i) { return i == kSamples ? u1 : u0 + (u1 - u0) * i / kSamples; };
  std::vector<double> sampled(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) sampled[static_cast<std::size_t>(i)] = q.Distance(curve->Value(u(i)));
  double best = std::min(sampled.front(), sampled.back());
  for (int i = 0; i <= kSamples; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if ((i > 0 && sampled[k] > sampled[k - 1]) || (i < kSamples && sampled[k] > sampled[k + 1])) continue;
    const int lo = std::max(i - 1, 0);
    const int hi = std::min(i + 1, kSamples);
    GeomAPI_ProjectPointOnCurve proj(q, curve, u(lo), u(hi));
    if (proj.NbPoints() > 0) best = std::min(best, proj.LowerDistance());
    // A foot where the distance is nearly flat (p near a centre of curvature) can escape the projection's
    // Newton step: a golden-section search of OCCT's own points on the bracket backs it up.
    double a = u(lo);
    double b = u(hi);
    constexpr double kGolden = 0.6180339887498949;
    for (int it = 0; it < 80; ++it) {
      const double x1 = b - kGolden * (b - a);
      const double x2 = a + kGolden * (b - a);
      if (q.Distance(curve->Value(x1)) < q.Distance(curve->Value(x2)))
        b = x2;
      else
        a = x1;
    }
    best = std::min(best, q.Distance(curve->Value(0.5 * (a + b))));
  }
  return best;
}

// checks every point of the trimmed offset lies |d| from the curve by OCCT (1e-7), on the corpus with distances
// large enough to make cusps and loops (and, on the curled random curves, stretches of the offset that the curve
// reaches from its other side); counts the loops trimmed.
TEST(PlanarOffsetOcct, TrimmedOffsetLiesAtTheDistance) {
  Rng rng(11, 26);
  int loops = 0;
  int samples = 0;
  for (const nurbs::NurbsCurve& c : corpus()) {
    const double d = (rng.uniform() < 0.5 ? 1.0 : -1.0) * rng.uniform(0.05, 0.2) * c.model_size();
    OffsetOptions o;
    o.tolerance = 1e-9;
    const PlanarOffset ours = planar_offset(curve::Curve(c), d, o);
    loops += static_cast<int>(ours.loops.size());
    const Handle(Geom_BSplineCurve) basis = to_occt(c);
    for (const OffsetPiece& piece : ours.trimmed) {
      const Interval dom = piece.curve.domain();
      for (int i = 0; i <= 200; ++i) {
        const Vec3 p = piece.curve.evaluate(i == 200 ? dom.end : dom.start + (dom.end - dom.start) * i / 200.0);
        const double dist = occt_distance(basis, p);
        EXPECT_NEAR(dist, std::abs(d), 1e-7) << "d=" << d;
        ++samples;
      }
    }
  }
  std::printf("loops trimmed on the corpus: %d; trimmed points checked: %d\n", loops, samples);
  EXPECT_GT(loops, 0);
  EXPECT_GE(samples, 20 * 201);  // every curve keeps some of its offset
}

}  // namespace
}  // namespace hula::diffgeom
