// SPDX-License-Identifier: MIT
// Tests of design by curvature on existing curves (issue 21 item 4): the ends,
// end tangents and (G2) end curvatures come back as the originals' closed-form
// values — the data points of interpolated splines, a quarter circle's ends,
// tangents and κ = 1/R — to 1e-9; the curvature at the edited arc length moves
// the way and about as far as asked; the inflection count stays; the result has
// at most twice the handles; the documented errors.
#include "hula/studies/curvature_edit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/law/parser.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

constexpr double kPi = std::numbers::pi;

struct Laws {
  law::Context ctx;
  law::Law operator()(const std::string& text) {
    law::ParseOptions po;
    po.parameters = {"s"};
    return law::parse(text, ctx, po);
  }
};

curve::Curve spline(std::vector<Vec3> points, std::vector<double> parameters = {}) {
  curve::InterpolatedData d;
  d.points = std::move(points);
  d.dimension = 2;
  d.parameters = std::move(parameters);
  return curve::Curve::interpolated(std::move(d));
}

// The one-sided (left) Frenet quantities at the domain end.
diffgeom::FrenetPoint frenet_end(const nurbs::NurbsCurve& c) {
  diffgeom::FrenetOptions o;
  o.eval.side = nurbs::Side::Left;
  return diffgeom::frenet(c, c.domain().end, o);
}

CurvatureEditOptions holding(EndHold hold) {
  CurvatureEditOptions o;
  o.hold = hold;
  return o;
}

// The thesis's shapes: a 4-point S and Example 1's corner (7.4.2, 3 points, parameters 0, 0.5, 1).
curve::Curve s_curve() { return spline({{0, 0, 0}, {40, 40, 0}, {80, -40, 0}, {120, -40, 0}}); }
curve::Curve example1() { return spline({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}}, {0.0, 0.5, 1.0}); }

// The exact rational quarter circle of radius R from (R, 0) to (0, R), counter-clockwise.
curve::Curve quarter_circle(double R) {
  const double w = std::sqrt(0.5);
  return curve::Curve(nurbs::NurbsCurve(2, {0, 0, 0, 1, 1, 1}, {{R, 0, 0}, {R, R, 0}, {0, R, 0}}, {1.0, w, 1.0}, 2));
}

// The cos² bump of the workbench's κ-graph drag: height h at s0, half-width w.
std::string bump(double h, double s0, double w) {
  const std::string x = "((s - " + std::to_string(s0) + ")/" + std::to_string(w) + ")";
  return "piecewise(abs" + x + " < 1, " + std::to_string(h) + "*cos(" + std::to_string(kPi / 2) + "*" + x + ")^2, 0)";
}

// Signed curvature about +Z at arc length s.
double kappa_at_length(const curve::Curve& c, double s) {
  const double t = nurbs::parameter_at_length(c.nurbs(), s);
  return diffgeom::frenet(c.nurbs(), t).signed_curvature;
}

// |κ| of `edited` at the same fraction of its own length as s is of `original`'s length: where the κ(s) graph, redrawn
// for the new length, shows the point the designer dragged (the edit may change the length).
double kappa_at_fraction(const curve::Curve& original, const curve::Curve& edited, double s) {
  const nurbs::NurbsCurve& c = edited.nurbs();
  const double t = nurbs::parameter_at_length(c, s / original.length() * edited.length());
  return std::abs(diffgeom::frenet(c, t).signed_curvature);
}

// checks the held ends against the original's closed-form end points, tangents, and (G2) curvatures.
void expect_ends(const CurvatureEditResult& r, bool g2) {
  EXPECT_LE(r.start_point_error, 1e-9);
  EXPECT_LE(r.end_point_error, 1e-9);
  EXPECT_LE(r.start_tangent_error, 1e-9);
  EXPECT_LE(r.end_tangent_error, 1e-9);
  if (g2) {
    EXPECT_LE(r.start_curvature_error, 1e-9);
    EXPECT_LE(r.end_curvature_error, 1e-9);
  }
}

