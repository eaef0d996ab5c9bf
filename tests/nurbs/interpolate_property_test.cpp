// SPDX-License-Identifier: MIT
// Property tests (RapidCheck) for interpolation: on random point sets, every
// end condition and parameterisation gives a C2 cubic through the points with
// breakpoints at the data parameters; the result is invariant under
// translation and scaling of the data; Hermite curves meet their data.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/interpolate.hpp"

namespace hula::nurbs {
namespace {

// Random points with integer-thousandth coordinates in [-1, 1]; at least `min` of them.
std::vector<Vec3> gen_points(std::size_t min, std::size_t max) {
  const auto n = *rc::gen::inRange(min, max + 1);
  std::vector<Vec3> p(n);
  for (auto& q : p)
    q = {*rc::gen::inRange(-1000, 1001) / 1000.0, *rc::gen::inRange(-1000, 1001) / 1000.0,
         *rc::gen::inRange(-1000, 1001) / 1000.0};
  return p;
}

EndCondition gen_end() {
  const int k = *rc::gen::inRange(0, 5);
  switch (k) {
    case 0:
      return EndCondition::natural();
    case 1:
      return EndCondition::clamped(
          {*rc::gen::inRange(-50, 51) / 10.0, *rc::gen::inRange(-50, 51) / 10.0, *rc::gen::inRange(-50, 51) / 10.0});
    case 2:
      return EndCondition::bessel();
    case 3:
      return EndCondition::not_a_knot();
    default:
      return EndCondition::occt();
  }
}

Parameterisation gen_rule() { return static_cast<Parameterisation>(*rc::gen::inRange(0, 3)); }

// Chord-length parameters degrade as neighbours get close: keep data whose
// smallest spacing is a reasonable fraction of the largest (the well-posed
// regime the tolerances below are stated for).
bool well_spaced(const std::vector<Vec3>& p) {
  double lo = HUGE_VAL, hi = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const double d = distance(p[i - 1], p[i]);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return lo > 0.05 * hi;
}

// property: every end condition × parameterisation interpolates (1e-12 of model size) at the data parameters,
// the breakpoints are the data parameters, and C, C', C'' agree from both sides at interior knots.
RC_GTEST_PROP(InterpolateCubicProperty, InterpolatesAndIsC2, ()) {
  const auto pts = gen_points(2, 30);
  RC_PRE(well_spaced(pts));
  const auto rule = gen_rule();
  const InterpolationOptions opt{.parameterisation = rule, .start = gen_end(), .end = gen_end()};
  const auto t = parameterise(pts, rule);
  const NurbsCurve c = interpolate_cubic(pts, opt);
  Box3 box;
  for (const auto& p : pts) box.add(p);
  for (std::size_t i = 0; i < pts.size(); ++i) RC_ASSERT(distance(c.evaluate(t[i]), pts[i]) <= 1e-12 * box.diagonal());
  RC_ASSERT(c.knots().breakpoints() == t);
  for (int k = 1; k <= 2; ++k) {
    double scale = 0.0;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      scale = std::max(scale, norm(c.derivatives(0.5 * (t[i] + t[i + 1]), k)[static_cast<std::size_t>(k)]));
    for (std::size_t i = 1; i + 1 < t.size(); ++i) {
      const Vec3 l = c.derivatives(t[i], k, {.side = Side::Left})[static_cast<std::size_t>(k)];
      const Vec3 r = c.derivatives(t[i], k, {.side = Side::Right})[static_cast<std::size_t>(k)];
      RC_ASSERT(distance(l, r) <= 1e-10 * std::max(scale, 1.0));
    }
  }
}

// property: translating and scaling the data by a power of two moves the control points the same way
// (the construction is affine invariant; the shifted points carry rounding, so the comparison is relative).
RC_GTEST_PROP(InterpolateCubicProperty, AffineInvariant, ()) {
  const auto pts = gen_points(2, 20);
  RC_PRE(well_spaced(pts));
  const auto rule = gen_rule();
  auto end = gen_end();
  const double s = std::ldexp(1.0, *rc::gen::inRange(-600, 601));
  const Vec3 shift{*rc::gen::inRange(-9, 10) * s, *rc::gen::inRange(-9, 10) * s, 0.0};
  std::vector<Vec3> moved = pts;
  for (auto& p : moved) p = p * s + shift;
  auto scaled = end;
  scaled.derivative = end.derivative * s;
  const NurbsCurve a = interpolate_cubic(pts, {.parameterisation = rule, .start = end, .end = end});
  const NurbsCurve b = interpolate_cubic(moved, {.parameterisation = rule, .start = scaled, .end = scaled});
  RC_ASSERT(a.knots().size() == b.knots().size());
  for (std::size_t i = 0; i < a.knots().size(); ++i) RC_ASSERT(std::fabs(a.knots()[i] - b.knots()[i]) <= 1e-14);
  double size = 0.0;
  for (const auto& p : a.control_points()) size = std::max(size, max_abs(p));
  for (std::size_t i = 0; i < a.control_points().size(); ++i)
    RC_ASSERT(distance((b.control_points()[i] - shift) / s, a.control_points()[i]) <= 1e-10 * std::max(size, 1.0));
}

// property: Hermite cubic and quintic meet points and derivatives from both sides of every knot.
RC_GTEST_PROP(HermiteProperty, MeetsData, ()) {
  const auto pts = gen_points(2, 12);
  RC_PRE(well_spaced(pts));
  std::vector<Vec3> d1(pts.size()), d2(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    d1[i] = {*rc::gen::inRange(-50, 51) / 10.0, *rc::gen::inRange(-50, 51) / 10.0, 0.0};
    d2[i] = {*rc::gen::inRange(-50, 51) * 1.0, 0.0, *rc::gen::inRange(-50, 51) * 1.0};
  }
  const auto t = parameterise(pts, Parameterisation::ChordLength);
  const NurbsCurve c3 = hermite_cubic(pts, d1);
  const NurbsCurve c5 = hermite_quintic(pts, d1, d2);
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (Side side : {Side::Left, Side::Right}) {
      const auto a = c3.derivatives(t[i], 1, {.side = side});
      RC_ASSERT(distance(a[0], pts[i]) <= 1e-13);
      RC_ASSERT(distance(a[1], d1[i]) <= 1e-11);
      const auto b = c5.derivatives(t[i], 2, {.side = side});
      RC_ASSERT(distance(b[0], pts[i]) <= 1e-13);
      RC_ASSERT(distance(b[1], d1[i]) <= 1e-11);
      RC_ASSERT(distance(b[2], d2[i]) <= 1e-9);
    }
}

}  // namespace
}  // namespace hula::nurbs
