// SPDX-License-Identifier: MIT
// Prescribed compound fins (thesis 8.3): the planar normal fin compound against
// closed forms (circle: a concentric circle; ellipse: its offset; helix: the
// Combescure compound is the helix shifted along its axis by C·w/r), against the
// project's normal fin (diffgeom::fins), round trips compound → curve on circle,
// ellipse, helix projections (with inflections) and a random Bézier, the forward
// check of an edited compound, and the documented refusals.
#include "hula/studies/fin_compound.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/core/rng.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

using diffgeom::Plane;

// The ellipse (a cos θ, b sin θ) as a rational NURBS: the rational circle scaled (affine invariance).
nurbs::NurbsCurve ellipse(double a, double b) {
  const nurbs::NurbsCurve c = testing::rational_circle(1.0);
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p = {a * p.x, b * p.y, 0.0};
  return nurbs::NurbsCurve(c.knots(), P, std::vector<double>(c.weights().begin(), c.weights().end()), 2);
}

// A helix of radius r and pitch parameter h over `turns` turns as a quintic NURBS (fit of the exact law).
nurbs::NurbsCurve helix_nurbs(double r, double h, double turns) {
  law::Context ctx;
  const law::Law t = ctx.parameter("t");
  const law::Law p = law::vec(r * law::cos(t), r * law::sin(t), h * t);
  return law::to_nurbs(p, "t", 0.0, 2.0 * std::numbers::pi * turns, {.tolerance = 1e-11}).curve;
}

double max_distance_to(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b, int n = 400) {
  double d = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double u = static_cast<double>(i) / n;
    const double ta = a.domain().start * (1 - u) + a.domain().end * u;
    const double tb = b.domain().start * (1 - u) + b.domain().end * u;
    d = std::max(d, distance(a.evaluate(ta), b.evaluate(tb)));
  }
  return d;
}

// checks the compound of a CCW circle of radius R is the circle of radius R + s (closed form), and the
// stretch 1 − s κ_Q = R / (R + s).
TEST(NormalCompound, CircleGivesConcentricCircle) {
  const double R = 2.0, s = 0.5;
  const nurbs::NurbsCurve c = testing::rational_circle(R, 0.3);
  const LawCurveFit q = normal_compound(c, {.scale = s});
  for (int i = 0; i <= 200; ++i) EXPECT_NEAR(norm(q.curve.evaluate(i / 200.0)), R + s, 1e-8);
  const StretchReport st = compound_stretch(q.curve, {.scale = s});
  EXPECT_NEAR(st.min_stretch, R / (R + s), 1e-7);
}

// checks the ellipse's compound against the closed-form offset (a cos θ, b sin θ) + s (b cos θ, a sin θ)/w
// and against diffgeom::fins (FinKind::Normal, P − s N), which agree where the curve turns CCW.
TEST(NormalCompound, EllipseMatchesClosedFormAndNormalFins) {
  const double a = 3.0, b = 1.0, s = 0.4;
  const nurbs::NurbsCurve e = ellipse(a, b);
  const LawCurveFit q = normal_compound(e, {.scale = s});
  const diffgeom::Fins fins = diffgeom::fins(e, {.kind = diffgeom::FinKind::Normal, .scale = s, .density = 101});
  for (std::size_t i = 0; i < fins.t.size(); ++i) {
    const double t = fins.t[i];
    const Vec3 p = e.evaluate(t);
    const double th = std::atan2(p.y / b, p.x / a);
    const double w = std::hypot(b * std::cos(th), a * std::sin(th));
    const Vec3 expect{a * std::cos(th) + s * b * std::cos(th) / w, b * std::sin(th) + s * a * std::sin(th) / w, 0.0};
    EXPECT_NEAR(distance(q.curve.evaluate(t), expect), 0.0, 1e-8) << "t = " << t;
    ASSERT_TRUE(fins.defined[i]);
    EXPECT_NEAR(distance(q.curve.evaluate(t), fins.tip[i]), 0.0, 1e-8) << "t = " << t;
  }
}