// checks: a bump of |κ| at 30 % of the S (its sharpest turn) keeps its data end points and end tangents (closed
// form: the points and the spline's own end directions), its one inflection, at most 8 points, and raises |κ|
// there by about the bump's height.
TEST(CurvatureEdit, SCurveBumpKeepsEndsTangentsAndInflection) {
  Laws l;
  const curve::Curve c = s_curve();
  const double L = c.length(), s0 = 0.3 * L, h = 0.008;
  const CurvatureEditResult r =
      edit_curvature(c, {.curvature = l(bump(h, s0, L / 6)), .target = CurvatureTarget::Change});
  expect_ends(r, false);
  const nurbs::NurbsCurve& out = r.curve.nurbs();
  EXPECT_LE(distance(out.evaluate(out.domain().start), Vec3{0, 0, 0}), 1e-9);
  EXPECT_LE(distance(out.evaluate(out.domain().end), Vec3{120, -40, 0}), 1e-9);
  EXPECT_LE(distance(frenet_end(out).tangent, frenet_end(c.nurbs()).tangent), 1e-9);
  EXPECT_EQ(r.inflections_before, 1u);
  EXPECT_EQ(r.inflections_after, 1u);
  EXPECT_EQ(r.curve.kind(), curve::Kind::Interpolated);
  EXPECT_LE(r.handles_after, 2 * r.handles_before);
  const double raised = kappa_at_fraction(c, r.curve, s0) - kappa_at_fraction(c, c, s0);
  EXPECT_GT(raised, 0.6 * h);
  EXPECT_LT(raised, 1.3 * h);
}

// checks: the same on Example 1's corner, G1 and G2 (its natural ends have κ = 0, held to 1e-9); a drag down
// lowers |κ| there; no inflection appears (a relative correction keeps κ ≥ 0).
TEST(CurvatureEdit, Example1CornerG1AndG2) {
  Laws l;
  const curve::Curve c = example1();
  const double L = c.length(), s0 = 0.3 * L;
  for (const double h : {0.004, -0.002})
    for (const EndHold hold : {EndHold::Tangent, EndHold::Curvature}) {
      SCOPED_TRACE(std::string(end_hold_name(hold)) + " h = " + std::to_string(h));
      const CurvatureEditResult r =
          edit_curvature(c, {.curvature = l(bump(h, s0, L / 6)), .target = CurvatureTarget::Change}, holding(hold));
      expect_ends(r, hold == EndHold::Curvature);
      const nurbs::NurbsCurve& out = r.curve.nurbs();
      EXPECT_LE(distance(out.evaluate(out.domain().end), Vec3{100, 100, 0}), 1e-9);
      if (hold == EndHold::Curvature) {
        EXPECT_LE(std::abs(kappa_at_length(r.curve, 0.0)), 1e-9);
        EXPECT_LE(std::abs(kappa_at_length(r.curve, r.length_after)), 1e-9);
      }
      EXPECT_EQ(r.inflections_after, r.inflections_before);
      EXPECT_LE(r.handles_after, 6u);
      const double moved = kappa_at_fraction(c, r.curve, s0) - kappa_at_fraction(c, c, s0);
      EXPECT_GT(moved / h, 0.5) << moved;
      EXPECT_LT(moved / h, 1.3) << moved;
    }
}

