// SPDX-License-Identifier: MIT
// Oracle: NurbsCurve positions and derivatives up to order 3 against Open
// CASCADE 7.6 Geom_BSplineCurve::D3 (and LocalD3 for one-sided limits) on
// seeded random curves, rational and not, with repeated knots. Pattern of
// OCCT's GeomProp_VsCLProps_Test: named per-quantity tolerance, the parameter
// in the failure message.
//
// Tolerance rule: |ours - occt| ≤ 1e-12 × scale_k, where scale_k is the
// largest |C^(k)| over the samples of that curve (derivatives near zero are
// compared against the curve's own derivative magnitude, not against 0).
#include <gtest/gtest.h>

#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <array>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/occt_curve.hpp"

namespace hula::nurbs {
namespace {

using testing::to_occt;
using testing::to_vec3;

// rel_tol[k]: tolerance for order k relative to scale_k. `use_value` compares
// positions with Geom_BSplineCurve::Value (de Boor) instead of D3's cached
// polynomial.
void compare_curve(const NurbsCurve& c, Rng& rng, int curve_index,
                   std::array<double, 4> rel_tol = {1e-12, 1e-12, 1e-12, 1e-12}, bool use_value = false) {
  Handle(Geom_BSplineCurve) occ = to_occt(c);
  const Interval d = c.domain();
  std::vector<double> ts;
  for (int i = 0; i < 60; ++i) ts.push_back(rng.uniform(d.start, d.end));
  ts.push_back(d.start);
  ts.push_back(d.end);
  std::vector<std::array<Vec3, 4>> ours, theirs;
  for (double t : ts) {
    const auto D = c.derivatives(t, 3);
    gp_Pnt p;
    gp_Vec v1, v2, v3v;
    occ->D3(t, p, v1, v2, v3v);
    if (use_value) p = occ->Value(t);
    ours.push_back({D[0], D[1], D[2], D[3]});
    theirs.push_back({to_vec3(p), to_vec3(v1), to_vec3(v2), to_vec3(v3v)});
  }
  double scale[4] = {0, 0, 0, 0};
  for (const auto& o : theirs)
    for (int k = 0; k < 4; ++k) scale[k] = std::max(scale[k], norm(o[static_cast<std::size_t>(k)]));
  for (std::size_t i = 0; i < ts.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      const auto K = static_cast<std::size_t>(k);
      EXPECT_LE(distance(ours[i][K], theirs[i][K]), rel_tol[K] * scale[k])
          << "curve " << curve_index << " degree " << c.degree() << (c.is_rational() ? " rational" : "")
          << " t=" << ts[i] << " order " << k;
    }
}

// checks: C, C', C'', C''' equal Geom_BSplineCurve::D3 to 1e-12 relative on 200 random non-rational curves.
TEST(NurbsCurveOcct, NonRationalMatchesD3) {
  Rng rng(101);
  for (int i = 0; i < 200; ++i) {
    const int p = 1 + static_cast<int>(rng.below(7));
    compare_curve(testing::random_curve(rng, {.degree = p, .clamped = (i % 4 != 0), .extra_points = i % 9}), rng, i);
  }
}

// checks: rational derivatives (quotient rule) equal Geom_BSplineCurve::D3 to 1e-12 relative.
TEST(NurbsCurveOcct, RationalMatchesD3) {
  Rng rng(202);
  for (int i = 0; i < 200; ++i) {
    const int p = 1 + static_cast<int>(rng.below(7));
    compare_curve(
        testing::random_curve(rng, {.degree = p, .rational = true, .clamped = (i % 4 != 0), .extra_points = i % 9}),
        rng, i);
  }
}

// checks: high degrees (direct de Boor path, degree > kCachedDegreeLimit): position equals
// Geom_BSplineCurve::Value to 1e-12. OCCT's D3 evaluates a cached monomial form that loses
// about three digits at degree 13 (checked against a long-double de Boor sum while writing
// this test: OCCT D3 position off by ~1e-11 relative, ours and Value() by ~1e-15), so
// derivatives are compared with D3 at 1e-9.
TEST(NurbsCurveOcct, HighDegreeMatchesValueAndD3) {
  Rng rng(303);
  for (int i = 0; i < 20; ++i)
    compare_curve(
        testing::random_curve(
            rng, {.degree = 10 + static_cast<int>(rng.below(5)), .rational = (i % 2 == 1), .extra_points = 8}),
        rng, i, {1e-12, 1e-9, 1e-9, 1e-9}, true);
}

// checks: one-sided limits at interior knots equal OCCT's LocalD3 restricted to the left/right span.
TEST(NurbsCurveOcct, OneSidedLimitsMatchLocalD3) {
  Rng rng(404);
  for (int i = 0; i < 50; ++i) {
    const NurbsCurve c = testing::random_curve(
        rng, {.degree = 2 + static_cast<int>(rng.below(4)), .rational = (i % 2 == 0), .extra_points = 6});
    Handle(Geom_BSplineCurve) occ = to_occt(c);
    struct Sample {
      double u;
      std::array<Vec3, 4> ours, theirs;
    };
    std::vector<Sample> samples;
    for (int k = 2; k < occ->NbKnots(); ++k) {
      const double u = occ->Knot(k);
      gp_Pnt p;
      gp_Vec a1, a2, a3;
      const auto left = c.derivatives(u, 3, {.side = Side::Left});
      occ->LocalD3(u, k - 1, k, p, a1, a2, a3);
      samples.push_back({u, {left[0], left[1], left[2], left[3]}, {to_vec3(p), to_vec3(a1), to_vec3(a2), to_vec3(a3)}});
      const auto right = c.derivatives(u, 3, {.side = Side::Right});
      occ->LocalD3(u, k, k + 1, p, a1, a2, a3);
      samples.push_back(
          {u, {right[0], right[1], right[2], right[3]}, {to_vec3(p), to_vec3(a1), to_vec3(a2), to_vec3(a3)}});
    }
    // Same rule as compare_curve: per-order scale over all samples of the curve.
    std::array<double, 4> scale{};
    for (const auto& smp : samples)
      for (std::size_t o = 0; o < 4; ++o) scale[o] = std::max(scale[o], norm(smp.theirs[o]));
    for (std::size_t j = 0; j < samples.size(); ++j)
      for (std::size_t o = 0; o < 4; ++o)
        EXPECT_LE(distance(samples[j].ours[o], samples[j].theirs[o]), 1e-12 * scale[o])
            << "curve " << i << " knot " << samples[j].u << (j % 2 == 0 ? " left" : " right") << " order " << o;
  }
}

// checks: the batch evaluator (sorted and shuffled) gives exactly the single-point results.
TEST(NurbsCurveOcct, BatchEqualsSinglePoint) {
  Rng rng(505);
  for (int i = 0; i < 30; ++i) {
    const NurbsCurve c =
        testing::random_curve(rng, {.degree = 1 + static_cast<int>(rng.below(5)), .rational = (i % 2 == 0)});
    std::vector<double> ts;
    for (int j = 0; j < 100; ++j) ts.push_back(rng.uniform(c.domain().start, c.domain().end));
    if (i % 3 == 0) std::sort(ts.begin(), ts.end());
    std::vector<Vec3> out(ts.size() * 3);
    c.derivatives(ts, 2, out);
    for (std::size_t j = 0; j < ts.size(); ++j) {
      const auto d = c.derivatives(ts[j], 2);
      for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(out[j * 3 + k], d[k]);
    }
  }
}

}  // namespace
}  // namespace hula::nurbs