// checks compound → curve recovers the projection (circle, ellipse, helix on all planes: XY is a circle,
// YZ and ZX are sine curves with inflections, and a random 3-D Bézier).
TEST(NormalCompound, RoundTripRecoversProjection) {
  Rng rng(7);
  std::vector<Vec3> cp;
  for (int i = 0; i < 6; ++i) cp.push_back({i * 2.0, rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)});
  const nurbs::NurbsCurve bez = nurbs::make_bezier(cp);
  struct Case {
    const char* name;
    nurbs::NurbsCurve curve;
    double scale;
  };
  const Case cases[] = {{"circle", testing::rational_circle(1.5), 0.3},
                        {"ellipse", ellipse(2.0, 1.0), -0.2},
                        {"helix", helix_nurbs(1.0, 0.6, 1.5), 0.1},
                        {"bezier", bez, 0.05}};
  for (const Case& c : cases) {
    for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX}) {
      if (c.curve.dimension() == 2 && plane != Plane::XY) continue;
      if (std::string_view(c.name) == "bezier" && plane == Plane::YZ) {
        // x is dropped: this projection turns tighter than |s| somewhere, so the fins cross and the
        // compound folds back (the inverse would give Q + s n_Q ≠ P): refused, naming the parameter.
        HULA_EXPECT_ERROR(normal_compound(c.curve, {.plane = plane, .scale = c.scale}), Errc::InvalidArgument,
                          "fins cross at t = ");
        continue;
      }
      const NormalCompoundOptions o{.plane = plane, .scale = c.scale};
      const LawCurveFit q = normal_compound(c.curve, o);
      ASSERT_GT(compound_stretch(q.curve, o).min_stretch, 0.05) << c.name;
      const LawCurveFit p = curve_from_normal_compound(q.curve, o);
      EXPECT_LT(max_distance_to(p.curve, diffgeom::project(c.curve, plane)), 1e-7)
          << c.name << " " << diffgeom::plane_name(plane);
    }
  }
}

// checks the inverse of a prescribed circle compound of radius ρ is the circle of radius ρ − s, and that
// s ≥ ρ (the offset reverses) is refused naming the compound and the parameter.
TEST(NormalCompound, InverseOfCircleAndBreakdown) {
  const nurbs::NurbsCurve q = testing::rational_circle(1.0);
  const LawCurveFit p = curve_from_normal_compound(q, {.scale = 0.25});
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(norm(p.curve.evaluate(i / 100.0)), 0.75, 1e-8);
  const LawCurveFit outer = curve_from_normal_compound(q, {.scale = -0.5});
  EXPECT_NEAR(norm(outer.curve.evaluate(0.3)), 1.5, 1e-8);
  HULA_EXPECT_ERROR(curve_from_normal_compound(q, {.scale = 1.5}), Errc::InvalidArgument, "bends too tightly at t = ");
}

// checks an edited compound: the reconstructed projection's own compound equals the edited one (forward),
// the dropped coordinate is the original's (by normalised parameter) and the in-plane ones changed.
TEST(NormalCompound, EditedCompoundForwardCheck) {
  const nurbs::NurbsCurve h = helix_nurbs(1.0, 0.5, 1.0);
  const NormalCompoundOptions o{.plane = Plane::ZX, .scale = 0.1};
  const LawCurveFit q = normal_compound(h, o);
  // Edit: bulge the compound in x by a smooth bump and interpolate 41 points of it (the edit stays in ZX).
  std::vector<Vec3> P;
  nurbs::InterpolationOptions io;
  for (int i = 0; i <= 40; ++i) {
    const double u = i / 40.0;
    P.push_back(q.curve.evaluate(q.curve.domain().end * u) + Vec3{0.2 * std::sin(std::numbers::pi * u), 0, 0});
    io.parameters.push_back(u);
  }
  const nurbs::NurbsCurve edited = nurbs::interpolate_cubic(P, io);
  const CompoundEditResult r = edit_normal_compound(h, edited, o);
  EXPECT_LT(r.forward_deviation, 1e-7);
  EXPECT_LT(r.assembly_deviation, 1e-12);
  double moved = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const Vec3 a = r.curve.evaluate(u), b = h.evaluate(h.domain().end * u);
    EXPECT_NEAR(a.y, b.y, 1e-12) << "u = " << u;
    moved = std::max(moved, std::abs(a.x - b.x));
  }
  EXPECT_GT(moved, 0.1);
  // The compound of the result's ZX projection is the edited compound (independent re-computation).
  const LawCurveFit again = normal_compound(r.curve, o);
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const Vec3 a = again.curve.evaluate(u), b = edited.evaluate(edited.domain().end * u);
    EXPECT_NEAR(a.x, b.x, 1e-7);
    EXPECT_NEAR(a.z, b.z, 1e-7);
  }
}