// checks: a quarter circle (exact rational NURBS) with a bump keeps (R, 0), (0, R), the tangents (0, 1) and
// (−1, 0) and, G2, κ = 1/R at both ends — closed forms — and comes back as a NURBS of degree 2.
TEST(CurvatureEdit, QuarterCircleHoldsClosedFormEnds) {
  Laws l;
  const double R = 50.0;
  const curve::Curve c = quarter_circle(R);
  const double L = kPi * R / 2;
  const CurvatureEditResult r = edit_curvature(
      c, {.curvature = l(bump(0.004, 0.5 * L, L / 6)), .target = CurvatureTarget::Change}, holding(EndHold::Curvature));
  const nurbs::NurbsCurve& out = r.curve.nurbs();
  const diffgeom::FrenetPoint a = diffgeom::frenet(out, out.domain().start);
  const diffgeom::FrenetPoint b = frenet_end(out);
  EXPECT_LE(distance(a.position, Vec3{R, 0, 0}), 1e-9);
  EXPECT_LE(distance(b.position, Vec3{0, R, 0}), 1e-9);
  EXPECT_LE(distance(a.tangent, Vec3{0, 1, 0}), 1e-9);
  EXPECT_LE(distance(b.tangent, Vec3{-1, 0, 0}), 1e-9);
  EXPECT_NEAR(a.signed_curvature, 1.0 / R, 1e-9);
  EXPECT_NEAR(b.signed_curvature, 1.0 / R, 1e-9);
  EXPECT_NEAR(r.length_before, L, 1e-9 * L);
  EXPECT_EQ(r.curve.kind(), curve::Kind::Nurbs);
  EXPECT_LE(r.handles_after, 6u);
  // G2 leaves a quadratic (6 control points at most, 3 held at each end) little freedom: κ stays within the bump's
  // height of the circle's.
  EXPECT_NEAR(kappa_at_fraction(c, r.curve, 0.5 * L), 1.0 / R, 0.004);
  // Holding only the ends and tangents, the bump is about what was asked.
  const CurvatureEditResult g1 =
      edit_curvature(c, {.curvature = l(bump(0.004, 0.5 * L, L / 6)), .target = CurvatureTarget::Change});
  expect_ends(g1, false);
  const double raised = kappa_at_fraction(c, g1.curve, 0.5 * L) - 1.0 / R;
  EXPECT_GT(raised, 0.5 * 0.004);
  EXPECT_LT(raised, 1.3 * 0.004);
}

// checks: typing the curve's own curvature law (κ = 1/R) gives the circle back: no correction, every point on
// the circle (closed form) to the fit tolerance.
TEST(CurvatureEdit, TypedOwnCurvatureIsTheIdentity) {
  Laws l;
  const double R = 50.0;
  const curve::Curve c = quarter_circle(R);
  const CurvatureEditResult r = edit_curvature(c, {.curvature = l("0.02")});
  EXPECT_LT(r.max_curvature_deviation, 1e-6);
  const nurbs::NurbsCurve& out = r.curve.nurbs();
  for (int i = 0; i <= 50; ++i) {
    const Vec3 p = out.evaluate(out.domain().start + (out.domain().end - out.domain().start) * i / 50.0);
    EXPECT_NEAR(norm(p), R, 1e-4 * R) << i;
  }
}

// checks: a typed constant κ that cannot close Example 1's corner (0.02 × L turns 4 rad, the corner 90°) goes through
// the boundary-value reconstruction: the ends (closed form: the data points) and end tangents stay, the corner turns
// the right way (no inflection), the result has at most 6 points.
TEST(CurvatureEdit, TypedLawGoesThroughTheReconstruction) {
  Laws l;
  const CurvatureEditResult r = edit_curvature(example1(), {.curvature = l("0.02")});
  EXPECT_TRUE(r.reconstructed);
  EXPECT_GT(r.iterations, 0);
  EXPECT_GT(r.reconstruction_max_deviation, 0.0);  // the price of the held ends
  expect_ends(r, false);
  const nurbs::NurbsCurve& out = r.curve.nurbs();
  EXPECT_LE(distance(out.evaluate(out.domain().start), Vec3{0, 0, 0}), 1e-9);
  EXPECT_LE(distance(out.evaluate(out.domain().end), Vec3{100, 100, 0}), 1e-9);
  EXPECT_EQ(r.inflections_after, 0u);
  EXPECT_LE(r.handles_after, 6u);
}