// checks a compound that leaves the plane is refused naming the control point.
TEST(NormalCompound, RefusesNonPlanarCompound) {
  const std::vector<Vec3> cp{{0, 0, 0}, {1, 1, 0}, {2, 0, 0.5}, {3, 1, 0}};
  const nurbs::NurbsCurve q = nurbs::make_bezier(cp);
  HULA_EXPECT_ERROR(curve_from_normal_compound(q, {.plane = Plane::XY}), Errc::InvalidArgument, "control_points[2].z");
  HULA_EXPECT_ERROR(curve_from_normal_compound(q, {.scale = 0.0}), Errc::InvalidOption, "scale");
  // A polyline's tangent jumps at its corner, so its compound would tear there: refused, naming the knot.
  const nurbs::NurbsCurve corner(1, {0, 0, 0.5, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  HULA_EXPECT_ERROR(normal_compound(corner, {.scale = 0.1}), Errc::InvalidArgument,
                    "curve's tangent turns by 1.5707963267948966 rad at the knot t = 0.5");
}

// checks the Combescure compound of a helix (r, h) is the helix shifted by C w / r along its axis
// (τ/κ T + B = (0, 0, w/r), w = √(r² + h²)), and that the inverse of the exact compound is the helix.
TEST(Combescure, HelixShiftsAlongAxisAndInverts) {
  const double r = 1.0, h = 0.4, C = 0.7;
  law::Context ctx;
  const law::Law t = ctx.parameter("t");
  const law::Law helix = law::vec(r * law::cos(t), r * law::sin(t), h * t);
  const nurbs::Interval dom{0.0, 4.0};
  const CombescureOptions o{.c = C};
  const LawCurveFit q = combescure_compound(helix, "t", dom, o);
  const double shift = C * std::hypot(r, h) / r;
  const LawCurveFit p = combescure_parent(q.law, "t", dom, o);
  law::CurveEvaluator ev(p.law, "t", 0);
  for (int i = 0; i <= 50; ++i) {
    const double tt = 4.0 * i / 50.0;
    const Vec3 expect{r * std::cos(tt), r * std::sin(tt), h * tt};
    EXPECT_NEAR(distance(q.curve.evaluate(tt), expect + Vec3{0, 0, shift}), 0.0, 1e-8) << "t = " << tt;
    Vec3 back[1];
    ASSERT_TRUE(ev.derivatives(tt, back));
    EXPECT_NEAR(distance(back[0], expect), 0.0, 1e-10) << "t = " << tt;
    EXPECT_NEAR(distance(p.curve.evaluate(tt), expect), 0.0, 1e-8) << "t = " << tt;
  }
}

// checks the NURBS forms: a random space Bézier (C∞) → compound law → parent = the Bézier; the parent
// of a prescribed Bézier compound has that compound (forward check on the exact laws).
TEST(Combescure, BezierRoundTrips) {
  Rng rng(11);
  std::vector<Vec3> cp;
  // A twisted arc: control points on a helix, jittered.
  for (int i = 0; i < 6; ++i)
    cp.push_back({std::cos(0.5 * i) + rng.uniform(-0.05, 0.05), std::sin(0.5 * i) + rng.uniform(-0.05, 0.05),
                  0.3 * i + rng.uniform(-0.05, 0.05)});
  const nurbs::NurbsCurve bez = nurbs::make_bezier(cp);
  const CombescureOptions o{.c = 0.05};
  const LawCurveFit q = combescure_compound(bez, o);
  const LawCurveFit p = combescure_parent(q.law, "t", bez.domain(), o);
  EXPECT_LT(testing::max_deviation(p.curve, bez, 400), 1e-8);
  const LawCurveFit parent = combescure_parent(bez, o);
  const LawCurveFit forward = combescure_compound(parent.law, "t", bez.domain(), o);
  law::CurveEvaluator ev(forward.law, "t", 0);
  for (int i = 0; i <= 50; ++i) {
    Vec3 v[1];
    ASSERT_TRUE(ev.derivatives(i / 50.0, v));
    EXPECT_NEAR(distance(v[0], bez.evaluate(i / 50.0)), 0.0, 1e-10);
  }
}

// checks the thesis's limits as errors: a planar curve, and a cubic spline whose torsion jumps at knots.
TEST(Combescure, RefusesPlanarAndTornCurves) {
  const std::vector<Vec3> flat{{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
  HULA_EXPECT_ERROR(combescure_compound(nurbs::make_bezier(flat)), Errc::InvalidArgument, "is planar");
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 1, 0.5}, {2, 0, 1}, {3, 1, 0}, {4, 0, 0.3}};
  const nurbs::NurbsCurve spline = nurbs::interpolate_cubic(pts);
  HULA_EXPECT_ERROR(combescure_parent(spline), Errc::InvalidArgument, "compound is only C2 at the knot");
  const std::vector<Vec3> cp{{0, 0, 0}, {1, 1, 1}, {2, -1, 0}, {3, 0, 1}};
  const nurbs::NurbsCurve bez = nurbs::make_bezier(cp);
  HULA_EXPECT_ERROR(combescure_compound(bez, {.c = 0.0}), Errc::InvalidOption, "c = 0");
}

}  // namespace
}  // namespace hula::studies