// checks: a space curve keeps its ends, end tangents and (G2) end curvature and normal, and its torsion edit
// raises τ where asked.
TEST(CurvatureEdit, SpaceBezierG2) {
  Laws l;
  const curve::Curve c =
      curve::Curve::bezier({.control_points = {{0, 0, 0}, {30, 40, 10}, {70, 40, -10}, {100, 0, 20}}, .weights = {}});
  const double L = c.length();
  const CurvatureEditResult r = edit_curvature(
      c, {.curvature = l(bump(0.002, 0.4 * L, L / 6)), .target = CurvatureTarget::Change}, holding(EndHold::Curvature));
  EXPECT_FALSE(r.planar);
  expect_ends(r, true);
  EXPECT_LE(r.handles_after, 8u);
  const nurbs::NurbsCurve& out = r.curve.nurbs();
  const nurbs::NurbsCurve& in = c.nurbs();
  const diffgeom::FrenetPoint a0 = frenet_end(in);
  const diffgeom::FrenetPoint a1 = frenet_end(out);
  EXPECT_LE(distance(a0.normal, a1.normal), 1e-9);
}

// checks: dragging |κ| down by more than it is never bends the corner the other way: no inflection appears, and
// |κ| stays positive at the dragged point.
TEST(CurvatureEdit, DragDownNeverReverses) {
  Laws l;
  const curve::Curve c = example1();
  const double L = c.length(), s0 = 0.25 * L;
  const CurvatureEditResult r =
      edit_curvature(c, {.curvature = l(bump(-0.02, s0, L / 6)), .target = CurvatureTarget::Change});
  expect_ends(r, false);
  EXPECT_EQ(r.inflections_after, 0u);
  const nurbs::NurbsCurve& out = r.curve.nurbs();
  const double k = diffgeom::frenet(out, nurbs::parameter_at_length(out, s0 / L * r.length_after)).signed_curvature;
  EXPECT_GT(k, 0.0);
  EXPECT_LT(k, kappa_at_fraction(c, c, s0));
}

// κ of `c` at the fractions f of its own length (signed about +Z for a planar curve, ≥ 0 for a space curve), and its
// length: diffgeom::analyse_curve sampling by arc length (adaptive quadrature and Newton on each sample), a
// measurement independent of the edit's own fixed-grid arc length.
struct ProfileByFraction {
  double length = 0.0;
  std::vector<double> kappa, tau;
};

ProfileByFraction profile_by_fraction(const curve::Curve& c, const std::vector<double>& f, bool planar) {
  ProfileByFraction p{.length = c.length(), .kappa = {}, .tau = {}};
  diffgeom::AnalysisOptions o;
  o.by = diffgeom::SampleBy::ArcLength;
  for (const double fi : f) o.at.push_back(std::min(fi * p.length, p.length));
  const diffgeom::CurveAnalysis a = diffgeom::analyse_curve(c, o);
  for (const diffgeom::FrenetPoint& q : a.samples) {
    p.kappa.push_back(planar ? q.signed_curvature : q.curvature);
    p.tau.push_back(q.torsion);
  }
  return p;
}

// The misses of a drag of |κ| by the cos² bump (height h at the fraction f0, half-width a sixth of the length, the
// workbench's drag) against the documented target κ*(f) = σ(κ) max(|κ| + δ, |κ| / 10) of the original's κ at the
// same fraction f (σ the sign, smoothed over 1e-3 of max |κ|), measured on the result at f · L_new.
struct FractionMisses {
  double at_edit = 0.0;     // |κ_new(f0 L_new) − κ*(f0)|
  double worst = 0.0;       // max over 1,001 fractions
  double moved = 0.0;       // |κ_new(f0 L_new)| − |κ(f0 L)|: how far the drag moved |κ| where it was asked
  double tau_change = 0.0;  // max over the fractions of |τ_new − τ| (space curves)
  double tau_max = 0.0;     // max |τ| of the original
  CurvatureEditResult result;
};

FractionMisses drag_by_fraction(const curve::Curve& c, double h, double f0, EndHold hold) {
  Laws l;
  const double L = c.length();
  CurvatureEditResult r =
      edit_curvature(c, {.curvature = l(bump(h, f0 * L, L / 6)), .target = CurvatureTarget::Change}, holding(hold));
  const bool planar = r.planar;
  std::vector<double> f;
  for (int i = 0; i <= 1000; ++i) f.push_back(i / 1000.0);
  f.push_back(f0);
  const ProfileByFraction before = profile_by_fraction(c, f, planar);
  const ProfileByFraction after = profile_by_fraction(r.curve, f, planar);
  double kmax = 0.0;
  for (const double k : before.kappa) kmax = std::max(kmax, std::abs(k));
  const double eps = 1e-3 * kmax;
  FractionMisses m{.result = r};
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double k = before.kappa[i];
    const double x = (f[i] - f0) * L / (L / 6);
    const double delta = std::abs(x) < 1 ? h * std::pow(std::cos(kPi / 2 * x), 2) : 0.0;
    const double magnitude = std::max(std::abs(k) + delta, 0.1 * std::abs(k));
    const double target = planar ? magnitude * k / std::sqrt(k * k + eps * eps) : magnitude;
    const double miss = std::abs(after.kappa[i] - target);
    m.worst = std::max(m.worst, miss);
    m.tau_change = std::max(m.tau_change, std::abs(after.tau[i] - before.tau[i]));
    m.tau_max = std::max(m.tau_max, std::abs(before.tau[i]));
    if (i + 1 == f.size()) {
      m.at_edit = miss;
      m.moved = std::abs(after.kappa[i]) - std::abs(k);
    }
  }
  return m;
}

// The S-spline scaled to `width` units across.
curve::Curve s_curve_of_width(double width) {
  const double k = width / 120.0;
  return spline({{0, 0, 0}, {40 * k, 40 * k, 0}, {80 * k, -40 * k, 0}, {120 * k, -40 * k, 0}});
}

// Example 1's corner scaled to `size` units.
curve::Curve example1_of_size(double size) {
  const double k = size / 100.0;
  return spline({{0, 0, 0}, {100 * k, 0, 0}, {100 * k, 100 * k, 0}}, {0.0, 0.5, 1.0});
}

// checks (what a designer dragging the κ(s) graph sees): after a drag of |κ| by a tenth of its value at the dragged
// fraction, the new curve's |κ| at the same fraction of its own length moved by about the drag h, the way asked, on
// curves from four generators (interpolated S-splines and Example 1's corner 1, 100 and 1,000 units across, a
// rational quarter circle, a space Bézier ~1,000 units across), ends held; measured by re-sampling the result by arc
// length (analyse_curve), not by the fit. A planar drag is fitted to a consistent target (the boundary-value
// reconstruction of κ + δ with the held ends, its correction fading out under the drag), so the dragged spot keeps
// what was asked and the rest of the profile takes back the turning the bump adds. Measured (moved / h): S-splines
// 1.11 (G1) and 1.00 (G2) at every size, Example 1 0.72–0.86 (it bends through one corner: the held ends take
// back most of the turning near the drag), quarter circle 0.90, space Bézier 0.99 (G1) and 1.00 (G2: a consistent
// target with the original's τ, and the drag's height corrected on what the fit reaches; 0.65–0.71 fitted to κ + δ
// as asked). Before the consistent target: 0.57–0.62 on the S, 1.04 on the quarter circle. The worst miss against
// the raw κ + δ, which the held ends cannot have, is 0.4–1.3 h: bounded by 2 h.
TEST(CurvatureEdit, DragMatchesTheTargetAtTheNewCurvesOwnArcLengthFractions) {
  struct Case {
    std::string name;
    curve::Curve curve;
    double f0;
    std::vector<EndHold> holds;
    double low, high;  // band of moved / h
  };
  const std::vector<EndHold> g1g2 = {EndHold::Tangent, EndHold::Curvature};
  const std::vector<Case> cases = {
      {"S at 1 unit", s_curve_of_width(1.0), 0.3, g1g2, 0.9, 1.2},
      {"S at 100 units", s_curve_of_width(100.0), 0.3, g1g2, 0.9, 1.2},
      {"S at 1,000 units", s_curve_of_width(1000.0), 0.3, g1g2, 0.9, 1.2},
      {"Example 1 at 1 unit", example1_of_size(1.0), 0.3, g1g2, 0.65, 1.1},
      {"Example 1 at 100 units", example1_of_size(100.0), 0.3, g1g2, 0.65, 1.1},
      {"Example 1 at 1,000 units", example1_of_size(1000.0), 0.3, g1g2, 0.65, 1.1},
      // G2 on a quadratic fixes all of its 6 control points: no freedom left for the bump.
      {"quarter circle", quarter_circle(50.0), 0.5, {EndHold::Tangent}, 0.85, 1.1},
      {"space Bezier",
       curve::Curve::bezier(
           {.control_points = {{0, 0, 0}, {300, 400, 100}, {700, 400, 300}, {1000, 0, 600}}, .weights = {}}),
       0.3, g1g2, 0.95, 1.05},
  };
  for (const Case& k : cases)
    for (const EndHold hold : k.holds) {
      SCOPED_TRACE(k.name + " " + std::string(end_hold_name(hold)));
      const ProfileByFraction p = profile_by_fraction(k.curve, {k.f0}, true);
      const double h = 0.1 * std::abs(p.kappa[0]);
      const FractionMisses m = drag_by_fraction(k.curve, h, k.f0, hold);
      expect_ends(m.result, hold == EndHold::Curvature);
      EXPECT_EQ(m.result.inflections_after, m.result.inflections_before);
      EXPECT_GE(m.moved, k.low * h) << m.moved / h;  // the way and about as far as asked
      EXPECT_LE(m.moved, k.high * h) << m.moved / h;
      EXPECT_LE(m.worst, 2.0 * h) << m.worst / h;
      EXPECT_LE(m.result.handles_after, 2 * m.result.handles_before);
    }
}

// A right-handed helix of radius a and rise c per radian over `turn` radians (closed form: κ = a / (a² + c²),
// τ = c / (a² + c²)), as the interpolated spline through `points` of its points with its exact end derivatives.
struct Helix {
  double a = 0.0, c = 0.0;
  curve::Curve curve;
  [[nodiscard]] double kappa() const { return a / (a * a + c * c); }
  [[nodiscard]] double tau() const { return c / (a * a + c * c); }
};

Helix helix(double a, double c, double turn, int points) {
  curve::InterpolatedData d;
  d.dimension = 3;
  const auto at = [&](double th) { return Vec3{a * std::cos(th), a * std::sin(th), c * th}; };
  // dC/dt on t ∈ [0, 1], θ = turn · t.
  const auto velocity = [&](double th) { return Vec3{-a * std::sin(th), a * std::cos(th), c} * turn; };
  for (int i = 0; i < points; ++i) {
    const double t = static_cast<double>(i) / (points - 1);
    d.points.push_back(at(turn * t));
    d.parameters.push_back(t);
  }
  d.start = nurbs::EndCondition::clamped(velocity(0.0));
  d.end = nurbs::EndCondition::clamped(velocity(turn));
  return {.a = a, .c = c, .curve = curve::Curve::interpolated(std::move(d))};
}

// A seeded random space cubic Bézier in [0, size]³ whose control polygon is far from flat (|det| of its legs at
// least a tenth of size³: a cubic's det(C', C'', C''') is constant, so κ > 0 and τ has one sign along it).
curve::Curve random_space_bezier(std::uint64_t seed, double size) {
  Rng rng(seed);
  for (;;) {
    std::vector<Vec3> p(4);
    for (Vec3& q : p) q = {rng.uniform(0, size), rng.uniform(0, size), rng.uniform(0, size)};
    const double det = dot(cross(p[1] - p[0], p[2] - p[1]), p[3] - p[2]);
    if (std::abs(det) >= 0.1 * size * size * size) return curve::Curve::bezier({.control_points = p, .weights = {}});
  }
}

// checks (a drag of a space curve's κ graph by a tenth of κ): the new curve's κ at the same fraction of its own length
// moved by the drag h within 5 %, its ends and end tangents (G2: end curvatures and end normal) held to 1e-9, its
// torsion profile within a tenth of its largest |τ| of the original's, the worst miss against κ + δ at most h, at
// most twice the handles; on curves from two generators — interpolated helices (their closed-form κ and τ check the
// generator) and seeded random Béziers — at 1 and 1,000 units; measured by re-sampling both curves by arc length
// (analyse_curve), not by the edit. Measured: moved / h 0.988–1.010, max |Δτ| / max |τ| 0.010–0.048, worst miss
// 0.52–0.84 h, 9–10 handles for the 8-point helices, 8 for the Béziers. Fitted to κ + δ as asked (before): moved / h
// 0.58–0.63, |Δτ| 0.004–0.023, 16 handles for the helices.
TEST(CurvatureEdit, SpaceDragReachesTheAskedCurvature) {
  struct Case {
    std::string name;
    curve::Curve curve;
    double f0;
  };
  const Helix small = helix(0.5, 0.15, 1.5 * kPi, 8), large = helix(500.0, 150.0, 1.5 * kPi, 8);
  for (const Helix* h : {&small, &large}) {
    const ProfileByFraction p = profile_by_fraction(h->curve, {0.3, 0.7}, false);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(p.kappa[i], h->kappa(), 3e-2 * h->kappa());
      EXPECT_NEAR(p.tau[i], h->tau(), 5e-2 * h->tau());
    }
  }
  const std::vector<Case> cases = {
      {"helix at 1 unit", small.curve, 0.3},
      {"helix at 1,000 units", large.curve, 0.6},
      {"random Bezier at 1 unit", random_space_bezier(2101, 1.0), 0.3},
      {"random Bezier at 1,000 units", random_space_bezier(2102, 1000.0), 0.5},
  };
  for (const Case& k : cases)
    for (const EndHold hold : {EndHold::Tangent, EndHold::Curvature}) {
      SCOPED_TRACE(k.name + " " + std::string(end_hold_name(hold)));
      const ProfileByFraction p = profile_by_fraction(k.curve, {k.f0}, false);
      const double h = 0.1 * p.kappa[0];
      const FractionMisses m = drag_by_fraction(k.curve, h, k.f0, hold);
      EXPECT_FALSE(m.result.planar);
      expect_ends(m.result, hold == EndHold::Curvature);
      if (hold == EndHold::Curvature) {  // G2 in space: the osculating plane at the end too
        EXPECT_LE(distance(frenet_end(k.curve.nurbs()).normal, frenet_end(m.result.curve.nurbs()).normal), 1e-9);
      }
      EXPECT_NEAR(m.moved, h, 0.05 * h) << m.moved / h;
      EXPECT_LE(m.worst, h) << m.worst / h;
      EXPECT_LE(m.tau_change, 0.1 * m.tau_max) << m.tau_change / m.tau_max;
      EXPECT_LE(m.result.handles_after, 2 * m.result.handles_before);
    }
}

// checks: the documented errors name their input.
TEST(CurvatureEdit, Errors) {
  Laws l;
  const curve::Curve line(nurbs::NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {}, 2));
  HULA_EXPECT_ERROR(static_cast<void>(edit_curvature(line, {.curvature = l("0.1")})), Errc::InvalidArgument,
                    "degree 1");
  HULA_EXPECT_ERROR(static_cast<void>(edit_curvature(s_curve(), {.curvature = l("0.1"), .torsion = l("0.1")})),
                    Errc::InvalidArgument, "torsion");
  CurvatureEditOptions bad;
  bad.max_handles_factor = 0.5;
  HULA_EXPECT_ERROR(static_cast<void>(edit_curvature(s_curve(), {.curvature = l("0.1")}, bad)), Errc::InvalidOption,
                    "max_handles_factor");
}

}  // namespace
}  // namespace hula::studies
